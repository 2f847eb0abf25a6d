/* surfpoint.h - GSurfPoint: the geometry of one surface point, handed to every material method.
 *
 * The renderer fills the geometric fields once per hit (gsurfpoint_init, then the fields); materials
 * and texture nodes read them and cache what they compute for the point: the shading normal (which a
 * material such as a bump node may change) and the generator values of texture nodes, so a sequence of
 * material calls on the same point evaluates each generator once. The public fields come first; the caches are
 * the private member `priv` at the end, reached only through the functions below. A renderer keeps points on its
 * stack; a binding or a test that does not lay the struct out makes one with gsurfpoint_new. */
#ifndef GENERIC_SURFPOINT_H
#define GENERIC_SURFPOINT_H

#include "export.h"
#include "vec.h"
#include "color.h"
#include "error.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct GMaterial GMaterial;

/** Number of texture-node cache slots per surface point. */
#define GSURF_CACHE_SLOTS 16

/** One cached generator result, keyed by the object that computed it (part of GSurfPointPrivate). */
typedef struct GSurfCacheSlot {
    const void *key;
    double value;
    GVec3 gradient;
} GSurfCacheSlot;

/** The caches of a surface point: private. Only the gsurfpoint_* functions below read or write them; they are laid
 * out here so that a renderer can keep a point on its stack, and may change in any release (a program or binding
 * that allocates points with gsurfpoint_new never lays them out). */
typedef struct GSurfPointPrivate {
    unsigned cached_flags;          /* which of the cached values below are set */
    int ncache;                     /* generator values put so far (the first GSURF_CACHE_SLOTS slots are used) */
    GVec3 cached_normal;            /* the shading normal (gsurfpoint_normal) */
    double cached_rel_index;        /* the scalar relative index (gsurfpoint_relative_index) */
    const float *rel_index_values;  /* the storage of the colour gsurfpoint_set_relative_index read */
    uint64_t cache_scope;           /* the coordinates the cached generator values belong to (0: the point's own;
                                       gsurfpoint_cache_enter) */
    GSurfCacheSlot cache[GSURF_CACHE_SLOTS];       /* generator values */
    uint64_t cache_slot_scope[GSURF_CACHE_SLOTS]; /* the scope of each slot */
} GSurfPointPrivate;

/** Everything a material needs to know about the point it is evaluated at: the public fields, then the private
 * caches. */
typedef struct GSurfPoint {
    GVec3 point;            /**< hit point in world space */
    GVec3 object_point;     /**< hit point in the object's own space (for solid textures) */
    GVec3 geometric_normal; /**< unit normal, on the side the incident ray came from */
    GVec3 dpdu, dpdv;       /**< surface tangents along u and v (world space, not normalised) */
    double u, v;            /**< surface parameters for 2D textures */
    int surface;            /**< index of the object's surface (e.g. the face of a box) */
    int entering;           /**< 1 when the incident ray comes from the object's outside */
    double t;               /**< distance the ray travelled in the current medium to reach the point */
    double footprint;       /**< width of the pixel's footprint at the point, world units (0 = unknown) */
    double uv_footprint;    /**< the footprint in (u,v) units, for mip-mapping (0 = unknown) */
    const GMaterial *material; /**< the surface's material (the root of its texture tree) */
    const GMaterial *from;     /**< the medium the incident ray travels in (NULL = vacuum, index 1) */
    const GMaterial *to;       /**< the medium on the other side of the surface */
    const GColorModel *model;  /**< colour model of the computation */
    GScratch *scratch;         /**< per-thread arena for temporaries */
    GVec3 object_dpdu, object_dpdv; /**< tangents along u and v in object space, for the derivatives of solid
                                         textures (zero = unknown: dpdu/dpdv are used, exact when the object's
                                         transform to world space is a translation) */
    double uv_axis1[2], uv_axis2[2]; /**< the pixel footprint as an ellipse in (u,v): its two axes (du, dv), full
                                          widths, for anisotropic filtering (both zero = unknown: uv_footprint,
                                          isotropic, is used) */
    GSurfPointPrivate priv; /**< private: the caches (use the functions below) */
} GSurfPoint;

/** A surface point on the heap, for bindings and programs that do not lay GSurfPoint out: gsurfpoint_init's point
 * with model and scratch (both required; scratch is the arena of the thread that evaluates materials at it), the
 * world and object-space point `point`, the geometric normal `normal` (normalised here), the tangents dpdu and dpdv,
 * (u, v) and the surface index (>= 0); every other public field is as gsurfpoint_init leaves it, and may be set
 * afterwards (material, from, to, t, footprints, entering). NULL with G_ERR_INVALID in err when model or scratch is
 * NULL, a number is not finite, the normal is zero or the surface index negative; G_ERR_NOMEM when out of memory.
 * Free it with gsurfpoint_free. */
