/* affine.h - 2D and 3D affine maps (textures/affine.c): the moves of transform nodes and of CSG/CPG trees, and
 * the steps texture files write (texture_parse.h). */
#ifndef GENERIC_AFFINE_H
#define GENERIC_AFFINE_H

#include "error.h"
#include "vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A 2D affine map: x' = m[0] x + m[1] y + m[2], y' = m[3] x + m[4] y + m[5]. */
typedef struct GAffine2 {
    double m[6];
} GAffine2;

/** A 3D affine map: row i gives coordinate i: p'_i = m[4i] x + m[4i+1] y + m[4i+2] z + m[4i+3]. */
typedef struct GAffine3 {
    double m[12];
} GAffine3;

/** The identity. */
GAffine2 gaffine2_identity(void);
/** Translation by (tx, ty). */
GAffine2 gaffine2_translate(double tx, double ty);
/** Counter-clockwise rotation by an angle in degrees about the origin. */
GAffine2 gaffine2_rotate(double degrees);
/** Scaling by (sx, sy) about the origin. */
GAffine2 gaffine2_scale(double sx, double sy);
/** The composition a after b: (a * b)(p) = a(b(p)). */
GAffine2 gaffine2_mul(const GAffine2 *a, const GAffine2 *b);
/** The inverse; G_ERR_INVALID (with a message) when the map is singular or not finite. */
int gaffine2_invert(const GAffine2 *a, GAffine2 *inv, GError *err);
/** Applies the map to a point. */
void gaffine2_apply(const GAffine2 *a, double x, double y, double *ox, double *oy);

/** The identity. */
GAffine3 gaffine3_identity(void);
/** Translation by t. */
GAffine3 gaffine3_translate(GVec3 t);
/** Rotation by an angle in degrees about an axis through the origin (right-handed). */
GAffine3 gaffine3_rotate(GVec3 axis, double degrees);
/** Scaling by s about the origin. */
GAffine3 gaffine3_scale(GVec3 s);
/** The composition a after b. */
GAffine3 gaffine3_mul(const GAffine3 *a, const GAffine3 *b);
/** The inverse; G_ERR_INVALID when singular or not finite. */
int gaffine3_invert(const GAffine3 *a, GAffine3 *inv, GError *err);
/** Applies the map to a point. */
GVec3 gaffine3_apply(const GAffine3 *a, GVec3 p);
/** Applies the linear part (no translation) to a direction. */
GVec3 gaffine3_apply_dir(const GAffine3 *a, GVec3 d);

#ifdef __cplusplus
}
#endif
#endif
