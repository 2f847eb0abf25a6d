/* test_spectral_kernels.c - the vector kernels of spectral_kernels.h that have a scalar definition in their
 * comment (division with zero where the divisor is zero, axpy with the product in double, the finiteness and
 * sign test, the fill, the mix of three rows) give bit for bit the scalar definition's results, for every length
 * from 0 to 90 (the vector part and the tail), with operands that alias the output, and with zeros, negative
 * zeros, infinities and NaNs among the samples. The colour matching kernel (float weights and float sums) stays
 * within a bound of the double sums, on its own and through the sampled models' to_xyz, and shows every non-finite
 * sample in all three coordinates (gcolormodel_xyz_shows_nonfinite). Where the processor has
 * AVX2, the 8-float versions give bit for bit the 4-float versions' results. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/kit/spectral_kernels.h"
#include <stdio.h>

enum { N = 90 };

static uint32_t rng_state = 12345u;
static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    uint32_t r = rng_state >> 8;
    switch (r % 11) {
    case 0: return 0.0f;
    case 1: return -0.0f;
    default: return ((float)(r % 20000) - 10000.0f) / 997.0f;
    }
}

static void fill(float *v, int n)
{
    for (int i = 0; i < n; i++)
        v[i] = rnd();
}

static int same_bits(const float *a, const float *b, int n) { return memcmp(a, b, (size_t)n * sizeof *a) == 0; }

static void test_div_equals_scalar(void **state)
{
    (void)state;
    for (int round = 0; round < 20; round++)
        for (int n = 0; n <= N; n++) {
            float a[N], b[N], o[N], ref[N];
            fill(a, n);
            fill(b, n);
            for (int i = 0; i < n; i++)
                ref[i] = b[i] != 0.0f ? a[i] / b[i] : 0.0f;
            gspectral_kdiv(o, a, b, n);
            assert_true(same_bits(o, ref, n));
            gspectral_kdiv(a, a, b, n); /* out aliases a */
            assert_true(same_bits(a, ref, n));
        }
}

static void test_axpyd_equals_scalar(void **state)
{
    (void)state;
    const double scales[] = {0.0, 1.0, -0.3, 1.0 / 3.0, 1e-30, 7.123456789012345};
    for (int k = 0; k < (int)(sizeof scales / sizeof *scales); k++)
        for (int n = 0; n <= N; n++) {
            float a[N], b[N], o[N], ref[N];
            fill(a, n);
            fill(b, n);
            for (int i = 0; i < n; i++)
                ref[i] = b[i] + (float)(a[i] * scales[k]);
            gspectral_kaxpyd(o, scales[k], a, b, n);
            assert_true(same_bits(o, ref, n));
            gspectral_kaxpyd(b, scales[k], a, b, n); /* out aliases b, as gcolor_add_scaled does */
            assert_true(same_bits(b, ref, n));
        }
}

#ifdef GSPECTRAL_AVX2
/* gspectral_kfinite8 where the test may call it (compiled for AVX2; run only when the processor has it). */
static GSPECTRAL_TARGET_AVX2 int finite8(const float *a, int n, int nonneg) { return gspectral_kfinite8(a, n, nonneg); }
#endif

static void test_finite_equals_scalar(void **state)
{
    (void)state;
    const float odd[] = {INFINITY, -INFINITY, NAN, -1.0f, -0.0f, 0.0f, 1e38f, -1e-40f};
    for (int n = 1; n <= N; n++)
        for (int pos = 0; pos < n; pos += 3)
            for (int k = 0; k < (int)(sizeof odd / sizeof *odd); k++) {
                float a[N];
                for (int i = 0; i < n; i++)
                    a[i] = (float)(i % 5) * 0.25f; /* finite, not negative */
                a[pos] = odd[k];
                for (int nonneg = 0; nonneg <= 1; nonneg++) {
                    int ref = 1;
                    for (int i = 0; i < n; i++)
                        if (!isfinite(a[i]) || (nonneg && a[i] < 0.0f))
                            ref = 0;
                    assert_int_equal(gspectral_kfinite(a, n, nonneg), ref);
#ifdef GSPECTRAL_AVX2
                    if (gspectral_have_avx2()) /* positions 3 apart: in the two-block steps and after them */
                        assert_int_equal(finite8(a, n, nonneg), ref);
#endif
                }
            }
    assert_int_equal(gspectral_kfinite(NULL, 0, 1), 1);
}

