/* test_gtrace_sppm.c - the particle integrators: stochastic progressive photon mapping (integrators/sppm.c) and
 * particle tracing to the camera (integrators/light.c). Agreement with the path tracer on the diffuse Cornell box
 * patch by patch, the same image for any thread count and for a crop, the options' bounds, and a scene without a
 * light that sends photons refused. */
#include "test_gtrace_common.h"
#include "integrators/sppm.h"
#include "generic/builtins.h"

static Scene *load_scene_file(const char *rel, const char *model)
{
    const char *root = getenv("GENERIC_SOURCE_DIR");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", root ? root : ".", rel);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(path, model, &s, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    GError e2;
    if (accel_build(s, &e2) != G_OK)
        fail_msg("accel_build: %s", e2.message);
    return s;
}

/* Settings of a small render by `integrator`; sppm with `passes` passes of `photons` photons. */
static RenderSettings settings(int w, int h, int spp, int threads, int integrator, int passes, long photons)
{
    return (RenderSettings){.width = w, .height = h, .spp = spp, .depth = 6, .threads = threads, .quiet = 1,
                            .integrator = integrator, .sppm_passes = passes, .sppm_photons = photons};
}

static void render_ok(const Scene *s, const RenderSettings *rs, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    RenderStats st;
    if (render_image(s, rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

/* Reference luma above which a pixel shows the lamp: it and its neighbours are left out (at the lamp's edge a few
 * camera rays per pixel decide how much of the lamp a pixel sees, noise far above a patch's 3%). */
#define LAMP_LUMA 0.5

static int near_lamp(const Framebuffer *ref, int x, int y)
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < ref->width && v < ref->height && luma(pixel(ref, u, v)) > LAMP_LUMA)
                return 1;
        }
    return 0;
}

/* The mean luma of fb's n x n patch at (x0, y0) over the pixels where ref does not show the lamp. */
static double patch_luma(const Framebuffer *fb, const Framebuffer *ref, int x0, int y0, int n)
{
    double sum = 0.0;
    int count = 0;
    for (int y = y0; y < y0 + n; y++)
        for (int x = x0; x < x0 + n; x++)
            if (!near_lamp(ref, x, y)) {
                sum += luma(pixel(fb, x, y));
                count++;
            }
    assert_true(count > 0);
    return sum / count;
}

/* ---- the diffuse Cornell box: sppm agrees with the path tracer patch by patch ---- */

