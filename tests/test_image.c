/* test_image.c - the OpenImageIO shim: round trips, encodings, errors, and no partial output. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/image.h"
#include "test_alloc.h"

static char dir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/gimage_test_XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    DIR *d = opendir(dir);
    if (d) {
        struct dirent *e;
        char p[600];
        while ((e = readdir(d)))
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
                snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
                unlink(p);
            }
        closedir(d);
    }
    rmdir(dir);
    return 0;
}

static const char *path_in_dir(const char *name)
{
    static char p[600];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return p;
}

static int count_files(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    assert_non_null(d);
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(d);
    return n;
}

/* Deterministic pseudo-random values in [lo, hi). */
static double rnd(unsigned *s, double lo, double hi)
{
    *s = *s * 1664525u + 1013904223u;
    return lo + (hi - lo) * ((*s >> 8) / 16777216.0);
}

static void fill(GImage *img, unsigned seed, double lo, double hi)
{
    size_t n = (size_t)img->width * img->height * img->channels;
    for (size_t i = 0; i < n; i++)
        img->pixels[i] = (float)rnd(&seed, lo, hi);
}

static void test_srgb_transfer(void **state)
{
    (void)state;
    assert_float_equal(gimage_srgb_encode(0.0), 0.0, 1e-12);
    assert_float_equal(gimage_srgb_encode(1.0), 1.0, 1e-12);
    assert_float_equal(gimage_srgb_encode(0.5), 0.735356983, 1e-8);   /* IEC 61966-2-1 */
    assert_float_equal(gimage_srgb_encode(0.002), 0.02584, 1e-12);    /* linear segment */
    for (double v = 0.0; v <= 1.0; v += 0.01)
        assert_float_equal(gimage_srgb_decode(gimage_srgb_encode(v)), v, 1e-12);
}

static void test_exr_round_trip_exact(void **state)
{
    (void)state;
    for (int ch = 3; ch <= 4; ch++) {
        GImage a, b;
        assert_int_equal(gimage_create(&a, 37, 23, ch, NULL), G_OK);
        fill(&a, 7u + ch, -2.0, 5000.0);
        a.pixels[5] = 1e-30f;
        a.pixels[6] = 65504.0f * 3.0f; /* beyond half range: EXR must be written as float */
        GError err;
        assert_int_equal(gimage_write(path_in_dir("a.exr"), &a, NULL, &err), G_OK);
        assert_int_equal(gimage_read(path_in_dir("a.exr"), 0, &b, &err), G_OK);
        assert_int_equal(b.width, 37);
        assert_int_equal(b.height, 23);
        assert_int_equal(b.channels, ch);
        assert_memory_equal(a.pixels, b.pixels, sizeof(float) * 37 * 23 * ch);
        gimage_free(&a);
        gimage_free(&b);
        assert_null(b.pixels);
    }
    assert_int_equal(count_files(), 1); /* only a.exr: no temporaries left */
}

/* A crop written with its place in the full image reports it back as its window; a plain image is its own
 * whole picture; a missing file is G_ERR_IO. */
static void test_window_of_a_crop(void **state)
{
    (void)state;
    GImage a;
    GError err;
    assert_int_equal(gimage_create(&a, 7, 5, 3, NULL), G_OK);
    fill(&a, 3u, 0.0, 1.0);
    GImageWriteOptions opt = {.x = 11, .y = 4, .full_width = 40, .full_height = 30};
    assert_int_equal(gimage_write(path_in_dir("crop.exr"), &a, &opt, &err), G_OK);
    GImageWindow w;
    assert_int_equal(gimage_window(path_in_dir("crop.exr"), &w, &err), G_OK);
    assert_int_equal(w.x, 11);
    assert_int_equal(w.y, 4);
    assert_int_equal(w.width, 7);
    assert_int_equal(w.height, 5);
    assert_int_equal(w.full_width, 40);
    assert_int_equal(w.full_height, 30);
    assert_int_equal(gimage_write(path_in_dir("whole.exr"), &a, NULL, &err), G_OK);
    assert_int_equal(gimage_window(path_in_dir("whole.exr"), &w, &err), G_OK);
    assert_true(w.x == 0 && w.y == 0 && w.width == 7 && w.height == 5 && w.full_width == 7 && w.full_height == 5);
    assert_int_equal(gimage_window(path_in_dir("absent.exr"), &w, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "absent.exr"));
    assert_int_equal(gimage_window(path_in_dir("crop.exr"), NULL, &err), G_ERR_INVALID);
    gimage_free(&a);
}

