/* exr_writer.h - a minimal OpenEXR writer for tests (header only): one part, scanlines, no compression, 32-bit
 * float channels with any names, so that a test can write the spectral layout (T.<nm>nm, S0.<nm>nm) and the
 * broken files a reader must refuse (malformed or duplicated names, NaN values, a header claiming a huge image)
 * without committing binary data. OpenEXR 2 file layout: magic, version, header attributes, the offset table of
 * the scanlines, then each scanline as its y, its byte count and each channel's row in the header's order. */
#ifndef TEST_EXR_WRITER_H
#define TEST_EXR_WRITER_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline void exr_u32(FILE *f, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16),
                          (unsigned char)(v >> 24)};
    fwrite(b, 1, 4, f);
}

static inline void exr_u64(FILE *f, uint64_t v)
{
    exr_u32(f, (uint32_t)v);
    exr_u32(f, (uint32_t)(v >> 32));
}

static inline void exr_f32(FILE *f, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    exr_u32(f, u);
}

static inline void exr_attr(FILE *f, const char *name, const char *type, uint32_t size)
{
    fwrite(name, 1, strlen(name) + 1, f);
    fwrite(type, 1, strlen(type) + 1, f);
    exr_u32(f, size);
}

/* Writes path: width x height pixels (header_width x header_height claimed in the header when they are > 0, for a
 * file that lies), n channels named names[c] (written in the given order, which must be OpenEXR's: sorted by
 * strcmp), values[(y * width + x) * n + c]. Returns 0, or -1 when the file cannot be written. */
static inline int exr_write(const char *path, int width, int height, int n, const char *const *names,
                            const float *values, int header_width, int header_height)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    const int hw = header_width > 0 ? header_width : width, hh = header_height > 0 ? header_height : height;
    exr_u32(f, 20000630u); /* magic 76 2f 31 01 */
    exr_u32(f, 2u);        /* version 2, single part scanline */
    uint32_t chsize = 1;
    for (int c = 0; c < n; c++)
        chsize += (uint32_t)strlen(names[c]) + 1 + 16;
    exr_attr(f, "channels", "chlist", chsize);
    for (int c = 0; c < n; c++) {
        fwrite(names[c], 1, strlen(names[c]) + 1, f);
        exr_u32(f, 2); /* FLOAT */
        exr_u32(f, 0); /* pLinear and reserved */
        exr_u32(f, 1); /* x sampling */
        exr_u32(f, 1); /* y sampling */
    }
    fputc(0, f);
    exr_attr(f, "compression", "compression", 1);
    fputc(0, f); /* none */
    exr_attr(f, "dataWindow", "box2i", 16);
    exr_u32(f, 0), exr_u32(f, 0), exr_u32(f, (uint32_t)(hw - 1)), exr_u32(f, (uint32_t)(hh - 1));
    exr_attr(f, "displayWindow", "box2i", 16);
    exr_u32(f, 0), exr_u32(f, 0), exr_u32(f, (uint32_t)(hw - 1)), exr_u32(f, (uint32_t)(hh - 1));
    exr_attr(f, "lineOrder", "lineOrder", 1);
    fputc(0, f); /* increasing y */
    exr_attr(f, "pixelAspectRatio", "float", 4);
    exr_f32(f, 1.0f);
    exr_attr(f, "screenWindowCenter", "v2f", 8);
    exr_f32(f, 0.0f), exr_f32(f, 0.0f);
    exr_attr(f, "screenWindowWidth", "float", 4);
    exr_f32(f, 1.0f);
    fputc(0, f); /* end of the header */
    const uint64_t line = 8 + (uint64_t)width * (uint64_t)n * 4;
    uint64_t start = (uint64_t)ftell(f) + 8 * (uint64_t)height;
    for (int y = 0; y < height; y++)
        exr_u64(f, start + (uint64_t)y * line);
    for (int y = 0; y < height; y++) {
        exr_u32(f, (uint32_t)y);
        exr_u32(f, (uint32_t)(width * n * 4));
        for (int c = 0; c < n; c++)
            for (int x = 0; x < width; x++)
                exr_f32(f, values[((size_t)y * width + x) * n + c]);
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* The name of a spectral channel in the layout of Fichet et al. 2021: prefix ("T." or "S0.") and nm with six
 * decimals and a comma (T.550,000000nm), into buf. */
static inline const char *exr_spectral_name(char *buf, size_t size, const char *prefix, double nm)
{
    snprintf(buf, size, "%s%.6fnm", prefix, nm);
    for (char *p = buf; *p; p++)
        if (*p == '.' && p > buf + strlen(prefix))
            *p = ',';
    return buf;
}

#endif
