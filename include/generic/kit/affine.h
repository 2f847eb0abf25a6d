/* affine.h - 2D and 3D affine maps (textures/affine.c): the moves of transform nodes and of CSG/CPG trees, and
 * the steps texture files write (texture_parse.h). */
#ifndef GENERIC_AFFINE_H
#define GENERIC_AFFINE_H

#include "../export.h"
#include "../error.h"
#include "../vec.h"

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
GENERIC_API GAffine2 gaffine2_identity(void);
/** Translation by (tx, ty). */
GENERIC_API GAffine2 gaffine2_translate(double tx, double ty);
/** Counter-clockwise rotation by an angle in degrees about the origin. */
GENERIC_API GAffine2 gaffine2_rotate(double degrees);
/** Scaling by (sx, sy) about the origin. */
GENERIC_API GAffine2 gaffine2_scale(double sx, double sy);
/** The composition a after b: (a * b)(p) = a(b(p)). */
GENERIC_API GAffine2 gaffine2_mul(const GAffine2 *a, const GAffine2 *b);
/** The inverse; G_ERR_INVALID (with a message) when the map is singular or not finite. */
GENERIC_API GENERIC_NODISCARD int gaffine2_invert(const GAffine2 *a, GAffine2 *inv, GError *err);
/** Applies the map to a point. */
GENERIC_API void gaffine2_apply(const GAffine2 *a, double x, double y, double *ox, double *oy);

/** The identity. */
GENERIC_API GAffine3 gaffine3_identity(void);
/** Translation by t. */
GENERIC_API GAffine3 gaffine3_translate(GVec3 t);
/** Rotation by an angle in degrees about an axis through the origin (right-handed). */
GENERIC_API GAffine3 gaffine3_rotate(GVec3 axis, double degrees);
/** Scaling by s about the origin. */
GENERIC_API GAffine3 gaffine3_scale(GVec3 s);
/** The composition a after b. */
GENERIC_API GAffine3 gaffine3_mul(const GAffine3 *a, const GAffine3 *b);
/** The inverse; G_ERR_INVALID when singular or not finite. */
GENERIC_API GENERIC_NODISCARD int gaffine3_invert(const GAffine3 *a, GAffine3 *inv, GError *err);
/** Applies the map to a point. */
GENERIC_API GVec3 gaffine3_apply(const GAffine3 *a, GVec3 p);
/** Applies the linear part (no translation) to a direction. */
GENERIC_API GVec3 gaffine3_apply_dir(const GAffine3 *a, GVec3 d);

#ifdef __cplusplus
}
#endif
#endif
