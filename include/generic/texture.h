/* texture.h - the texture generator interface (GGenerator) and its evaluation functions.
 *
 * A texture tree is a tree of materials: its leaves are ordinary materials and its inner nodes
 * (interpolate, select, spline, bump, scale, image, transform; include/generic/nodes.h) implement
 * the whole material interface by delegating to their children. What varies over the surface comes
 * from generators: a generator maps a surface point to a scalar (checker: 0 or 1, noise: [0, 1],
 * surface index: 0, 1, 2, ...) and, for bump mapping, to the gradient of that scalar.
 *
 * Spaces. Every generator instance says which coordinates it is a function of (GGeneratorSpace):
 * (u, v), the object-space point, the world-space point, or nothing. The space decides what the
 * gradient means and what a transform node (nodes.h) changes for it: transform nodes move (u, v)
 * and the object-space point of their subtree; world-space generators ignore them.
 *
 * Caching. Texture nodes evaluate generators through ggenerator_cached_value/ggenerator_cached_gradient,
 * which keep the result in the surface point's cache slots keyed by the generator, so a sequence of
 * material calls on one point (normal, reflection for each light, ambient, ...) evaluates each
 * generator once, also when several nodes share it. Generators that combine other generators
 * (turbulence, CSG) call the uncached ggenerator_value of their inputs.
 *
 * Ownership: generators are reference counted like materials; ggenerator_unref destroys the last
 * reference. Generators are immutable after creation, so one instance may be used by many threads. */
#ifndef GENERIC_TEXTURE_H
#define GENERIC_TEXTURE_H

#include "export.h"
#include <stddef.h>
#include "error.h"
#include "surfpoint.h"
#include "vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the generator vtable. */
#define GGENERATOR_ABI_VERSION 1

/** The coordinates a generator instance is a function of. */
typedef enum GGeneratorSpace {
    GGENERATOR_SPACE_NONE = 0, /**< constant over the surface (or piecewise, e.g. the surface index): gradient 0 */
    GGENERATOR_SPACE_UV,       /**< of (u, v): the gradient is (d/du, d/dv, 0) */
    GGENERATOR_SPACE_OBJECT,   /**< of sp->object_point: the gradient is in object space */
    GGENERATOR_SPACE_WORLD     /**< of sp->point: the gradient is in world space */
} GGeneratorSpace;

typedef struct GGenerator GGenerator;
typedef struct GGeneratorClass GGeneratorClass;

/** A generator instance begins with this header; implementations embed it as their first member. */
struct GGenerator {
    const GGeneratorClass *cls;
    int refcount; /**< owners; see ggenerator_ref/ggenerator_unref */
    int space;    /**< a GGeneratorSpace: what value() reads from the surface point */
};

/** The generator vtable. Required: destroy, value. Optional: gradient (NULL: central differences of
 * value in the instance's space, see ggenerator_gradient). */
struct GGeneratorClass {
    int abi_version;         /**< GGENERATOR_ABI_VERSION */
    const char *name;        /**< type keyword */
    const char *description; /**< one line for listings */
    /** Frees the instance (called when the last reference goes). */
    void (*destroy)(GGenerator *self);
    /** The scalar at the surface point. Must not keep state between calls (threads share instances). */
    double (*value)(const GGenerator *self, GSurfPoint *sp);
    /** The gradient of value in the instance's space (see GGeneratorSpace); a status. */
    int (*gradient)(const GGenerator *self, GSurfPoint *sp, GVec3 *grad);
};

/** Fills the header of a new instance (refcount 1) with its space; G_ERR_VERSION when the class is of
 * another version, G_ERR_INVALID when destroy or value is missing or the space is unknown. */
GENERIC_API GENERIC_NODISCARD int ggenerator_init(GGenerator *g, const GGeneratorClass *cls, GGeneratorSpace space,
                                                  GError *err);
/** Allocates a zeroed generator of `size` bytes (a struct that begins with its GGenerator) of class cls
 * computing in space, into *out: G_ERR_NOMEM "<class>: out of memory", or ggenerator_init's error. Until it
 * is complete, free it with gmem_free. */
