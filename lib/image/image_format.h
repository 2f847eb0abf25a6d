/* image_format.h - an image file's format, decided from its first bytes (its magic number), never from its name;
 * and the formats the library reads. Header only (static inline), so that the library and its OpenImageIO module
 * (which is not linked with the library, lib/image/oiio_module.h) use the same code.
 *
 * Read: OpenEXR, Radiance HDR, PFM and PNM (PPM, PGM, PBM), PNG, JPEG, TIFF - what docs/reference/format.md
 * promises for textures and light probes. Every other content is refused before any reader sees it, by name
 * when this file knows the format (IFF, DPX, Cineon, BMP, ...), so that OpenImageIO's own guessing never hands a
 * file to one of its other readers. */
#ifndef GENERIC_IMAGE_FORMAT_H
#define GENERIC_IMAGE_FORMAT_H

#include <stddef.h>
#include <string.h>

/** How many leading bytes gimage_sniff needs (fewer is fine for a short file). */
#define GIMAGE_SNIFF_BYTES 16

/** A format found from a file's first bytes. */
typedef struct GImageFormat {
    const char *name;  /**< a human name: "PNG", "IFF", ...; "unknown" when nothing matched */
    const char *oiio;  /**< OpenImageIO's reader for it, when the library reads the format; NULL when refused */
} GImageFormat;

static inline int gimage_sniff_is(const unsigned char *b, size_t n, const char *magic, size_t len)
{
    return n >= len && memcmp(b, magic, len) == 0;
}

static inline int gimage_sniff_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/** The format of a file whose first n bytes are b. */
static inline GImageFormat gimage_sniff(const unsigned char *b, size_t n)
{
    /* the formats read */
    if (gimage_sniff_is(b, n, "\x76\x2f\x31\x01", 4))
        return (GImageFormat){"OpenEXR", "openexr"};
    if (gimage_sniff_is(b, n, "#?", 2))
        return (GImageFormat){"Radiance HDR", "hdr"};
    if (n >= 3 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f') && gimage_sniff_space(b[2]))
        return (GImageFormat){"PFM", "pnm"};
    if (n >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6' && gimage_sniff_space(b[2]))
        return (GImageFormat){"PNM", "pnm"};
    if (gimage_sniff_is(b, n, "\x89PNG\r\n\x1a\n", 8))
        return (GImageFormat){"PNG", "png"};
    if (gimage_sniff_is(b, n, "\xff\xd8\xff", 3))
        return (GImageFormat){"JPEG", "jpeg"};
    if (gimage_sniff_is(b, n, "II*\0", 4) || gimage_sniff_is(b, n, "MM\0*", 4) ||
        gimage_sniff_is(b, n, "II+\0", 4) || gimage_sniff_is(b, n, "MM\0+", 4))
        return (GImageFormat){"TIFF", "tiff"};
    /* formats OpenImageIO would read, which the library refuses: named in the message */
    static const struct {
        const char *magic;
        size_t len;
        const char *name;
    } refused[] = {
        {"FOR4", 4, "IFF"}, {"FOR8", 4, "IFF"}, {"FORM", 4, "IFF"}, {"SDPX", 4, "DPX"}, {"XPDS", 4, "DPX"},
        {"\x80\x2a\x5f\xd7", 4, "Cineon"}, {"\xd7\x5f\x2a\x80", 4, "Cineon"}, {"BM", 2, "BMP"},
        {"GIF8", 4, "GIF"}, {"8BPS", 4, "Photoshop PSD"}, {"DDS ", 4, "DirectDraw DDS"},
        {"\x01\xda", 2, "SGI"}, {"\x53\x80\xf6\x34", 4, "Softimage PIC"}, {"SIMPLE", 6, "FITS"},
        {"\x00\x00\x00\x0cjP  ", 8, "JPEG 2000"}, {"\xff\x4f\xff\x51", 4, "JPEG 2000"}, {"\x00\x00\x01\x00", 4, "ICO"},
        {"\x2f\xb3\x8b\x8d", 4, "Zfile"}, {"\x8aMNG", 4, "MNG"}, {"RIFF", 4, "RIFF (WebP)"},
        {"#!", 2, "a script"}, {"\x7f" "ELF", 4, "an ELF binary"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        if (gimage_sniff_is(b, n, refused[i].magic, refused[i].len))
            return (GImageFormat){refused[i].name, NULL};
    if (n >= 12 && memcmp(b + 4, "ftyp", 4) == 0)
        return (GImageFormat){"HEIF/AVIF", NULL};
    return (GImageFormat){"unknown", NULL};
}

/** The formats gimage_sniff accepts, for messages. */
#define GIMAGE_READ_FORMATS "OpenEXR, Radiance HDR, PFM, PNM, PNG, JPEG, TIFF"

#endif
