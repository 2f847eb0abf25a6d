/* test_microfacet.c - the microfacet kit (generic/kit/microfacet.h), the per-sample kernels (kit/color_map.h) and the
 * Fresnel terms on colours (kit/fresnel.h): D normalised (the integral of D(h) h.z is 1) and the visible-normal density
 * integrating to 1, by quadrature; G1 and G2 within their bounds; the samplers' moments against the quadrature of
 * their density; the conductor's Fresnel term against the complex-arithmetic closed form and its normal-incidence
 * value; the colour forms in every model against the scalar ones. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/kit/color_map.h"
#include "generic/kit/fresnel.h"
#include "generic/kit/microfacet.h"
#include "test_util.h"

#include <complex.h>

static const double alphas[] = {0.05, 0.3, 0.8, 1.0};

static GMicrofacet distribution(int d, int i, int aniso)
{
    double a = alphas[i];
    return gmicrofacet_make(d, a, aniso ? gfmin(1.0, 2.5 * a) : a);
}

static GVec3 dir(double theta, double phi) { return gvec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)); }

/* The integral over the upper hemisphere of f(h), by the midpoint rule in (s, phi) with cos theta = 1 - s^3, which
 * packs the points near the pole and resolves the narrow peak of alpha 0.05. */
typedef double (*HemiFn)(const GMicrofacet *m, GVec3 wo, GVec3 h, const void *extra);

static double integrate(const GMicrofacet *m, GVec3 wo, HemiFn f, const void *extra, int ns, int nphi)
{
    double sum = 0.0;
    for (int i = 0; i < ns; i++) {
        double s = (i + 0.5) / ns, u = 1.0 - s * s * s, du = 3.0 * s * s / ns; /* d(cos theta) */
        double st = sqrt(gfmax(0.0, 1.0 - u * u));
        for (int j = 0; j < nphi; j++) {
            double phi = 2.0 * M_PI * (j + 0.5) / nphi;
            GVec3 h = gvec3(st * cos(phi), st * sin(phi), u);
            sum += f(m, wo, h, extra) * du * (2.0 * M_PI / nphi);
        }
    }
    return sum;
}

static double d_cos(const GMicrofacet *m, GVec3 wo, GVec3 h, const void *extra)
{
    (void)wo, (void)extra;
    return gmicrofacet_d(m, h) * h.z;
}

static double visible(const GMicrofacet *m, GVec3 wo, GVec3 h, const void *extra)
{
    (void)extra;
    return gmicrofacet_pdf_visible(m, wo, h);
}

static void test_d_normalised(void **state)
{
    (void)state;
    for (int d = 0; d < 2; d++)
        for (int i = 0; i < 4; i++)
            for (int an = 0; an < 2; an++) {
                GMicrofacet m = distribution(d, i, an);
                assert_near(integrate(&m, gvec3(0, 0, 1), d_cos, NULL, 3000, 96), 1.0, 2e-3);
            }
}

static void test_visible_normalised(void **state)
{
    (void)state;
    for (int d = 0; d < 2; d++)
        for (int i = 0; i < 4; i++)
            for (int an = 0; an < 2; an++)
                for (int k = 0; k < 4; k++) {
                    GMicrofacet m = distribution(d, i, an);
                    GVec3 wo = dir((double[]){0.0, 0.6, 1.2, 1.5}[k], 0.7);
                    assert_near(integrate(&m, wo, visible, NULL, 3000, 96), 1.0, 3e-3);
                }
}

/* Smith's relation: the projected area of the visible facets is that of the macro surface, the integral of
 * G1(wo, h) max(0, wo.h) D(h) over h is wo.z (the same integral as above, checked at Lambda's exact form). And G1 and
 * G2 within their bounds at random directions. */
