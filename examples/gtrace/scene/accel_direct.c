/* accel_direct.c - the direct list: a scene of a few analytic shapes, each tested in turn.
 *
 * Embree's per-ray cost (setting up the ray, the context and the traversal, and calling back into the user
 * geometry) exceeds testing every shape when the scene holds only a few analytic ones, so such a scene keeps a flat
 * array of its shapes with each shape's padded world bounds. A ray tests the boxes of all entries at once (slab
 * tests against [tmin, tmax], two entries side by side: lanes2.h, SSE2 doubles or two scalars, bit for bit the
 * scalar test), then, in the scene's order, skips an entry whose box begins beyond the closest hit so far and
 * intersects the others in double precision in the shape's own space exactly as Embree's user-geometry callbacks do
 * (accel.c). The hit is therefore the one the Embree path finds, with the same double t, but for two kinds of near
 * ties: Embree narrows its ray to the single-precision t of a hit, so a second shape hit within float rounding
 * (about 6e-8 relative) behind the first may be missed by Embree and found here; and of two shapes hit at exactly
 * the same t the first in the scene's order wins here, the first Embree visits there. Likewise a hit within float
 * rounding of the ray's tmax: Embree's tfar is tmax in single precision, the direct list keeps tmax in double.
 * Planes are box-tested like the others (their bounds end at SHAPE_PLANE_EXTENT, as Embree's do).
 *
 * Occlusion: the first opaque-everywhere shape on the segment ends the query (OCCLUDED_OPAQUE); otherwise a
 * shape that may let light through makes it OCCLUDED_PASSABLE (the shadow walk of lights.c decides). Embree
 * ends the query at whichever shape it meets first, so where it says opaque this says opaque too, and where
 * it says passable this may say opaque (the walk would have ended at that opaque surface). */
#include "accel_direct.h"
#include "accel.h"

#include "lanes2.h"
#include <math.h>

/* ACCEL_DIRECT_MAX (accel_direct.h), the largest scene (in shapes) traced through the direct list: where it stops
 * paying. Measured with callgrind
 * (whole process, millions of instructions, 1 thread, 320x240, depth 8; a checker plane and k lambert spheres,
 * radius up to 1, on a grid across x in [-3, 3] and z in [-2, 2] seen from <0, 2.2, 8>, one point light; the
 * pictures of both paths byte-identical):
 *   shapes (k + 1)   2      3      5      6      8      9      12     13     14     15     16     17     25     31
 *   Embree         254.2  252.1  251.6  251.5  253.8  254.8  256.4  257.1  257.1  257.8  258.0  257.6  258.8  258.8
 *   direct         217.2  220.2  225.0  224.7  232.9  238.0  245.4  250.9  250.8  256.3  256.2  262.9  284.9  302.5
 * The box tests of two entries cost about 40 instructions a ray (and a shape test follows when a box is met):
 * up to 16 shapes that is less than Embree's cost per ray, from 17 on more. With one entry's box test at a
 * time the threshold was 8 (a heavier scene then: 342.1 Embree against 340.5 direct at 8 shapes, 342.5 against
 * 346.0 at 9). */
_Static_assert(ACCEL_DIRECT_MAX >= 0 && ACCEL_DIRECT_MAX <= 31, "the entries met are the bits of an unsigned");

/* One shape of the direct list. */
typedef struct DirectEntry {
    const Object *obj;
    int plain;        /* SHAPE_SPHERE or SHAPE_PLANE without a transform (intersected inline), else -1 */
    int opaque;       /* its material blocks all light (gmaterial_opaque_everywhere) */
    int opaque_later; /* an opaque entry follows this one (occlusion stops at a passable one otherwise) */
} DirectEntry;

/* The padded world bounds of two entries (2k and 2k + 1) as Embree gets them (user_bounds in accel.c), one
 * axis a vector: their box tests run side by side in the two lanes. */
typedef struct DirectPair {
    Lanes2 lo[3], hi[3];
} DirectPair;

#define DIRECT_PAIRS ((ACCEL_DIRECT_MAX + 1) / 2)

/* The direct list (s->direct): the entries in the scene's order and their bounds in pairs (the lane of a
 * missing last entry holds zeros and is masked off). */
typedef struct AccelDirect {
    DirectPair pair[DIRECT_PAIRS];
    DirectEntry e[2 * DIRECT_PAIRS];
} AccelDirect;

