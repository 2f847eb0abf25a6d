/* test_material_once.c - gmaterial_once (kit/material_kit.h): the work runs exactly once however many threads ask
 * at the same time, every caller gets its status (an error too), work may use another material's once on the same
 * thread; and the materials that make their tables on first use (rough plastic and dielectric, textured roughness
 * too) give the same values, bit for bit, when their first use comes from many threads at once as when it comes
 * from one. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/kit/material_kit.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"

typedef struct Counted {
    int runs;
    int status;
    GMaterialOnce *inner; /* run from within the work (NULL: none) */
    struct Counted *inner_arg;
} Counted;

static int counted_work(void *arg)
{
    Counted *c = arg;
    __atomic_add_fetch(&c->runs, 1, __ATOMIC_RELAXED);
    for (volatile int i = 0; i < 100000; i++) /* long enough for the other threads to arrive meanwhile */
        ;
    if (c->inner)
        return gmaterial_once(c->inner, counted_work, c->inner_arg) == G_OK ? c->status : G_ERR_INVALID;
    return c->status;
}

static void test_once_across_threads(void **state)
{
    (void)state;
    static const int statuses[] = {G_OK, G_ERR_NOMEM};
    for (int i = 0; i < 2; i++) {
        int status = statuses[i];
        GMaterialOnce once = {0};
        Counted c = {0, status, NULL, NULL};
        int wrong = 0;
#pragma omp parallel num_threads(8) reduction(+ : wrong)
        for (int k = 0; k < 200; k++)
            wrong += gmaterial_once(&once, counted_work, &c) != status;
        assert_int_equal(c.runs, 1);
        assert_int_equal(wrong, 0);
        assert_int_equal(gmaterial_once(&once, counted_work, &c), status);
        assert_int_equal(c.runs, 1);
    }
}

static void test_once_nested(void **state)
{
    (void)state;
    GMaterialOnce outer = {0}, inner = {0};
    Counted in = {0, G_OK, NULL, NULL}, out = {0, G_OK, &inner, &in};
    int wrong = 0;
#pragma omp parallel num_threads(4) reduction(+ : wrong)
    wrong += gmaterial_once(&outer, counted_work, &out) != G_OK;
    assert_int_equal(wrong, 0);
    assert_int_equal(out.runs, 1);
    assert_int_equal(in.runs, 1);
    assert_int_equal(gmaterial_once(&inner, counted_work, &in), G_OK);
    assert_int_equal(in.runs, 1);
}

static const char *const library =
    "material plastic plastic { reflectance rgb 0.6 0.05 0.04 roughness 0.2 }\n"
    "material tplastic plastic { reflectance rgb 0.2 0.5 0.3 roughness fbm { frequency 8 range 0.1 0.6 } }\n"
    "material glass dielectric { glass BK7 roughness 0.1 }\n"
    "material tglass dielectric { index 1.5 roughness fbm { frequency 4 range 0.05 0.4 } }\n";
static const char *const names[] = {"plastic", "tplastic", "glass", "tglass"};
enum { NAMES = 4, DIRS = 16, THREADS = 4 };

/* reflection() of material name at DIRS direction pairs into v[DIRS * nvalues], each thread its own point. */
static int reflections(const GLibrary *lib, const GColorModel *md, const char *name, float *v)
{
    const GMaterial *m = glibrary_material(lib, name);
    if (!m)
        return G_ERR_NOTFOUND;
    GError err;
    GScratch *s = gscratch_create(1 << 16);
    GSurfPoint *sp = s ? gsurfpoint_new(md, s, gvec3(0, 0, 0), gvec3(0, 0, 1), gvec3(1, 0, 0), gvec3(0, 1, 0), 0.3,
                                        0.7, 0, &err)
                       : NULL;
    GColor light = {0}, out = {0};
    int rc = sp && gcolor_alloc(&light, md) == G_OK && gcolor_alloc(&out, md) == G_OK ? G_OK : G_ERR_NOMEM;
    if (rc == G_OK)
        rc = gcolor_fill(&light, 1.0);
    if (sp) {
        sp->material = sp->to = m;
        sp->from = NULL;
    }
    for (int k = 0; rc == G_OK && k < DIRS; k++) {
        double c = 0.1 + 0.85 * k / DIRS, t = 0.7 * k;
        GVec3 in = gvec3(sqrt(1.0 - c * c) * cos(t), sqrt(1.0 - c * c) * sin(t), c);
        GVec3 o = gvec3_normalize(gvec3(0.3 - 0.04 * k, 0.1, 1.0));
        rc = gmaterial_reflection(m, sp, in, &light, o, &out);
        memcpy(v + (size_t)k * md->nvalues, out.v, md->nvalues * sizeof(float));
    }
    gcolor_free(&light);
    gcolor_free(&out);
    gsurfpoint_free(sp);
    gscratch_destroy(s);
    return rc;
}

static void test_first_use_from_many_threads(void **state)
{
    (void)state;
    GError err;
    GColorModel *md;
    assert_int_equal(gcolormodel_create("spectrum9", NULL, &md, &err), G_OK);
    GReaderOptions ro = {.model = md};
    GLibrary *one, *many;
    assert_int_equal(greader_load_string(library, "one.mat", &ro, &one, &err), G_OK);
    assert_int_equal(greader_load_string(library, "many.mat", &ro, &many, &err), G_OK);
    size_t n = (size_t)DIRS * md->nvalues;
    float *want = test_malloc(n * sizeof(float)), *got = test_malloc(THREADS * n * sizeof(float));
    for (int i = 0; i < NAMES; i++) {
        assert_int_equal(reflections(one, md, names[i], want), G_OK);
        int bad = 0;
#pragma omp parallel num_threads(THREADS) reduction(+ : bad)
        bad += reflections(many, md, names[i], got + (size_t)omp_get_thread_num() * n) != G_OK;
        assert_int_equal(bad, 0);
        double sum = 0.0;
        for (size_t j = 0; j < n; j++)
            sum += want[j];
        assert_true(sum > 0.0); /* the comparison sees light */
        for (int t = 0; t < THREADS; t++)
            if (memcmp(want, got + (size_t)t * n, n * sizeof(float)) != 0)
                fail_msg("%s: thread %d's first use differs from a single thread's", names[i], t);
    }
    test_free(want);
    test_free(got);
    glibrary_destroy(many);
    glibrary_destroy(one);
    gcolormodel_destroy(md);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_once_across_threads),
        cmocka_unit_test(test_once_nested),
        cmocka_unit_test(test_first_use_from_many_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
