/* textures.h - constructors of the built-in texture nodes and generators (the files in textures/).
 *
 * Nodes are materials (GMaterial): every method of the material interface is implemented by calling the
 * children, so a tree stands wherever a material does. Node constructors take their own references to
 * the children and generators they are given (the caller keeps its own), check that all children compute
 * in one colour model (G_ERR_MISMATCH otherwise) and return a node with one reference (gmaterial_unref).
 * Generator constructors return a generator with one reference (ggenerator_unref).
 *
 * Nodes evaluate their generators once per surface point (ggenerator_cached_value, texture.h). Their
 * temporaries live on sp->scratch; nothing is allocated per call. Methods that may be called without a
 * surface point (refraction_index and absorption with sp == NULL) use the first child.
 *
 * Renderers set sp->material to the root of the tree: leaves take the shading normal from
 * gsurfpoint_normal(sp), which asks the root, so a bump node anywhere in the tree reaches them. */
#ifndef GENERIC_TEXTURES_H
#define GENERIC_TEXTURES_H

#include "color.h"
#include "material.h"
#include "texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================================================
 * Affine transforms (textures/affine.c)
 * ====================================================================================================== */

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

/* ======================================================================================================
 * Nodes
 * ====================================================================================================== */

/** The methods of the material interface, for nodes that treat one of them specially. */
typedef enum GNodeMethod {
    GNODE_REFLECTION = 0,
    GNODE_REFRACTION,
    GNODE_REFRACTION_INDEX,
    GNODE_REFLECTION_DIR,
    GNODE_REFRACTION_DIR,
    GNODE_EMISSION,
    GNODE_AMBIENT,
    GNODE_ABSORPTION,
    GNODE_NORMAL,
    GNODE_DIFFUSE,
    GNODE_OPAQUE,
    GNODE_METHOD_COUNT
} GNodeMethod;

/** The method's keyword ("reflection", "refraction_index", ...); "?" when out of range. */
const char *gnode_method_name(GNodeMethod m);
/** The method of a keyword; -1 when unknown. */
int gnode_method_from_name(const char *name);

/** interpolate: child a where the generator gives t <= 0, child b where t >= 1, and in between every
 * method blends the two results linearly ((1 - t) a + t b):
 *   - colours (reflection, refraction, refraction_index, emission, ambient, absorption, diffuse) blend
 *     as colours (gcolor_scale / gcolor_add_scaled);
 *   - normal: the two normals blended and normalised;
 *   - reflection_dir / refraction_dir: valid when either child's is; two valid directions are blended and
 *     normalised, a single valid one is returned as it is (its child's weight already scales the colour
 *     the renderer gets back from reflection/refraction along it);
 *   - opaque: opaque only when both children are (so the renderer traces refraction whenever either
 *     child transmits light).
 * At t = 0 and t = 1 exactly one child is called (the paper's integer fast path). t is clamped to [0, 1]
 * and taken from the generator once per surface point. */
int gnode_interpolate_create(GMaterial *a, GMaterial *b, GGenerator *t, GMaterial **out, GError *err);

/** interpolate-one: blends the single method `method` like interpolate and takes every other method from
 * child a (e.g. a spatially varying refraction index in hand-made glass). */
int gnode_interpolate_one_create(GMaterial *a, GMaterial *b, GGenerator *t, GNodeMethod method, GMaterial **out,
                                 GError *err);

/** select: n >= 1 children; the generator's value, rounded down and clamped to [0, n - 1], picks the child
 * that answers every method (e.g. the surface index picks a material per face of a cube). */
int gnode_select_create(GMaterial *const *children, int n, GGenerator *index, GMaterial **out, GError *err);

/** Spline bases for the spline node. */
typedef enum GSplineBasis {
    GSPLINE_CATMULL_ROM = 0, /**< interpolating cubic: child i at t = i / (n - 1); weights may be negative
                                  (overshoot between very different children, as in Perlin's colour splines) */
    GSPLINE_BSPLINE,         /**< uniform cubic B-spline: smooth, weights in [0, 1] (no overshoot), approximating */
    GSPLINE_LINEAR           /**< piecewise linear between neighbouring children */
} GSplineBasis;

/** spline: n >= 2 children at t = i / (n - 1) blended by a cubic spline over the generator value t
 * (clamped to [0, 1]; the end children repeat past the ends). At most four children are evaluated per
 * call, and only one where t hits a child's knot (Catmull-Rom, linear). Blending as in interpolate. */
int gnode_spline_create(GMaterial *const *children, int n, GGenerator *t, GSplineBasis basis, GMaterial **out,
                        GError *err);

