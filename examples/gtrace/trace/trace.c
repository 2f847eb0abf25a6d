/* trace.c - what the integrators and the lights share (trace.h): the per-thread tracing context's temporaries, the
 * stack of media a ray travels through, the surface point filled at a hit (geometry, the normal on the incident
 * side, the footprint of the ray cone, the materials on both sides) with the relative index across it, and the
 * offset of a secondary ray's origin against self-intersection. */
#include "trace.h"

#include <math.h>

double shadow_reach(GVec3 origin, GVec3 dir, GVec3 target, GVec3 normal)
{
    GVec3 to = gvec3_sub(target, origin);
    double height = gvec3_dot(to, normal), cos_t = gvec3_dot(dir, normal);
    if (height < 0.0) { /* the origin lies on the side normal points to: measure from that side */
        height = -height;
        cos_t = -cos_t;
    }
    /* height: how far the target's tangent plane lies ahead of the origin; cos_t: how fast the ray closes on it */
    double reach = (height - offset_eps(target)) / cos_t;
    if (!(cos_t > 0.0) || !isfinite(reach)) /* running along the plane (or away): it cannot meet the target's surface */
        return fmax(0.0, gvec3_dot(to, dir));
    return fmax(0.0, reach);
}

const GMaterial *media_top(const Media *m) { return m->n > 0 ? m->m[m->n - 1] : NULL; }

/* The medium outside `mat` as seen from the stack: the entry below its top-most occurrence. */
static const GMaterial *media_outside(const Media *m, const GMaterial *mat)
{
    for (int i = m->n - 1; i >= 0; i--)
        if (m->m[i] == mat)
            return i > 0 ? m->m[i - 1] : NULL;
    return media_top(m);
}

/* The (u, v) coordinates of the tangent vectors v1 and v2 in the frame of the tangents a = dp/du, b = dp/dv
 * (least squares: exact for a vector in their plane; the Gram matrix once for both); zero when the tangents are
 * degenerate. */
static void uv_of(GVec3 a, GVec3 b, GVec3 v1, GVec3 v2, double out1[2], double out2[2])
{
    double aa = gvec3_dot(a, a), ab = gvec3_dot(a, b), bb = gvec3_dot(b, b), det = aa * bb - ab * ab;
    if (!(det > 0.0) || !isfinite(det)) {
        out1[0] = out1[1] = out2[0] = out2[1] = 0.0;
        return;
    }
    double inv = 1.0 / det, av = gvec3_dot(a, v1), bv = gvec3_dot(b, v1);
    out1[0] = (bb * av - ab * bv) * inv;
    out1[1] = (aa * bv - ab * av) * inv;
    av = gvec3_dot(a, v2);
    bv = gvec3_dot(b, v2);
    out2[0] = (bb * av - ab * bv) * inv;
    out2[1] = (aa * bv - ab * av) * inv;
}

int trace_ctx_temps(TraceCtx *c)
{
    for (int i = 0; i < TRACE_TMP_COUNT; i++)
        if (c->tmp[i].storage == GCOLOR_STORAGE_NONE &&
            gcolor_scratch(&c->tmp[i], c->scene->model, c->scratch) != G_OK)
            return G_ERR_NOMEM;
    for (int i = 0; i < TRACE_RI_SLOTS; i++)
        if (c->ri_cache[i].ri.storage == GCOLOR_STORAGE_NONE &&
            gcolor_scratch(&c->ri_cache[i].ri, c->scene->model, c->scratch) != G_OK)
            return G_ERR_NOMEM;
    return G_OK;
}

void trace_ctx_free_temps(TraceCtx *c)
{
    for (int i = 0; i < TRACE_TMP_COUNT; i++)
        gcolor_free(&c->tmp[i]);
    for (int i = 0; i < TRACE_RI_SLOTS; i++)
        gcolor_free(&c->ri_cache[i].ri);
    c->ri_filled = 0;
}

int trace_tmp(TraceCtx *c, int which, GColor *out)
{
    if (c->tmp[which].storage != GCOLOR_STORAGE_NONE) {
        *out = c->tmp[which];
        return G_OK;
    }
    return gcolor_scratch(out, c->scene->model, c->scratch);
}

void media_copy(Media *out, const Media *in)
{
    int n = in->n < 0 ? 0 : in->n > MEDIA_MAX ? MEDIA_MAX : in->n;
    for (int i = 0; i < n; i++)
        out->m[i] = in->m[i];
    out->n = n;
}

void media_cross(const Media *in, const GMaterial *mat, int entering, Media *out)
{
    media_copy(out, in);
    if (entering) {
        if (out->n < MEDIA_MAX)
            out->m[out->n++] = mat;
        return;
    }
    for (int i = out->n - 1; i >= 0; i--)
        if (out->m[i] == mat) {
            for (int j = i; j + 1 < out->n; j++)
                out->m[j] = out->m[j + 1];
            out->n--;
            return;
        }
}

