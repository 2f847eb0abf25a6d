/* test_util.h - small helpers shared by the test programs (static inline, include after <cmocka.h>):
 * a double-precision closeness assertion, the test allocator (test_alloc.h), running a built tool with its output
 * captured, a model's diagonal matrix, and clocks for time bounds. */
#ifndef GENERIC_TEST_UTIL_H
#define GENERIC_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "generic/color.h"
#include "test_alloc.h"

/** 1 in a build with AddressSanitizer (make SANITIZE=1), whose code runs several times slower, else 0. Statistical
 * tests there check fewer angles, configurations or samples: what the sanitizers look for (memory errors, undefined
 * behaviour, leaks) lies in the code paths, which the reduced set runs as well; the plain build checks the full set. */
#ifdef __SANITIZE_ADDRESS__
#define TU_SANITIZED 1
#else
#define TU_SANITIZED 0
#endif

/** |a - b| <= tol in double precision (cmocka's assert_float_equal works in float); a failure prints the
 * expression, both values and the tolerance. */
#define assert_near(a, b, tol) tu_near((a), (b), (tol), #a, __FILE__, __LINE__)

/** Deterministic uniform numbers in [0, 1) from the state *s (a 64-bit LCG: the same draws on every run). */
static inline double tu_uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * 0x1.0p-53;
}

static inline void tu_near(double a, double b, double tol, const char *what, const char *file, int line)
{
    if (!(fabs(a - b) <= tol)) {
        print_error("%s:%d: %s = %.10g, expected %.10g within %g\n", file, line, what, a, b, tol);
        _fail(file, line);
    }
}

/** A matrix of model m (through from_reradiation): the diagonal reflectance 0.5. 0 when the model turns a
 * re-radiation matrix into a vector (it has no matrices). */
static inline int tu_diagonal_matrix(const GColorModel *m, GColor *out)
{
    int n = m->nsamples;
    if (n <= 0 || m->capacity != n * n)
        return 0;
    float *data = calloc((size_t)n * n, sizeof *data);
    assert_non_null(data);
    for (int k = 0; k < n; k++)
        data[k * n + k] = 0.5f;
    GReradiation r = {m->lambda_min, m->lambda_step, n, m->lambda_min, m->lambda_step, n, data};
    GError err;
    assert_int_equal(gcolor_from_reradiation(out, &r, &err), G_OK);
    free(data);
    return out->kind == GCOLOR_MATRIX;
}

/** The number of elements of an array (for gcolor_wrap's size argument; not for a pointer). */
#define tu_floats(a) (sizeof(a) / sizeof((a)[0]))

/** Writes text into a new file at path; 0, or -1 when it cannot be created. */
static inline int tu_write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    fclose(f);
    return 0;
}

/** Runs `'exe' args 2>&1` through the shell, capturing up to size - 1 bytes of what it prints into out
 * (NUL-terminated); returns its exit status, -1 when it did not exit normally. */
static inline int tu_run_capture(const char *exe, const char *args, char *out, size_t size)
{
    char cmd[16384];
    int len = snprintf(cmd, sizeof cmd, "'%s' %s 2>&1", exe, args);
    assert_true(len > 0 && (size_t)len < sizeof cmd);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t n = fread(out, 1, size - 1, p);
    out[n] = '\0';
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/** Makes a private directory "/tmp/PREFIX.XXXXXX" into dir (at least 64 + strlen(prefix) bytes); 0 on success. */
static inline int tu_tempdir(char *dir, size_t size, const char *prefix)
{
    snprintf(dir, size, "/tmp/%s.XXXXXX", prefix);
    return mkdtemp(dir) ? 0 : -1;
}

/** dir/name into buf (n bytes); returns buf. */
static inline const char *tu_in_dir(const char *dir, const char *name, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s", dir, name);
    return buf;
}

/** Removes a directory made by tu_tempdir with everything in it; 0 on success. */
static inline int tu_rmtree(const char *dir)
{
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

/** Seconds of a clock, for time bounds: tu_seconds() the monotonic clock, tu_cpu_seconds() the process's CPU time
 * (all threads). A time bound holds only on a machine that no other test loads: a program that asserts one is
 * listed in SERIAL of scripts/run_tests.sh, which runs it alone after the parallel batch. Read in the batch
 * (GENERIC_TEST_BATCH set), either clock fails the test instead. */
#define tu_seconds() tu_clock_seconds(CLOCK_MONOTONIC, __FILE__, __LINE__)
#define tu_cpu_seconds() tu_clock_seconds(CLOCK_PROCESS_CPUTIME_ID, __FILE__, __LINE__)

static inline double tu_clock_seconds(clockid_t clock, const char *file, int line)
{
    if (getenv("GENERIC_TEST_BATCH")) {
        print_error("%s:%d: a time bound in the parallel batch: list the program in SERIAL of scripts/run_tests.sh\n",
                    file, line);
        _fail(file, line);
    }
    struct timespec t;
    clock_gettime(clock, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

#endif
