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
 * bounces. The path's random numbers depend on the pixel's index and the sample's index only, so the image does
 * not depend on the thread count or the order of the tiles: with sampler SAMPLER_SOBOL (trace/sampler.h) each
 * vertex's light sample, material sample, wavelength group and roulette take dimensions of the sample's point in
 * the pixel's scrambled Sobol sequence (the camera's group, dimensions 0 to 3, is the caller's), the rest come from
 * a generator seeded by the two indices; with SAMPLER_INDEPENDENT all of them come from that generator. out must
 * have storage. */
int path_trace(TraceCtx *c, const Ray *r, const Media *media, uint64_t pixel, int sample, int sampler, GColor *out);

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

#endif
