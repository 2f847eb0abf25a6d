/* test_image_writers.c - "write only what can be written": every extension of gimage_write_extensions() (the
 * list --help prints, generated when the library was built) writes a small image that reads back with its size when
 * its format is one the library reads, and is refused by its content, naming the format, when it is not;
 * an extension outside the list is refused by gimage_check_output, naming the list, and gtrace refuses it before
 * it reads the scene. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_util.h"

#include "generic/services/image.h"

#include <string.h>

static char dir[128];

static int setup(void **state)
{
    (void)state;
    return tu_tempdir(dir, sizeof dir, "image_writers");
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

/* Whether files with extension ext are of a format the library reads (image.h): the others are refused. */
static int read_format(const char *ext)
{
    static const char *const read[] = {".exr", ".hdr", ".rgbe", ".pbm", ".pgm", ".pnm", ".ppm", ".png", ".jpg",
                                       ".jpeg", ".jpe", ".jfif", ".jfi", ".jif", ".tif", ".tiff", ".tx", ".env",
                                       ".sm", ".vsm", ".sxr", ".mxr"};
    for (size_t i = 0; i < sizeof read / sizeof read[0]; i++)
        if (!strcmp(ext, read[i]))
            return 1;
    return 0;
}

static void test_every_listed_extension_writes(void **state)
{
    (void)state;
    GImage img;
    GError err;
    assert_int_equal(gimage_create(&img, 5, 3, 3, &err), G_OK);
    for (int i = 0; i < 5 * 3 * 3; i++)
        img.pixels[i] = (float)(i % 7) / 6.0f;
    const char *list = gimage_write_extensions();
    assert_non_null(strstr(list, ".exr"));
    assert_non_null(strstr(list, ".png"));
    assert_null(strstr(list, ".pfm")); /* Debian 12's OpenImageIO has no PFM writer */
    int n = 0, nread = 0;
    for (const char *p = list; *p;) {
        size_t len = strcspn(p, " ");
        assert_true(p[0] == '.' && len > 1 && len < 16);
        char path[256];
        snprintf(path, sizeof path, "%s/w%d%.*s", dir, n, (int)len, p);
        assert_int_equal(gimage_check_output(path, &err), G_OK);
        if (gimage_write(path, &img, NULL, &err) != G_OK)
            fail_msg("%.*s is listed but does not write: %s", (int)len, p, err.message);
        int w = 0, h = 0, ch = 0;
        char ext[16];
        snprintf(ext, sizeof ext, "%.*s", (int)len, p);
        if (read_format(ext)) {
            if (gimage_info(path, &w, &h, &ch, &err) != G_OK)
                fail_msg("%s: the written file does not read back: %s", ext, err.message);
            assert_int_equal(w, 5);
            assert_int_equal(h, 3);
            nread++;
        } else if (gimage_info(path, &w, &h, &ch, &err) != G_ERR_IO || !strstr(err.message, "not one of the formats")) {
            fail_msg("%s: a written format the library does not read was not refused by its content: %s", ext,
                     err.message);
        }
        n++;
        p += len;
        p += *p == ' ';
    }
    print_message("%d extensions listed, each wrote a 5x3 image; %d read back, the others refused by content\n", n,
                  nread);
    assert_true(n >= 10);
    assert_true(nread >= 10);
    gimage_free(&img);
}

static void test_unlisted_refused(void **state)
{
    (void)state;
    GError err;
    const char *bad[] = {"x.pfm", "x.nosuchformat", "x.PFM", "noextension"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char path[256];
        snprintf(path, sizeof path, "%s/%s", dir, bad[i]);
        assert_int_equal(gimage_check_output(path, &err), G_ERR_IO);
        assert_true(strstr(err.message, "no writer for") || strstr(err.message, "no extension"));
        if (strchr(bad[i], '.'))
            assert_non_null(strstr(err.message, gimage_write_extensions()));
    }
    char path[256];
    snprintf(path, sizeof path, "%s/x.EXR", dir); /* case is ignored */
    assert_int_equal(gimage_check_output(path, &err), G_OK);
    /* gtrace refuses before reading the scene: a scene that does not exist is not what it complains about */
    const char *b = getenv("GENERIC_BUILD_DIR");
    char gtrace[512], args[512], out[4096];
    snprintf(gtrace, sizeof gtrace, "%s/bin/gtrace", b ? b : "build");
    if (access(gtrace, X_OK) != 0)
        skip();
    snprintf(args, sizeof args, "%s/no-such.scene -o %s/x.nosuchformat", dir, dir);
    assert_int_equal(tu_run_capture(gtrace, args, out, sizeof out), 1);
    assert_non_null(strstr(out, "no writer for '.nosuchformat'"));
    assert_null(strstr(out, "no-such.scene"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_listed_extension_writes),
        cmocka_unit_test(test_unlisted_refused),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
