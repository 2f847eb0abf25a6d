/* sppm.c - stochastic progressive photon mapping on the generic interfaces (`gtrace --integrator sppm`;
 * Hachisuka and Jensen, "Stochastic progressive photon mapping", 2009).
 *
 * A pass has two halves. The camera half: one ray through each pixel (its position in the pixel drawn from a
 * generator seeded by the pixel and the pass) followed through ideal surfaces (every lobe delta: mirrors, clear
 * glass, dispersing by one wavelength group as the path tracer does) with its weight beta, adding the emission and
 * the background it meets, to the first non-ideal surface: the pass's visible point, where the direct light is
 * estimated by light samples of one light source chosen by power (light_pick.h; lights.c's light_shade; shadow rays
 * stop at any surface, light through glass is left to the photons). The photon half: the pass's particle paths
 * (photons.h, index pass * photons + i) in batches of bounded size; each batch is put in a hashed grid whose cells are
 * as wide as the initial radius, and every visible point sums the particles within its radius, cell by cell and in slot
 * order (an order that neither the thread count nor the crop changes), through its material's reflection (for a
 * Lambertian material the particles' powers are summed and reflected once). Then each point's count N, radius r and
 * light tau are updated: N' = N + alpha M, r' = r sqrt(N' / (N + M)), tau' = (tau + Phi) r'^2 / r^2. The pixel is its
 * direct light averaged over the passes plus tau / (passes * photons * pi r^2).
 *
 * Memory: four colours per pixel and one batch of particles, whatever the number of passes.
 *
 * In a distributed job (PhotonShare) each process keeps the visible points of its band of rows and traces its
 * range of every batch's paths; the batch is then completed on every process, which gathers it at its own points
 * exactly as a single process would: the pixels are the same bits for any number of processes. */
#include "sppm.h"
#include "photons.h"
#include "path.h"
#include "bands.h"
#include "scene/accel.h"
#include "lights/light_pick.h"
#include "lights/lighting.h"
#include "lights/probe_env.h"
#include "check.h"
#include "camera/rng.h"

#include <generic/kit/material_kit.h>
#include <generic/services/image.h>

#include <math.h>
#include <omp.h>
#include <string.h>

/* One pixel's state across the passes. */
typedef struct VisiblePoint {
    Ray ray;    /**< the ray that reached the pass's visible point */
    Hit hit;
    Media media;
    int valid;  /**< the pass found a non-ideal surface */
    double radius, n;
    long m;     /**< particles gathered this pass */
    GColor beta, direct, tau, phi;
} VisiblePoint;

typedef struct Sppm {
    const Scene *scene;
    const RenderSettings *rs;
    Renderer *r;
    const Camera *cam;
    const Media *media0;
    PhotonSource src;
    PhotonBatch batch;
    const PhotonShare *share; /**< NULL: this process renders alone */
    VisiblePoint *vp;
    int x0, y0, w, h, passes; /**< the pixels this process gathers for: w x h from (x0, y0) */
    long photons;
    double radius0, alpha;
} Sppm;

int sppm_check(const RenderSettings *rs, GError *err)
{
    if (rs->sppm_passes < 0 || rs->sppm_passes > SPPM_MAX_PASSES)
        return gerror_set(err, G_ERR_INVALID, "passes %d out of range (1..%d)", rs->sppm_passes, SPPM_MAX_PASSES);
    if (rs->sppm_photons < 0 || rs->sppm_photons > SPPM_MAX_PHOTONS)
        return gerror_set(err, G_ERR_INVALID, "photons per pass %ld out of range (1..%d)", rs->sppm_photons,
                          SPPM_MAX_PHOTONS);
    if (!(rs->sppm_radius >= 0.0 && rs->sppm_radius <= 1e15))
        return gerror_set(err, G_ERR_INVALID, "initial radius %g out of range (a positive number up to 1e15)",
                          rs->sppm_radius);
    if (!(rs->sppm_alpha >= 0.0 && rs->sppm_alpha <= 1.0))
        return gerror_set(err, G_ERR_INVALID, "alpha %g out of range (0, 1]", rs->sppm_alpha);
    return G_OK;
}

