/* test_image_exr.c - OpenEXR output without OpenImageIO (lib/image/image_exr.h): a process that writes EXR files maps
 * neither the OpenImageIO module nor OpenImageIO; every file reads back through gimage_read (OpenImageIO's reader, in
 * the decoder process) with the written floats bit for bit (denormals, huge, negative, NaN and infinite values), for
 * 1 to 4 channels and sizes around the 16 scanlines of a ZIP chunk; exposure scales the colour channels and not
 * alpha; a crop keeps its windows and note; a failed write leaves no file and an existing one untouched. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/image.h"
#include "test_util.h"

static char dir[128];

/* Whether /proc/self/maps has a file whose path contains name. */
static int mapped(const char *name)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f)
        return -1;
    char line[4096];
    int found = 0;
    while (fgets(line, sizeof line, f))
        found |= strchr(line, '/') && strstr(strchr(line, '/'), name);
    fclose(f);
    return found;
}

/* The next of a xorshift sequence. */
static uint32_t next_bits(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (uint32_t)(*s >> 16);
}

/* The float whose bits are b. */
static float from_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

/* img (w x h, ch channels) filled with arbitrary bit patterns, the special values first. */
static void fill(GImage *img, int w, int h, int ch, uint64_t seed)
{
    GError err = {0};
    assert_int_equal(gimage_create(img, w, h, ch, &err), G_OK);
    static const uint32_t special[] = {0x00000001u, 0x807fffffu, 0x7f7fffffu, 0xff7fffffu, 0x7f800000u, 0xff800000u,
                                       0x7fc00000u, 0xffc12345u, 0x7f800001u, 0x80000000u, 0x00000000u, 0xbf800000u};
    const size_t n = (size_t)w * h * ch;
    for (size_t i = 0; i < n; i++)
        img->pixels[i] = from_bits(i < tu_floats(special) ? special[i] : next_bits(&seed));
}

/* Writes img to name in dir with opt, reads it back whole: G_OK expected from both. */
static void write_read(const GImage *img, const char *name, const GImageWriteOptions *opt, GImage *back)
{
    char path[300];
    GError err = {0};
    tu_in_dir(dir, name, path, sizeof path);
    if (gimage_write(path, img, opt, &err) != G_OK)
        fail_msg("writing %s: %s", path, err.message);
    if (gimage_read(path, 0, back, &err) != G_OK)
        fail_msg("reading %s: %s", path, err.message);
    assert_int_equal(back->width, img->width);
    assert_int_equal(back->height, img->height);
    assert_int_equal(back->channels, img->channels == 1 || img->channels == 3 ? 3 : 4);
}

/* The written channel that gimage_read returns as channel c of a file of ch channels: grey as RGB, grey and alpha
 * as RGBA. */
static int source_channel(int ch, int c)
{
    static const int map[4][4] = {{0, 0, 0}, {0, 0, 0, 1}, {0, 1, 2}, {0, 1, 2, 3}};
    return map[ch - 1][c];
}

/* Whether back (as gimage_read returns it) holds want's values bit for bit; a signalling NaN may come back quiet
 * (the reader passes colour values through a double). Fails naming what differs. */
static void assert_same_bits(const GImage *want, const GImage *back, const char *name)
{
    for (size_t i = 0; i < (size_t)want->width * want->height; i++)
        for (int c = 0; c < back->channels; c++) {
            uint32_t a, b;
            memcpy(&a, &want->pixels[i * want->channels + source_channel(want->channels, c)], 4);
            memcpy(&b, &back->pixels[i * back->channels + c], 4);
            if (a != b && !(isnan(from_bits(a)) && (a | 0x00400000u) == b))
                fail_msg("%s: pixel %zu channel %d written 0x%08x, read 0x%08x", name, i, c, a, b);
        }
}

/* Runs first: writing EXR files (and checking their names) maps OpenEXRCore and no OpenImageIO. */
static void test_write_loads_no_oiio(void **state)
{
    (void)state;
    GImage img;
    fill(&img, 7, 5, 3, 1);
    char path[300];
    GError err = {0};
    assert_int_equal(gimage_check_output(tu_in_dir(dir, "first.EXR", path, sizeof path), &err), G_OK);
    assert_int_equal(mapped("libOpenEXRCore"), 0);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    GImageWriteOptions crop = {0.5, 1, 2, 20, 10, NULL, NULL, "a note"};
    assert_int_equal(gimage_write(tu_in_dir(dir, "second.exr", path, sizeof path), &img, &crop, &err), G_OK);
    assert_int_equal(mapped("libOpenEXRCore"), 1);
    assert_int_equal(mapped("libgeneric_oiio"), 0);
    assert_int_equal(mapped("libOpenImageIO"), 0);
    gimage_free(&img);
}