static void test_masking_bounds(void **state)
{
    (void)state;
    unsigned long long s = 11;
    for (int d = 0; d < 2; d++)
        for (int i = 0; i < 4; i++) {
            GMicrofacet m = distribution(d, i, 1);
            assert_near(gmicrofacet_lambda(&m, gvec3(0, 0, 1)), 0.0, 0.0);
            assert_true(isinf(gmicrofacet_lambda(&m, gvec3(1, 0, 0))));
            for (int k = 0; k < 20000; k++) {
                GVec3 wi = dir(acos(tu_uniform(&s)), 2 * M_PI * tu_uniform(&s));
                GVec3 wo = dir(acos(tu_uniform(&s)), 2 * M_PI * tu_uniform(&s));
                GVec3 h = gvec3_normalize(gvec3_add(wi, wo));
                double g1i = gmicrofacet_g1(&m, wi, h), g1o = gmicrofacet_g1(&m, wo, h);
                double g2 = gmicrofacet_g2(&m, wi, wo, h);
                assert_true(g1i >= 0.0 && g1i <= 1.0 && g1o >= 0.0 && g1o <= 1.0);
                assert_true(g2 >= 0.0 && g2 <= gfmin(g1i, g1o) + 1e-15);
                assert_true(g2 >= g1i * g1o - 1e-15); /* correlated heights mask no more than independent ones */
                assert_true(gmicrofacet_lambda(&m, wi) >= 0.0);
            }
        }
    /* Lambda of GGX at alpha 1 and 60 degrees: (sqrt(1 + tan^2) - 1) / 2 = (2 - 1) / 2 */
    GMicrofacet g = gmicrofacet_make(GMICROFACET_GGX, 1.0, 1.0);
    assert_near(gmicrofacet_lambda(&g, dir(M_PI / 3, 0.3)), 0.5, 1e-12);
    /* Beckmann at a = 1 / (alpha tan theta) = 1: (erf(1) - 1) / 2 + exp(-1) / (2 sqrt(pi)) */
    GMicrofacet b = gmicrofacet_make(GMICROFACET_BECKMANN, 1.0, 1.0);
    assert_near(gmicrofacet_lambda(&b, dir(M_PI / 4, 1.1)), (erf(1.0) - 1.0) / 2 + exp(-1.0) / (2 * sqrt(M_PI)),
                1e-12);
}

typedef struct Moment {
    int which;
} Moment;

static double moment_of(GVec3 h, int which)
{
    switch (which) {
    case 0: return h.x;
    case 1: return h.y;
    case 2: return h.z;
    default: return h.x * h.x - h.y * h.z;
    }
}

static double moment_density(const GMicrofacet *m, GVec3 wo, GVec3 h, const void *extra)
{
    return gmicrofacet_pdf_visible(m, wo, h) * moment_of(h, ((const Moment *)extra)->which);
}

/* The sampler draws from its density: four moments of 200000 draws agree with the quadrature of the density within
 * five standard errors, for both shapes, isotropic and anisotropic, at four angles of wo and four widths. */
static void test_sampler_moments(void **state)
{
    (void)state;
    unsigned long long s = 5;
    enum { N = 100000 };
    for (int d = 0; d < 2; d++)
        for (int i = 0; i < 4; i++)
            for (int an = 0; an < 2; an++)
                for (int k = 0; k < 4; k++) {
                    GMicrofacet m = distribution(d, i, an);
                    GVec3 wo = dir((double[]){0.0, 0.6, 1.2, 1.52}[k], 2.1);
                    double sum[4] = {0}, sum2[4] = {0};
                    for (int n = 0; n < N; n++) {
                        GVec3 h = gmicrofacet_sample_visible(&m, wo, tu_uniform(&s), tu_uniform(&s));
                        assert_true(h.z > 0.0 && gvec3_dot(h, wo) >= -1e-12);
                        assert_near(gvec3_length(h), 1.0, 1e-12);
                        for (int w = 0; w < 4; w++) {
                            double v = moment_of(h, w);
                            sum[w] += v;
                            sum2[w] += v * v;
                        }
                    }
                    for (int w = 0; w < 4; w++) {
                        double mean = sum[w] / N, var = sum2[w] / N - mean * mean;
                        double want = integrate(&m, wo, moment_density, &(Moment){w}, 2000, 96);
                        double tol = 5.0 * sqrt(gfmax(var, 0.0) / N) + 1e-3;
                        if (fabs(mean - want) > tol)
                            print_error("shape %d alpha %g aniso %d wo %d moment %d\n", d, alphas[i], an, k, w);
                        assert_near(mean, want, tol);
                    }
                }
}

