/* equiangular.h - equiangular sampling of a distance along a ray towards a point (equiangular.c; Kulla and Fajardo
 * 2012, "Importance sampling techniques for path tracing in participating media"): the density of t is proportional
 * to 1 / (D^2 + (t - delta)^2), the inverse square of the distance to the point, so single scattering from a point
 * light is sampled where it is strong, next to the light, instead of where the medium's free flight puts it. */
#ifndef GTRACE_EQUIANGULAR_H
#define GTRACE_EQUIANGULAR_H

#include <generic/vec.h>

/** The set-up of one ray and one point: delta, the distance along the ray to the point's foot; dist, the point's
 * distance from the ray's line; theta_a and theta_b, the angles (seen from the point, from the foot) of the ends
 * of the interval. */
typedef struct Equiangular {
    double delta, dist, theta_a, theta_b;
} Equiangular;

/** Sets e up for t in (0, tmax) along o + t d (d a unit vector; tmax may be INFINITY) towards the point c: 1, or 0
 * when the point lies on the ray's line (within 1e-9 of the distances involved; the density would be singular) or
 * the interval is empty. */
int equiangular_setup(Equiangular *e, GVec3 o, GVec3 d, double tmax, GVec3 c);
/** A distance drawn with the uniform number u in [0, 1), and its density into *pdf. */
double equiangular_sample(const Equiangular *e, double u, double *pdf);
/** The density of the distance t (0 outside the interval). */
double equiangular_pdf(const Equiangular *e, double t);

#endif
