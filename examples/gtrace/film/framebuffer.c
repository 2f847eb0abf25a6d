/* framebuffer.c - the per-pixel arrays of a framebuffer, driven by FRAMEBUFFER_ARRAYS (framebuffer.h): allocating,
 * freeing, and packing a rectangle of each into a byte buffer and back. */
#include "framebuffer.h"

#include <generic/memory.h>

#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* Floats per pixel over all arrays. */
static size_t floats_per_pixel(const Framebuffer *fb)
{
    (void)fb; /* read by the counts that depend on it */
    size_t n = 0;
#define COUNT(name, count) n += (size_t)(count);
    FRAMEBUFFER_ARRAYS(COUNT)
#undef COUNT
    return n;
}

int framebuffer_alloc(Framebuffer *fb, GError *err)
{
    size_t npix = (size_t)fb->width * (size_t)fb->height;
    const double bytes = (double)npix * (double)floats_per_pixel(fb) * sizeof(float);
    char what[64];
    snprintf(what, sizeof what, "a %dx%d framebuffer", fb->width, fb->height);
    int rc = gmem_budget_reserve(bytes < (double)SIZE_MAX ? (size_t)bytes : SIZE_MAX, what, err);
    if (rc != G_OK) {
        framebuffer_free(fb);
        return rc;
    }
    fb->charged = (size_t)bytes;
    int ok = 1;
#define ALLOC(name, count)                                                                                          \
    fb->name = (count) > 0 && ok ? gmem_calloc(npix * (size_t)(count), sizeof(float)) : NULL;                       \
    ok = ok && ((count) <= 0 || fb->name);
    FRAMEBUFFER_ARRAYS(ALLOC)
#undef ALLOC
    if (ok)
        return G_OK;
    framebuffer_free(fb);
    return gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d image", fb->width, fb->height);
}

void framebuffer_free(Framebuffer *fb)
{
    if (!fb)
        return;
#define FREE(name, n)                                                                                               \
    gmem_free(fb->name);                                                                                            \
    fb->name = NULL;
    FRAMEBUFFER_ARRAYS(FREE)
#undef FREE
    gmem_free(fb->wavelengths);
    fb->wavelengths = NULL;
    fb->nwaves = 0;
    gmem_budget_release(fb->charged);
    fb->charged = 0;
}

size_t framebuffer_region_bytes(const Framebuffer *fb, const int region[4])
{
    return (size_t)(region[2] - region[0]) * (size_t)(region[3] - region[1]) * floats_per_pixel(fb) * sizeof(float);
}

/* Copies the region's rows of one array (n floats per pixel) between the framebuffer and buf (to_buf: from the
 * framebuffer into buf); returns the bytes of buf used. */
static size_t copy_rows(const Framebuffer *fb, float *array, int n, const int region[4], unsigned char *buf, int to_buf)
{
    size_t row = (size_t)(region[2] - region[0]) * (size_t)n * sizeof(float), used = 0;
    for (int y = region[1]; y < region[3]; y++, used += row) {
        float *p = array + (size_t)n * ((size_t)(y - fb->y) * (size_t)fb->width + (size_t)(region[0] - fb->x));
        if (to_buf)
            memcpy(buf + used, p, row);
        else
            memcpy(p, buf + used, row);
    }
    return used;
}

void framebuffer_pack(const Framebuffer *fb, const int region[4], unsigned char *buf)
{
#define PACK(name, count)                                                                                           \
    if ((count) > 0)                                                                                                \
        buf += copy_rows(fb, fb->name, (count), region, buf, 1);
    FRAMEBUFFER_ARRAYS(PACK)
#undef PACK
}

void framebuffer_unpack(Framebuffer *fb, const int region[4], const unsigned char *buf)
{
#define UNPACK(name, count)                                                                                         \
    if ((count) > 0)                                                                                                \
        buf += copy_rows(fb, fb->name, (count), region, (unsigned char *)buf, 0);
    FRAMEBUFFER_ARRAYS(UNPACK)
#undef UNPACK
}
