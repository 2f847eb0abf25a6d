/* vec.h - small 3D vector type used by the material and surface point interfaces. */
#ifndef GENERIC_VEC_H
#define GENERIC_VEC_H

#include <math.h>

/** A 3D vector or point in double precision. */
typedef struct GVec3 {
    double x, y, z;
} GVec3;

/** The larger of a and b as C's fmax gives it (the other operand when one is NaN; b when they compare equal),
 * inline: without -ffinite-math-only compilers call libm's fmax, which costs a call on hot paths. */
static inline double gfmax(double a, double b) { return a > b || b != b ? a : b; }
/** The smaller of a and b as C's fmin gives it (the other operand when one is NaN; b when they compare equal),
 * inline. */
static inline double gfmin(double a, double b) { return a < b || b != b ? a : b; }

/** Makes a vector. */
static inline GVec3 gvec3(double x, double y, double z) { GVec3 r = {x, y, z}; return r; }
/** a + b */
static inline GVec3 gvec3_add(GVec3 a, GVec3 b) { return gvec3(a.x + b.x, a.y + b.y, a.z + b.z); }
/** a - b */
static inline GVec3 gvec3_sub(GVec3 a, GVec3 b) { return gvec3(a.x - b.x, a.y - b.y, a.z - b.z); }
/** a * s */
static inline GVec3 gvec3_scale(GVec3 a, double s) { return gvec3(a.x * s, a.y * s, a.z * s); }
/** -a */
static inline GVec3 gvec3_neg(GVec3 a) { return gvec3(-a.x, -a.y, -a.z); }
/** a + b * s */
static inline GVec3 gvec3_madd(GVec3 a, GVec3 b, double s)
{
    return gvec3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}
/** Dot product. */
static inline double gvec3_dot(GVec3 a, GVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/** Cross product. */
static inline GVec3 gvec3_cross(GVec3 a, GVec3 b)
{
    return gvec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/** Euclidean length. */
static inline double gvec3_length(GVec3 a) { return sqrt(gvec3_dot(a, a)); }
/** a / |a|; the zero vector stays zero. */
static inline GVec3 gvec3_normalize(GVec3 a)
{
    double l = gvec3_length(a);
    return l > 0.0 ? gvec3_scale(a, 1.0 / l) : a;
}
/** Linear blend a + (b - a) t. */
static inline GVec3 gvec3_lerp(GVec3 a, GVec3 b, double t)
{
    return gvec3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}
/** Mirror of d about n: d - 2 (d.n) n (d points towards the surface, the result away from it). */
static inline GVec3 gvec3_reflect(GVec3 d, GVec3 n) { return gvec3_madd(d, n, -2.0 * gvec3_dot(d, n)); }

#endif
