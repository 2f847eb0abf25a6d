/* render.c - the render loop: 16x16 tiles (of the image or of its crop), in a fixed shuffled order so that the
 * progress estimate follows the work wherever the costly pixels are, shared among OpenMP threads with a dynamic
 * schedule, one scratch arena per thread (marked and released per sample), a generator seeded per pixel so the image
 * does not depend on the thread count. Samples that come back NaN or infinite are counted and dropped
 * (they never reach a pixel); a camera sample spawns at most max_rays reflected and refracted rays (the
 * branches beyond are not traced, and the samples so cut are counted); pixels leave the colour model through its XYZ
 * conversion (as a light) and become linear sRGB. */
#include "render.h"
#include "trace/trace.h"
#include "integrators/path.h"
#include "integrators/whitted.h"
#include "integrators/sppm.h"
#include "integrators/light.h"
#include "film/progress.h"
#include "film/viewing.h"
#include "lights/emissive.h"
#include "lights/light_pick.h"
#include "trace/sampler.h"

#include <generic/memory.h>
#include <generic/services/image.h>

#include <math.h>
#include <omp.h>
#include <string.h>

#define TILE 16

typedef struct Job {
    const Scene *scene;
    const Camera *cam;
    Framebuffer *fb;
    int spp, depth, max_rays, integrator;
    int grid;  /* strata_grid(spp): the pixel's samples on a grid of grid x grid strata (0: not a square) */
    int ahead; /* one sample a pixel from a pinhole camera: a row's camera rays are computed ahead (render_row) */
    int finite_by_xyz; /* one sample a pixel, and a model whose conversion to XYZ shows every non-finite value
                        * (gcolormodel_xyz_shows_nonfinite): a non-finite sample is found by store_pixel in the
                        * coordinates it converts, three numbers, not tested sample by sample in render_pixel */
    int sampler; /* the path tracer's (RenderSettings.sampler) */
    int x0, y0; /* the crop's origin in the full image */
    Media media0;
    const double *adaptation; /* the viewing illuminant's matrix on XYZ (RenderSettings.adaptation), or NULL */
} Job;

/* One thread's state, kept from one region to the next: its context, the pixel's sample pairing, its counts, the
 * colours of a tile row's pixels and the sample (heap, made with the worker: render_pixel does not nest). */
typedef struct Worker {
    TraceCtx ctx;
    int *perm;
    uint64_t nonfinite, capped;
    GColor pixel[TILE], sample;
    Ray row[TILE]; /* the camera rays of a tile's row, computed ahead (render_row) */
    char apart[64]; /* keeps the next worker's fields, written per ray, off the cache line of these */
} Worker;

/* The colour of pixel (x, y) into out (black when its one sample is not finite, unless job->finite_by_xyz leaves
 * that to store_pixel); ahead: its camera ray computed beforehand (one sample through the pixel's centre from a
 * pinhole camera, as pixel_sample and camera_ray_lens give it), or NULL. */
static int render_pixel(Worker *w, const Job *job, int x, int y, const Ray *ahead, GColor *out)
{
    TraceCtx *c = &w->ctx;
    int rc = G_OK;
    uint64_t index = (uint64_t)y * (uint64_t)job->fb->full_width + (uint64_t)x;
    rng_seed(&c->rng, index, 0x9e3779b97f4a7c15ULL);
    int n = job->spp, grid = job->grid;
    /* the path tracer's Sobol sampler: the pixel positions are the first two dimensions of its sample points */
    int sobol = job->integrator == RENDER_PATH && job->sampler == SAMPLER_SOBOL;
    if (n > 1 && !grid && !sobol)
        strata_shuffle(&c->rng, n, w->perm);
    /* with one sample, the pixel is the sample itself, traced into out (black + s, divided by 1: s but for a
     * zero's sign) */
    GColor *sample = n == 1 ? out : &w->sample;
    if (n > 1)
        gcolor_black(out);
    for (int i = 0; i < n; i++) {
        Ray r;
        if (ahead) {
            r = *ahead;
        } else {
            double sx, sy;
            if (sobol && n > 1) {
                SamplePoint pt = sample_point(index, (uint32_t)i);
                SampleGroup camera = sample_group(&pt, 0);
                sx = sample_group_value(&camera, 0);
                sy = sample_group_value(&camera, 1);
            } else {
                pixel_sample(&c->rng, i, n, grid, w->perm, &sx, &sy);
            }
            camera_ray_lens(job->cam, x + sx, y + sy, &c->rng, &r);
        }
        GScratchMark m2 = gscratch_mark(c->scratch);
        c->weight = 1.0;
        c->rays_left = job->max_rays;
        c->capped = 0;
        rc = job->integrator == RENDER_PATH
                 ? path_trace(c, &r, &job->media0, index, i, job->sampler, sample)
                 : whitted_trace(c, &r, &job->media0, 0, sample);
        w->capped += (uint64_t)c->capped;
        gscratch_release(c->scratch, m2);
        if (rc < 0)
            return rc;
        if (!job->finite_by_xyz && !gcolor_is_finite(sample)) {
            w->nonfinite++;
            if (n == 1) /* the one sample dropped: black */
                gcolor_black(out);
            continue;
        }
        if (n > 1 && (rc = gcolor_add(out, out, sample)) < 0)
            return rc;
    }
    if (n > 1 && (rc = gcolor_scale(out, out, 1.0 / n)) < 0)
        return rc;
    return G_OK;
}