void surfpoint_fill(TraceCtx *c, const Ray *r, const Hit *h, const Media *media, GSurfPoint *sp, GVec3 *facing)
{
    /* a material that reads nothing of the parametrisation (GMAT_NO_UV) gets it zero, as gsurfpoint_init leaves
     * it: no (u, v), tangents or footprint ellipse to compute */
    int want_uv = !(h->material && (h->material->flags & GMAT_NO_UV));
    HitGeom g;
    hit_geom(r, h, want_uv, &g);
    gsurfpoint_init(sp, c->scene->model, c->scratch);
    sp->point = g.p;
    sp->object_point = g.op;
    double dn = gvec3_dot(r->d, g.n_out);
    sp->entering = dn < 0.0;
    /* the geometry's normal on the incident side (interpolated for meshes with normals) */
    GVec3 ns = sp->entering ? g.n_smooth : gvec3_neg(g.n_smooth);
    sp->geometric_normal = ns;
    *facing = sp->entering ? g.n_out : gvec3_neg(g.n_out);
    sp->surface = g.surface;
    sp->t = h->t;
    /* ray cone: width w at the hit. The isotropic footprint is the long axis of the footprint ellipse,
     * w / cos: a filter as wide as that does not alias at grazing angles (the geometric mean of the axes,
     * w / sqrt(cos), keeps the area but leaves moire on receding checkers) */
    double w = r->cone_width + r->cone_spread * h->t;
    double cosv = gfmax(fabs(dn), 0.02);
    sp->footprint = w / cosv;
    if (want_uv) {
        sp->dpdu = g.dpdu;
        sp->dpdv = g.dpdv;
        if (g.object_tangents) { /* else zero, which means dpdu and dpdv (surfpoint.h) */
            sp->object_dpdu = g.odpdu;
            sp->object_dpdv = g.odpdv;
        }
        sp->u = g.u;
        sp->v = g.v;
        double area = gvec3_length(gvec3_cross(g.dpdu, g.dpdv));
        sp->uv_footprint = area > 0.0 ? sp->footprint / sqrt(area) : 0.0;
        /* the same footprint as an ellipse for anisotropic filters: w / cos along the ray's projection onto the
         * surface, w across it, both mapped into (u, v) through the tangents */
        GVec3 along = gvec3_sub(r->d, gvec3_scale(g.n_out, dn));
        double la = gvec3_length(along);
        along = la > 1e-9 ? gvec3_scale(along, 1.0 / la) : gvec3_normalize(g.dpdu);
        GVec3 across = gvec3_cross(g.n_out, along);
        uv_of(g.dpdu, g.dpdv, gvec3_scale(along, sp->footprint), gvec3_scale(across, w), sp->uv_axis1,
              sp->uv_axis2);
    }
    sp->material = h->material;
    if (sp->entering) {
        sp->from = media_top(media);
        sp->to = sp->material;
    } else {
        sp->from = sp->material;
        sp->to = media_outside(media, sp->material);
    }
}

/* n(from) / n(to) at sp into out, which has storage: the two indices in the context's temporaries, then the division
 * (the one computation of a relative index, kept or not, so that both give the same bits). */
static int divide_indices(TraceCtx *c, const GMaterial *from, const GMaterial *to, GSurfPoint *sp, GColor *out)
{
    GColor n_from, n_to;
    int rc;
    if ((rc = trace_tmp(c, TRACE_TMP_N_FROM, &n_from)) < 0 || (rc = trace_tmp(c, TRACE_TMP_N_TO, &n_to)) < 0 ||
        (rc = gmaterial_refraction_index(from, sp, &n_from)) < 0 ||
        (rc = gmaterial_refraction_index(to, sp, &n_to)) < 0)
        return rc;
    return gcolor_div(out, &n_from, &n_to);
}

/* GMAT_CONSTANT_INDEX read from the flags, as the other flags are (no call per vertex); NULL is vacuum, index 1. */
static inline int constant_index(const GMaterial *m) { return !m || (m->flags & GMAT_CONSTANT_INDEX); }

int trace_cached_index(TraceCtx *c, const GMaterial *from, const GMaterial *to, GSurfPoint *sp, const GColor **ri)
{
    *ri = NULL;
    if (!constant_index(from) || !constant_index(to))
        return G_OK;
    int n = c->ri_filled, i = 0;
    while (i < n && (c->ri_cache[i].from != from || c->ri_cache[i].to != to))
        i++;
    TraceRelIndex *e = &c->ri_cache[i < TRACE_RI_SLOTS ? i : 0];
    if (i == n) { /* a pair not met yet: into the next entry, if any */
        if (n >= TRACE_RI_SLOTS || e->ri.storage == GCOLOR_STORAGE_NONE) /* full, or no storage made */
            return G_OK;
        int rc = divide_indices(c, from, to, sp, &e->ri);
        if (rc < 0)
            return rc;
        e->from = from;
        e->to = to;
        e->scalar = gsurfpoint_scalar_index(&e->ri);
        c->ri_filled = n + 1;
    }
    gsurfpoint_set_relative_index_scalar(sp, &e->ri, e->scalar);
    *ri = &e->ri;
    return G_OK;
}

int trace_relative_index(TraceCtx *c, GSurfPoint *sp, GColor *room, const GColor **ri)
{
    int rc;
    if (sp->material && (sp->material->flags & GMAT_NO_REL_INDEX)) { /* read by no method: not computed (trace.h) */
        *ri = &c->unit;
        return G_OK;
    }
    if ((rc = trace_cached_index(c, sp->from, sp->to, sp, ri)) < 0 || *ri) /* kept, and set on sp with its scalar */
        return rc;
    if ((rc = gcolor_scratch_uncleared(room, c->scene->model, c->scratch)) < 0 || /* the division writes it */
        (rc = divide_indices(c, sp->from, sp->to, sp, room)) < 0)
        return rc;
    *ri = room;
    gsurfpoint_set_relative_index(sp, room); /* what the material's reflection reads: not divided again */
    return G_OK;
}
