/* test_gtrace_emitter_shadow.c - the shadow ray of a light sample drawn on glowing geometry ends before that geometry
 * at every distance and scale (trace.h's shadow_reach): emitter quads, triangles, discs and spheres at gaps of 0.01
 * to 50 times their size above a floor, with the whole configuration scaled by 1e-2 to 1e3 and moved off the origin;
 * the floor's radiance under the emitter from next-event estimation, in the path tracer and the Whitted tracer,
 * equals albedo / pi times the analytic irradiance (Lambert's polygon formula for quads and triangles, pi L R^2 /
 * (h^2 + R^2) for a disc, pi L R^2 / hc^2 for a sphere) within 1% plus four standard errors of the estimate. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"
#include "lights/emissive.h"
#include "lights/light_pick.h"

enum { SHAPE_KIND_QUAD, SHAPE_KIND_TRIANGLE, SHAPE_KIND_DISC, SHAPE_KIND_SPHERE, SHAPE_KINDS };
/* 1 under AddressSanitizer (test_util.h's TU_SANITIZED, whose header the common header cannot share): a quarter of
 * the configurations and fewer samples there. */
#ifdef __SANITIZE_ADDRESS__
#define SANITIZED 1
#else
#define SANITIZED 0
#endif

static const char *const KIND_NAME[SHAPE_KINDS] = {"quad", "triangle", "disc", "sphere"};
static const double GAPS[] = {0.01, 0.05, 0.2, 0.5, 1, 5, 50};
static const double SCALES[] = {1e-2, 1e-1, 1, 10, 1e2, 1e3};
#define ALBEDO 0.5

/* Lambert's formula: the irradiance at x (normal n) from a polygon of unit radiance with vertices v[0..count). */
static double polygon_irradiance(GVec3 x, GVec3 n, const GVec3 *v, int count)
{
    double sum = 0.0;
    for (int i = 0; i < count; i++) {
        GVec3 a = gvec3_normalize(gvec3_sub(v[i], x)), b = gvec3_normalize(gvec3_sub(v[(i + 1) % count], x));
        double theta = acos(fmax(-1.0, fmin(1.0, gvec3_dot(a, b))));
        sum += 0.5 * theta * gvec3_dot(n, gvec3_normalize(gvec3_cross(a, b)));
    }
    return fabs(sum);
}

/* A floor of albedo ALBEDO through the origin offset by `shift` and an emitter of `kind` of size `size` (quad and
 * triangle span, disc and sphere diameter) whose lowest point lies `gap` above the floor over floor point *x, of
 * radiance L chosen so that the floor's radiance there is about 1; the expected radiance into *expect. */
static Scene *emitter_over_floor(int kind, double size, double gap, GVec3 shift, GVec3 *x, double *expect)
{
    Scene *s = new_scene("rgb", gvec3(0, 1, 1), gvec3(0, 0, 0), 40);
    add_plane(s, lambert(s, ALBEDO), shift, gvec3(0, 1, 0));
    *x = shift;
    GVec3 up = gvec3(0, 1, 0);
    double h = size * 0.5, irradiance; /* for unit radiance */
    GVec3 quad[4] = {gvec3(-h, gap, -h), gvec3(h, gap, -h), gvec3(h, gap, h), gvec3(-h, gap, h)};
    GVec3 tri[3] = {gvec3(-h, gap, -h), gvec3(h, gap, -h), gvec3(0, gap, h)};
    for (int i = 0; i < 4; i++)
        quad[i] = gvec3_add(quad[i], shift);
    for (int i = 0; i < 3; i++)
        tri[i] = gvec3_add(tri[i], shift);
    switch (kind) {
    case SHAPE_KIND_QUAD:
        irradiance = polygon_irradiance(*x, up, quad, 4);
        break;
    case SHAPE_KIND_TRIANGLE:
        irradiance = polygon_irradiance(*x, up, tri, 3);
        break;
    case SHAPE_KIND_DISC:
        irradiance = M_PI * h * h / (gap * gap + h * h);
        break;
    default:
        irradiance = M_PI * h * h / ((gap + h) * (gap + h));
        break;
    }
    double L = M_PI / (ALBEDO * irradiance);
    GMaterial *m = emitter(s, L);
    Object *o = kind == SHAPE_KIND_QUAD       ? object_new(SHAPE_QUAD, m)
                : kind == SHAPE_KIND_TRIANGLE ? object_new(SHAPE_TRIANGLE, m)
                : kind == SHAPE_KIND_DISC     ? object_new(SHAPE_DISC, m)
                                              : object_new(SHAPE_SPHERE, m);
    gmaterial_unref(m);
    GError err;
    int rc = kind == SHAPE_KIND_QUAD       ? object_quad(o, quad[0], gvec3_sub(quad[1], quad[0]),
                                                         gvec3_sub(quad[3], quad[0]), &err)
             : kind == SHAPE_KIND_TRIANGLE ? object_triangle(o, tri[0], tri[1], tri[2], &err)
             : kind == SHAPE_KIND_DISC     ? object_disc(o, gvec3_add(shift, gvec3(0, gap, 0)), gvec3_neg(up), h, &err)
                                           : object_sphere(o, gvec3_add(shift, gvec3(0, gap + h, 0)), h, &err);
    assert_int_equal(rc, G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    *expect = L * ALBEDO * irradiance / M_PI;
    return s;
}

/* The mean and standard error of n estimates of the radiance leaving floor point x upwards (a ray from half the gap
 * above it straight down), by the path tracer (Sobol samples 0 .. n-1 of one pixel) or the Whitted tracer. */
static void floor_radiance(Scene *s, int path, GVec3 x, double gap, int n, double *mean, double *stderr_)
{
    GError err;
    assert_int_equal(accel_build(s, &err), G_OK);
    TraceCtx c = {.scene = s, .max_depth = 2, .cutoff = 0.0, .band = -1};
    c.scratch = gscratch_create(0);
    assert_non_null(c.scratch);
    assert_int_equal(gcolor_scratch(&c.unit, s->model, c.scratch), G_OK);
    assert_int_equal(gmaterial_refraction_index(NULL, NULL, &c.unit), G_OK);
    assert_int_equal(trace_ctx_temps(&c), G_OK);
    EmissiveSet *e = NULL;
    assert_int_equal(emissive_build(s, &c, &e, &err), G_OK);
    assert_int_equal(emissive_count(e), 1);
    LightPick lp;
    assert_int_equal(light_pick_build(&lp, s, e, &err), G_OK);
    c.emissive = e;
    c.pick = &lp;
    GColor out;
    assert_int_equal(gcolor_scratch(&out, s->model, c.scratch), G_OK);
    Media none = {{NULL}, 0};
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < n; k++) {
        Ray r = {gvec3_add(x, gvec3(0, 0.5 * gap, 0)), gvec3(0, -1, 0), 0.0, INFINITY, 0.0, 0.0};
        double rgb[3];
        gcolor_black(&out);
        if (path) {
            assert_int_equal(path_trace(&c, &r, &none, 17, k, SAMPLER_SOBOL, &out), G_OK);
        } else {
            rng_seed(&c.rng, 4242 + (uint64_t)k, 99);
            assert_int_equal(whitted_trace(&c, &r, &none, 0, &out), G_OK);
        }
        assert_int_equal(gcolor_to_rgb(&out, GCOLOR_LIGHT, rgb), G_OK);
        sum += rgb[1];
        sum2 += rgb[1] * rgb[1];
    }
    *mean = sum / n;
    *stderr_ = sqrt(fmax(0.0, sum2 / n - *mean * *mean) / (n - 1));
    light_pick_free(&lp);
    emissive_free(e);
    trace_ctx_free_temps(&c);
    gscratch_destroy(c.scratch);
}

