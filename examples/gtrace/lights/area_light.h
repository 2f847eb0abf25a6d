/* area_light.h - sphere and rectangle lights met by rays and sampled from a point (area_light.c): what the path
 * tracer, the medium vertices and sppm's direct light share. */
#ifndef GTRACE_AREA_LIGHT_H
#define GTRACE_AREA_LIGHT_H

#include "lighting.h"
#include "trace/trace.h"

#include <generic/color.h>

/** The distance along r to area light l (a sphere, or a rectangle seen from its lit side) within (0, tmax),
 * INFINITY when missed or for another kind of light; *pdf is the density (solid angle) with which the path
 * tracer's light sample from r->o draws that direction. Camera rays and rays after ideal bounces see these lights
 * whether or not they are marked visible. */
double area_light_hit(const Light *l, const Ray *r, double tmax, double *pdf);

/** Draws a direction towards the sphere or rectangle light l from x with c's generator: 1 with the direction, the
 * distance, the density in solid angle and the radiance L (storage given); 0 when the light offers none (another
 * kind, x inside it); or a status. */
int path_light_sample(TraceCtx *c, const Light *l, GVec3 x, GVec3 *in, double *dist, double *pdf, GColor *L);
/** path_light_sample with the two numbers u1, u2 in [0, 1) given: the point on the light they map to. */
int path_light_sample_at(const Light *l, GVec3 x, double u1, double u2, GVec3 *in, double *dist, double *pdf,
                         GColor *L);
/** path_light_sample_at without the radiance, which is the light's own colour l->color (a caller that reads it there
 * needs no copy): 1 with the direction, the distance and the density, 0 when the light offers none. */
int path_light_direction_at(const Light *l, GVec3 x, double u1, double u2, GVec3 *in, double *dist, double *pdf);

#endif
