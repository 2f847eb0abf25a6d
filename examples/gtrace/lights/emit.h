/* emit.h - light leaving the light sources as particles (emit.c): how much power each light sends into the
 * scene and one ray of it drawn from uniform numbers, for the particle integrators (integrators/photons.h). */
#ifndef GTRACE_EMIT_H
#define GTRACE_EMIT_H

#include "scene/scene.h"

#include <generic/vec.h>

/** The sphere around the scene that a directional light's particles cross: every object whose bounds are finite
 * (planes are left out), or the unit sphere around the origin when there is none. */
typedef struct EmitBounds {
    GVec3 centre;
    double radius;
} EmitBounds;

/** The bounding sphere of s's objects (planes left out). */
void emit_bounds(const Scene *s, EmitBounds *b);
/** 1 when light l sends particles (point, spot, directional, IES, sphere, rectangle, a probe sampled as a whole:
 * `technique reference`); 0 for the others (a probe's basis, ambient). */
int emit_supported(const Light *l);
/** The factor by which l's colour (intensity, irradiance or radiance) is multiplied to give the power it sends into
 * the scene (for choosing among lights by power: 4 pi for a point light, pi R^2 of the bounds for a directional
 * light, pi times the area for an area light, ...); 0 for a light that sends none. */
double emit_power_factor(const Light *l, const EmitBounds *b);
/** The power l sends into the scene, as a brightness: the brightness of its colour times emit_power_factor; for a
 * probe, pi R^2 of the bounds times its radiance's brightness integrated over the sphere. A guide for choosing
 * among lights (0 for a light that sends none). */
double emit_power(const Light *l, const EmitBounds *b);
/** One particle of l from u[0..3] in [0, 1): its origin, unit direction and the factor by which l's colour is
 * multiplied to give its power over the density with which it was drawn (its power when one particle of l is
 * sent); 0 when the draw gave nothing. */
double emit_sample(const Light *l, const EmitBounds *b, const double u[4], GVec3 *origin, GVec3 *dir);
/** One particle of any light emit_supported accepts, from u[0..3] in [0, 1): its origin and unit direction, into
 * *factor what emit_sample returns and into color (a colour of l's model, allocated by the caller) the colour
 * that factor multiplies: l's colour, or for a probe its radiance along the reverse of the drawn direction (a
 * probe's particles cross a disc as wide as the bounds, as a directional light's, from directions drawn by the
 * probe's brightness). G_OK or a status of the colour operations. */
int emit_particle(const Light *l, const EmitBounds *b, const double u[4], GVec3 *origin, GVec3 *dir, double *factor,
                  GColor *color);

#endif
