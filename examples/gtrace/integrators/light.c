/* light.c - particle tracing to the camera (`gtrace --integrator light`): the particle paths of photons.c, each
 * non-ideal surface point they meet connected to the pinhole. A particle of power P at x, arriving from wi, adds to
 * the pixel its point projects into
 *     f(wi, wo) cos(theta_x) P / (d^2 cos^3(theta) A)
 * where wo points to the camera, d is the distance, theta the angle from the view direction and A the pixel's area
 * on the image plane at distance 1: the radiance towards the camera averaged over the pixel. The material is asked
 * through reflection() (which multiplies by the cosine at the arriving side, divided out here), so a fluorescent
 * material re-radiates what arrives. Contributions are computed in parallel into the particles' slots and summed
 * into the pixels in slot order. Unbiased for what it draws; a reference for SPPM's caustics on diffuse surfaces.
 * In a distributed job (PhotonShare) each process traces its range of every batch's paths and rank 0 sums the
 * completed batch in slot order, as a single process does. */
#include "light.h"
#include "photons.h"
#include "sppm.h"
#include "scene/accel.h"

#include <generic/kit/material_kit.h>
#include <generic/services/image.h>

#include <math.h>
#include <omp.h>
#include <string.h>

typedef struct LightJob {
    const Camera *cam;
    int x0, y0, w, h;
    double pixel_area; /**< a pixel's area on the image plane at distance 1 */
} LightJob;

/* PhotonVisit: the particle's light towards the camera into slot (its pixel in the crop, or -1). */
static int connect_camera(void *user, TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 wi,
                          const GColor *power, Photon *slot)
{
    (void)media;
    const LightJob *j = user;
    const Camera *cam = j->cam;
    GVec3 v = gvec3_sub(sp->point, cam->eye);
    double z = gvec3_dot(v, cam->forward), d = gvec3_length(v);
    if (!(z > 0.0) || !(d > 0.0))
        return G_OK;
    double px = (gvec3_dot(v, cam->right) / (z * cam->half_w) + 1.0) * 0.5 * cam->width;
    double py = (1.0 - gvec3_dot(v, cam->upv) / (z * cam->half_h)) * 0.5 * cam->height;
    if (!(px >= j->x0 && px < j->x0 + j->w && py >= j->y0 && py < j->y0 + j->h))
        return G_OK;
    GVec3 wo = gvec3_scale(v, -1.0 / d);
    if (gvec3_dot(wo, facing) <= 0.0)
        return G_OK; /* the camera is behind the surface */
    GVec3 n;
    double ci = gmaterial_cos_in(sp, wi, wo, &n), co = fabs(gvec3_dot(wo, n)), ct = z / d;
    if (!(ci > 0.0))
        return G_OK;
    Ray sr = {offset_origin(sp->point, facing, wo), wo, 0.0, d * (1.0 - 1e-7), 0.0, 0.0};
    c->rays++;
    if (accel_occluded(c->scene, &sr))
        return G_OK;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor tmp;
    int rc = gcolor_scratch_uncleared(&tmp, c->scene->model, c->scratch);
    if (rc == G_OK)
        rc = gcolor_scale(&tmp, power, co / (ci * d * d * ct * ct * ct * j->pixel_area));
    if (rc == G_OK)
        rc = gmaterial_reflection(sp->material, sp, wi, &tmp, wo, &slot->power);
    gscratch_release(c->scratch, mark);
    if (rc == G_OK)
        slot->pixel = (long)((int)py - j->y0) * j->w + ((int)px - j->x0);
    return rc;
}

/* Records the first failure of a parallel loop. */
static void first_error(int *status, int rc)
{
    if (rc < 0) {
#pragma omp critical(gtrace_light_status)
        if (*status == G_OK)
            *status = rc;
    }
}

