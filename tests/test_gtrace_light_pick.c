/* test_gtrace_light_pick.c - the scene's light table by power (examples/gtrace/lights/light_pick.c) and its users:
 * the probabilities are the lights' powers over their sum (a black light left out), the alias table chooses each as
 * often (stratified numbers: within one choice in 20,000) and what is left of the number is uniform; one light
 * sample a vertex in the path tracer keeps the expected value: LIGHT_PICK_EVERY_MAX + 44 point lights of powers spread
 * over 50:1 light a floor as the Whitted tracer's sum over every light does (whole image within 1%, four patches within
 * 2%), and an emitter quad, a rectangle, a sphere and point lights together equal the Whitted tracer's estimate (every
 * light sampled, 1.5%), both with 3 point lights (the path tracer samples every light) and with LIGHT_PICK_EVERY_MAX of
 * them (one chosen: multiple importance sampling with the choice's probability in both densities); the particle
 * integrators (SPPM, light tracing) that choose their emitting light from the same table agree with it too; the
 * image with many lights does not depend on the thread count. Images are tiny. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"
#include "lights/light_pick.h"

/* 1 under AddressSanitizer (test_util.h's SANITIZED, whose header this file's common header cannot share): fewer
 * samples and wider bounds there. */
#ifdef __SANITIZE_ADDRESS__
#define SANITIZED 1
#else
#define SANITIZED 0
#endif

#define W 24
#define H 24

/* Renders s by `integrator` on `threads` threads (SPPM and light tracing: `passes` passes of `photons` photons). */
static void render_by(Scene *s, int integrator, int spp, int threads, int passes, long photons, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = W, .height = H, .spp = spp, .depth = 4, .threads = threads, .quiet = 1,
                         .integrator = integrator, .sppm_passes = passes, .sppm_photons = photons};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

static double patch_mean(const Framebuffer *fb, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            sum += luma(pixel(fb, x, y));
    return sum / ((x1 - x0) * (y1 - y0));
}

/* Compares a's whole image and its four quadrants with ref's: within tol_image and tol_patch (relative). */
static void agree(const char *what, const Framebuffer *a, const Framebuffer *ref, double tol_image, double tol_patch)
{
    double ia = patch_mean(a, 0, 0, W, H), ir = patch_mean(ref, 0, 0, W, H), worst = 0.0;
    print_message("%s: image %.5f against %.5f (%+.2f%%)\n", what, ia, ir, 100.0 * (ia / ir - 1.0));
    for (int q = 0; q < 4; q++) {
        int x0 = (q & 1) * W / 2, y0 = (q >> 1) * H / 2;
        double pa = patch_mean(a, x0, y0, x0 + W / 2, y0 + H / 2), pr = patch_mean(ref, x0, y0, x0 + W / 2, y0 + H / 2);
        print_message("%s: patch %d %.5f against %.5f (%+.2f%%)\n", what, q, pa, pr, 100.0 * (pa / pr - 1.0));
        worst = fmax(worst, fabs(pa / pr - 1.0));
    }
    assert_true(ir > 0.01);
    assert_true(fabs(ia / ir - 1.0) < tol_image);
    assert_true(worst < tol_patch);
}

/* A grey floor seen from above. */
static Scene *floor_scene(void)
{
    Scene *s = new_scene("rgb", gvec3(0, 5.0, 0.01), gvec3(0, 0, 0), 50);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    return s;
}

/* The floor under n point lights on a square grid over [-2.25, 2.25]^2, of intensities 1 / n (1 + k mod 7)^2: a
 * spread of 49:1, the total that of 100 lights of 0.01 to 0.49 whatever n. */
