/* test_texture_image.c - the image node: exact texels at a tiny footprint, MIP level selection against
 * box-filtered averages as the footprint grows, wrap modes, orientation, sRGB decoding, colour images in
 * a spectral model, GMAT_NO_EMISSION over a lambert and an emitter, and files that do not exist or are
 * corrupt. Images are written as PGM/PPM files into a temporary directory. */
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
#include <stdio.h>
#include <unistd.h>

typedef struct Fix {
    ImageNodeFix n;
    char checker1[128], checker16[128], halves[128], grey[128], red[128], corrupt[128], missing[128];
} Fix;

enum { N = 256 };

/* Writes an 8-bit grey PGM of N x N pixels with value(x, y) (y = 0 the top row). */
static int write_pgm(const char *path, int (*value)(int x, int y))
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    fprintf(f, "P5\n%d %d\n255\n", N, N);
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++)
            fputc(value(x, y), f);
    return fclose(f);
}

static int pixel_checker(int x, int y) { return ((x + y) & 1) ? 255 : 0; }
static int cell_checker(int x, int y) { return (((x / 16) + (y / 16)) & 1) ? 255 : 0; }
static int top_white(int x, int y) { (void)x; return y < N / 2 ? 255 : 0; }
static int mid_grey(int x, int y) { (void)x; (void)y; return 128; }

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    if (!f || image_node_fix_open(&f->n, "/tmp/gtexXXXXXX") != 0)
        return -1;
    snprintf(f->checker1, sizeof f->checker1, "%s/checker1.pgm", f->n.dir);
    snprintf(f->checker16, sizeof f->checker16, "%s/checker16.pgm", f->n.dir);
    snprintf(f->halves, sizeof f->halves, "%s/halves.pgm", f->n.dir);
    snprintf(f->grey, sizeof f->grey, "%s/grey.pgm", f->n.dir);
    snprintf(f->red, sizeof f->red, "%s/red.ppm", f->n.dir);
    snprintf(f->corrupt, sizeof f->corrupt, "%s/corrupt.png", f->n.dir);
    snprintf(f->missing, sizeof f->missing, "%s/missing.png", f->n.dir);
    if (write_pgm(f->checker1, pixel_checker) || write_pgm(f->checker16, cell_checker) ||
        write_pgm(f->halves, top_white) || write_pgm(f->grey, mid_grey))
        return -1;
    FILE *fp = fopen(f->red, "wb");
    fprintf(fp, "P6\n2 2\n255\n");
    for (int i = 0; i < 4; i++)
        fputc(255, fp), fputc(0, fp), fputc(0, fp);
    fclose(fp);
    fp = fopen(f->corrupt, "wb");
    fprintf(fp, "\x89PNG\r\n\x1a\nthis is not really a png file at all");
    fclose(fp);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    const char *files[] = {f->checker1, f->checker16, f->halves, f->grey, f->red, f->corrupt};
    image_node_fix_close(&f->n, files, sizeof files / sizeof files[0]);
    free(f);
    return 0;
}

/* The red channel the node gives at (u, v) with a footprint in texels. */
static double lookup(Fix *f, const GMaterial *m, double u, double v, double texels)
{
    GSurfPoint sp;
    plane_point(&sp, f->n.rgb, f->n.scratch, u, v);
    sp.uv_footprint = texels / N;
    assert_int_equal(gmaterial_diffuse(m, &sp, &f->n.c), G_OK);
    return color_r(&f->n.c);
}

/* The 16-texel checker's value averaged over a box of w texels centred at texel coordinates (x, y),
 * by counting sub-texel samples (the reference for the MIP-mapped lookups). */
static double box_average(double x, double y, double w)
{
    const int k = 64;
    double sum = 0;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) {
            double sx = x - w / 2 + w * (i + 0.5) / k, sy = y - w / 2 + w * (j + 0.5) / k;
            int cx = (int)floor(sx / 16), cy = (int)floor(sy / 16);
            sum += ((cx + cy) & 1) ? 1.0 : 0.0;
        }
    return sum / (k * k);
}

