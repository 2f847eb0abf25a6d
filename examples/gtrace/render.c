/* render.c - the render loop: 16x16 tiles (of the image or of its crop), in a fixed shuffled order so that the
 * progress estimate follows the work wherever the costly pixels are, shared among OpenMP threads with a dynamic schedule, one
 * scratch arena per thread (marked and released per sample), a generator seeded per pixel so the image
 * does not depend on the thread count. Samples that come back NaN or infinite are counted and dropped
 * (they never reach a pixel); a camera sample spawns at most max_rays reflected and refracted rays (the
 * branches beyond are not traced, and the samples so cut are counted); pixels leave the colour model through its XYZ conversion (as a light)
 * and become linear sRGB. */
#include "render.h"
#include "trace.h"
#include "path.h"
#include "progress.h"

#include <math.h>
#include <omp.h>
#include <string.h>

#define TILE 16

typedef struct Job {
    const Scene *scene;
    const Camera *cam;
    Framebuffer *fb;
    int spp, depth, ntx, max_rays, integrator;
    int x0, y0; /* the crop's origin in the full image */
    Media media0;
} Job;

static int render_pixel(TraceCtx *c, const Job *job, int x, int y, int *perm, uint64_t *nonfinite, uint64_t *capped)
{
    const Scene *s = job->scene;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor acc, sample;
    int rc = gcolor_scratch(&acc, s->model, c->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&sample, s->model, c->scratch);
    if (rc != G_OK)
        goto done;
    rng_seed(&c->rng, (uint64_t)y * (uint64_t)job->fb->full_width + (uint64_t)x, 0x9e3779b97f4a7c15ULL);
    int n = job->spp, grid = strata_grid(n);
    if (n > 1 && !grid)
        strata_shuffle(&c->rng, n, perm);
    for (int i = 0; i < n; i++) {
        double sx, sy;
        pixel_sample(&c->rng, i, n, grid, perm, &sx, &sy);
        Ray r;
        camera_ray_lens(job->cam, x + sx, y + sy, &c->rng, &r);
        GScratchMark m2 = gscratch_mark(c->scratch);
        c->weight = 1.0;
        c->rays_left = job->max_rays;
        c->capped = 0;
        rc = job->integrator == RENDER_PATH
                 ? path_trace(c, &r, &job->media0, (uint64_t)y * (uint64_t)job->fb->full_width + (uint64_t)x, i, &sample)
                 : trace_ray(c, &r, &job->media0, 0, &sample);
        *capped += (uint64_t)c->capped;
        gscratch_release(c->scratch, m2);
        if (rc < 0)
            goto done;
        if (!gcolor_is_finite(&sample)) {
            (*nonfinite)++;
            continue;
        }
        if ((rc = gcolor_add(&acc, &acc, &sample)) < 0)
            goto done;
    }
    if ((rc = gcolor_scale(&acc, &acc, 1.0 / n)) < 0)
        goto done;
    double xyz[3], lin[3];
    if ((rc = gcolor_to_xyz(&acc, GCOLOR_LIGHT, xyz)) < 0)
        goto done;
    gcie_xyz_to_rgb(xyz, lin);
    float *px = job->fb->pixels + 3 * ((size_t)(y - job->y0) * (size_t)job->fb->width + (size_t)(x - job->x0));
    for (int ch = 0; ch < 3; ch++) {
        if (!isfinite(lin[ch]) || fabs(lin[ch]) > 3.0e38) {
            (*nonfinite)++;
            lin[0] = lin[1] = lin[2] = 0.0;
            break;
        }
    }
    for (int ch = 0; ch < 3; ch++)
        px[ch] = (float)lin[ch];
done:
    gscratch_release(c->scratch, mark);
    return rc < 0 ? rc : G_OK;
}

void render_tile_order(int n, int *order)
{
    uint64_t state = 0x2545f4914f6cdd1dULL; /* a fixed xorshift sequence: every run renders in the same order */
    for (int i = 0; i < n; i++)
        order[i] = i;
    for (int i = n - 1; i > 0; i--) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        int j = (int)(state % (uint64_t)(i + 1));
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
}

void framebuffer_free(Framebuffer *fb)
{
    if (!fb)
        return;
    gmem_free(fb->pixels);
    fb->pixels = NULL;
}

