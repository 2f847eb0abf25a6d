/* emissive.h - glowing geometry as light (emissive.c): every object of the top-level scene whose material emits
 * becomes a set of primitives that next-event estimation samples, each chosen with a probability proportional to
 * its power through an alias table (constant time whatever their number). */
#ifndef GTRACE_EMISSIVE_H
#define GTRACE_EMISSIVE_H

#include "lighting.h"
#include "trace/trace.h"

#include <generic/color.h>
#include <generic/error.h>
#include <generic/vec.h>

/** The emissive primitives of a scene and their alias table (opaque). */
typedef struct EmissiveSet EmissiveSet;

/** Light samples the Whitted tracer takes from the emissive set at each shading point. */
#define EMISSIVE_WHITTED_SAMPLES 16

/** Collects the emissive primitives of s: the spheres (untransformed or moved by a rotation, a uniform scale and a
 * translation), discs, quads, triangles and mesh triangles of the top-level scene (not the parts of groups and
 * instances) whose material's emission, asked at the primitive's centre on both sides, is not black. Their power
 * (area times the brightness of that emission) sets the probability of choosing each. c is a tracing context of s
 * (its scratch arena and temporaries serve the emission's surface points). *out is NULL when the scene has none
 * (then nothing changes for the integrators); G_ERR_NOMEM when the tables cannot be had. */
int emissive_build(const Scene *s, TraceCtx *c, EmissiveSet **out, GError *err);
/** Frees the set (NULL: no-op). */
void emissive_free(EmissiveSet *e);
/** The number of primitives of the set (0 for NULL). */
int emissive_count(const EmissiveSet *e);
/** Draws a point of the set as seen from x with three uniform numbers: 1 with the unit direction `in` towards it,
 * its distance, the unit normal of its primitive there (of either side), the density of that direction in solid
 * angle (the choice of the primitive included) and the radiance the material emits towards x there in L; 0 when the
 * draw offers no light (the point lies behind its primitive's plane as seen from x is still drawn: its emission
 * decides); or a status. */
int emissive_sample(TraceCtx *c, const EmissiveSet *e, GVec3 x, double u0, double u1, double u2, GVec3 *in,
                    double *dist, GVec3 *normal, double *pdf, GColor *L);
/** The length of the shadow ray towards a point emissive_sample drew from x (in, dist, normal as it gave them) that
 * ends before the glowing surface (trace.h's shadow_reach): the ray leaves from x offset along facing as sample_light's
 * and light_transmit's do (offset_origin; a point in a medium: facing = in, as light_transmit's walk leaves it). */
double emissive_shadow_reach(GVec3 x, GVec3 facing, GVec3 in, double dist, GVec3 normal);
/** The density in solid angle with which emissive_sample from x draws direction dir that meets the hit h at
 * distance t: 0 when h's primitive is not in the set. */
double emissive_pdf(const EmissiveSet *e, const Hit *h, GVec3 x, GVec3 dir, double t);

/** The guide to the power the set sends into the scene: pi times the sum over its primitives of their area
 * times the brightness of their emission at the centre (both sides of a flat one); 0 for NULL. */
double emissive_power(const EmissiveSet *e);
/** One particle leaving the set, for the particle integrators, from u[0..4] in [0, 1): a primitive chosen by
 * power, a point uniform on its area, a side (flat kinds: either, each with probability 1/2), a direction
 * distributed by the cosine about that side's normal; its origin and unit direction, and into power (a colour of
 * the scene's model) the radiance the material emits along it over the density of that point and direction
 * (black when it emits nothing that way). G_OK or a status of the emission. */
int emissive_emit(TraceCtx *c, const EmissiveSet *e, const double u[5], GVec3 *origin, GVec3 *dir, GColor *power);

/** The Whitted tracer's light from the set at sp towards out_dir (as light_shade for an area light):
 * EMISSIVE_WHITTED_SAMPLES points drawn with c->rng (the choice of primitive stratified), each through
 * sample_light (t's shadow rule); opaque culls points behind the surface. */
int emissive_shade(TraceCtx *c, const EmissiveSet *e, GSurfPoint *sp, GVec3 facing, const Media *media,
                   GVec3 out_dir, int opaque, LightTmp *t, GColor *result);

#endif
