/* test_gtrace_viewing.c - the viewing illuminant (film/viewing.h, gtrace --illuminant): a white lambert lit by
 * illuminant A renders neutral (r = g = b) when A is the viewing illuminant, and clearly warm without it, in the
 * spectral models; an unknown name is refused with the known names listed; the adaptation takes the light's white
 * to the white of sRGB. */
#include "test_gtrace_common.h"

#include "film/viewing.h"

#include <generic/builtins.h>

static const char scene_text[] =
    "camera pinhole { from <0, 3, 3> at <0, 0, 0> fov 40 width 16 height 12 spp 1 depth 2 }\n"
    "light point { position <0, 2, 0.5> intensity scale 8 %s }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 1 1 1 } }\n";

/* Renders the white plane under light `light` (a colour literal) in `model`, with the viewing illuminant `viewing`
 * (NULL: none); the linear sRGB of every pixel into fb. */
static void render_white(const char *model, const char *light, const char *viewing, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    assert_int_equal(gtrace_register_types(&err), G_OK);
    gcolormodel_destroy(model_or_skip(model));
    char text[1024];
    snprintf(text, sizeof text, scene_text, light);
    Scene *s = NULL;
    if (scene_load(write_text("viewing.scene", text), model, &s, &err) != G_OK)
        fail_msg("scene: %s", err.message);
    assert_int_equal(accel_build(s, &err), G_OK);
    RenderSettings rs = {.width = 16, .height = 12, .spp = 1, .depth = 2, .threads = 2, .quiet = 1};
    if (viewing) {
        assert_int_equal(viewing_adaptation(s->model, viewing, rs.adaptation, &err), G_OK);
        rs.adapt = 1;
    }
    RenderStats st;
    *fb = (Framebuffer){0};
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    scene_destroy(s);
}

/* The largest |c - mean| / mean over the channels of the lit pixels (mean > 0.01), and their number. */
static double worst_cast(const Framebuffer *fb, int *lit)
{
    double worst = 0.0;
    *lit = 0;
    for (int i = 0; i < fb->width * fb->height; i++) {
        const float *p = fb->pixels + 3 * i;
        double mean = (p[0] + p[1] + p[2]) / 3.0;
        if (!(mean > 0.01))
            continue;
        ++*lit;
        for (int c = 0; c < 3; c++)
            worst = fmax(worst, fabs(p[c] - mean) / mean);
    }
    return worst;
}

static void test_white_under_a_is_neutral(void **state)
{
    (void)state;
    static const char *const models[] = {"spectrum", "bispectral"};
    for (int m = 0; m < 2; m++) {
        Framebuffer adapted, plain;
        int lit_a, lit_p;
        render_white(models[m], "illuminant A", "A", &adapted);
        render_white(models[m], "illuminant A", NULL, &plain);
        double cast_a = worst_cast(&adapted, &lit_a), cast_p = worst_cast(&plain, &lit_p);
        print_message("%s: lit pixels %d, largest cast %.2e with viewing A, %.3f without\n", models[m], lit_a, cast_a,
                      cast_p);
        assert_true(lit_a > 100);
        assert_int_equal(lit_a, lit_p);
        assert_true(cast_a <= 1e-5); /* float pixels: the matrix itself is exact to 1e-12 */
        assert_true(cast_p > 0.2); /* A is far warmer than D65: without the adaptation red is well above blue */
        const float *p = plain.pixels + 3 * (6 * 16 + 8);
        assert_true(p[0] > 1.5 * p[2]);
        framebuffer_free(&adapted);
        framebuffer_free(&plain);
    }
}

/* A blackbody of 2856 K (illuminant A's temperature) as the viewing illuminant also neutralises a light of A, to
 * within the difference of A's tabulated spectrum from Planck's law at 1 nm; the light of D65 viewed under D65 is
 * neutral too. */
static void test_blackbody_and_d65(void **state)
{
    (void)state;
    Framebuffer fb;
    int lit;
    render_white("spectrum", "illuminant A", "blackbody 2856", &fb);
    double cast = worst_cast(&fb, &lit);
    assert_true(lit > 100);
    assert_true(cast <= 5e-3);
    framebuffer_free(&fb);
    render_white("spectrum", "illuminant D65", "D65", &fb);
    assert_true(worst_cast(&fb, &lit) <= 1e-3);
    framebuffer_free(&fb);
}

/* An unknown name is G_ERR_NOTFOUND naming it and listing the known ones; a bad temperature is G_ERR_INVALID. */
static void test_unknown_names_refused(void **state)
{
    (void)state;
    GError err;
    gerror_clear(&err);
    assert_int_equal(gcolor_named_light(NULL, "F13", &err), G_ERR_NOTFOUND);
    assert_non_null(strstr(err.message, "'F13'"));
    assert_non_null(strstr(err.message, "F11"));
    assert_non_null(strstr(err.message, "D50"));
    assert_non_null(strstr(err.message, "LED-B1"));
    assert_non_null(strstr(err.message, "blackbody K"));
    assert_int_equal(gcolor_named_light(NULL, "blackbody", &err), G_ERR_INVALID);
    assert_int_equal(gcolor_named_light(NULL, "blackbody 50", &err), G_ERR_INVALID);
    assert_int_equal(gcolor_named_light(NULL, "blackbody 3000x", &err), G_ERR_INVALID);
    assert_int_equal(gcolor_named_light(NULL, "blackbody 3000", &err), G_OK);
    assert_int_equal(gcolor_named_light(NULL, "F11", &err), G_OK);
}

/* The matrix takes the light's white, as the model has it, to XYZ that gcie_xyz_to_rgb maps to r = g = b, with the
 * same Y; and a grey of D65 under the viewing illuminant D65 is nearly unchanged (the model's D65 against the
 * exact white of sRGB). */
static void test_adaptation_maps_white(void **state)
{
    (void)state;
    GColorModel *m = model_or_skip("spectrum");
    GError err;
    double M[9], src[3], dst[3], rgb[3];
    assert_int_equal(viewing_adaptation(m, "F11", M, &err), G_OK);
    GColor c = {0};
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gcolor_named_light(&c, "F11", &err), G_OK);
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, src), G_OK);
    viewing_apply(M, src, dst);
    assert_near(dst[1], src[1], 1e-12 * src[1]);
    gcie_xyz_to_rgb(dst, rgb);
    assert_near(rgb[0], rgb[1], 1e-9 * rgb[1]);
    assert_near(rgb[2], rgb[1], 1e-9 * rgb[1]);
    assert_int_equal(viewing_adaptation(m, "D65", M, &err), G_OK);
    for (int i = 0; i < 9; i++)
        assert_near(M[i], i % 4 == 0 ? 1.0 : 0.0, 2e-2);
    gcolor_free(&c);
    gcolormodel_destroy(m);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_white_under_a_is_neutral),
        cmocka_unit_test(test_blackbody_and_d65),
        cmocka_unit_test(test_unknown_names_refused),
        cmocka_unit_test(test_adaptation_maps_white),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
