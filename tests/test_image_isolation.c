/* test_image_isolation.c - untrusted images: decided by content and decoded in the decoder process.
 * - Files of formats the library does not read (IFF, DPX, ... named .png or .hdr) are refused by their content,
 *   naming the format found, in both decoding modes, and by the texture system too.
 * - A decoder that crashes, spins or grows without bound becomes an error for that one file (the signal or the
 *   limit named), and the next file decodes in a new decoder with the same pixels as in this process.
 * - Decodes are charged to the memory budget: light probes are held against it until they are destroyed, so that
 *   loading the same probe again and again stops at exactly floor(limit / probe bytes) probes, refused before the
 *   decode; a probe whose tables alone exceed what is left is refused from its header.
 * - Textures of more than 8192 x 8192 pixels (small PNG files of 12000 x 12000) are refused from their header.
 * - GENERIC_DECODE accepts "isolated" and "inprocess" only. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/services/image.h"
#include "generic/services/probe.h"
#include "generic/services/texsys.h"
#include "test_util.h"

#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char dir[256];

static int setup(void **state)
{
    (void)state;
    if (tu_tempdir(dir, sizeof dir, "test_image_isolation") != 0)
        return -1;
    GError err;
    return generic_register_builtins(&err) == G_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

static const char *in_dir(const char *name)
{
    static char path[512];
    return tu_in_dir(dir, name, path, sizeof path);
}

static void write_bytes(const char *path, const void *bytes, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

/* A PFM of w x h RGB pixels whose value is (x + 1) * 0.5, y * 0.25, 1. */
static void write_pfm(const char *path, int w, int h)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fprintf(f, "PF\n%d %d\n-1.0\n", w, h);
    for (int y = h - 1; y >= 0; y--) /* PFM rows go from the bottom up */
        for (int x = 0; x < w; x++) {
            float px[3] = {(float)(x + 1) * 0.5f, (float)y * 0.25f, 1.0f};
            assert_int_equal(fwrite(px, sizeof px, 1, f), 1);
        }
    assert_int_equal(fclose(f), 0);
}

/* The headers of formats OpenImageIO reads and the library does not, padded to 176 bytes of a mutated body. */
static void test_foreign_formats_refused(void **state)
{
    (void)state;
    static const struct {
        const char *magic, *name, *file;
    } foreign[] = {
        {"FOR4", "IFF", "iff_as.png"},      {"FOR4", "IFF", "iff_as.hdr"}, {"SDPX", "DPX", "dpx_as.hdr"},
        {"XPDS", "DPX", "dpx_as.exr"},      {"BM", "BMP", "bmp_as.png"},   {"GIF8", "GIF", "gif_as.tif"},
        {"\x80\x2a\x5f\xd7", "Cineon", "cin_as.pfm"},
    };
    const char *modes[] = {"isolated", "inprocess"};
    for (int m = 0; m < 2; m++) {
        setenv("GENERIC_DECODE", modes[m], 1);
        for (size_t i = 0; i < sizeof foreign / sizeof foreign[0]; i++) {
            unsigned char body[176];
            for (size_t k = 0; k < sizeof body; k++)
                body[k] = (unsigned char)(k * 37 + i);
            memcpy(body, foreign[i].magic, strlen(foreign[i].magic));
            const char *path = in_dir(foreign[i].file);
            write_bytes(path, body, sizeof body);
            GImage img;
            GError err;
            assert_int_equal(gimage_read(path, 0, &img, &err), G_ERR_IO);
            assert_null(img.pixels);
            char expect[64];
            snprintf(expect, sizeof expect, "its content is %s, not one of the formats read", foreign[i].name);
            if (!strstr(err.message, expect))
                fail_msg("%s (%s): %s", foreign[i].file, modes[m], err.message);
            assert_int_equal(gimage_info(path, NULL, NULL, NULL, &err), G_ERR_IO);
            assert_non_null(strstr(err.message, expect));
        }
    }
    setenv("GENERIC_DECODE", "isolated", 1);
    GTextureSystem *ts = NULL;
    GError err;
    assert_int_equal(gtexsys_create(&ts, &err), G_OK);
    GTexFile *file;
    int channels, srgb;
    assert_int_equal(gtexsys_open(ts, in_dir("iff_as.png"), GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err),
                     G_ERR_IO);
    assert_non_null(strstr(err.message, "its content is IFF"));
    setenv("GENERIC_DECODE", "inprocess", 1); /* the texture system checks the content itself too */
    assert_int_equal(gtexsys_open(ts, in_dir("dpx_as.hdr"), GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err),
                     G_ERR_IO);
    assert_non_null(strstr(err.message, "its content is DPX"));
    setenv("GENERIC_DECODE", "isolated", 1);
    gtexsys_unref(ts);
}

