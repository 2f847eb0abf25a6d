/* test_probe_techniques.c - the approximation techniques: energy, the single bright pixel, counts,
 * determinism, and on the shared real probes: irradiance optimisation beats its start, SH9 accuracy. */
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

static const char *const shared_probes[] = {"grace.hdr", "pisa.hdr", "uffizi.hdr"};

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

static void sum_lights(const GProbeLight *l, int n, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            out[c] += l[i].rgb[c];
}

static void sum_weights(const GProbe *p, double out[3])
{
    const float *q = gprobe_weights(p);
    out[0] = out[1] = out[2] = 0.0;
    for (int i = 0; i < gprobe_width(p) * gprobe_height(p); i++)
        for (int c = 0; c < 3; c++)
            out[c] += q[3 * i + c];
}

static GProbe *random_probe(int h, unsigned seed)
{
    const int w = 2 * h;
    float *px = malloc(sizeof(float) * 3 * w * h);
    for (int i = 0; i < 3 * w * h; i++)
        px[i] = (float)rnd(&seed);
    for (int k = 0; k < 3; k++) {
        int i = (int)(rnd(&seed) * w * h);
        px[3 * i] = 800.0f;
        px[3 * i + 1] = 600.0f;
        px[3 * i + 2] = 400.0f;
    }
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(w, h, px, &p, NULL), G_OK);
    free(px);
    return p;
}

/* A black probe with one bright pixel: every technique puts the pixel's power into lights in its direction. */
static void test_single_bright_pixel(void **state)
{
    (void)state;
    const int w = 64, h = 32, pu = 37, pv = 9;
    float *px = calloc((size_t)3 * w * h, sizeof(float));
    px[3 * (pv * w + pu)] = 100.0f;
    px[3 * (pv * w + pu) + 1] = 50.0f;
    px[3 * (pv * w + pu) + 2] = 25.0f;
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(w, h, px, &p, NULL), G_OK);
    const float *q = gprobe_weights(p) + 3 * (pv * w + pu);
    double power[3];
    gprobe_power(p, power);
    GVec3 d = gprobe_direction(p, pu + 0.5, pv + 0.5);
    const int counts[GPROBE_TECHNIQUE_COUNT] = {8, 5, 6, 4, 7};
    for (int t = 0; t < GPROBE_TECHNIQUE_COUNT; t++) {
        GProbeLight lights[8];
        GError err;
        assert_int_equal(gprobe_approximate(p, (GProbeTechnique)t, counts[t], NULL, lights, &err), G_OK);
        double sum[3];
        sum_lights(lights, counts[t], sum);
        for (int c = 0; c < 3; c++) {
            assert_true(fabs(sum[c] / q[c] - 1.0) < 1e-6);     /* its weight Q */
            assert_true(fabs(sum[c] / power[c] - 1.0) < 1e-3); /* P times its exact solid angle */
        }
        for (int i = 0; i < counts[t]; i++) {
            assert_true(fabs(gvec3_length(lights[i].dir) - 1.0) < 1e-9);
            if (lights[i].rgb[0] > 1e-9 * q[0])
                assert_true(gvec3_dot(lights[i].dir, d) > 1.0 - 1e-9);
        }
    }
    free(px);
    gprobe_destroy(p);
}

static void test_median_cut_counts_and_energy(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 11u);
    double total[3];
    sum_weights(p, total);
    GProbeLight lights[128];
    for (int k = 0; k <= 7; k++) {
        int n = 1 << k;
        for (int i = 0; i < 128; i++)
            lights[i].rgb[0] = -1.0; /* marks slots not written */
        assert_int_equal(gprobe_median_cut(p, n, lights, NULL), G_OK);
        double sum[3];
        sum_lights(lights, n, sum);
        for (int c = 0; c < 3; c++)
            assert_true(fabs(sum[c] / total[c] - 1.0) < 1e-9);
        for (int i = 0; i < n; i++)
            assert_true(lights[i].rgb[0] >= 0.0);
        if (n < 128)
            assert_float_equal(lights[n].rgb[0], -1.0, 0.0);
    }
    GError err;
    assert_int_equal(gprobe_median_cut(p, 6, lights, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "power of two"));
    assert_int_equal(gprobe_median_cut(p, 0, lights, &err), G_ERR_INVALID);
    gprobe_destroy(p);
}