/* direct += beta * x */
static int add_weighted(GColor *direct, const GColor *beta, GColor *x)
{
    int rc = gcolor_mul(x, beta, x);
    return rc < 0 ? rc : gcolor_add(direct, direct, x);
}

/* Adds to out the direct light at sp towards to_viewer (shadow rays stop at any surface): the lights that are no entry
 * of the scene's table (a probe's basis term), each in full, and one entry chosen by power (light_pick.h) with the
 * pass's generator (no number when the table has one entry), its estimate (lights.c's light_shade with the light's
 * samples, the glowing geometry's emissive_shade) divided by the probability of the choice: over the passes, the
 * sum of all. */
static int direct_light(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 to_viewer, GColor *out)
{
    const Scene *s = c->scene;
    const LightPick *lp = c->pick;
    LightTmp lt;
    int rc = light_temps(c, &lt), opaque = gmaterial_opaque(sp->material, sp);
    if (rc < 0)
        return rc;
    lt.blocked = 1;
    light_gather(sp, &lt);
    for (int i = 0; i < s->nlights && rc >= 0; i++) {
        const Light *l = s->lights[i];
        if (light_pick_pmf(lp, i) > 0.0)
            continue;
        rc = l->kind == LIGHT_PROBE ? probe_light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, out)
                                    : light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, out);
    }
    if (rc >= 0)
        rc = light_gather_finish(sp, &lt, out);
    double pick;
    int k = !lp || rc < 0                    ? -1
            : lp->n == 1                    ? light_pick_sample(lp, 0.5, &pick, NULL)
                                            : light_pick_sample(lp, rng_next(&c->rng), &pick, NULL);
    if (k < 0 || !(pick > 0.0))
        return rc;
    const Light *l = lp->lights[k];
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor acc, *sum = out; /* the chosen light's estimate, before the division by pick (out itself when 1) */
    if (pick != 1.0 && (rc = gcolor_scratch(&acc, s->model, c->scratch)) == G_OK)
        sum = &acc;
    light_gather(sp, &lt);
    if (rc >= 0)
        rc = !l                       ? emissive_shade(c, lp->emissive, sp, facing, media, to_viewer, opaque, &lt, sum)
             : l->kind == LIGHT_PROBE ? probe_light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, sum)
                                      : light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, sum);
    if (rc >= 0)
        rc = light_gather_finish(sp, &lt, sum);
    if (rc >= 0 && sum != out)
        rc = gcolor_add_scaled(out, sum, 1.0 / pick);
    gscratch_release(c->scratch, mark);
    return rc;
}

/* The camera half of pass `pass` for pixel (x, y): vp's visible point, beta, and the light met on the way added to
 * vp->direct. */
