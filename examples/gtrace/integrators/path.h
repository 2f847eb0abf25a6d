/* path.h - unidirectional path tracing (path.c): `gtrace --integrator path`. */
#ifndef GTRACE_PATH_H
#define GTRACE_PATH_H

#include "lights/area_light.h"
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

#endif