GENERIC_API GENERIC_NODISCARD int ggenerator_new(const GGeneratorClass *cls, GGeneratorSpace space, size_t size,
                                                 GGenerator **out, GError *err);
/** The destroy method of the generators that own nothing but their own struct (frees it with gmem_free). */
GENERIC_API void ggenerator_free(GGenerator *self);
/** Adds an owner; returns g. */
GENERIC_API GGenerator *ggenerator_ref(GGenerator *g);
/** Drops an owner and destroys the generator with the last; NULL is a no-op. */
GENERIC_API void ggenerator_unref(GGenerator *g);
/** ggenerator_unref for a void pointer (the registry's destroy hook for generators). */
GENERIC_API void ggenerator_release(void *g);
/** The generator's type keyword. */
GENERIC_API const char *ggenerator_name(const GGenerator *g);

/** The coordinates a generator of space g->space reads: (u, v, 0), sp->object_point or sp->point (object
 * space for GGENERATOR_SPACE_NONE). */
static inline GVec3 ggenerator_coords(const GGenerator *g, const GSurfPoint *sp)
{
    switch (g->space) {
    case GGENERATOR_SPACE_UV: return gvec3(sp->u, sp->v, 0.0);
    case GGENERATOR_SPACE_WORLD: return sp->point;
    default: return sp->object_point;
    }
}
/** A gradient with respect to ggenerator_coords as the generator's gradient method returns it (z dropped for
 * (u, v) generators). */
static inline GVec3 ggenerator_space_gradient(const GGenerator *g, GVec3 d)
{
    if (g->space == GGENERATOR_SPACE_UV)
        d.z = 0.0;
    return d;
}

/** The value at the point, computed now (not cached). */
GENERIC_API double ggenerator_value(const GGenerator *g, GSurfPoint *sp);
/** The gradient at the point in the generator's space, computed now: the class's gradient method, or
 * central differences of value with a step of 1e-4 times max(1, |coordinate|) along u and v or the
 * three axes of the point (the zero vector for GGENERATOR_SPACE_NONE). */
GENERIC_API GENERIC_NODISCARD int ggenerator_gradient(const GGenerator *g, GSurfPoint *sp, GVec3 *grad);
/** The value at the point, computed once per point and then taken from sp's cache (key: g). */
GENERIC_API double ggenerator_cached_value(const GGenerator *g, GSurfPoint *sp);
/** Value and gradient (either pointer may be NULL), computed once per point and then cached. */
GENERIC_API GENERIC_NODISCARD int ggenerator_cached_gradient(const GGenerator *g, GSurfPoint *sp, double *value,
                                                             GVec3 *grad);
/** The derivatives of the generator's value along the surface parameters, dh/du and dh/dv, for bump
 * mapping: the gradient itself for (u, v) generators, its projection on the surface tangents for the
 * others (sp->object_dpdu/object_dpdv for object space, falling back to dpdu/dpdv when those are zero;
 * dpdu/dpdv for world space). Cached through ggenerator_cached_gradient. */
GENERIC_API GENERIC_NODISCARD int ggenerator_surface_derivatives(const GGenerator *g, GSurfPoint *sp, double *dh_du,
                                                                 double *dh_dv);

/** A generator whose value is inner's mapped linearly from [0, 1] onto [lo, hi]: lo (1 - v) + hi v, exactly lo
 * where inner is 0 and exactly hi where it is 1; gradient (hi - lo) times inner's; the space is inner's. What the
 * reader makes of `range LO HI` in any generator's block (the default, 0 1, makes none). Takes its own reference of
 * inner. G_ERR_INVALID naming the parameter `range` when lo or hi is not finite or lo > hi. */
GENERIC_API GENERIC_NODISCARD int ggenerator_range_create(GGenerator *inner, double lo, double hi, GGenerator **out,
                                                          GError *err);
/** The interval a generator's value is declared to take: [lo, hi] of a generator made by ggenerator_range_create,
 * [0, 1] for every other (the convention of the built-in generators; a value outside it is the generator's own). */
GENERIC_API void ggenerator_declared_range(const GGenerator *g, double *lo, double *hi);

#ifdef __cplusplus
}
#endif
#endif