static int camera_visit(Sppm *sp_, TraceCtx *c, int pass, int x, int y, VisiblePoint *vp)
{
    const Scene *s = c->scene;
    uint64_t pixel = (uint64_t)y * (uint64_t)sp_->rs->width + (uint64_t)x;
    rng_seed(&c->rng, rng_mix64(pixel ^ rng_mix64((uint64_t)pass + 1)), 0x5851f42d4c957f2dULL);
    Ray r;
    double sx = rng_next(&c->rng), sy = rng_next(&c->rng);
    camera_ray_lens(sp_->cam, x + sx, y + sy, &c->rng, &r);
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor tmp, weight, room, rg;
    int rc = G_OK, band = -1;
    vp->valid = 0;
    CHECK(gcolor_scratch(&tmp, s->model, c->scratch));
    CHECK(gcolor_scratch(&weight, s->model, c->scratch));
    CHECK(gcolor_scratch(&rg, s->model, c->scratch));
    CHECK(gcolor_fill(&vp->beta, 1.0));
    Media media;
    media_copy(&media, sp_->media0);
    const Bands *bands = c->bands;
    for (int depth = 0; depth <= c->max_depth; depth++) {
        Hit h;
        c->rays++;
        int hit = accel_intersect(s, &r, &h);
        const Light *seen = NULL;
        double t_seen = hit ? h.t : INFINITY, pdf;
        for (int i = 0; i < s->nlights; i++) { /* the nearest area light in front of the surface, as path.c */
            double t = area_light_hit(s->lights[i], &r, t_seen, &pdf);
            if (t < t_seen) {
                t_seen = t;
                seen = s->lights[i];
            }
        }
        if (seen) {
            CHECK(gcolor_copy(&tmp, &seen->color));
            CHECK(add_weighted(&vp->direct, &vp->beta, &tmp));
            break;
        }
        if (!hit) {
            if (s->env)
                CHECK(probe_background(s->env, r.d, &tmp));
            else
                CHECK(gcolor_copy(&tmp, &s->background));
            CHECK(add_weighted(&vp->direct, &vp->beta, &tmp));
            break;
        }
        const GMaterial *medium = media_top(&media);
        if (!media_clear(medium)) { /* clear (GMAT_CLEAR, vacuum): the dispatch gives the light back */
            CHECK(gmaterial_absorption(medium, NULL, &vp->beta, h.t, &tmp));
            CHECK(gcolor_copy(&vp->beta, &tmp));
        }
        GScratchMark bounce = gscratch_mark(c->scratch);
        GSurfPoint sp;
        GVec3 facing, to_viewer = gvec3_neg(r.d);
        surfpoint_fill(c, &r, &h, &media, &sp, &facing);
        const GMaterial *m = sp.material;
        int delta = 0, valid = 0, transmit = 0, pick = -1;
        GMaterialSample smp;
        if ((rc = gmaterial_emission(m, &sp, to_viewer, &tmp)) >= 0)
            rc = add_weighted(&vp->direct, &vp->beta, &tmp);
        if (rc >= 0)
            rc = delta = gmaterial_is_delta(m, &sp);
        if (rc >= 0 && !delta) { /* the visible point */
            if ((rc = gcolor_fill(&tmp, 0.0)) >= 0 && (rc = direct_light(c, &sp, facing, &media, to_viewer, &tmp)) >= 0)
                rc = add_weighted(&vp->direct, &vp->beta, &tmp);
            vp->ray = r;
            vp->hit = h;
            media_copy(&vp->media, &media);
            vp->valid = rc >= 0;
        } else if (rc >= 0 && depth < c->max_depth) { /* through the ideal surface */
            const GColor *ri = NULL; /* read only: it may be a colour the context keeps (trace.h) */
            rc = trace_relative_index(c, &sp, &room, &ri);
            const GColor *ri_use = ri;
            if (rc >= 0 && !gmaterial_opaque(m, &sp) && bands && bands->n > 1) {
                if (band < 0 && bands_disperse(bands, ri)) {
                    pick = (int)(rng_next(&c->rng) * bands->n);
                    if (pick >= bands->n)
                        pick = bands->n - 1;
                }
                int g = band >= 0 ? band : pick;
                if (g >= 0 && (rc = gcolor_fill(&rg, bands_value(bands, ri, g))) >= 0)
                    ri_use = &rg;
            }
            double u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
            if (rc >= 0)
                rc = valid = gmaterial_sample(m, &sp, to_viewer, ri_use, u1, u2, &smp, &weight);
            valid = rc > 0 && smp.pdf > 0.0;
            if (valid) {
                transmit = (smp.flags & GSAMPLE_TRANSMIT) != 0;
                rc = gcolor_mul(&vp->beta, &vp->beta, &weight);
                if (rc >= 0 && transmit && pick >= 0) {
                    band = pick;
                    if ((rc = gcolor_mul(&vp->beta, &bands->mask[pick], &vp->beta)) >= 0)
                        rc = gcolor_scale(&vp->beta, &vp->beta, (double)bands->n);
                }
            }
        }
        gscratch_release(c->scratch, bounce);
        if (rc < 0)
            goto done;
        if (!delta || !valid || gcolor_is_black(&vp->beta))
            break;
        if (transmit) {
            Media next;
            media_cross(&media, m, sp.entering, &next);
            media_copy(&media, &next);
        }
        r = (Ray){offset_origin(sp.point, facing, smp.in), smp.in, 0.0, INFINITY, r.cone_width, r.cone_spread};
    }
    rc = G_OK;
done:
    gscratch_release(c->scratch, mark);
    if (rc < 0)
        vp->valid = 0;
    return rc;
}

