/* test_gtrace_lambertian.c - the light gathered for Lambertian materials (lights.c's light_gather): a surface whose
 * material has GMAT_LAMBERTIAN is asked once per shading point for its diffuse colour, times the sum of the lights'
 * light times cosine, where any other material is asked for its reflection of each light sample. The same scene is
 * rendered twice: with a lambert, an interpolate node over two lamberts, a spline over colours, and the one-child
 * nodes scale (over a lambert, by a checker that is 0 on half the cells), transform (over an interpolate of lamberts,
 * its pattern moved in (u, v) and in space) and bump (over a lambert) used directly
 * (flagged: gathered), and with each of them seen through an interpolate-one node whose one blended method is
 * reflection at t = 0 (every call handed to the material as it is, but the node is not flagged: each light asks the
 * reflection as before). Point, spot, directional, sphere (4 samples) and rectangle (4 samples) lights; a glass
 * sphere that shadows the floor (the walk through glass, whose transmitted light is gathered) and an absorbing glass
 * sphere around a point light and a lambert ball (the medium absorbs the reflected light: reflected per sample).
 * Both integrators, in rgb, spectrum and bispectral: the pictures agree within rounding (relative 1e-5 per
 * channel), and differ where a gathered light is dropped. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"

#include <unistd.h>

/* The flagged materials, named white, floor, wood, scaled, moved and bumpy followed by `suffix`, into buf. */
static void materials(char *buf, size_t size, const char *suffix)
{
    snprintf(buf, size,
             "material white%s lambert { reflectance rgb 0.7 0.65 0.6 }\n"
             "material floor%s interpolate { a lambert { reflectance rgb 0.8 0.8 0.8 }\n"
             "    b lambert { reflectance rgb 0.1 0.2 0.3 }  t checker { dims 2 frequency 2 } }\n"
             "material wood%s spline { t wood { space object frequency 6.67 rings 6.67 turbulence 0.1 latewood 0.5 }\n"
             "    basis catmull-rom colors { 0 rgb 0.75 0.5 0.25  0.5 rgb 0.6 0.4 0.2  1 rgb 0.4 0.22 0.08 } }\n"
             "material scaled%s scale { child lambert { reflectance rgb 0.9 0.8 0.7 }\n"
             "    factor checker { dims 3 frequency 4 } }\n"
             "material moved%s transform { child interpolate { a lambert { reflectance rgb 0.2 0.6 0.3 }\n"
             "    b lambert { reflectance rgb 0.9 0.85 0.2 }  t checker { dims 2 frequency 6 } }\n"
             "    uv { rotate 30 scale 0.5 }  xyz { rotate 0 1 0 20 } }\n"
             "material bumpy%s bump { child lambert { reflectance rgb 0.6 0.7 0.9 }\n"
             "    height fbm { frequency 8 octaves 3 }  strength 0.05 }\n",
             suffix, suffix, suffix, suffix, suffix, suffix);
}

/* The scene; wrap: each flagged material seen through an unflagged node that hands it every call. */
static Scene *lit_scene(const char *model, int wrap)
{
    static const char *const text =
        "colormodel rgb\n"
        "%s%s"
        "material glass dielectric { index 1.5 }\n"
        "material tinted dielectric { index 1.3 absorption rgb 0.3 0.1 0.05 }\n"
        "camera pinhole { from <0, 3, 7> at <0, 0.8, 0> fov 50 width 40 height 30 spp 2 depth 6 }\n"
        "object plane { point <0, 0, 0> normal <0, 1, 0> material floor }\n"
        "object sphere { center <-1.3, 0.7, 0> radius 0.7 material glass }\n"
        "object sphere { center <1.3, 0.6, 0.4> radius 0.6 material wood }\n"
        "object sphere { center <0, 0.35, 1.4> radius 0.35 material white }\n"
        "object sphere { center <0.2, 2.4, -1.5> radius 0.9 material tinted }\n"
        "object sphere { center <0.55, 2.4, -1.5> radius 0.25 material white }\n"
        "object sphere { center <-0.9, 0.3, 1.6> radius 0.3 material scaled }\n"
        "object sphere { center <0.9, 0.3, 1.6> radius 0.3 material moved }\n"
        "object sphere { center <-2.2, 0.4, 1.0> radius 0.4 material bumpy }\n"
        "light point { position <-0.1, 2.4, -1.5> intensity rgb 3 3 3 }\n"
        "light point { position <-4, 6, 5> intensity rgb 60 60 60 }\n"
        "light spot { position <3, 4, 3> at <0, 0, 0> intensity rgb 40 30 20 inner 20 outer 35 }\n"
        "light directional { direction <-0.3, -1, -0.5> irradiance rgb 0.6 0.6 0.7 }\n"
        "light sphere { center <2, 3.5, -1> radius 0.4 radiance rgb 4 4 4 samples 4 }\n"
        "light rectangle { corner <-2.5, 3, 1> edge1 <1, 0, 0> edge2 <0, 0, 1> radiance rgb 3 2 1 samples 4 }\n"
        "light background { color rgb 0.1 0.12 0.15 }\n";
    static const char *const wrapped =
        "material white interpolate-one { a white_l b white_l t constant { value 0 } method reflection }\n"
        "material floor interpolate-one { a floor_l b floor_l t constant { value 0 } method reflection }\n"
        "material wood interpolate-one { a wood_l b wood_l t constant { value 0 } method reflection }\n"
        "material scaled interpolate-one { a scaled_l b scaled_l t constant { value 0 } method reflection }\n"
        "material moved interpolate-one { a moved_l b moved_l t constant { value 0 } method reflection }\n"
        "material bumpy interpolate-one { a bumpy_l b bumpy_l t constant { value 0 } method reflection }\n";
    char defs[2048];
    materials(defs, sizeof defs, wrap ? "_l" : "");
    char buf[8192], path[256];
    snprintf(buf, sizeof buf, text, defs, wrap ? wrapped : "");
    snprintf(path, sizeof path, "/tmp/gtrace_test_%d_lambertian.scene", (int)getpid());
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(buf, f);
    fclose(f);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    int rc = scene_load(path, model, &s, &err);
    unlink(path);
    if (rc != G_OK)
        fail_msg("%s", err.message);
    /* the floor, the wood, the white, scaled, moved and bumpy balls: flagged directly, not through the wrapper */
    static const int lit[] = {0, 2, 3, 5, 6, 7, 8};
    for (size_t i = 0; i < sizeof lit / sizeof lit[0]; i++) {
        const GMaterial *m = s->objects[lit[i]]->material;
        if (gmaterial_lambertian(m) != !wrap)
            fail_msg("object %d (%s): GMAT_LAMBERTIAN %d with wrap %d", lit[i], gmaterial_name(m),
                     gmaterial_lambertian(m), wrap);
    }
    return s;
}

