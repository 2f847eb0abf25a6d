/* photons.c - particles of light from the light sources into the scene (photons.h). Only the generic interfaces:
 * colours through gcolor_*, materials through gmaterial_*. A particle carries power; at a surface it arrives from
 * wi and leaves along a direction drawn by gmaterial_sample(out = wi): by reciprocity the drawn `in` is where it goes,
 * and the weight f cos / pdf multiplies its power. A material whose re-radiation is not diagonal (fluorescence)
 * passes the power itself through reflection() (or refraction()), scaled so that the cosine is that of the leaving
 * direction. */
#include "photons.h"
#include "bands.h"
#include "scene/accel.h"
#include "check.h"
#include "camera/rng.h"

#include <generic/kit/material_kit.h>
#include <generic/memory.h>

#include <math.h>
#include <string.h>

int photon_source_init(PhotonSource *src, const Scene *s, const EmissiveSet *emissive, GError *err)
{
    *src = (PhotonSource){0};
    int rc = light_pick_build(&src->pick, s, emissive, err);
    if (rc != G_OK)
        return rc;
    src->bounds = src->pick.bounds;
    if (src->pick.n == 0) {
        photon_source_free(src);
        return gerror_set(err, G_ERR_INVALID, "the scene has no light that sends photons (point, spot, directional, "
                          "ies, sphere or rectangle light, probe of technique reference or glowing object of some "
                          "power): the particle integrators would render black");
    }
    return G_OK;
}

void photon_source_free(PhotonSource *src)
{
    light_pick_free(&src->pick);
    *src = (PhotonSource){0};
}

void photon_batch_free(PhotonBatch *b)
{
    gmem_free(b->photons);
    gmem_free(b->count);
    gmem_free(b->bucket_start);
    gmem_free(b->order);
    if (b->arena)
        gscratch_destroy(b->arena);
    *b = (PhotonBatch){0};
}

int photon_batch_init(PhotonBatch *b, const GColorModel *m, int paths, int per_path, GError *err)
{
    *b = (PhotonBatch){.paths = paths, .per_path = per_path};
    size_t slots = (size_t)paths * (size_t)per_path, bytes = gcolormodel_value_bytes(m);
    b->photons = gmem_calloc(slots, sizeof *b->photons);
    b->count = gmem_calloc((size_t)paths, sizeof *b->count);
    b->order = gmem_calloc(slots, sizeof *b->order);
    b->arena = gscratch_create(slots * (bytes + 64) + 4096);
    int ok = b->photons && b->count && b->order && b->arena;
    for (size_t i = 0; ok && i < slots; i++)
        ok = gcolor_scratch(&b->photons[i].power, m, b->arena) == G_OK;
    if (!ok) {
        photon_batch_free(b);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for a batch of %d photon paths", paths);
    }
    return G_OK;
}

