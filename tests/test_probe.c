/* test_probe.c - light probes: weights, ground-truth irradiance, conventions, conversion, rotation, loading. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/probe.h"
#include "test_alloc.h"

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

/* A probe whose pixels are f(direction of the pixel centre). */
static GProbe *probe_from(int h, void (*f)(GVec3, float *))
{
    const int w = 2 * h;
    float *px = malloc(sizeof(float) * 3 * w * h);
    for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++) {
            double th = M_PI * (v + 0.5) / h, ph = M_PI - 2.0 * M_PI * (u + 0.5) / w; /* probe.h's convention */
            f(gvec3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th)), px + 3 * (v * w + u));
        }
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(w, h, px, &p, NULL), G_OK);
    free(px);
    return p;
}

static void linear_field(GVec3 d, float *c)
{
    c[0] = (float)(1.0 + d.x);
    c[1] = (float)(1.0 + d.y);
    c[2] = (float)(1.0 + d.z);
}

static void constant_field(GVec3 d, float *c)
{
    (void)d;
    c[0] = 1.0f;
    c[1] = 2.0f;
    c[2] = 0.5f;
}

static GProbe *random_probe(int h, unsigned seed)
{
    const int w = 2 * h;
    float *px = malloc(sizeof(float) * 3 * w * h);
    for (int i = 0; i < 3 * w * h; i++)
        px[i] = (float)(rnd(&seed) * 2.0);
    for (int k = 0; k < 5; k++) { /* a few bright "suns" */
        int i = (int)(rnd(&seed) * w * h);
        px[3 * i] = px[3 * i + 1] = px[3 * i + 2] = 5000.0f;
    }
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(w, h, px, &p, NULL), G_OK);
    free(px);
    return p;
}

static void test_weights_sum_to_power(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 1u);
    const int w = gprobe_width(p), h = gprobe_height(p);
    const float *q = gprobe_weights(p), *px = gprobe_pixels(p);
    double sq[3] = {0, 0, 0}, power[3];
    for (int i = 0; i < w * h; i++)
        for (int c = 0; c < 3; c++)
            sq[c] += q[3 * i + c];
    gprobe_power(p, power);
    /* midpoint sin(theta) dtheta against the exact band solid angle: relative difference (pi/H)^2 / 24 */
    const double expected = (M_PI / h) * (M_PI / h) / 24.0;
    for (int c = 0; c < 3; c++) {
        double rel = sq[c] / power[c] - 1.0;
        assert_true(fabs(rel - expected) < 2e-6);
        assert_true(fabs(rel) < 1e-3);
    }
    /* the weight of one pixel, Eq. 4 at its centre */
    int u = 17, v = 5;
    double th = M_PI * (v + 0.5) / h;
    assert_float_equal(q[3 * (v * w + u) + 1], 2.0 * M_PI * M_PI * px[3 * (v * w + u) + 1] * sin(th) / (w * h), 1e-5);
    gprobe_destroy(p);
}

static void test_constant_probe_gives_pi_L(void **state)
{
    (void)state;
    GProbe *p = probe_from(64, constant_field);
    const int m = 2000;
    GVec3 *n = malloc(sizeof *n * m);
    double *E = malloc(sizeof(double) * 3 * m);
    gprobe_fibonacci(m, n);
    assert_int_equal(gprobe_irradiance(p, n, m, E, NULL), G_OK);
    const double L[3] = {1.0, 2.0, 0.5};
    double worst = 0.0;
    for (int i = 0; i < m; i++)
        for (int c = 0; c < 3; c++)
            worst = fmax(worst, fabs(E[3 * i + c] / (M_PI * L[c]) - 1.0));
    assert_true(worst < 0.005);
    /* the nine harmonics represent a constant exactly (up to the pixel sum) */
    GProbeSH9 sh;
    gprobe_sh9_project(p, &sh);
    gprobe_sh9_irradiance(&sh, n, m, E);
    for (int i = 0; i < m; i++)
        for (int c = 0; c < 3; c++)
            assert_true(fabs(E[3 * i + c] / (M_PI * L[c]) - 1.0) < 1e-3);
    free(n);
    free(E);
    gprobe_destroy(p);
}