static void test_fill_and_mix3_equal_scalar(void **state)
{
    (void)state;
    for (int n = 0; n <= N; n++) {
        float o[N + 1], b0[N], b1[N], b2[N], ref[N];
        o[n] = 42.0f;
        gspectral_kfill(o, 0.3f, n);
        for (int i = 0; i < n; i++)
            assert_true(o[i] == 0.3f);
        assert_true(o[n] == 42.0f); /* nothing written past n */
        fill(b0, n);
        fill(b1, n);
        fill(b2, n);
        const float r = 0.7f, g = -1.3f, bl = 2.9f;
        for (int i = 0; i < n; i++)
            ref[i] = r * b0[i] + g * b1[i] + bl * b2[i];
        gspectral_kmix3(o, b0, b1, b2, r, g, bl, n);
        assert_true(same_bits(o, ref, n));
        assert_true(o[n] == 42.0f);
    }
}

#ifdef GSPECTRAL_AVX2
/* Runs every 8-float kernel and its 4-float version on the same operands; 1 when all agree bit for bit. */
static GSPECTRAL_TARGET_AVX2 int avx2_equal(int n, float *a, float *b, const float *t, double s)
{
    float o4[N], o8[N];
    int same = 1;
    for (int op = 0; op < 2; op++) {
        gspectral_kmap((GSpectralOp)op, o4, a, b, n);
        gspectral_kmap8((GSpectralOp)op, o8, a, b, n);
        same &= same_bits(o4, o8, n);
        memcpy(o8, a, (size_t)n * sizeof *a); /* in place: the last block overlaps the whole ones */
        gspectral_kmap8((GSpectralOp)op, o8, o8, b, n);
        same &= same_bits(o4, o8, n);
    }
    gspectral_kscale(o4, a, (float)s, n);
    gspectral_kscale8(o8, a, (float)s, n);
    same &= same_bits(o4, o8, n);
    memcpy(o8, a, (size_t)n * sizeof *a);
    gspectral_kscale8(o8, o8, (float)s, n);
    same &= same_bits(o4, o8, n);
    gspectral_kdiv(o4, a, b, n);
    gspectral_kdiv8(o8, a, b, n);
    same &= same_bits(o4, o8, n);
    gspectral_kaxpyd(o4, s, a, b, n);
    gspectral_kaxpyd8(o8, s, a, b, n);
    same &= same_bits(o4, o8, n);
    gspectral_kfill(o4, (float)s, n);
    gspectral_kfill8(o8, (float)s, n);
    same &= same_bits(o4, o8, n);
    double r4 = gspectral_kbright(b, a, n), r8 = gspectral_kbright8(b, a, n);
    same &= memcmp(&r4, &r8, sizeof r4) == 0;
    for (int term = 0; term < 3; term++) {
        float f4 = gspectral_ksum((GSpectralTerm)term, a, b, n), f8 = gspectral_ksum8((GSpectralTerm)term, a, b, n);
        same &= memcmp(&f4, &f8, sizeof f4) == 0 || (isnan(f4) && isnan(f8));
    }
    for (int nonneg = 0; nonneg <= 1; nonneg++)
        same &= gspectral_kfinite(a, n, nonneg) == gspectral_kfinite8(a, n, nonneg);
    double x4[3], x8[3];
    gspectral_kxyz(t, a, n, x4);
    gspectral_kxyz8(t, a, n, x8);
    same &= memcmp(x4, x8, sizeof x4) == 0;
    return same;
}

/* gspectral_kaxpyd has one version: compiled for AVX2 (4 doubles a register) it must round as by default. */
static void axpyd_default(float *o, double s, const float *a, const float *b, int n)
{
    gspectral_kaxpyd(o, s, a, b, n);
}

static GSPECTRAL_TARGET_AVX2 void axpyd_avx2(float *o, double s, const float *a, const float *b, int n)
{
    gspectral_kaxpyd(o, s, a, b, n);
}
#endif