static void test_png_round_trip(void **state)
{
    (void)state;
    const char *names[] = {"c.png", "c.tif"};
    for (int f = 0; f < 2; f++) {
        GImage a, b;
        assert_int_equal(gimage_create(&a, 64, 16, 4, NULL), G_OK);
        fill(&a, 11u, 0.0, 1.0);
        GError err;
        assert_int_equal(gimage_write(path_in_dir(names[f]), &a, NULL, &err), G_OK);
        assert_int_equal(gimage_read(path_in_dir(names[f]), 0, &b, &err), G_OK);
        assert_int_equal(b.channels, 4);
        double worst = 0.0;
        for (int i = 0; i < 64 * 16 * 4; i++) {
            double d = (i % 4 == 3) ? fabs(b.pixels[i] - a.pixels[i])
                                    : fabs(gimage_srgb_encode(b.pixels[i]) - gimage_srgb_encode(a.pixels[i]));
            if (d > worst)
                worst = d;
        }
        /* 8-bit quantisation of the encoded value: at most half a step, and certainly within 1/255 */
        assert_true(worst <= 0.5 / 255.0 + 1e-6);
        assert_true(worst > 0.0); /* it really was quantised */
        /* and the decoded value is linear: a mid grey of 0.5 encoded reads back near 0.5, not 0.735 */
        gimage_free(&a);
        gimage_free(&b);
    }
}

static void test_png_exposure_clamp_and_grey(void **state)
{
    (void)state;
    GImage a, b;
    assert_int_equal(gimage_create(&a, 4, 1, 1, NULL), G_OK);
    a.pixels[0] = 0.25f;  /* exposure +1 -> 0.5 */
    a.pixels[1] = 3.0f;   /* clamped to 1 */
    a.pixels[2] = -1.0f;  /* clamped to 0 */
    a.pixels[3] = NAN;    /* written as 0 */
    GImageWriteOptions opt = {.exposure = 1.0};
    GError err;
    assert_int_equal(gimage_write(path_in_dir("g.png"), &a, &opt, &err), G_OK);
    assert_int_equal(gimage_read(path_in_dir("g.png"), 0, &b, &err), G_OK);
    assert_int_equal(b.channels, 3); /* grey expanded to RGB */
    assert_float_equal(b.pixels[0], gimage_srgb_decode(188.0 / 255.0), 1e-6); /* round(0.7354*255) = 188 */
    assert_float_equal(b.pixels[1], b.pixels[0], 0.0);
    assert_float_equal(b.pixels[3], 1.0, 1e-7);
    assert_float_equal(b.pixels[6], 0.0, 0.0);
    assert_float_equal(b.pixels[9], 0.0, 0.0);
    gimage_free(&b);
    /* raw reading keeps the encoded value */
    assert_int_equal(gimage_read(path_in_dir("g.png"), GIMAGE_READ_RAW | GIMAGE_READ_RGBA, &b, &err), G_OK);
    assert_int_equal(b.channels, 4);
    assert_float_equal(b.pixels[0], 188.0 / 255.0, 1e-6);
    assert_float_equal(b.pixels[3], 1.0, 0.0);
    int w, h, c;
    assert_int_equal(gimage_info(path_in_dir("g.png"), &w, &h, &c, &err), G_OK);
    assert_int_equal(w, 4);
    assert_int_equal(h, 1);
    assert_int_equal(c, 1);
    gimage_free(&b);
    gimage_free(&a);
    /* a header with a size below 1 (a PFM with a negative width) is refused, not passed on */
    FILE *f = fopen(path_in_dir("neg.pfm"), "wb");
    assert_non_null(f);
    fprintf(f, "PF\n-8 4\n-1.0\n");
    float zero[96] = {0};
    fwrite(zero, sizeof zero, 1, f);
    fclose(f);
    GError err2;
    assert_int_equal(gimage_info(path_in_dir("neg.pfm"), &w, &h, &c, &err2), G_ERR_IO);
    assert_non_null(strstr(err2.message, "invalid image size"));
    assert_int_not_equal(gimage_read(path_in_dir("neg.pfm"), 0, &b, &err2), G_OK);
    assert_null(b.pixels);
    unlink(path_in_dir("neg.pfm"));
}