/* Writes pixel (x, y) of the framebuffer from its colour: linear sRGB (black, and counted, when not finite: a
 * non-finite colour, which job->finite_by_xyz lets through render_pixel, converts to non-finite coordinates) and,
 * when the framebuffer keeps them, the values at its wavelengths. */
static int store_pixel(Worker *w, const Job *job, int x, int y, const GColor *pixel)
{
    double xyz[3], lin[3];
    int rc = gcolor_to_xyz(pixel, GCOLOR_LIGHT, xyz);
    if (rc < 0)
        return rc;
    if (job->adaptation)
        viewing_apply(job->adaptation, xyz, xyz);
    gcie_xyz_to_rgb(xyz, lin);
    float *px = job->fb->pixels + 3 * ((size_t)(y - job->y0) * (size_t)job->fb->width + (size_t)(x - job->x0));
    int dropped = 0;
    for (int ch = 0; ch < 3; ch++) {
        if (!isfinite(lin[ch]) || fabs(lin[ch]) > 3.0e38) {
            w->nonfinite++;
            lin[0] = lin[1] = lin[2] = 0.0;
            dropped = 1;
            break;
        }
    }
    for (int ch = 0; ch < 3; ch++)
        px[ch] = (float)lin[ch];
    if (job->fb->waves) {
        size_t n = (size_t)job->fb->nwaves;
        float *wv = job->fb->waves + n * ((size_t)(y - job->y0) * (size_t)job->fb->width + (size_t)(x - job->x0));
        if (dropped) /* black, as the pixel */
            memset(wv, 0, n * sizeof *wv);
        else
            rc = gcolor_at_wavelengths(pixel, GCOLOR_LIGHT, wv, (int)n);
    }
    return rc < 0 ? rc : G_OK;
}

/* The pixels x0 .. x1 - 1 (at most TILE) of row y, in three passes, so that the short dependent chains at the two
 * ends of a pixel's work overlap each other instead of stalling it: when job->ahead, the row's camera rays first (a
 * square root and divisions before the first intersection test); then the pixels' colours; then their conversions
 * to the framebuffer (the conversion to XYZ waits for the whole trace). The same rays and values, bit for bit. */