/* The first split of median cut halves the energy, along the longer side. */
static void test_median_cut_halves_energy(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 5u);
    GProbeLight l[2];
    assert_int_equal(gprobe_median_cut(p, 2, l, NULL), G_OK);
    double e0 = 0.2126 * l[0].rgb[0] + 0.7152 * l[0].rgb[1] + 0.0722 * l[0].rgb[2];
    double e1 = 0.2126 * l[1].rgb[0] + 0.7152 * l[1].rgb[1] + 0.0722 * l[1].rgb[2];
    /* the cut falls between columns: the halves differ by at most one column's energy */
    const float *q = gprobe_weights(p);
    double col_max = 0.0;
    for (int u = 0; u < 64; u++) {
        double c = 0.0;
        for (int v = 0; v < 32; v++)
            c += 0.2126 * q[3 * (v * 64 + u)] + 0.7152 * q[3 * (v * 64 + u) + 1] + 0.0722 * q[3 * (v * 64 + u) + 2];
        col_max = fmax(col_max, c);
    }
    assert_true(fabs(e0 - e1) <= col_max + 1e-9);
    /* the 64 x 32 image is 2 pi wide and pi high: the first cut is vertical, so the lights differ in phi */
    double x0, y0, x1, y1;
    gprobe_position(p, l[0].dir, &x0, &y0);
    gprobe_position(p, l[1].dir, &x1, &y1);
    assert_true(fabs(x0 - x1) > 4.0);
    gprobe_destroy(p);
}

static void test_adaptive_any_count(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 13u);
    double total[3];
    sum_weights(p, total);
    const int counts[] = {1, 3, 7, 100};
    for (int k = 0; k < 4; k++) {
        int n = counts[k];
        GProbeLight *l = calloc((size_t)n, sizeof *l);
        assert_int_equal(gprobe_adaptive_median_cut(p, n, l, NULL), G_OK);
        double sum[3];
        sum_lights(l, n, sum);
        for (int c = 0; c < 3; c++)
            assert_true(fabs(sum[c] / total[c] - 1.0) < 1e-9);
        free(l);
    }
    gprobe_destroy(p);
}

/* More lights approximate better: the error of adaptive median cut and k-means falls with N. */
static void test_errors_fall_with_count(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 17u);
    const int m = 2000;
    GVec3 *n = malloc(sizeof *n * m);
    double *truth = malloc(sizeof(double) * 3 * m), *approx = malloc(sizeof(double) * 3 * m);
    gprobe_fibonacci(m, n);
    assert_int_equal(gprobe_irradiance(p, n, m, truth, NULL), G_OK);
    GProbeTechnique ts[2] = {GPROBE_ADAPTIVE, GPROBE_KMEANS};
    for (int t = 0; t < 2; t++) {
        double prev = 1e30;
        for (int k = 1; k <= 64; k *= 4) {
            GProbeLight l[64];
            assert_int_equal(gprobe_approximate(p, ts[t], k, NULL, l, NULL), G_OK);
            gprobe_lights_irradiance(l, k, n, m, approx);
            GProbeErrors e;
            gprobe_compare(truth, approx, m, &e);
            assert_true(e.mean_rel < prev);
            prev = e.mean_rel;
        }
        assert_true(prev < 3.0);
    }
    free(n);
    free(truth);
    free(approx);
    gprobe_destroy(p);
}

static void test_kmeans_is_deterministic(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 19u);
    GProbeLight a[12], b[12];
    assert_int_equal(gprobe_kmeans(p, 12, NULL, a, NULL), G_OK);
    assert_int_equal(gprobe_kmeans(p, 12, NULL, b, NULL), G_OK);
    assert_memory_equal(a, b, sizeof a);
    double total[3], sum[3];
    sum_weights(p, total);
    sum_lights(a, 12, sum);
    for (int c = 0; c < 3; c++)
        assert_true(fabs(sum[c] / total[c] - 1.0) < 1e-9);
    gprobe_destroy(p);
}

static void test_technique_names(void **state)
{
    (void)state;
    for (int t = 0; t < GPROBE_TECHNIQUE_COUNT; t++) {
        GProbeTechnique back;
        assert_int_equal(gprobe_technique_parse(gprobe_technique_name((GProbeTechnique)t), &back, NULL), G_OK);
        assert_int_equal(back, t);
    }
    GProbeTechnique x;
    GError err;
    assert_int_equal(gprobe_technique_parse("lightcuts", &x, &err), G_ERR_NOTFOUND);
    assert_non_null(strstr(err.message, "lightcuts"));
}

/* On each shared probe: the optimisation ends below where it started (the adaptive median cut it is
 * initialised from), on its own objective and on the paper's measure at other normals; and it converges. */