static Scene *many_lights(int n)
{
    Scene *s = floor_scene();
    int side = (int)ceil(sqrt((double)n));
    for (int k = 0; k < n; k++) {
        double i = (1 + k % 7) * (1 + k % 7) / (double)n;
        Light *l = add_light(s, LIGHT_POINT, i);
        l->position = gvec3(-2.25 + 4.5 * (k % side) / (side - 1), 0.6 + 0.1 * (k % 3),
                            -2.25 + 4.5 * (k / side) / (side - 1));
    }
    return s;
}

/* The point lights of test_many_lights, which next-event estimation chooses among. */
#define MANY (LIGHT_PICK_EVERY_MAX + 44)

static void test_table(void **state)
{
    (void)state;
    Scene *s = floor_scene();
    double intensity[4] = {1.0, 2.0, 0.0, 3.0}; /* the third is black: no entry */
    for (int k = 0; k < 4; k++)
        add_light(s, LIGHT_POINT, intensity[k])->position = gvec3(k, 1, 0);
    Light *rect = add_light(s, LIGHT_RECT, 2.0);
    rect->position = gvec3(0, 2, 0);
    rect->edge1 = gvec3(0.5, 0, 0);
    rect->edge2 = gvec3(0, 0, 2.0); /* area 1, power pi * 2 against a point light's 4 pi I */
    LightPick lp;
    GError err;
    assert_int_equal(light_pick_build(&lp, s, NULL, &err), G_OK);
    assert_int_equal(lp.n, 4);
    assert_int_equal(lp.narea, 1);
    assert_int_equal(lp.area[0], 4);
    double power[5] = {4 * M_PI, 8 * M_PI, 0.0, 12 * M_PI, 2 * M_PI}, total = 26 * M_PI;
    for (int i = 0; i < 5; i++)
        assert_near(light_pick_pmf(&lp, i), power[i] / total, 1e-5);
    int n = 20000, count[5] = {0}, bins[5][4] = {{0}};
    for (int j = 0; j < n; j++) {
        double pick, rest;
        int k = light_pick_sample(&lp, (j + 0.5) / n, &pick, &rest);
        assert_true(k >= 0 && k < lp.n);
        int i = 0;
        while (s->lights[i] != lp.lights[k])
            i++;
        assert_near(pick, light_pick_pmf(&lp, i), 1e-12);
        assert_true(rest >= 0.0 && rest < 1.0);
        count[i]++;
        bins[i][(int)(rest * 4)]++;
    }
    for (int i = 0; i < 5; i++) {
        print_message("light %d: chosen %d of %d (expected %.1f)\n", i, count[i], n, n * power[i] / total);
        assert_true(fabs(count[i] - n * power[i] / total) <= 1.0 + 1e-9);
        for (int b = 0; b < 4; b++) /* what is left of the number, uniform within each choice */
            assert_true(abs(4 * bins[i][b] - count[i]) <= 8);
    }
    assert_int_equal(light_pick_sample(&lp, 0.999999999999, &(double){0}, NULL) >= 0, 1);
    light_pick_free(&lp);
    LightPick none;
    Scene *dark = floor_scene();
    assert_int_equal(light_pick_build(&none, dark, NULL, &err), G_OK);
    double pick;
    assert_int_equal(none.n, 0);
    assert_int_equal(light_pick_sample(&none, 0.5, &pick, NULL), -1);
    light_pick_free(&none);
    scene_destroy(dark);
    scene_destroy(s);
}