static void render_as(Scene *s, int integrator, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = s->camera.width, .height = s->camera.height, .spp = s->camera.spp, .depth = 6,
                         .threads = 2, .quiet = 1, .cutoff = 0.0, .integrator = integrator};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

static double mean_of(const Framebuffer *fb)
{
    double sum = 0.0;
    size_t n = 3 * (size_t)fb->width * fb->height;
    for (size_t i = 0; i < n; i++)
        sum += fb->pixels[i];
    return sum / (double)n;
}

static void same_picture(const char *model, int integrator)
{
    Scene *gathered = lit_scene(model, 0), *per_light = lit_scene(model, 1);
    Framebuffer a, b;
    render_as(gathered, integrator, &a);
    render_as(per_light, integrator, &b);
    int off;
    double worst = largest_difference(&a, &b, &off);
    print_message("%s, %s: largest relative difference %.3g, %d channels over 1e-5, mean %.5f\n", model,
                  integrator == RENDER_PATH ? "path" : "whitted", worst, off, mean_of(&a));
    assert_true(mean_of(&a) > 0.01); /* something is lit */
    assert_int_equal(off, 0);
    framebuffer_free(&a);
    framebuffer_free(&b);
    scene_destroy(gathered);
    scene_destroy(per_light);
}

static void test_whitted_same_picture(void **state) { same_picture(*state, RENDER_WHITTED); }

static void test_path_same_picture(void **state) { same_picture(*state, RENDER_PATH); }

/* The comparison can fail: without the lights inside the absorbing sphere (its point light and the medium's
 * per-sample reflection), the ball in it goes dark and many channels differ. */
static void test_comparison_sees_a_lost_light(void **state)
{
    (void)state;
    Scene *a = lit_scene("rgb", 0), *b = lit_scene("rgb", 0);
    set_grey(&b->lights[0]->color, 0.0, GCOLOR_LIGHT);
    Framebuffer fa, fb;
    render_as(a, RENDER_WHITTED, &fa);
    render_as(b, RENDER_WHITTED, &fb);
    int off;
    double worst = largest_difference(&fa, &fb, &off);
    print_message("without the light in the medium: largest relative difference %.3g, %d channels\n", worst, off);
    assert_true(off > 10);
    framebuffer_free(&fa);
    framebuffer_free(&fb);
    scene_destroy(a);
    scene_destroy(b);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        {"test_whitted_same_picture (rgb)", test_whitted_same_picture, NULL, NULL, (void *)"rgb"},
        {"test_whitted_same_picture (spectrum)", test_whitted_same_picture, NULL, NULL, (void *)"spectrum"},
        {"test_whitted_same_picture (bispectral)", test_whitted_same_picture, NULL, NULL, (void *)"bispectral"},
        {"test_path_same_picture (rgb)", test_path_same_picture, NULL, NULL, (void *)"rgb"},
        {"test_path_same_picture (bispectral)", test_path_same_picture, NULL, NULL, (void *)"bispectral"},
        cmocka_unit_test(test_comparison_sees_a_lost_light),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