static void test_avx2_equals_sse(void **state)
{
    (void)state;
#ifdef GSPECTRAL_AVX2
    if (!gspectral_have_avx2()) {
        print_message("no AVX2 on this processor: nothing to compare\n");
        return;
    }
    const double scales[] = {0.0, 1.0, -0.3, 1.0 / 3.0, 1e-30, 7.123456789012345};
    const float odd[] = {INFINITY, -INFINITY, NAN, -1.0f, -0.0f, 1e38f, -1e-40f};
    for (int round = 0; round < 12; round++)
        for (int n = 0; n <= N; n++) {
            float a[N], b[N], t[(N + 7) / 8 * 24], o4[N], o8[N];
            fill(a, n);
            fill(b, n);
            fill(t, (n + 7) / 8 * 24);
            if (round >= 6 && n > 0) /* a non-finite or negative sample somewhere */
                a[(round * 13) % n] = odd[round - 6];
            assert_true(avx2_equal(n, a, b, t, scales[round % 6]));
            axpyd_default(o4, scales[round % 6], a, b, n);
            axpyd_avx2(o8, scales[round % 6], a, b, n);
            assert_true(same_bits(o4, o8, n));
        }
    print_message("8-float kernels equal the 4-float ones bit for bit, lengths 0 to %d\n", N);
#else
    print_message("no 8-float kernels in this build\n");
#endif
}

/* Relative error bound of gspectral_kxyz against the double sums, as a share of the sum of the terms'
 * magnitudes: float weights and products (2 roundings) and float sums of at most 23 terms a lane (n <= 90),
 * 2^-24 each, with room to spare. */
#define XYZ_BOUND 2e-6

static void test_xyz_kernel_within_bound(void **state)
{
    (void)state;
    double worst = 0.0;
    for (int round = 0; round < 30; round++)
        for (int n = 1; n <= N; n++) {
            double w[3][N];
            float a[N], t[(N + 7) / 8 * 24];
            for (int k = 0; k < n; k++) {
                for (int c = 0; c < 3; c++)
                    w[c][k] = fabs(rnd()) * 1e-3 * (c + 1);
                /* positive spectra, signed ones, and a narrow line over a dim floor */
                a[k] = round % 3 == 0 ? fabsf(rnd()) : round % 3 == 1 ? rnd() : (k == n / 2 ? 1e4f : 1e-3f);
            }
            gspectral_xyz_table(t, w[0], w[1], w[2], n);
            double xyz[3];
            gspectral_kxyz(t, a, n, xyz);
            for (int c = 0; c < 3; c++) {
                double exact = 0.0, mag = 0.0;
                for (int k = 0; k < n; k++) {
                    exact += w[c][k] * a[k];
                    mag += fabs(w[c][k] * a[k]);
                }
                double err = fabs(xyz[c] - exact);
                assert_true(err <= XYZ_BOUND * mag);
                if (mag > 0.0 && err / mag > worst)
                    worst = err / mag;
            }
        }
    print_message("colour matching in float: worst error %.2e of the sum of magnitudes (bound %.0e)\n", worst,
                  XYZ_BOUND);
}

/* The models' to_xyz (the float kernel) against the nm path (their to_nm, then gcie_nm_to_xyz in double) on a
 * range of spectra: RGB colours as reflectances and lights, CIE illuminants, blackbodies and narrow lines. */