static void test_many_lights(void **state)
{
    (void)state;
    Scene *s = many_lights(MANY); /* more than LIGHT_PICK_EVERY_MAX: one light a vertex */
    assert_true(MANY > LIGHT_PICK_EVERY_MAX);
    Framebuffer whitted, path, path1;
    render_by(s, RENDER_WHITTED, 1, 2, 0, 0, &whitted);
    render_by(s, RENDER_PATH, SANITIZED ? 64 : 256, 2, 0, 0, &path);
    agree("many point lights, path", &path, &whitted, SANITIZED ? 0.02 : 0.01, SANITIZED ? 0.04 : 0.02);
    render_by(s, RENDER_PATH, SANITIZED ? 64 : 256, 1, 0, 0, &path1); /* the choice does not depend on threads */
    int off = 0;
    assert_true(largest_difference(&path, &path1, &off) == 0.0);
    framebuffer_free(&path1);
    framebuffer_free(&path);
    if (!SANITIZED) { /* the particle integrators' emission by the same table */
        Framebuffer sppm, light;
        render_by(s, RENDER_SPPM, 1, 2, 256, 1000, &sppm);
        agree("many point lights, sppm", &sppm, &whitted, 0.025, 0.05); /* one light a pass: noisier */
        render_by(s, RENDER_LIGHT, 1, 2, 16, 20000, &light);
        agree("many point lights, light tracing", &light, &whitted, 0.02, 0.04);
        framebuffer_free(&sppm);
        framebuffer_free(&light);
    }
    framebuffer_free(&whitted);
    scene_destroy(s);
}

/* An emitter quad, a rectangle light, a sphere light and npoints point lights (of the same total intensity whatever
 * their number): the path tracer against the Whitted tracer. */
static void emissive_and_lights(int npoints, const char *what)
{
    Scene *s = floor_scene();
    GError err;
    /* every light below the emitter quad's plane, none behind it as seen from the floor: no shadows (the two
     * integrators' shadow rules differ where a light shines through a surface); the quad out of view, 1.5 above the
     * floor, facing down */
    Object *o = object_new(SHAPE_QUAD, emitter(s, 3.0));
    gmaterial_unref(o->material);
    assert_int_equal(object_quad(o, gvec3(-4.0, 1.5, -1.0), gvec3(1, 0, 0), gvec3(0, 0, 2), &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    Light *rect = add_light(s, LIGHT_RECT, 1.5); /* over the right half */
    rect->position = gvec3(1.0, 0.7, -1.0);
    rect->edge1 = gvec3(1, 0, 0);
    rect->edge2 = gvec3(0, 0, 2);
    rect->samples = 16;
    Light *ball = add_light(s, LIGHT_SPHERE, 2.0);
    ball->position = gvec3(0.3, 0.4, 1.5);
    ball->radius = 0.2;
    ball->samples = 16;
    ball->visible = 1; /* seen by the camera in both integrators */
    double sum = 0.0;
    for (int k = 0; k < npoints; k++)
        sum += k % 3 + 1;
    for (int k = 0; k < npoints; k++)
        add_light(s, LIGHT_POINT, 0.6 * (k % 3 + 1) / sum)->position = gvec3(-1.5 + 3.0 * k / (npoints - 1), 0.5, -1.8);
    Framebuffer whitted, path;
    render_by(s, RENDER_WHITTED, 16, 2, 0, 0, &whitted);
    render_by(s, RENDER_PATH, SANITIZED ? 64 : 256, 2, 0, 0, &path);
    agree(what, &path, &whitted, SANITIZED ? 0.03 : 0.015,
          SANITIZED ? 0.05 : 0.03);
    framebuffer_free(&whitted);
    framebuffer_free(&path);
    scene_destroy(s);
}

/* Six entries: next-event estimation samples every light. */
static void test_emissive_and_lights(void **state)
{
    (void)state;
    assert_true(3 + 3 <= LIGHT_PICK_EVERY_MAX);
    emissive_and_lights(3, "emitter, rectangle, sphere and 3 points (every light), path");
}

/* More entries than LIGHT_PICK_EVERY_MAX: one light a vertex, the choice's probability in both MIS densities. */
static void test_emissive_and_many_lights(void **state)
{
    (void)state;
    emissive_and_lights(LIGHT_PICK_EVERY_MAX, "emitter, rectangle, sphere and many points (one chosen), path");
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK || gtrace_register_types(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_many_lights),
        cmocka_unit_test(test_emissive_and_lights),
        cmocka_unit_test(test_emissive_and_many_lights),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
