/* test_probe_sg_convergence.c - the spherical Gaussian fits that solve for amplitudes (sg-ls, sg-nnls,
 * sg-ambient) improve with the number of lobes on real probes: on the shared probes (each skipped when the
 * data is absent) and on the synthetic sky of the repository, the mean irradiance error at 64 lobes is below
 * that at 8, and it never rises by more than 5% from one count to the next of 8, 16, 32, 64; sg-ambient's
 * irradiance is never negative, and all its amplitudes and its ambient term are >= 0. Under the sanitizers only
 * the repository's sky (TU_SANITIZED). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/probe.h"
#include "test_util.h"

/* Normals of the error measure: not the fits' own validation normals. */
#define NORMALS 2000

/* The probe named, from the shared data or the repository (examples/scenes/sky.hdr); NULL when absent. */
static GProbe *load(const char *name, int shared)
{
    const char *src = getenv("GENERIC_SOURCE_DIR");
    char path[1024];
    if (shared) {
        snprintf(path, sizeof path, "%s/../shared/data/probes/%s", src ? src : ".", name);
        if (access(path, R_OK) != 0)
            snprintf(path, sizeof path, "/work/shared/data/probes/%s", name);
    } else {
        snprintf(path, sizeof path, "%s/examples/scenes/%s", src ? src : ".", name);
    }
    if (access(path, R_OK) != 0)
        return NULL;
    GProbe *p = NULL;
    GError err;
    if (gprobe_load(path, GPROBE_AUTO, 0, &p, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    return p;
}

static void check_probe(const char *name, int shared)
{
    if (shared && TU_SANITIZED) { /* the sanitizers look at the code paths, which the repository's sky runs */
        print_message("%s: checked in the plain build only\n", name);
        return;
    }
    GProbe *p = load(name, shared);
    if (!p) {
        print_message("%s not found: skipped\n", name);
        return;
    }
    static GVec3 n[NORMALS];
    static double truth[NORMALS * 3], approx[NORMALS * 3];
    gprobe_fibonacci(NORMALS, n);
    assert_int_equal(gprobe_irradiance(p, n, NORMALS, truth, NULL), G_OK);
    const int counts[4] = {8, 16, 32, 64};
    const GProbeBasisKind kinds[3] = {GPROBE_BASIS_SG_LS, GPROBE_BASIS_SG_NNLS, GPROBE_BASIS_SG_AMBIENT};
    for (int k = 0; k < 3; k++) {
        double error[4];
        for (int i = 0; i < 4; i++) {
            GProbeBasis b;
            GError err;
            if (gprobe_basis_fit(p, kinds[k], counts[i], &b, &err) != G_OK)
                fail_msg("%s %s %d: %s", name, gprobe_basis_name(kinds[k]), counts[i], err.message);
            gprobe_basis_irradiance(&b, n, NORMALS, approx);
            GProbeErrors e;
            gprobe_compare(truth, approx, NORMALS, &e);
            error[i] = e.mean_rel; /* percent */
            if (kinds[k] == GPROBE_BASIS_SG_AMBIENT) {
                for (int j = 0; j < NORMALS * 3; j++)
                    assert_true(approx[j] >= 0.0);
                for (int c = 0; c < 3; c++) {
                    assert_true(b.ambient[c] >= 0.0);
                    for (int l = 0; l < b.size; l++)
                        assert_true(b.lobes[l].amp[c] >= 0.0);
                }
            }
            gprobe_basis_free(&b);
        }
        print_message("%-10s %-10s mean error %6.3f %6.3f %6.3f %6.3f %% at 8/16/32/64 lobes\n", name,
                      gprobe_basis_name(kinds[k]), error[0], error[1], error[2], error[3]);
        assert_true(error[3] < error[0]);
        for (int i = 1; i < 4; i++)
            assert_true(error[i] <= 1.05 * error[i - 1]);
    }
    gprobe_destroy(p);
}

static void test_grace(void **state)
{
    (void)state;
    check_probe("grace.hdr", 1);
}

static void test_pisa(void **state)
{
    (void)state;
    check_probe("pisa.hdr", 1);
}

static void test_uffizi(void **state)
{
    (void)state;
    check_probe("uffizi.hdr", 1);
}

static void test_sky(void **state)
{
    (void)state;
    check_probe("sky.hdr", 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grace),
        cmocka_unit_test(test_pisa),
        cmocka_unit_test(test_uffizi),
        cmocka_unit_test(test_sky),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
