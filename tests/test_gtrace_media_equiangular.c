/* test_gtrace_media_equiangular.c - equiangular sampling towards point and spot lights in homogeneous media
 * (media/equiangular.h, integrators/medium_light.h): its density integrates to 1 over the ray and is the density of
 * what it draws; and the path tracer with it, MIS-weighted against free flight, renders fog lit by a spot light and
 * a point light with the same expectation as free flight alone (pixel by pixel within 3 sigma), with less noise. */
#include "test_gtrace_common.h"
#include "test_gtrace_pixel_stats.h"
#include "media/equiangular.h"

#include "generic/builtins.h"

/* Under AddressSanitizer (several times slower) fewer samples and one model. */
#ifdef __SANITIZE_ADDRESS__
#define SANITIZED 1
#else
#define SANITIZED 0
#endif

static void test_density(void **state)
{
    (void)state;
    const GVec3 o = gvec3(0.2, -0.1, 0.3), light = gvec3(1.0, 0.6, 2.0);
    const GVec3 d = gvec3_normalize(gvec3(0.3, 0.2, 1.0));
    const double ends[3] = {0.8, 4.0, INFINITY};
    for (int k = 0; k < 3; k++) {
        Equiangular e;
        assert_int_equal(equiangular_setup(&e, o, d, ends[k], light), 1);
        /* the integral over (0, tmax) by the midpoint rule in theta = atan((t - delta) / D), where dt = D / cos^2 */
        const int steps = 200000;
        double sum = 0.0, mean_t = 0.0, h = (e.theta_b - e.theta_a) / steps;
        for (int i = 0; i < steps; i++) {
            double th = e.theta_a + (i + 0.5) * h, t = e.delta + e.dist * tan(th);
            double p = equiangular_pdf(&e, t) * e.dist / (cos(th) * cos(th)) * h;
            sum += p;
            mean_t += p * atan2(t - e.delta, e.dist);
        }
        /* the sampled values: their densities are pdf's, and the mean angle is the interval's middle */
        Rng rng;
        rng_seed(&rng, 3, 5);
        double sampled = 0.0;
        const int ns = 100000;
        for (int i = 0; i < ns; i++) {
            double pdf, t = equiangular_sample(&e, rng_next(&rng), &pdf);
            assert_true(t >= -1e-9 && (!isfinite(ends[k]) || t <= ends[k] * (1.0 + 1e-9)));
            assert_near(pdf, equiangular_pdf(&e, t), 1e-9 * pdf);
            sampled += atan2(t - e.delta, e.dist) / ns;
        }
        double middle = 0.5 * (e.theta_a + e.theta_b), width = e.theta_b - e.theta_a;
        print_message("tmax %g: integral %.8f, mean angle %.5f, sampled %.5f (middle %.5f)\n", ends[k], sum, mean_t,
                      sampled, middle);
        assert_near(sum, 1.0, 1e-6);
        assert_near(mean_t, middle, 1e-6);
        assert_near(sampled, middle, 0.01 * width); /* its standard error is 0.001 of the width */
        assert_near(equiangular_pdf(&e, -0.5), 0.0, 0.0);
    }
    /* a light on the ray's line: refused */
    Equiangular e;
    assert_int_equal(equiangular_setup(&e, o, d, 4.0, gvec3_madd(o, d, 2.0)), 0);
}

enum { FOG_W = 8, FOG_H = 6, FOG_N = FOG_W * FOG_H };

static void test_fog_expectation(void **state)
{
    (void)state;
    /* chromatic fog over a floor, a spot light and a point light in it (the point light close to the view) */
    static const char text[] =
        "medium fog homogeneous { sigma_a rgb 0.04 0.05 0.08 sigma_s rgb 0.3 0.25 0.2 phase hg { g 0.5 } }\n"
        "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.6 0.6 0.6 } }\n"
        "object sphere { center <-0.4, 0.4, 0> radius 0.4 material lambert { reflectance rgb 0.7 0.2 0.1 } }\n"
        "light spot { position <0.4, 2.5, -0.5> at <0, 0, 0.2> intensity rgb 20 19 17 inner 20 outer 30 }\n"
        "light point { position <0.9, 0.9, 0.8> intensity rgb 0.5 0.5 0.6 }\n"
        "camera pinhole { from <0, 1.2, 3.5> at <0, 0.7, 0> fov 45 width 8 height 6 spp 1 depth 16 atmosphere fog }\n";
    static const char *const models[] = {"rgb", "spectrum"};
    const int n = SANITIZED ? 32 : 1024, nmodels = SANITIZED ? 1 : 2;
    double *mean = malloc(2 * 3 * FOG_N * sizeof *mean), *var = malloc(2 * 3 * FOG_N * sizeof *var);
    assert_non_null(mean);
    assert_non_null(var);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    for (int k = 0; k < nmodels; k++) {
        Scene *s = NULL;
        if (scene_load(write_text("fog.scene", text), models[k], &s, &err) != G_OK)
            fail_msg("%s", err.message);
        if (accel_build(s, &err) != G_OK)
            fail_msg("accel_build: %s", err.message);
        /* 0: with equiangular sampling, 1: free flight alone; disjoint samples */
        for (int i = 0; i < 2; i++)
            pixel_stats_opt(s, FOG_W, FOG_H, i * n, n, i, mean + 3 * FOG_N * i, var + 3 * FOG_N * i);
        int beyond = 0;
        double sum_z2 = 0.0, sum_d = 0.0, sum_v = 0.0, var_on = 0.0, var_off = 0.0, sum_m = 0.0;
        for (int j = 0; j < 3 * FOG_N; j++) {
            double dd = mean[j] - mean[3 * FOG_N + j], v = var[j] + var[3 * FOG_N + j];
            assert_true(v > 0.0);
            double z = dd / sqrt(v);
            beyond += fabs(z) > 3.0;
            sum_z2 += z * z;
            sum_d += dd;
            sum_v += v;
            var_on += var[j];
            var_off += var[3 * FOG_N + j];
            sum_m += mean[3 * FOG_N + j];
        }
        print_message("%s: %d pixel channels, %d beyond 3 sigma, mean z^2 %.3f; summed, equiangular minus free flight "
                      "%.4f +- %.4f (of %.3f); variance free flight / equiangular %.2f\n", models[k], 3 * FOG_N, beyond,
                      sum_z2 / (3 * FOG_N), sum_d, sqrt(sum_v), sum_m, var_off / var_on);
        assert_true(beyond <= 2 + 3 * FOG_N / 50);
        assert_true(sum_z2 / (3 * FOG_N) < 1.5);
        assert_true(fabs(sum_d) <= 4.0 * sqrt(sum_v)); /* 4: see test_gtrace_media_chroma.c */
        if (!SANITIZED)
            assert_true(var_off > 1.5 * var_on);
        scene_destroy(s);
    }
    free(mean);
    free(var);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_density),
        cmocka_unit_test(test_fog_expectation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
