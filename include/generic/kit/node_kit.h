/* node_kit.h - what texture nodes are built from (lib/kit/node_kit.c, node_blend.c and node_flags.c), for the
 * built-in nodes and for nodes of one's own: construction with checks of the children, weighted blends of
 * children for every material method (interpolate, spline, select), colour temporaries, pass-through methods of
 * one-child nodes (bump, scale, image) and the state of nodes over a list of children. */
#ifndef GENERIC_NODE_KIT_H
#define GENERIC_NODE_KIT_H

#include "../export.h"
#include <stddef.h>
#include "../color.h"
#include "../error.h"
#include "../material.h"
#include "../memory.h"
#include "../nodes.h"
#include "../surfpoint.h"
#include "../texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- construction ---- */

/** Deepest texture node: a node's depth (GMaterial.depth) is 1 + the largest depth of its children (1 for a
 * material), and the constructors below refuse a node deeper than this (G_ERR_INVALID "NODE: the node would be
 * N deep, the limit is 256"), so a material call and the release of a tree never recurse deeper. */
#define GNODE_MAX_DEPTH 256

/** Most material calls one call of a texture node may make (its work budget): a node's cost (GMaterial.cost)
 * is 1 + the sum of the costs of its GNODE_BLEND_MAX costliest children (a call evaluates at most that many
 * children at once), 1 for a material, and the constructors below refuse a node that costs more (G_ERR_INVALID
 * "NODE: one call of the node would make N material calls, the limit is 100000"). A shared child counts once
 * for every path to it: a chain of nodes that each blend the node before with itself doubles at every step. */
#define GNODE_MAX_COST 100000

/** The depth and cost (see GNODE_MAX_DEPTH, GNODE_MAX_COST) of a node over n children, checked against
 * the limits (G_ERR_INVALID, the message begins with `node`). Nodes built with the constructors below have
 * them set; a node made otherwise sets its GMaterial's depth and cost from these. */
GENERIC_API GENERIC_NODISCARD int gnode_measure(const char *node, GMaterial *const *children, int n, int *depth,
                                                int *cost, GError *err);

/** Checks a node's children (n >= 1, none NULL, all in one colour model: G_ERR_MISMATCH otherwise) and its
 * generator (non-NULL when gen_needed); *model gets the common model. Messages begin with `node`. */
GENERIC_API GENERIC_NODISCARD int gnode_check(const char *node, GMaterial *const *children, int n,
                                              const GGenerator *gen, int gen_needed, const GColorModel **model,
                                              GError *err);

/** gnode_check and gnode_measure (messages naming the class), then a zeroed node of `size` bytes (a struct
 * that begins with its GMaterial) of class cls in the children's model into *out, with one reference, its depth
 * and cost set, GMAT_OPAQUE as gnode_inherit_opaque says for a class with the kit's opaque slot,
 * GMAT_GEOMETRIC_NORMAL as gnode_inherit_geometric_normal says for a class with the kit's normal slot, and
 * GMAT_NO_EMISSION (material.h) when its emission is black: cls has no emission slot, or the
 * slot is the kit's gnode_blended_emission or gnode_child_emission and every child has the bit (a blend class's
 * pick must blend only these children, a GNodeChild's child must be the one given). A class with an emission method of
 * its own gets the bit only from gnode_inherit_no_emission. It holds no reference to the children yet: the caller takes
 * those. Until it is complete, free it with gmem_free. */
GENERIC_API GENERIC_NODISCARD int gnode_new_checked(const GMaterialClass *cls, GMaterial *const *children, int n,
                                                    const GGenerator *gen, int gen_needed, size_t size, GMaterial **out,
                                                    GError *err);

/** 1 when each of the n children has GMAT_NO_EMISSION (material.h): a node whose emission only combines theirs
 * (weighted sums, products with finite factors, the child's at a moved point) then emits nothing. */
GENERIC_API GENERIC_NODISCARD int gnode_children_dark(GMaterial *const *children, int n);

/** Sets GMAT_NO_EMISSION on node when gnode_children_dark(children, n): for a node class whose own emission
 * method only combines its children's emissions (the scale, image and transform nodes call it after
 * construction). Never for a node that adds light of its own: a wrong bit gives wrong pictures. */