static void test_exact_texels(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->checker1, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    /* texel centres at a quarter-texel footprint: the texel itself */
    for (int x = 0; x < 8; x++)
        for (int y = 0; y < 8; y++) {
            double u = (x + 0.5) / N, v = 1.0 - (y + 0.5) / N;
            assert_float_equal(lookup(f, m, u, v, 0.25), ((x + y) & 1) ? 1.0 : 0.0, 1e-3);
        }
    gmaterial_unref(m);
}

static void test_mip_level_follows_footprint(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->checker1, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    /* one-texel checker: sharp at 1/4 texel, grey once the footprint covers 2 texels, and the distance from
     * grey shrinks as the footprint grows (the lookup blends towards coarser levels) */
    double u = 10.5 / N, v = 1.0 - 20.5 / N; /* texel (10, 20): black */
    double prev = 1.0;
    const double widths[] = {0.25, 1.0, 1.2, 1.5, 1.8, 2.0, 4.0, 16.0};
    for (int i = 0; i < 8; i++) {
        double d = fabs(lookup(f, m, u, v, widths[i]) - 0.5);
        print_message("pixel checker, footprint %5.2f texels: |value - 0.5| = %.4f\n", widths[i], d);
        assert_true(d <= prev + 1e-6);
        prev = d;
    }
    assert_float_equal(lookup(f, m, u, v, 0.25), 0.0, 1e-3);
    assert_float_equal(lookup(f, m, u, v, 2.0), 0.5, 0.01);
    assert_float_equal(lookup(f, m, u, v, 16.0), 0.5, 0.01);
    gmaterial_unref(m);

    /* 16-texel cells: compared with the box average over the footprint */
    m = image_node(&f->n, f->checker16, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    const double pts[][2] = {{24, 8}, {40, 40}, {16, 24}, {100, 3}};
    const double fw[] = {0.5, 2, 4, 8, 32, 64, 128};
    double worst = 0;
    for (int p = 0; p < 4; p++)
        for (int i = 0; i < 7; i++) {
            double x = pts[p][0], y = pts[p][1];
            double got = lookup(f, m, x / N, 1.0 - y / N, fw[i]), want = box_average(x, y, fw[i]);
            worst = fmax(worst, fabs(got - want));
            assert_float_equal(got, want, 0.2);
        }
    print_message("16-texel checker: largest |lookup - box average| over footprints 0.5..128: %.3f\n", worst);
    /* at a cell centre a footprint up to the cell keeps the cell's value, and 4 cells wide gives grey */
    assert_float_equal(lookup(f, m, 24.0 / N, 1.0 - 8.0 / N, 8.0), 1.0, 0.02);
    assert_float_equal(lookup(f, m, 24.0 / N, 1.0 - 8.0 / N, 64.0), 0.5, 0.02);
    gmaterial_unref(m);
}

static void test_wrap_and_orientation(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->halves, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    /* the top half of the file is white: v up */
    assert_float_equal(lookup(f, m, 0.3, 0.75, 0.0), 1.0, 1e-3);
    assert_float_equal(lookup(f, m, 0.3, 0.25, 0.0), 0.0, 1e-3);
    /* periodic: one period up */
    assert_float_equal(lookup(f, m, 1.3, 1.25, 0.0), 0.0, 1e-3);
    assert_float_equal(lookup(f, m, -0.7, -0.25, 0.0), 1.0, 1e-3);
    gmaterial_unref(m);
    m = image_node(&f->n, f->halves, GTEX_WRAP_CLAMP, GTEX_COLORSPACE_LINEAR);
    assert_float_equal(lookup(f, m, 0.3, 1.5, 0.0), 1.0, 1e-3); /* the top row continues */
    assert_float_equal(lookup(f, m, 0.3, -3.0, 0.0), 0.0, 1e-3);
    gmaterial_unref(m);
    m = image_node(&f->n, f->halves, GTEX_WRAP_BLACK, GTEX_COLORSPACE_LINEAR);
    assert_float_equal(lookup(f, m, 0.3, 1.5, 0.0), 0.0, 1e-3);
    assert_float_equal(lookup(f, m, 0.3, 0.75, 0.0), 1.0, 1e-3);
    gmaterial_unref(m);
    m = image_node(&f->n, f->halves, GTEX_WRAP_MIRROR, GTEX_COLORSPACE_LINEAR);
    assert_float_equal(lookup(f, m, 0.3, 1.25, 0.0), 1.0, 1e-3); /* mirrored: 1.25 reads 0.75 */
    gmaterial_unref(m);
}

static void test_color_spaces(void **state)
{
    Fix *f = *state;
    GMaterial *lin = image_node(&f->n, f->grey, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    GMaterial *srgb = image_node(&f->n, f->grey, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_SRGB);
    double e = 128.0 / 255.0;
    assert_float_equal(lookup(f, lin, 0.5, 0.5, 0.0), e, 1e-4);
    assert_float_equal(lookup(f, srgb, 0.5, 0.5, 0.0), pow((e + 0.055) / 1.055, 2.4), 1e-4);
    gmaterial_unref(lin);
    gmaterial_unref(srgb);

    /* a red image over a grey child in a spectral model: the texel colour is converted into the model */
    GColorModel *spec;
    GError err;
    assert_int_equal(gcolormodel_create("spectrum", NULL, &spec, &err), G_OK);
    GColor one, c;
    assert_int_equal(gcolor_alloc(&one, spec), G_OK);
    assert_int_equal(gcolor_alloc(&c, spec), G_OK);
    assert_int_equal(gcolor_from_rgb(&one, (double[3]){0.8, 0.8, 0.8}, GCOLOR_REFLECTANCE), G_OK);
    GMaterial *w, *m;
    assert_int_equal(glambert_create(spec, &one, &w, &err), G_OK);
    GImageNodeOptions o = {.texsys = f->n.ts, .colorspace = GTEX_COLORSPACE_LINEAR};
    assert_int_equal(gnode_image_create(w, f->red, &o, &m, &err), G_OK);
    GSurfPoint sp;
    plane_point(&sp, spec, f->n.scratch, 0.5, 0.5);
    assert_int_equal(gmaterial_diffuse(m, &sp, &c), G_OK);
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(&c, GCOLOR_REFLECTANCE, rgb), G_OK);
    assert_float_equal(rgb[0], 0.8, 0.02);
    assert_float_equal(rgb[1], 0.0, 0.02);
    assert_float_equal(rgb[2], 0.0, 0.02);
    gmaterial_unref(m);
    gmaterial_unref(w);
    gcolor_free(&one);
    gcolor_free(&c);
    gcolormodel_destroy(spec);
}

/* GMAT_NO_EMISSION (material.h): the node over a lambert has it; over an emitter it has not, and its emission is
 * the emitter's times the texel (mid grey, linear). */
static void test_emission_flag(void **state)
{
    Fix *f = *state;
    GMaterial *lit = image_node(&f->n, f->grey, GTEX_WRAP_PERIODIC, GTEX_COLORSPACE_LINEAR);
    assert_true(lit->flags & GMAT_NO_EMISSION);
    gmaterial_unref(lit);
    GColor one;
    GMaterial *e, *m;
    GError err;
    assert_int_equal(gcolor_alloc(&one, f->n.rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&one, (double[3]){2, 2, 2}, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gemitter_create(f->n.rgb, &one, 1, &e, &err), G_OK);
    GImageNodeOptions o = {.texsys = f->n.ts, .colorspace = GTEX_COLORSPACE_LINEAR};
    assert_int_equal(gnode_image_create(e, f->grey, &o, &m, &err), G_OK);
    assert_false(m->flags & GMAT_NO_EMISSION);
    GSurfPoint sp;
    plane_point(&sp, f->n.rgb, f->n.scratch, 0.5, 0.5);
    assert_int_equal(gmaterial_emission(m, &sp, gvec3(0, 0, 1), &f->n.c), G_OK);
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(&f->n.c, GCOLOR_LIGHT, rgb), G_OK);
    assert_float_equal(rgb[1], 2.0 * 128.0 / 255.0, 1e-4);
    gmaterial_unref(m);
    gmaterial_unref(e);
    gcolor_free(&one);
}

static void test_bad_files(void **state)
{
    Fix *f = *state;
    GError err;
    GMaterial *m = (GMaterial *)1;
    GImageNodeOptions o = {.texsys = f->n.ts};
    assert_int_equal(gnode_image_create(f->n.white, f->missing, &o, &m, &err), G_ERR_IO);
    assert_null(m);
    assert_non_null(strstr(err.message, f->missing));
    assert_non_null(strstr(err.message, "no such file"));
    assert_int_equal(gnode_image_create(f->n.white, f->corrupt, &o, &m, &err), G_ERR_IO);
    assert_null(m);
    assert_non_null(strstr(err.message, f->corrupt));
    assert_non_null(strstr(err.message, "cannot be read"));
    print_message("corrupt file: %s\n", err.message);
    assert_int_equal(gnode_image_create(f->n.white, "", &o, &m, &err), G_ERR_INVALID);
    o.blur = -1;
    assert_int_equal(gnode_image_create(f->n.white, f->grey, &o, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "blur"));
    /* the default texture system is made on demand and goes with its last image node */
    assert_int_equal(gnode_image_create(f->n.white, f->grey, NULL, &m, &err), G_OK);
    GTextureSystem *d = gtexsys_default(&err);
    assert_non_null(d);
    gtexsys_unref(d);
    gmaterial_unref(m);
}

/* An elliptical footprint (sp->uv_axis1/2) is filtered anisotropically: long along u over an image that only
 * changes along v, the lookup stays sharp where an isotropic filter of the same length blurs; the same
 * ellipse turned to lie along v blurs too (the axes reach OpenImageIO with t = 1 - v). */
static void test_anisotropic_footprint(void **state)
{
    Fix *f = *state;
    GMaterial *m = image_node(&f->n, f->halves, GTEX_WRAP_CLAMP, GTEX_COLORSPACE_LINEAR);
    const double u = 0.3, v = 0.5 + 4.0 / N; /* 4 texels into the white half */
    double iso = lookup(f, m, u, v, 32.0);
    GSurfPoint sp;
    plane_point(&sp, f->n.rgb, f->n.scratch, u, v);
    sp.uv_footprint = 32.0 / N;
    sp.uv_axis1[0] = 32.0 / N; /* long along u */
    sp.uv_axis2[1] = 0.5 / N;  /* half a texel along v */
    assert_int_equal(gmaterial_diffuse(m, &sp, &f->n.c), G_OK);
    double along_u = color_r(&f->n.c);
    plane_point(&sp, f->n.rgb, f->n.scratch, u, v);
    sp.uv_footprint = 32.0 / N;
    sp.uv_axis1[1] = 32.0 / N; /* the same ellipse along v */
    sp.uv_axis2[0] = 0.5 / N;
    assert_int_equal(gmaterial_diffuse(m, &sp, &f->n.c), G_OK);
    double along_v = color_r(&f->n.c);
    print_message("isotropic 32 texels %.4f, ellipse along u %.4f, along v %.4f\n", iso, along_u, along_v);
    assert_true(iso < 0.9);
    assert_true(along_u > 0.97);
    assert_true(along_v < 0.9);
    gmaterial_unref(m);
}

/* Float texels that are NaN, infinite or negative become 0; the finite positive ones pass unchanged, also
 * above 1 (HDR images scale light). A 4 x 1 EXR: NaN, +Inf, -0.5, 2.5. */
static void test_nonfinite_texels(void **state)
{
    Fix *f = *state;
    char path[128];
    snprintf(path, sizeof path, "%s/nonfinite.exr", f->n.dir);
    GImage img;
    GError err;
    assert_int_equal(gimage_create(&img, 4, 1, 3, &err), G_OK);
    const float v[4] = {NAN, INFINITY, -0.5f, 2.5f};
    for (int x = 0; x < 4; x++)
        for (int c = 0; c < 3; c++)
            img.pixels[x * 3 + c] = v[x];
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    gimage_free(&img);
    GMaterial *m = image_node(&f->n, path, GTEX_WRAP_CLAMP, GTEX_COLORSPACE_LINEAR);
    const double want[4] = {0.0, 0.0, 0.0, 2.5};
    for (int x = 0; x < 4; x++) {
        GSurfPoint sp;
        plane_point(&sp, f->n.rgb, f->n.scratch, (x + 0.5) / 4, 0.5);
        sp.uv_footprint = 0.01 / 4; /* a hundredth of a texel: the texel itself */
        assert_int_equal(gmaterial_diffuse(m, &sp, &f->n.c), G_OK);
        assert_float_equal(color_r(&f->n.c), want[x], 1e-6);
    }
    gmaterial_unref(m);
    unlink(path);
}

/* A PNG cut at every few bytes: each cut file is refused when the node is made (naming the file), or, when it
 * loads, gives exactly the texels of the whole file - never black ones for the pixels it lacks. */
static void test_truncated_files(void **state)
{
    Fix *f = *state;
    char whole[128], cut[160];
    snprintf(whole, sizeof whole, "%s/whole.png", f->n.dir);
    GImage img;
    GError err;
    enum { W = 64 };
    assert_int_equal(gimage_create(&img, W, W, 3, &err), G_OK);
    unsigned seed = 12345;
    for (int i = 0; i < W * W * 3; i++) { /* pseudo-random texels: little to compress */
        seed = seed * 1103515245u + 12345u;
        img.pixels[i] = 0.2f + 0.6f * (float)((seed >> 16) % 1000) / 1000.0f;
    }
    assert_int_equal(gimage_write(whole, &img, NULL, &err), G_OK);
    gimage_free(&img);
    FILE *fp = fopen(whole, "rb");
    assert_non_null(fp);
    static unsigned char bytes[1 << 16];
    size_t n = fread(bytes, 1, sizeof bytes, fp);
    fclose(fp);
    assert_true(n > 1000 && n < sizeof bytes);
    GMaterial *ref = image_node(&f->n, whole, GTEX_WRAP_CLAMP, GTEX_COLORSPACE_LINEAR);
    int refused = 0, loaded = 0;
    for (size_t len = 40; len < n; len += len < n - 40 ? 397 : 1) {
        snprintf(cut, sizeof cut, "%s/cut%zu.png", f->n.dir, len);
        fp = fopen(cut, "wb");
        assert_non_null(fp);
        assert_int_equal(fwrite(bytes, 1, len, fp), len);
        assert_int_equal(fclose(fp), 0);
        GImageNodeOptions o = {.texsys = f->n.ts, .swrap = GTEX_WRAP_CLAMP, .twrap = GTEX_WRAP_CLAMP,
                               .colorspace = GTEX_COLORSPACE_LINEAR};
        GMaterial *m = NULL;
        int rc = gnode_image_create(f->n.white, cut, &o, &m, &err);
        if (rc != G_OK) {
            assert_int_equal(rc, G_ERR_IO);
            assert_null(m);
            assert_non_null(strstr(err.message, cut));
            refused++;
        } else {
            for (int k = 0; k < 16; k++) {
                double u = (k % 4 + 0.5) / 4, v = (k / 4 + 0.5) / 4;
                assert_float_equal(lookup(f, m, u, v, 0.01 * N / W), lookup(f, ref, u, v, 0.01 * N / W), 1e-6);
            }
            gmaterial_unref(m);
            loaded++;
        }
        unlink(cut);
    }
    print_message("%d cut files refused, %d complete enough to load (of %zu bytes)\n", refused, loaded, n);
    assert_true(refused > 10);
    gmaterial_unref(ref);
    unlink(whole);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_texels),
        cmocka_unit_test(test_mip_level_follows_footprint),
        cmocka_unit_test(test_wrap_and_orientation),
        cmocka_unit_test(test_color_spaces),
        cmocka_unit_test(test_bad_files),
        cmocka_unit_test(test_emission_flag),
        cmocka_unit_test(test_nonfinite_texels),
        cmocka_unit_test(test_anisotropic_footprint),
        cmocka_unit_test(test_truncated_files),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