static int light_run(Renderer *r, const Scene *s, const RenderSettings *rs, const PhotonSource *src,
                     const Framebuffer *fb, GColor *acc, const PhotonShare *share, Progress *prog, GError *err)
{
    const Camera *cam = renderer_camera(r);
    LightJob job = {.cam = cam, .x0 = fb->x, .y0 = fb->y, .w = fb->width, .h = fb->height,
                    .pixel_area = (2.0 * cam->half_w / cam->width) * (2.0 * cam->half_h / cam->height)};
    int passes = rs->sppm_passes > 0 ? rs->sppm_passes : SPPM_DEFAULT_PASSES;
    long photons = rs->sppm_photons > 0 ? rs->sppm_photons : SPPM_DEFAULT_PHOTONS;
    int per_path = rs->depth < 1 ? 1 : rs->depth > 32 ? 32 : rs->depth, nthreads = renderer_threads(r), rc;
    size_t per_slot = gcolormodel_value_bytes(s->model) + sizeof(Photon) + 2 * sizeof(int) + 64;
    long paths = (long)(SPPM_BATCH_BYTES / (per_slot * (size_t)per_path));
    if (paths < 64)
        paths = 64;
    if (paths > photons)
        paths = photons;
    PhotonBatch batch;
    if ((rc = photon_batch_init(&batch, s->model, (int)paths, per_path, err)) != G_OK)
        return rc;
    const Media *media0 = renderer_media(r);
    int status = G_OK;
    for (int pass = 0; pass < passes && status == G_OK; pass++) {
        for (long start = 0; start < photons && status == G_OK; start += paths) {
            long n = photons - start < paths ? photons - start : paths;
            int lo = 0, hi = (int)n; /* the paths this process traces */
            if (share)
                photon_share_range((int)n, share->rank, share->size, &lo, &hi);
            batch.paths = (int)n;
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 256)
            for (long i = lo; i < hi; i++) {
                TraceCtx *c = renderer_thread_ctx(r, omp_get_thread_num());
                uint64_t index = (uint64_t)pass * (uint64_t)photons + (uint64_t)(start + i);
                first_error(&status, photon_trace(c, src, media0, index, &batch, (int)i, 1, connect_camera, &job));
            }
            if (status == G_OK && share && (rc = share->batch(share->user, &batch, 0, err)) != G_OK) {
                photon_batch_free(&batch);
                return rc;
            }
            if (share && share->rank != 0)
                continue; /* rank 0 sums the job's contributions */
            for (long i = 0; i < n && status == G_OK; i++) /* in slot order: the same sums on any thread count */
                for (int k = 0; k < batch.count[i]; k++) {
                    const Photon *ph = &batch.photons[(size_t)i * (size_t)per_path + (size_t)k];
                    if (ph->pixel >= 0)
                        first_error(&status, gcolor_add(&acc[ph->pixel], &acc[ph->pixel], &ph->power));
                }
        }
        if (prog)
            progress_add(prog, 1);
    }
    photon_batch_free(&batch);
    if (status != G_OK)
        return gerror_set(err, status, "light tracing failed: %s", gstatus_string(status));
    double total = (double)passes * (double)photons;
    for (long i = 0; i < (long)fb->width * fb->height && status == G_OK && !(share && share->rank != 0); i++) {
        int x = fb->x + (int)(i % fb->width), y = fb->y + (int)(i / fb->width);
        if ((rc = gcolor_scale(&acc[i], &acc[i], 1.0 / total)) >= 0)
            rc = renderer_store(r, 0, x, y, &acc[i]);
        first_error(&status, rc);
    }
    if (status != G_OK)
        return gerror_set(err, status, "light tracing: writing the pixels failed: %s", gstatus_string(status));
    return G_OK;
}

int light_check(const Scene *s, const RenderSettings *rs, GError *err)
{
    int rc = sppm_check(rs, err);
    if (rc != G_OK)
        return rc;
    if (s->camera.projection == CAMERA_ORTHOGRAPHIC || !camera_is_pinhole(&s->camera))
        return gerror_set(err, G_ERR_UNSUPPORTED, "--integrator light connects particles to a pinhole camera: this "
                          "scene's camera is %s", s->camera.projection == CAMERA_ORTHOGRAPHIC ? "orthographic"
                                                                                              : "a thin lens");
    return G_OK;
}

int light_render(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, const PhotonShare *share,
                 GError *err)
{
    memset(st, 0, sizeof *st);
    int rc = light_check(s, rs, err);
    if (rc != G_OK)
        return rc;
    PhotonSource src;
    Renderer *r;
    if ((rc = renderer_create(&r, s, rs, fb, err)) != G_OK)
        return rc;
    if ((rc = photon_source_init(&src, s, renderer_thread_ctx(r, 0)->emissive, err)) != G_OK) {
        renderer_destroy(r);
        framebuffer_free(fb);
        return rc;
    }
    long npix = (long)fb->width * fb->height;
    GColor *acc = NULL;
    if ((double)npix * (double)gcolormodel_value_bytes(s->model) > (double)gimage_memory_budget())
        rc = gerror_set(err, G_ERR_NOMEM, "light tracing: a colour for each of %ld pixels takes more than the image "
                        "memory budget of %zu MiB (GENERIC_IMAGE_BUDGET_MB)", npix, gimage_memory_budget() >> 20);
    else if (!(acc = gmem_calloc((size_t)npix, sizeof *acc)))
        rc = gerror_set(err, G_ERR_NOMEM, "light tracing: out of memory for %ld pixels", npix);
    for (long i = 0; rc == G_OK && i < npix; i++)
        if (gcolor_alloc(&acc[i], s->model) != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "light tracing: out of memory for %ld pixels", npix);
    Progress prog;
    double t0 = now_seconds();
    if (rc == G_OK) {
        progress_start(&prog, rs->sppm_passes > 0 ? rs->sppm_passes : SPPM_DEFAULT_PASSES, rs->quiet);
        rc = light_run(r, s, rs, &src, fb, acc, share, &prog, err);
        progress_finish(&prog);
    }
    renderer_stats(r, st);
    st->seconds = now_seconds() - t0;
    for (long i = 0; acc && i < npix; i++)
        gcolor_free(&acc[i]);
    gmem_free(acc);
    renderer_destroy(r);
    photon_source_free(&src);
    if (rc != G_OK)
        framebuffer_free(fb);
    return rc;
}