/** bump: Blinn's bump mapping. The generator is a height field h; the surface is displaced by
 * strength * h along its normal, and the normal method returns the normal of the displaced surface:
 *   N' = |Pu x Pv| n + s (h_u (n x Pv) + h_v (Pu x n)),  normalised,
 * with n the child's normal (oriented to the outside, i.e. flipped when !sp->entering, and flipped back),
 * Pu, Pv = sp->dpdu, sp->dpdv and h_u, h_v from ggenerator_surface_derivatives. On a plane with unit
 * tangents and h = k u, the normal tilts by atan(strength * k). When the tangents are zero or parallel an
 * arbitrary orthonormal frame around n is used. Every other method is the child's. */
int gnode_bump_create(GMaterial *child, GGenerator *height, double strength, GMaterial **out, GError *err);

/** scale: the child's colour results that carry light (reflection, refraction, emission, ambient, diffuse)
 * multiplied by the generator's value (e.g. noise as dirt); refraction_index, absorption, directions,
 * normal and opaque are the child's. */
int gnode_scale_create(GMaterial *child, GGenerator *factor, GMaterial **out, GError *err);

/** transform: the subtree sees its texture coordinates moved: the pattern it generates is moved by
 * `uv` in the (u, v) plane and by `xyz` in object space (either may be NULL for none). A subtree that
 * gives pattern f(u, v) gives f(uv^-1 (u, v)) below the node; translate 0.5 0 moves a checker's edges
 * by +0.5 in u. The node evaluates the child on a copy of the surface point with u, v, dpdu, dpdv,
 * uv_footprint (for uv) and object_point, object_dpdu, object_dpdv (for xyz) transformed; the copy
 * starts with empty generator caches, since values cached above were computed at other coordinates, so
 * generators below a transform are evaluated once per method call on it. The copy keeps the shading
 * normal computed for the original point (the normal is a world-space quantity). World-space
 * generators and the world point are not moved. */
int gnode_transform_create(GMaterial *child, const GAffine2 *uv, const GAffine3 *xyz, GMaterial **out,
                           GError *err);

/* ---- images ---- */

/** A texture system: OpenImageIO's TextureSystem with its tile cache, shared by the image nodes of a scene.
 * Thread safe; reference counted. */
typedef struct GTextureSystem GTextureSystem;

/** Creates a texture system (MIP maps made on the fly for files that have none). */
int gtexsys_create(GTextureSystem **out, GError *err);
/** Adds an owner; returns ts. */
GTextureSystem *gtexsys_ref(GTextureSystem *ts);
/** Drops an owner; the last frees the system and its cache. NULL is a no-op. */
void gtexsys_unref(GTextureSystem *ts);
/** The process's default texture system, created on first use and freed when its last owner lets go;
 * returns a new reference (or NULL with err filled). Image nodes created without a system use it. */
GTextureSystem *gtexsys_default(GError *err);

/** How lookups outside [0, 1] behave. */
typedef enum GTexWrap {
    GTEX_WRAP_PERIODIC = 0, /**< repeat */
    GTEX_WRAP_CLAMP,        /**< the edge texels continue */
    GTEX_WRAP_BLACK,        /**< black outside */
    GTEX_WRAP_MIRROR        /**< repeat mirrored */
} GTexWrap;

/** How stored values relate to linear values. */
typedef enum GTexColorSpace {
    GTEX_COLORSPACE_AUTO = 0, /**< sRGB for 8- and 16-bit files that say sRGB (PNG, JPEG), linear otherwise */
    GTEX_COLORSPACE_SRGB,     /**< decode the sRGB curve */
    GTEX_COLORSPACE_LINEAR    /**< values are linear */
} GTexColorSpace;

/** Options of an image node; a zeroed struct takes the defaults. */
typedef struct GImageNodeOptions {
    GTextureSystem *texsys; /**< NULL: gtexsys_default() */
    GTexWrap swrap, twrap;  /**< along u and v (default periodic) */
    GTexColorSpace colorspace;
    double blur;            /**< extra filter width in (u, v) units, >= 0 */
} GImageNodeOptions;

/** image: the child's colour results that carry light (as for scale) multiplied by the image's colour at
 * (u, v) (u to the right, v up: v = 0 is the image's bottom row), read as a reflectance into the child's
 * model. Lookups are MIP-mapped over the pixel footprint: anisotropically over the ellipse sp->uv_axis1/2
 * when the renderer gives it, else with the isotropic width sp->uv_footprint (0: the finest level, bilinear). The file is opened (and checked) here: a missing or unreadable file is G_ERR_IO naming it.
 * sRGB-encoded files are decoded after filtering. Grey images give grey colours; alpha is ignored. */