static int render_row(Worker *w, const Job *job, int x0, int x1, int y)
{
    int ahead = job->ahead;
    if (ahead)
        for (int x = x0; x < x1; x++)
            camera_ray(job->cam, x + 0.5, y + 0.5, &w->row[x - x0]);
    int rc = G_OK;
    for (int x = x0; x < x1 && rc == G_OK; x++)
        rc = render_pixel(w, job, x, y, ahead ? &w->row[x - x0] : NULL, &w->pixel[x - x0]);
    for (int x = x0; x < x1 && rc == G_OK; x++)
        rc = store_pixel(w, job, x, y, &w->pixel[x - x0]);
    return rc;
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

struct Renderer {
    Job job;
    Camera cam;
    Bands bands;
    EmissiveSet *emissive; /**< the glowing geometry as light, shared by the workers (NULL: none) */
    LightPick pick;        /**< every light source by power (the glowing geometry one entry), shared by the workers */
    Worker *workers;
    int nthreads, status;
    const char *culprit;
    double seconds;
    double adaptation[9]; /**< RenderSettings.adaptation, when adapt */
};

/* The settings' checks; G_OK or G_ERR_INVALID. */
static int check_render_settings(const RenderSettings *rs, GError *err)
{
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
    if (rs->crop[0] || rs->crop[1] || rs->crop[2] || rs->crop[3]) {
        const int *c = rs->crop;
        if (c[0] < 0 || c[1] < 0 || c[0] >= c[2] || c[1] >= c[3] || c[2] > rs->width || c[3] > rs->height)
            return gerror_set(err, G_ERR_INVALID, "crop %d,%d,%d,%d is not a non-empty region of the %dx%d image", c[0],
                              c[1], c[2], c[3], rs->width, rs->height);
    }
    if (rs->sampler != SAMPLER_SOBOL && rs->sampler != SAMPLER_INDEPENDENT)
        return gerror_set(err, G_ERR_INVALID, "sampler %d is neither sobol (%d) nor independent (%d)", rs->sampler,
                          SAMPLER_SOBOL, SAMPLER_INDEPENDENT);
    if (rs->bands < 0 || rs->bands > BANDS_LIMIT)
        return gerror_set(err, G_ERR_INVALID, "wavelength bands %d out of range (1..%d)", rs->bands, BANDS_LIMIT);
    return G_OK;
}

void renderer_destroy(Renderer *r)
{
    if (!r)
        return;
    /* the team's threads, idle now, would otherwise spin a few milliseconds waiting for another parallel region
     * (libgomp's default wait policy) while the picture is written: released, they cost no CPU */
    omp_pause_resource_all(omp_pause_soft);
    for (int i = 0; r->workers && i < r->nthreads; i++) {
        gcolor_free(&r->workers[i].ctx.unit);
        trace_ctx_free_temps(&r->workers[i].ctx);
        for (int k = 0; k < TILE; k++)
            gcolor_free(&r->workers[i].pixel[k]);
        gcolor_free(&r->workers[i].sample);
        gmem_free(r->workers[i].perm);
        gscratch_destroy(r->workers[i].ctx.scratch);
    }
    gmem_free(r->workers);
    light_pick_free(&r->pick);
    emissive_free(r->emissive);
    bands_free(&r->bands);
    gmem_free(r);
}

/* fb->wavelengths and fb->nwaves for the model's wavelengths (framebuffer_alloc then allocates fb->waves), within
 * the memory limit. */
static int set_wavelengths(Framebuffer *fb, const GColorModel *m, GError *err)
{
    int n = gcolormodel_wavelengths(m, NULL, 0);
    if (n < 1)
        return gerror_set(err, G_ERR_UNSUPPORTED, "--spectral: the colour model '%s' has no wavelength samples to "
                          "write (choose one that has, with --colormodel)", gcolormodel_name(m));
    size_t bytes = (size_t)fb->width * (size_t)fb->height * (size_t)n * sizeof(float);
    if (bytes > gmem_budget_limit())
        return gerror_set(err, G_ERR_NOMEM, "--spectral: %d values per pixel of a %dx%d image take %zu MiB, more than "
                          "the memory limit of %zu MiB (--memory-limit, GENERIC_MEMORY_LIMIT_MB)", n, fb->width,
                          fb->height, bytes >> 20, gmem_budget_limit() >> 20);
    if (!(fb->wavelengths = gmem_alloc((size_t)n * sizeof(double))))
        return gerror_set(err, G_ERR_NOMEM, "--spectral: out of memory for %d wavelengths", n);
    fb->nwaves = gcolormodel_wavelengths(m, fb->wavelengths, n);
    return G_OK;
}

/* The colours a worker keeps in its arena from the start: the context's temporaries and kept relative indices, 1, a
 * tile row's pixels and the sample (there, not on the heap, so that two workers' colours never share a cache line). */
#define WORKER_COLOURS (TRACE_TMP_COUNT + TRACE_RI_SLOTS + TILE + 2)

/* A worker's arena: its own colours and room for 32 colours a bounce down to the deepest one (a bounce holds a handful:
 * the shading point's, its lights', its textures'), so that it need not grow while rendering, where a new depth reached
 * would allocate (the default 256 KiB holds 38 values of a model with 41 x 41 re-radiation matrices); at least that
 * default, at most 16 MiB. Pages never reached are never touched. */
static size_t arena_bytes(const GColorModel *m, int depth)
{
    size_t want = gcolormodel_value_bytes(m) * (32 * ((size_t)depth + 2) + WORKER_COLOURS), lo = 256 * 1024,
           hi = 16u << 20;
    return want < lo ? lo : want > hi ? hi : want;
}

int renderer_create(Renderer **out, const Scene *s, const RenderSettings *rs, Framebuffer *fb, GError *err)
{
    *out = NULL;
    *fb = (Framebuffer){0};
    int rc = check_render_settings(rs, err);
    if (rc != G_OK)
        return rc;
    Renderer *r = gmem_calloc(1, sizeof *r);
    if (!r)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the renderer");
    if ((rc = bands_init(&r->bands, s->model, rs->bands, err)) != G_OK) {
        gmem_free(r);
        return rc;
    }
    r->cam = s->camera;
    camera_setup(&r->cam, rs->width, rs->height);
    int cropped = rs->crop[0] || rs->crop[1] || rs->crop[2] || rs->crop[3];
    fb->x = cropped ? rs->crop[0] : 0;
    fb->y = cropped ? rs->crop[1] : 0;
    fb->width = (cropped ? rs->crop[2] : rs->width) - fb->x;
    fb->height = (cropped ? rs->crop[3] : rs->height) - fb->y;
    fb->full_width = rs->width;
    fb->full_height = rs->height;
    r->job = (Job){.scene = s, .cam = &r->cam, .fb = fb, .spp = rs->spp, .grid = strata_grid(rs->spp),
                   .depth = rs->depth, .max_rays = rs->max_rays > 0 ? rs->max_rays : RENDER_DEFAULT_MAX_RAYS,
                   .x0 = fb->x, .y0 = fb->y, .integrator = rs->integrator, .sampler = rs->sampler,
                   .ahead = rs->spp == 1 && camera_is_pinhole(&r->cam),
                   .finite_by_xyz = rs->spp == 1 && gcolormodel_xyz_shows_nonfinite(s->model)};
    if (rs->adapt) { /* the renderer keeps its own copy: rs need not outlive it */
        memcpy(r->adaptation, rs->adaptation, sizeof r->adaptation);
        r->job.adaptation = r->adaptation;
    }
    if (s->medium) {
        r->job.media0.m[0] = s->medium;
        r->job.media0.n = 1;
    }
    r->nthreads = rs->threads > 0 ? rs->threads : omp_get_max_threads();
    r->workers = gmem_calloc((size_t)r->nthreads, sizeof *r->workers);
    int ok = r->workers != NULL;
    for (int i = 0; ok && i < r->nthreads; i++) {
        Worker *w = &r->workers[i];
        w->ctx = (TraceCtx){.scene = s, .max_depth = rs->depth, .cutoff = rs->cutoff, .bands = &r->bands, .band = -1,
                            .equiangular = !rs->no_equiangular};
        w->ctx.scratch = gscratch_create(arena_bytes(s->model, rs->depth));
        w->perm = gmem_alloc((size_t)rs->spp * sizeof(int));
        ok = w->ctx.scratch && w->perm && gcolor_scratch(&w->ctx.unit, s->model, w->ctx.scratch) == G_OK &&
             gmaterial_refraction_index(NULL, NULL, &w->ctx.unit) == G_OK && trace_ctx_temps(&w->ctx) == G_OK &&
             gcolor_scratch(&w->sample, s->model, w->ctx.scratch) == G_OK;
        for (int k = 0; ok && k < TILE; k++)
            ok = gcolor_scratch(&w->pixel[k], s->model, w->ctx.scratch) == G_OK;
    }
    if (!ok)
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d image", fb->width, fb->height);
    if (rc == G_OK && !rs->no_emissive_lights)
        rc = emissive_build(s, &r->workers[0].ctx, &r->emissive, err);
    if (rc == G_OK)
        rc = light_pick_build(&r->pick, s, r->emissive, err);
    for (int i = 0; rc == G_OK && i < r->nthreads; i++) {
        r->workers[i].ctx.emissive = r->emissive;
        r->workers[i].ctx.pick = &r->pick;
    }
    if (rc == G_OK && rs->waves)
        rc = set_wavelengths(fb, s->model, err);
    if (rc == G_OK)
        rc = framebuffer_alloc(fb, err);
    if (rc != G_OK) {
        framebuffer_free(fb);
        renderer_destroy(r);
        return rc;
    }
    *out = r;
    return G_OK;
}

int renderer_region(Renderer *r, const int region[4], Progress *prog, GError *err)
{
    const Framebuffer *fb = r->job.fb;
    if (r->job.integrator == RENDER_SPPM || r->job.integrator == RENDER_LIGHT)
        return gerror_set(err, G_ERR_UNSUPPORTED, "--integrator sppm and light render the whole image (or its crop) at "
                          "once, not in regions (under mpirun they share batches of photons: distributed/dist.c)");
    int rx0 = region[0], ry0 = region[1], rx1 = region[2], ry1 = region[3];
    if (rx0 < fb->x || ry0 < fb->y || rx0 >= rx1 || ry0 >= ry1 || rx1 > fb->x + fb->width ||
        ry1 > fb->y + fb->height)
        return gerror_set(err, G_ERR_INVALID, "region %d,%d,%d,%d is not a non-empty part of the rendered %d,%d,%d,%d",
                          rx0, ry0, rx1, ry1, fb->x, fb->y, fb->x + fb->width, fb->y + fb->height);
    int ntx = (rx1 - rx0 + TILE - 1) / TILE, nty = (ry1 - ry0 + TILE - 1) / TILE, ntiles = ntx * nty;
    int *order = gmem_alloc((size_t)ntiles * sizeof(int));
    if (!order)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the tile list");
    render_tile_order(ntiles, order);
    int status = r->status;
    const char *culprit = NULL;
    double t0 = now_seconds();
#pragma omp parallel num_threads(r->nthreads)
    {
        Worker *w = &r->workers[omp_get_thread_num()];
#pragma omp for schedule(dynamic, 1)
        for (int tile = 0; tile < ntiles; tile++) {
            int st_now;
#pragma omp critical(gtrace_status)
            st_now = status;
            if (st_now != G_OK)
                continue; /* a thread failed: finish quickly */
            int x0 = rx0 + (order[tile] % ntx) * TILE, y0 = ry0 + (order[tile] / ntx) * TILE;
            int x1 = x0 + TILE < rx1 ? x0 + TILE : rx1;
            int y1 = y0 + TILE < ry1 ? y0 + TILE : ry1;
            int rc = G_OK;
            for (int y = y0; y < y1 && rc == G_OK; y++)
                rc = render_row(w, &r->job, x0, x1, y);
            if (rc != G_OK) {
#pragma omp critical(gtrace_status)
                {
                    if (status == G_OK) {
                        status = rc;
                        culprit = w->ctx.culprit;
                    }
                }
            }
            if (prog) {
#pragma omp critical(gtrace_progress)
                progress_add(prog, (long)(x1 - x0) * (y1 - y0));
            }
        }
    }
    r->seconds += now_seconds() - t0;
    gmem_free(order);
    if (status != G_OK && r->status == G_OK) {
        r->status = status;
        r->culprit = culprit;
    }
    if (status == G_OK)
        return G_OK;
    if (r->culprit)
        return gerror_set(err, status, "rendering failed in a '%s' material: %s", r->culprit, gstatus_string(status));
    return gerror_set(err, status, "rendering failed: %s", gstatus_string(status));
}

int renderer_threads(const Renderer *r) { return r->nthreads; }

TraceCtx *renderer_thread_ctx(Renderer *r, int i) { return &r->workers[i].ctx; }

const Camera *renderer_camera(const Renderer *r) { return &r->cam; }

const Media *renderer_media(const Renderer *r) { return &r->job.media0; }

int renderer_store(Renderer *r, int i, int x, int y, const GColor *pixel)
{
    return store_pixel(&r->workers[i], &r->job, x, y, pixel);
}

void renderer_stats(const Renderer *r, RenderStats *st)
{
    memset(st, 0, sizeof *st);
    for (int i = 0; i < r->nthreads; i++) {
        st->rays += r->workers[i].ctx.rays;
        st->nonfinite += r->workers[i].nonfinite;
        st->capped += r->workers[i].capped;
    }
    st->seconds = r->seconds;
    st->threads = r->nthreads;
}

int render_image(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err)
{
    if (rs->integrator == RENDER_SPPM)
        return sppm_render(s, rs, fb, st, NULL, err);
    if (rs->integrator == RENDER_LIGHT)
        return light_render(s, rs, fb, st, NULL, err);
    memset(st, 0, sizeof *st);
    Renderer *r;
    int rc = renderer_create(&r, s, rs, fb, err);
    if (rc != G_OK)
        return rc;
    int all[4] = {fb->x, fb->y, fb->x + fb->width, fb->y + fb->height};
    Progress prog;
    progress_start(&prog, (long)fb->width * fb->height, rs->quiet); /* in pixels */
    rc = renderer_region(r, all, &prog, err);
    progress_finish(&prog);
    renderer_stats(r, st);
    renderer_destroy(r);
    if (rc != G_OK)
        framebuffer_free(fb);
    return rc;
}