static void test_bits_all_channels_and_sizes(void **state)
{
    (void)state;
    static const int sizes[][2] = {{1, 1}, {1, 37}, {37, 1}, {19, 41}, {33, 16}, {5, 17}};
    const int nsizes = TU_SANITIZED ? 3 : (int)tu_floats(sizes);
    for (int ch = 1; ch <= 4; ch++)
        for (int s = 0; s < nsizes; s++) {
            GImage img, back;
            fill(&img, sizes[s][0], sizes[s][1], ch, 1000u * ch + s + 7);
            char name[64];
            snprintf(name, sizeof name, "bits%d_%dx%d.exr", ch, sizes[s][0], sizes[s][1]);
            write_read(&img, name, NULL, &back);
            assert_same_bits(&img, &back, name);
            gimage_free(&img);
            gimage_free(&back);
        }
}

static void test_exposure_scales_colour_not_alpha(void **state)
{
    (void)state;
    const double exposure = -2.5, scale = exp2(exposure);
    for (int ch = 1; ch <= 4; ch++) {
        GImage img, back;
        GError err = {0};
        assert_int_equal(gimage_create(&img, 9, 18, ch, &err), G_OK);
        uint64_t seed = 99u + ch;
        for (int i = 0; i < 9 * 18 * ch; i++)
            img.pixels[i] = (float)((next_bits(&seed) & 0xffffff) / 65536.0 - 100.0);
        GImageWriteOptions opt = {exposure, 0, 0, 0, 0, NULL, NULL, NULL};
        char name[64];
        snprintf(name, sizeof name, "exposure%d.exr", ch);
        write_read(&img, name, &opt, &back);
        const int alpha = ch == 2 || ch == 4 ? ch - 1 : -1;
        for (int i = 0; i < 9 * 18 * ch; i++) /* the expected values, in place */
            img.pixels[i] = i % ch == alpha ? img.pixels[i] : (float)(img.pixels[i] * scale);
        assert_same_bits(&img, &back, name);
        gimage_free(&img);
        gimage_free(&back);
    }
}

static void test_crop_windows_and_note(void **state)
{
    (void)state;
    GImage img, back;
    fill(&img, 13, 21, 4, 5);
    GError err = {0};
    GImageWriteOptions crop = {0, 6, 35, 40, 60, NULL, NULL, "render 3f2a of 4, tile 2"};
    write_read(&img, "crop.exr", &crop, &back);
    assert_same_bits(&img, &back, "crop.exr");
    char path[300];
    GImageWindow win;
    assert_int_equal(gimage_window(tu_in_dir(dir, "crop.exr", path, sizeof path), &win, &err), G_OK);
    assert_int_equal(win.x, 6);
    assert_int_equal(win.y, 35);
    assert_int_equal(win.width, 13);
    assert_int_equal(win.height, 21);
    assert_int_equal(win.full_width, 40);
    assert_int_equal(win.full_height, 60);
    assert_string_equal(win.note, "render 3f2a of 4, tile 2");
    gimage_free(&back);

    /* the crop at the far corner, without a note */
    GImageWriteOptions corner = {0, 27, 39, 40, 60, NULL, NULL, NULL};
    write_read(&img, "corner.exr", &corner, &back);
    gimage_free(&back);
    assert_int_equal(gimage_window(tu_in_dir(dir, "corner.exr", path, sizeof path), &win, &err), G_OK);
    assert_true(win.x == 27 && win.y == 39 && win.full_width == 40 && win.full_height == 60);
    assert_string_equal(win.note, "");

    /* a whole image: both windows the image, the note not stored */
    GImageWriteOptions whole = {0, 0, 0, 0, 0, NULL, NULL, "not stored"};
    write_read(&img, "whole.exr", &whole, &back);
    gimage_free(&back);
    assert_int_equal(gimage_window(tu_in_dir(dir, "whole.exr", path, sizeof path), &win, &err), G_OK);
    assert_true(win.x == 0 && win.y == 0 && win.full_width == 13 && win.full_height == 21);
    assert_string_equal(win.note, "");

    /* a crop that does not fit is refused before anything is written */
    GImageWriteOptions outside = {0, 28, 0, 40, 60, NULL, NULL, NULL};
    assert_int_equal(gimage_write(tu_in_dir(dir, "outside.exr", path, sizeof path), &img, &outside, &err),
                     G_ERR_INVALID);
    assert_int_equal(access(path, F_OK), -1);
    gimage_free(&img);
}