/* Reads probe.pfm (4x2) and checks every pixel. */
static void read_and_check(const char *path)
{
    GImage img;
    GError err;
    if (gimage_read(path, GIMAGE_READ_RGB, &img, &err) != G_OK)
        fail_msg("%s", err.message);
    assert_int_equal(img.width, 4);
    assert_int_equal(img.height, 2);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 4; x++) {
            const float *p = img.pixels + (y * 4 + x) * 3;
            assert_true(p[0] == (float)(x + 1) * 0.5f && p[1] == (float)y * 0.25f && p[2] == 1.0f);
        }
    gimage_free(&img);
}

static void test_decoder_faults_contained(void **state)
{
    (void)state;
    const char *path = in_dir("small.pfm");
    write_pfm(path, 4, 2);
    setenv("GENERIC_DECODE", "isolated", 1);
    static const struct {
        const char *file, *says;
    } faults[] = {
#if !defined(__SANITIZE_ADDRESS__)
        {"fault-crash.pfm", "its decoder crashed (Segmentation fault)"},
#else /* the sanitizer reports the fault and ends the decoder with status 1 */
        {"fault-crash.pfm", "its decoder ended (exit status 1)"},
#endif
        {"fault-spin.pfm", "its decoder took more than its"},
#if !defined(__SANITIZE_ADDRESS__) /* a sanitizer build's decoder has no address space limit */
        {"fault-grow.pfm", "its decoder crashed (Aborted)"},
#endif
    };
    for (size_t i = 0; i < sizeof faults / sizeof faults[0]; i++) {
        read_and_check(path);
        char faulty[512];
        tu_in_dir(dir, faults[i].file, faulty, sizeof faulty);
        write_pfm(faulty, 4, 2);
        GImage img;
        GError err;
        assert_int_equal(gimage_read(faulty, 0, &img, &err), G_ERR_IO);
        assert_null(img.pixels);
        if (!strstr(err.message, faults[i].says) || !strstr(err.message, faulty))
            fail_msg("%s: %s", faults[i].file, err.message);
        print_message("%s: %s\n", faults[i].file, err.message);
        assert_int_equal(gmem_budget_used(), 0); /* the failed decode's charge is returned */
        read_and_check(path); /* the next file: a new decoder, the same pixels */
    }
}

static void test_probes_held_against_budget(void **state)
{
    (void)state;
    setenv("GENERIC_DECODE", "isolated", 1);
    const char *path = in_dir("probe.pfm");
    write_pfm(path, 256, 128);
    /* the tables of a 256x128 probe: 6 floats a pixel, 7 doubles a corner of the summed-area table */
    const size_t probe = 256u * 128u * 6u * 4u + 257u * 129u * 7u * 8u;
    const size_t limit = 64u << 20;
    gmem_budget_set_limit(limit);
    assert_int_equal(gmem_budget_used(), 0);
    enum { MAX = 64 };
    GProbe *held[MAX];
    int n = 0;
    GError err;
    int rc;
    while (n < MAX && (rc = gprobe_load(path, GPROBE_AUTO, 0, &held[n], &err)) == G_OK)
        n++;
    assert_int_equal(rc, G_ERR_NOMEM);
    print_message("%d probes held, the next refused: %s\n", n, err.message);
    assert_int_equal(n, (int)(limit / probe));
    assert_non_null(strstr(err.message, path));
    assert_non_null(strstr(err.message, "a 256x128 probe"));
    assert_non_null(strstr(err.message, "GENERIC_MEMORY_LIMIT_MB"));
    assert_int_equal(gmem_budget_used(), (size_t)n * probe);
    for (int i = 0; i < n; i++)
        gprobe_destroy(held[i]);
    assert_int_equal(gmem_budget_used(), 0);
    /* one probe whose tables alone do not fit: refused from its header */
    gmem_budget_set_limit(probe - 1);
    GProbe *p = NULL;
    assert_int_equal(gprobe_load(path, GPROBE_AUTO, 0, &p, &err), G_ERR_NOMEM);
    assert_null(p);
    assert_non_null(strstr(err.message, "a 256x128 probe needs"));
    gmem_budget_set_limit(0);
}