static void test_models_to_xyz_against_nm(void **state)
{
    (void)state;
    const char *names[] = {"spectrum", "spectrum", "spectrum", "spectrum9", "bispectral"};
    const double steps[] = {5, 1, 10, 0, 0};
    for (int i = 0; i < 5; i++) {
        GColorModelOptions opt = {steps[i], 0, 0, 0};
        GColorModel *m;
        assert_int_equal(gcolormodel_create(names[i], &opt, &m, NULL), G_OK);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        double worst = 0.0, worst_own = 0.0; /* relative to |X|+|Y|+|Z|, and to the coordinate itself */
        for (int k = 0; k < 40; k++) {
            GSpectrumNM in, back;
            GColorRole role = k % 2 ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE;
            if (k < 16) {
                double rgb[3] = {(k & 1) * 0.9 + 0.05, (k >> 1 & 1) * 0.8, (k >> 2 & 1) * 0.7 + (k >> 3) * 0.2};
                assert_int_equal(gcolor_from_rgb(&c, rgb, role), G_OK);
            } else {
                if (k < 22)
                    assert_int_equal(gcie_illuminant_nm(k % 3 == 0 ? "D65" : k % 3 == 1 ? "A" : "E", &in), G_OK);
                else if (k < 30)
                    gcie_blackbody_nm(1000.0 + 1500.0 * (k - 22), &in);
                else
                    for (int j = 0; j < GNM_COUNT; j++)
                        in.v[j] = j == 40 * (k - 30) ? 50.0f : 0.01f;
                assert_int_equal(gcolor_from_nm(&c, &in, role), G_OK);
            }
            double fast[3], exact[3];
            assert_int_equal(gcolor_to_xyz(&c, role, fast), G_OK);
            assert_int_equal(gcolor_to_nm(&c, role, &back), G_OK);
            gcie_nm_to_xyz(&back, role, exact);
            double mag = fabs(exact[0]) + fabs(exact[1]) + fabs(exact[2]);
            for (int j = 0; j < 3; j++) {
                double rel = fabs(fast[j] - exact[j]) / mag;
                assert_true(rel <= 1e-5);
                worst = fmax(worst, rel);
                if (fabs(exact[j]) > 1e-3 * mag)
                    worst_own = fmax(worst_own, fabs(fast[j] - exact[j]) / fabs(exact[j]));
            }
        }
        print_message("%-10s step %g: to_xyz within %.2e of the nm path relative to |X|+|Y|+|Z|, %.2e relative to "
                      "the coordinate\n", names[i], m->lambda_step, worst, worst_own);
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
}

/* Every non-finite sample shows in all three coordinates of the colour matching kernel, whatever its weight (zero
 * included: NaN and infinity times 0 are NaN), for every length and position, in the 4- and 8-float versions: what
 * gcolormodel_xyz_shows_nonfinite promises for the models on the kit's to_xyz, which a renderer relies on to skip
 * the sample-by-sample finiteness test. Then the promise itself, model by model, on grids whose lengths are and are
 * not multiples of 8. */
static int xyz_nonfinite(const double xyz[3]) { return !isfinite(xyz[0]) && !isfinite(xyz[1]) && !isfinite(xyz[2]); }

#ifdef GSPECTRAL_AVX2
static GSPECTRAL_TARGET_AVX2 void kxyz8(const float *t, const float *a, int n, double xyz[3])
{
    gspectral_kxyz8(t, a, n, xyz);
}
#endif

/* A matrix of c's model (n x n entries, n = nvalues) reads as the vector of its row sums (each in double, rounded
 * to float): its coordinates equal that vector's bit for bit, and a non-finite entry anywhere, or +inf and -inf in
 * one row, makes all three non-finite. Returns the cases checked. */
static int matrix_nonfinite_cases(GColor *c)
{
    const GColorModel *m = c->model;
    const int n = m->nvalues;
    const float odd[] = {NAN, INFINITY, -INFINITY};
    float sums[128];
    assert_true(n <= 128);
    GColor v = {.model = m, .v = sums, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_CALLER, .capacity = 128};
    int cases = 0;
    for (int e = -1; e < n * n; e++)
        for (int o = 0; o < 3; o++) {
            c->kind = GCOLOR_MATRIX;
            for (int j = 0; j < n * n; j++)
                c->v[j] = (j % (n + 1) == 0 ? 0.5f : 0.02f) + 0.001f * (float)(j % 7);
            double xyz[3], ref[3];
            if (e < 0) { /* all finite, in both roles; then +inf and -inf in row o */
                for (int r = 0; r < n; r++) {
                    double s = 0.0;
                    for (int j = 0; j < n; j++)
                        s += c->v[r * n + j];
                    sums[r] = (float)s;
                }
                for (GColorRole role = GCOLOR_REFLECTANCE; role <= GCOLOR_LIGHT; role++) {
                    assert_int_equal(gcolor_to_xyz(c, role, xyz), G_OK);
                    assert_int_equal(gcolor_to_xyz(&v, role, ref), G_OK);
                    assert_memory_equal(xyz, ref, sizeof xyz);
                    assert_true(isfinite(xyz[0]) && isfinite(xyz[1]) && isfinite(xyz[2]));
                }
                c->v[o * n] = INFINITY;
                c->v[o * n + n - 1] = -INFINITY;
            } else {
                c->v[e] = odd[o];
            }
            assert_int_equal(gcolor_to_xyz(c, GCOLOR_LIGHT, xyz), G_OK);
            assert_true(xyz_nonfinite(xyz));
            assert_false(gcolor_is_finite(c));
            cases++;
        }
    print_message("%-10s %3d x %d matrices: every non-finite entry shows\n", gcolormodel_name(m), n, n);
    return cases;
}

static void test_xyz_shows_nonfinite(void **state)
{
    (void)state;
    const float odd[] = {NAN, INFINITY, -INFINITY};
    int cases = 0;
    for (int n = 1; n <= N; n++)
        for (int k = 0; k < n; k++)
            for (int o = 0; o < 3; o++) {
                float a[N], t[(N + 7) / 8 * 24];
                fill(a, n);
                fill(t, (n + 7) / 8 * 24);
                if ((k + o) % 2) /* the sample's three weights zero */
                    for (int c = 0; c < 3; c++)
                        t[(k >> 3) * 24 + (k & 7) + 8 * c] = 0.0f;
                a[k] = odd[o];
                double xyz[3];
                gspectral_kxyz(t, a, n, xyz);
                assert_true(xyz_nonfinite(xyz));
#ifdef GSPECTRAL_AVX2
                if (gspectral_have_avx2()) {
                    kxyz8(t, a, n, xyz);
                    assert_true(xyz_nonfinite(xyz));
                }
#endif
                cases++;
            }
    const char *names[] = {"spectrum", "spectrum", "spectrum", "spectrum", "spectrum9", "bispectral", "rgb"};
    const GColorModelOptions opts[] = {{5, 0, 0, 0},   {1, 0, 0, 0}, {10, 0, 0, 0}, {6, 400, 700, 0},
                                       {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    const int shows[] = {1, 1, 1, 1, 1, 1, 0}; /* rgb has a conversion of its own */
    assert_int_equal(gcolormodel_xyz_shows_nonfinite(NULL), 0);
    for (int i = 0; i < 7; i++) {
        GColorModel *m;
        assert_int_equal(gcolormodel_create(names[i], &opts[i], &m, NULL), G_OK);
        assert_int_equal(gcolormodel_xyz_shows_nonfinite(m), shows[i]);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        for (int k = 0; shows[i] && k < m->nvalues; k++)
            for (int o = 0; o < 3; o++) {
                for (int j = 0; j < m->nvalues; j++)
                    c.v[j] = 0.5f + 0.01f * (float)j;
                c.v[k] = odd[o];
                double xyz[3];
                assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
                assert_true(xyz_nonfinite(xyz));
                assert_false(gcolor_is_finite(&c));
                cases++;
            }
        print_message("%-10s %3d samples: the conversion %s every non-finite sample\n", names[i], m->nvalues,
                      shows[i] ? "shows" : "is not known to show");
        if (shows[i] && m->capacity == m->nvalues * m->nvalues && m->nvalues > 1)
            cases += matrix_nonfinite_cases(&c);
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
    print_message("%d non-finite samples, each in all three coordinates\n", cases);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_div_equals_scalar),
        cmocka_unit_test(test_axpyd_equals_scalar),
        cmocka_unit_test(test_finite_equals_scalar),
        cmocka_unit_test(test_fill_and_mix3_equal_scalar),
        cmocka_unit_test(test_xyz_kernel_within_bound),
        cmocka_unit_test(test_models_to_xyz_against_nm),
        cmocka_unit_test(test_xyz_shows_nonfinite),
        cmocka_unit_test(test_avx2_equals_sse),
    };
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