/* The code the PNG writer must give a linear value: round(255 * sRGB(clamp(v, 0, 1))), NaN as 0. */
static int srgb_code(double v)
{
    if (!(v > 0.0))
        v = 0.0;
    v = gimage_srgb_encode(v);
    return (int)((v > 1.0 ? 1.0 : v) * 255.0 + 0.5);
}

/* The writer's table of codes gives exactly the formula's code on both sides of every one of the 255 steps
 * (values a few ulps and 1e-9 around each step, as floats) and for 0, negatives, NaN, 1 and beyond. */
static void test_png_codes_match_formula(void **state)
{
    (void)state;
    enum { PER = 8, N = 255 * PER + 6 };
    GImage a, b;
    assert_int_equal(gimage_create(&a, N, 1, 1, NULL), G_OK);
    int n = 0;
    for (int k = 1; k <= 255; k++) {
        float t = (float)gimage_srgb_decode((k - 0.5) / 255.0);
        const float around[PER] = {nextafterf(t, 0.0f), t, nextafterf(t, 1.0f), nextafterf(nextafterf(t, 0.0f), 0.0f),
                                   t * (1.0f - 1e-6f), t * (1.0f + 1e-6f), t - 1e-9f, t + 1e-9f};
        for (int i = 0; i < PER; i++)
            a.pixels[n++] = around[i];
    }
    const float odd[6] = {0.0f, -0.5f, NAN, 1.0f, 7.0f, INFINITY};
    for (int i = 0; i < 6; i++)
        a.pixels[n++] = odd[i];
    GError err;
    assert_int_equal(gimage_write(path_in_dir("codes.png"), &a, NULL, &err), G_OK);
    assert_int_equal(gimage_read(path_in_dir("codes.png"), GIMAGE_READ_RAW, &b, &err), G_OK);
    int bad = 0;
    for (int i = 0; i < N; i++) {
        int got = (int)lround(b.pixels[(size_t)i * b.channels] * 255.0), want = srgb_code(a.pixels[i]);
        if (got != want && bad++ < 5)
            print_message("value %.9g: code %d, formula %d\n", a.pixels[i], got, want);
    }
    assert_int_equal(bad, 0);
    gimage_free(&b);
    gimage_free(&a);
    unlink(path_in_dir("codes.png"));
}

static void test_exr_exposure_and_alpha_drop(void **state)
{
    (void)state;
    GImage a, b;
    assert_int_equal(gimage_create(&a, 2, 2, 4, NULL), G_OK);
    for (int i = 0; i < 16; i++)
        a.pixels[i] = (float)(i + 1);
    GImageWriteOptions opt = {.exposure = -2.0};
    GError err;
    assert_int_equal(gimage_write(path_in_dir("e.exr"), &a, &opt, &err), G_OK);
    assert_int_equal(gimage_read(path_in_dir("e.exr"), GIMAGE_READ_RGB, &b, &err), G_OK);
    assert_int_equal(b.channels, 3);
    for (int p = 0; p < 4; p++)
        for (int c = 0; c < 3; c++)
            assert_float_equal(b.pixels[p * 3 + c], a.pixels[p * 4 + c] * 0.25f, 0.0);
    gimage_free(&b);
    assert_int_equal(gimage_read(path_in_dir("e.exr"), 0, &b, &err), G_OK);
    assert_int_equal(b.channels, 4);
    assert_float_equal(b.pixels[3], 4.0, 0.0); /* alpha not scaled by the exposure */
    gimage_free(&b);
    gimage_free(&a);
}