int photon_trace(TraceCtx *c, const PhotonSource *src, const Media *media0, uint64_t index, PhotonBatch *b, int slot,
                 int direct, PhotonVisit visit, void *user)
{
    const Scene *s = c->scene;
    Rng *rng = &c->rng;
    rng_seed(rng, rng_mix64(index ^ 0x243f6a8885a308d3ULL), 0xda3e39cb94b95bdbULL);
    b->count[slot] = 0;
    /* the light, by power */
    double p_light;
    int k = light_pick_sample(&src->pick, rng_next(rng), &p_light, NULL);
    const Light *l = src->pick.lights[k];
    double ue[5] = {rng_next(rng), rng_next(rng), rng_next(rng), rng_next(rng), 0.0};
    if (!l)
        ue[4] = rng_next(rng);
    GVec3 o, d;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor power, weight, tmp, room, rg;
    int rc = G_OK;
    double f = 1.0;
    CHECK(gcolor_scratch(&power, s->model, c->scratch));
    CHECK(gcolor_scratch_uncleared(&weight, s->model, c->scratch));
    CHECK(gcolor_scratch_uncleared(&tmp, s->model, c->scratch));
    CHECK(gcolor_scratch_uncleared(&rg, s->model, c->scratch));
    if (l)
        CHECK(emit_particle(l, &src->bounds, ue, &o, &d, &f, &tmp));
    else
        CHECK(emissive_emit(c, src->pick.emissive, ue, &o, &d, &tmp));
    if (!(f > 0.0) || !(p_light > 0.0) || !(gcolor_brightness(&tmp) > 0.0))
        goto done;
    CHECK(gcolor_scale(&power, &tmp, f / p_light));
    Media media;
    media_copy(&media, media0);
    Ray ray = {o, d, 0.0, INFINITY, 0.0, 0.0};
    const Bands *bands = c->bands;
    int band = -1;
    for (int depth = 0; depth <= c->max_depth; depth++) {
        Hit h;
        c->rays++;
        if (!accel_intersect(s, &ray, &h))
            break;
        const GMaterial *medium = media_top(&media);
        if (!media_clear(medium)) { /* clear (GMAT_CLEAR, vacuum): the dispatch gives the light back */
            CHECK(gmaterial_absorption(medium, NULL, &power, h.t, &tmp));
            CHECK(gcolor_copy(&power, &tmp));
        }
        GScratchMark bounce = gscratch_mark(c->scratch);
        GSurfPoint sp;
        GVec3 facing;
        surfpoint_fill(c, &ray, &h, &media, &sp, &facing);
        const GMaterial *m = sp.material;
        GVec3 wi = gvec3_neg(ray.d);
        int delta = gmaterial_is_delta(m, &sp);
        if (delta < 0) {
            rc = delta;
            gscratch_release(c->scratch, bounce);
            goto done;
        }
        if (!delta && (depth > 0 || direct) && b->count[slot] < b->per_path) {
            Photon *ph = &b->photons[(size_t)slot * (size_t)b->per_path + (size_t)b->count[slot]];
            ph->p = sp.point;
            ph->wi = wi;
            ph->pixel = -1;
            rc = visit ? visit(user, c, &sp, facing, &media, wi, &power, ph) : gcolor_copy(&ph->power, &power);
            b->count[slot]++;
        }
        if (rc < 0 || depth == c->max_depth) {
            gscratch_release(c->scratch, bounce);
            break;
        }
        const GColor *ri = NULL; /* read only: it may be a colour the context keeps (trace.h) */
        int pick = -1, opaque = gmaterial_opaque(m, &sp), valid = 0, transmit = 0;
        GMaterialSample smp;
        double before = gcolor_brightness(&power);
        rc = trace_relative_index(c, &sp, &room, &ri);
        const GColor *ri_use = ri;
        if (rc == G_OK && !opaque && bands && bands->n > 1) {
            if (band < 0 && bands_disperse(bands, ri)) {
                pick = (int)(rng_next(rng) * bands->n);
                if (pick >= bands->n)
                    pick = bands->n - 1;
            }
            int g = band >= 0 ? band : pick;
            if (g >= 0) {
                rc = gcolor_fill(&rg, bands_value(bands, ri, g));
                ri_use = &rg;
            }
        }
        if (rc == G_OK) {
            double u1 = rng_next(rng), u2 = rng_next(rng);
            rc = valid = gmaterial_sample(m, &sp, wi, ri_use, u1, u2, &smp, &weight);
            valid = valid > 0 && smp.pdf > 0.0;
            rc = rc < 0 ? rc : G_OK;
        }
        if (rc == G_OK && valid) {
            transmit = (smp.flags & GSAMPLE_TRANSMIT) != 0;
            if (gmaterial_diagonal(m)) {
                rc = gcolor_mul(&power, &power, &weight);
            } else { /* re-radiation: the power itself through the material, with the leaving direction's cosine */
                GVec3 n;
                double ci = fabs(gmaterial_cos_in(&sp, wi, smp.in, &n)), co = fabs(gvec3_dot(smp.in, n));
                rc = ci > 0.0 ? gcolor_scale(&tmp, &power, co / (ci * smp.pdf)) : gcolor_fill(&tmp, 0.0);
                if (rc == G_OK)
                    rc = transmit ? gmaterial_refraction(m, &sp, wi, &tmp, ri_use, smp.in, &power)
                                  : gmaterial_reflection(m, &sp, wi, &tmp, smp.in, &power);
            }
            if (rc == G_OK && transmit && pick >= 0) { /* one group of n: its light, n times */
                band = pick;
                if ((rc = gcolor_mul(&power, &bands->mask[pick], &power)) == G_OK)
                    rc = gcolor_scale(&power, &power, (double)bands->n);
            }
        }
        gscratch_release(c->scratch, bounce);
        if (rc < 0)
            goto done;
        if (!valid)
            break;
        double after = gcolor_brightness(&power);
        if (!(after > 0.0) || !isfinite(after))
            break;
        if (depth >= PHOTON_RR_START) {
            double q = before > 0.0 ? fmin(1.0, after / before) : 0.0;
            if (rng_next(rng) >= q)
                break;
            CHECK(gcolor_scale(&power, &power, 1.0 / q));
        }
        if (transmit) {
            Media next;
            media_cross(&media, m, sp.entering, &next);
            media_copy(&media, &next);
        }
        ray = (Ray){offset_origin(sp.point, facing, smp.in), smp.in, 0.0, INFINITY, 0.0, 0.0};
    }
done:
    gscratch_release(c->scratch, mark);
    if (rc < 0 && c->status == G_OK)
        c->status = rc;
    return rc < 0 ? rc : G_OK;
}
#undef CHECK

void photon_cell(const PhotonBatch *b, GVec3 p, int64_t cell[3])
{
    cell[0] = (int64_t)floor(p.x / b->cell);
    cell[1] = (int64_t)floor(p.y / b->cell);
    cell[2] = (int64_t)floor(p.z / b->cell);
}

int photon_bucket(const PhotonBatch *b, const int64_t cell[3])
{
    uint64_t h = (uint64_t)cell[0] * 73856093ULL ^ (uint64_t)cell[1] * 19349663ULL ^ (uint64_t)cell[2] * 83492791ULL;
    return (int)(rng_mix64(h) % (uint64_t)b->buckets);
}