int render_image(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err)
{
    memset(st, 0, sizeof *st);
    fb->pixels = NULL;
    if (rs->width < 1 || rs->height < 1 || rs->width > 65536 || rs->height > 65536)
        return gerror_set(err, G_ERR_INVALID, "image size %dx%d is out of range (1..65536)", rs->width, rs->height);
    if (rs->spp < 1 || rs->spp > 65536)
        return gerror_set(err, G_ERR_INVALID, "samples per pixel %d out of range (1..65536)", rs->spp);
    if (rs->depth < 0 || rs->depth > 1000)
        return gerror_set(err, G_ERR_INVALID, "depth %d out of range (0..1000)", rs->depth);
    if (!(rs->cutoff >= 0.0 && rs->cutoff <= 1.0))
        return gerror_set(err, G_ERR_INVALID, "cutoff %g out of range [0, 1]", rs->cutoff);
    if (rs->max_rays < 0 || rs->max_rays > RENDER_LIMIT_MAX_RAYS)
        return gerror_set(err, G_ERR_INVALID, "rays per sample %d out of range (1..%d)", rs->max_rays,
                          RENDER_LIMIT_MAX_RAYS);
    int cx0 = 0, cy0 = 0, cx1 = rs->width, cy1 = rs->height;
    if (rs->crop[0] || rs->crop[1] || rs->crop[2] || rs->crop[3]) {
        cx0 = rs->crop[0], cy0 = rs->crop[1], cx1 = rs->crop[2], cy1 = rs->crop[3];
        if (cx0 < 0 || cy0 < 0 || cx0 >= cx1 || cy0 >= cy1 || cx1 > rs->width || cy1 > rs->height)
            return gerror_set(err, G_ERR_INVALID, "crop %d,%d,%d,%d is not a non-empty region of the %dx%d image", cx0,
                              cy0, cx1, cy1, rs->width, rs->height);
    }
    if (rs->bands < 0 || rs->bands > BANDS_LIMIT)
        return gerror_set(err, G_ERR_INVALID, "wavelength bands %d out of range (1..%d)", rs->bands, BANDS_LIMIT);
    Bands bands;
    int rc0 = bands_init(&bands, s->model, rs->bands, err);
    if (rc0 != G_OK)
        return rc0;
    Camera cam = s->camera;
    camera_setup(&cam, rs->width, rs->height);
    fb->width = cx1 - cx0;
    fb->height = cy1 - cy0;
    fb->x = cx0;
    fb->y = cy0;
    fb->full_width = rs->width;
    fb->full_height = rs->height;
    fb->pixels = gmem_calloc((size_t)fb->width * (size_t)fb->height * 3, sizeof(float));
    if (!fb->pixels) {
        bands_free(&bands);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d image", fb->width, fb->height);
    }
    Job job = {.scene = s, .cam = &cam, .fb = fb, .spp = rs->spp, .depth = rs->depth,
               .max_rays = rs->max_rays > 0 ? rs->max_rays : RENDER_DEFAULT_MAX_RAYS, .x0 = cx0, .y0 = cy0,
               .integrator = rs->integrator};
    job.ntx = (fb->width + TILE - 1) / TILE;
    int nty = (fb->height + TILE - 1) / TILE, ntiles = job.ntx * nty;
    int *order = gmem_alloc((size_t)ntiles * sizeof(int));
    if (!order) {
        framebuffer_free(fb);
        bands_free(&bands);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the tile list");
    }
    render_tile_order(ntiles, order);
    if (s->medium) {
        job.media0.m[0] = s->medium;
        job.media0.n = 1;
    }
    int nthreads = rs->threads > 0 ? rs->threads : omp_get_max_threads();
    int status = G_OK;
    const char *culprit = NULL;
    uint64_t rays = 0, nonfinite = 0, capped = 0;
    Progress prog;
    progress_start(&prog, (long)fb->width * fb->height, rs->quiet); /* in pixels */
    double t0 = now_seconds();
#pragma omp parallel num_threads(nthreads) reduction(+ : rays, nonfinite, capped)
    {
        TraceCtx ctx = {.scene = s, .max_depth = rs->depth, .cutoff = rs->cutoff, .bands = &bands, .band = -1};
        ctx.scratch = gscratch_create(0);
        int *perm = gmem_alloc((size_t)rs->spp * sizeof(int));
        int ok = ctx.scratch && perm && gcolor_alloc(&ctx.unit, s->model) == G_OK &&
                 gmaterial_refraction_index(NULL, NULL, &ctx.unit) == G_OK;
        if (!ok) {
#pragma omp critical(gtrace_status)
            status = G_ERR_NOMEM;
        }
#pragma omp for schedule(dynamic, 1)
        for (int tile = 0; tile < ntiles; tile++) {
            int st_now;
#pragma omp critical(gtrace_status)
            st_now = status;
            if (st_now != G_OK)
                continue; /* a thread failed: finish quickly */
            int x0 = cx0 + (order[tile] % job.ntx) * TILE, y0 = cy0 + (order[tile] / job.ntx) * TILE;
            int x1 = x0 + TILE < cx1 ? x0 + TILE : cx1;
            int y1 = y0 + TILE < cy1 ? y0 + TILE : cy1;
            int rc = G_OK;
            for (int y = y0; y < y1 && rc == G_OK; y++)
                for (int x = x0; x < x1 && rc == G_OK; x++)
                    rc = render_pixel(&ctx, &job, x, y, perm, &nonfinite, &capped);
            if (rc != G_OK) {
#pragma omp critical(gtrace_status)
                {
                    if (status == G_OK) {
                        status = rc;
                        culprit = ctx.culprit;
                    }
                }
            }
#pragma omp critical(gtrace_progress)
            progress_add(&prog, (long)(x1 - x0) * (y1 - y0));
        }
        rays += ctx.rays;
        gcolor_free(&ctx.unit);
        gmem_free(perm);
        gscratch_destroy(ctx.scratch);
    }
    progress_finish(&prog);
    bands_free(&bands);
    gmem_free(order);
    st->seconds = now_seconds() - t0;
    st->rays = rays;
    st->nonfinite = nonfinite;
    st->capped = capped;
    st->threads = nthreads;
    if (status != G_OK) {
        framebuffer_free(fb);
        if (culprit)
            return gerror_set(err, status, "rendering failed in a '%s' material: %s", culprit, gstatus_string(status));
        return gerror_set(err, status, "rendering failed: %s", gstatus_string(status));
    }
    return G_OK;
}
