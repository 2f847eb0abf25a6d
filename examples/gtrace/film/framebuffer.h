/* framebuffer.h - the rendered image and its per-pixel arrays (framebuffer.c): allocation, and the packing of a
 * region into bytes and back, through which tiles travel between processes (dist.c). */
#ifndef GTRACE_FRAMEBUFFER_H
#define GTRACE_FRAMEBUFFER_H

#include <generic/error.h>

#include <stddef.h>

/** Every per-pixel array of a framebuffer, as X(name, floats per pixel): the struct's fields, their allocation,
 * freeing, packing and unpacking all come from this list, so a new per-pixel array is one more line here. The
 * count is an expression that may read the framebuffer as `fb` (a count set before framebuffer_alloc, such as a
 * number of wavelengths); an array whose count is 0 is not kept (NULL) and does not travel.
 * pixels: linear sRGB (from the model's XYZ), 3 floats per pixel, row by row from the top.
 * waves: with RenderSettings.waves (--spectral), nwaves values per pixel at the colour model's wavelengths, the
 * light as the model has it; else not kept. */
#define FRAMEBUFFER_ARRAYS(X) X(pixels, 3) X(waves, fb->nwaves)

#define FRAMEBUFFER_FIELD(name, n) float *name;

/** A rendered image, or the region of one that a crop renders. */
typedef struct Framebuffer {
    int width, height;
    FRAMEBUFFER_ARRAYS(FRAMEBUFFER_FIELD)
    int x, y;                    /**< where pixel (0, 0) lies in the full image (a crop; else 0, 0) */
    int full_width, full_height; /**< the full image's size */
    double *wavelengths;         /**< the nwaves wavelengths (nm) of waves; NULL and 0 without --spectral */
    int nwaves;
    size_t charged;              /**< bytes of the arrays reserved against the memory budget (framebuffer_alloc) */
} Framebuffer;

/** Allocates every per-pixel array for fb's width x height, zeroed (pages never written cost no memory, so a
 * process that renders a few tiles of a large image touches only those), reserving their bytes against the memory
 * budget (generic/memory.h) until framebuffer_free. G_OK, or G_ERR_NOMEM (over the budget, or out of memory) with
 * nothing allocated (the arrays and the wavelengths freed). */
int framebuffer_alloc(Framebuffer *fb, GError *err);

/** Frees the per-pixel arrays and the wavelengths (NULL or a zeroed framebuffer: no-op). */
void framebuffer_free(Framebuffer *fb);

/** The bytes framebuffer_pack writes for region (x0, y0, x1, y1 in full-image coordinates, inside fb). */
size_t framebuffer_region_bytes(const Framebuffer *fb, const int region[4]);

/** Copies the pixels of region (full-image coordinates, inside fb) of every per-pixel array into buf, which holds
 * framebuffer_region_bytes bytes: array after array, each row by row, in native float layout. */
void framebuffer_pack(const Framebuffer *fb, const int region[4], unsigned char *buf);

/** The inverse of framebuffer_pack: writes buf's pixels into region of fb. */
void framebuffer_unpack(Framebuffer *fb, const int region[4], const unsigned char *buf);

#endif
