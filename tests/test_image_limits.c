/* test_image_limits.c - image headers that lie: a generator of PNG, PFM and HDR files whose headers claim
 * far more pixels than they hold, and of OpenEXR headers whose attributes claim more than their file, each refused
 * by every reader (gimage_read, gimage_info, gprobe_load, the image node) before the claimed memory is allocated
 * and within a second; the memory budget (refusal above it, a budget-sized image accepted, the setting restored);
 * true images at the extreme of compression still read. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/services/image.h"
#include "generic/services/probe.h"
#include "generic/reader.h"
#include "test_util.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

static char dir[256];

static int setup(void **state)
{
    (void)state;
    if (tu_tempdir(dir, sizeof dir, "test_image_limits") != 0)
        return -1;
    GError err;
    return generic_register_builtins(&err) == G_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

static long max_rss_kb(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

/* ---- the generator ---- */

static uint32_t crc32_of(const unsigned char *p, size_t n, uint32_t c)
{
    c = ~c;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

static void put32(FILE *f, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)(v >> 24), (unsigned char)(v >> 16), (unsigned char)(v >> 8),
                          (unsigned char)v};
    fwrite(b, 1, 4, f);
}

static void chunk(FILE *f, const char *type, const unsigned char *data, uint32_t n)
{
    put32(f, n);
    fwrite(type, 1, 4, f);
    if (n)
        fwrite(data, 1, n, f);
    uint32_t c = crc32_of((const unsigned char *)type, 4, 0);
    put32(f, crc32_of(data, n, c));
}

/* A PNG whose header is valid (with its CRC) and claims w x h pixels of colour type ct and depth bits,
 * followed by a few bytes of (broken) image data. */
static void lying_png(const char *path, uint32_t w, uint32_t h, int ct, int bits)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
    unsigned char ihdr[13] = {(unsigned char)(w >> 24), (unsigned char)(w >> 16), (unsigned char)(w >> 8),
                              (unsigned char)w, (unsigned char)(h >> 24), (unsigned char)(h >> 16),
                              (unsigned char)(h >> 8), (unsigned char)h, (unsigned char)bits, (unsigned char)ct,
                              0, 0, 0};
    chunk(f, "IHDR", ihdr, 13);
    if (ct == 3) {
        unsigned char plte[3] = {255, 0, 0};
        chunk(f, "PLTE", plte, 3);
    }
    const unsigned char idat[] = {0x78, 0x9c, 0x63, 0x00, 0x00, 0x00, 0x01, 0x00, 0x01};
    chunk(f, "IDAT", idat, sizeof idat);
    chunk(f, "IEND", NULL, 0);
    assert_int_equal(fclose(f), 0);
}

/* A PFM (colour or grey) that claims w x h pixels and holds `data` bytes of them. */
static void lying_pfm(const char *path, long w, long h, int grey, long data)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fprintf(f, "%s\n%ld %ld\n-1.0\n", grey ? "Pf" : "PF", w, h);
    for (long i = 0; i < data; i++)
        fputc(0, f);
    assert_int_equal(fclose(f), 0);
}

/* A Radiance HDR header (run-length encoded or flat) that claims w x h pixels, with `data` bytes after it. */
static void lying_hdr(const char *path, long w, long h, long data)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fprintf(f, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %ld +X %ld\n", h, w);
    for (long i = 0; i < data; i++)
        fputc(i % 4 == 3 ? 128 : 2, f);
    assert_int_equal(fclose(f), 0);
}

