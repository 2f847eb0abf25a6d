/* render_file.c - a scene file rendered into floats: the steps of gtrace's command line (load, the settings from
 * the camera and the options, the camera fitted again to another image size, the accelerator, the render) without
 * the output file. */
#include "render_file.h"

#include "render/render.h"
#include "scene/accel.h"
#include "scenefile/parse.h"

#include <generic/builtins.h>
#include <generic/memory.h>
#include <generic/reader.h>

#include <string.h>

int gtrace_embed_register(GError *err)
{
    int rc = generic_register_builtins(err);
    return rc == G_OK ? gtrace_register_kinds(err) : rc;
}

/* The render settings of rq over the scene's camera, as gtrace's prepare() makes them (refitting a framed view). */
static int settings(const GtraceRenderRequest *rq, Scene *scene, RenderSettings *rs, GError *err)
{
    const Camera *cam = &scene->camera;
    *rs = (RenderSettings){.width = cam->width, .height = cam->height, .spp = cam->spp, .depth = cam->depth,
                           .threads = rq->threads, .quiet = 1, .cutoff = cam->cutoff, .bands = cam->bands,
                           .integrator = rq->integrator};
    if (rq->width > 0 && rq->height > 0) {
        rs->width = rq->width;
        rs->height = rq->height;
    } else if (rq->width > 0) {
        rs->width = rq->width;
        rs->height = (int)((double)rq->width * cam->height / cam->width + 0.5);
    } else if (rq->height > 0) {
        rs->height = rq->height;
        rs->width = (int)((double)rq->height * cam->width / cam->height + 0.5);
    }
    rs->width = rs->width < 1 ? 1 : rs->width;
    rs->height = rs->height < 1 ? 1 : rs->height;
    Camera *framed = &scene->camera;
    int rc;
    if (framed->frame >= 0.0 && (rs->width != framed->width || rs->height != framed->height) &&
        (rc = camera_frame(framed, framed->frame_lo, framed->frame_hi, rs->width, rs->height, err)) < 0)
        return rc;
    if (rq->spp > 0)
        rs->spp = rq->spp;
    if (rq->depth >= 0)
        rs->depth = rq->depth;
    const int *c = rq->crop;
    if (c[0] || c[1] || c[2] || c[3]) {
        if (c[0] < 0 || c[1] < 0 || c[0] >= c[2] || c[1] >= c[3] || c[2] > rs->width || c[3] > rs->height)
            return gerror_set(err, G_ERR_INVALID, "crop %d,%d,%d,%d is not a region of the %dx%d image", c[0], c[1],
                              c[2], c[3], rs->width, rs->height);
        memcpy(rs->crop, c, sizeof rs->crop);
    }
    return accel_build_for(scene, (double)rs->width * rs->height * rs->spp, err);
}

int gtrace_render_file(const GtraceRenderRequest *rq, GtraceImage *img, GError *err)
{
    if (img)
        memset(img, 0, sizeof *img);
    if (!rq || !rq->scene || !img)
        return gerror_set(err, G_ERR_INVALID, "gtrace_render_file: no request, scene file or image given");
    if (rq->integrator != RENDER_WHITTED && rq->integrator != RENDER_PATH)
        return gerror_set(err, G_ERR_INVALID, "gtrace_render_file: integrator %d is neither whitted (0) nor path (1)",
                          rq->integrator);
    int rc = gtrace_embed_register(err);
    if (rc != G_OK)
        return rc;
    GReaderOptions trust = {.allow_plugins = rq->allow_plugins, .confine_dir = rq->confine_dir};
    Scene *scene = NULL;
    rc = scene_load_opts(rq->scene, rq->colormodel, NULL, &trust, &scene, err);
    RenderSettings rs;
    if (rc == G_OK)
        rc = settings(rq, scene, &rs, err);
    Framebuffer fb = {0};
    RenderStats st = {0};
    if (rc == G_OK)
        rc = render_image(scene, &rs, &fb, &st, err);
    if (rc == G_OK) {
        *img = (GtraceImage){.width = fb.width, .height = fb.height, .x = fb.x, .y = fb.y,
                             .full_width = fb.full_width, .full_height = fb.full_height, .pixels = fb.pixels};
        fb.pixels = NULL; /* handed over */
    }
    framebuffer_free(&fb);
    scene_destroy(scene);
    return rc;
}

void gtrace_image_free(GtraceImage *img)
{
    if (!img)
        return;
    Framebuffer fb = {.pixels = img->pixels};
    framebuffer_free(&fb);
    memset(img, 0, sizeof *img);
}
