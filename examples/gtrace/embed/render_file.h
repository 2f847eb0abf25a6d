/* render_file.h - gtrace as a function: a scene file rendered into an array of floats, with the settings the
 * command line takes (render_file.c). The entry points a binding calls through libgtrace.so (examples/gtrace/
 * build.mk): they are exported from it, and everything else of the tracer stays hidden. */
#ifndef GTRACE_RENDER_FILE_H
#define GTRACE_RENDER_FILE_H

#include <generic/error.h>

#define GTRACE_EMBED_API __attribute__((visibility("default")))

/** What to render, as gtrace's options say it: 0 (or NULL) keeps the scene's own value. */
typedef struct GtraceRenderRequest {
    const char *scene;      /**< the scene file */
    const char *colormodel; /**< --colormodel (NULL: the scene's) */
    int width, height;      /**< --width, --height (0: the camera's; one of them given: the other by its aspect) */
    int spp;                /**< --spp (0: the camera's) */
    int depth;              /**< --depth (-1: the camera's) */
    int integrator;         /**< 0: whitted, 1: path (--integrator) */
    int threads;            /**< --threads (0: all processors) */
    int crop[4];            /**< --crop x0, y0, x1, y1 (all 0: the whole image) */
    int allow_plugins;      /**< --allow-plugins */
    const char *confine_dir; /**< --confine (NULL: none) */
} GtraceRenderRequest;

/** A rendered image: width x height pixels of linear sRGB, 3 floats each, row by row from the top: the floats
 * gtrace writes into an EXR. (x, y) is where its pixel (0, 0) lies in the full_width x full_height image. */
typedef struct GtraceImage {
    int width, height;
    int x, y, full_width, full_height;
    float *pixels;
} GtraceImage;

/** Registers the built-in types and gtrace's kinds (object, light, camera) with their types, once (idempotent):
 * after it, the library's reader reads scene files. G_OK or the registry's error. */
GTRACE_EMBED_API int gtrace_embed_register(GError *err);

/** Renders rq->scene as `gtrace SCENE -o OUT.exr` with the same options would, into img (pixels freed with
 * gtrace_image_free). Quiet: prints nothing. G_OK, or the status with err's message as gtrace prints it
 * (FILE:LINE:COL for an error in the scene); img is then empty. */
GTRACE_EMBED_API int gtrace_render_file(const GtraceRenderRequest *rq, GtraceImage *img, GError *err);

/** Frees the pixels of an image from gtrace_render_file and clears it; NULL is a no-op. */
GTRACE_EMBED_API void gtrace_image_free(GtraceImage *img);

#endif