int photon_batch_index(PhotonBatch *b, double cell, GError *err)
{
    b->cell = cell;
    int stored = 0;
    for (int i = 0; i < b->paths; i++)
        stored += b->count[i];
    int want = 2 * stored + 1;
    if (want > b->buckets) {
        gmem_free(b->bucket_start);
        b->bucket_start = gmem_calloc((size_t)want + 1, sizeof *b->bucket_start);
        if (!b->bucket_start) {
            b->buckets = 0;
            return gerror_set(err, G_ERR_NOMEM, "out of memory for the photon grid");
        }
    }
    b->buckets = want;
    b->stored = stored;
    memset(b->bucket_start, 0, ((size_t)want + 1) * sizeof *b->bucket_start);
    /* counting sort by bucket, slots in increasing order */
    for (int i = 0; i < b->paths; i++)
        for (int k = 0; k < b->count[i]; k++) {
            int64_t c3[3];
            photon_cell(b, b->photons[(size_t)i * (size_t)b->per_path + (size_t)k].p, c3);
            b->bucket_start[photon_bucket(b, c3) + 1]++;
        }
    for (int j = 0; j < want; j++)
        b->bucket_start[j + 1] += b->bucket_start[j];
    int *fill = gmem_calloc((size_t)want, sizeof *fill);
    if (!fill)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the photon grid");
    for (int i = 0; i < b->paths; i++)
        for (int k = 0; k < b->count[i]; k++) {
            int slot = i * b->per_path + k;
            int64_t c3[3];
            photon_cell(b, b->photons[slot].p, c3);
            int bk = photon_bucket(b, c3);
            b->order[b->bucket_start[bk] + fill[bk]++] = slot;
        }
    gmem_free(fill);
    return G_OK;
}

void photon_share_range(int n, int part, int parts, int *lo, int *hi)
{
    *lo = (int)((int64_t)n * part / parts);
    *hi = (int)((int64_t)n * (part + 1) / parts);
}

/* The packed bytes of one particle: position, direction, pixel, colour kind, values. */
static size_t packed_photon_bytes(const GColorModel *m)
{
    return 6 * sizeof(double) + sizeof(int64_t) + sizeof(int32_t) + gcolormodel_value_bytes(m);
}

size_t photon_batch_pack_bytes(const PhotonBatch *b, const GColorModel *m, int lo, int hi)
{
    return (size_t)(hi - lo) * (sizeof(int32_t) + (size_t)b->per_path * packed_photon_bytes(m));
}

size_t photon_batch_pack(const PhotonBatch *b, int lo, int hi, unsigned char *buf)
{
    unsigned char *at = buf;
    for (int i = lo; i < hi; i++) {
        int32_t count = b->count[i];
        memcpy(at, &count, sizeof count);
        at += sizeof count;
        for (int k = 0; k < count; k++) {
            const Photon *ph = &b->photons[(size_t)i * (size_t)b->per_path + (size_t)k];
            double v[6] = {ph->p.x, ph->p.y, ph->p.z, ph->wi.x, ph->wi.y, ph->wi.z};
            int64_t pixel = ph->pixel;
            int32_t kind = ph->power.kind;
            size_t vb = gcolormodel_value_bytes(ph->power.model);
            memcpy(at, v, sizeof v);
            at += sizeof v;
            memcpy(at, &pixel, sizeof pixel);
            at += sizeof pixel;
            memcpy(at, &kind, sizeof kind);
            at += sizeof kind;
            memcpy(at, ph->power.v, vb);
            at += vb;
        }
    }
    return (size_t)(at - buf);
}

int photon_batch_unpack(PhotonBatch *b, int lo, int hi, const unsigned char *buf, size_t len)
{
    const unsigned char *at = buf, *end = buf + len;
    for (int i = lo; i < hi; i++) {
        int32_t count;
        if ((size_t)(end - at) < sizeof count)
            return G_ERR_INVALID;
        memcpy(&count, at, sizeof count);
        at += sizeof count;
        if (count < 0 || count > b->per_path)
            return G_ERR_INVALID;
        b->count[i] = count;
        for (int k = 0; k < count; k++) {
            Photon *ph = &b->photons[(size_t)i * (size_t)b->per_path + (size_t)k];
            size_t vb = gcolormodel_value_bytes(ph->power.model);
            double v[6];
            int64_t pixel;
            int32_t kind;
            if ((size_t)(end - at) < sizeof v + sizeof pixel + sizeof kind + vb)
                return G_ERR_INVALID;
            memcpy(v, at, sizeof v);
            at += sizeof v;
            memcpy(&pixel, at, sizeof pixel);
            at += sizeof pixel;
            memcpy(&kind, at, sizeof kind);
            at += sizeof kind;
            if (kind != GCOLOR_VECTOR && kind != GCOLOR_MATRIX)
                return G_ERR_INVALID;
            ph->p = (GVec3){v[0], v[1], v[2]};
            ph->wi = (GVec3){v[3], v[4], v[5]};
            ph->pixel = (long)pixel;
            ph->power.kind = kind;
            memcpy(ph->power.v, at, vb);
            at += vb;
        }
    }
    return at == end ? G_OK : G_ERR_INVALID;
}
