/* gen_image.c - image and light probe files whose headers lie: a valid header (magic, chunk CRCs, attribute
 * sizes) claiming a huge, overflowing or degenerate size, followed by a body of a few bytes or none. A reader
 * must refuse them from the header and the file size, before it allocates the pixels. And files of formats the
 * library does not read (IFF, DPX) named as ones it does, which it must refuse by their content. */
#include "gen.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Size {
    uint32_t w, h;
} Size;

/* Sizes that overflow int, size_t arithmetic on floats, or a memory budget (23170x23170 is just under the
 * library's 2^29 pixels); and a few that are merely odd. */
static Size lying_size(GenRng *r)
{
    static const Size sizes[] = {{60000, 60000}, {2147483647u, 1}, {1, 2147483647u}, {65535, 65535},
                                 {46341, 46341}, {100000, 100000}, {16384, 16384},   {23170, 23170},
                                 {4294967295u, 4294967295u},       {0, 5},           {5, 0},
                                 {1, 1},         {2, 1},           {1 << 20, 1 << 19}};
    return sizes[gen_below(r, sizeof sizes / sizeof sizes[0])];
}

/* A probe-like size: 2:1 (lat-long), square (angular), or the odd ones. */
static Size probe_size(GenRng *r)
{
    /* 32000x16000 and 23000x23000 stay under the library's 2^29 pixels and take 6 GB as floats */
    static const Size sizes[] = {{60000, 30000}, {30000, 30000}, {1, 1},           {2, 1},         {1, 2},
                                 {65536, 32768}, {8192, 4096},   {32000, 16000},   {23000, 23000}, {0, 0},
                                 {2147483646u, 1073741823u},     {4, 2147483647u}};
    return sizes[gen_below(r, sizeof sizes / sizeof sizes[0])];
}

/* A body of a few bytes (or none): zeros, random bytes, or a pattern. */
static void short_body(GenBuf *b, GenRng *r)
{
    size_t n = gen_below(r, 3) ? gen_below(r, 64) : 0;
    int form = (int)gen_below(r, 3);
    for (size_t i = 0; i < n; i++)
        gb_byte(b, form == 0 ? 0 : form == 1 ? (int)gen_below(r, 256) : 0x3f);
}

/* ---- PNG ---- */

static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

static void png_chunk(GenBuf *b, const char *type, const unsigned char *data, uint32_t len)
{
    gb_u32be(b, len);
    size_t at = b->n;
    gb_put(b, type, 4);
    gb_put(b, data, len);
    gb_u32be(b, crc32_of(b->p + at, 4 + len));
}