static void test_read_errors(void **state)
{
    (void)state;
    GImage b;
    GError err;
    assert_int_equal(gimage_read(path_in_dir("missing.exr"), 0, &b, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "missing.exr"));
    assert_null(b.pixels);
    FILE *f = fopen(path_in_dir("junk.png"), "w");
    assert_non_null(f);
    fputs("this is not an image\n", f);
    fclose(f);
    assert_int_equal(gimage_read(path_in_dir("junk.png"), 0, &b, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "junk.png"));
    assert_true(strlen(err.message) > strlen(path_in_dir("junk.png")) + 20); /* carries a reason */
    assert_int_equal(gimage_read(path_in_dir("x.png"), GIMAGE_READ_RGB | GIMAGE_READ_RGBA, &b, &err), G_ERR_INVALID);
    unlink(path_in_dir("junk.png"));
}

static void test_failed_write_leaves_nothing(void **state)
{
    (void)state;
    int before = count_files();
    GImage a;
    assert_int_equal(gimage_create(&a, 64, 64, 3, NULL), G_OK);
    fill(&a, 3u, 0.0, 1.0);
    GError err;
    /* unknown format */
    assert_int_equal(gimage_write(path_in_dir("x.notaformat"), &a, NULL, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "x.notaformat"));
    /* missing directory */
    assert_int_equal(gimage_write("/nonexistent-dir-of-test/x.png", &a, NULL, &err), G_ERR_IO);
    /* invalid image */
    GImage bad = {0, 0, 3, NULL};
    assert_int_equal(gimage_write(path_in_dir("y.png"), &bad, NULL, &err), G_ERR_INVALID);
    assert_int_equal(count_files(), before);

    /* an existing file survives a write that fails after the temporary was created */
    assert_int_equal(gimage_write(path_in_dir("keep.png"), &a, NULL, &err), G_OK);
    struct stat st0, st1;
    assert_int_equal(stat(path_in_dir("keep.png"), &st0), 0);
    GImage big;
    assert_int_equal(gimage_create(&big, 256, 256, 3, NULL), G_OK);
    /* blocks of 60000 bytes and more refused: more than a row, less than the encoder's state (zlib's 64 KiB
     * deflate window) */
    static TuAlloc limited;
    limited = (TuAlloc){.max_bytes = 60000};
    tu_alloc_install(&limited);
    int rc = gimage_write(path_in_dir("keep.png"), &big, NULL, &err);
    gmem_set_allocator(NULL);
    assert_int_equal(rc, G_ERR_NOMEM);
    assert_int_equal(stat(path_in_dir("keep.png"), &st1), 0);
    assert_int_equal(st0.st_size, st1.st_size);
    assert_int_equal(st0.st_ino, st1.st_ino);
    assert_int_equal(count_files(), before + 1); /* keep.png only: the temporary is gone */
    GImage back;
    assert_int_equal(gimage_read(path_in_dir("keep.png"), 0, &back, &err), G_OK);
    assert_int_equal(back.width, 64);
    gimage_free(&back);
    gimage_free(&big);
    gimage_free(&a);
    gimage_free(NULL);
}

static void test_create_rejects_bad_sizes(void **state)
{
    (void)state;
    GImage a;
    assert_int_equal(gimage_create(&a, 0, 4, 3, NULL), G_ERR_INVALID);
    assert_int_equal(gimage_create(&a, 4, 4, 5, NULL), G_ERR_INVALID);
    assert_int_equal(gimage_create(&a, 1 << 20, 1 << 20, 3, NULL), G_ERR_INVALID);
    assert_null(a.pixels);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_srgb_transfer),
        cmocka_unit_test(test_exr_round_trip_exact),
        cmocka_unit_test(test_window_of_a_crop),
        cmocka_unit_test(test_png_round_trip),
        cmocka_unit_test(test_png_exposure_clamp_and_grey),
        cmocka_unit_test(test_png_codes_match_formula),
        cmocka_unit_test(test_exr_exposure_and_alpha_drop),
        cmocka_unit_test(test_read_errors),
        cmocka_unit_test(test_failed_write_leaves_nothing),
        cmocka_unit_test(test_create_rejects_bad_sizes),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
