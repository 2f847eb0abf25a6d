/* test_texture_srgb.c - sRGB-encoded image textures are filtered in linear light: a minified one-texel black and
 * white checker averages to 0.5 (not to the decoded 0.5 of the encoded values, 0.214), a lookup between a black and
 * a white texel under magnification gives 0.5, a constant 8-bit texel gives its decoded value rounded to half (the
 * type the texture cache holds decoded 8-bit files in: within a relative 2^-11 of the exact decode) and a 16-bit
 * one its decoded value to float precision, for every code of either depth, the image node's colorspace option
 * picks decoded or raw values of the same file in one texture system, and float files follow the same rules. The
 * PNG files are written here with libpng, byte for byte. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/services/image.h>
#include <generic/materials.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "image_node_fixture.h"

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <unistd.h>

typedef struct Fix {
    ImageNodeFix n;
    char checker[128], edge[128], grey8[128], grey16[128], half_exr[128], codes8[128], codes16[128];
} Fix;

enum { CHECKER = 256, GREY8 = 128, GREY16 = 40000 };

/* Writes a w x h RGB PNG of bit depth 8 or 16 (no gAMA or sRGB chunk) whose every channel at (x, y) is
 * value(x, y). 0 on success. */
static int write_png(const char *path, int w, int h, int depth, unsigned (*value)(int x, int y))
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    unsigned char *row = malloc((size_t)w * 3 * 2);
    if (!png || !info || !row || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(row);
        fclose(fp);
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                unsigned v = value(x, y);
                if (depth == 16) { /* big-endian samples */
                    row[(x * 3 + c) * 2] = (unsigned char)(v >> 8);
                    row[(x * 3 + c) * 2 + 1] = (unsigned char)(v & 0xff);
                } else {
                    row[x * 3 + c] = (unsigned char)v;
                }
            }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    return fclose(fp) == 0 ? 0 : -1;
}

static unsigned pixel_checker(int x, int y) { return ((x + y) & 1) ? 255u : 0u; }
static unsigned right_white(int x, int y) { (void)y; return x > 0 ? 255u : 0u; }
static unsigned grey8(int x, int y) { (void)x, (void)y; return GREY8; }
static unsigned grey16(int x, int y) { (void)x, (void)y; return GREY16; }
static unsigned code8(int x, int y) { return (unsigned)(y * 16 + x); }    /* every 8-bit code on 16 x 16 texels */
static unsigned code16(int x, int y) { return (unsigned)(y * 256 + x); } /* every 16-bit code on 256 x 256 */

/* x (>= 0) rounded to the nearest half-precision value, ties to even: 11 significant bits for a normal half
 * (x >= 2^-14, within a relative 2^-11 of x), steps of 2^-24 below. */
static double half_of(double x)
{
    int e;
    frexp(x, &e); /* x = m 2^e with 0.5 <= m < 1: the halfs of [2^(e-1), 2^e) lie 2^(e-11) apart */
    const double step = ldexp(1.0, (e < -13 ? -13 : e) - 11);
    return nearbyint(x / step) * step;
}

/* The decoded value of an 8-bit code as the texture cache holds it. */
static double decoded8(double encoded) { return half_of(gimage_srgb_decode(encoded)); }

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    if (!f || image_node_fix_open(&f->n, "/tmp/gsrgbXXXXXX") != 0)
        return -1;
    snprintf(f->checker, sizeof f->checker, "%s/checker.png", f->n.dir);
    snprintf(f->edge, sizeof f->edge, "%s/edge.png", f->n.dir);
    snprintf(f->grey8, sizeof f->grey8, "%s/grey8.png", f->n.dir);
    snprintf(f->grey16, sizeof f->grey16, "%s/grey16.png", f->n.dir);
    snprintf(f->half_exr, sizeof f->half_exr, "%s/half.exr", f->n.dir);
    snprintf(f->codes8, sizeof f->codes8, "%s/codes8.png", f->n.dir);
    snprintf(f->codes16, sizeof f->codes16, "%s/codes16.png", f->n.dir);
    if (write_png(f->checker, CHECKER, CHECKER, 8, pixel_checker) || write_png(f->edge, 2, 2, 8, right_white) ||
        write_png(f->grey8, 4, 4, 8, grey8) || write_png(f->grey16, 4, 4, 16, grey16) ||
        write_png(f->codes8, 16, 16, 8, code8) || write_png(f->codes16, 256, 256, 16, code16))
        return -1;
    GImage img;
    if (gimage_create(&img, 4, 4, 3, &err) != G_OK)
        return -1;
    for (int i = 0; i < 4 * 4 * 3; i++)
        img.pixels[i] = 0.5f;
    int rc = gimage_write(f->half_exr, &img, NULL, &err);
    gimage_free(&img);
    if (rc != G_OK)
        return -1;
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    const char *files[] = {f->checker, f->edge, f->grey8, f->grey16, f->half_exr, f->codes8, f->codes16};
    image_node_fix_close(&f->n, files, sizeof files / sizeof files[0]);
    free(f);
    return 0;
}

