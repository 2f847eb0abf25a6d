/* path.h - unidirectional path tracing (path.c): `gtrace --integrator path`. */
#ifndef GTRACE_PATH_H
#define GTRACE_PATH_H

#include "trace/trace.h"

#include <generic/color.h>

#include <stdint.h>

/** Bounces after which Russian roulette may end a path. */
#define PATH_RR_START 3

/** Radiance arriving along the camera ray r, estimated by one path: next-event estimation to every light
 * combined with material sampling by multiple importance sampling, Russian roulette, at most c->max_depth
 * bounces. The path's random numbers come from a generator seeded by the pixel's index and the sample's
 * index, so the image does not depend on the thread count or the order of the tiles. out must have storage. */
int path_trace(TraceCtx *c, const Ray *r, const Media *media, uint64_t pixel, int sample, GColor *out);

/** The distance along r to area light l (a sphere, or a rectangle seen from its lit side) within (0, tmax),
 * INFINITY when missed or for another kind of light; *pdf is the density (solid angle) with which the path
 * tracer's light sample from r->o draws that direction. Camera rays and rays after ideal bounces see these lights
 * whether or not they are marked visible. */
double area_light_hit(const Light *l, const Ray *r, double tmax, double *pdf);

/** Draws a direction towards the sphere or rectangle light l from x with c's generator: 1 with the direction, the
 * distance, the density in solid angle and the radiance L (storage given); 0 when the light offers none (another
 * kind, x inside it); or a status. */
int path_light_sample(TraceCtx *c, const Light *l, GVec3 x, GVec3 *in, double *dist, double *pdf, GColor *L);

#endif
