/* surfpoint.c - the surface point's caches. */
#include "generic/surfpoint.h"
#include "generic/material.h"
#include "generic/memory.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* HAVE_REL_INDEX_COLOUR: the relative index is the colour at rel_index_values (set by gsurfpoint_set_relative_index,
 * not computed by gsurfpoint_relative_index): a vector of sp->model, whose scalar is taken when first asked for
 * (HAVE_REL_INDEX then says it is cached); REL_INDEX_MATRIX: that colour is a matrix */
enum { HAVE_NORMAL = 1u, HAVE_REL_INDEX = 2u, HAVE_REL_INDEX_COLOUR = 4u, REL_INDEX_MATRIX = 8u };

/* always inlined where the optimiser sees it (link-time optimisation of a renderer): the stores then merge with the
 * caller's, which overwrites most of them; an external definition all the same (surfpoint.h declares it) */
__attribute__((always_inline)) inline void gsurfpoint_init(GSurfPoint *sp, const GColorModel *model, GScratch *scratch)
{
    /* every field zero but the cache slots' contents and scopes (768 bytes, most of the struct): only the first
     * ncache of them are ever read, and ncache is 0. Field by field, not one memset of the public fields: GCC makes
     * that a `rep stos`, whose start-up was a fifth of a renderer's surface-point fill; these stores merge into
     * vector stores, and a renderer that inlines this drops those it overwrites. */
    const GVec3 zero = {0.0, 0.0, 0.0};
    sp->point = sp->object_point = sp->geometric_normal = sp->dpdu = sp->dpdv = zero;
    sp->u = sp->v = 0.0;
    sp->surface = 0;
    sp->entering = 1;
    sp->t = sp->footprint = sp->uv_footprint = 0.0;
    sp->material = sp->from = sp->to = NULL;
    sp->model = model;
    sp->scratch = scratch;
    sp->object_dpdu = sp->object_dpdv = zero;
    sp->uv_axis1[0] = sp->uv_axis1[1] = sp->uv_axis2[0] = sp->uv_axis2[1] = 0.0;
    GSurfPointPrivate *p = &sp->priv;
    p->cached_flags = 0;
    p->ncache = 0;
    p->cached_normal = zero;
    p->cached_rel_index = 0.0;
    p->rel_index_values = NULL;
    p->cache_scope = 0;
}

