/* render.h - rendering the image: OpenMP over tiles, samples per pixel, the framebuffer (render.c). */
#ifndef GTRACE_RENDER_H
#define GTRACE_RENDER_H

#include "bands.h"
#include "scene.h"

#include <generic/error.h>

#include <stdint.h>

/** Default and largest number of reflected and refracted rays one camera sample may spawn (its ray tree):
 * with cutoff 0 a branching material (glass) doubles the rays at every level, 2^depth in all. */
#define RENDER_DEFAULT_MAX_RAYS 4096
#define RENDER_LIMIT_MAX_RAYS 1000000

/** The light transport algorithm (--integrator). */
enum { RENDER_WHITTED = 0, RENDER_PATH = 1 };

typedef struct RenderSettings {
    int width, height, spp, depth, threads, quiet;
    double cutoff; /**< adaptive depth control threshold (0: off) */
    int max_rays;  /**< secondary rays per camera sample (0: RENDER_DEFAULT_MAX_RAYS); the rest are not traced */
    int bands;     /**< most wavelength groups a dispersive refraction splits into (0: BANDS_DEFAULT_CAP; 1: no
                        dispersion) */
    int integrator; /**< RENDER_WHITTED (the paper's Fig. 4, default) or RENDER_PATH (path.c) */
    int crop[4];   /**< x0, y0, x1, y1: render only x0 <= x < x1, y0 <= y < y1 of the width x height image, each
                        pixel as the full render has it; all 0: the whole image */
    int waves;     /**< 1: also keep each pixel's values at the colour model's wavelengths (--spectral) */
} RenderSettings;

/** Linear sRGB pixels (from the model's XYZ), row by row from the top. */
typedef struct Framebuffer {
    int width, height;
    float *pixels; /**< 3 floats per pixel */
    int x, y;                    /**< where pixel (0, 0) lies in the full image (a crop; else 0, 0) */
    int full_width, full_height; /**< the full image's size */
    /** With RenderSettings.waves: nwaves values per pixel at the colour model's wavelengths (in nm, nwaves of
     * them), pixel by pixel in the order of pixels, the light as the model has it; else NULL and 0. */
    float *waves;
    double *wavelengths;
    int nwaves;
} Framebuffer;

typedef struct RenderStats {
    double seconds;
    uint64_t rays;
    uint64_t nonfinite; /**< samples that were NaN or infinite (replaced by black) */
    uint64_t capped;    /**< camera samples whose ray tree reached max_rays (branches left untraced) */
    int threads;
} RenderStats;

/** Renders the scene (accel_build must have run). fb->pixels (and fb->waves when asked) are allocated here (free
 * with framebuffer_free). Asking for the values at wavelengths in a model without wavelength samples is
 * G_ERR_UNSUPPORTED; more of them than the image memory budget allows is G_ERR_NOMEM, before rendering. */
int render_image(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err);
/** The order in which the tiles are rendered: a fixed shuffle of 0..n-1 (the same for every run), so that the
 * finished fraction of tiles follows the work done wherever the expensive parts of the image lie. */
void render_tile_order(int n, int *order);
/** Frees the pixels and the values at wavelengths (NULL or a zeroed framebuffer: no-op). */
void framebuffer_free(Framebuffer *fb);

#endif
