/* test_spectral_simd.c - the per-colour work of the spectral models that has a vector body and a scalar one, or
 * that is measured once and kept, gives the same bits as doing it afresh on the scalar path:
 * - the sigmoid fit (lib/color/uplift_fit.c): the AVX2 body against the scalar one on generated discretisations
 *   (1 to 401 samples: whole blocks of 4 and every tail) and generated targets, reachable and not; the fitted
 *   coefficients and the distance left must be equal bit for bit;
 * - the samples of an uplifted colour (guplift_sigmoid_samples): the AVX2 body against the scalar one, for every
 *   length from 0 to 90, with coefficients that make the polynomial infinite (black and white) or overflow;
 * - gcolor_from_rgb in the sigmoid models, asked again for the same colour among others, gives what it gave
 *   the first time, in two models and two grids at once (what is kept is kept per model);
 * - gcolormodel_rgb_range, kept per model and role, equals the extremes of the cube's corners measured here. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "color/uplift.h"
#include "color/uplift_fit.h"
#include "generic/builtins.h"
#include "generic/color.h"
#include "test_util.h"

static uint32_t rng_state = 2024u;

/* A uniform number in [0, 1). */
static double rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

enum { MAXN = 401 };

/* A discretisation of n samples over u in [0, 1] with smooth positive weights like colour matching functions
 * (three bumps), scaled by a random factor per sample. */
static void make_fit(int n, double *u, double *w, GUpliftFit *f)
{
    static const double centre[3] = {0.55, 0.42, 0.2}, width[3] = {0.12, 0.1, 0.08};
    for (int k = 0; k < n; k++) {
        u[k] = n > 1 ? (double)k / (n - 1) : 0.5;
        for (int c = 0; c < 3; c++) {
            double t = (u[k] - centre[c]) / width[c];
            w[c * n + k] = exp(-0.5 * t * t) * (0.5 + rnd()) / n;
        }
    }
    *f = (GUpliftFit){n, u, {w, w + n, w + 2 * n}, {0, 0, 0}};
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < n; k++)
            f->white[c] += w[c * n + k];
}

static void test_fit_bodies_agree(void **state)
{
    (void)state;
    if (!guplift_fit_vectorised())
        printf("the processor has no AVX2: both calls run the scalar body\n");
    static const int sizes[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 13, 41, 81, 401};
    static double u[MAXN], w[3 * MAXN];
    int per_size = TU_SANITIZED ? 8 : 60, fits = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof *sizes; si++) {
        int n = sizes[si];
        GUpliftFit f;
        make_fit(n, u, w, &f);
        for (int t = 0; t < per_size; t++) {
            /* targets: the XYZ of a random sigmoid (reachable) or, one in four, a random XYZ (often not) */
            double xyz[3], truth[3] = {40.0 * (rnd() - 0.5), 40.0 * (rnd() - 0.5), 8.0 * (rnd() - 0.5)};
            for (int c = 0; c < 3; c++) {
                xyz[c] = 0.0;
                for (int k = 0; k < n; k++) {
                    double x = (truth[0] * u[k] + truth[1]) * u[k] + truth[2];
                    xyz[c] += w[c * n + k] * (0.5 + 0.5 * x / sqrt(1.0 + x * x));
                }
                if (t % 4 == 3)
                    xyz[c] = f.white[c] * rnd();
            }
            double start[3] = {4.0 * (rnd() - 0.5), 4.0 * (rnd() - 0.5), 2.0 * (rnd() - 0.5)};
            double cv[3], cs[3];
            memcpy(cv, start, sizeof cv);
            memcpy(cs, start, sizeof cs);
            int iterations = t % 3 == 0 ? 100 : 20;
            double dv = guplift_fit_solve(&f, xyz, cv, iterations, 2e-5);
            double ds = guplift_fit_solve_scalar(&f, xyz, cs, iterations, 2e-5);
            if (memcmp(cv, cs, sizeof cv) != 0 || memcmp(&dv, &ds, sizeof dv) != 0)
                fail_msg("n %d target %d: vector c (%a %a %a) left %a, scalar c (%a %a %a) left %a", n, t, cv[0],
                         cv[1], cv[2], dv, cs[0], cs[1], cs[2], ds);
            assert_true(isfinite(dv));
            fits++;
        }
    }
    printf("%d fits: vector and scalar bodies equal bit for bit\n", fits);
}