/* The photon half for one visible point: the batch's particles within its radius into vp->phi and vp->m. */
static int gather(TraceCtx *c, const PhotonBatch *b, VisiblePoint *vp)
{
    if (!vp->valid || b->stored == 0)
        return G_OK;
    const Scene *s = c->scene;
    GScratchMark mark = gscratch_mark(c->scratch);
    GSurfPoint sp;
    GVec3 facing, to_viewer = gvec3_neg(vp->ray.d);
    GColor sum, tmp, refl;
    int rc = G_OK;
    surfpoint_fill(c, &vp->ray, &vp->hit, &vp->media, &sp, &facing);
    const GMaterial *m = sp.material;
    int lambert = gmaterial_lambertian(m);
    CHECK(gcolor_scratch(&sum, s->model, c->scratch));
    CHECK(gcolor_scratch(&tmp, s->model, c->scratch));
    CHECK(gcolor_scratch(&refl, s->model, c->scratch));
    double r = vp->radius, r2 = r * r;
    int64_t lo[3], hi[3], cell[3];
    photon_cell(b, gvec3_sub(sp.point, (GVec3){r, r, r}), lo);
    photon_cell(b, gvec3_add(sp.point, (GVec3){r, r, r}), hi);
    long found = 0;
    for (cell[0] = lo[0]; cell[0] <= hi[0]; cell[0]++)
        for (cell[1] = lo[1]; cell[1] <= hi[1]; cell[1]++)
            for (cell[2] = lo[2]; cell[2] <= hi[2]; cell[2]++) {
                int bk = photon_bucket(b, cell);
                for (int j = b->bucket_start[bk]; j < b->bucket_start[bk + 1]; j++) {
                    const Photon *ph = &b->photons[b->order[j]];
                    GVec3 d = gvec3_sub(ph->p, sp.point);
                    if (gvec3_dot(d, d) > r2)
                        continue;
                    int64_t pc[3];
                    photon_cell(b, ph->p, pc);
                    if (pc[0] != cell[0] || pc[1] != cell[1] || pc[2] != cell[2])
                        continue; /* another cell in the same bucket: counted with its own cell */
                    GVec3 n;
                    double ci = gmaterial_cos_in(&sp, ph->wi, to_viewer, &n);
                    if (!(ci > 0.0))
                        continue;
                    found++;
                    if (lambert) {
                        CHECK(gcolor_add(&sum, &sum, &ph->power));
                    } else {
                        CHECK(gcolor_scale(&tmp, &ph->power, 1.0 / ci));
                        CHECK(gmaterial_reflection(m, &sp, ph->wi, &tmp, to_viewer, &refl));
                        CHECK(gcolor_add(&sum, &sum, &refl));
                    }
                }
            }
    if (found > 0) {
        if (lambert) {
            CHECK(gmaterial_diffuse(m, &sp, &tmp));
            CHECK(gcolor_mul_scaled(&sum, &tmp, &sum, 1.0 / M_PI));
        }
        CHECK(add_weighted(&vp->phi, &vp->beta, &sum));
        vp->m += found;
    }
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

/* The progressive update of one visible point after a pass. */
static int update(VisiblePoint *vp, double alpha)
{
    int rc = G_OK;
    if (vp->m > 0) {
        double n_new = vp->n + alpha * (double)vp->m, r_new = vp->radius * sqrt(n_new / (vp->n + (double)vp->m));
        double shrink = (r_new * r_new) / (vp->radius * vp->radius);
        if ((rc = gcolor_add(&vp->tau, &vp->tau, &vp->phi)) >= 0)
            rc = gcolor_scale(&vp->tau, &vp->tau, shrink);
        vp->n = n_new;
        vp->radius = r_new;
        vp->m = 0;
        if (rc >= 0)
            rc = gcolor_fill(&vp->phi, 0.0);
    }
    return rc < 0 ? rc : G_OK;
}

/* A default initial radius: twice the width of a pixel's cone at the distance of the scene's centre. */
static double default_radius(const Sppm *p)
{
    Ray r;
    camera_ray(p->cam, 0.5 * p->rs->width, 0.5 * p->rs->height, &r);
    double d = gvec3_length(gvec3_sub(p->src.bounds.centre, r.o));
    double w = 2.0 * (r.cone_width + r.cone_spread * d);
    return w > 0.0 && isfinite(w) ? w : p->src.bounds.radius * 0.01;
}

static void sppm_free(Sppm *p)
{
    size_t n = (size_t)p->w * (size_t)p->h;
    for (size_t i = 0; p->vp && i < n; i++) {
        gcolor_free(&p->vp[i].beta);
        gcolor_free(&p->vp[i].direct);
        gcolor_free(&p->vp[i].tau);
        gcolor_free(&p->vp[i].phi);
    }
    gmem_free(p->vp);
    photon_batch_free(&p->batch);
    photon_source_free(&p->src);
}

/* Records the first failure of a parallel loop. */
static void first_error(int *status, int rc)
{
    if (rc < 0) {
#pragma omp critical(gtrace_sppm_status)
        if (*status == G_OK)
            *status = rc;
    }
}

static int sppm_run(Sppm *p, Progress *prog, GError *err)
{
    const Scene *s = p->scene;
    long npix = (long)p->w * p->h;
    int nthreads = renderer_threads(p->r), status = G_OK, rc;
    const GColorModel *model = s->model;
    size_t per_value = gcolormodel_value_bytes(model);
    if ((double)npix * 4.0 * (double)per_value > (double)gimage_memory_budget())
        return gerror_set(err, G_ERR_NOMEM, "sppm: four colours for each of %ld pixels take more than the image memory "
                          "budget of %zu MiB (GENERIC_IMAGE_BUDGET_MB)", npix, gimage_memory_budget() >> 20);
    p->vp = npix > 0 ? gmem_calloc((size_t)npix, sizeof *p->vp) : NULL;
    if (npix > 0 && !p->vp)
        return gerror_set(err, G_ERR_NOMEM, "sppm: out of memory for %ld visible points", npix);
    for (long i = 0; i < npix; i++) {
        VisiblePoint *vp = &p->vp[i];
        if (gcolor_alloc(&vp->beta, model) != G_OK || gcolor_alloc(&vp->direct, model) != G_OK ||
            gcolor_alloc(&vp->tau, model) != G_OK || gcolor_alloc(&vp->phi, model) != G_OK)
            return gerror_set(err, G_ERR_NOMEM, "sppm: out of memory for %ld visible points", npix);
        vp->radius = p->radius0;
    }
    int per_path = p->rs->depth < 1 ? 1 : p->rs->depth > 32 ? 32 : p->rs->depth;
    size_t per_slot = per_value + sizeof(Photon) + 2 * sizeof(int) + 64;
    long paths = (long)(SPPM_BATCH_BYTES / (per_slot * (size_t)per_path));
    if (paths < 64)
        paths = 64;
    if (paths > p->photons)
        paths = p->photons;
    if ((rc = photon_batch_init(&p->batch, model, (int)paths, per_path, err)) != G_OK)
        return rc;
    for (int pass = 0; pass < p->passes && status == G_OK; pass++) {
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 64)
        for (long i = 0; i < npix; i++) {
            TraceCtx *c = renderer_thread_ctx(p->r, omp_get_thread_num());
            int x = p->x0 + (int)(i % p->w), y = p->y0 + (int)(i / p->w);
            GScratchMark mark = gscratch_mark(c->scratch);
            first_error(&status, camera_visit(p, c, pass, x, y, &p->vp[i]));
            gscratch_release(c->scratch, mark);
        }
        for (long start = 0; start < p->photons && status == G_OK; start += paths) {
            long n = p->photons - start < paths ? p->photons - start : paths;
            int lo = 0, hi = (int)n; /* the paths this process traces */
            if (p->share)
                photon_share_range((int)n, p->share->rank, p->share->size, &lo, &hi);
            p->batch.paths = (int)n;
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 256)
            for (long i = lo; i < hi; i++) {
                TraceCtx *c = renderer_thread_ctx(p->r, omp_get_thread_num());
                uint64_t index = (uint64_t)pass * (uint64_t)p->photons + (uint64_t)(start + i);
                first_error(&status, photon_trace(c, &p->src, p->media0, index, &p->batch, (int)i, 0, NULL, NULL));
            }
            if (status != G_OK)
                break;
            if (p->share && (rc = p->share->batch(p->share->user, &p->batch, 1, err)) != G_OK)
                return rc;
            if ((rc = photon_batch_index(&p->batch, p->radius0, err)) != G_OK)
                return rc;
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 64)
            for (long i = 0; i < npix; i++) {
                TraceCtx *c = renderer_thread_ctx(p->r, omp_get_thread_num());
                first_error(&status, gather(c, &p->batch, &p->vp[i]));
            }
        }
        for (long i = 0; i < npix && status == G_OK; i++)
            first_error(&status, update(&p->vp[i], p->alpha));
        if (prog)
            progress_add(prog, 1);
    }
    if (status != G_OK)
        return gerror_set(err, status, "sppm: rendering failed: %s", gstatus_string(status));
    double total = (double)p->passes * (double)p->photons;