/* A true PNG of w x h black pixels, 1 bit each: a few kilobytes for a huge image. */
static void write_black_png(const char *path, int w, int h)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    assert_true(png && info);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng failed writing %s", path);
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_bytep row = calloc((size_t)(w + 7) / 8, 1);
    for (int y = 0; y < h; y++)
        png_write_row(png, row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    assert_int_equal(fclose(f), 0);
}

/* Four small files of 12000 x 12000 pixels as textures: each refused from its header, naming the limit, and so
 * is one of a row more than 8192 x 8192. */
static void test_huge_textures_refused(void **state)
{
    (void)state;
    setenv("GENERIC_DECODE", "isolated", 1);
    GTextureSystem *ts = NULL;
    GError err;
    assert_int_equal(gtexsys_create(&ts, &err), G_OK);
    GTexFile *file;
    int channels, srgb;
    for (int i = 0; i < 4; i++) {
        char name[32], path[512];
        snprintf(name, sizeof name, "huge%d.png", i);
        tu_in_dir(dir, name, path, sizeof path);
        write_black_png(path, 12000, 12000);
        assert_int_equal(gtexsys_open(ts, path, GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err), G_ERR_IO);
        if (!strstr(err.message, "is 12000x12000 pixels, more than a texture may have"))
            fail_msg("%s", err.message);
    }
    print_message("%s\n", err.message);
    assert_int_equal(gmem_budget_used(), 512u << 20); /* the texture system's cache only: nothing decoded */
    const char *edge = in_dir("edge.png"); /* one row over the limit */
    write_black_png(edge, 8192, 8193);
    assert_int_equal(gtexsys_open(ts, edge, GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "is 8192x8193 pixels"));
    write_black_png(edge, 64, 32);
    if (gtexsys_open(ts, edge, GTEX_COLORSPACE_AUTO, &file, &channels, &srgb, &err) != G_OK)
        fail_msg("%s", err.message);
    gtexsys_unref(ts);
    assert_int_equal(gmem_budget_used(), 0);
}

static void test_decode_switch(void **state)
{
    (void)state;
    const char *path = in_dir("small.pfm");
    write_pfm(path, 4, 2);
    setenv("GENERIC_DECODE", "inprocess", 1);
    read_and_check(path);
    setenv("GENERIC_DECODE", "", 1);
    read_and_check(path);
    setenv("GENERIC_DECODE", "sandbox", 1);
    GImage img;
    GError err;
    assert_int_equal(gimage_read(path, 0, &img, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "GENERIC_DECODE is 'sandbox'"));
    setenv("GENERIC_DECODE", "isolated", 1);
}

int main(void)
{
    setenv("GENERIC_DECODE_FAULT", "by-name", 1); /* files named fault-*: see lib/image/decoder/generic_decode.c */
    unsetenv("GENERIC_MEMORY_LIMIT_MB");
    unsetenv("GENERIC_IMAGE_BUDGET_MB");
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_foreign_formats_refused),
        cmocka_unit_test(test_decoder_faults_contained),
        cmocka_unit_test(test_probes_held_against_budget),
        cmocka_unit_test(test_huge_textures_refused),
        cmocka_unit_test(test_decode_switch),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
