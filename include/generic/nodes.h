/* nodes.h - constructors of the built-in texture nodes (the files in textures/). Writing a node of one's own:
 * node_kit.h.
 *
 * Nodes are materials (GMaterial): every method of the material interface is implemented by calling the
 * children, so a tree stands wherever a material does. Node constructors take their own references to
 * the children and generators they are given (the caller keeps its own), check that all children compute
 * in one colour model (G_ERR_MISMATCH otherwise) and return a node with one reference (gmaterial_unref).
 *
 * Nodes evaluate their generators once per surface point (ggenerator_cached_value, texture.h). Their
 * temporaries live on sp->scratch; nothing is allocated per call. Methods that may be called without a
 * surface point (refraction_index and absorption with sp == NULL) use the first child.
 *
 * Renderers set sp->material to the root of the tree: leaves take the shading normal from
 * gsurfpoint_normal(sp), which asks the root, so a bump node anywhere in the tree reaches them. */
#ifndef GENERIC_NODES_H
#define GENERIC_NODES_H

#include "export.h"
#include "color.h"
#include "material.h"
#include "texture.h"
#include "kit/affine.h"
#include "services/texsys.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The methods a blend node's pick is asked for (node_kit.h, GNodeBlendClass), GNODE_<NAME> for each method of
 * GMATERIAL_METHODS (material.h) whose blend is `pick`, in the list's order: every method but the sampling ones
 * (sample, pdf, is_delta), which follow the blends of reflection and refraction. */
#define GNODE_METHOD_ENUM_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    GNODE_METHOD_ENUM_##blend(GNODE_##NAME)
#define GNODE_METHOD_ENUM_pick(id) id,
#define GNODE_METHOD_ENUM_sampled(id)
typedef enum GNodeMethod {
    GMATERIAL_METHODS(GNODE_METHOD_ENUM_)
    GNODE_METHOD_COUNT
} GNodeMethod;

/** The method's keyword ("reflection", "refraction_index", ...); "?" when out of range. */
GENERIC_API const char *gnode_method_name(GNodeMethod m);
/** The method of a keyword; -1 when unknown. */
GENERIC_API GENERIC_NODISCARD int gnode_method_from_name(const char *name);

/** interpolate: child a where the generator gives t <= 0, child b where t >= 1, and in between every
 * method blends the two results linearly ((1 - t) a + t b):
 *   - colours (reflection, refraction, refraction_index, emission, ambient, absorption, diffuse) blend
 *     as colours (gcolor_scale / gcolor_add_scaled), but for reflection and refraction along the node's
 *     ideal ray: there only a child with an ideal ray of its own answers, the specular case, and a child
 *     without one adds nothing (materials.h, gnode_blend_reflection in node_kit.h);
 *   - normal: the two normals blended and normalised;
 *   - reflection_dir / refraction_dir: valid when either child's is; two valid directions are blended and
 *     normalised, a single valid one is returned as it is (its child's weight already scales the colour
 *     the renderer gets back from reflection/refraction along it);
 *   - opaque: opaque only when both children are (so the renderer traces refraction whenever either
 *     child transmits light).
 * At t = 0 and t = 1 exactly one child is called (the paper's integer fast path). t is clamped to [0, 1]
 * and taken from the generator once per surface point. */
GENERIC_API GENERIC_NODISCARD int gnode_interpolate_create(GMaterial *a, GMaterial *b, GGenerator *t, GMaterial **out,
                                                           GError *err);

/** interpolate-one: blends the single method `method` like interpolate and takes every other method from
 * child a (e.g. a spatially varying refraction index in hand-made glass). */
GENERIC_API GENERIC_NODISCARD int gnode_interpolate_one_create(GMaterial *a, GMaterial *b, GGenerator *t,
                                                               GNodeMethod method, GMaterial **out, GError *err);

/** select: n >= 1 children; the generator's value, rounded down and clamped to [0, n - 1], picks the child
 * that answers every method (e.g. the surface index picks a material per face of a cube). */
GENERIC_API GENERIC_NODISCARD int gnode_select_create(GMaterial *const *children, int n, GGenerator *index,
                                                      GMaterial **out, GError *err);

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
GENERIC_API GENERIC_NODISCARD int gnode_spline_create(GMaterial *const *children, int n, GGenerator *t,
                                                      GSplineBasis basis, GMaterial **out, GError *err);

/** Most keys a spline's ramp may have. */
#define GSPLINE_MAX_KEYS 1024