static void check_integrator(int path)
{
    int failures = 0, runs = 0;
    double worst = 0.0;
    for (int kind = 0; kind < SHAPE_KINDS; kind++)
        for (size_t g = 0; g < sizeof GAPS / sizeof *GAPS; g++)
            for (size_t k = 0; k < sizeof SCALES / sizeof *SCALES; k++) {
                if (SANITIZED && (g + k + (size_t)kind) % 4 != 0)
                    continue;
                double scale = SCALES[k], gap = GAPS[g] * scale, expect, mean, se;
                /* Whitted's 16 points by area are noisy right under a close emitter: more traces there */
                int n = SANITIZED ? 256 : path ? 4096 : GAPS[g] <= 0.05 ? 8192 : 512;
                GVec3 x, shift = gvec3(0.7 * scale, 0.0, -0.4 * scale);
                Scene *s = emitter_over_floor(kind, scale, gap, shift, &x, &expect);
                floor_radiance(s, path, x, gap, n, &mean, &se);
                double err = fabs(mean - expect) / expect;
                int ok = fabs(mean - expect) <= 0.01 * expect + 4.0 * se;
                worst = fmax(worst, err);
                runs++;
                if (!ok) {
                    failures++;
                    print_message("%s: %s gap %g scale %g: %.5f, expected %.5f (standard error %.5f)\n",
                                  path ? "path" : "Whitted", KIND_NAME[kind], GAPS[g], scale, mean, expect, se);
                }
                scene_destroy(s);
            }
    print_message("%s: %d configurations, largest relative difference %.4f, %d outside 1%% + 4 standard errors\n",
                  path ? "path" : "Whitted", runs, worst, failures);
    assert_int_equal(failures, 0);
}

static void test_path_floor_under_emitters(void **state)
{
    (void)state;
    check_integrator(1);
}

static void test_whitted_floor_under_emitters(void **state)
{
    (void)state;
    check_integrator(0);
}

/* shadow_reach itself: a ray towards a point of a plane ends the offset short of the plane, at any scale. */
static void test_shadow_reach_margin(void **state)
{
    (void)state;
    for (int e = -2; e <= 3; e++) {
        double scale = pow(10.0, e);
        GVec3 target = gvec3(0.3 * scale, 2.0 * scale, 0.1 * scale), normal = gvec3(0, -1, 0);
        GVec3 origin = gvec3(-1.1 * scale, 0.0, 0.4 * scale);
        GVec3 dir = gvec3_normalize(gvec3_sub(target, origin));
        double reach = shadow_reach(origin, dir, target, normal);
        GVec3 end = gvec3_madd(origin, dir, reach);
        double margin = target.y - end.y, offset = 2e-5 * (1.0 + 2.0 * scale);
        assert_near(margin, offset, 1e-9 * scale);
        /* the origin closer to the plane than the offset: nothing is left */
        assert_true(shadow_reach(gvec3(0, target.y - 0.5 * offset, 0), dir, target, normal) == 0.0);
    }
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shadow_reach_margin),
        cmocka_unit_test(test_path_floor_under_emitters),
        cmocka_unit_test(test_whitted_floor_under_emitters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