static void test_fast_sum_matches_direct_sum(void **state)
{
    (void)state;
    GProbe *p = random_probe(48, 7u);
    const int m = 300;
    GVec3 *n = malloc(sizeof *n * m);
    gprobe_fibonacci(m, n);
    unsigned s = 99u;
    for (int i = 0; i < 100; i++) /* random normals */
        n[i] = gvec3_normalize(gvec3(rnd(&s) - 0.5, rnd(&s) - 0.5, rnd(&s) - 0.5));
    n[100] = gvec3(0, 0, 1); /* poles, the horizon, and the exact centre direction of a pixel */
    n[101] = gvec3(0, 0, -1);
    n[102] = gvec3(1, 0, 0);
    n[103] = gvec3(0, -1, 0);
    n[104] = gprobe_direction(p, 10.5, 20.5);
    n[105] = gvec3(0.3, 0.4, 0.0);
    double *a = malloc(sizeof(double) * 3 * m), *b = malloc(sizeof(double) * 3 * m);
    assert_int_equal(gprobe_irradiance(p, n, m, a, NULL), G_OK);
    assert_int_equal(gprobe_irradiance_direct(p, n, m, b, NULL), G_OK);
    for (int i = 0; i < 3 * m; i++)
        assert_true(fabs(a[i] - b[i]) <= 1e-10 * b[i] + 1e-12);
    free(n);
    free(a);
    free(b);
    gprobe_destroy(p);
}

static void test_direction_convention(void **state)
{
    (void)state;
    GProbe *p = probe_from(16, constant_field);
    const int w = gprobe_width(p), h = gprobe_height(p);
    GVec3 d = gprobe_direction(p, 0.0, 0.0); /* top edge: the zenith */
    assert_float_equal(d.z, 1.0, 1e-12);
    d = gprobe_direction(p, 0.0, h / 2.0); /* left edge on the horizon: -x */
    assert_float_equal(d.x, -1.0, 1e-12);
    d = gprobe_direction(p, w / 4.0, h / 2.0); /* a quarter to the right: +y */
    assert_float_equal(d.y, 1.0, 1e-12);
    d = gprobe_direction(p, w / 2.0, h / 2.0); /* the middle: +x */
    assert_float_equal(d.x, 1.0, 1e-12);
    d = gprobe_direction(p, 0.75 * w, h / 2.0); /* three quarters: -y, the right hand of a viewer facing +x */
    assert_float_equal(d.y, -1.0, 1e-12);
    assert_float_equal(gvec3_dot(gvec3_cross(gvec3(1, 0, 0), gvec3(0, 0, 1)), d), 1.0, 1e-12);
    d = gprobe_direction(p, 3.0, h); /* bottom edge: the nadir */
    assert_float_equal(d.z, -1.0, 1e-12);
    double x, y;
    for (double tx = 0.25; tx < w; tx += 3.7)
        for (double ty = 0.5; ty < h; ty += 2.9) {
            gprobe_position(p, gprobe_direction(p, tx, ty), &x, &y);
            assert_float_equal(x, tx, 1e-9);
            assert_float_equal(y, ty, 1e-9);
        }
    gprobe_destroy(p);
}

/* The ground truth is the same, to the last bit, with one thread and with several (fits built on it repeat). */
static void test_irradiance_repeats_exactly(void **state)
{
    (void)state;
    GProbe *p = random_probe(64, 11u);
    const int m = 2000;
    GVec3 *n = malloc(sizeof *n * m);
    gprobe_fibonacci(m, n);
    double *a = malloc(sizeof(double) * 3 * m), *b = malloc(sizeof(double) * 3 * m);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    assert_int_equal(gprobe_irradiance(p, n, m, a, NULL), G_OK);
    omp_set_num_threads(threads > 1 ? threads : 2);
    assert_int_equal(gprobe_irradiance(p, n, m, b, NULL), G_OK);
    omp_set_num_threads(threads);
    assert_memory_equal(a, b, sizeof(double) * 3 * m);
    free(n);
    free(a);
    free(b);
    gprobe_destroy(p);
}