/* 1 for the shapes the direct list holds: the analytic ones. */
static int direct_kind(const Object *o)
{
    switch (o->kind) {
    case SHAPE_SPHERE:
    case SHAPE_PLANE:
    case SHAPE_BOX:
    case SHAPE_DISC:
    case SHAPE_CYLINDER: return 1;
    default: return 0;
    }
}

int accel_direct_build(Scene *s, GError *err)
{
    accel_direct_release(s);
    if (s->accel_embree_only)
        return G_OK;
    int n = 0;
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (o->is_part)
            continue;
        if (!direct_kind(o) || ++n > ACCEL_DIRECT_MAX)
            return G_OK;
    }
    AccelDirect *d = gmem_calloc(1, sizeof *d); /* malloc's alignment (16 bytes) suits the vectors */
    if (!d)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    int k = 0;
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (o->is_part)
            continue;
        GVec3 wlo, whi;
        object_world_bounds(o, &wlo, &whi);
        /* the padding of user_bounds (accel.c): flat shapes and rounding lose no hits */
        double pad = 1e-6 * (1.0 + fmax(fmax(fabs(wlo.x), fabs(whi.x)), fmax(fmax(fabs(wlo.y), fabs(whi.y)),
                                                                          fmax(fabs(wlo.z), fabs(whi.z)))));
        double *lo = (double *)d->pair[k / 2].lo, *hi = (double *)d->pair[k / 2].hi;
        lo[0 + k % 2] = wlo.x - pad;
        lo[2 + k % 2] = wlo.y - pad;
        lo[4 + k % 2] = wlo.z - pad;
        hi[0 + k % 2] = whi.x + pad;
        hi[2 + k % 2] = whi.y + pad;
        hi[4 + k % 2] = whi.z + pad;
        d->e[k].obj = o;
        d->e[k].plain = !o->has_xf && (o->kind == SHAPE_SPHERE || o->kind == SHAPE_PLANE) ? (int)o->kind : -1;
        d->e[k].opaque = gmaterial_opaque_everywhere(o->material) != 0;
        k++;
    }
    for (int i = n - 2, later = 0; i >= 0; i--) {
        later |= d->e[i + 1].opaque;
        d->e[i].opaque_later = later;
    }
    s->direct = d;
    s->ndirect = n;
    return G_OK;
}

void accel_direct_release(Scene *s)
{
    gmem_free(s->direct);
    s->direct = NULL;
    s->ndirect = 0;
}

int accel_uses_direct(const Scene *s) { return s->direct != NULL; }

/* x clamped to [-1e300, 1e300] (minsd and maxsd: no call, no branch). */
static inline double clamp_big(double x)
{
    x = x < 1e300 ? x : 1e300;
    return x > -1e300 ? x : -1e300;
}

/* The box tests of every entry against r within [tmin, tf] (a NaN tf meets nothing): bit i of the result is
 * set when entry i's box is met, and near[i] is the parameter where the ray enters it. A component of the
 * direction that is zero has the reciprocal +-1e300 rather than an infinity, so that no product is 0 * inf (a
 * ray in a box's face plane stays in) and none is a NaN: min and max below are minpd and maxpd, and each lane
 * computes exactly what a scalar slab test computes. */
