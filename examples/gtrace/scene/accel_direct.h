/* accel_direct.h - the direct list (accel_direct.c): a scene of a few analytic shapes traced by testing each
 * shape in turn, without Embree; accel.c builds it and sends rays to it when it exists. */
#ifndef GTRACE_ACCEL_DIRECT_H
#define GTRACE_ACCEL_DIRECT_H

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "scene.h"

#include <generic/error.h>

/** The most shapes a scene traced through the direct list may have (measured: accel_direct.c). */
#define ACCEL_DIRECT_MAX 16

/** Builds s->direct when the top-level scene is only analytic shapes (spheres, planes, boxes, discs, cylinders;
 * no meshes, quads, triangles, groups or instances), at most ACCEL_DIRECT_MAX of them, and
 * s->accel_embree_only is not set; otherwise leaves it NULL. */
int accel_direct_build(Scene *s, GError *err);
/** Frees the direct list (none: no-op). */
void accel_direct_release(Scene *s);
/** Closest hit along a traceable r through the direct list; 1 when something was hit (Hit as accel_intersect). */
int accel_direct_intersect(const Scene *s, const Ray *r, Hit *h);
/** The Occlusion of a traceable r through the direct list (as accel_occluded). */
int accel_direct_occluded(const Scene *s, const Ray *r);

#endif