GENERIC_API GSurfPoint *gsurfpoint_new(const GColorModel *model, GScratch *scratch, GVec3 point, GVec3 normal,
                                       GVec3 dpdu, GVec3 dpdv, double u, double v, int surface, GError *err);
/** Frees a point made by gsurfpoint_new; NULL is a no-op. */
GENERIC_API void gsurfpoint_free(GSurfPoint *sp);
/** sizeof(GSurfPoint) in the library: what a binding checks its own view of the public fields against. */
GENERIC_API size_t gsurfpoint_size(void);
/** Clears a surface point (all fields zero, caches empty) and sets its model and arena. */
GENERIC_API void gsurfpoint_init(GSurfPoint *sp, const GColorModel *model, GScratch *scratch);
/** Forgets every cached value (call after changing geometric fields of an initialised point). */
GENERIC_API void gsurfpoint_invalidate(GSurfPoint *sp);
/** Shading normal: the material's normal() computed once and cached (the geometric normal without a material,
 * and without a call when the material has GMAT_GEOMETRIC_NORMAL, material.h). */
GENERIC_API GVec3 gsurfpoint_normal(GSurfPoint *sp);
/** Overrides the cached shading normal. */
GENERIC_API void gsurfpoint_set_normal(GSurfPoint *sp, GVec3 n);
/** Scalar relative refraction index n(from) / n(to) (luminance-weighted), computed once and cached: the
 * brightness of the ratio of the two materials' refraction_index colours (1 when that is not positive). */
GENERIC_API double gsurfpoint_relative_index(GSurfPoint *sp);
/** The scalar relative index of the colour ri = n(from) / n(to): its brightness, 1 when that is not positive. What
 * gsurfpoint_relative_index caches, and what a material reads from the rel_index refraction() is handed, so that
 * reflection and refraction see the same eta. */
GENERIC_API double gsurfpoint_scalar_index(const GColor *ri);
/** Makes ri, the colour n(from) / n(to) that a renderer computed for sp (as it hands it to refraction()), sp's
 * relative index, so that gsurfpoint_relative_index gives its scalar without the two refraction_index calls and the
 * division again. The scalar is taken when it is first asked for (by gsurfpoint_relative_index or
 * gsurfpoint_index_of) and cached then: a point at which no method reads it (an opaque material's) costs none. So ri's
 * storage must stay valid, and its values unchanged, while the point is shaded. */
GENERIC_API void gsurfpoint_set_relative_index(GSurfPoint *sp, const GColor *ri);
/** gsurfpoint_set_relative_index with ri's scalar already known: scalar must be gsurfpoint_scalar_index(ri), which
 * a renderer that keeps one colour for many points (the relative index of two media of constant index) takes once,
 * so that no point takes it again. The same rules for ri's storage and values. */
GENERIC_API void gsurfpoint_set_relative_index_scalar(GSurfPoint *sp, const GColor *ri, double scalar);
/** The scalar relative index of ri for a material's refraction at sp: when ri is the colour last given to
 * gsurfpoint_set_relative_index (the same storage), the point's cached value (taken and cached on the first ask);
 * otherwise gsurfpoint_scalar_index(ri). A renderer that sets the relative index from a colour must therefore not
 * change that colour's values while it shades the point (hand another colour to refraction() instead). */
GENERIC_API double gsurfpoint_index_of(const GSurfPoint *sp, const GColor *ri);
/** Looks up a value cached under key; 1 when found (value and gradient copied out, either may be NULL). */
GENERIC_API GENERIC_NODISCARD int gsurfpoint_cache_get(const GSurfPoint *sp, const void *key, double *value,
                                                       GVec3 *gradient);
/** Caches a value under key (the oldest slot is reused when all are taken). */
GENERIC_API void gsurfpoint_cache_put(GSurfPoint *sp, const void *key, double value, GVec3 gradient);
/** Widths of the pixel footprint along u and along v (the extent of the uv_axis ellipse, or uv_footprint for
 * both when the axes are unknown), for filters that are separable in u and v. */
GENERIC_API void gsurfpoint_uv_widths(const GSurfPoint *sp, double *wu, double *wv);
/** For a node that evaluates its subtree at moved coordinates (a transform): makes q, a copy of sp with moved
 * fields, use its own cache scope derived from sp's and `node`. Values the subtree caches on q are then found
 * again on the next call through the same node (after gsurfpoint_cache_return) and never mistaken for values
 * at sp's own coordinates, even when a generator is shared inside and outside the subtree. */
GENERIC_API void gsurfpoint_cache_enter(GSurfPoint *q, const GSurfPoint *sp, const void *node);
/** Hands the generator cache of q (made by gsurfpoint_cache_enter from sp) back to sp after the subtree's call. */
GENERIC_API void gsurfpoint_cache_return(GSurfPoint *sp, const GSurfPoint *q);

#ifdef __cplusplus
}
#endif
#endif