/* Every reader must refuse path quickly, with a message naming it, without holding the claimed memory. */
static void expect_refused(const char *path, const char *why)
{
    const double t0 = tu_seconds();
    GError err;
    GImage img;
    int rc = gimage_read(path, 0, &img, &err);
    if (rc == G_OK)
        fail_msg("gimage_read accepted %s (%dx%d)", path, img.width, img.height);
    assert_null(img.pixels);
    assert_non_null(strstr(err.message, path));
    if (why && !strstr(err.message, why))
        fail_msg("%s: expected '%s' in '%s'", path, why, err.message);
    int w, h, c;
    rc = gimage_info(path, &w, &h, &c, &err);
    /* the header alone may be readable; when it is refused, it is for the same reason */
    if (rc != G_OK && why && strstr(why, "claims") && !strstr(err.message, why))
        fail_msg("gimage_info %s: expected '%s' in '%s'", path, why, err.message);
    GProbe *p = NULL;
    assert_true(gprobe_load(path, GPROBE_AUTO, 0, &p, &err) < 0);
    assert_null(p);
    char text[400];
    snprintf(text, sizeof text, "node n image { child lambert file \"%s\" }\n", path);
    GLibrary *lib = NULL;
    rc = greader_load_string(text, "lying.mat", NULL, &lib, &err);
    if (rc == G_OK) { /* the image node opens the file when the library loads; a look-up must then fail */
        glibrary_destroy(lib);
        if (why && strstr(why, "claims"))
            fail_msg("the image node accepted %s", path);
    }
    const double dt = tu_seconds() - t0;
    if (dt > 2.0)
        fail_msg("%s took %.2f s to refuse", path, dt);
}

static void test_lying_png_headers(void **state)
{
    (void)state;
    /* sizes from a few thousand pixels to the largest a PNG header holds, every colour type */
    const uint32_t sizes[][2] = {{20000, 20000}, {60000, 60000}, {1u << 20, 64}, {64, 1u << 20}, {5000, 5000},
                                 {0x7fffffffu, 1}, {1, 0x7fffffffu}};
    const int types[][2] = {{2, 8}, {6, 16}, {0, 1}, {3, 8}, {4, 8}};
    char path[300];
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
            snprintf(path, sizeof path, "%s/lie_%zu_%zu.png", dir, i, t);
            lying_png(path, sizes[i][0], sizes[i][1], types[t][0], types[t][1]);
            /* libpng refuses a side over 1,000,000 itself; above 2^29 pixels the size is refused outright */
            int own = sizes[i][0] > 1000000u || sizes[i][1] > 1000000u ||
                      sizes[i][0] * (double)sizes[i][1] > (double)(1u << 29);
            expect_refused(path, own ? NULL : "claims");
        }
    assert_true(max_rss_kb() < 1024 * 1024); /* no claimed size was ever touched */
}

static void test_lying_pfm_headers(void **state)
{
    (void)state;
    const long sizes[][2] = {{30000, 30000}, {16384, 8192}, {4096, 2048}, {1024, 512}, {2, 1}, {100000, 1}};
    char path[300];
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (int grey = 0; grey < 2; grey++) {
            /* one float short of the data the header claims */
            long need = sizes[i][0] * sizes[i][1] * (grey ? 1 : 3) * 4;
            long data = need > 1000 ? 1000 : need - 4;
            snprintf(path, sizeof path, "%s/lie_%zu_%d.pfm", dir, i, grey);
            lying_pfm(path, sizes[i][0], sizes[i][1], grey, data);
            /* the comparison is with the whole file, header included: a claim within a header's length of
             * the file's size is left to the decoder, which fails at the missing floats */
            int claims = sizes[i][0] * sizes[i][1] <= (1L << 29) && need > data + 64;
            expect_refused(path, claims ? "claims" : NULL);
        }
    assert_true(max_rss_kb() < 1024 * 1024);
}

static void test_lying_hdr_headers(void **state)
{
    (void)state;
    /* more than the bytes a run-length encoded row needs at least (claims), or a header that fits its file
     * (the smallest sizes with 64 bytes of data) left to the decoder, which fails at the first missing row */
    const long sizes[][2] = {{60000, 30000}, {16384, 8192}, {8192, 4096}, {4096, 2048}, {32767, 16}, {40000, 2},
                             {7, 100}};
    char path[300];
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (long data = 0; data <= 64; data += 32) {
            snprintf(path, sizeof path, "%s/lie_%zu_%ld.hdr", dir, i, data);
            lying_hdr(path, sizes[i][0], sizes[i][1], data);
            expect_refused(path, sizes[i][0] * sizes[i][1] > (1L << 29) ? NULL : "claims");
        }
    assert_true(max_rss_kb() < 1024 * 1024);
}

/* ---- OpenEXR: headers whose attributes claim more than the file ---- */