static void test_cornell_agrees_with_path(void **state)
{
    int integrator = (int)(intptr_t)*state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    static Framebuffer ref; /* the path-traced reference, rendered once for both integrators */
    Framebuffer fb;
    RenderSettings rp = settings(32, 32, 1024, 2, RENDER_PATH, 0, 0);
    RenderSettings rq = settings(32, 32, 1, 2, integrator, integrator == RENDER_SPPM ? 64 : 32, 40000);
    if (!ref.pixels)
        render_ok(s, &rp, &ref);
    render_ok(s, &rq, &fb);
    int n = 8, worse = 0;
    double worst = 0.0;
    for (int py = 0; py < 32; py += n)
        for (int px = 0; px < 32; px += n) {
            double a = patch_luma(&ref, &ref, px, py, n), b = patch_luma(&fb, &ref, px, py, n), d = fabs(b - a) / a;
            print_message("patch %2d,%2d: path %.5f other %.5f (%+.2f%%)\n", px, py, a, b, 100.0 * (b - a) / a);
            worst = fmax(worst, d);
            worse += d > 0.03;
        }
    print_message("largest patch difference %.2f%%\n", 100.0 * worst);
    assert_int_equal(worse, 0);
    if (integrator == RENDER_LIGHT) /* the last user */
        framebuffer_free(&ref);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- determinism: the same pixels for 1 and 2 threads and for a crop ---- */

static void test_threads_and_crop(void **state)
{
    int integrator = (int)(intptr_t)*state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    Framebuffer a, b, c, d;
    RenderSettings r1 = settings(20, 18, 1, 1, integrator, 3, 5000), r2 = r1;
    r2.threads = 2;
    render_ok(s, &r1, &a);
    render_ok(s, &r2, &b);
    assert_memory_equal(a.pixels, b.pixels, sizeof(float) * 3 * 20 * 18);
    RenderSettings rc = r2;
    rc.crop[0] = 5, rc.crop[1] = 4, rc.crop[2] = 17, rc.crop[3] = 13;
    render_ok(s, &rc, &c);
    for (int y = 4; y < 13; y++)
        assert_memory_equal(pixel(&c, 0, y - 4), pixel(&a, 5, y), sizeof(float) * 3 * 12);
    /* more photons give another image (the photons' sequences depend on their indices) */
    RenderSettings r3 = r1;
    r3.sppm_photons = 5001;
    render_ok(s, &r3, &d);
    assert_memory_not_equal(a.pixels, d.pixels, sizeof(float) * 3 * 20 * 18);
    framebuffer_free(&a);
    framebuffer_free(&b);
    framebuffer_free(&c);
    framebuffer_free(&d);
    scene_destroy(s);
}

/* ---- a glass ball's focus: a collimated beam through a ball of index n = 1.5 and radius R onto a screen at the
 * paraxial focus f = n R / (2 (n - 1)) from its centre ---- */

static const char ball_scene[] =
    "colormodel rgb\n"
    "camera pinhole { from <0, 0.3, 3> at <0, 0, 0> fov 12 width 64 height 48 spp 1 depth 8 }\n"
    "material glass dielectric { index 1.5 }\n"
    "object sphere { center <0, 0.75, 0> radius 0.5 material glass }\n" /* f = 1.5 * 0.5 / 1 = 0.75 */
    "object box { min <-1.5, -0.05, -1.5> max <1.5, 0, 1.5> material lambert { reflectance rgb 0.8 0.8 0.8 } }\n"
    "light directional { direction <0, -1, 0> irradiance rgb 1 1 1 }\n";

static void test_glass_ball_focus(void **state)
{
    int integrator = (int)(intptr_t)*state;
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(write_text("ball.scene", ball_scene), NULL, &s, &err) != G_OK)
        fail_msg("%s", err.message);
    assert_int_equal(accel_build(s, &err), G_OK);
    int w = 64, h = 48;
    Framebuffer fb;
    RenderSettings rs = settings(w, h, 1, 2, integrator, 16, 100000);
    rs.depth = 8;
    rs.sppm_radius = 0.004;
    render_ok(s, &rs, &fb);
    /* where the focus, the screen's point on the axis, lies in the image */
    Camera cam = s->camera;
    camera_setup(&cam, w, h);
    GVec3 v = gvec3_sub(gvec3(0, 0, 0), cam.eye);
    double z = gvec3_dot(v, cam.forward);
    double fx = (gvec3_dot(v, cam.right) / (z * cam.half_w) + 1.0) * 0.5 * w;
    double fy = (1.0 - gvec3_dot(v, cam.upv) / (z * cam.half_h)) * 0.5 * h;
    int bx = 0, by = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (luma(pixel(&fb, x, y)) > luma(pixel(&fb, bx, by)))
                bx = x, by = y;
    /* the lit screen in front of the ball's shadow (rows 33..38 meet it about 0.9 to 1.2 from the axis): rho E / pi
     * = 0.8 / pi, and a little of the light the ball reflects */
    double lit = 0.0;
    for (int y = 33; y < 39; y++)
        for (int x = 0; x < w; x++)
            lit += luma(pixel(&fb, x, y)) / (6 * w);
    double peak = luma(pixel(&fb, bx, by));
    print_message("focus expected at (%.2f, %.2f), brightest pixel (%d, %d) centre (%.1f, %.1f); peak %.3f, lit screen "
                  "%.4f (rho E / pi = %.4f), ratio %.1f\n", fx, fy, bx, by, bx + 0.5, by + 0.5, peak, lit, 0.8 / M_PI,
                  peak / lit);
    assert_true(fabs(bx + 0.5 - fx) <= 1.0 && fabs(by + 0.5 - fy) <= 1.0);
    assert_true(peak > 10.0 * lit);
    assert_near(lit, 0.8 / M_PI, 0.05 * 0.8 / M_PI);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- bad input ---- */

/* Renders s with rs, which must fail with status `want` and a message containing `words`. */
static void render_fails(const Scene *s, const RenderSettings *rs, int want, const char *words)
{
    GError err;
    gerror_clear(&err);
    Framebuffer fb;
    RenderStats st;
    int rc = render_image(s, rs, &fb, &st, &err);
    print_message("%s\n", err.message);
    assert_int_equal(rc, want);
    assert_non_null(strstr(err.message, words));
}

static void test_bad_options(void **state)
{
    (void)state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    RenderSettings rs = settings(8, 8, 1, 1, RENDER_SPPM, 1, 100);
    rs.sppm_passes = SPPM_MAX_PASSES + 1;
    render_fails(s, &rs, G_ERR_INVALID, "1..1000000");
    rs.sppm_passes = 1;
    rs.sppm_photons = -1;
    render_fails(s, &rs, G_ERR_INVALID, "photons per pass");
    rs.sppm_photons = 100;
    rs.sppm_radius = NAN;
    render_fails(s, &rs, G_ERR_INVALID, "radius");
    rs.sppm_radius = 0.0;
    rs.sppm_alpha = 1.5;
    render_fails(s, &rs, G_ERR_INVALID, "(0, 1]");
    scene_destroy(s);
}

static void test_no_photon_light(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 0, 4), gvec3(0, 0, 0), 40);
    set_grey(&s->background, 1.0, GCOLOR_LIGHT);
    GError err;
    assert_int_equal(accel_build(s, &err), G_OK);
    RenderSettings rs = settings(8, 8, 1, 1, RENDER_SPPM, 1, 100);
    render_fails(s, &rs, G_ERR_INVALID, "no light that sends photons");
    scene_destroy(s);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        {"test_cornell_agrees_with_path (sppm)", test_cornell_agrees_with_path, NULL, NULL, (void *)RENDER_SPPM},
        {"test_cornell_agrees_with_path (light)", test_cornell_agrees_with_path, NULL, NULL, (void *)RENDER_LIGHT},
        {"test_glass_ball_focus (sppm)", test_glass_ball_focus, NULL, NULL, (void *)RENDER_SPPM},
        {"test_glass_ball_focus (light)", test_glass_ball_focus, NULL, NULL, (void *)RENDER_LIGHT},
        {"test_threads_and_crop (sppm)", test_threads_and_crop, NULL, NULL, (void *)RENDER_SPPM},
        {"test_threads_and_crop (light)", test_threads_and_crop, NULL, NULL, (void *)RENDER_LIGHT},
        cmocka_unit_test(test_bad_options),
        cmocka_unit_test(test_no_photon_light),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
