/* test_gtrace_camera_frame.c - the camera's `frame`: the view fitted to the scene's bounds along the view line.
 * For a cube of half size 1 seen along an axis with a 60 degree field of view the eye ends at 1 + sqrt(3) from the
 * centre (the near face's corners on the edges of the view), at 1 + (1 + margin) sqrt(3) with a margin, further
 * when the image is narrower than high; an oblique view touches the view's edges with one corner; the orthographic
 * window becomes the box's extent. Rendered: the framed cube's near face fills the image, a margin leaves a border,
 * a framed unit sphere has the radius the distance gives; planes are left out; errors are clear. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

#include <unistd.h>

static const double SQRT3 = 1.7320508075688772;

static Camera looking(GVec3 from, GVec3 at, double fov, double margin)
{
    Camera c;
    camera_defaults(&c);
    c.from = from;
    c.at = at;
    c.fov = fov;
    c.frame = margin;
    return c;
}

static void assert_vec(GVec3 v, double x, double y, double z, double tol)
{
    assert_near(v.x, x, tol);
    assert_near(v.y, y, tol);
    assert_near(v.z, z, tol);
}

static void test_frame_distance(void **state)
{
    (void)state;
    GVec3 lo = gvec3(-1, -1, -1), hi = gvec3(1, 1, 1);
    GError err;
    const struct {
        int w, h;
        double margin, distance;
    } cases[] = {
        {100, 100, 0.0, 1 + SQRT3},         /* the near face's corners at tan 30 = 1 / sqrt(3) of their distance */
        {100, 100, 0.25, 1 + 1.25 * SQRT3}, /* the view a quarter wider than the box */
        {200, 100, 0.0, 1 + SQRT3},         /* wider than high: the height binds */
        {100, 200, 0.0, 1 + 2 * SQRT3},     /* higher than wide: the width, half the height's tangent */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        Camera c = looking(gvec3(0, 0, 10), gvec3(0, 0, 0), 60.0, cases[i].margin);
        assert_int_equal(camera_frame(&c, lo, hi, cases[i].w, cases[i].h, &err), G_OK);
        assert_vec(c.from, 0, 0, cases[i].distance, 1e-12);
        assert_vec(c.at, 0, 0, 0, 1e-12); /* the view line's point nearest the centre */
        assert_vec(c.up, 0, 1, 0, 0.0);
    }
    /* moving nearer works as well as moving back, and off the view line the farthest corner binds */
    Camera c = looking(gvec3(5, 0, 100), gvec3(5, 0, 99), 60.0, 0.0);
    assert_int_equal(camera_frame(&c, lo, hi, 100, 100, &err), G_OK);
    assert_vec(c.from, 5, 0, 1 + 6 * SQRT3, 1e-12); /* x = -6 from the view line at the near face */
    assert_vec(c.at, 5, 0, 0, 1e-12);

    /* an oblique view keeps its direction; every corner is in view and one is on the view's edge */
    c = looking(gvec3(3, 7, 11), gvec3(0.5, 0.2, -0.3), 35.0, 0.1);
    GVec3 dir = gvec3_normalize(gvec3_sub(c.at, c.from));
    lo = gvec3(-2, 0.5, -1), hi = gvec3(1, 3, 0.25);
    assert_int_equal(camera_frame(&c, lo, hi, 64, 48, &err), G_OK);
    camera_setup(&c, 64, 48);
    assert_vec(c.forward, dir.x, dir.y, dir.z, 1e-12);
    double worst = 0.0;
    for (int i = 0; i < 8; i++) {
        GVec3 p = gvec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z), rel = gvec3_sub(p, c.eye);
        double z = gvec3_dot(rel, c.forward);
        assert_true(z > 0.0);
        double across = fabs(gvec3_dot(rel, c.right)) / (z * c.half_w);
        double up = fabs(gvec3_dot(rel, c.upv)) / (z * c.half_h);
        worst = fmax(worst, fmax(across, up));
    }
    assert_near(worst, 1.0 / 1.1, 1e-9); /* the margin: the box reaches 1 / 1.1 of the half view */

    /* orthographic: the window fits the box (its height, or its width over the aspect), before the box */
    lo = gvec3(-1, -1, -1), hi = gvec3(1, 1, 1);
    const struct {
        int w, h;
        double margin, size;
    } ortho[] = {{100, 50, 0.0, 2.0}, {100, 50, 0.5, 3.0}, {50, 100, 0.0, 4.0}};
    for (size_t i = 0; i < sizeof ortho / sizeof *ortho; i++) {
        c = looking(gvec3(0, 0, -0.5), gvec3(0, 0, -10), 40.0, ortho[i].margin); /* inside the box, looking down -z */
        c.projection = CAMERA_ORTHOGRAPHIC;
        assert_int_equal(camera_frame(&c, lo, hi, ortho[i].w, ortho[i].h, &err), G_OK);
        assert_near(c.size, ortho[i].size, 1e-12);
        assert_true(c.from.z > 1.0 && c.from.z < 1.05); /* moved back before the near face */
        assert_vec(c.at, 0, 0, 0, 1e-12);
    }

    /* a thin lens without focus_distance is focused on the centre's plane */
    c = looking(gvec3(0, 0, 10), gvec3(0, 0, 9), 60.0, 0.0);
    c.projection = CAMERA_THINLENS;
    c.aperture = 0.1;
    assert_int_equal(camera_frame(&c, lo, hi, 100, 100, &err), G_OK);
    camera_setup(&c, 100, 100);
    assert_near(c.focus, 1 + SQRT3, 1e-12);

    /* errors: nothing to frame; an eye beyond the scene's coordinate limit */
    c = looking(gvec3(0, 0, 10), gvec3(0, 0, 0), 60.0, 0.0);
    assert_int_equal(camera_frame(&c, hi, lo, 100, 100, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "no bounds to frame"));
    c = looking(gvec3(0, 0, 10), gvec3(0, 0, 0), 0.01, 0.0);
    assert_int_equal(camera_frame(&c, gvec3(-1e14, -1e14, 0), gvec3(1e14, 1e14, 1), 100, 100, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "beyond the scene's limit"));
    assert_vec(c.from, 0, 0, 10, 0.0); /* left as it was */
}