static void test_pdf_reflect(void **state)
{
    (void)state;
    GMicrofacet m = gmicrofacet_make(GMICROFACET_GGX, 0.3, 0.3);
    GVec3 wo = dir(0.8, 0.2), wi = dir(0.5, 2.9), h = gvec3_normalize(gvec3_add(wo, wi));
    assert_near(gmicrofacet_pdf_reflect(&m, wo, wi), gmicrofacet_pdf_visible(&m, wo, h) / (4 * gvec3_dot(wo, h)),
                1e-15);
    assert_near(gmicrofacet_pdf_reflect(&m, wo, gvec3(wi.x, wi.y, -wi.z)), 0.0, 0.0);
    /* the rough-mirror term: D G2 / (4 wo.z) */
    assert_near(gmicrofacet_reflect_cos(&m, wi, wo),
                gmicrofacet_d(&m, h) * gmicrofacet_g2(&m, wi, wo, h) / (4 * wo.z), 1e-15);
    /* reciprocity of f cos / cos_in */
    assert_near(gmicrofacet_reflect_cos(&m, wi, wo) / wi.z, gmicrofacet_reflect_cos(&m, wo, wi) / wo.z, 1e-12);
    assert_near(gmicrofacet_alpha_from_roughness(0.4), 0.4, 0.0);
    assert_true(isnan(gmicrofacet_alpha_from_roughness(1.5)) && isnan(gmicrofacet_alpha_from_roughness(-0.1)));
    GMicrofacet c = gmicrofacet_make(7, NAN, 1e9);
    assert_int_equal(c.distribution, GMICROFACET_GGX);
    assert_near(c.alpha_x, GMICROFACET_ALPHA_MIN, 0.0);
    assert_near(c.alpha_y, 1e3, 0.0);
}

/* The closed form with complex arithmetic: rs = (cos - w) / (cos + w), rp = (n^2 cos - w) / (n^2 cos + w),
 * w = sqrt(n^2 - sin^2), n = eta + i k. */
static double fresnel_complex(double c, double eta, double k)
{
    double complex n = eta + I * k, n2 = n * n, w = csqrt(n2 - (1.0 - c * c));
    double complex rs = (c - w) / (c + w), rp = (n2 * c - w) / (n2 * c + w);
    return 0.5 * (creal(rs * conj(rs)) + creal(rp * conj(rp)));
}

static void test_fresnel_conductor(void **state)
{
    (void)state;
    const double nk[][2] = {{0.2, 3.0}, {1.1, 2.6}, {2.9, 3.1}, {0.05, 4.2}, {1.5, 0.0}, {3.0, 0.01}};
    for (size_t i = 0; i < sizeof nk / sizeof nk[0]; i++) {
        double n = nk[i][0], k = nk[i][1];
        assert_near(goptics_fresnel_conductor(1.0, n, k), ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k),
                    1e-14);
        for (int a = 0; a <= 89; a += 8) {
            double c = cos(a * M_PI / 180);
            double r = goptics_fresnel_conductor(c, n, k);
            assert_near(r, fresnel_complex(c, n, k), 1e-12);
            assert_true(r >= 0.0 && r <= 1.0);
            if (k == 0.0)
                assert_near(r, goptics_fresnel(c, 1.0 / n), 1e-12);
        }
        assert_near(goptics_fresnel_conductor(0.0, n, k), 1.0, 1e-12); /* grazing */
        assert_near(goptics_fresnel_conductor(-0.5, n, k), goptics_fresnel_conductor(0.5, n, k), 0.0);
    }
}

static double mix3(double a, double b, double c, const void *params)
{
    return a * b + c * *(const double *)params;
}

/* In every model: the colour forms equal the scalar forms sample by sample; a matrix operand is read by its
 * diagonal. */