static void test_clamping_counts_bad_pixels(void **state)
{
    (void)state;
    float px[8 * 4 * 3];
    for (int i = 0; i < 8 * 4 * 3; i++)
        px[i] = 1.0f;
    px[0] = -1.0f;
    px[1] = NAN; /* same pixel: counted once */
    px[7] = INFINITY;
    px[20] = -INFINITY;
    px[30] = 3e38f; /* finite but too large: clamped to GPROBE_MAX_RADIANCE, counted */
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(8, 4, px, &p, NULL), G_OK);
    assert_int_equal(gprobe_clamped_count(p), 4);
    assert_float_equal(gprobe_pixels(p)[30], GPROBE_MAX_RADIANCE, 0.0);
    const float *w = gprobe_weights(p);
    for (int i = 0; i < 8 * 4 * 3; i++)
        assert_true(isfinite(w[i]));
    const float *q = gprobe_pixels(p);
    assert_float_equal(q[0], 0.0, 0.0);
    assert_float_equal(q[1], 0.0, 0.0);
    assert_float_equal(q[2], 1.0, 0.0);
    assert_float_equal(q[7], 0.0, 0.0);
    assert_float_equal(q[20], 0.0, 0.0);
    gprobe_destroy(p);
    gprobe_destroy(NULL);
}

static void test_bad_shapes_and_files(void **state)
{
    (void)state;
    GProbe *p = NULL;
    GError err;
    assert_int_equal(gprobe_create(10, 4, NULL, &p, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "twice as wide"));
    assert_null(p);
    assert_int_equal(gprobe_load("/nonexistent/probe.exr", GPROBE_AUTO, 0, &p, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "/nonexistent/probe.exr"));

    char path[64] = "/tmp/test_probe_XXXXXX.exr";
    int fd = mkstemps(path, 4);
    assert_true(fd >= 0);
    close(fd);
    GImage img;
    assert_int_equal(gimage_create(&img, 30, 20, 3, NULL), G_OK);
    assert_int_equal(gimage_write(path, &img, NULL, NULL), G_OK);
    assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "30x20"));
    assert_int_equal(gprobe_load(path, GPROBE_LATLONG, 0, &p, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "twice as wide"));
    assert_int_equal(gprobe_load(path, GPROBE_ANGULAR, 0, &p, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "square"));
    gimage_free(&img);
    unlink(path);
}

/* lat-long -> angular map -> lat-long, on a field that is linear in the direction */
static void test_latlong_angular_round_trip(void **state)
{
    (void)state;
    GProbe *p = probe_from(64, linear_field);
    GImage map;
    assert_int_equal(gprobe_to_angular(p, 256, &map, NULL), G_OK);
    /* orientation: centre +x, top +z, right -y, left +y (as the lat-long image: not mirrored) */
    const float *c = map.pixels + 3 * (128 * 256 + 128);
    assert_float_equal(c[0], 2.0, 0.02);
    assert_float_equal(c[1], 1.0, 0.02);
    assert_float_equal(c[2], 1.0, 0.02);
    c = map.pixels + 3 * (64 * 256 + 128); /* halfway up: 90 degrees from +x towards +z */
    assert_float_equal(c[2], 2.0, 0.02);
    c = map.pixels + 3 * (128 * 256 + 192); /* halfway right: -y */
    assert_float_equal(c[1], 0.0, 0.02);
    c = map.pixels + 3 * (128 * 256 + 64); /* halfway left: +y */
    assert_float_equal(c[1], 2.0, 0.02);
    c = map.pixels; /* corner: outside the disc */
    assert_float_equal(c[0], 0.0, 0.0);

    GProbe *back = NULL;
    assert_int_equal(gprobe_from_angular(&map, 64, &back, NULL), G_OK);
    assert_int_equal(gprobe_width(back), 128);
    const float *a = gprobe_pixels(back);
    double worst = 0.0, sum = 0.0;
    int count = 0;
    for (int v = 0; v < 64; v++)
        for (int u = 0; u < 128; u++) {
            GVec3 d = gprobe_direction(back, u + 0.5, v + 0.5);
            float want[3];
            linear_field(d, want);
            double e = 0.0;
            for (int k = 0; k < 3; k++)
                e = fmax(e, fabs(a[3 * (v * 128 + u) + k] - want[k]));
            worst = fmax(worst, e);
            sum += e;
            count++;
        }
    assert_true(worst < 0.01); /* bilinear twice on a field ranging over [0, 2] */
    assert_true(sum / count < 0.001);
    /* and the irradiance survives the trip */
    GVec3 n[64];
    double e1[192], e2[192];
    gprobe_fibonacci(64, n);
    assert_int_equal(gprobe_irradiance(p, n, 64, e1, NULL), G_OK);
    assert_int_equal(gprobe_irradiance(back, n, 64, e2, NULL), G_OK);
    for (int i = 0; i < 192; i++)
        assert_true(fabs(e2[i] / e1[i] - 1.0) < 0.003);
    gimage_free(&map);
    gprobe_destroy(back);
    gprobe_destroy(p);
}