static void png_lying(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    Size s = lying_size(r);
    static const unsigned char depth_type[][2] = {{8, 2}, {8, 6}, {16, 2}, {8, 0}, {1, 0}, {8, 3}, {16, 6}};
    const unsigned char *dt = depth_type[gen_below(r, 7)];
    unsigned char ihdr[13] = {(unsigned char)(s.w >> 24), (unsigned char)(s.w >> 16), (unsigned char)(s.w >> 8),
                              (unsigned char)s.w,         (unsigned char)(s.h >> 24), (unsigned char)(s.h >> 16),
                              (unsigned char)(s.h >> 8),  (unsigned char)s.h,         dt[0],
                              dt[1],                      0,                          0,
                              (unsigned char)gen_below(r, 2)};
    gb_put(b, "\x89PNG\r\n\x1a\n", 8);
    png_chunk(b, "IHDR", ihdr, 13);
    if (dt[1] == 3) /* a palette of two entries */
        png_chunk(b, "PLTE", (const unsigned char *)"\0\0\0\xff\xff\xff", 6);
    if (gen_below(r, 3)) { /* the start of a zlib stream: a stored block claiming 65535 bytes */
        static const unsigned char idat[] = {0x78, 0x01, 0x00, 0xff, 0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
        png_chunk(b, "IDAT", idat, sizeof idat);
    }
    if (gen_below(r, 2))
        png_chunk(b, "IEND", NULL, 0);
}

/* ---- Radiance HDR ---- */

static void hdr_header(GenBuf *b, GenRng *r, Size s)
{
    static const char *const orient[] = {"-Y %u +X %u", "+Y %u +X %u", "-Y %u -X %u", "+X %u -Y %u"};
    gb_printf(b, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=%s\n\n", gen_below(r, 4) ? "1.0" : "1e-300");
    gb_printf(b, GEN_PICK(r, orient), s.h, s.w);
    gb_byte(b, '\n');
    if (gen_below(r, 2) && s.w >= 8 && s.w < 32768) { /* an RLE scanline header, then a run that lies */
        unsigned char rle[] = {2, 2, (unsigned char)(s.w >> 8), (unsigned char)s.w, 0xff, 0x80};
        gb_put(b, rle, sizeof rle);
    }
    short_body(b, r);
}

static void hdr_lying(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    hdr_header(b, r, lying_size(r));
}

static void hdr_probe(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    hdr_header(b, r, probe_size(r));
}

/* ---- PFM ---- */

static void pfm_header(GenBuf *b, GenRng *r, Size s)
{
    static const char *const scales[] = {"-1.0", "1.0", "-1", "0", "nan", "1e40", "-1e-45"};
    gb_printf(b, "P%c\n%u %u\n%s\n", gen_below(r, 2) ? 'F' : 'f', s.w, s.h, GEN_PICK(r, scales));
    short_body(b, r);
}

static void pfm_lying(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    pfm_header(b, r, lying_size(r));
}

static void pfm_probe(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    pfm_header(b, r, probe_size(r));
}

/* ---- OpenEXR (scan lines, no compression or ZIP) ---- */

static void exr_attr(GenBuf *b, const char *name, const char *type, const void *value, uint32_t size)
{
    gb_put(b, name, strlen(name) + 1);
    gb_put(b, type, strlen(type) + 1);
    gb_u32le(b, size);
    gb_put(b, value, size);
}

static void exr_lying(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    Size s = lying_size(r);
    gb_put(b, "\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    GenBuf ch = {0};
    static const char *const names[] = {"B", "G", "R"};
    uint32_t type = gen_below(r, 2) ? 1 : 2; /* half or float */
    for (int k = 0; k < 3; k++) {
        gb_put(&ch, names[k], 2);
        gb_u32le(&ch, type);
        gb_put(&ch, "\0\0\0\0", 4);
        gb_u32le(&ch, 1);
        gb_u32le(&ch, 1);
    }
    gb_byte(&ch, 0);
    exr_attr(b, "channels", "chlist", ch.p, (uint32_t)ch.n);
    free(ch.p);
    unsigned char comp = gen_below(r, 2) ? 0 : 3;
    exr_attr(b, "compression", "compression", &comp, 1);
    /* the window: from a (possibly negative) origin, w x h pixels, in int32 arithmetic that may wrap */
    int32_t x0 = gen_below(r, 3) ? 0 : -2147483647 - 1, y0 = 0;
    uint32_t win[4] = {(uint32_t)x0, (uint32_t)y0, (uint32_t)x0 + s.w - 1u, (uint32_t)y0 + s.h - 1u};
    GenBuf box = {0};
    for (int k = 0; k < 4; k++)
        gb_u32le(&box, win[k]);
    exr_attr(b, "dataWindow", "box2i", box.p, 16);
    exr_attr(b, "displayWindow", "box2i", box.p, 16);
    free(box.p);
    unsigned char order = 0;
    exr_attr(b, "lineOrder", "lineOrder", &order, 1);
    static const unsigned char one[4] = {0x00, 0x00, 0x80, 0x3f}, zero2[8] = {0};
    exr_attr(b, "pixelAspectRatio", "float", one, 4);
    exr_attr(b, "screenWindowCenter", "v2f", zero2, 8);
    exr_attr(b, "screenWindowWidth", "float", one, 4);
    gb_byte(b, 0);
    /* a few entries of the line offset table, pointing past the end */
    int n = (int)gen_below(r, 4);
    for (int k = 0; k < n; k++) {
        gb_u32le(b, (uint32_t)(b->n + 64 + 16 * k));
        gb_u32le(b, 0);
    }
    short_body(b, r);
}

/* ---- PPM ---- */

static void ppm_lying(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    Size s = lying_size(r);
    gb_printf(b, "P%c\n%u %u\n%s\n", gen_below(r, 2) ? '6' : '3', s.w, s.h, gen_below(r, 2) ? "255" : "65535");
    short_body(b, r);
}

/* ---- formats the library does not read, named as ones it does ----
 * OpenImageIO picks a reader by content: a mutated Maya IFF header (its IFF reader corrupted memory on 8 of 100) or
 * a DPX header with a user-data size up to 2^31 - 1 (its DPX reader touched gigabytes), named .png or .hdr. The
 * library must refuse them by their content, naming the format, before any reader sees them. */

static void iff_header(GenBuf *b, GenRng *r, size_t budget)
{
    static const uint32_t sizes[] = {0, 1, 2, 64, 65535, 0x7fffffffu, 0xffffffffu};
    gb_put(b, gen_below(r, 4) ? "FOR4" : "FORM", 4);
    gb_u32be(b, sizes[gen_below(r, 7)]);
    gb_put(b, "CIMG", 4);
    gb_put(b, "TBHD", 4);
    gb_u32be(b, gen_below(r, 2) ? 32 : sizes[gen_below(r, 7)]);
    for (int i = 0; i < 4; i++) /* width, height, prnum, prden: some lie */
        gb_u32be(b, gen_below(r, 2) ? sizes[gen_below(r, 7)] : (uint32_t)gen_below(r, 512));
    size_t n = 176 + gen_below(r, budget > 8192 ? 8192 : budget + 1);
    for (size_t i = b->n; i < n; i++) /* the rest of a 176-byte file or more: mutated bytes */
        gb_byte(b, (int)gen_below(r, 256));
}

static void dpx_header(GenBuf *b, GenRng *r, size_t budget)
{
    static const uint32_t user[] = {0, 1, 8000, 0x7fffffffu, 0xffffffffu, 0x80000000u};
    int big_endian = (int)gen_below(r, 2);
    void (*u32)(GenBuf *, uint32_t) = big_endian ? gb_u32be : gb_u32le;
    gb_put(b, big_endian ? "SDPX" : "XPDS", 4);
    u32(b, 2048);               /* image data offset */
    gb_put(b, "V2.0\0\0\0\0", 8); /* version */
    u32(b, 2048 + (uint32_t)gen_below(r, 8192)); /* file size */
    u32(b, 1);                  /* ditto key */
    u32(b, 1664);               /* generic header size */
    u32(b, 384);                /* industry header size */
    u32(b, user[gen_below(r, 6)]); /* user data size */
    gb_fill(b, 0, 768 - b->n);
    u32(b, (uint32_t)gen_below(r, 8) << 16); /* orientation, number of elements */
    u32(b, gen_below(r, 2) ? 0x7fffffffu : (uint32_t)gen_below(r, 4096)); /* pixels per line */
    u32(b, gen_below(r, 2) ? 0x7fffffffu : (uint32_t)gen_below(r, 4096)); /* lines per element */
    size_t n = 2048 + gen_below(r, budget > 8192 ? 8192 : budget + 1);
    for (size_t i = b->n; i < n; i++)
        gb_byte(b, gen_below(r, 4) ? 0 : (int)gen_below(r, 256));
}

const GenFamily gen_image_families[] = {
    {"iff-as-png", ".png", iff_header}, {"iff-as-hdr", ".hdr", iff_header}, {"dpx-as-hdr", ".hdr", dpx_header},
    {"dpx-as-png", ".png", dpx_header},
    {"png-lying", ".png", png_lying}, {"hdr-lying", ".hdr", hdr_lying}, {"pfm-lying", ".pfm", pfm_lying},
    {"exr-lying", ".exr", exr_lying}, {"ppm-lying", ".ppm", ppm_lying},
};
const int gen_image_count = (int)(sizeof gen_image_families / sizeof gen_image_families[0]);

const GenFamily gen_probe_families[] = {
    {"hdr-probe", ".hdr", hdr_probe},
    {"pfm-probe", ".pfm", pfm_probe},
    {"iff-as-hdr", ".hdr", iff_header},
    {"dpx-as-pfm", ".pfm", dpx_header},
};
const int gen_probe_count = (int)(sizeof gen_probe_families / sizeof gen_probe_families[0]);