int gnode_image_create(GMaterial *child, const char *path, const GImageNodeOptions *opt, GMaterial **out,
                       GError *err);

/* ======================================================================================================
 * Generators
 * ====================================================================================================== */

/** constant: the same value everywhere. */
int ggen_constant_create(double value, GGenerator **out, GError *err);

/** checker: 1 on the cells of a checkerboard whose cell index sum is odd, 0 on the others; dims 2 in
 * (u, v), dims 3 in object space; `frequency` cells per unit (> 0). Box-filtered over the footprint
 * when it is known (in (u, v) the widths of gsurfpoint_uv_widths, separately along u and v; in object space
 * footprint), so far-away checkers fade to 0.5 instead of aliasing. */
int ggen_checker_create(int dims, double frequency, GGenerator **out, GError *err);

/** Parameters shared by the noise generators; zero fields take the defaults. */
typedef struct GNoiseParams {
    GGeneratorSpace space; /**< NONE (0) means object space */
    double frequency;      /**< features per unit (default 1) */
    unsigned seed;         /**< picks the permutation (default 0: the same noise in every run) */
    int octaves;           /**< fbm, turbulence, wood, marble (default 4 for wood/marble/fbm/turbulence) */
    double lacunarity;     /**< frequency factor per octave (default 2) */
    double gain;           /**< amplitude factor per octave (default 0.5) */
} GNoiseParams;

/** The improved gradient noise of Perlin (2002) mapped to [0, 1] as (1 + n) / 2; 0.5 at every lattice point.
 * The gradient is analytic. */
double gnoise_perlin3(unsigned seed, double x, double y, double z, GVec3 *grad);

/** perlin: improved Perlin noise (gnoise_perlin3) of the point in the chosen space times frequency. */
int ggen_perlin_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** fbm: fractional Brownian motion, sum of octaves of signed noise, normalised by the sum of amplitudes
 * and mapped to [0, 1]. */
int ggen_fbm_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** turbulence: Perlin's sum of |noise| over octaves, normalised to [0, 1]. */
int ggen_turbulence_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** wood: rings around the space's z axis, `rings` per unit of radius, displaced by `turbulence` rings of
 * fbm; within a ring the value rises smoothly from 0 (early wood) to 1 and falls back over the last
 * `latewood` fraction of the ring (0 < latewood < 1; 0 = default 0.2). Continuous everywhere. */
int ggen_wood_create(const GNoiseParams *p, double rings, double turbulence, double latewood, GGenerator **out,
                     GError *err);
/** marble: 0.5 + 0.5 sin(2 pi (stripes * x + turbulence * T(p))), T Perlin's turbulence: veins across x. */
int ggen_marble_create(const GNoiseParams *p, double stripes, double turbulence, GGenerator **out, GError *err);

/** surface: the surface index of the point (sp->surface), for select nodes. */
int ggen_surface_create(GGenerator **out, GError *err);

/** gradient: a linear field offset + slope . c, c = (u, v, 0) or the point in object or world space; its
 * gradient is slope (a height field for bump nodes, or a ramp for interpolate). */
int ggen_gradient_create(GGeneratorSpace space, GVec3 slope, double offset, GGenerator **out, GError *err);

/* ---- CSG: solids in 3D (textures/csg.c) ---- */

/** A CSG tree node (a solid or a combination). Owned by its parent or by the generator it is given to. */
typedef struct GCsgShape GCsgShape;

/** Boolean operations of CSG and CPG trees. */
typedef enum GShapeOp {
    GSHAPE_UNION = 0,
    GSHAPE_INTERSECTION,
    GSHAPE_DIFFERENCE /**< the first minus the second */
} GShapeOp;

/** Sphere of radius r > 0 about the origin. */
int gcsg_sphere(double radius, GCsgShape **out, GError *err);
/** Axis-aligned box between lo and hi (lo < hi on every axis). */
int gcsg_box(GVec3 lo, GVec3 hi, GCsgShape **out, GError *err);
/** Closed cylinder of radius r > 0 around the z axis from z0 to z1 > z0. */
int gcsg_cylinder(double radius, double z0, double z1, GCsgShape **out, GError *err);
/** Closed (truncated) cone around the z axis: radius r0 at z0, r1 at z1 > z0 (r0, r1 >= 0, not both 0). */
int gcsg_cone(double r0, double z0, double r1, double z1, GCsgShape **out, GError *err);
/** Half-space of the points p with normal . p <= offset (normal not zero; it need not be unit). */
int gcsg_halfspace(GVec3 normal, double offset, GCsgShape **out, GError *err);
/** Combines two shapes; takes ownership of a and b, also when it fails. */
int gcsg_combine(GShapeOp op, GCsgShape *a, GCsgShape *b, GCsgShape **out, GError *err);
/** Moves a shape (and its subtree) by m, after any earlier transform; G_ERR_INVALID for a singular m
 * (the shape is unchanged then). */
