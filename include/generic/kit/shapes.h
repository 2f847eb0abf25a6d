/* shapes.h - the shape trees of the csg and cpg generators (generators.h): solids in 3D (lib/kit/csg_shape.c)
 * and shapes in the (u, v) plane (lib/kit/cpg_shape.c, lib/kit/cpg_path.c), with boolean operations and
 * affine moves. */
#ifndef GENERIC_SHAPES_H
#define GENERIC_SHAPES_H

#include "../export.h"
#include "affine.h"
#include "../error.h"
#include "../vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- CSG: solids in 3D ---- */

/** A CSG tree node (a solid or a combination). Owned by its parent or by the generator it is given to. */
typedef struct GCsgShape GCsgShape;

/** Boolean operations of CSG and CPG trees. */
typedef enum GShapeOp {
    GSHAPE_UNION = 0,
    GSHAPE_INTERSECTION,
    GSHAPE_DIFFERENCE /**< the first minus the second */
} GShapeOp;

/** Deepest CSG or CPG tree (a shape: 1, an operation: 1 + its deepest operand): gcsg_combine and gcpg_combine
 * refuse deeper ones (G_ERR_INVALID "csg: shapes nested more than 256 deep"), so evaluation never recurses
 * deeper. An operation keeps its operands in one list: combining an operation that has no transform of its own
 * with a further operand of the same operation (a union with one more shape, a difference with one more shape to
 * cut away) adds to that list, so a union of a million shapes, built pair by pair, is depth 2. */
#define GSHAPE_MAX_DEPTH 256

/** Sphere of radius r > 0 about the origin. */
GENERIC_API GENERIC_NODISCARD int gcsg_sphere(double radius, GCsgShape **out, GError *err);
/** Axis-aligned box between lo and hi (lo < hi on every axis). */
GENERIC_API GENERIC_NODISCARD int gcsg_box(GVec3 lo, GVec3 hi, GCsgShape **out, GError *err);
/** Closed cylinder of radius r > 0 around the z axis from z0 to z1 > z0. */
GENERIC_API GENERIC_NODISCARD int gcsg_cylinder(double radius, double z0, double z1, GCsgShape **out, GError *err);
/** Closed (truncated) cone around the z axis: radius r0 at z0, r1 at z1 > z0 (r0, r1 >= 0, not both 0). */
GENERIC_API GENERIC_NODISCARD int gcsg_cone(double r0, double z0, double r1, double z1, GCsgShape **out, GError *err);
/** Half-space of the points p with normal . p <= offset (normal not zero; it need not be unit). */
GENERIC_API GENERIC_NODISCARD int gcsg_halfspace(GVec3 normal, double offset, GCsgShape **out, GError *err);
/** Combines two shapes (see GSHAPE_MAX_DEPTH: *out may be a itself, grown by b); takes ownership of a and b,
 * also when it fails. */
GENERIC_API GENERIC_NODISCARD int gcsg_combine(GShapeOp op, GCsgShape *a, GCsgShape *b, GCsgShape **out, GError *err);
/** Moves a shape (and its subtree) by m, after any earlier transform; G_ERR_INVALID for a singular m
 * (the shape is unchanged then). */
GENERIC_API GENERIC_NODISCARD int gcsg_transform(GCsgShape *s, const GAffine3 *m, GError *err);
/** 1 when p is inside or on the boundary, 0 outside. */
GENERIC_API GENERIC_NODISCARD int gcsg_inside(const GCsgShape *s, GVec3 p);
/** Frees a tree (without recursion); NULL is a no-op. */
GENERIC_API void gcsg_destroy(GCsgShape *s);

/* ---- CPG: shapes in the (u, v) plane (textures/cpg_shape.c, textures/cpg_path.c) ---- */

/** A CPG tree node (a 2D shape or a combination). */
typedef struct GCpgShape GCpgShape;
/** A closed contour under construction: edges that follow one another (a gap between the end of one and
 * the start of the next, and between the last and the first, is closed with a straight line). */