/* A write that fails part way (the file size limit: EFBIG) leaves no file, no temporary, and an existing file as it
 * was; a directory that does not exist is refused. */
static void test_failed_write_leaves_no_file(void **state)
{
    (void)state;
    char sub[200], path[300];
    tu_in_dir(dir, "failing", sub, sizeof sub);
    assert_int_equal(mkdir(sub, 0700), 0);
    snprintf(path, sizeof path, "%s/big.exr", sub);
    GImage img;
    fill(&img, 64, 64, 4, 11); /* random bits: about 64 KiB compressed */
    GError err = {0};

    struct rlimit old, small = {16384, 0};
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    small.rlim_max = old.rlim_max;
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
    int rc = gimage_write(path, &img, NULL, &err);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
    signal(SIGXFSZ, prev);
    assert_int_equal(rc, G_ERR_IO);
    if (!strstr(err.message, "big.exr") || !strstr(err.message, strerror(EFBIG)))
        fail_msg("not the write's own failure: %s", err.message);
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(rmdir(sub), 0); /* empty: no temporary left either */
    assert_int_equal(mkdir(sub, 0700), 0);

    /* the limit reached in the header, its first bytes or its chunk table: the library reports the failure while it
     * holds its context's lock (a handler that asked the context for anything would wait for ever) */
    const rlim_t early[] = {1, 8, 64, 300, 1000};
    for (size_t k = 0; k < sizeof early / sizeof early[0]; k++) {
        small.rlim_cur = early[k];
        prev = signal(SIGXFSZ, SIG_IGN);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
        rc = gimage_write(path, &img, NULL, &err);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
        signal(SIGXFSZ, prev);
        assert_int_equal(rc, G_ERR_IO);
        if (!strstr(err.message, "big.exr"))
            fail_msg("a failure at %ld bytes not named: %s", (long)early[k], err.message);
        assert_int_equal(access(path, F_OK), -1);
    }
    assert_int_equal(rmdir(sub), 0);
    small.rlim_cur = 16384;

    /* an existing file is kept as it was */
    assert_int_equal(mkdir(sub, 0700), 0);
    assert_int_equal(tu_write_file(path, "kept"), 0);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
    prev = signal(SIGXFSZ, SIG_IGN);
    rc = gimage_write(path, &img, NULL, &err);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
    signal(SIGXFSZ, prev);
    assert_int_equal(rc, G_ERR_IO);
    char text[16] = {0};
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    assert_int_equal(fread(text, 1, sizeof text - 1, f), 4);
    fclose(f);
    assert_string_equal(text, "kept");
    assert_int_equal(unlink(path), 0);
    assert_int_equal(rmdir(sub), 0);

    /* a folder that does not exist, or one that cannot be written (unless the process may write anywhere) */
    snprintf(path, sizeof path, "%s/missing/x.exr", dir);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_ERR_IO);
    assert_int_equal(mkdir(sub, 0500), 0);
    snprintf(path, sizeof path, "%s/x.exr", sub);
    if (geteuid() != 0) {
        assert_int_equal(gimage_write(path, &img, NULL, &err), G_ERR_IO);
        assert_int_equal(access(path, F_OK), -1);
    }
    assert_int_equal(rmdir(sub), 0);
    gimage_free(&img);
}

static int setup(void **state)
{
    (void)state;
    return tu_tempdir(dir, sizeof dir, "gimage_exr");
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_write_loads_no_oiio),
        cmocka_unit_test(test_bits_all_channels_and_sizes),
        cmocka_unit_test(test_exposure_scales_colour_not_alpha),
        cmocka_unit_test(test_crop_windows_and_note),
        cmocka_unit_test(test_failed_write_leaves_no_file),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