/* The scene file text (a camera line and objects) loaded, or NULL with err filled. */
static Scene *load_text(const char *text, GError *err)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/gtrace_frame_%d.scene", (int)getpid());
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "material e emitter { radiance rgb 1 1 1 }\n%s", text);
    fclose(f);
    Scene *s = NULL;
    gerror_clear(err);
    scene_load(path, "rgb", &s, err);
    unlink(path);
    return s;
}

/* Pixels of the middle row brighter than a half. */
static int bright_run(const Framebuffer *fb)
{
    int n = 0;
    for (int x = 0; x < fb->width; x++)
        n += pixel(fb, x, fb->height / 2)[1] > 0.5f;
    return n;
}

static void test_frame_scenes(void **state)
{
    (void)state;
    GError err;
    /* the cube's near face fills the framed image (pinhole and orthographic), a margin of 0.2 leaves a border */
    const char *cameras[] = {"camera pinhole { from <0,0,7> at <0,0,0> fov 60 width 32 height 32 frame 0 }\n",
                             "camera orthographic { from <0,0,7> at <0,0,0> width 32 height 32 frame 0 }\n",
                             "camera pinhole { from <0,0,7> at <0,0,0> fov 60 width 32 height 32 frame 0.2 }\n"};
    for (int k = 0; k < 3; k++) {
        char text[512];
        snprintf(text, sizeof text, "%sobject box { min <-1,-1,-1> max <1,1,1> material e }\n", cameras[k]);
        Scene *s = load_text(text, &err);
        if (!s)
            fail_msg("%s", err.message);
        if (k == 0)
            assert_vec(s->camera.from, 0, 0, 1 + SQRT3, 1e-12);
        Framebuffer fb = {0};
        render(s, 32, 32, 1, 1, &fb);
        int lit = 0;
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++)
                lit += pixel(&fb, x, y)[1] > 0.5f;
        if (k < 2)
            assert_int_equal(lit, 32 * 32);
        else /* pixel centres within 16 / 1.2 of the image's centre: 26 of 32 in a row and a column */
            assert_int_equal(lit, 26 * 26);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
    /* a unit sphere framed at 60 degrees (its bounding cube fitted): the eye at 1 + sqrt(3), the silhouette's radius
     * tan(asin(1 / (1 + sqrt 3))) / tan 30 of the half height; the floor plane is left out of the bounds */
    Scene *s = load_text("camera pinhole { from <0,0,3> at <0,0,0> fov 60 width 64 height 64 frame 0 }\n"
                         "object sphere { center <0,0,0> radius 1 material e }\n"
                         "object plane { point <0,-1,0> normal <0,1,0> material lambert { } }\n", &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_vec(s->camera.from, 0, 0, 1 + SQRT3, 1e-12);
    Framebuffer fb = {0};
    render(s, 64, 64, 1, 1, &fb);
    double radius = 32.0 * tan(asin(1.0 / (1.0 + SQRT3))) / tan(M_PI / 6.0);
    print_message("framed unit sphere: %d px across the middle row, %.2f predicted\n", bright_run(&fb), 2 * radius);
    assert_true(fabs(bright_run(&fb) - 2.0 * radius) <= 1.0);
    framebuffer_free(&fb);
    scene_destroy(s);

    /* errors: only a plane to frame; the margin out of range, at the parameter */
    s = load_text("camera pinhole { frame 0 }\nobject plane { point <0,0,0> normal <0,1,0> material e }\n", &err);
    assert_null(s);
    assert_non_null(strstr(err.message, "the camera's frame needs an object other than a plane"));
    s = load_text("camera pinhole { frame -1 }\nobject sphere { material e }\n", &err);
    assert_null(s);
    assert_non_null(strstr(err.message, ":2:24:"));
    s = load_text("camera pinhole { frame 11 }\nobject sphere { material e }\n", &err);
    assert_null(s);
    /* without frame nothing moves */
    s = load_text("camera pinhole { from <0,0,7> at <0,0,0> }\nobject sphere { material e }\n", &err);
    assert_non_null(s);
    assert_vec(s->camera.from, 0, 0, 7, 0.0);
    assert_true(s->camera.frame < 0.0);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_frame_distance), cmocka_unit_test(test_frame_scenes)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
