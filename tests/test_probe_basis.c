/* test_probe_basis.c - the basis-function approximations (spherical harmonics L1..L4 and their Hanning
 * window, the ambient cube, spherical Gaussians), the variance-minimising cut and the sMAPE measure. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/services/probe.h"

/* Path of a shared probe, or NULL when the data is not there. */
static const char *shared_probe(const char *name, char *buf, size_t size)
{
    const char *src = getenv("GENERIC_SOURCE_DIR");
    if (src) {
        snprintf(buf, size, "%s/../shared/data/probes/%s", src, name);
        if (access(buf, R_OK) == 0)
            return buf;
    }
    snprintf(buf, size, "/work/shared/data/probes/%s", name);
    return access(buf, R_OK) == 0 ? buf : NULL;
}

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

typedef void (*RadianceFn)(const void *user, GVec3 d, float rgb[3]);

/* A lat-long probe of h rows whose pixel (u, v) is f at the pixel's centre direction. */
static GProbe *probe_from(int h, RadianceFn f, const void *user)
{
    const int w = 2 * h;
    float *px = malloc(sizeof(float) * 3 * w * h);
    assert_non_null(px);
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(w, h, NULL, &p, NULL), G_OK);
    for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++)
            f(user, gprobe_direction(p, u + 0.5, v + 0.5), px + 3 * ((size_t)v * w + u));
    gprobe_destroy(p);
    p = NULL;
    assert_int_equal(gprobe_create(w, h, px, &p, NULL), G_OK);
    free(px);
    return p;
}

static void sh_radiance(const void *user, GVec3 d, float rgb[3])
{
    double out[3];
    gprobe_sh_radiance(user, d, out);
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)out[c];
}

/* A probe made of the harmonics of order <= L is given back by the order-L projection: coefficients,
 * radiance and irradiance (up to the pixel quadrature, which the resolution bounds). Order 2 equals SH9. */
static void test_sh_reproduces_its_order(void **state)
{
    (void)state;
    unsigned seed = 7;
    for (int L = 1; L <= GPROBE_SH_MAX_ORDER; L++) {
        GProbeSH truth = {0};
        truth.order = L;
        for (int c = 0; c < 3; c++) {
            truth.c[0][c] = 4.0 + c; /* large enough that the radiance stays positive */
            for (int k = 1; k < GPROBE_SH_COEFFS(L); k++)
                truth.c[k][c] = 0.6 * (rnd(&seed) - 0.5);
        }
        GProbe *p = probe_from(96, sh_radiance, &truth);
        assert_int_equal(gprobe_clamped_count(p), 0);
        GProbeSH sh;
        assert_int_equal(gprobe_sh_project(p, L, &sh, NULL), G_OK);
        for (int k = 0; k < GPROBE_SH_COEFFS(L); k++)
            for (int c = 0; c < 3; c++)
                assert_true(fabs(sh.c[k][c] - truth.c[k][c]) < 2e-3);
        GVec3 n[200];
        double E[600], Et[600];
        gprobe_fibonacci(200, n);
        gprobe_sh_irradiance(&sh, n, 200, E);
        assert_int_equal(gprobe_irradiance(p, n, 200, Et, NULL), G_OK);
        for (int i = 0; i < 600; i++)
            assert_true(fabs(E[i] - Et[i]) < 2e-3 * Et[i]);
        if (L == 2) {
            GProbeSH9 s9;
            gprobe_sh9_project(p, &s9);
            for (int k = 0; k < 9; k++)
                for (int c = 0; c < 3; c++)
                    assert_true(fabs(s9.c[k][c] - sh.c[k][c]) < 1e-9);
        }
        gprobe_destroy(p);
    }
    GError err;
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(8, 4, NULL, &p, NULL), G_OK);
    GProbeSH sh;
    assert_int_equal(gprobe_sh_project(p, 5, &sh, &err), G_ERR_INVALID);
    assert_int_equal(gprobe_sh_project(p, 0, &sh, &err), G_ERR_INVALID);
    gprobe_destroy(p);
}

