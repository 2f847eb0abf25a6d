/* exr_header.h - what an OpenEXR file's header claims, checked against the file's size before OpenEXR reads it.
 * OpenEXR allocates what the header says while it reads it: an attribute's value (a string attribute claiming 2 GB
 * is a 2 GB string), a preview image's pixels, the table of chunk offsets that the data window and the compression
 * decide (8 bytes a chunk). A file that holds less than its header claims is refused here, before any of that.
 * Header only (static inline), for the library and its OpenImageIO module alike (as image_format.h). The layout
 * read is OpenEXR's file layout: the magic number, a version field (flags: long names 0x400, multi-part 0x1000),
 * then one header (or, multi-part, several, ended by an empty one), each a list of attributes (name, type name,
 * 32-bit size, value) ended by an empty name. */
#ifndef GENERIC_IMAGE_EXR_HEADER_H
#define GENERIC_IMAGE_EXR_HEADER_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

/** A window of the file: its bytes from base, len of them. */
typedef struct GExrScan {
    int fd;
    long long size, base;
    size_t len;
    unsigned char buf[4096];
} GExrScan;

/* Writes the reason into why (n bytes); returns -1. */
static inline __attribute__((format(printf, 3, 4))) int gexr_refuse(char *why, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
    return -1;
}

/* The bytes [off, off + need) of the file (need at most the window), or NULL when the file ends before them. */
static inline const unsigned char *gexr_scan_at(GExrScan *s, long long off, size_t need)
{
    if (off < 0 || need > sizeof s->buf || off + (long long)need > s->size)
        return NULL;
    if (off < s->base || off + (long long)need > s->base + (long long)s->len) {
        ssize_t got = pread(s->fd, s->buf, sizeof s->buf, (off_t)off);
        if (got < 0 || (size_t)got < need)
            return NULL;
        s->base = off;
        s->len = (size_t)got;
    }
    return s->buf + (off - s->base);
}