typedef struct GCpgPath GCpgPath;

/** Axis-aligned square with centre (cx, cy) and side > 0. */
GENERIC_API GENERIC_NODISCARD int gcpg_square(double cx, double cy, double side, GCpgShape **out, GError *err);
/** Circle with centre (cx, cy) and radius > 0. */
GENERIC_API GENERIC_NODISCARD int gcpg_circle(double cx, double cy, double radius, GCpgShape **out, GError *err);
/** Closed polygon through n >= 3 points xy[2i], xy[2i+1] (any orientation; self-intersecting polygons
 * are filled by the non-zero winding rule). */
GENERIC_API GENERIC_NODISCARD int gcpg_polygon(const double *xy, int n, GCpgShape **out, GError *err);

/** A new empty contour. */
GENERIC_API GENERIC_NODISCARD int gcpg_path_create(GCpgPath **out, GError *err);
/** Straight edges through n >= 1 points. */
GENERIC_API GENERIC_NODISCARD int gcpg_path_lines(GCpgPath *p, const double *xy, int n, GError *err);
/** A Bézier edge of degree 1..GCPG_MAX_DEGREE through its degree + 1 control points. */
GENERIC_API GENERIC_NODISCARD int gcpg_path_bezier(GCpgPath *p, int degree, const double *xy, GError *err);
/** A uniform B-spline edge of degree 1..GCPG_MAX_DEGREE over n > degree control points with knots
 * 0, 1, 2, ...; periodic != 0 closes it smoothly (the control polygon wraps around), otherwise it runs
 * from knot degree to knot n (it does not pass through its end control points). */
GENERIC_API GENERIC_NODISCARD int gcpg_path_bspline(GCpgPath *p, int degree, const double *xy, int n, int periodic,
                                                    GError *err);
/** A NURBS edge of degree 1..GCPG_MAX_DEGREE over n > degree control points with weights > 0 and a
 * non-decreasing knot vector of n + degree + 1 values (NULL: clamped uniform, so the edge runs from the
 * first to the last control point). Zero or negative weights and bad knot vectors are G_ERR_INVALID. */
GENERIC_API GENERIC_NODISCARD int gcpg_path_nurbs(GCpgPath *p, int degree, const double *xy, const double *weights,
                                                  int n, const double *knots, GError *err);
/** Closes the contour into a shape (non-zero winding rule); consumes the path, also when it fails
 * (G_ERR_INVALID for a contour of fewer than 3 distinct points without curved edges, or of no edges). */
GENERIC_API GENERIC_NODISCARD int gcpg_path_close(GCpgPath *p, GCpgShape **out, GError *err);
/** Frees a contour that was not closed; NULL is a no-op. */
GENERIC_API void gcpg_path_destroy(GCpgPath *p);

/** Highest degree of a curved edge. */
#define GCPG_MAX_DEGREE 7

/** Combines two shapes (see GSHAPE_MAX_DEPTH: *out may be a itself, grown by b); takes ownership of a and b,
 * also when it fails. */
GENERIC_API GENERIC_NODISCARD int gcpg_combine(GShapeOp op, GCpgShape *a, GCpgShape *b, GCpgShape **out, GError *err);
/** Moves a shape (and its subtree) by m, after any earlier transform; G_ERR_INVALID for a singular m. */
GENERIC_API GENERIC_NODISCARD int gcpg_transform(GCpgShape *s, const GAffine2 *m, GError *err);
/** 1 when (x, y) is inside, 0 outside (points on an edge may go either way). */
GENERIC_API GENERIC_NODISCARD int gcpg_inside(const GCpgShape *s, double x, double y);
/** Frees a tree (without recursion); NULL is a no-op. */
GENERIC_API void gcpg_destroy(GCpgShape *s);

#ifdef __cplusplus
}
#endif
#endif