static void test_sigmoid_samples_agree(void **state)
{
    (void)state;
    enum { N = 90 };
    double x[N], f[N];
    float vec[N + 1], sca[N + 1];
    int compared = 0;
    for (int trial = 0; trial < 40; trial++) {
        GUplift u = {{40.0 * (rnd() - 0.5), 40.0 * (rnd() - 0.5), 8.0 * (rnd() - 0.5)}, 1.0 + 3.0 * rnd(), 0, {0}};
        if (trial == 1 || trial == 2) /* white and black: S's limits */
            u.c[0] = u.c[1] = 0.0, u.c[2] = trial == 1 ? INFINITY : -INFINITY;
        if (trial == 3) /* a polynomial whose square overflows */
            u.c[2] = 1e200;
        for (int k = 0; k < N; k++) {
            x[k] = rnd() * 1.2 - 0.1;
            f[k] = trial % 2 ? 0.5 + rnd() : 1.0;
        }
        for (int n = 0; n <= N; n++) {
            vec[n] = sca[n] = -7.0f; /* the sample past the end stays as it was */
            guplift_sigmoid_samples(&u, n, x, f, vec);
            guplift_sigmoid_samples_scalar(&u, n, x, f, sca);
            if (memcmp(vec, sca, sizeof(float) * (size_t)(n + 1)) != 0)
                fail_msg("trial %d, %d samples: the vector and scalar samples differ", trial, n);
            assert_true(vec[n] == -7.0f);
            compared++;
        }
        if (trial == 1 || trial == 2)
            assert_true(vec[N - 1] == (trial == 1 ? (float)(u.scale * f[N - 1]) : 0.0f));
    }
    printf("%d sample vectors: vector and scalar bodies equal bit for bit\n", compared);
}

/* from_rgb of colours in a fixed order, twice over, in several models: the second pass must give the first pass's
 * bits. The colours repeat within a pass too, between others, as texels of an image do. */
static void test_from_rgb_repeats_exactly(void **state)
{
    (void)state;
    static const char *const names[] = {"spectrum", "bispectral", "spectrum9", "spectrum"};
    GColorModelOptions coarse = {.step_nm = 10.0};
    enum { MODELS = 4, COLOURS = 24, PASSES = 2 };
    GColorModel *m[MODELS];
    GError err;
    for (int i = 0; i < MODELS; i++)
        assert_int_equal(gcolormodel_create(names[i], i == 3 ? &coarse : NULL, &m[i], &err), G_OK);
    double rgb[COLOURS][3];
    for (int k = 0; k < COLOURS; k++)
        for (int c = 0; c < 3; c++)
            rgb[k][c] = k % 5 == 4 ? rgb[k - 3][c] : rnd() * (k % 7 == 0 ? 3.0 : 1.0);
    static float first[MODELS][2][COLOURS][1024];
    for (int pass = 0; pass < PASSES; pass++)
        for (int k = 0; k < COLOURS; k++)
            for (int role = 0; role < 2; role++)
                for (int i = 0; i < MODELS; i++) {
                    GColor c;
                    assert_true(m[i]->nvalues <= 1024);
                    assert_int_equal(gcolor_alloc(&c, m[i]), G_OK);
                    assert_int_equal(gcolor_from_rgb(&c, rgb[k], (GColorRole)role), G_OK);
                    size_t bytes = (size_t)m[i]->nvalues * sizeof(float);
                    if (pass == 0)
                        memcpy(first[i][role][k], c.v, bytes);
                    else if (memcmp(first[i][role][k], c.v, bytes) != 0)
                        fail_msg("%s colour %d role %d: a second from_rgb differs from the first", names[i], k, role);
                    gcolor_free(&c);
                }
    for (int i = 0; i < MODELS; i++)
        gcolormodel_destroy(m[i]);
}

/* The range kept with the model equals the corners' extremes measured here, in both roles, asked twice. */
static void test_rgb_range_kept_equals_measured(void **state)
{
    (void)state;
    static const char *const names[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    for (int i = 0; i < 4; i++) {
        GColorModel *m;
        GError err;
        assert_int_equal(gcolormodel_create(names[i], NULL, &m, &err), G_OK);
        for (int role = 0; role < 3; role++) {
            double lo = 0.0, hi = 0.0;
            GColor p;
            assert_int_equal(gcolor_alloc(&p, m), G_OK);
            for (int corner = 1; corner < 8; corner++) {
                double e[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
                assert_int_equal(gcolor_from_rgb(&p, e, (GColorRole)role), G_OK);
                for (int k = 0; k < m->nvalues; k++) {
                    lo = fmin(lo, p.v[k]);
                    hi = fmax(hi, p.v[k]);
                }
            }
            gcolor_free(&p);
            for (int again = 0; again < 2; again++) {
                double klo, khi;
                assert_int_equal(gcolormodel_rgb_range(m, (GColorRole)role, &klo, &khi), G_OK);
                if (klo != lo || khi != hi)
                    fail_msg("%s role %d: kept range %a..%a, measured %a..%a", names[i], role, klo, khi, lo, hi);
            }
        }
        gcolormodel_destroy(m);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fit_bodies_agree),
        cmocka_unit_test(test_sigmoid_samples_agree),
        cmocka_unit_test(test_from_rgb_repeats_exactly),
        cmocka_unit_test(test_rgb_range_kept_equals_measured),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
