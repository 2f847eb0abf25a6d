/* test_gtrace_diagonal.c - secondary rays through materials that filter light sample by sample (GMAT_DIAGONAL,
 * material.h): shade.c's trace_secondary asks such a material once what it passes on of white light, weighs the
 * branch with it and multiplies the ray's light by it, where it asks any other material again with the light.
 * The same scene is rendered with the bits as the materials set them and with GMAT_DIAGONAL cleared on every
 * object's material (always allowed): a tinted glass, an absorbing dispersive glass (split into wavelength groups
 * in the spectral models, each group's mask applied), a mirror, a Phong with a mirror part, and interpolate,
 * scale and transform nodes over them. Whitted, in rgb, spectrum and bispectral: the pictures agree within
 * rounding (relative 1e-5 per channel). The comparison can fail: a mirror whose reflectance is a re-radiation
 * matrix, flagged by force, turns the light it re-radiates into a filter of white, and its reflection of a blue
 * sky changes. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"

#include <unistd.h>

/* The scene in `model` from text (a file that is removed again). */
static Scene *load_text(const char *text, const char *model)
{
    char path[256];
    snprintf(path, sizeof path, "/tmp/gtrace_test_%d_diagonal.scene", (int)getpid());
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    int rc = scene_load(path, model, &s, &err);
    unlink(path);
    if (rc != G_OK)
        fail_msg("%s", err.message);
    return s;
}

static const char *const glass_scene =
    "colormodel rgb\n"
    "material floor interpolate { a lambert { reflectance rgb 0.8 0.8 0.8 }\n"
    "    b lambert { reflectance rgb 0.1 0.2 0.3 }  t checker { dims 2 frequency 2 } }\n"
    "material tinted dielectric { index 1.5 tint rgb 0.9 0.6 0.3 }\n"
    "material flint dielectric { index cauchy 1.62 0.012 absorption rgb 0.3 0.1 0.05 }\n"
    "material chrome mirror { reflectance rgb 0.9 0.8 0.6 }\n"
    "material shiny phong { diffuse rgb 0.3 0.1 0.1 specular rgb 0.1 0.1 0.1 exponent 60 mirror rgb 0.4 0.5 0.3 }\n"
    "material mixed interpolate { a chrome  b tinted  t checker { dims 3 frequency 3 } }\n"
    "material dimmed scale { child chrome factor fbm { space object frequency 4 } }\n"
    "camera pinhole { from <0, 2.5, 7> at <0, 0.8, 0> fov 50 width 48 height 36 spp 2 depth 6 bands 8 }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material floor }\n"
    "object sphere { center <-1.5, 0.7, 0> radius 0.7 material tinted }\n"
    "object sphere { center <0, 0.7, 0.5> radius 0.7 material flint }\n"
    "object sphere { center <1.5, 0.7, 0> radius 0.7 material mixed }\n"
    "object sphere { center <-0.8, 0.4, 1.8> radius 0.4 material shiny }\n"
    "object sphere { center <0.9, 0.4, 1.8> radius 0.4 material dimmed }\n"
    "object box { min <-0.4, 0, -0.4> max <0.4, 0.8, 0.4> material chrome transform { rotate <0, 30, 0> translate "
    "<0, 0, -1.8> } }\n"
    "light point { position <-4, 6, 5> intensity rgb 60 60 60 }\n"
    "light point { position <3, 4, 3> intensity rgb 20 15 10 }\n"
    "light background { color rgb 0.3 0.4 0.6 }\n";

/* Clears GMAT_DIAGONAL on every object's material (a bit that is always safe to clear); how many had it. */
static int clear_diagonal(Scene *s)
{
    int had = 0;
    for (int i = 0; i < s->nobjects; i++) {
        GMaterial *m = (GMaterial *)s->objects[i]->material;
        had += gmaterial_diagonal(m);
        if (m)
            m->flags &= ~GMAT_DIAGONAL;
    }
    return had;
}

static void render_as(Scene *s, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = s->camera.width, .height = s->camera.height, .spp = s->camera.spp, .depth = 6,
                         .threads = 2, .quiet = 1, .cutoff = 0.0, .bands = 8, .integrator = RENDER_WHITTED};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

static void test_same_picture(void **state)
{
    const char *model = *state;
    Scene *flagged = load_text(glass_scene, model), *plain = load_text(glass_scene, model);
    /* every object's material filters sample by sample: the floor, the glasses, the mirror, the Phong, the nodes */
    int n = clear_diagonal(plain);
    assert_int_equal(n, plain->nobjects);
    Framebuffer a, b;
    render_as(flagged, &a);
    render_as(plain, &b);
    int off;
    double worst = largest_difference(&a, &b, &off);
    print_message("%s: %d flagged materials; largest relative difference %.3g, %d channels over 1e-5\n", model, n,
                  worst, off);
    assert_int_equal(off, 0);
    framebuffer_free(&a);
    framebuffer_free(&b);
    scene_destroy(flagged);
    scene_destroy(plain);
}

/* A mirror whose reflectance is a fluorescent re-radiation matrix (not diagonal) reflecting a blue sky, flagged by
 * force. */
static void test_comparison_sees_a_false_bit(void **state)
{
    (void)state;
    static const char *const text =
        "colormodel bispectral\n"
        "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"
        "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"
        "material dayglo-mirror mirror { reflectance dayglo }\n"
        "camera pinhole { from <0, 0.5, 4> at <0, 0.5, 0> fov 40 width 32 height 24 spp 1 depth 4 }\n"
        "object sphere { center <0, 0.5, 0> radius 0.8 material dayglo-mirror }\n"
        "light point { position <-3, 4, 4> intensity rgb 30 30 30 }\n"
        "light background { color rgb 0.1 0.2 0.9 }\n";
    Scene *plain = load_text(text, "bispectral"), *forced = load_text(text, "bispectral");
    GMaterial *m = (GMaterial *)forced->objects[0]->material;
    assert_false(gmaterial_diagonal(m)); /* its reflectance re-radiates: not flagged */
    m->flags |= GMAT_DIAGONAL;
    Framebuffer a, b;
    render_as(plain, &a);
    render_as(forced, &b);
    int off;
    double worst = largest_difference(&a, &b, &off);
    print_message("a fluorescent mirror flagged by force: largest relative difference %.3g, %d channels\n", worst,
                  off);
    assert_true(off > 10);
    framebuffer_free(&a);
    framebuffer_free(&b);
    scene_destroy(plain);
    scene_destroy(forced);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        {"test_same_picture (rgb)", test_same_picture, NULL, NULL, (void *)"rgb"},
        {"test_same_picture (spectrum)", test_same_picture, NULL, NULL, (void *)"spectrum"},
        {"test_same_picture (bispectral)", test_same_picture, NULL, NULL, (void *)"bispectral"},
        cmocka_unit_test(test_comparison_sees_a_false_bit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