int gcsg_transform(GCsgShape *s, const GAffine3 *m, GError *err);
/** 1 when p is inside or on the boundary, 0 outside. */
int gcsg_inside(const GCsgShape *s, GVec3 p);
/** Frees a tree; NULL is a no-op. */
void gcsg_destroy(GCsgShape *s);
/** csg: 1 inside the solid, 0 outside, at the point in object (or world) space. Takes ownership of the
 * tree, also when it fails. */
int ggen_csg_create(GCsgShape *root, GGeneratorSpace space, GGenerator **out, GError *err);

/* ---- CPG: shapes in the (u, v) plane (textures/cpg.c, textures/cpg_path.c) ---- */

/** A CPG tree node (a 2D shape or a combination). */
typedef struct GCpgShape GCpgShape;
/** A closed contour under construction: edges that follow one another (a gap between the end of one and
 * the start of the next, and between the last and the first, is closed with a straight line). */
typedef struct GCpgPath GCpgPath;

/** Axis-aligned square with centre (cx, cy) and side > 0. */
int gcpg_square(double cx, double cy, double side, GCpgShape **out, GError *err);
/** Circle with centre (cx, cy) and radius > 0. */
int gcpg_circle(double cx, double cy, double radius, GCpgShape **out, GError *err);
/** Closed polygon through n >= 3 points xy[2i], xy[2i+1] (any orientation; self-intersecting polygons
 * are filled by the non-zero winding rule). */
int gcpg_polygon(const double *xy, int n, GCpgShape **out, GError *err);

/** A new empty contour. */
int gcpg_path_create(GCpgPath **out, GError *err);
/** Straight edges through n >= 1 points. */
int gcpg_path_lines(GCpgPath *p, const double *xy, int n, GError *err);
/** A Bézier edge of degree 1..GCPG_MAX_DEGREE through its degree + 1 control points. */
int gcpg_path_bezier(GCpgPath *p, int degree, const double *xy, GError *err);
/** A uniform B-spline edge of degree 1..GCPG_MAX_DEGREE over n > degree control points with knots
 * 0, 1, 2, ...; periodic != 0 closes it smoothly (the control polygon wraps around), otherwise it runs
 * from knot degree to knot n (it does not pass through its end control points). */
int gcpg_path_bspline(GCpgPath *p, int degree, const double *xy, int n, int periodic, GError *err);
/** A NURBS edge of degree 1..GCPG_MAX_DEGREE over n > degree control points with weights > 0 and a
 * non-decreasing knot vector of n + degree + 1 values (NULL: clamped uniform, so the edge runs from the
 * first to the last control point). Zero or negative weights and bad knot vectors are G_ERR_INVALID. */
int gcpg_path_nurbs(GCpgPath *p, int degree, const double *xy, const double *weights, int n, const double *knots,
                    GError *err);
/** Closes the contour into a shape (non-zero winding rule); consumes the path, also when it fails
 * (G_ERR_INVALID for a contour of fewer than 3 distinct points without curved edges, or of no edges). */
int gcpg_path_close(GCpgPath *p, GCpgShape **out, GError *err);
/** Frees a contour that was not closed; NULL is a no-op. */
void gcpg_path_destroy(GCpgPath *p);

/** Highest degree of a curved edge. */
#define GCPG_MAX_DEGREE 7

/** Combines two shapes; takes ownership of a and b, also when it fails. */
int gcpg_combine(GShapeOp op, GCpgShape *a, GCpgShape *b, GCpgShape **out, GError *err);
/** Moves a shape (and its subtree) by m, after any earlier transform; G_ERR_INVALID for a singular m. */
int gcpg_transform(GCpgShape *s, const GAffine2 *m, GError *err);
/** 1 when (x, y) is inside, 0 outside (points on an edge may go either way). */
int gcpg_inside(const GCpgShape *s, double x, double y);
/** Frees a tree; NULL is a no-op. */
void gcpg_destroy(GCpgShape *s);
/** cpg: 1 inside the shape, 0 outside, at (u, v). Takes ownership of the tree, also when it fails. */
int ggen_cpg_create(GCpgShape *root, GGenerator **out, GError *err);

#ifdef __cplusplus
}
#endif
#endif