/* The red channel the node gives at (u, v) with a footprint of width uv units. */
static double lookup(Fix *f, const GMaterial *m, double u, double v, double width)
{
    GSurfPoint sp;
    plane_point(&sp, f->n.rgb, f->n.scratch, u, v);
    sp.uv_footprint = width;
    assert_int_equal(gmaterial_diffuse(m, &sp, &f->n.c), G_OK);
    return color_r(&f->n.c);
}

static void test_minified_checker_averages_linear_light(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->checker, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_AUTO);
    const double u = 10.5 / CHECKER, v = 1.0 - 20.5 / CHECKER; /* texel (10, 20): black */
    assert_float_equal(lookup(f, m, u, v, 0.25 / CHECKER), 0.0, 1e-3);
    const double widths[] = {2.0, 4.0, 16.0, 64.0};
    for (int i = 0; i < 4; i++) {
        double got = lookup(f, m, u, v, widths[i] / CHECKER);
        print_message("1-texel checker seen %g texels wide: %.4f (encoded values averaged: %.4f)\n", widths[i], got,
                      gimage_srgb_decode(0.5));
        assert_float_equal(got, 0.5, 0.01);
    }
    gmaterial_unref(m);
}

static void test_magnified_edge_is_linear_mean(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->edge, GTEX_WRAP_CLAMP, GTEX_COLORSPACE_AUTO);
    /* 2 x 2 texels, black left, white right: u = 0.5 lies halfway between the texel centres 0.25 and 0.75 */
    double got = lookup(f, m, 0.5, 0.5, 1e-3);
    print_message("halfway between a black and a white texel: %.4f\n", got);
    assert_float_equal(got, 0.5, 0.01);
    assert_float_equal(lookup(f, m, 0.375, 0.5, 1e-3), 0.25, 0.01); /* a quarter of the way: a quarter */
    assert_float_equal(lookup(f, m, 0.25, 0.5, 1e-3), 0.0, 1e-6);
    assert_float_equal(lookup(f, m, 0.75, 0.5, 1e-3), 1.0, 1e-6);
    gmaterial_unref(m);
}