/* The whole of a file, into buf (at most cap bytes); its size. */
static long read_all(const char *path, unsigned char *buf, long cap)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    long n = (long)fread(buf, 1, (size_t)cap, f);
    assert_int_equal(fclose(f), 0);
    assert_true(n > 0 && n < cap);
    return n;
}

static void write_all(const char *path, const unsigned char *buf, long n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal((long)fwrite(buf, 1, (size_t)n, f), n);
    assert_int_equal(fclose(f), 0);
}

static void put_le32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* Where each attribute of the single-part header in buf keeps its size (offsets of the 32-bit fields), and where
 * its value starts, for at most max attributes; how many were found. */
static int exr_attributes(const unsigned char *buf, long n, long *size_at, char names[][32], int max)
{
    long off = 8;
    int count = 0;
    while (off < n && buf[off] && count < max) {
        size_t len = strlen((const char *)buf + off);
        memcpy(names[count], buf + off, len < 31 ? len + 1 : 31);
        names[count][31] = '\0';
        off += (long)len + 1;
        off += (long)strlen((const char *)buf + off) + 1; /* the type name */
        size_at[count++] = off;
        uint32_t sz = (uint32_t)buf[off] | (uint32_t)buf[off + 1] << 8 | (uint32_t)buf[off + 2] << 16 |
                      (uint32_t)buf[off + 3] << 24;
        off += 4 + (long)sz;
    }
    return count;
}

/* A true EXR written by the library, then every attribute's size made a lie (the largest a header holds, the
 * file's own size, negative), the data window made 2^30 rows tall (its table of chunk offsets alone far beyond the
 * file), and the header cut short at every 5th byte: each refused by every reader, the lies by the header check
 * ("claims"), before OpenEXR allocates what they claim. */
static void test_lying_exr_headers(void **state)
{
    (void)state;
    GError err;
    GImage img, back;
    char path[300];
    snprintf(path, sizeof path, "%s/true_small.exr", dir);
    assert_int_equal(gimage_create(&img, 5, 4, 3, &err), G_OK);
    for (size_t i = 0; i < 60; i++)
        img.pixels[i] = (float)i * 0.125f;
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    gimage_free(&img);
    assert_int_equal(gimage_read(path, 0, &back, &err), G_OK); /* the true file reads */
    gimage_free(&back);
    static unsigned char buf[1 << 16], lie[1 << 16];
    const long n = read_all(path, buf, sizeof buf);
    long size_at[64];
    char names[64][32];
    const int count = exr_attributes(buf, n, size_at, names, 64);
    assert_true(count >= 6); /* channels, compression, dataWindow, displayWindow, lineOrder, ... */
    const uint32_t claims[] = {0x7fffffffu, (uint32_t)n, 0x80000000u};
    int window = 0;
    for (int a = 0; a < count; a++) {
        for (size_t c = 0; c < sizeof claims / sizeof claims[0]; c++) {
            memcpy(lie, buf, (size_t)n);
            put_le32(lie + size_at[a], claims[c]);
            snprintf(path, sizeof path, "%s/lie_attr_%d_%zu.exr", dir, a, c);
            write_all(path, lie, n);
            expect_refused(path, c == 2 ? NULL : "claims");
        }
        if (!strcmp(names[a], "dataWindow")) { /* ymax = 2^30 - 1 */
            memcpy(lie, buf, (size_t)n);
            put_le32(lie + size_at[a] + 4 + 12, (1u << 30) - 1);
            snprintf(path, sizeof path, "%s/lie_window.exr", dir);
            write_all(path, lie, n);
            expect_refused(path, "chunks of pixels");
            window = 1;
        }
    }
    assert_true(window);
    const long header_end = size_at[count - 1] + 4;
    for (long cut = 8; cut < header_end; cut += 5) {
        snprintf(path, sizeof path, "%s/cut_%ld.exr", dir, cut);
        write_all(path, buf, cut);
        expect_refused(path, NULL);
    }
    assert_true(max_rss_kb() < 1024 * 1024);
}

