/* test_gtrace_camera.c - the cameras and what camera rays see: a thin lens of aperture 0 renders the pinhole's
 * image bit for bit; the thin lens blurs an out-of-focus edge by the predicted circle of confusion (measured as
 * the 10-90 % width of the edge in the rendered image) and keeps an in-focus one sharp; the orthographic camera's
 * rays are parallel (a sphere's image keeps its size at every distance, the pinhole's shrinks as 1 / distance);
 * area lights with `visible on` are seen by camera rays as their radiance, in front of what is behind them,
 * hidden by what is in front, from their lit side only, and not at all by default; a pinhole camera's ray through a
 * pixel's one sample is the one the renderer computes ahead. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

/* Emitting quad (radiance value) for crisp image values. */
static Object *add_emitting_quad(Scene *s, double value, GVec3 corner, GVec3 e1, GVec3 e2)
{
    Object *o = object_new(SHAPE_QUAD, NULL);
    o->material = emitter(s, value);
    GError err;
    assert_int_equal(object_quad(o, corner, e1, e2, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

/* A scene with everything a camera sample draws random numbers for: area light, glass, a checker-free floor. */
static Scene *busy_scene(void)
{
    Scene *s = new_scene("rgb", gvec3(0.3, 1.2, 5), gvec3(0, 0.5, 0), 40.0);
    add_plane(s, lambert(s, 0.6), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, glass(s, 1.5), gvec3(-0.6, 0.5, 0), 0.5);
    add_sphere(s, lambert(s, 0.7), gvec3(0.7, 0.4, -0.5), 0.4);
    Light *l = add_light(s, LIGHT_RECT, 6.0);
    l->position = gvec3(-0.5, 3, -0.5);
    l->edge1 = gvec3(1, 0, 0);
    l->edge2 = gvec3(0, 0, 1);
    l->samples = 4;
    return s;
}

static void test_thinlens_aperture0_is_pinhole(void **state)
{
    (void)state;
    Framebuffer a = {0}, b = {0};
    Scene *s = busy_scene();
    render(s, 48, 32, 4, 4, &a);
    scene_destroy(s);
    s = busy_scene();
    s->camera.projection = CAMERA_THINLENS;
    s->camera.aperture = 0.0;
    s->camera.focus_distance = 2.0;
    render(s, 48, 32, 4, 4, &b);
    scene_destroy(s);
    assert_int_equal(memcmp(a.pixels, b.pixels, sizeof(float) * 3 * 48 * 32), 0);
    /* and a real aperture does change the image (the comparison can fail) */
    s = busy_scene();
    s->camera.projection = CAMERA_THINLENS;
    s->camera.aperture = 0.2;
    s->camera.focus_distance = 2.0;
    Framebuffer c = {0};
    render(s, 48, 32, 4, 4, &c);
    scene_destroy(s);
    assert_int_not_equal(memcmp(a.pixels, c.pixels, sizeof(float) * 3 * 48 * 32), 0);
    framebuffer_free(&a);
    framebuffer_free(&b);
    framebuffer_free(&c);
}

/* The edge spread of a uniform disc of radius 1: the fraction of its area left of x. */
static double disc_esf(double x)
{
    if (x <= -1.0)
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    return 0.5 + (x * sqrt(1.0 - x * x) + asin(x)) / M_PI;
}

/* Where the profile (rising from 0 to 1 along x) crosses level, interpolated between pixel centres. */
static double crossing(const double *prof, int n, double level)
{
    for (int i = 0; i + 1 < n; i++)
        if (prof[i] < level && prof[i + 1] >= level)
            return i + 0.5 + (level - prof[i]) / (prof[i + 1] - prof[i]);
    fail_msg("the profile never crosses %g", level);
    return 0;
}

/* 10-90 % width in pixels of the edge between a black background (left) and an emitting wall (right) at distance
 * z, seen by a thin lens of aperture A focused at f. */
static double edge_width(double aperture, double focus, double z, int w, int h, double fov)
{
    Scene *s = new_scene("rgb", gvec3(0, 0, 0), gvec3(0, 0, -1), fov);
    s->camera.projection = CAMERA_THINLENS;
    s->camera.aperture = aperture;
    s->camera.focus_distance = focus;
    add_emitting_quad(s, 1.0, gvec3(0, -50, -z), gvec3(50, 0, 0), gvec3(0, 100, 0));
    Framebuffer fb = {0};
    render(s, w, h, 256, 1, &fb);
    double prof[512] = {0};
    for (int x = 0; x < w; x++) {
        for (int y = 0; y < h; y++)
            prof[x] += pixel(&fb, x, y)[1];
        prof[x] /= h;
    }
    double top = prof[w - 1];
    assert_true(top > 0.5);
    for (int x = 0; x < w; x++)
        prof[x] /= top;
    framebuffer_free(&fb);
    scene_destroy(s);
    return crossing(prof, w, 0.9) - crossing(prof, w, 0.1);
}

static void test_depth_of_field_blur(void **state)
{
    (void)state;
    const int w = 160, h = 16;
    const double half_h = 0.05, fov = 2.0 * atan(half_h) * 180.0 / M_PI;
    const double px_per_unit = h / (2.0 * half_h); /* pixels per unit of the image plane at distance 1 */
    /* the 10-90 % width of a disc's edge spread is 2 s90 radii: s90 from the analytic ESF */
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi);
        *(disc_esf(mid) < 0.9 ? &lo : &hi) = mid;
    }
    double s90 = lo; /* 0.404 */
    const struct { double aperture, focus, z; } cases[] = {{0.4, 4.0, 2.0}, {0.3, 2.0, 6.0}, {0.2, 1.0, 3.0}};
    for (int i = 0; i < 3; i++) {
        double coc = cases[i].aperture * fabs(1.0 / cases[i].z - 1.0 / cases[i].focus) * px_per_unit;
        double predicted = s90 * coc; /* 2 s90 times the radius coc / 2 */
        double measured = edge_width(cases[i].aperture, cases[i].focus, cases[i].z, w, h, fov);
        print_message("aperture %g focus %g z %g: circle of confusion %.2f px, edge 10-90 %% width %.2f px "
                      "(predicted %.2f)\n", cases[i].aperture, cases[i].focus, cases[i].z, coc, measured, predicted);
        assert_near(measured, predicted, 0.06 * predicted + 0.3);
    }
    /* in focus: only the pixel's own width (a box of 1 px: 0.8 px from 10 to 90 %) */
    double sharp = edge_width(0.4, 2.0, 2.0, w, h, fov);
    print_message("in focus: edge width %.2f px\n", sharp);
    assert_true(sharp < 1.0);
}

/* Pixels of the image brighter than half the brightest, in the middle row. */
static int bright_run(const Framebuffer *fb)
{
    int y = fb->height / 2, n = 0;
    for (int x = 0; x < fb->width; x++)
        n += pixel(fb, x, y)[1] > 0.5f;
    return n;
}

static int sphere_image_width(CameraProjection proj, double distance)
{
    Scene *s = new_scene("rgb", gvec3(0, 0, distance), gvec3(0, 0, 0), 20.0);
    s->camera.projection = proj;
    s->camera.size = 2.0;
    add_sphere(s, emitter(s, 1.0), gvec3(0, 0, 0), 0.5);
    Framebuffer fb = {0};
    render(s, 101, 101, 1, 1, &fb);
    int n = bright_run(&fb);
    framebuffer_free(&fb);
    scene_destroy(s);
    return n;
}

static void test_orthographic_parallel(void **state)
{
    (void)state;
    /* a window 2 units high over 101 pixels: the sphere's diameter 1 covers about 50.5 pixels at any distance */
    int near_o = sphere_image_width(CAMERA_ORTHOGRAPHIC, 3.0), far_o = sphere_image_width(CAMERA_ORTHOGRAPHIC, 30.0);
    int near_p = sphere_image_width(CAMERA_PINHOLE, 6.0), far_p = sphere_image_width(CAMERA_PINHOLE, 12.0);
    print_message("orthographic: %d px at distance 3, %d px at 30; pinhole: %d px at 6, %d px at 12\n", near_o, far_o,
                  near_p, far_p);
    assert_int_equal(near_o, far_o);
    assert_true(abs(near_o - 50) <= 1);
    assert_true(abs(2 * far_p - near_p) <= 2); /* the pinhole's image halves with twice the distance */
    /* every orthographic ray has the view direction and starts on the plane through `from` */
    Camera c;
    camera_defaults(&c);
    c.projection = CAMERA_ORTHOGRAPHIC;
    c.from = gvec3(1, 2, 3);
    c.at = gvec3(1, 2, -1);
    c.size = 4.0;
    camera_setup(&c, 40, 20);
    Ray r;
    camera_ray(&c, 0.0, 0.0, &r);
    assert_near(r.d.z, -1.0, 1e-15);
    assert_near(r.o.x, 1.0 - 4.0, 1e-12); /* half the width: 2 * 40/20 */
    assert_near(r.o.y, 2.0 + 2.0, 1e-12);
    assert_near(r.o.z, 3.0, 1e-12);
    camera_ray(&c, 40.0, 20.0, &r);
    assert_near(r.d.z, -1.0, 1e-15);
    assert_near(r.o.x, 1.0 + 4.0, 1e-12);
    assert_near(r.o.y, 2.0 - 2.0, 1e-12);
}

/* The renderer computes a row's camera rays ahead for one sample per pixel from a pinhole camera
 * (camera_is_pinhole): that is exact only if such a camera's ray through the pixel's sample is camera_ray's through
 * its centre, bit for bit, and draws nothing from the pixel's generator. A lens of non-zero aperture draws. */
static void test_pinhole_rays_ahead(void **state)
{
    (void)state;
    const int projections[4] = {CAMERA_PINHOLE, CAMERA_THINLENS, CAMERA_ORTHOGRAPHIC, CAMERA_THINLENS};
    const double apertures[4] = {0.0, 0.0, 0.0, 0.2};
    for (int k = 0; k < 4; k++) {
        Camera c;
        camera_defaults(&c);
        c.projection = projections[k];
        c.aperture = apertures[k];
        c.from = gvec3(0.3, 1.2, 5);
        c.at = gvec3(0.1, 0.5, -0.2);
        c.focus_distance = 2.0;
        camera_setup(&c, 37, 23);
        assert_int_equal(camera_is_pinhole(&c), apertures[k] == 0.0);
        int same = 0, drawn = 0;
        for (int y = 0; y < 23; y++)
            for (int x = 0; x < 37; x++) {
                Rng rng, before;
                rng_seed(&rng, (uint64_t)y * 37u + (uint64_t)x, 0x9e3779b97f4a7c15ULL);
                before = rng;
                double sx, sy;
                pixel_sample(&rng, 0, 1, 0, NULL, &sx, &sy);
                Ray a, b;
                memset(&a, 0, sizeof a);
                memset(&b, 0, sizeof b);
                camera_ray_lens(&c, x + sx, y + sy, &rng, &a);
                camera_ray(&c, x + 0.5, y + 0.5, &b);
                same += memcmp(&a, &b, sizeof a) == 0;
                drawn += memcmp(&rng, &before, sizeof rng) != 0;
            }
        if (apertures[k] == 0.0) {
            assert_int_equal(same, 37 * 23);
            assert_int_equal(drawn, 0);
        } else {
            assert_int_equal(drawn, 37 * 23);
            assert_true(same < 37 * 23 / 2);
        }
    }
}

/* A visible rectangle light straight ahead of the camera, a grey background and an optional occluder. */
static Scene *light_scene(int visible, int flip, int occluder)
{
    Scene *s = new_scene("rgb", gvec3(0, 0, 5), gvec3(0, 0, 0), 30.0);
    set_grey(&s->background, 0.25, GCOLOR_LIGHT);
    Light *l = add_light(s, LIGHT_RECT, 3.0);
    l->position = gvec3(-0.5, -0.5, 0);
    l->edge1 = flip ? gvec3(0, 1, 0) : gvec3(1, 0, 0);
    l->edge2 = flip ? gvec3(1, 0, 0) : gvec3(0, 1, 0); /* lit side +z (towards the camera) unless flipped */
    l->visible = visible;
    Light *sl = add_light(s, LIGHT_SPHERE, 5.0);
    sl->position = gvec3(0.9, 0, 0);
    sl->radius = 0.2;
    sl->visible = visible;
    if (occluder)
        add_sphere(s, lambert(s, 0.0), gvec3(0, 0, 2), 0.1);
    return s;
}

static void test_visible_area_lights(void **state)
{
    (void)state;
    const int w = 64, h = 64;
    Framebuffer fb = {0};
    Scene *s = light_scene(1, 0, 0);
    render(s, w, h, 1, 1, &fb);
    int cx = w / 2, cy = h / 2;
    /* the sphere light's centre: x = 0.9 at distance 5, tan(15 deg) * 5 = 1.34 half height */
    int sx = (int)(w / 2 + 0.9 / (5.0 * tan(15.0 * M_PI / 180.0)) * (w / 2));
    print_message("visible: rectangle %g, sphere %g, background %g\n", pixel(&fb, cx, cy)[1], pixel(&fb, sx, cy)[1],
                  pixel(&fb, 2, 2)[1]);
    assert_near(pixel(&fb, cx, cy)[1], 3.0, 1e-3);
    assert_near(pixel(&fb, sx, cy)[1], 5.0, 1e-3);
    assert_near(pixel(&fb, 2, 2)[1], 0.25, 1e-3);
    framebuffer_free(&fb);
    scene_destroy(s);
    /* the default: not seen */
    s = light_scene(0, 0, 0);
    render(s, w, h, 1, 1, &fb);
    assert_near(pixel(&fb, cx, cy)[1], 0.25, 1e-3);
    assert_near(pixel(&fb, sx, cy)[1], 0.25, 1e-3);
    framebuffer_free(&fb);
    scene_destroy(s);
    /* the rectangle from its unlit side: not seen */
    s = light_scene(1, 1, 0);
    render(s, w, h, 1, 1, &fb);
    assert_near(pixel(&fb, cx, cy)[1], 0.25, 1e-3);
    framebuffer_free(&fb);
    scene_destroy(s);
    /* a black sphere in front hides it */
    s = light_scene(1, 0, 1);
    render(s, w, h, 1, 1, &fb);
    assert_true(pixel(&fb, cx, cy)[1] < 0.01f);
    assert_near(pixel(&fb, cx + 10, cy)[1], 3.0, 1e-3);
    framebuffer_free(&fb);
    scene_destroy(s);
}

static void test_camera_entries(void **state)
{
    (void)state;
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    GLibrary *lib = NULL;
    if (greader_load_string("camera thinlens { aperture 0.5 focus_distance 3 fov 30 }\n", "cam", NULL, &lib, &err) !=
        G_OK)
        fail_msg("%s", err.message);
    const Camera *c = glibrary_entry(lib, gtrace_kind_camera, 0, NULL, NULL);
    assert_int_equal(c->projection, CAMERA_THINLENS);
    assert_near(c->aperture, 0.5, 0);
    assert_near(c->focus_distance, 3.0, 0);
    glibrary_destroy(lib);
    assert_int_equal(greader_load_string("camera orthographic { size 7 }\n", "cam", NULL, &lib, &err), G_OK);
    c = glibrary_entry(lib, gtrace_kind_camera, 0, NULL, NULL);
    assert_int_equal(c->projection, CAMERA_ORTHOGRAPHIC);
    assert_near(c->size, 7.0, 0);
    glibrary_destroy(lib);
    assert_int_not_equal(greader_load_string("camera orthographic { fov 30 }\n", "cam", NULL, &lib, &err), G_OK);
    assert_non_null(strstr(err.message, "cam:1:23:"));
    assert_int_not_equal(greader_load_string("camera pinhole { aperture 1 }\n", "cam", NULL, &lib, &err), G_OK);
    assert_int_not_equal(greader_load_string("camera thinlens { aperture -1 }\n", "cam", NULL, &lib, &err), G_OK);
    assert_int_not_equal(greader_load_string("light point { position <0,0,0> intensity rgb 1 1 1 visible on }\n",
                                             "l", NULL, &lib, &err), G_OK);
    assert_int_equal(greader_load_string("light sphere { radiance rgb 1 1 1 visible on }\n", "l", NULL, &lib, &err),
                     G_OK);
    const Light *l = glibrary_entry(lib, gtrace_kind_light, 0, NULL, NULL);
    assert_int_equal(l->visible, 1);
    glibrary_destroy(lib);
    assert_int_equal(greader_load_string("light rectangle { radiance rgb 1 1 1 }\n", "l", NULL, &lib, &err), G_OK);
    l = glibrary_entry(lib, gtrace_kind_light, 0, NULL, NULL);
    assert_int_equal(l->visible, 0);
    glibrary_destroy(lib);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_thinlens_aperture0_is_pinhole), cmocka_unit_test(test_depth_of_field_blur),
        cmocka_unit_test(test_orthographic_parallel),         cmocka_unit_test(test_visible_area_lights),
        cmocka_unit_test(test_camera_entries),                cmocka_unit_test(test_pinhole_rays_ahead),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