static void test_rotation(void **state)
{
    (void)state;
    GProbe *p = random_probe(32, 3u), *r = NULL;
    const int w = gprobe_width(p), h = gprobe_height(p);
    double R[9];
    /* a turn about z by a whole number of pixels is an exact column shift (phi falls to the right, so a
       positive turn moves the image left) */
    gprobe_rotation_xyz(0.0, 0.0, 360.0 * 5 / w, R);
    assert_int_equal(gprobe_rotate(p, R, &r, NULL), G_OK);
    for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++)
            assert_memory_equal(gprobe_pixels(r) + 3 * (v * w + (u + w - 5) % w), gprobe_pixels(p) + 3 * (v * w + u),
                                3 * sizeof(float));
    gprobe_destroy(r);
    /* a general rotation: the irradiance at R n after equals the irradiance at n before */
    GProbe *s = probe_from(64, linear_field);
    gprobe_rotation_xyz(30.0, -50.0, 70.0, R);
    assert_int_equal(gprobe_rotate(s, R, &r, NULL), G_OK);
    GVec3 n[50], rn[50];
    gprobe_fibonacci(50, n);
    for (int i = 0; i < 50; i++)
        rn[i] = gvec3(R[0] * n[i].x + R[1] * n[i].y + R[2] * n[i].z, R[3] * n[i].x + R[4] * n[i].y + R[5] * n[i].z,
                      R[6] * n[i].x + R[7] * n[i].y + R[8] * n[i].z);
    double e1[150], e2[150];
    assert_int_equal(gprobe_irradiance(s, n, 50, e1, NULL), G_OK);
    assert_int_equal(gprobe_irradiance(r, rn, 50, e2, NULL), G_OK);
    for (int i = 0; i < 150; i++)
        assert_true(fabs(e2[i] / e1[i] - 1.0) < 0.002);
    /* +z goes to R (0,0,1): rotating -90 degrees about x makes the zenith +y */
    gprobe_rotation_xyz(-90.0, 0.0, 0.0, R);
    assert_float_equal(R[5], 1.0, 1e-12);
    double bad[9] = {2, 0, 0, 0, 1, 0, 0, 0, 1};
    GProbe *t = NULL;
    assert_int_equal(gprobe_rotate(s, bad, &t, NULL), G_ERR_INVALID);
    gprobe_destroy(r);
    gprobe_destroy(s);
    gprobe_destroy(p);
}

static void test_save_and_load(void **state)
{
    (void)state;
    GProbe *p = random_probe(16, 5u), *q = NULL;
    char path[64] = "/tmp/test_probe_XXXXXX.exr";
    int fd = mkstemps(path, 4);
    assert_true(fd >= 0);
    close(fd);
    assert_int_equal(gprobe_save(p, path, GPROBE_LATLONG, NULL), G_OK);
    assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &q, NULL), G_OK);
    assert_memory_equal(gprobe_pixels(p), gprobe_pixels(q), sizeof(float) * 3 * 32 * 16);
    gprobe_destroy(q);
    /* as an angular map: square, read back by shape */
    GProbe *s = probe_from(32, linear_field);
    assert_int_equal(gprobe_save(s, path, GPROBE_ANGULAR, NULL), G_OK);
    int w, h, c;
    assert_int_equal(gimage_info(path, &w, &h, &c, NULL), G_OK);
    assert_int_equal(w, 32);
    assert_int_equal(h, 32);
    assert_int_equal(gprobe_load(path, GPROBE_AUTO, 32, &q, NULL), G_OK);
    assert_int_equal(gprobe_height(q), 32);
    float got[3], want[3];
    gprobe_radiance(q, gvec3(0, 0, 1), got);
    linear_field(gvec3(0, 0, 1), want);
    assert_float_equal(got[2], want[2], 0.05);
    gprobe_destroy(q);
    gprobe_destroy(s);
    gprobe_destroy(p);
    unlink(path);
}