static void test_memory_budget(void **state)
{
    (void)state;
    GError err;
    gimage_set_memory_budget(0);
    assert_int_equal(gimage_memory_budget(), (size_t)GIMAGE_DEFAULT_BUDGET_MB << 20);
    /* a true 512x512 RGB EXR needs 3 MiB as floats */
    GImage img, back;
    char path[300];
    snprintf(path, sizeof path, "%s/true.exr", dir);
    assert_int_equal(gimage_create(&img, 512, 512, 3, &err), G_OK);
    for (size_t i = 0; i < 512u * 512u * 3u; i++)
        img.pixels[i] = (float)(i % 7) * 0.25f;
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    /* decoding it in this process takes the file's 3 channels and a 4-channel result as floats: 7 MiB */
    gimage_set_memory_budget(7u << 20); /* exactly enough */
    assert_int_equal(gimage_read(path, GIMAGE_READ_RGB, &back, &err), G_OK);
    assert_int_equal(back.width, 512);
    assert_true(memcmp(back.pixels, img.pixels, 512u * 512u * 3u * sizeof(float)) == 0);
    assert_int_equal(gmem_budget_used(), 0); /* the decode's charge is returned */
    gimage_free(&back);
    gimage_set_memory_budget((7u << 20) - 1); /* one byte short */
    assert_int_equal(gimage_read(path, GIMAGE_READ_RGB, &back, &err), G_ERR_NOMEM);
    assert_non_null(strstr(err.message, "needs 7.0 MiB, over the memory budget"));
    assert_null(back.pixels);
    gimage_set_memory_budget((3u << 20) - 1); /* the image alone does not fit: refused from its header */
    assert_int_equal(gimage_info(path, NULL, NULL, NULL, &err), G_ERR_NOMEM);
    assert_non_null(strstr(err.message, "more than the memory limit of 2 MiB"));
    /* a probe's tables count against the same budget: 512x256 needs about 8 MiB */
    gimage_set_memory_budget(4u << 20);
    GProbe *p = NULL;
    assert_int_equal(gprobe_create(512, 256, NULL, &p, &err), G_ERR_NOMEM);
    assert_non_null(strstr(err.message, "a 512x256 probe needs"));
    gimage_set_memory_budget(16u << 20);
    assert_int_equal(gprobe_create(512, 256, NULL, &p, &err), G_OK);
    assert_true(gmem_budget_used() > (6u << 20)); /* held while the probe lives */
    GProbe *second = NULL; /* a second one does not fit beside it */
    assert_int_equal(gprobe_create(512, 256, NULL, &second, &err), G_ERR_NOMEM);
    assert_null(second);
    gprobe_destroy(p);
    assert_int_equal(gmem_budget_used(), 0);
    gimage_set_memory_budget(0);
    assert_int_equal(gimage_memory_budget(), (size_t)GIMAGE_DEFAULT_BUDGET_MB << 20);
    gimage_free(&img);
}

/* True files at the limit of compression are not refused: a one-colour 4000x4000 PNG (deflate near its
 * 1032:1) and a PFM of exactly the size its header gives. */
static void test_true_files_read(void **state)
{
    (void)state;
    GError err;
    char path[300];
    GImage img, back;
    snprintf(path, sizeof path, "%s/flat.png", dir);
    assert_int_equal(gimage_create(&img, 4000, 4000, 1, &err), G_OK);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    gimage_free(&img);
    assert_int_equal(gimage_read(path, 0, &back, &err), G_OK);
    assert_int_equal(back.width, 4000);
    assert_int_equal(back.height, 4000);
    assert_near(back.pixels[3 * 1234567], 0.0, 0.0);
    gimage_free(&back);
    snprintf(path, sizeof path, "%s/exact.pfm", dir);
    lying_pfm(path, 8, 4, 0, 8 * 4 * 3 * 4);
    assert_int_equal(gimage_read(path, 0, &back, &err), G_OK);
    assert_int_equal(back.width, 8);
    gimage_free(&back);
}

int main(void)
{
    /* the header checks and the budget in this process; tests/test_image_isolation.c decodes in a decoder process */
    setenv("GENERIC_DECODE", "inprocess", 1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lying_png_headers),
        cmocka_unit_test(test_lying_pfm_headers),
        cmocka_unit_test(test_lying_hdr_headers),
        cmocka_unit_test(test_lying_exr_headers),
        cmocka_unit_test(test_memory_budget),
        cmocka_unit_test(test_true_files_read),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
