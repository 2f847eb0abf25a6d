/* ray.h - the tracer's ray. */
#ifndef GTRACE_RAY_H
#define GTRACE_RAY_H

#include <generic/vec.h>

/** A ray in double precision; the cone gives the pixel footprint (width at the origin, spread angle). */
typedef struct Ray {
    GVec3 o, d; /**< d is unit length so t is a distance */
    double tmin, tmax;
    double cone_width, cone_spread;
} Ray;

#endif