#pragma omp parallel for num_threads(nthreads) schedule(dynamic, 64)
    for (long i = 0; i < npix; i++) {
        VisiblePoint *vp = &p->vp[i];
        int x = p->x0 + (int)(i % p->w), y = p->y0 + (int)(i / p->w), st;
        double area = M_PI * vp->radius * vp->radius * total;
        /* direct / passes + tau / (passes photons pi r^2), in phi's storage */
        if ((st = gcolor_scale(&vp->phi, &vp->direct, 1.0 / p->passes)) >= 0)
            st = gcolor_add_scaled(&vp->phi, &vp->tau, 1.0 / area);
        if (st >= 0)
            st = renderer_store(p->r, omp_get_thread_num(), x, y, &vp->phi);
        first_error(&status, st);
    }
    if (status != G_OK)
        return gerror_set(err, status, "sppm: writing the pixels failed: %s", gstatus_string(status));
    return G_OK;
}

int sppm_render(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, const PhotonShare *share,
                GError *err)
{
    memset(st, 0, sizeof *st);
    int rc = sppm_check(rs, err);
    if (rc != G_OK)
        return rc;
    Sppm p = {.scene = s, .rs = rs, .share = share};
    if ((rc = renderer_create(&p.r, s, rs, fb, err)) != G_OK)
        return rc;
    if ((rc = photon_source_init(&p.src, s, renderer_thread_ctx(p.r, 0)->emissive, err)) != G_OK) {
        renderer_destroy(p.r);
        framebuffer_free(fb);
        return rc;
    }
    p.cam = renderer_camera(p.r);
    p.media0 = renderer_media(p.r);
    p.x0 = fb->x;
    p.y0 = fb->y;
    p.w = fb->width;
    p.h = fb->height;
    if (share) { /* this process's band of rows */
        int lo, hi;
        photon_share_range(fb->height, share->rank, share->size, &lo, &hi);
        p.y0 = fb->y + lo;
        p.h = hi - lo;
    }
    p.passes = rs->sppm_passes > 0 ? rs->sppm_passes : SPPM_DEFAULT_PASSES;
    p.photons = rs->sppm_photons > 0 ? rs->sppm_photons : SPPM_DEFAULT_PHOTONS;
    p.alpha = rs->sppm_alpha > 0.0 ? rs->sppm_alpha : SPPM_DEFAULT_ALPHA;
    p.radius0 = rs->sppm_radius > 0.0 ? rs->sppm_radius : default_radius(&p);
    Progress prog;
    progress_start(&prog, p.passes, rs->quiet);
    double t0 = now_seconds();
    rc = sppm_run(&p, &prog, err);
    progress_finish(&prog);
    renderer_stats(p.r, st);
    st->seconds = now_seconds() - t0;
    sppm_free(&p);
    renderer_destroy(p.r);
    if (rc != G_OK)
        framebuffer_free(fb);
    return rc;
}
#undef CHECK
