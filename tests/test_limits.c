/* test_limits.c - numbers beyond what integer types hold, given to the noise lattice and to spectral grid
 * conversions: the results are defined (finite, the documented values), and under `make test SANITIZE=1`
 * (-fsanitize=float-cast-overflow) no conversion of an out-of-range double to an integer happens. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "generic/builtins.h"
#include "generic/kit/noise.h"
#include "generic/kit/spectral.h"

/* The lattice wraps every 2^32 cells: a point and the same point 2^32 cells away have the same noise, and
 * beyond 2^53 (every double an integer, a lattice point) the noise is 0 with a finite gradient. */
static void noise_far_and_overflowing(void **state)
{
    (void)state;
    GVec3 g;
    double near = gnoise_signed(7u, gvec3(0.25, 0.5, 0.75), &g);
    double wrapped = gnoise_signed(7u, gvec3(0.25 + 4294967296.0, 0.5, 0.75 - 4294967296.0), &g);
    assert_true(fabs(near - wrapped) < 1e-6);
    assert_true(fabs(near) > 1e-3); /* not a lattice point: the comparison above means something */
    static const double far[] = {1e19, -1e19, 9.3e18, 1e300, -1.7e308};
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++) {
        assert_true(gnoise_signed(3u, gvec3(far[i], far[i], -far[i]), &g) == 0.0);
        assert_true(isfinite(g.x) && isfinite(g.y) && isfinite(g.z));
    }
    assert_true(gnoise_signed(3u, gvec3(INFINITY, 0.5, 0.5), &g) == 0.0);
    assert_true(g.x == 0.0 && g.y == 0.0 && g.z == 0.0);
    assert_true(gnoise_signed(3u, gvec3(NAN, 0.5, 0.5), NULL) == 0.0);
    /* fractal sums whose octaves run past every integer type: finite and within [-1, 1] / [0, 1] */
    GNoiseParams p = {GGENERATOR_SPACE_OBJECT, 1e9, 1u, 16, 1000.0, 0.5};
    double f = gnoise_fbm(&p, gvec3(1e13, 2.5e12, -7e12), &g);
    assert_true(isfinite(f) && fabs(f) <= 1.0);
    assert_true(isfinite(g.x) && isfinite(g.y) && isfinite(g.z));
    double t = gnoise_turbulence(&p, gvec3(1e13, 2.5e12, -7e12), NULL);
    assert_true(t >= 0.0 && t <= 1.0);
}

/* A source grid far from the destination feeds none of its samples: all zero, whatever the direction. */
static void resample_far_grids(void **state)
{
    (void)state;
    GSpectralGrid dst = {400.0, 10.0, 31};
    static const GSpectralGrid srcs[] = {{1e300, 10.0, 3}, {-1e300, 1e299, 3}, {1e300, 1e300, 3}, {2e9, 10.0, 3}};
    float in[3] = {1.0f, 2.0f, 3.0f}, out[31];
    for (size_t k = 0; k < sizeof srcs / sizeof srcs[0]; k++) {
        for (int interpolate = 0; interpolate < 2; interpolate++) {
            GSpectralResample r;
            assert_int_equal(gspectral_resample_build(&r, srcs[k], dst, interpolate), G_OK);
            memset(out, 0x7f, sizeof out);
            gspectral_resample_apply(&r, in, 1, out, 1);
            for (int i = 0; i < 31; i++)
                assert_true(out[i] == 0.0f);
            gspectral_resample_free(&r);
        }
    }
    /* and the same grid still maps one to one (the clamping did not move a sample) */
    GSpectralResample r;
    GSpectralGrid same = {400.0, 10.0, 3};
    assert_int_equal(gspectral_resample_build(&r, same, (GSpectralGrid){400.0, 10.0, 3}, 0), G_OK);
    gspectral_resample_apply(&r, in, 1, out, 1);
    assert_true(out[0] == 1.0f && out[1] == 2.0f && out[2] == 3.0f);
    gspectral_resample_free(&r);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(noise_far_and_overflowing),
        cmocka_unit_test(resample_far_grids),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
