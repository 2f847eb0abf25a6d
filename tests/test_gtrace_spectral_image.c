/* test_gtrace_spectral_image.c - a spectral OpenEXR texture rendered by gtrace: an sRGB PNG's texels uplifted (the
 * spectrum model's sigmoid, as a reflectance) and written as the reflective channels T.<nm>nm of an OpenEXR render,
 * as `lambert { reflectance image { file "x.exr" } }`, what the PNG renders in the spectrum model within 1e-3 in
 * every pixel (the texture is magnified and its colours change gently from texel to texel, so that filtering
 * spectra and filtering RGB before uplifting agree). */
#include "test_gtrace_common.h"

#include "embed/render_file.h"
#include "exr_writer.h"

#include <generic/builtins.h>
#include <generic/services/image.h>

enum { TW = 8, TH = 8 };

static const char scene_text[] =
    "camera pinhole { from <0, 0.8, 4> at <0, 0.8, 0> fov 35 width 64 height 48 spp 1 depth 2 }\n"
    "light background { color rgb 0.05 0.05 0.05 }\n"
    "light point { position <-1, 3, 4> intensity rgb 30 30 30 }\n"
    "object box { min <-1.6, 0, -0.5> max <1.6, 1.6, -0.45> material lambert { reflectance image { file \"%s\" "
    "wrap clamp } } }\n";

static void render_with(const char *texture, const char *name, GtraceImage *img)
{
    char text[1024];
    snprintf(text, sizeof text, scene_text, texture);
    GtraceRenderRequest rq = {.scene = write_text(name, text), .colormodel = "spectrum", .depth = -1, .threads = 2};
    GError err;
    gerror_clear(&err);
    int rc = gtrace_render_file(&rq, img, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
}

static void test_uplifted_exr_renders_as_png(void **state)
{
    (void)state;
    GError err;
    /* the PNG: gentle gradients, linear values 0.15..0.75 */
    GImage png;
    assert_int_equal(gimage_create(&png, TW, TH, 3, &err), G_OK);
    for (int y = 0; y < TH; y++)
        for (int x = 0; x < TW; x++) {
            float *p = png.pixels + 3 * (y * TW + x);
            p[0] = 0.2f + 0.03f * x + 0.01f * y;
            p[1] = 0.45f - 0.02f * y + 0.01f * x;
            p[2] = 0.7f - 0.03f * x;
        }
    char png_path[256], exr_path[256];
    snprintf(png_path, sizeof png_path, "%s", temp_path("uplift.png"));
    snprintf(exr_path, sizeof exr_path, "%s", temp_path("uplift.exr"));
    assert_int_equal(gimage_write(png_path, &png, NULL, &err), G_OK);
    gimage_free(&png);
    /* its texels as the file stores them (8 bits, sRGB decoded), uplifted in the spectrum model, at every nm */
    GImage back;
    assert_int_equal(gimage_read(png_path, GIMAGE_READ_RGB, &back, &err), G_OK);
    GColorModel *m = model_or_skip("spectrum");
    GColor c;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    float *values = malloc(sizeof(float) * TW * TH * GNM_COUNT);
    static char names[GNM_COUNT][32];
    const char *ptr[GNM_COUNT];
    assert_non_null(values);
    for (int k = 0; k < GNM_COUNT; k++)
        ptr[k] = exr_spectral_name(names[k], sizeof names[k], "T.", GNM_MIN + k);
    for (int i = 0; i < TW * TH; i++) {
        double rgb[3] = {back.pixels[3 * i], back.pixels[3 * i + 1], back.pixels[3 * i + 2]};
        GSpectrumNM nm;
        assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
        assert_int_equal(gcolor_to_nm(&c, GCOLOR_REFLECTANCE, &nm), G_OK);
        memcpy(values + (size_t)i * GNM_COUNT, nm.v, sizeof nm.v);
    }
    assert_int_equal(exr_write(exr_path, TW, TH, GNM_COUNT, ptr, values, 0, 0), 0);
    free(values);
    gcolor_free(&c);
    gcolormodel_destroy(m);
    gimage_free(&back);
    GtraceImage a, b;
    render_with(png_path, "png.scene", &a);
    render_with(exr_path, "exr.scene", &b);
    assert_int_equal(a.width, b.width);
    assert_int_equal(a.height, b.height);
    double worst = 0.0, sum = 0.0;
    for (int i = 0; i < 3 * a.width * a.height; i++) {
        worst = fmax(worst, fabs((double)a.pixels[i] - (double)b.pixels[i]));
        sum += a.pixels[i];
    }
    print_message("largest pixel difference PNG - spectral EXR: %.2e (mean pixel value %.3f)\n", worst,
                  sum / (3.0 * a.width * a.height));
    assert_true(sum / (3.0 * a.width * a.height) > 0.05);
    assert_true(worst <= 1e-3);
    gtrace_image_free(&a);
    gtrace_image_free(&b);
    unlink(png_path);
    unlink(exr_path);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uplifted_exr_renders_as_png),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