static void test_constant_texels_and_colour_spaces(void **state)
{
    Fix *f = *state;
    const double e8 = GREY8 / 255.0, e16 = GREY16 / 65535.0;
    /* the sRGB and the raw values of one file in one texture system, opened in both orders */
    GMaterial *srgb = image_node(&f->n, f->grey8, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_SRGB);
    GMaterial *lin = image_node(&f->n, f->grey8, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    GMaterial *aut = image_node(&f->n, f->grey8, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_AUTO);
    for (int round = 0; round < 2; round++) {
        assert_float_equal(lookup(f, srgb, 0.5, 0.5, 0.01), decoded8(e8), 1e-6);
        assert_float_equal(lookup(f, lin, 0.5, 0.5, 0.01), e8, 1e-6);
        assert_float_equal(lookup(f, aut, 0.5, 0.5, 0.01), decoded8(e8), 1e-6);
        assert_float_equal(lookup(f, srgb, 0.3, 0.7, 0.5), decoded8(e8), 1e-6); /* the coarse levels */
        assert_float_equal(lookup(f, lin, 0.3, 0.7, 0.5), e8, 1e-6);
    }
    /* the cache holds the decoded values under a spelling of the file's path with "/./": a path spelt so names
     * the file's values as they are all the same */
    char dotted[160];
    snprintf(dotted, sizeof dotted, "%s/./grey8.png", f->n.dir);
    GMaterial *dot_lin = image_node(&f->n, dotted, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    GMaterial *dot_srgb = image_node(&f->n, dotted, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_SRGB);
    assert_float_equal(lookup(f, dot_lin, 0.5, 0.5, 0.01), e8, 1e-6);
    assert_float_equal(lookup(f, dot_srgb, 0.5, 0.5, 0.01), decoded8(e8), 1e-6);
    gmaterial_unref(dot_lin);
    gmaterial_unref(dot_srgb);
    gmaterial_unref(srgb);
    gmaterial_unref(lin);
    gmaterial_unref(aut);
    lin = image_node(&f->n, f->grey16, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    aut = image_node(&f->n, f->grey16, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_AUTO);
    assert_float_equal(lookup(f, aut, 0.5, 0.5, 0.01), gimage_srgb_decode(e16), 1e-6);
    assert_float_equal(lookup(f, lin, 0.5, 0.5, 0.01), e16, 1e-6);
    gmaterial_unref(lin);
    gmaterial_unref(aut);
    /* float data is linear unless the option says sRGB */
    aut = image_node(&f->n, f->half_exr, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_AUTO);
    srgb = image_node(&f->n, f->half_exr, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_SRGB);
    assert_float_equal(lookup(f, aut, 0.5, 0.5, 0.01), 0.5, 1e-6);
    assert_float_equal(lookup(f, srgb, 0.5, 0.5, 0.01), gimage_srgb_decode(0.5), 1e-6);
    gmaterial_unref(aut);
    gmaterial_unref(srgb);
}

#ifndef TEST_OLD_TEXSYS_API
/* gtexsys_open says which files it decodes, and its lookups are linear. */
static void test_texsys_reports_decoding(void **state)
{
    Fix *f = *state;
    const struct {
        const char *path;
        GTexColorSpace space;
        int srgb;
        double want;
    } cases[] = {
        {f->grey8, GTEX_COLORSPACE_AUTO, 1, decoded8(GREY8 / 255.0)},
        {f->grey8, GTEX_COLORSPACE_LINEAR, 0, GREY8 / 255.0},
        {f->grey16, GTEX_COLORSPACE_AUTO, 1, gimage_srgb_decode(GREY16 / 65535.0)},
        {f->half_exr, GTEX_COLORSPACE_AUTO, 0, 0.5},
        {f->half_exr, GTEX_COLORSPACE_SRGB, 1, gimage_srgb_decode(0.5)},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        GTexFile *file;
        int channels = 0, srgb = -1;
        GError err;
        assert_int_equal(gtexsys_open(f->n.ts, cases[i].path, cases[i].space, &file, &channels, &srgb, &err), G_OK);
        assert_int_equal(channels, 3);
        assert_int_equal(srgb, cases[i].srgb);
        float rgb[3];
        static const double finest[4] = {0, 0, 0, 0};
        assert_int_equal(gtexsys_lookup(f->n.ts, file, GTEX_WRAP_CLAMP, GTEX_WRAP_CLAMP, 0.5, 0.5, finest, 0.0, rgb),
                         G_OK);
        for (int c = 0; c < 3; c++)
            assert_float_equal(rgb[c], cases[i].want, 1e-6);
    }
    GTexFile *file;
    int channels, srgb;
    GError err;
    assert_int_equal(gtexsys_open(f->n.ts, f->grey8, (GTexColorSpace)7, &file, &channels, &srgb, &err), G_ERR_INVALID);
}

/* Every code of an 8-bit file gives the nearest half of its exact decode (within a relative 2^-11 of it), every
 * code of a 16-bit file its decode to float precision (a relative 1e-6), each above the code below it: looked up
 * at each texel's centre on the finest level. */
static void test_every_code_decodes(void **state)
{
    Fix *f = *state;
    const struct {
        const char *path;
        int side, depth;
    } files[] = {{f->codes8, 16, 8}, {f->codes16, 256, 16}};
    static const double finest[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        GTexFile *file;
        int channels = 0, srgb = 0;
        GError err;
        assert_int_equal(gtexsys_open(f->n.ts, files[i].path, GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err),
                         G_OK);
        assert_int_equal(srgb, 1);
        const int side = files[i].side, codes = side * side;
        const double top = files[i].depth == 8 ? 255.0 : 65535.0;
        double below = -1.0, worst = 0.0;
        for (int code = 0; code < codes; code++) {
            float rgb[3];
            const double s = (code % side + 0.5) / side, t = (code / side + 0.5) / side;
            assert_int_equal(gtexsys_lookup(f->n.ts, file, GTEX_WRAP_CLAMP, GTEX_WRAP_CLAMP, s, t, finest, 0.0, rgb),
                             G_OK);
            const double exact = gimage_srgb_decode(code / top);
            const double want = files[i].depth == 8 ? half_of(exact) : exact;
            for (int c = 0; c < 3; c++)
                if (!(fabs(rgb[c] - want) <= 1e-6 * want))
                    fail_msg("%d-bit code %d: %.9g, not %.9g", files[i].depth, code, rgb[c], want);
            if (code > 0)
                worst = fmax(worst, fabs(rgb[0] - exact) / exact);
            if (!(rgb[0] > below))
                fail_msg("%d-bit code %d: %.9g, not above the code below, %.9g", files[i].depth, code, rgb[0], below);
            below = rgb[0];
        }
        print_message("%d-bit codes: the largest relative error against the exact decode %.3g\n", files[i].depth,
                      worst);
        assert_true(worst <= (files[i].depth == 8 ? ldexp(1.0, -11) : 1e-6));
    }
}
#endif

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_minified_checker_averages_linear_light),
        cmocka_unit_test(test_magnified_edge_is_linear_mean),
        cmocka_unit_test(test_constant_texels_and_colour_spaces),
#ifndef TEST_OLD_TEXSYS_API
        cmocka_unit_test(test_texsys_reports_decoding),
        cmocka_unit_test(test_every_code_decodes),
#endif
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
