/* test_image_module.c - the OpenImageIO module is loaded on first use, once, when several threads need it at the
 * same moment (lib/image/oiio_module.h): before, the process maps no libOpenImageIO (PNG output goes through libpng and
 * needs none; NULL texture systems need none); then eight threads read the same PNG at once, all get the same
 * pixels, and the process maps the module exactly once. One test per process: the first use is the subject. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/services/image.h"
#include "generic/services/texsys.h"
#include "test_util.h"

/* Counts the distinct mapped files of /proc/self/maps whose path contains name. */
static int mapped(const char *name)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f)
        return -1;
    char line[4096], seen[16][512];
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        char *path = strchr(line, '/');
        if (!path || !strstr(path, name))
            continue;
        path[strcspn(path, "\n")] = 0;
        int known = 0;
        for (int i = 0; i < n; i++)
            known |= !strcmp(seen[i], path);
        if (!known && n < 16)
            snprintf(seen[n++], sizeof seen[0], "%s", path);
    }
    fclose(f);
    return n;
}

enum { THREADS = 8, W = 5, H = 3 };
static char path[300];
static pthread_barrier_t start;

typedef struct {
    int rc;
    GImage img;
    char message[512];
} Reader;

static void *read_at_once(void *arg)
{
    Reader *r = arg;
    GError err = {0};
    pthread_barrier_wait(&start);
    r->rc = gimage_read(path, GIMAGE_READ_RAW, &r->img, &err);
    snprintf(r->message, sizeof r->message, "%s", err.message);
    return NULL;
}

static void test_first_use_from_threads(void **state)
{
    (void)state;
    char dir[128];
    assert_int_equal(tu_tempdir(dir, sizeof dir, "gimage_module"), 0);
    snprintf(path, sizeof path, "%s/ramp.png", dir);
    assert_int_equal(mapped("libOpenImageIO"), 0);

    GError err = {0};
    GImage img;
    assert_int_equal(gimage_create(&img, W, H, 3, &err), G_OK);
    for (int i = 0; i < W * H * 3; i++)
        img.pixels[i] = (float)gimage_srgb_decode((double)(i * 17 % 256) / 255.0); /* exact 8-bit codes */
    assert_int_equal(gimage_check_output(path, &err), G_OK);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    gtexsys_unref(NULL);
    assert_null(gtexsys_ref(NULL));
    assert_int_equal(mapped("libOpenImageIO"), 0); /* PNG output and NULL systems load nothing */
    assert_int_equal(mapped("libgeneric_oiio"), 0);

    pthread_t t[THREADS];
    Reader r[THREADS];
    assert_int_equal(pthread_barrier_init(&start, NULL, THREADS), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_create(&t[i], NULL, read_at_once, &r[i]), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_join(t[i], NULL), 0);
    pthread_barrier_destroy(&start);
    for (int i = 0; i < THREADS; i++) {
        if (r[i].rc != G_OK)
            fail_msg("thread %d: %s", i, r[i].message);
        assert_int_equal(r[i].img.width, W);
        assert_int_equal(r[i].img.height, H);
        assert_int_equal(r[i].img.channels, 3);
        for (int k = 0; k < W * H * 3; k++) /* RAW: the 8-bit codes as they are in the file */
            assert_near(r[i].img.pixels[k], (double)(k * 17 % 256) / 255.0, 1e-6);
        gimage_free(&r[i].img);
    }
    assert_int_equal(mapped("libgeneric_oiio.so"), 1);
    assert_true(mapped("libOpenImageIO") >= 1);
    gimage_free(&img);
    assert_int_equal(tu_rmtree(dir), 0);
}

int main(void)
{
    setenv("GENERIC_DECODE", "inprocess", 1); /* the module's first use in this process, from several threads */
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_use_from_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