typedef struct Sun {
    GVec3 dir;
    double cos_radius, sky, sun;
} Sun;

static void sun_radiance(const void *user, GVec3 d, float rgb[3])
{
    const Sun *s = user;
    double v = gvec3_dot(d, s->dir) > s->cos_radius ? s->sun : s->sky;
    rgb[0] = rgb[1] = rgb[2] = (float)v;
}

/* Hanning windowing lowers the negative irradiance (ringing) of SH L2 on a probe with a small bright sun. */
static void test_window_reduces_ringing(void **state)
{
    (void)state;
    Sun sun = {gvec3_normalize(gvec3(0.3, -0.2, 0.9)), cos(3.0 * M_PI / 180.0), 0.02, 2000.0};
    GProbe *p = probe_from(64, sun_radiance, &sun);
    const int m = 2000;
    GVec3 *n = malloc(sizeof *n * m);
    double *E = malloc(sizeof *E * 3 * m);
    gprobe_fibonacci(m, n);
    double worst[2] = {0, 0};
    int negative[2] = {0, 0};
    for (int w = 0; w < 2; w++) {
        GProbeBasis b;
        assert_int_equal(gprobe_basis_fit(p, w ? GPROBE_BASIS_SH_HANNING : GPROBE_BASIS_SH, 9, &b, NULL), G_OK);
        gprobe_basis_irradiance(&b, n, m, E);
        for (int i = 0; i < m; i++) {
            worst[w] = fmin(worst[w], E[3 * i]);
            negative[w] += E[3 * i] < 0.0;
        }
        gprobe_basis_free(&b);
    }
    assert_true(worst[0] < 0.0);                /* plain L2 rings below zero opposite the sun */
    assert_true(worst[1] > 0.6 * worst[0]);    /* the window nearly halves the worst of it */
    assert_true(negative[1] < negative[0]);
    free(n);
    free(E);
    gprobe_destroy(p);
}

static void lobe_radiance(const void *user, GVec3 d, float rgb[3])
{
    const GProbeSGLobe *l = user;
    double g = exp(l->sharpness * (gvec3_dot(d, l->axis) - 1.0));
    for (int c = 0; c < 3; c++)
        rgb[c] = (float)(l->amp[c] * g);
}

/* A probe that is one Gaussian lobe: every fit gives back its axis, sharpness and amplitude, and the lobe's
 * irradiance matches the probe's ground truth. */
static void test_sg_recovers_one_lobe(void **state)
{
    (void)state;
    const double sharp[3] = {2.0, 12.0, 60.0};
    for (int s = 0; s < 3; s++) {
        GProbeSGLobe lobe = {gvec3_normalize(gvec3(0.3, 0.5, 0.7)), sharp[s], {3.0, 1.5, 0.5}};
        GProbe *p = probe_from(96, lobe_radiance, &lobe);
        for (int f = GPROBE_BASIS_SG_NAIVE; f <= GPROBE_BASIS_SG_AMBIENT; f++) {
            GProbeBasis b;
            assert_int_equal(gprobe_basis_fit(p, (GProbeBasisKind)f, 1, &b, NULL), G_OK);
            const GProbeSGLobe *l = &b.lobes[0];
            assert_true(gvec3_dot(l->axis, lobe.axis) > cos(0.5 * M_PI / 180.0));
            assert_true(fabs(l->sharpness / lobe.sharpness - 1.0) < 0.02);
            for (int c = 0; c < 3; c++)
                assert_true(fabs(l->amp[c] / lobe.amp[c] - 1.0) < 0.02);
            assert_true(fabs(b.ambient[0]) < 0.01 * lobe.amp[0]);
            GVec3 n[300];
            double E[900], Et[900], emax = 0.0;
            gprobe_fibonacci(300, n);
            gprobe_basis_irradiance(&b, n, 300, E);
            assert_int_equal(gprobe_irradiance(p, n, 300, Et, NULL), G_OK);
            for (int i = 0; i < 900; i++)
                emax = fmax(emax, Et[i]);
            for (int i = 0; i < 900; i++)
                assert_true(fabs(E[i] - Et[i]) < 0.02 * emax);
            gprobe_basis_free(&b);
        }
        gprobe_destroy(p);
    }
    /* the lobe irradiance: a flat lobe is a uniform sky (E = pi), a sharp one a directional light */
    assert_true(fabs(gprobe_sg_lobe_irradiance(1e-6, 0.3) - M_PI) < 1e-4);
    double l = 5000.0, integral = 2.0 * M_PI / l;
    assert_true(fabs(gprobe_sg_lobe_irradiance(l, 0.6) / (0.6 * integral) - 1.0) < 2e-3);
    assert_true(gprobe_sg_lobe_irradiance(l, -0.2) < 1e-9);
}

