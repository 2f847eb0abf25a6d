/* image_png.c - PNG output through libpng (see image_png.h). */
#include "image_png.h"
#include "image_sink.h"

#include "generic/memory.h"

#include <png.h>

#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <string.h>

/* The output, written in sequence (its message: libpng's own error, if it gave up), and whether an allocation of
 * libpng's failed. */
typedef struct {
    GImageSink out;
    int nomem;
} Sink;

/* libpng's (and zlib's) memory comes from the library's allocator (gmem_set_allocator). */
static png_voidp sink_alloc(png_structp png, png_alloc_size_t n)
{
    void *p = gmem_alloc(n);
    if (!p)
        ((Sink *)png_get_mem_ptr(png))->nomem = 1;
    return p;
}

static void sink_free(png_structp png, png_voidp p)
{
    (void)png;
    gmem_free(p);
}

static void sink_write(png_structp png, png_bytep data, size_t n)
{
    Sink *s = png_get_io_ptr(png);
    gimage_sink_write(&s->out, data, n, s->out.size); /* a failure stays in the sink until libpng is done */
}

static void sink_flush(png_structp png) { (void)png; }

static void on_error(png_structp png, png_const_charp msg)
{
    Sink *s = png_get_error_ptr(png);
    snprintf(s->out.message, sizeof s->out.message, "%s", msg);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg) { (void)png; (void)msg; }

static unsigned char encode(double v, int is_alpha)
{
    if (!(v > 0.0)) /* also NaN */
        v = 0.0;
    if (!is_alpha)
        v = gimage_srgb_encode(v);
    if (v > 1.0)
        v = 1.0;
    return (unsigned char)(v * 255.0 + 0.5);
}

/* The codes of the colour channels by table: thresholds[k] is the least value that encode() turns into code k or
 * more (k = 1..255), found once against encode() itself. encode() does not decrease, so the table gives its codes
 * exactly. A second table holds the code at the start of each of BUCKETS equal steps of [0, 1), so a look-up
 * starts there and steps up past the thresholds at most a few times (4 at the steepest, near 0), instead of a pow
 * per channel (3% of a small render's instructions, more of a large one's). */
enum { BUCKETS = 4096 };
static double thresholds[256];
static unsigned char bucket_code[BUCKETS];
static pthread_once_t thresholds_once = PTHREAD_ONCE_INIT;

/* the largest k with thresholds[k] <= v, from code k upwards (thresholds[k] <= v) */
static unsigned char code_from(int k, double v)
{
    while (k < 255 && thresholds[k + 1] <= v)
        k++;
    return (unsigned char)k;
}

static void make_thresholds(void)
{
    for (int k = 1; k < 256; k++) {
        double t = gimage_srgb_decode((k - 0.5) / 255.0); /* within a few ulps of the threshold */
        while (encode(t, 0) < k)
            t = nextafter(t, INFINITY);
        while (t > 0.0 && encode(nextafter(t, 0.0), 0) >= k)
            t = nextafter(t, 0.0);
        thresholds[k] = t;
    }
    for (int i = 0; i < BUCKETS; i++) /* thresholds[0] is 0: every value from 0 up has code 0 or more */
        bucket_code[i] = code_from(i ? bucket_code[i - 1] : 0, (double)i / BUCKETS);
}

/* encode(v, 0) through the tables (make_thresholds done) */
static unsigned char encode_colour(double v)
{
    if (!(v >= thresholds[1])) /* also NaN */
        return 0;
    if (!(v < 1.0))
        return 255;
    return code_from(bucket_code[(int)(v * BUCKETS)], v);
}

/* Encodes the pixels into the open temporary, a row at a time (no second copy of the image). G_OK or
 * G_ERR_IO/G_ERR_NOMEM. */
static int encode_png(Sink *sink, const char *path, const GImage *img, double scale, unsigned char *row,
                      GError *err)
{
    static const int types[4] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                 PNG_COLOR_TYPE_RGB_ALPHA};
    const int ch = img->channels;
    const int alpha = (ch == 2 || ch == 4) ? ch - 1 : -1;
    const size_t stride = (size_t)img->width * ch;
    png_structp png = png_create_write_struct_2(PNG_LIBPNG_VER_STRING, sink, on_error, on_warning, sink, sink_alloc,
                                                sink_free);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, img->width, img->height);
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (sink->nomem)
            return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, img->width,
                              img->height);
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, sink->out.message);
    }
    png_set_write_fn(png, sink, sink_write, sink_flush);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8, types[ch - 1],
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    /* zlib level 3 and the Sub filter on every row instead of libpng's level 6 with the filter chosen per row:
     * on an 800x600 render and a 960x540 path-traced one, 3 to 3.6 times less encoding CPU for files 1% to 6%
     * larger (encoding was 6% of a whole 800x600 Whitted render's CPU) */
    png_set_compression_level(png, 3);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    pthread_once(&thresholds_once, make_thresholds);
    for (int y = 0; y < img->height; y++) {
        const float *src = img->pixels + (size_t)y * stride;
        /* a pixel at a time, its channels by index (no division per sample to find the alpha channel, which is
         * unscaled and linear) */
        for (size_t i = 0; i < stride; i += (size_t)ch)
            for (int k = 0; k < ch; k++)
                row[i + k] = k == alpha ? encode(src[i + k], 1) : encode_colour(src[i + k] * scale);
        png_write_row(png, row);
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return G_OK;
}

int gimage_png_write(const char *path, const GImage *img, double scale, GError *err)
{
    unsigned char *row = gmem_alloc((size_t)img->width * img->channels);
    if (!row)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, img->width,
                          img->height);
    Sink sink = {.nomem = 0};
    int rc = gimage_sink_begin(&sink.out, path, err);
    if (rc != G_OK) {
        gmem_free(row);
        return rc;
    }
    rc = encode_png(&sink, path, img, scale, row, err);
    gmem_free(row);
    return gimage_sink_end(&sink.out, rc, path, err);
}
