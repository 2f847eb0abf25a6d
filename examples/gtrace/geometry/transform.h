/* transform.h - affine transforms between an object's own space and world space (transform.c). */
#ifndef GTRACE_TRANSFORM_H
#define GTRACE_TRANSFORM_H

#include <generic/vec.h>

/** world = m * object; inv is the inverse. Rows are x, y, z; column 3 is the translation. */
typedef struct Xform {
    double m[3][4];
    double inv[3][4];
} Xform;

/** The identity. */
void xform_identity(Xform *x);
/** x = x followed by a translation / rotation (degrees about an axis) / scale; return 0 or G_ERR_INVALID
 * for a singular result. */
int xform_translate(Xform *x, GVec3 t);
int xform_rotate(Xform *x, GVec3 axis, double degrees);
int xform_scale(Xform *x, GVec3 s);
/** x = x followed by the affine matrix rows (3x4). */
int xform_matrix(Xform *x, const double rows[3][4]);
/** out = outer after inner (inner applied first); out may not alias. */
void xform_compose(const Xform *outer, const Xform *inner, Xform *out);
/** Points, vectors and normals from object to world space and back. */
GVec3 xform_point(const Xform *x, GVec3 p);
GVec3 xform_vector(const Xform *x, GVec3 v);
GVec3 xform_normal(const Xform *x, GVec3 n);
GVec3 xform_inv_point(const Xform *x, GVec3 p);
GVec3 xform_inv_vector(const Xform *x, GVec3 v);
/** Two unit vectors t1, t2 with t1 x t2 = n (n unit). */
void frame_from_normal(GVec3 n, GVec3 *t1, GVec3 *t2);

#endif
