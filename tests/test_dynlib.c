/* test_dynlib.c - libraries opened by soname on first use (generic/services/dynlib.h): a library that exists
 * (libm: cos resolved and called), a symbol it lacks (named, no slot set), a soname that does not exist (the
 * loader's reason), the outcome kept without a second try, and one open for threads that ask at once. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "generic/services/dynlib.h"
#include "test_util.h"

#include <dlfcn.h>
#include <math.h>
#include <pthread.h>
#include <string.h>
#include <time.h>

#define LIBM "libm.so.6"

/* The program's dlopen stands before libc's (the library is linked statically into this program): it counts the
 * opens of LIBM and makes each of them slow, so that threads asking at once would all reach it without the lock. */
static int libm_opens;

void *dlopen(const char *file, int mode)
{
    static void *(*next)(const char *, int);
    if (!__atomic_load_n(&next, __ATOMIC_ACQUIRE)) {
        void *f = dlsym(RTLD_NEXT, "dlopen");
        void *(*g)(const char *, int);
        memcpy(&g, &f, sizeof g);
        __atomic_store_n(&next, g, __ATOMIC_RELEASE);
    }
    if (file && !strcmp(file, LIBM)) {
        __atomic_add_fetch(&libm_opens, 1, __ATOMIC_RELAXED);
        nanosleep(&(struct timespec){0, 20 * 1000 * 1000}, NULL);
    }
    return __atomic_load_n(&next, __ATOMIC_ACQUIRE)(file, mode);
}

typedef double (*Unary)(double);

static void test_existing_library_and_symbol(void **state)
{
    (void)state;
    Unary cos_fn = NULL, sqrt_fn = NULL;
    const GDynLibSymbol symbols[] = {{"cos", &cos_fn}, {"sqrt", &sqrt_fn}};
    GDynLib lib = GDYNLIB_INIT(LIBM, symbols, 2);
    assert_int_equal(gdynlib_open(&lib), 1);
    assert_string_equal(lib.why, "");
    assert_non_null(cos_fn);
    assert_non_null(sqrt_fn);
    assert_near(cos_fn(M_PI / 3.0), 0.5, 1e-15);
    assert_near(cos_fn(0.0), 1.0, 0.0);
    assert_near(sqrt_fn(2.0) * sqrt_fn(2.0), 2.0, 1e-15);
    /* a second call gives the same functions */
    Unary first = cos_fn;
    assert_int_equal(gdynlib_open(&lib), 1);
    assert_ptr_equal((void *)cos_fn, (void *)first);
}

static void test_missing_symbol_is_named(void **state)
{
    (void)state;
    Unary cos_fn = NULL, missing = NULL;
    const GDynLibSymbol symbols[] = {{"cos", &cos_fn}, {"gdynlib_test_no_such_function", &missing}};
    GDynLib lib = GDYNLIB_INIT(LIBM, symbols, 2);
    assert_int_equal(gdynlib_open(&lib), 0);
    assert_string_equal(lib.why, "it has no gdynlib_test_no_such_function");
    assert_null(cos_fn); /* all slots or none */
    assert_null(missing);
}

static void test_missing_library_gives_the_loaders_reason(void **state)
{
    (void)state;
    Unary f = NULL;
    const GDynLibSymbol symbols[] = {{"cos", &f}};
    GDynLib lib = GDYNLIB_INIT("libgeneric-test-no-such-library.so.7", symbols, 1);
    assert_int_equal(gdynlib_open(&lib), 0);
    /* glibc's dlerror: "NAME: cannot open shared object file: No such file or directory" */
    assert_non_null(strstr(lib.why, "libgeneric-test-no-such-library.so.7"));
    assert_non_null(strstr(lib.why, "cannot open shared object file"));
    assert_null(f);
    /* the outcome is kept: no second try, even once the name would open */
    char why[sizeof lib.why];
    memcpy(why, lib.why, sizeof why);
    lib.soname = LIBM;
    int opens = __atomic_load_n(&libm_opens, __ATOMIC_RELAXED);
    assert_int_equal(gdynlib_open(&lib), 0);
    assert_int_equal(__atomic_load_n(&libm_opens, __ATOMIC_RELAXED), opens);
    assert_string_equal(lib.why, why);
    assert_null(f);
}

enum { THREADS = 8 };

static Unary shared_sqrt;
static const GDynLibSymbol shared_symbols[] = {{"sqrt", &shared_sqrt}};
static GDynLib shared_lib = GDYNLIB_INIT(LIBM, shared_symbols, 1);
static pthread_barrier_t start;

static void *open_shared(void *arg)
{
    double *out = arg;
    pthread_barrier_wait(&start);
    *out = gdynlib_open(&shared_lib) ? shared_sqrt(9.0) : -1.0; /* the slot is set when the call returns */
    return NULL;
}

static void test_threads_at_once_open_it_once(void **state)
{
    (void)state;
    __atomic_store_n(&libm_opens, 0, __ATOMIC_RELAXED);
    pthread_t t[THREADS];
    double got[THREADS];
    assert_int_equal(pthread_barrier_init(&start, NULL, THREADS), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_create(&t[i], NULL, open_shared, &got[i]), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_join(t[i], NULL), 0);
    pthread_barrier_destroy(&start);
    for (int i = 0; i < THREADS; i++)
        assert_near(got[i], 3.0, 0.0);
    assert_int_equal(__atomic_load_n(&libm_opens, __ATOMIC_RELAXED), 1);
    assert_int_equal(gdynlib_open(&shared_lib), 1);
    assert_int_equal(__atomic_load_n(&libm_opens, __ATOMIC_RELAXED), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_existing_library_and_symbol),
        cmocka_unit_test(test_missing_symbol_is_named),
        cmocka_unit_test(test_missing_library_gives_the_loaders_reason),
        cmocka_unit_test(test_threads_at_once_open_it_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