GENERIC_API void gnode_inherit_no_emission(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_OPAQUE (material.h): a node whose opacity is theirs (any child it blends,
 * the child's at a moved point) is then opaque everywhere. gnode_new_checked applies it to a class whose opaque
 * slot is the kit's gnode_blended_opaque or gnode_child_opaque. */
GENERIC_API GENERIC_NODISCARD int gnode_children_opaque(GMaterial *const *children, int n);

/** Sets GMAT_OPAQUE on node when gnode_children_opaque(children, n): for a node class whose own opaque method
 * only asks its children (the transform node calls it after construction). Never for a node that can be
 * transparent where its children are not. */
GENERIC_API void gnode_inherit_opaque(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_GEOMETRIC_NORMAL (material.h): a node whose normal is a child's or a
 * normalised blend of its children's, asked at the point's own geometric normal (a moved copy of the point keeps
 * it), then has the geometric normal everywhere. gnode_new_checked applies it to a class whose normal slot is
 * the kit's gnode_blended_normal or gnode_child_normal (gnode_inherit_kit_normal). */
GENERIC_API GENERIC_NODISCARD int gnode_children_geometric_normal(GMaterial *const *children, int n);

/** Sets GMAT_GEOMETRIC_NORMAL on node when gnode_children_geometric_normal(children, n): for a node class whose
 * own normal method only asks its children at a point with the same geometric normal (the transform node calls it
 * after construction). Never for a node that changes the normal (bump): a wrong bit flattens its pictures. */
GENERIC_API void gnode_inherit_geometric_normal(GMaterial *node, GMaterial *const *children, int n);

/** gnode_inherit_geometric_normal for a node whose class's normal slot is the kit's gnode_blended_normal or
 * gnode_child_normal (their normal is a child's or a blend of the children's at the same point); nothing for any
 * other slot. gnode_new_checked calls it. */
GENERIC_API void gnode_inherit_kit_normal(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_LAMBERTIAN (material.h): a node whose reflection is the sum of its
 * children's reflections at the same point with weights w_i, and whose diffuse colour the sum of their diffuse
 * colours with the same w_i, is then Lambertian: sum w_i diffuse_i * illum * cos / pi, the cosine being the same
 * for every child (gmaterial_cos_in reads the shading normal cached on the point, which the kit's nodes hand on
 * unchanged, and the geometric normal, which none moves). */
GENERIC_API GENERIC_NODISCARD int gnode_children_lambertian(GMaterial *const *children, int n);

/** Sets GMAT_LAMBERTIAN on node when gnode_children_lambertian(children, n) and node's class is a GNodeBlendClass
 * with the kit's reflection and diffuse slots (gnode_blended_reflection, gnode_blended_diffuse): for a blend class
 * whose pick gives the same blend for GNODE_REFLECTION as for GNODE_DIFFUSE at every point, which only the class
 * knows, so gnode_new_checked never sets the bit: the class calls this after construction (interpolate, spline
 * and select, whose picks ignore the method; interpolate-one unless its one blended method is reflection or
 * diffuse). Never for a pick that answers the two methods differently: a wrong bit renders the diffuse blend where
 * the reflection blend belongs. It refuses any other class: one-child nodes (bump, scale, image, transform) get the
 * bit from gnode_inherit_lambertian_child. */
GENERIC_API void gnode_inherit_lambertian(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_LAMBERTIAN on node when child has it (gnode_children_lambertian(&child, 1)): for a one-child node
 * class whose reflection at sp is the child's reflection at a point q times a factor k, whose diffuse colour at sp
 * is the child's diffuse colour at the same q times the same k, and whose is_delta is the child's (0 for a
 * Lambertian child). q is sp itself or a copy of it that carries sp's shading normal (gsurfpoint_normal(sp),
 * cached on sp before the copy) and its geometric normal, so that gmaterial_cos_in(q, ...) is gmaterial_cos_in(sp,
 * ...); k is a number or a colour that is a vector (GCOLOR_VECTOR), never a re-radiation matrix: k * (d * light) is
 * then (k * d) * light for the child's diffuse colour d, which a matrix k times a vector d is not. The node is then
 * Lambertian: k * d * light * gmaterial_cos_in(sp) / pi. Only the class knows this, so it calls this after
 * construction: bump (q = sp, k = 1: the child reads the shading normal cached on sp, the bumped one when the bump is
 * the point's material, which is what gsurfpoint_normal(sp) gives), scale (k the factor; 0 makes both black), image (k
 * the texel colour, when the image's primaries are vectors in the model) and transform (q the moved copy, k = 1). Never
 * for a node whose reflection and diffuse colour differ otherwise (a tint of one alone, a point with another shading
 * normal for the child): a wrong bit renders the diffuse colour where the reflection belongs. */
GENERIC_API void gnode_inherit_lambertian_child(GMaterial *node, GMaterial *child);

/** 1 when each of the n children has GMAT_DIAGONAL (material.h): a node whose reflection and refraction are sums
 * of its children's reflections and refractions of the same light, with weights and at points that do not depend
 * on the light (a blend, a factor, a texel, a moved point), then filters light sample by sample too. */
GENERIC_API GENERIC_NODISCARD int gnode_children_diagonal(GMaterial *const *children, int n);

/** Sets GMAT_DIAGONAL on node when gnode_children_diagonal(children, n): for a class whose reflection and
 * refraction are such sums, which only the class knows, so a class with slots of its own calls it after
 * construction (image, scale, transform). */
GENERIC_API void gnode_inherit_diagonal(GMaterial *node, GMaterial *const *children, int n);

/** gnode_inherit_diagonal when node's reflection and refraction slots are the kit's blends or pass-throughs
 * (gnode_blended_reflection and _refraction, gnode_child_reflection and _refraction) or empty: gnode_new_checked
 * calls it for every node it makes, plug-in classes included. */
GENERIC_API void gnode_inherit_kit_diagonal(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_NO_IDEAL (material.h): a node whose reflection_dir and refraction_dir are
 * its children's or blends of them (any point, view and index) then has no ideal ray anywhere. */
GENERIC_API GENERIC_NODISCARD int gnode_children_no_ideal(GMaterial *const *children, int n);

/** Sets GMAT_NO_IDEAL on node when gnode_children_no_ideal(children, n): for a node class whose own reflection_dir
 * and refraction_dir only ask these children, at any point (transform calls it after construction). */
GENERIC_API void gnode_inherit_no_ideal(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_NO_IDEAL on node when gnode_children_no_ideal(children, n) and each of its class's reflection_dir and
 * refraction_dir slots is empty or the kit's blend or pass-through (gnode_blended_<name>, gnode_child_<name>):
 * gnode_new_checked calls it for every node it makes, plug-in classes included. */
GENERIC_API void gnode_inherit_kit_no_ideal(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_NO_REL_INDEX (material.h): a node whose own methods read no relative index
 * and hand rel_index only to these children then gives the same results for any relative index. */
GENERIC_API GENERIC_NODISCARD int gnode_children_no_rel_index(GMaterial *const *children, int n);

/** Sets GMAT_NO_REL_INDEX on node when gnode_children_no_rel_index(children, n): for a node class whose own methods
 * read neither their rel_index argument nor the point's relative index (gsurfpoint_relative_index,
 * gsurfpoint_index_of) but hand them on to these children, and whose generators do not read it either (scale, image,
 * bump, transform and the textured materials call it after construction). */
GENERIC_API void gnode_inherit_no_rel_index(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_NO_REL_INDEX on node when gnode_children_no_rel_index(children, n), every slot of its class is empty,
 * the kit's pass-through gnode_child_<name> or the kit's blend gnode_blended_<name>, and, when its refraction or
 * sample slot is the kit's blend, each child has GMAT_OPAQUE or GMAT_NO_IDEAL: the blend's refraction asks whether
 * a pair is the ideal refraction for the point's index only where some child has an ideal refraction ray, which
 * none has through an opaque material (refraction_dir, material.h). A blend class's pick, and the generators it
 * reads, must not read the relative index (the kit's and the built-ins' read the point's position, (u, v) or surface
 * index). gnode_new_checked calls it for every node it makes, plug-in classes included. */
GENERIC_API void gnode_inherit_kit_no_rel_index(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_CONSTANT_INDEX (material.h) on node when child has it: for a node class whose refraction_index is the
 * child's at every point (at the point itself or a moved copy of it) and for sp NULL (transform calls it after
 * construction). */
GENERIC_API void gnode_inherit_constant_index(GMaterial *node, const GMaterial *child);

/** Sets GMAT_CONSTANT_INDEX on node when its class's refraction_index slot is the kit's pass-through
 * gnode_child_refraction_index, n is 1 and the child has it (a class without the slot has it from gmaterial_init; a
 * blend's index, the kit's gnode_blended_refraction_index, follows its generators and never gets it).
 * gnode_new_checked calls it for every node it makes, plug-in classes included. */
GENERIC_API void gnode_inherit_kit_constant_index(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_CLEAR (material.h) on node when each of the n children has it: for a node class whose absorption is, at
 * every point (the point itself or a moved copy of it) and for sp NULL, one of these children's absorption of the
 * same light, with nothing computed on it (transform; select, whose blend is always one child; interpolate-one of
 * another method, over its first child; they call it after construction). A blend of several children's absorptions
 * must not call it: w x + (1 - w) x is not always x in floating point. */
GENERIC_API void gnode_inherit_clear(GMaterial *node, GMaterial *const *children, int n);

/** Sets GMAT_CLEAR on node when its class's absorption slot is the kit's pass-through gnode_child_absorption, n is 1
 * and the child has it (a class without the slot has it from gmaterial_init; the kit's blend
 * gnode_blended_absorption sums weighted children and never gets it). gnode_new_checked calls it for every node it
 * makes, plug-in classes included. */
GENERIC_API void gnode_inherit_kit_clear(GMaterial *node, GMaterial *const *children, int n);

/** 1 when each of the n children has GMAT_NO_UV (material.h) and gen, when given, is not a function of (u, v)
 * (its space, texture.h, is not GGENERATOR_SPACE_UV: a generator's space says what its value reads). */
GENERIC_API GENERIC_NODISCARD int gnode_children_no_uv(GMaterial *const *children, int n, const GGenerator *gen);

/** Sets GMAT_NO_UV on node when gnode_children_no_uv(children, n, gen): for a node class whose own methods read
 * nothing of the surface's parametrisation but through gen (interpolate, select, spline and scale call it after
 * construction; transform, which moves (u, v) for a subtree that then never reads them, too). Never for a node
 * that reads (u, v) or the tangents itself (image, bump): a wrong bit gives wrong pictures. */
GENERIC_API void gnode_inherit_no_uv(GMaterial *node, GMaterial *const *children, int n, const GGenerator *gen);

/** 1 for the methods whose colour carries light (reflection, refraction, emission, ambient, diffuse): the ones
 * a node that darkens or tints its child (scale, image) multiplies. */
GENERIC_API GENERIC_NODISCARD int gnode_scales_method(GNodeMethod m);

/* ---- blends of children ---- */

/** Most children a blend evaluates at once (a cubic spline segment). */
#define GNODE_BLEND_MAX 4

/** A weighted sum of children: sum_i w[i] * child_i for every method. Children with weight 0 are not
 * called; n == 1 calls the child for the result directly. */
typedef struct GNodeBlend {
    int n;
    const GMaterial *m[GNODE_BLEND_MAX];
    double w[GNODE_BLEND_MAX];
} GNodeBlend;

/** The blend of a with weight 1 - t and c with weight t: a alone for t <= 0 (and NaN), c alone for t >= 1. */
GENERIC_API void gnode_blend_pair(GNodeBlend *b, const GMaterial *a, const GMaterial *c, double t);
/** The blend of one child with weight 1. */
GENERIC_API void gnode_blend_one(GNodeBlend *b, const GMaterial *m);

/** Reflection of the blend: the weighted sum of the children's colours (result may alias illum). At a pair
 * aligned with the blend's own ideal ray (materials.h) only the children with an ideal ray of their own count:
 * when some child of non-zero weight has the reflection_dir slot and `in` is the mirror direction of `out` about
 * the point's shading normal (gmaterial_is_mirror_pair with gsurfpoint_normal(sp), the normal every child reads),
 * the children are asked for their reflection_dir of the view -out, and if one has a ray, those that have none
 * are left out (their BRDF has no delta part); the others answer as ever, each checking its own aligned case.
 * That pair is the blend's ray (gnode_blend_reflection_dir) whenever the children reflect about the point's shading
 * normal, as every built-in material and node does; for children whose rays differ (a plug-in with a normal of
 * its own) the blended ray is an approximation and the test stays the point's mirror pair. Without a child with
 * the slot, or away from the pair, the cost is that of the plain sum (a few products, no square root, no call),
 * and the one-child blend calls its child directly. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_reflection(const GNodeBlend *b, GSurfPoint *sp, GVec3 in,
                                                         const GColor *illum, GVec3 out, GColor *result);
/** Refraction of the blend: the weighted sum (result may alias illum or rel_index), with the rule of
 * gnode_blend_reflection at the ideal refraction: `in` the ideal refraction of -out about the point's shading
 * normal with the scalar index of rel_index (gsurfpoint_scalar_index; the point's relative index when rel_index
 * is NULL, as the dielectric reads it: goptics_is_refraction_pair), refraction_dir for the children's rays. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_refraction(const GNodeBlend *b, GSurfPoint *sp, GVec3 in,
                                                         const GColor *illum, const GColor *rel_index, GVec3 out,
                                                         GColor *result);
/** Refraction index of the blend: the weighted sum. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_refraction_index(const GNodeBlend *b, GSurfPoint *sp, GColor *result);
/** Reflection direction of the blend: valid when a child's is; two or more valid directions are summed with
 * their weights and normalised (the one of largest weight when the sum vanishes), a single one is returned. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_reflection_dir(const GNodeBlend *b, GSurfPoint *sp, GVec3 view,
                                                             GVec3 *dir);
/** Refraction direction of the blend, as gnode_blend_reflection_dir. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_refraction_dir(const GNodeBlend *b, GSurfPoint *sp, GVec3 view,
                                                             const GColor *rel_index, GVec3 *dir);
/** Emission of the blend: the weighted sum. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_emission(const GNodeBlend *b, GSurfPoint *sp, GVec3 out, GColor *result);
/** Ambient reflection of the blend: the weighted sum (result may alias illum). */
GENERIC_API GENERIC_NODISCARD int gnode_blend_ambient(const GNodeBlend *b, GSurfPoint *sp, const GColor *illum,
                                                      GColor *result);
/** Absorption of the blend: the weighted sum (result may alias illum). */
GENERIC_API GENERIC_NODISCARD int gnode_blend_absorption(const GNodeBlend *b, GSurfPoint *sp, const GColor *illum,
                                                         double length, GColor *result);
/** Normal of the blend: the children's normals summed with their weights and normalised. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_normal(const GNodeBlend *b, GSurfPoint *sp, GVec3 *n);
/** Diffuse colour of the blend: the weighted sum. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_diffuse(const GNodeBlend *b, GSurfPoint *sp, GColor *result);
/** 1 when every child of non-zero weight is opaque. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_opaque(const GNodeBlend *b, GSurfPoint *sp);
/** Sampling of the blend as a mixture: child i is chosen with probability q_i = |w_i| / sum |w_j| (u1 remapped)
 * and draws the direction. A delta sample keeps the child's direction, pdf q_i * the child's, weight w_i / q_i
 * times the child's; otherwise pdf = sum q_j pdf_j(in) (gnode_blend_pdf) and the weight is the blend's own value
 * (gnode_blend_reflection or _refraction of white) / pdf, so the estimate is that of the blend's methods. A
 * non-delta direction on the blend's ideal ray (see gnode_blend_reflection) is weighed with the value of the lobes
 * that are not ideal: the children without a ray of their own there (those with one would give their ideal part,
 * which only the delta samples carry). */
GENERIC_API GENERIC_NODISCARD int gnode_blend_sample(const GNodeBlend *b, GSurfPoint *sp, GVec3 out,
                                                     const GColor *rel_index, double u1, double u2, GMaterialSample *s,
                                                     GColor *weight);
/** The mixture's density: sum q_j pdf_j(in, out) (see gnode_blend_sample). */
GENERIC_API double gnode_blend_pdf(const GNodeBlend *b, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index);
/** 1 when every child of non-zero weight is delta. */
GENERIC_API GENERIC_NODISCARD int gnode_blend_is_delta(const GNodeBlend *b, GSurfPoint *sp);

/** The class of a node that answers each call with a blend of its children chosen by `pick`: its material
 * methods are the gnode_blended_* below (GNODE_BLENDED_METHODS fills them in), so the node itself writes only
 * pick and destroy. Register &cls.base as the vtable. */
typedef struct GNodeBlendClass {
    GMaterialClass base;
    /** Fills the blend that answers method m at sp. sp is NULL for the calls without a surface point
     * (refraction_index and absorption of a homogeneous medium): pick the first child then. */
    void (*pick)(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *blend);
} GNodeBlendClass;

/** The material methods of a GNodeBlendClass node, `type gnode_blended_<name>(const GMaterial *self, params)` for
 * each of GMATERIAL_METHODS (material.h): for a method whose blend is `pick`, the blend the node's pick gives for
 * GNODE_<NAME>, then gnode_blend_<name>. Sampling (sample, pdf, is_delta) draws from the blend the pick gives for
 * GNODE_REFLECTION (the blend its reflection is), with gnode_blend_sample, _pdf and _is_delta. When the pick gives
 * another blend for GNODE_REFRACTION (interpolate-one of reflection or refraction), the mixture is over every child
 * of either blend (weight |w_reflection| + |w_refraction|), and a sample weighs the value of the blend its flag
 * names: a reflected one the reflection's, a transmitted one the refraction's; pdf and is_delta are those of the
 * same mixture. */
#define GNODE_DECLARE_BLENDED_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    GENERIC_API attr type gnode_blended_##name GMATERIAL_WITH(const GMaterial *self, params);
GMATERIAL_METHODS(GNODE_DECLARE_BLENDED_)

/** The slots of a GNodeBlendClass's `base`: `.<name> = gnode_blended_<name>,` for each of GMATERIAL_METHODS,
 * designated initialisers each followed by a comma. */
#define GNODE_BLENDED_SLOT_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    .name = gnode_blended_##name,
#define GNODE_BLENDED_METHODS GMATERIAL_METHODS(GNODE_BLENDED_SLOT_)

/* ---- temporaries ---- */

/** Storage for temporary colours of a node method: on sp->scratch when there is one, else on the thread's own
 * arena (gscratch_thread), so a model of any size works without an arena from the caller. */
typedef struct GNodeTemps {
    GScratch *scratch; /**< the arena a mark was taken on (NULL before the first colour) */
    GScratchMark mark;
} GNodeTemps;

/** Starts an empty set of temporaries. */
static inline void gnode_temps_init(GNodeTemps *t) { t->scratch = NULL; }
/** Gives c temporary storage of model m (index: which of the method's temporaries, 0 or 1; kept for source
 * compatibility); G_ERR_NOMEM when the arena cannot grow. */
GENERIC_API GENERIC_NODISCARD int gnode_temps_color(GNodeTemps *t, GSurfPoint *sp, const GColorModel *m, int index,
                                                    GColor *c);
/** Returns the arena to where it was before the first gnode_temps_color. */
GENERIC_API void gnode_temps_release(GNodeTemps *t);

/* ---- nodes with one child ---- */

/** The start of a node with one child (bump, scale, image): the node's struct begins with it. */
typedef struct GNodeChild {
    GMaterial base;
    GMaterial *child; /**< one reference, the node's */
} GNodeChild;

/** The child of such a node. */
static inline GMaterial *gnode_child_of(const GMaterial *self) { return ((const GNodeChild *)self)->child; }

/** Creates a node of class cls whose struct (`size` bytes) begins with a GNodeChild holding a reference to child
 * (checked with gnode_check; gen, when gen_needed, must be non-NULL: the caller takes its own reference to
 * it). Until it is complete, free it with the class's destroy. */
GENERIC_API GENERIC_NODISCARD int gnode_child_new(const GMaterialClass *cls, GMaterial *child, const GGenerator *gen,
                                                  int gen_needed, size_t size, GMaterial **out, GError *err);
/** The destroy method of one-child nodes that own nothing else: drops the child and frees the struct. */
GENERIC_API void gnode_child_destroy(GMaterial *self);

/** The pass-through methods of one-child nodes, `type gnode_child_<name>(const GMaterial *self, params)` for each
 * of GMATERIAL_METHODS (material.h): the child's gmaterial_<name> at the same point (a bump node's child samples
 * about the bumped normal, which it reads from sp). */
#define GNODE_DECLARE_CHILD_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    GENERIC_API attr type gnode_child_##name GMATERIAL_WITH(const GMaterial *self, params);
GMATERIAL_METHODS(GNODE_DECLARE_CHILD_)

/** What a GNodeTimes node multiplies its child's results by at sp: result = factor(sp) * result, in place. */
typedef int (*GNodeTimesFn)(const GMaterial *self, GSurfPoint *sp, GColor *result);
/** The start of a one-child node whose light-carrying results are its child's times a colour at the point (image
 * node, textured colour parameters): reflection, refraction, emission, ambient, diffuse and sample's weight go
 * through `times`; the rest is the child's (gnode_child_*). Create it with gnode_child_new, then set times. */
typedef struct GNodeTimes {
    GNodeChild node;
    GNodeTimesFn times;
} GNodeTimes;
/** The reflection method of a GNodeTimes node: the child's, then times. */
GENERIC_API int gnode_times_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                                       GVec3 out, GColor *result);
/** The refraction method of a GNodeTimes node: the child's, then times. */
GENERIC_API int gnode_times_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                                       const GColor *rel_index, GVec3 out, GColor *result);
/** The emission method of a GNodeTimes node: the child's, then times. */
GENERIC_API int gnode_times_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result);
/** The ambient method of a GNodeTimes node: the child's, then times. */
GENERIC_API int gnode_times_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result);
/** The diffuse method of a GNodeTimes node: the child's, then times. */
GENERIC_API int gnode_times_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result);
/** The sample method of a GNodeTimes node: the child's direction and density, its weight times the factor. */
GENERIC_API int gnode_times_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index,
                                   double u1, double u2, GMaterialSample *s, GColor *weight);
/** The method slots of a GNodeTimes node's class, for its GMaterialClass initialiser (after abi_version, name,
 * description and destroy): the colour methods multiply, the geometric ones are the child's. */
#define GNODE_TIMES_METHODS                                                                                            \
    .reflection = gnode_times_reflection, .refraction = gnode_times_refraction,                                       \
    .refraction_index = gnode_child_refraction_index, .reflection_dir = gnode_child_reflection_dir,                    \
    .refraction_dir = gnode_child_refraction_dir, .emission = gnode_times_emission, .ambient = gnode_times_ambient,    \
    .absorption = gnode_child_absorption, .normal = gnode_child_normal, .diffuse = gnode_times_diffuse,                \
    .opaque = gnode_child_opaque, .sample = gnode_times_sample, .pdf = gnode_child_pdf,                                \
    .is_delta = gnode_child_is_delta

/* ---- nodes over a list of children ---- */

/** The state of a node that picks among n children by a generator's value (select, spline); the node's
 * struct begins with it. */
typedef struct GNodeList {
    GMaterial base;
    GGenerator *gen;      /**< one reference */
    int n;                /**< >= 1 */
    GMaterial **children; /**< n, one reference each */
} GNodeList;

/** Creates a node of class cls whose struct (`size` bytes) begins with a GNodeList holding a reference to each
 * of the n children and to gen (all checked with gnode_check). */
GENERIC_API GENERIC_NODISCARD int gnode_list_new(const GMaterialClass *cls, GMaterial *const *children, int n,
                                                 GGenerator *gen, size_t size, GMaterial **out, GError *err);
/** The destroy method of the nodes whose struct begins with a GNodeList. */
GENERIC_API void gnode_list_destroy(GMaterial *self);

#ifdef __cplusplus
}
#endif
#endif
