/* accel_direct.c - the direct list: a scene of a few analytic shapes, each tested in turn.
 *
 * Embree's per-ray cost (setting up the ray, the context and the traversal, and calling back into the user
 * geometry) exceeds testing every shape when the scene holds only a few analytic ones, so such a scene keeps
 * a flat array of its shapes with each shape's padded world bounds: a ray tests the box of each entry (a
 * slab test against [tmin, closest hit so far]) and intersects only the shapes whose box it meets, in double
 * precision in the shape's own space exactly as Embree's user-geometry callbacks do (accel.c). The hit is
 * therefore the one the Embree path finds, with the same double t, but for two kinds of near ties: Embree
 * narrows its ray to the single-precision t of a hit, so a second shape hit within float rounding (about 6e-8
 * relative) behind the first may be missed by Embree and found here; and of two shapes hit at exactly the same
 * t the first in the scene's order wins here, the first Embree visits there. Likewise a hit within float rounding
 * of the ray's tmax: Embree's tfar is tmax in single precision, the direct list keeps tmax in double.
 * Planes are box-tested like the others (their bounds end at SHAPE_PLANE_EXTENT, as Embree's do).
 *
 * Occlusion: the first opaque-everywhere shape on the segment ends the query (OCCLUDED_OPAQUE); otherwise a
 * shape that may let light through makes it OCCLUDED_PASSABLE (the shadow walk of lights.c decides). Embree
 * ends the query at whichever shape it meets first, so where it says opaque this says opaque too, and where
 * it says passable this may say opaque (the walk would have ended at that opaque surface). */
#include "accel_direct.h"
#include "accel.h"

#include <math.h>

/* The largest scene (in shapes) traced through the direct list: where it stops paying. Measured with callgrind
 * (whole process, millions of instructions, 1 thread, 320x240, depth 8; a checker plane and k lambert spheres
 * on a grid across the view, one point light; the pictures of both paths byte-identical):
 *   shapes (k + 1)   2      3      5      6      7      8      9      17     33     65
 *   Embree         344.3  340.9  338.0  342.7  342.7  342.1  342.5  346.5  347.0  348.8
 *   direct         306.2  310.6  319.8  329.8  335.5  340.5  346.0  391.8  484.5  665.9
 * Each entry costs about 40 instructions a ray for its box test (and a shape test when the box is met): up to
 * 8 shapes that is less than Embree's cost per ray, from 9 on more. */
#ifndef ACCEL_DIRECT_MAX
#define ACCEL_DIRECT_MAX 8
#endif