/* Non-negative least squares keeps every amplitude >= 0, where least squares does not on a probe with a
 * sharp sun over a dim sky; its radiance error lies between. */
static void test_sg_nnls_nonnegative(void **state)
{
    (void)state;
    char buf[600];
    const char *path = shared_probe("grace.hdr", buf, sizeof buf);
    GProbe *p = NULL;
    if (path) {
        assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, NULL), G_OK);
    } else {
        Sun sun = {gvec3_normalize(gvec3(0.3, -0.2, 0.9)), cos(3.0 * M_PI / 180.0), 0.02, 2000.0};
        p = probe_from(64, sun_radiance, &sun);
    }
    const int counts[3] = {4, 12, 24};
    for (int k = 0; k < 3; k++) {
        GProbeBasis b;
        assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_SG_NNLS, counts[k], &b, NULL), G_OK);
        double total = 0.0;
        for (int i = 0; i < b.size; i++)
            for (int c = 0; c < 3; c++) {
                assert_true(b.lobes[i].amp[c] >= 0.0);
                total += b.lobes[i].amp[c];
            }
        assert_true(total > 0.0);
        gprobe_basis_free(&b);
    }
    gprobe_destroy(p);
}

static void const_radiance(const void *user, GVec3 d, float rgb[3])
{
    (void)d;
    const double *c = user;
    for (int k = 0; k < 3; k++)
        rgb[k] = (float)c[k];
}

/* A uniform sky of radiance c gives E = pi c for every normal: the ambient cube's six faces all hold it. */
static void test_ambient_cube_uniform(void **state)
{
    (void)state;
    const double c[3] = {1.0, 0.5, 0.25};
    GProbe *p = probe_from(32, const_radiance, c);
    GProbeBasis b;
    assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_AMBIENT_CUBE, 6, &b, NULL), G_OK);
    for (int f = 0; f < 6; f++)
        for (int k = 0; k < 3; k++)
            assert_true(fabs(b.cube.c[f][k] - M_PI * c[k]) < 2e-3 * M_PI * c[k]);
    double rgb[3];
    gprobe_basis_radiance(&b, gvec3(0.0, 0.6, 0.8), rgb);
    assert_true(fabs(rgb[0] - 1.0) < 2e-3);
    gprobe_basis_free(&b);
    GError err;
    assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_AMBIENT_CUBE, 9, &b, &err), G_ERR_INVALID);
    assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_SH, 10, &b, &err), G_ERR_INVALID);
    assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_SG_LS, 0, &b, &err), G_ERR_INVALID);
    assert_int_equal(gprobe_basis_fit(p, GPROBE_BASIS_SG_LS, GPROBE_SG_MAX_LOBES + 1, &b, &err), G_ERR_INVALID);
    GProbeBasisKind kind;
    assert_int_equal(gprobe_basis_parse("sg-nnls", &kind, NULL), G_OK);
    assert_int_equal(kind, GPROBE_BASIS_SG_NNLS);
    assert_int_equal(gprobe_basis_parse("sh9", &kind, &err), G_ERR_NOTFOUND);
    assert_string_equal(gprobe_basis_unit(GPROBE_BASIS_SG_AMBIENT), "lobes");
    assert_string_equal(gprobe_basis_unit(GPROBE_BASIS_SH), "coefficients");
    gprobe_destroy(p);
}