/** spline over a ramp: child i at t = keys[i] (2 <= n <= GSPLINE_MAX_KEYS keys in [0, 1], none smaller than the
 * one before; equal keys make a step). Between keys k and k + 1, t is mapped linearly onto the segment of
 * children k, k + 1 of the uniform spline, so the linear basis interpolates linearly between the keys and
 * Catmull-Rom passes through every key; below the first key and above the last the end children hold. keys
 * is copied. */
GENERIC_API GENERIC_NODISCARD int gnode_spline_create_keyed(GMaterial *const *children, const double *keys, int n,
                                                            GGenerator *t, GSplineBasis basis, GMaterial **out,
                                                            GError *err);

/** bump: Blinn's bump mapping. The generator is a height field h; the surface is displaced by
 * strength * h along its normal, and the normal method returns the normal of the displaced surface:
 *   N' = |Pu x Pv| n + s (h_u (n x Pv) + h_v (Pu x n)),  normalised,
 * with n the child's normal (oriented to the outside, i.e. flipped when !sp->entering, and flipped back),
 * Pu, Pv = sp->dpdu, sp->dpdv and h_u, h_v from ggenerator_surface_derivatives. On a plane with unit
 * tangents and h = k u, the normal tilts by atan(strength * k). When the tangents are zero or parallel an
 * arbitrary orthonormal frame around n is used. Every other method is the child's. */
GENERIC_API GENERIC_NODISCARD int gnode_bump_create(GMaterial *child, GGenerator *height, double strength,
                                                    GMaterial **out, GError *err);

/** scale: the child's colour results that carry light (reflection, refraction, emission, ambient, diffuse)
 * multiplied by the generator's value (e.g. noise as dirt), 0 where that value is negative (noise and gradients
 * go below 0: no light, never negative light); refraction_index, absorption, directions, normal and opaque are
 * the child's. */
GENERIC_API GENERIC_NODISCARD int gnode_scale_create(GMaterial *child, GGenerator *factor, GMaterial **out,
                                                     GError *err);

/** transform: the subtree sees its texture coordinates moved: the pattern it generates is moved by
 * `uv` in the (u, v) plane and by `xyz` in object space (either may be NULL for none). A subtree that
 * gives pattern f(u, v) gives f(uv^-1 (u, v)) below the node; translate 0.5 0 moves a checker's edges
 * by +0.5 in u. The node evaluates the child on a copy of the surface point with u, v, dpdu, dpdv,
 * uv_footprint (for uv) and object_point, object_dpdu, object_dpdv (for xyz) transformed; the object tangents
 * are those along the new (u, v) (turned with dpdu, dpdv by uv), so a (u, v) transform leaves the bumps of an
 * object- or world-space height field as they were (bump's normal does not depend on the parametrisation); the copy
 * starts with empty generator caches, since values cached above were computed at other coordinates, so
 * generators below a transform are evaluated once per method call on it. The copy keeps the shading
 * normal computed for the original point (the normal is a world-space quantity). World-space
 * generators and the world point are not moved. */
GENERIC_API GENERIC_NODISCARD int gnode_transform_create(GMaterial *child, const GAffine2 *uv, const GAffine3 *xyz,
                                                         GMaterial **out, GError *err);

/* ---- images (the texture system: texsys.h) ---- */

/** Options of an image node; a zeroed struct takes the defaults. */
typedef struct GImageNodeOptions {
    GTextureSystem *texsys; /**< NULL: gtexsys_default() */
    GTexWrap swrap, twrap;  /**< along u and v (default periodic) */
    GTexColorSpace colorspace;
    double blur;            /**< extra filter width in (u, v) units, >= 0 */
} GImageNodeOptions;

/** image: the child's colour results that carry light (as for scale) multiplied by the image's colour at
 * (u, v) (u to the right, v up: v = 0 is the image's bottom row), read as a reflectance into the child's
 * model (a spectral OpenEXR's reflective channels: gtexparam_image_open, kit/texparam.h). Lookups are MIP-mapped over
 * the pixel footprint: anisotropically over the ellipse sp->uv_axis1/2 when the renderer gives it, else with the
 * isotropic width sp->uv_footprint (0: the finest level, bilinear). The file is opened (and checked) here: a missing or
 * unreadable file is G_ERR_IO naming it. sRGB-encoded files are decoded after filtering. Grey images give grey colours;
 * alpha is ignored. */
GENERIC_API GENERIC_NODISCARD int gnode_image_create(GMaterial *child, const char *path, const GImageNodeOptions *opt,
                                                     GMaterial **out, GError *err);

#ifdef __cplusplus
}
#endif
#endif