static void test_irradiance_beats_its_start(void **state)
{
    (void)state;
    int found = 0;
    for (int k = 0; k < 3; k++) {
        char buf[1024];
        const char *path = shared_probe(shared_probes[k], buf, sizeof buf);
        if (!path)
            continue;
        found++;
        GProbe *p = NULL;
        assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, NULL), G_OK);
        const int m = 2500, nl = 16;
        GVec3 *n = malloc(sizeof *n * m);
        double *truth = malloc(sizeof(double) * 3 * m), *approx = malloc(sizeof(double) * 3 * m);
        gprobe_fibonacci(m, n);
        assert_int_equal(gprobe_irradiance(p, n, m, truth, NULL), G_OK);
        GProbeLight init[16], fit[16];
        GProbeFitReport rep;
        GProbeOptions opt = {0};
        opt.fit_normals = 2000;
        assert_int_equal(gprobe_adaptive_median_cut(p, nl, init, NULL), G_OK);
        assert_int_equal(gprobe_irradiance_fit(p, nl, &opt, fit, &rep, NULL), G_OK);
        GProbeErrors e0, e1;
        gprobe_lights_irradiance(init, nl, n, m, approx);
        gprobe_compare(truth, approx, m, &e0);
        gprobe_lights_irradiance(fit, nl, n, m, approx);
        gprobe_compare(truth, approx, m, &e1);
        assert_true(rep.projected <= rep.initial);
        assert_true(rep.final < 0.5 * rep.initial);
        assert_true(rep.converged);
        assert_true(rep.reweighted >= 1); /* the reweighting towards absolute errors kept at least one round */
        assert_true(e1.mean_rel < 0.5 * e0.mean_rel);
        assert_true(e1.max_rel < e0.max_rel);
        for (int i = 0; i < nl; i++)
            for (int c = 0; c < 3; c++)
                assert_true(fit[i].rgb[c] >= 0.0);
        free(n);
        free(truth);
        free(approx);
        gprobe_destroy(p);
    }
    if (!found)
        skip();
}

/* Every light ends up carrying colour: on uffizi with 48 lights fitted at 400 normals, two lights lose all
 * colour in the first fit; they are moved where the model is too dark and the fit continues. */
static void test_irradiance_uses_every_light(void **state)
{
    (void)state;
    char buf[1024];
    const char *path = shared_probe("uffizi.hdr", buf, sizeof buf);
    if (!path)
        skip();
    GProbe *p = NULL;
    assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, NULL), G_OK);
    GProbeLight l[48];
    GProbeFitReport rep;
    GProbeOptions opt = {0};
    opt.fit_normals = 400;
    assert_int_equal(gprobe_irradiance_fit(p, 48, &opt, l, &rep, NULL), G_OK);
    assert_int_equal(rep.active, 48);
    assert_true(rep.converged);
    assert_true(rep.final < rep.projected);
    gprobe_destroy(p);
}

/* Ramamoorthi & Hanrahan's nine coefficients: mean error within 2% of the largest irradiance. */
static void test_sh9_accuracy_on_shared_probes(void **state)
{
    (void)state;
    int found = 0;
    for (int k = 0; k < 3; k++) {
        char buf[1024];
        const char *path = shared_probe(shared_probes[k], buf, sizeof buf);
        if (!path)
            continue;
        found++;
        GProbe *p = NULL;
        assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, NULL), G_OK);
        const int m = 2000;
        GVec3 *n = malloc(sizeof *n * m);
        double *truth = malloc(sizeof(double) * 3 * m), *approx = malloc(sizeof(double) * 3 * m);
        gprobe_fibonacci(m, n);
        assert_int_equal(gprobe_irradiance(p, n, m, truth, NULL), G_OK);
        GProbeSH9 sh;
        gprobe_sh9_project(p, &sh);
        gprobe_sh9_irradiance(&sh, n, m, approx);
        GProbeErrors e;
        gprobe_compare(truth, approx, m, &e);
        assert_true(e.mean_norm <= 2.0);
        assert_true(e.mean_norm > 0.1); /* nine coefficients cannot be exact on a real probe */
        free(n);
        free(truth);
        free(approx);
        gprobe_destroy(p);
    }
    if (!found)
        skip();
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_single_bright_pixel),
        cmocka_unit_test(test_median_cut_counts_and_energy),
        cmocka_unit_test(test_median_cut_halves_energy),
        cmocka_unit_test(test_adaptive_any_count),
        cmocka_unit_test(test_errors_fall_with_count),
        cmocka_unit_test(test_kmeans_is_deterministic),
        cmocka_unit_test(test_technique_names),
        cmocka_unit_test(test_irradiance_beats_its_start),
        cmocka_unit_test(test_irradiance_uses_every_light),
        cmocka_unit_test(test_sh9_accuracy_on_shared_probes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
