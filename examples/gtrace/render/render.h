/* render.h - rendering the image: OpenMP over tiles, samples per pixel, the framebuffer (render.c). */
#ifndef GTRACE_RENDER_H
#define GTRACE_RENDER_H

#include "integrators/bands.h"
#include "film/framebuffer.h"
#include "film/progress.h"
#include "trace/trace.h"
#include "scene/scene.h"

#include <generic/error.h>

#include <stdint.h>

/** Default and largest number of reflected and refracted rays one camera sample may spawn (its ray tree):
 * with cutoff 0 a branching material (glass) doubles the rays at every level, 2^depth in all. */
#define RENDER_DEFAULT_MAX_RAYS 4096
#define RENDER_LIMIT_MAX_RAYS 1000000

/** The light transport algorithm (--integrator). */
enum { RENDER_WHITTED = 0, RENDER_PATH = 1, RENDER_SPPM = 2, RENDER_LIGHT = 3 };

typedef struct RenderSettings {
    int width, height, spp, depth, threads, quiet;
    double cutoff; /**< adaptive depth control threshold (0: off) */
    int max_rays;  /**< secondary rays per camera sample (0: RENDER_DEFAULT_MAX_RAYS); the rest are not traced */
    int bands;     /**< most wavelength groups a dispersive refraction splits into (0: BANDS_DEFAULT_CAP; 1: no
                        dispersion) */
    int integrator; /**< RENDER_WHITTED (the paper's Fig. 4, default), RENDER_PATH (path.c), RENDER_SPPM (sppm.c) or
                        RENDER_LIGHT (light.c) */
    int crop[4];   /**< x0, y0, x1, y1: render only x0 <= x < x1, y0 <= y < y1 of the width x height image, each
                        pixel as the full render has it; all 0: the whole image */
    int waves;     /**< 1: also keep each pixel's values at the colour model's wavelengths (--spectral) */
    int no_emissive_lights; /**< 1: glowing geometry is not sampled as light (lights/emissive.h), only met by rays:
                                 the integrators' estimate without next-event estimation towards it */
    int sppm_passes;     /**< RENDER_SPPM, RENDER_LIGHT: passes (0: the default; integrators/sppm.h) */
    long sppm_photons;   /**< RENDER_SPPM, RENDER_LIGHT: photon paths per pass (0: the default) */
    double sppm_radius;  /**< RENDER_SPPM: initial gather radius in scene units (0: from the pixel's footprint) */
    double sppm_alpha;   /**< RENDER_SPPM: the fraction of new photons kept per pass, in (0, 1] (0: 2/3) */
    int no_equiangular;  /**< RENDER_PATH: 1: no equiangular sampling towards point, spot and IES lights in
                              homogeneous media (TraceCtx.equiangular), free flight alone */
    int sampler;         /**< RENDER_PATH: SAMPLER_SOBOL (trace/sampler.h; 0, the default: the pixel positions and
                              the paths' main numbers from the pixel's scrambled Sobol sequence) or
                              SAMPLER_INDEPENDENT (stratified pixel positions, the generator's numbers) */
    int adapt;           /**< 1: every pixel's XYZ is multiplied by adaptation before its conversion to linear sRGB
                              (the viewing illuminant, film/viewing.h); the values at wavelengths are kept as they
                              are. 0: none */
    double adaptation[9]; /**< with adapt: the 3x3 matrix, row by row (viewing_adaptation) */
} RenderSettings;

typedef struct RenderStats {
    double seconds;
    uint64_t rays;
    uint64_t nonfinite; /**< samples that were NaN or infinite (replaced by black) */
    uint64_t capped;    /**< camera samples whose ray tree reached max_rays (branches left untraced) */
    int threads;
} RenderStats;

/** Renders the scene (accel_build must have run). fb->pixels (and fb->waves when asked) are allocated here (free
 * with framebuffer_free). Asking for the values at wavelengths in a model without wavelength samples is
 * G_ERR_UNSUPPORTED; more of them than the memory limit allows is G_ERR_NOMEM, before rendering. */
int render_image(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err);
/** The order in which the tiles are rendered: a fixed shuffle of 0..n-1 (the same for every run), so that the
 * finished fraction of tiles follows the work done wherever the expensive parts of the image lie. */
void render_tile_order(int n, int *order);
/** A render in parts: the settings checked, the camera, the wavelength bands and one tracing state per thread
 * set up once, then any regions of the image rendered into one framebuffer (dist.c renders the tiles a process
 * is given so). */
typedef struct Renderer Renderer;

/** Checks the settings and sets up a renderer for them; allocates fb's arrays (zeroed) for the image or its
 * crop. G_ERR_INVALID for bad settings, G_ERR_NOMEM. Destroy with renderer_destroy, fb with framebuffer_free. */
int renderer_create(Renderer **out, const Scene *s, const RenderSettings *rs, Framebuffer *fb, GError *err);

/** Renders the pixels x0 <= x < x1, y0 <= y < y1 of region (full-image coordinates, inside the framebuffer)
 * in 16x16 tiles shared among the threads; adds the pixels done to prog (NULL: none). After a failure every
 * later call fails too, with the first error. */
int renderer_region(Renderer *r, const int region[4], Progress *prog, GError *err);

/** The rays, non-finite and capped samples of every region so far, the seconds spent in them, the threads. */
void renderer_stats(const Renderer *r, RenderStats *st);

/** The number of threads and the tracing state of thread i (0 <= i < renderer_threads), for an integrator that
 * schedules its own work (sppm.c). */
int renderer_threads(const Renderer *r);
TraceCtx *renderer_thread_ctx(Renderer *r, int i);
/** The camera set up for the image size, and the medium the camera is in. */
const Camera *renderer_camera(const Renderer *r);
const Media *renderer_media(const Renderer *r);
/** Writes pixel (x, y) (full-image coordinates, inside the framebuffer) from its colour as the tile loop does
 * (linear sRGB, the values at the wavelengths when kept; a non-finite colour black and counted on thread i). */
int renderer_store(Renderer *r, int i, int x, int y, const GColor *pixel);

/** Frees the renderer (not the framebuffer); NULL is a no-op. */
void renderer_destroy(Renderer *r);

#endif
