/* accel.h - ray-scene intersection (accel.c, through Embree 3; the only file that includes Embree). */
#ifndef GTRACE_ACCEL_H
#define GTRACE_ACCEL_H

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "scene.h"

#include <generic/error.h>

/** Builds the Embree scene from the objects (after all are added), for the camera's own width x height x spp;
 * a scene of a few analytic shapes gets the direct list instead, which traces it with no Embree device made
 * (s->rtc stays NULL; unless accel_embree_only). */
int accel_build(Scene *s, GError *err);
/** The same for an image of `samples` camera samples in all (the command line's size and spp): the top-level
 * BVH's build quality depends on the samples per primitive. */
int accel_build_for(Scene *s, double samples, GError *err);
/** Releases Embree objects. */
void accel_release(Scene *s);
/** Closest hit along r; 1 when something was hit. */
int accel_intersect(const Scene *s, const Ray *r, Hit *h);
/** What lies on r between tmin and tmax (accel_occluded). */
typedef enum Occlusion {
    OCCLUDED_CLEAR = 0,    /**< nothing */
    OCCLUDED_OPAQUE = 1,   /**< a surface whose material is opaque everywhere (gmaterial_opaque_everywhere) */
    OCCLUDED_PASSABLE = 2, /**< a surface that may let light through (others may lie behind it) */
} Occlusion;
/** What lies on r between tmin and tmax: nonzero when anything does. */
int accel_occluded(const Scene *s, const Ray *r);
/** 1 when the built scene is traced through the direct list (accel_direct.c) rather than Embree. */
int accel_uses_direct(const Scene *s);

#endif