static double summed_variance(const GProbe *p, GProbeTechnique t, int n)
{
    GProbeRect *r = malloc(sizeof *r * n);
    assert_int_equal(gprobe_cut_regions(p, t, n, r, NULL), G_OK);
    double s = 0.0;
    long area = 0;
    for (int i = 0; i < n; i++) {
        s += gprobe_region_variance(p, &r[i]);
        area += (long)(r[i].u1 - r[i].u0) * (r[i].v1 - r[i].v0);
    }
    assert_int_equal(area, (long)gprobe_width(p) * gprobe_height(p)); /* the regions tile the image */
    free(r);
    return s;
}

/* On each shared probe the variance cut leaves less summed within-region variance than median cut. */
static void test_variance_cut_beats_median_cut(void **state)
{
    (void)state;
    const char *names[3] = {"grace.hdr", "pisa.hdr", "uffizi.hdr"};
    int tested = 0;
    for (int k = 0; k < 3; k++) {
        char buf[600];
        const char *path = shared_probe(names[k], buf, sizeof buf);
        if (!path)
            continue;
        GProbe *p = NULL;
        assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, NULL), G_OK);
        for (int n = 4; n <= 64; n *= 2) {
            double mc = summed_variance(p, GPROBE_MEDIANCUT, n), vc = summed_variance(p, GPROBE_VARIANCE, n);
            assert_true(vc < mc);
        }
        GProbeLight l[16];
        double total[3] = {0, 0, 0}, power[3] = {0, 0, 0};
        assert_int_equal(gprobe_approximate(p, GPROBE_VARIANCE, 16, NULL, l, NULL), G_OK);
        for (int i = 0; i < 16; i++)
            for (int c = 0; c < 3; c++)
                total[c] += l[i].rgb[c];
        const float *q = gprobe_weights(p);
        for (int i = 0; i < gprobe_width(p) * gprobe_height(p); i++)
            for (int c = 0; c < 3; c++)
                power[c] += q[3 * i + c];
        for (int c = 0; c < 3; c++)
            assert_true(fabs(total[c] - power[c]) < 1e-6 * power[c]); /* the lights carry all the energy */
        gprobe_destroy(p);
        tested++;
    }
    if (!tested)
        skip();
    /* a probe of 8 pixels cannot give 9 regions; its lights fill up with black ones */
    GProbe *p = NULL;
    const float px[24] = {1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5, 5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8};
    assert_int_equal(gprobe_create(4, 2, px, &p, NULL), G_OK);
    GProbeLight l[9];
    GProbeRect r[9];
    GError err;
    assert_int_equal(gprobe_variance_cut(p, 9, l, NULL), G_OK);
    assert_true(l[8].rgb[0] == 0.0);
    assert_int_equal(gprobe_cut_regions(p, GPROBE_VARIANCE, 9, r, &err), G_ERR_INVALID);
    assert_int_equal(gprobe_cut_regions(p, GPROBE_KMEANS, 2, r, &err), G_ERR_INVALID);
    gprobe_destroy(p);
}

/* sMAPE: 100 mean 2 |a - t| / (|a| + |t|). */
static void test_smape(void **state)
{
    (void)state;
    const double truth[6] = {1, 1, 1, 2, 2, 2}, approx[6] = {3, 3, 3, 2, 2, 2};
    GProbeErrors e;
    gprobe_compare(truth, approx, 2, &e);
    assert_true(fabs(e.smape - 50.0) < 1e-9); /* 100 and 0 */
    assert_true(fabs(e.mean_rel - 100.0) < 1e-9);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sh_reproduces_its_order),
        cmocka_unit_test(test_window_reduces_ringing),
        cmocka_unit_test(test_sg_recovers_one_lobe),
        cmocka_unit_test(test_sg_nnls_nonnegative),
        cmocka_unit_test(test_ambient_cube_uniform),
        cmocka_unit_test(test_variance_cut_beats_median_cut),
        cmocka_unit_test(test_smape),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