static inline int32_t gexr_le32(const unsigned char *p)
{
    return (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
}

/* The NUL-terminated string at off, at most max characters, copied to out (max + 1 bytes) with every byte that is
 * not printable ASCII as '?'; its length, or -1 when it is longer or the file ends before its NUL. */
static inline int gexr_scan_string(GExrScan *s, long long off, int max, char *out)
{
    long long left = s->size - off;
    size_t avail = (size_t)(left < (long long)max + 1 ? (left > 0 ? left : 0) : (long long)max + 1);
    const unsigned char *p = avail ? gexr_scan_at(s, off, avail) : NULL;
    if (!p)
        return -1;
    const unsigned char *nul = (const unsigned char *)memchr(p, 0, avail);
    if (!nul)
        return -1;
    int n = (int)(nul - p);
    for (int i = 0; i <= n; i++) /* the names OpenEXR knows are printable: others only show in messages */
        out[i] = (char)(p[i] == 0 || (p[i] >= 0x20 && p[i] < 0x7f) ? p[i] : '?');
    return n;
}

/* Scan lines a chunk holds under OpenEXR's compression method c (the most of any, 256, for one it does not name:
 * the fewest chunks, so the bound below stays a lower one). */
static inline long long gexr_lines_per_chunk(int c)
{
    static const int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return c >= 0 && c < (int)(sizeof lines / sizeof lines[0]) ? lines[c] : 256;
}

/** 0 when the header of the OpenEXR file open at fd (size bytes) claims no more than the file holds; otherwise -1,
 * with the reason in why (n bytes). Reads the header only, a window at a time; the attributes' values are skipped,
 * but for those whose contents decide an allocation (data window, compression, tiles, chunk count, preview, string
 * vector). */
static inline int gimage_exr_header_check(int fd, long long size, char *why, size_t n)
{
    GExrScan s;
    s.fd = fd;
    s.size = size;
    s.base = 0;
    s.len = 0;
    const unsigned char *p = gexr_scan_at(&s, 0, 8);
    if (!p)
        return gexr_refuse(why, n, "the OpenEXR file ends within its first 8 bytes");
    const int32_t version = gexr_le32(p + 4);
    const int maxname = (version & 0x400) ? 255 : 31, multipart = (version & 0x1000) != 0;
    long long off = 8, tables = 0;
    for (int part = 0;; part++) {
        if (multipart && part > 0) { /* an empty header ends the list */
            const unsigned char *b = gexr_scan_at(&s, off, 1);
            if (!b)
                return gexr_refuse(why, n, "the OpenEXR file ends within its list of headers");
            if (!*b)
                break;
        }
        long long xmin = 0, ymin = 0, xmax = -1, ymax = -1, chunk_count = -1, tile_w = 0, tile_h = 0;
        int compression = -1;
        for (;;) {
            char name[256], type[256];
            int len = gexr_scan_string(&s, off, maxname, name);
            if (len < 0)
                return gexr_refuse(why, n, "the OpenEXR header ends within an attribute's name (at byte %lld)", off);
            off += len + 1;
            if (len == 0)
                break;
            int tlen = gexr_scan_string(&s, off, 255, type);
            if (tlen < 0)
                return gexr_refuse(why, n, "the OpenEXR header's attribute '%s' has no type name", name);
            off += tlen + 1;
            const unsigned char *sz = gexr_scan_at(&s, off, 4);
            if (!sz)
                return gexr_refuse(why, n, "the OpenEXR header ends within the attribute '%s'", name);
            const long long bytes = gexr_le32(sz), left = size - off - 4;
            off += 4;
            if (bytes < 0 || bytes > left)
                return gexr_refuse(why, n,
                                "the OpenEXR header's attribute '%s' claims %lld bytes, more than the %lld bytes "
                                "left in the file",
                                name, bytes, left);
            const unsigned char *v = bytes <= 16 ? gexr_scan_at(&s, off, (size_t)bytes) : NULL;
            if (!strcmp(name, "dataWindow") && !strcmp(type, "box2i") && bytes == 16 && v) {
                xmin = gexr_le32(v);
                ymin = gexr_le32(v + 4);
                xmax = gexr_le32(v + 8);
                ymax = gexr_le32(v + 12);
            } else if (!strcmp(name, "compression") && bytes == 1 && v) {
                compression = v[0];
            } else if (!strcmp(name, "tiles") && !strcmp(type, "tiledesc") && bytes == 9 && v) {
                tile_w = (uint32_t)gexr_le32(v);
                tile_h = (uint32_t)gexr_le32(v + 4);
            } else if (!strcmp(name, "chunkCount") && bytes == 4 && v) {
                chunk_count = gexr_le32(v);
            } else if (!strcmp(type, "preview")) { /* width, height, then 4 bytes a pixel */
                const unsigned char *d = bytes >= 8 ? gexr_scan_at(&s, off, 8) : NULL;
                long long pw = d ? (uint32_t)gexr_le32(d) : 0, ph = d ? (uint32_t)gexr_le32(d + 4) : 0;
                if (!d || (double)pw * (double)ph * 4.0 > (double)(bytes - 8))
                    return gexr_refuse(why, n,
                                    "the OpenEXR header's preview claims %lldx%lld pixels, more than its %lld bytes "
                                    "hold",
                                    pw, ph, bytes);
            } else if (!strcmp(type, "stringvector")) { /* strings, each its length and its bytes */
                for (long long at = 0; at < bytes;) {
                    const unsigned char *d = bytes - at >= 4 ? gexr_scan_at(&s, off + at, 4) : NULL;
                    long long item = d ? gexr_le32(d) : -1;
                    if (item < 0 || item > bytes - at - 4)
                        return gexr_refuse(why, n,
                                        "the OpenEXR header's attribute '%s' holds a string longer than its %lld "
                                        "bytes",
                                        name, bytes);
                    at += 4 + item;
                }
            }
            off += bytes;
        }
        /* the chunks' offsets follow the headers, 8 bytes each: at least as many as the data window needs */
        const long long w = xmax - xmin + 1, h = ymax - ymin + 1;
        long long chunks = 0;
        if (w > 0 && h > 0) {
            if (tile_w > 0 && tile_h > 0)
                chunks = ((w + tile_w - 1) / tile_w) * ((h + tile_h - 1) / tile_h);
            else
                chunks = (h + gexr_lines_per_chunk(compression) - 1) / gexr_lines_per_chunk(compression);
        }
        if (chunk_count > chunks)
            chunks = chunk_count;
        tables += chunks;
        if ((double)tables * 8.0 > (double)(size - off))
            return gexr_refuse(why, n,
                            "the OpenEXR header claims %lld chunks of pixels, whose offsets alone (%.0f bytes) are "
                            "more than the %lld bytes left in the file",
                            tables, (double)tables * 8.0, size - off);
        if (!multipart)
            break;
    }
    return 0;
}

#endif