static void test_colour_forms(void **state)
{
    (void)state;
    assert_int_equal(generic_register_builtins(NULL), G_OK);
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    for (int mi = 0; mi < 4; mi++) {
        GColorModel *m;
        GError err;
        assert_int_equal(gcolormodel_create(models[mi], NULL, &m, &err), G_OK);
        GColor eta, k, out, third;
        assert_int_equal(gcolor_alloc(&eta, m), G_OK);
        assert_int_equal(gcolor_alloc(&k, m), G_OK);
        assert_int_equal(gcolor_alloc(&out, m), G_OK);
        assert_int_equal(gcolor_alloc(&third, m), G_OK);
        int n = m->nvalues;
        for (int i = 0; i < n; i++) {
            eta.v[i] = (float)(0.1 + 2.0 * i / n);
            k.v[i] = (float)(3.5 - 2.5 * i / n);
            third.v[i] = (float)(0.25 * i);
        }
        for (int a = 0; a < 90; a += 10) {
            double c = cos(a * M_PI / 180);
            assert_int_equal(gmaterial_fresnel_conductor(&out, c, &eta, &k), G_OK);
            for (int i = 0; i < n; i++)
                assert_near(out.v[i], goptics_fresnel_conductor(c, eta.v[i], k.v[i]), 1e-7);
            assert_int_equal(gmaterial_fresnel_conductor_mix(&out, c, &eta, &k, 0.7, &third, 0.25), G_OK);
            for (int i = 0; i < n; i++)
                assert_near(out.v[i], 0.7 * goptics_fresnel_conductor(c, eta.v[i], k.v[i]) + 0.25 * third.v[i], 2e-6);
            assert_int_equal(gmaterial_fresnel_conductor_mix(&out, c, &eta, &k, 0.5, NULL, 3.0), G_OK);
            for (int i = 0; i < n; i++)
                assert_near(out.v[i], 0.5 * goptics_fresnel_conductor(c, eta.v[i], k.v[i]), 1e-6);
            assert_int_equal(gmaterial_fresnel_dielectric(&out, c, &eta), G_OK);
            for (int i = 0; i < n; i++)
                assert_near(out.v[i], goptics_fresnel(c, eta.v[i]), 1e-7);
        }
        double w = 2.0;
        assert_int_equal(gcolor_map(&out, mix3, &w, &eta, &k, &third), G_OK);
        for (int i = 0; i < n; i++)
            assert_near(out.v[i], (double)eta.v[i] * k.v[i] + 2.0 * third.v[i], 1e-5);
        assert_int_equal(gcolor_map(&out, mix3, &w, &eta, NULL, NULL), G_OK); /* missing operands read 0 */
        for (int i = 0; i < n; i++)
            assert_near(out.v[i], 0.0, 0.0);
        /* out aliasing an operand */
        assert_int_equal(gcolor_map(&k, mix3, &w, &k, &eta, NULL), G_OK);
        for (int i = 0; i < n; i++)
            assert_near(k.v[i], (3.5f - 2.5f * i / n) * (double)eta.v[i], 1e-5);
        GColor mat;
        assert_int_equal(gcolor_alloc(&mat, m), G_OK);
        if (tu_diagonal_matrix(m, &mat)) { /* diagonal 0.5: a * b of the diagonal */
            assert_int_equal(gcolor_map(&out, mix3, &w, &mat, &eta, NULL), G_OK);
            assert_int_equal(out.kind, GCOLOR_VECTOR);
            for (int i = 0; i < n; i++)
                assert_near(out.v[i], 0.5 * eta.v[i], 1e-6);
        }
        GColorModel *other;
        assert_int_equal(gcolormodel_create(mi ? "rgb" : "spectrum", NULL, &other, &err), G_OK);
        GColor foreign;
        assert_int_equal(gcolor_alloc(&foreign, other), G_OK);
        assert_int_equal(gcolor_map(&out, mix3, &w, &eta, &foreign, NULL), G_ERR_MISMATCH);
        assert_int_equal(gcolor_map(&out, NULL, &w, &eta, NULL, NULL), G_ERR_INVALID);
        gcolor_free(&foreign);
        gcolormodel_destroy(other);
        gcolor_free(&mat);
        gcolor_free(&eta);
        gcolor_free(&k);
        gcolor_free(&out);
        gcolor_free(&third);
        gcolormodel_destroy(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_d_normalised),      cmocka_unit_test(test_visible_normalised),
        cmocka_unit_test(test_masking_bounds),    cmocka_unit_test(test_sampler_moments),
        cmocka_unit_test(test_pdf_reflect),       cmocka_unit_test(test_fresnel_conductor),
        cmocka_unit_test(test_colour_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