static void test_compare_measures(void **state)
{
    (void)state;
    double truth[6] = {1, 1, 1, 2, 2, 2}, approx[6] = {1.1, 0.9, 1, 2, 2, 1};
    GProbeErrors e;
    gprobe_compare(truth, approx, 2, &e);
    /* per channel: mean_rel R 5%, G 5%, B 25%; max R 10 G 10 B 50 */
    assert_float_equal(e.mean_rel, (5.0 + 5.0 + 25.0) / 3.0, 1e-9);
    assert_float_equal(e.max_rel, (10.0 + 10.0 + 50.0) / 3.0, 1e-9);
    /* normalised by the largest irradiance (2): R |0.1|/2/2 = 2.5%, G 2.5%, B (0 + 1)/2/2 = 25% */
    assert_float_equal(e.mean_norm, (2.5 + 2.5 + 25.0) / 3.0, 1e-9);
    assert_float_equal(e.max_norm, (5.0 + 5.0 + 50.0) / 3.0, 1e-9);
    /* lights: a light facing the normal gives its colour, one behind gives nothing */
    GProbeLight l[2] = {{gvec3(0, 0, 1), {1, 2, 3}}, {gvec3(0, 0, -1), {5, 5, 5}}};
    GVec3 n[2] = {gvec3(0, 0, 1), gvec3(1, 0, 0)};
    double E[6];
    gprobe_lights_irradiance(l, 2, n, 2, E);
    assert_float_equal(E[0], 1.0, 1e-12);
    assert_float_equal(E[2], 3.0, 1e-12);
    assert_float_equal(E[3], 0.0, 0.0);
}

static void test_fibonacci_is_even(void **state)
{
    (void)state;
    const int m = 2000;
    GVec3 *n = malloc(sizeof *n * m);
    gprobe_fibonacci(m, n);
    GVec3 sum = gvec3(0, 0, 0);
    for (int i = 0; i < m; i++) {
        assert_float_equal(gvec3_length(n[i]), 1.0, 1e-12);
        sum = gvec3_add(sum, n[i]);
    }
    assert_true(gvec3_length(sum) / m < 1e-3);
    int up = 0; /* a cap of solid angle 2 pi (1 - cos 60deg) = pi holds a quarter of them */
    for (int i = 0; i < m; i++)
        up += n[i].x > 0.5;
    assert_int_equal(abs(up - m / 4) <= 10, 1);
    free(n);
}

/* Every allocation failure is reported as G_ERR_NOMEM and leaks nothing (the sanitizer build checks). */
static void test_out_of_memory(void **state)
{
    (void)state;
    float px[16 * 8 * 3];
    for (int i = 0; i < 16 * 8 * 3; i++)
        px[i] = (float)(i % 7);
    static TuAlloc alloc; /* fails from the k-th call on (the irradiance sum allocates in threads) */
    const GProbeTechnique ts[] = {GPROBE_MEDIANCUT, GPROBE_ADAPTIVE, GPROBE_KMEANS, GPROBE_IRRADIANCE};
    for (int t = -1; t < 4; t++) {
        int succeeded = 0;
        for (long k = 0; k < 200 && !succeeded; k++) {
            alloc = (TuAlloc){.fail_call = k + 1, .fail_after = 1};
            tu_alloc_install(&alloc);
            GProbe *p = NULL;
            GError err;
            int rc = gprobe_create(16, 8, px, &p, &err);
            if (rc == G_OK && t >= 0) {
                GProbeLight l[4];
                GProbeOptions opt = {0};
                opt.fit_normals = 50;
                rc = gprobe_approximate(p, ts[t], 4, &opt, l, &err);
            } else if (rc == G_OK) {
                GVec3 n[10];
                double E[30];
                gprobe_fibonacci(10, n);
                rc = gprobe_irradiance(p, n, 10, E, &err);
            }
            gprobe_destroy(p);
            gmem_set_allocator(NULL);
            if (rc == G_OK)
                succeeded = 1;
            else
                assert_int_equal(rc, G_ERR_NOMEM);
        }
        assert_true(succeeded);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weights_sum_to_power),
        cmocka_unit_test(test_constant_probe_gives_pi_L),
        cmocka_unit_test(test_fast_sum_matches_direct_sum),
        cmocka_unit_test(test_direction_convention),
        cmocka_unit_test(test_irradiance_repeats_exactly),
        cmocka_unit_test(test_clamping_counts_bad_pixels),
        cmocka_unit_test(test_bad_shapes_and_files),
        cmocka_unit_test(test_latlong_angular_round_trip),
        cmocka_unit_test(test_rotation),
        cmocka_unit_test(test_save_and_load),
        cmocka_unit_test(test_compare_measures),
        cmocka_unit_test(test_fibonacci_is_even),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