/* One shape of the direct list. */
typedef struct AccelDirect {
    double b[6]; /* padded world bounds, as Embree gets them (user_bounds in accel.c): lo x y z, hi x y z */
    const Object *obj;
    int opaque;       /* its material blocks all light (gmaterial_opaque_everywhere) */
    int opaque_later; /* an opaque entry follows this one (occlusion stops at a passable one otherwise) */
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
    AccelDirect *d = gmem_calloc(n ? (size_t)n : 1, sizeof *d);
    if (!d)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    int k = 0;
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (o->is_part)
            continue;
        AccelDirect *e = &d[k++];
        GVec3 wlo, whi;
        object_world_bounds(o, &wlo, &whi);
        /* the padding of user_bounds (accel.c): flat shapes and rounding lose no hits */
        double pad = 1e-6 * (1.0 + fmax(fmax(fabs(wlo.x), fabs(whi.x)), fmax(fmax(fabs(wlo.y), fabs(whi.y)),
                                                                          fmax(fabs(wlo.z), fabs(whi.z)))));
        e->b[0] = wlo.x - pad;
        e->b[1] = wlo.y - pad;
        e->b[2] = wlo.z - pad;
        e->b[3] = whi.x + pad;
        e->b[4] = whi.y + pad;
        e->b[5] = whi.z + pad;
        e->obj = o;
        e->opaque = gmaterial_opaque_everywhere(o->material) != 0;
    }
    for (int i = n - 2, later = 0; i >= 0; i--) {
        later |= d[i + 1].opaque;
        d[i].opaque_later = later;
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

/* The ray's origin and reciprocal direction for the slab tests. A zero component's reciprocal is +-1e300
 * rather than infinite, so that no product is 0 * inf (a ray in a box's face plane stays in). */
typedef struct SlabRay {
    double o[3], inv[3];
} SlabRay;

/* x clamped to [-1e300, 1e300] (minsd and maxsd: no call, no branch). */
static inline double clamp_big(double x)
{
    x = x < 1e300 ? x : 1e300;
    return x > -1e300 ? x : -1e300;
}

static inline void slab_ray(const Ray *r, SlabRay *sr)
{
    sr->o[0] = r->o.x;
    sr->o[1] = r->o.y;
    sr->o[2] = r->o.z;
    sr->inv[0] = clamp_big(1.0 / r->d.x);
    sr->inv[1] = clamp_big(1.0 / r->d.y);
    sr->inv[2] = clamp_big(1.0 / r->d.z);
}

/* The parameters at which the ray crosses the two planes of one axis of a box, in order. */
#define SLAB_AXIS(e, sr, i, lo, hi)                                                                               \
    do {                                                                                                           \
        double a_ = ((e)->b[i] - (sr)->o[i]) * (sr)->inv[i], b_ = ((e)->b[(i) + 3] - (sr)->o[i]) * (sr)->inv[i];   \
        lo = a_ < b_ ? a_ : b_;                                                                                    \
        hi = a_ < b_ ? b_ : a_;                                                                                    \
    } while (0)

/* 1 when the ray meets e's box within [tn, tf] (a NaN tf meets nothing). No product is a NaN, so the
 * comparisons below are minsd and maxsd. */
static inline int slab_hit(const AccelDirect *e, const SlabRay *sr, double tn, double tf)
{
    double n0, f0, n1, f1, n2, f2;
    SLAB_AXIS(e, sr, 0, n0, f0);
    SLAB_AXIS(e, sr, 1, n1, f1);
    SLAB_AXIS(e, sr, 2, n2, f2);
    tn = n0 > tn ? n0 : tn;
    tn = n1 > tn ? n1 : tn;
    tn = n2 > tn ? n2 : tn;
    tf = f0 < tf ? f0 : tf;
    tf = f1 < tf ? f1 : tf;
    tf = f2 < tf ? f2 : tf;
    return tn <= tf;
}

/* The ray in o's own space (to_object of accel.c without a placement). */
static void in_object(const Object *o, const Ray *r, GVec3 *ro, GVec3 *rd)
{
    *ro = r->o;
    *rd = r->d;
    if (o->has_xf) {
        *ro = xform_inv_point(&o->xf, *ro);
        *rd = xform_inv_vector(&o->xf, *rd);
    }
}

/* Not inlined (nor accel_direct_occluded) into accel.c's entry points: inlined, they cost the Embree path of
 * a large scene some 9 instructions a ray in its prologue (10,000 spheres: +0.2% of the process). */
__attribute__((noinline)) int accel_direct_intersect(const Scene *s, const Ray *r, Hit *h)
{
    SlabRay sr;
    slab_ray(r, &sr);
    double best = r->tmax < 3.0e38 ? r->tmax : INFINITY; /* as Embree's tfar (make_ray in accel.c) */
    const Object *hit = NULL;
    int hit_surface = 0;
    for (int i = 0; i < s->ndirect; i++) {
        const AccelDirect *e = &s->direct[i];
        if (!slab_hit(e, &sr, r->tmin, best))
            continue;
        GVec3 ro, rd;
        in_object(e->obj, r, &ro, &rd);
        double t;
        int surface;
        if (shape_intersect(e->obj, ro, rd, r->tmin, best, &t, &surface)) {
            best = t;
            hit = e->obj;
            hit_surface = surface;
        }
    }
    if (!hit)
        return 0;
    h->obj = hit;
    h->inst = NULL;
    h->material = hit->material;
    h->prim = 0;
    h->t = best;
    h->bu = h->bv = 0.0;
    h->surface = hit_surface;
    return 1;
}

__attribute__((noinline)) int accel_direct_occluded(const Scene *s, const Ray *r)
{
    SlabRay sr;
    slab_ray(r, &sr);
    int passable = 0;
    for (int i = 0; i < s->ndirect; i++) {
        const AccelDirect *e = &s->direct[i];
        if (!slab_hit(e, &sr, r->tmin, r->tmax))
            continue;
        GVec3 ro, rd;
        in_object(e->obj, r, &ro, &rd);
        double t;
        int surface;
        if (!shape_intersect(e->obj, ro, rd, r->tmin, r->tmax, &t, &surface))
            continue;
        if (e->opaque)
            return OCCLUDED_OPAQUE;
        passable = 1;
        if (!e->opaque_later)
            break;
    }
    return passable ? OCCLUDED_PASSABLE : OCCLUDED_CLEAR;
}