static int finite3(GVec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

GSurfPoint *gsurfpoint_new(const GColorModel *model, GScratch *scratch, GVec3 point, GVec3 normal, GVec3 dpdu,
                           GVec3 dpdv, double u, double v, int surface, GError *err)
{
    const char *bad = !model ? "no colour model given"
                      : !scratch ? "no scratch arena given"
                      : !finite3(point) ? "the point is not finite"
                      : !finite3(normal) || gvec3_length(normal) == 0.0 ? "the normal is zero or not finite"
                      : !finite3(dpdu) || !finite3(dpdv) ? "a tangent is not finite"
                      : !isfinite(u) || !isfinite(v) ? "(u, v) is not finite"
                      : surface < 0 ? "the surface index is negative"
                      : NULL;
    if (bad) {
        gerror_set(err, G_ERR_INVALID, "gsurfpoint_new: %s", bad);
        return NULL;
    }
    GSurfPoint *sp = gmem_alloc(sizeof *sp);
    if (!sp) {
        gerror_set(err, G_ERR_NOMEM, "gsurfpoint_new: out of memory");
        return NULL;
    }
    gsurfpoint_init(sp, model, scratch);
    sp->point = sp->object_point = point;
    sp->geometric_normal = gvec3_normalize(normal);
    sp->dpdu = dpdu;
    sp->dpdv = dpdv;
    sp->u = u;
    sp->v = v;
    sp->surface = surface;
    return sp;
}

void gsurfpoint_free(GSurfPoint *sp) { gmem_free(sp); }

size_t gsurfpoint_size(void) { return sizeof(GSurfPoint); }

void gsurfpoint_invalidate(GSurfPoint *sp)
{
    sp->priv.cached_flags = 0;
    sp->priv.ncache = 0;
}

/* The first call's work of gsurfpoint_normal: the normal asked and cached. */
static __attribute__((noinline)) GVec3 normal_first(GSurfPoint *sp)
{
    GVec3 n = sp->geometric_normal;
    /* GMAT_GEOMETRIC_NORMAL: the material's normal is the geometric one, no call (material.h) */
    if (sp->material && !(sp->material->flags & GMAT_GEOMETRIC_NORMAL) &&
        gmaterial_normal(sp->material, sp, &n) != G_OK)
        n = sp->geometric_normal;
    sp->priv.cached_normal = n;
    sp->priv.cached_flags |= HAVE_NORMAL;
    return n;
}

/* always inlined where the optimiser sees it (link-time optimisation of a renderer, which asks for the normal of a
 * point many times: every light's cosine, every ideal pair): the cached normal is one test and a load there; an
 * external definition all the same (surfpoint.h declares it) */
__attribute__((always_inline)) inline GVec3 gsurfpoint_normal(GSurfPoint *sp)
{
    if (!(sp->priv.cached_flags & HAVE_NORMAL))
        return normal_first(sp);
    return sp->priv.cached_normal;
}

void gsurfpoint_set_normal(GSurfPoint *sp, GVec3 n)
{
    sp->priv.cached_normal = n;
    sp->priv.cached_flags |= HAVE_NORMAL;
}

double gsurfpoint_scalar_index(const GColor *ri)
{
    double ratio = gcolor_brightness(ri);
    return ratio > 0.0 ? ratio : 1.0;
}

/* The scalar of the colour gsurfpoint_set_relative_index gave sp, taken now and cached. */
static double set_index_scalar(GSurfPointPrivate *p, const GColorModel *model)
{
    GColor ri = {.model = model,
                 .v = (float *)p->rel_index_values,
                 .kind = p->cached_flags & REL_INDEX_MATRIX ? GCOLOR_MATRIX : GCOLOR_VECTOR,
                 .storage = GCOLOR_STORAGE_CALLER,
                 .capacity = model->capacity};
    p->cached_rel_index = gsurfpoint_scalar_index(&ri);
    p->cached_flags |= HAVE_REL_INDEX;
    return p->cached_rel_index;
}

double gsurfpoint_relative_index(GSurfPoint *sp)
{
    if (!(sp->priv.cached_flags & HAVE_REL_INDEX)) {
        if (sp->priv.cached_flags & HAVE_REL_INDEX_COLOUR)
            return set_index_scalar(&sp->priv, sp->model);
        double r = 1.0;
        if (sp->model && sp->scratch) {
            GScratchMark mark = gscratch_mark(sp->scratch);
            GColor a, b;
            if (gcolor_scratch(&a, sp->model, sp->scratch) == G_OK &&
                gcolor_scratch(&b, sp->model, sp->scratch) == G_OK &&
                gmaterial_refraction_index(sp->from, sp, &a) == G_OK &&
                gmaterial_refraction_index(sp->to, sp, &b) == G_OK && gcolor_div(&a, &a, &b) == G_OK)
                r = gsurfpoint_scalar_index(&a);
            gscratch_release(sp->scratch, mark);
        }
        sp->priv.cached_rel_index = r;
        sp->priv.cached_flags |= HAVE_REL_INDEX;
    }
    return sp->priv.cached_rel_index;
}

void gsurfpoint_set_relative_index(GSurfPoint *sp, const GColor *ri)
{
    GSurfPointPrivate *p = &sp->priv;
    p->rel_index_values = ri->v;
    p->cached_flags &= ~(unsigned)(HAVE_REL_INDEX | REL_INDEX_MATRIX);
    p->cached_flags |= HAVE_REL_INDEX_COLOUR | (ri->kind == GCOLOR_MATRIX ? REL_INDEX_MATRIX : 0u);
    if (ri->model != sp->model || !sp->model) { /* a colour of another model: its scalar now, from its own handle */
        p->cached_rel_index = gsurfpoint_scalar_index(ri);
        p->cached_flags |= HAVE_REL_INDEX;
    }
}

void gsurfpoint_set_relative_index_scalar(GSurfPoint *sp, const GColor *ri, double scalar)
{
    GSurfPointPrivate *p = &sp->priv;
    p->rel_index_values = ri->v;
    p->cached_flags &= ~(unsigned)REL_INDEX_MATRIX;
    p->cached_flags |= HAVE_REL_INDEX_COLOUR | HAVE_REL_INDEX | (ri->kind == GCOLOR_MATRIX ? REL_INDEX_MATRIX : 0u);
    p->cached_rel_index = scalar;
}

double gsurfpoint_index_of(const GSurfPoint *sp, const GColor *ri)
{
    unsigned f = sp->priv.cached_flags;
    if (!(f & HAVE_REL_INDEX_COLOUR) || ri->v != sp->priv.rel_index_values)
        return gsurfpoint_scalar_index(ri);
    if (f & HAVE_REL_INDEX)
        return sp->priv.cached_rel_index;
    /* the point's own cache, written through a const view: a surface point is never a const object (every material
     * method receives it writable, and gsurfpoint_relative_index writes the same cache) */
    return set_index_scalar(&((GSurfPoint *)sp)->priv, sp->model);
}

int gsurfpoint_cache_get(const GSurfPoint *sp, const void *key, double *value, GVec3 *gradient)
{
    const GSurfPointPrivate *p = &sp->priv;
    int n = p->ncache < GSURF_CACHE_SLOTS ? p->ncache : GSURF_CACHE_SLOTS;
    for (int i = 0; i < n; i++)
        if (p->cache[i].key == key && p->cache_slot_scope[i] == p->cache_scope) {
            if (value)
                *value = p->cache[i].value;
            if (gradient)
                *gradient = p->cache[i].gradient;
            return 1;
        }
    return 0;
}

void gsurfpoint_cache_put(GSurfPoint *sp, const void *key, double value, GVec3 gradient)
{
    GSurfPointPrivate *p = &sp->priv;
    int n = p->ncache < GSURF_CACHE_SLOTS ? p->ncache : GSURF_CACHE_SLOTS;
    for (int i = 0; i < n; i++)
        if (p->cache[i].key == key && p->cache_slot_scope[i] == p->cache_scope) { /* one slot per key: replace */
            p->cache[i].value = value;
            p->cache[i].gradient = gradient;
            return;
        }
    int slot = p->ncache % GSURF_CACHE_SLOTS;
    p->cache[slot].key = key;
    p->cache[slot].value = value;
    p->cache[slot].gradient = gradient;
    p->cache_slot_scope[slot] = p->cache_scope;
    /* after the slots are full, keep ncache in [GSURF_CACHE_SLOTS, 2 * GSURF_CACHE_SLOTS) so it never overflows */
    p->ncache = p->ncache + 1 >= 2 * GSURF_CACHE_SLOTS ? GSURF_CACHE_SLOTS : p->ncache + 1;
}

/* splitmix64's finaliser: a scope is a hash of the chain of nodes that moved the coordinates (64 bits: two
 * different chains meeting on the same point collide with probability about 2^-64). */
static uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

void gsurfpoint_cache_enter(GSurfPoint *q, const GSurfPoint *sp, const void *node)
{
    q->priv.cache_scope = mix64(sp->priv.cache_scope * 0x9e3779b97f4a7c15ull + (uint64_t)(uintptr_t)node) | 1u;
}

void gsurfpoint_cache_return(GSurfPoint *sp, const GSurfPoint *q)
{
    sp->priv.ncache = q->priv.ncache;
    memcpy(sp->priv.cache, q->priv.cache, sizeof sp->priv.cache);
    memcpy(sp->priv.cache_slot_scope, q->priv.cache_slot_scope, sizeof sp->priv.cache_slot_scope);
}

void gsurfpoint_uv_widths(const GSurfPoint *sp, double *wu, double *wv)
{
    const double *a = sp->uv_axis1, *b = sp->uv_axis2;
    if (a[0] == 0.0 && a[1] == 0.0 && b[0] == 0.0 && b[1] == 0.0) {
        *wu = *wv = sp->uv_footprint;
        return;
    }
    /* the bounding box of the ellipse with these two conjugate diameters */
    *wu = sqrt(a[0] * a[0] + b[0] * b[0]);
    *wv = sqrt(a[1] * a[1] + b[1] * b[1]);
}
