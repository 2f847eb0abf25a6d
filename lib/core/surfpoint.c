/* surfpoint.c - the surface point's caches. */
#include "generic/surfpoint.h"
#include "generic/material.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* HAVE_REL_INDEX_COLOUR: the cached relative index was read from the colour at rel_index_values (set by
 * gsurfpoint_set_relative_index, not computed by gsurfpoint_relative_index) */
enum { HAVE_NORMAL = 1u, HAVE_REL_INDEX = 2u, HAVE_REL_INDEX_COLOUR = 4u };

/* always inlined where the optimiser sees it (link-time optimisation of a renderer): the stores then merge with the
 * caller's, which overwrites most of them; an external definition all the same (surfpoint.h declares it) */
__attribute__((always_inline)) inline void gsurfpoint_init(GSurfPoint *sp, const GColorModel *model, GScratch *scratch)
{
    /* every field zero but the cache slots' contents and scopes (768 bytes, most of the struct): only the first
     * ncache of them are ever read, and ncache is 0. Field by field, not one memset of the 208 bytes before the
     * slots: GCC makes that a `rep stos`, whose start-up was a fifth of a renderer's surface-point fill; these
     * stores merge into vector stores, and a renderer that inlines this drops those it overwrites. */
    const GVec3 zero = {0.0, 0.0, 0.0};
    sp->point = sp->object_point = sp->geometric_normal = sp->dpdu = sp->dpdv = zero;
    sp->u = sp->v = 0.0;
    sp->surface = 0;
    sp->entering = 1;
    sp->t = sp->footprint = sp->uv_footprint = 0.0;
    sp->material = sp->from = sp->to = NULL;
    sp->model = model;
    sp->scratch = scratch;
    sp->cached_flags = 0;
    sp->cached_normal = zero;
    sp->cached_rel_index = 0.0;
    sp->ncache = 0;
    sp->object_dpdu = sp->object_dpdv = zero;
    sp->cache_scope = 0;
    memset(sp->uv_axis1, 0, sizeof *sp - offsetof(GSurfPoint, uv_axis1));
}

void gsurfpoint_invalidate(GSurfPoint *sp)
{
    sp->cached_flags = 0;
    sp->ncache = 0;
}

GVec3 gsurfpoint_normal(GSurfPoint *sp)
{
    if (!(sp->cached_flags & HAVE_NORMAL)) {
        GVec3 n = sp->geometric_normal;
        /* GMAT_GEOMETRIC_NORMAL: the material's normal is the geometric one, no call (material.h) */
        if (sp->material && !(sp->material->flags & GMAT_GEOMETRIC_NORMAL) &&
            gmaterial_normal(sp->material, sp, &n) != G_OK)
            n = sp->geometric_normal;
        sp->cached_normal = n;
        sp->cached_flags |= HAVE_NORMAL;
    }
    return sp->cached_normal;
}

void gsurfpoint_set_normal(GSurfPoint *sp, GVec3 n)
{
    sp->cached_normal = n;
    sp->cached_flags |= HAVE_NORMAL;
}

double gsurfpoint_scalar_index(const GColor *ri)
{
    double ratio = gcolor_brightness(ri);
    return ratio > 0.0 ? ratio : 1.0;
}

double gsurfpoint_relative_index(GSurfPoint *sp)
{
    if (!(sp->cached_flags & HAVE_REL_INDEX)) {
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
        sp->cached_rel_index = r;
        sp->cached_flags |= HAVE_REL_INDEX;
    }
    return sp->cached_rel_index;
}

void gsurfpoint_set_relative_index(GSurfPoint *sp, const GColor *ri)
{
    sp->cached_rel_index = gsurfpoint_scalar_index(ri);
    sp->rel_index_values = ri->v;
    sp->cached_flags |= HAVE_REL_INDEX | HAVE_REL_INDEX_COLOUR;
}

double gsurfpoint_index_of(const GSurfPoint *sp, const GColor *ri)
{
    if ((sp->cached_flags & HAVE_REL_INDEX_COLOUR) && ri->v == sp->rel_index_values)
        return sp->cached_rel_index;
    return gsurfpoint_scalar_index(ri);
}

int gsurfpoint_cache_get(const GSurfPoint *sp, const void *key, double *value, GVec3 *gradient)
{
    int n = sp->ncache < GSURF_CACHE_SLOTS ? sp->ncache : GSURF_CACHE_SLOTS;
    for (int i = 0; i < n; i++)
        if (sp->cache[i].key == key && sp->cache_slot_scope[i] == sp->cache_scope) {
            if (value)
                *value = sp->cache[i].value;
            if (gradient)
                *gradient = sp->cache[i].gradient;
            return 1;
        }
    return 0;
}

void gsurfpoint_cache_put(GSurfPoint *sp, const void *key, double value, GVec3 gradient)
{
    int n = sp->ncache < GSURF_CACHE_SLOTS ? sp->ncache : GSURF_CACHE_SLOTS;
    for (int i = 0; i < n; i++)
        if (sp->cache[i].key == key && sp->cache_slot_scope[i] == sp->cache_scope) { /* one slot per key: replace */
            sp->cache[i].value = value;
            sp->cache[i].gradient = gradient;
            return;
        }
    int slot = sp->ncache % GSURF_CACHE_SLOTS;
    sp->cache[slot].key = key;
    sp->cache[slot].value = value;
    sp->cache[slot].gradient = gradient;
    sp->cache_slot_scope[slot] = sp->cache_scope;
    /* after the slots are full, keep ncache in [GSURF_CACHE_SLOTS, 2 * GSURF_CACHE_SLOTS) so it never overflows */
    sp->ncache = sp->ncache + 1 >= 2 * GSURF_CACHE_SLOTS ? GSURF_CACHE_SLOTS : sp->ncache + 1;
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
    q->cache_scope = mix64(sp->cache_scope * 0x9e3779b97f4a7c15ull + (uint64_t)(uintptr_t)node) | 1u;
}

void gsurfpoint_cache_return(GSurfPoint *sp, const GSurfPoint *q)
{
    sp->ncache = q->ncache;
    memcpy(sp->cache, q->cache, sizeof sp->cache);
    memcpy(sp->cache_slot_scope, q->cache_slot_scope, sizeof sp->cache_slot_scope);
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