static inline unsigned boxes_met(const AccelDirect *d, int n, const Ray *r, double tf, double *near)
{
    const Lanes2 ox = lanes2_set1(r->o.x), oy = lanes2_set1(r->o.y), oz = lanes2_set1(r->o.z);
    const Lanes2 ix = lanes2_set1(clamp_big(1.0 / r->d.x)), iy = lanes2_set1(clamp_big(1.0 / r->d.y)),
                 iz = lanes2_set1(clamp_big(1.0 / r->d.z));
    const Lanes2 tn0 = lanes2_set1(r->tmin), tf0 = lanes2_set1(tf);
    unsigned met = 0;
    /* unrolled (GCC's and Clang's pragma; 8 is DIRECT_PAIRS at the default ACCEL_DIRECT_MAX): each pair's bits
     * are shifted by a constant and the loop's own counting goes, some 4 instructions a pair */
#pragma GCC unroll 8
    for (int p = 0; 2 * p < n; p++) {
        const DirectPair *b = &d->pair[p];
        Lanes2 ax = lanes2_mul(lanes2_sub(b->lo[0], ox), ix), bx = lanes2_mul(lanes2_sub(b->hi[0], ox), ix);
        Lanes2 ay = lanes2_mul(lanes2_sub(b->lo[1], oy), iy), by = lanes2_mul(lanes2_sub(b->hi[1], oy), iy);
        Lanes2 az = lanes2_mul(lanes2_sub(b->lo[2], oz), iz), bz = lanes2_mul(lanes2_sub(b->hi[2], oz), iz);
        /* lanes2_max(a, t) is a > t ? a : t and lanes2_min(a, t) is a < t ? a : t: a NaN tf stays */
        Lanes2 tn = lanes2_max(lanes2_min(ax, bx), tn0), tf_ = lanes2_min(lanes2_max(ax, bx), tf0);
        tn = lanes2_max(lanes2_min(ay, by), tn);
        tf_ = lanes2_min(lanes2_max(ay, by), tf_);
        tn = lanes2_max(lanes2_min(az, bz), tn);
        tf_ = lanes2_min(lanes2_max(az, bz), tf_);
        lanes2_store(near + 2 * p, tn);
        met |= lanes2_le(tn, tf_) << (2 * p);
    }
    return met & ((1u << n) - 1u);
}

/* r against e's shape within (r->tmin, tmax): shape_intersect in the shape's own space, with an untransformed
 * sphere or plane intersected inline (the same arithmetic, so the same t). */
static inline int entry_hit(const DirectEntry *e, const Ray *r, double tmax, double *t, int *surface)
{
    const Object *o = e->obj;
    if (e->plain == SHAPE_SPHERE) {
        *surface = 0;
        return shape_hit_sphere(o, r->o, r->d, r->tmin, tmax, t);
    }
    if (e->plain == SHAPE_PLANE) {
        *surface = 0;
        return shape_hit_plane(o, r->o, r->d, r->tmin, tmax, t);
    }
    if (!o->has_xf)
        return shape_intersect(o, r->o, r->d, r->tmin, tmax, t, surface);
    return shape_intersect(o, xform_inv_point(&o->xf, r->o), xform_inv_vector(&o->xf, r->d), r->tmin, tmax, t,
                           surface);
}

/* Not inlined (nor accel_direct_occluded) into accel.c's entry points: inlined, they cost the Embree path of
 * a large scene some 9 instructions a ray in its prologue (10,000 spheres: +0.2% of the process). */
__attribute__((noinline)) int accel_direct_intersect(const Scene *s, const Ray *r, Hit *h)
{
    double best = r->tmax < 3.0e38 ? r->tmax : INFINITY; /* as Embree's tfar (make_ray in accel.c) */
    double near[2 * DIRECT_PAIRS];
    unsigned met = boxes_met(s->direct, s->ndirect, r, best, near);
    const DirectEntry *hit = NULL;
    int hit_surface = 0;
    while (met) {
        int i = __builtin_ctz(met);
        met &= met - 1u;
        if (!(near[i] <= best)) /* the box lies beyond the closest hit so far */
            continue;
        const DirectEntry *e = &s->direct->e[i];
        double t;
        int surface;
        if (entry_hit(e, r, best, &t, &surface)) {
            best = t;
            hit = e;
            hit_surface = surface;
        }
    }
    if (!hit)
        return 0;
    h->obj = hit->obj;
    h->inst = NULL;
    h->material = hit->obj->material;
    h->prim = 0;
    h->t = best;
    h->bu = h->bv = 0.0;
    h->surface = hit_surface;
    return 1;
}

__attribute__((noinline)) int accel_direct_occluded(const Scene *s, const Ray *r)
{
    double near[2 * DIRECT_PAIRS];
    unsigned met = boxes_met(s->direct, s->ndirect, r, r->tmax, near);
    int passable = 0;
    while (met) {
        const DirectEntry *e = &s->direct->e[__builtin_ctz(met)];
        met &= met - 1u;
        double t;
        int surface;
        if (!entry_hit(e, r, r->tmax, &t, &surface))
            continue;
        if (e->opaque)
            return OCCLUDED_OPAQUE;
        passable = 1;
        if (!e->opaque_later)
            break;
    }
    return passable ? OCCLUDED_PASSABLE : OCCLUDED_CLEAR;
}
