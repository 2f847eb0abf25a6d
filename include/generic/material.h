/* material.h - the generic material interface (the paper's Fig. 3 in C).
 *
 * Directions: `in` and `out` point away from the surface (towards the light, towards the viewer);
 * `view` in reflection_dir/refraction_dir is the incident ray's direction (towards the surface) and the
 * returned direction points away from it. Normals come from the surface point and face the incident ray.
 *
 * reflection(in, illum, out) is the light leaving towards `out` when light `illum` arrives from `in`:
 *   - for directions that are not the material's ideal reflection: f_r(in, out) * cos(theta_in) * illum,
 *     so a point light of intensity I at distance d passes illum = I / d^2;
 *   - when out is the ideal mirror direction of in (checked by the material, as the paper asks), the
 *     perfect specular part: the specular reflectance times illum (the radiance traced along that ray).
 *     A material that sums others (a texture node's blend) sums there only the parts that have an ideal ray
 *     of their own: a BRDF value is a density, not a reflectance (materials.h, node_kit.h).
 * refraction(in, illum, rel_index, out) is the same for light arriving through the surface from `in`.
 * The geometric normal tells the sides: a reflection has in and out on its incident side, a refraction has in on
 * the other. About a shading normal that a bump node tilts, an ideal ray may point back across the surface (a
 * mirror ray into the body); one interface sends no light there, so what such a pair passes on is black
 * (gmaterial_cos_in, material_kit.h; the built-ins all do so), and a sample along it keeps its flag with a black
 * weight.
 *
 * The methods are listed once, in GMATERIAL_METHODS below, each with the default a missing method (a NULL slot)
 * takes.
 *
 * Sampling (for renderers other than a Whitted tracer: path tracers). sample(out, rel_index, u1, u2) draws a
 * direction `in` for light leaving towards `out`, from two uniform numbers in [0, 1); it returns the
 * direction, its pdf and the weight value(in, white, out) / pdf as a colour, where value is reflection() for a
 * reflected and refraction() for a transmitted direction: for a non-ideal direction f * cos(theta_in) / pdf
 * (pdf per unit solid angle), for an ideal (delta) lobe its reflectance / the probability of choosing the lobe
 * (then pdf is that probability). pdf(in, out) is the density sample() draws `in` with, counting the non-delta
 * lobes only (0 for a pair only a delta lobe produces). is_delta says that every lobe is ideal (a mirror, clear
 * glass): a renderer need not send light samples there. Defaults, built from the methods above so that every
 * material renders: delta lobes from reflection_dir and refraction_dir, weighted by the brightness of what
 * they pass on; a cosine lobe weighted by the brightness of diffuse(); without a diffuse colour a uniform
 * hemisphere lobe for the rest (1 - the delta lobes' weights) with reflection() as its value — correct for
 * any material, only noisier than a material's own sampling; is_delta: no.
 * pdf is a density over the whole sphere of directions: a lobe about the mirror direction may reach below the
 * surface, and sample() then returns such a direction (1) with a black weight, counted by pdf, so that pdf
 * integrates to the share of draws that give a non-delta direction (1 - P(delta) - P(nothing drawn)). A material
 * that reflects nothing (an emitter) draws nothing and is delta: a light sample would reflect nothing. */
#ifndef GENERIC_MATERIAL_H
#define GENERIC_MATERIAL_H

#include "export.h"
#include "vec.h"
#include "color.h"
#include "surfpoint.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the material vtable and the GMaterial header; a class of another version is refused. */
#define GMATERIAL_ABI_VERSION 4

typedef struct GMaterialClass GMaterialClass;

/** Flags of a sampled direction. */
enum {
    GSAMPLE_REFLECT = 1,  /**< on the side of `out`: a reflection */
    GSAMPLE_TRANSMIT = 2, /**< on the other side: a refraction; the path crosses into the other medium */
    GSAMPLE_DELTA = 4     /**< from an ideal (delta) lobe: pdf is the probability of choosing the lobe */
};

/** A direction drawn by gmaterial_sample. */
typedef struct GMaterialSample {
    GVec3 in;   /**< the sampled direction, pointing away from the surface (where the light comes from) */
    double pdf; /**< density of `in` per unit solid angle; for a delta lobe the probability of choosing it */
    int flags;  /**< GSAMPLE_* */
} GMaterialSample;

/** Properties of one material instance (bits of GMaterial.flags) that let the dispatch and a renderer skip work.
 * Each bit is a promise about every point and every pair of directions. Clearing a bit is always correct, only
 * slower; a bit set where it does not hold changes pictures without an error, so a class sets one by hand (after
 * gmaterial_init) only where it holds, and `gmat check` has a property per bit that tests it. */
enum {
    /** emission() is black: gmaterial_emission answers black without calling the class. Set by gmaterial_init for
     * a class without an emission slot, by the node kit for a node whose emission only combines its children's
     * when every child has it (node_kit.h); a class with a slot may set it on an instance that emits nothing. */
    GMAT_NO_EMISSION = 1u,
    /** opaque() is 1: gmaterial_opaque answers 1 without calling the class, and a renderer may let any surface of
     * the material block a shadow ray without a surface point (gmaterial_opaque_everywhere). Set by gmaterial_init
     * for a class without an opaque slot, by the node kit for a node whose opacity is its children's when every
     * child has it. */
    GMAT_OPAQUE = 2u,
    /** normal() is the geometric normal: gmaterial_normal and gsurfpoint_normal answer sp->geometric_normal
     * without calling the class. Set by gmaterial_init for a class without a normal slot, by the node kit for a
     * node whose normal is a child's or a normalised blend of them when every child has it; never on a node that
     * changes the normal (bump). */
    GMAT_GEOMETRIC_NORMAL = 4u,
    /** Lambertian: reflection(sp, in, illum, out) is diffuse(sp) times illum times gmaterial_cos_in(sp, in, out,
     * &n) / pi (material_kit.h), and is_delta is 0. A renderer may sum the light of all its light samples, each
     * times its cosine, and ask the material once for diffuse(sp); gmaterial_is_delta answers 0 without calling
     * the class. gmaterial_init never sets it: a class sets it on the instances it holds for (lambert); the node
     * kit sets it on a blend whose pick gives the same blend for reflection as for diffuse when every child has it
     * (gnode_inherit_lambertian), and on a one-child node whose reflection and diffuse colour are its child's times
     * the same factor (gnode_inherit_lambertian_child). */
    GMAT_LAMBERTIAN = 8u,
    /** No method reads the surface's parametrisation (u, v, dpdu, dpdv, object_dpdu, object_dpdv, uv_footprint,
     * uv_axis1, uv_axis2): a renderer may leave those fields zero, as gsurfpoint_init sets them, and skip computing
     * them. gmaterial_init never sets it; a class whose methods read none of them sets it on its instances (every
     * built-in material does), and a node when its own methods read none of them and every child has it
     * (gnode_inherit_no_uv). */
    GMAT_NO_UV = 16u,
    /** The material filters light sample by sample (no fluorescence): reflection(sp, in, illum, out) is
     * reflection(sp, in, white, out) times illum (gcolor_mul), and the same for refraction with any rel_index,
     * white being 1 in every sample, up to rounding. A renderer may ask once what the material passes on of white
     * light, weigh a secondary ray with it and multiply the ray's light by it. gmaterial_init never sets it: a
     * class sets it on the instances it holds for (the built-ins whose colours are not re-radiation matrices);
     * the node kit on a blend when every child has it (gnode_inherit_diagonal). */
    GMAT_DIAGONAL = 32u,
    /** No ideal ray: reflection_dir and refraction_dir say "not valid" (0) at every point for every view and index,
     * so gmaterial_reflection_dir and gmaterial_refraction_dir answer 0 without calling the class (a blend over such
     * children then picks no blend for them). Set by gmaterial_init for a class with neither slot, by the node kit
     * for a node whose direction slots are the kit's blends or pass-throughs (or empty) when every child has it
     * (gnode_inherit_kit_no_ideal). */
    GMAT_NO_IDEAL = 64u,
    /** No method reads the relative index: neither the rel_index argument of refraction, refraction_dir, sample
     * and pdf (nor of any slot that takes one) nor the point's (gsurfpoint_relative_index, gsurfpoint_index_of), so
     * every result is the same for any relative index n(from) / n(to), set on the point or handed as the argument.
     * A renderer may then skip computing it (two refraction_index calls and a division per hit) and hand any colour
     * of the model (1 in every sample) as rel_index. gmaterial_init never sets it (any method may read the point's
     * index): a class sets it on the instances it holds for (lambert, phong, mirror, emitter, conductor, plastic,
     * thindielectric, the fluorescent materials), the node kit on a node whose own methods read no relative index
     * when every child has it (gnode_inherit_no_rel_index, gnode_inherit_kit_no_rel_index). */
    GMAT_NO_REL_INDEX = 128u,
    /** refraction_index gives the same colour, bit for bit, at every point and for sp NULL: a renderer may compute
     * the relative index n(from) / n(to) of a pair of such materials once and keep it for every point between them.
     * Set by gmaterial_init for a class without a refraction_index slot (the default, 1); a class sets it on the
     * instances it holds for (dielectric: its index is a constant or a fit of the wavelength; layer and thinfilm
     * when the material whose index they give has it); the node kit on a node whose refraction_index is one child's
     * at any point when that child has it (gnode_inherit_constant_index, gnode_inherit_kit_constant_index: bump,
     * scale, image, transform, the textured materials), never on a blend of several children. */
    GMAT_CONSTANT_INDEX = 256u,
    /** The material as a medium absorbs nothing: absorption(sp, illum, length, result) writes illum itself (its
     * kind and samples, bit for bit) for every length >= 0, at every point and for sp NULL, so a renderer may skip
     * the call and the colour it writes to, and carry the light on unchanged; gmaterial_absorption answers so itself,
     * without calling the class. Set by gmaterial_init for a class
     * without an absorption slot (the default, illum); a class sets it on the instances it holds for (dielectric
     * without absorption; thinfilm when its base has it); the node kit on a node whose absorption is at every point
     * one child's when each such child has it (gnode_inherit_clear, gnode_inherit_kit_clear: bump, scale, image,
     * transform, select, the textured materials, interpolate-one of another method), never on a blend of several
     * children (w x + (1 - w) x is not always x in floating point). */
    GMAT_CLEAR = 512u
};

/** A material instance begins with this header; implementations embed it as their first member. */
struct GMaterial {
    const GMaterialClass *cls;
    const GColorModel *model; /**< the model its colours are in */
    int refcount;             /**< owners; see gmaterial_ref/gmaterial_unref */
    int depth;                /**< 1 (gmaterial_init); a texture node: 1 + its deepest child's (node_kit.h) */
    int cost;                 /**< most material calls one call can make, itself included: 1 (gmaterial_init);
                                   a texture node: see GNODE_MAX_COST (node_kit.h) */
    unsigned flags;           /**< GMAT_* bits: set by gmaterial_init and the node kit; 0 in a header made
                                   without them, which only costs speed */
};

/* ---- the methods, written once ----
 *
 * GMATERIAL_METHODS(X) applies X to each method of the interface, in the order of GMaterialClass's slots (a method
 * is only ever appended), as X(name, NAME, type, attr, unless, dispatch, blend, params, args):
 *   name      the slot; the suffix of gmaterial_<name> (below) and of the node kit's gnode_child_<name>,
 *             gnode_blended_<name> and gnode_blend_<name> (node_kit.h)
 *   NAME      the same in capitals: GNODE_<NAME> (GNodeMethod, nodes.h)
 *   type      the result: int (a status; for the direction methods and opaque and is_delta 1 or 0) or double
 *   attr      GENERIC_NODISCARD when the result must be read, else empty
 *   unless    the GMAT_* bit with which gmaterial_<name> answers the default without calling the class (0: none)
 *   dispatch  call: gmaterial_<name> calls the slot, or answers the default for a NULL slot (lib/core/material.c,
 *             default_<name>); own: gmaterial_<name> has a body of its own (sample checks its numbers first and
 *             blackens the weight of a draw that fails)
 *   blend     pick: a blend node asks its pick for GNODE_<NAME> and the blend's gnode_blend_<name> answers;
 *             sampled: no GNodeMethod, the method follows the blends of reflection and refraction
 *             (gnode_blended_<name> of its own in lib/kit/node_kit.c)
 *   params    the parameters after the material, parenthesised; args: their names, parenthesised
 * The slots, the dispatch functions, GNodeMethod and its names and the node kit's forwarding methods are generated
 * from it. A method is added with its line here, its default_<name> in lib/core/material.c and, for a picked
 * method, its blend rule gnode_blend_<name> in lib/kit/node_blend.c; GMATERIAL_ABI_VERSION rises with it. */
#define GMATERIAL_METHODS(X)                                                                                           \
    /** Light leaving towards out when light illum arrives from in (see the top of this file). Default: black. */      \
    X(reflection, REFLECTION, int, GENERIC_NODISCARD, 0, call, pick,                                                   \
      (GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out, GColor *result), (sp, in, illum, out, result))        \
    /** The same for light arriving through the surface from in; rel_index is n(from) / n(to) at sp. Default:          \
     * black. */                                                                                                       \
    X(refraction, REFRACTION, int, GENERIC_NODISCARD, 0, call, pick,                                                   \
      (GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *rel_index, GVec3 out, GColor *result),             \
      (sp, in, illum, rel_index, out, result))                                                                         \
    /** Wavelength-dependent refraction index (sp may be NULL for a homogeneous material). Default: 1, and 1 for       \
     * m == NULL (vacuum). */                                                                                          \
    X(refraction_index, REFRACTION_INDEX, int, GENERIC_NODISCARD, 0, call, pick, (GSurfPoint *sp, GColor *result),     \
      (sp, result))                                                                                                    \
    /** Ideal reflection direction for the incident direction view: 1 when valid, 0 when not. Default: not valid,     \
     * without a call to the class when m has GMAT_NO_IDEAL. */                                                        \
    X(reflection_dir, REFLECTION_DIR, int, GENERIC_NODISCARD, GMAT_NO_IDEAL, call, pick,                               \
      (GSurfPoint *sp, GVec3 view, GVec3 *dir), (sp, view, dir))                                                       \
    /** Ideal refraction direction: 0 on total internal reflection or through an opaque material. Default: not         \
     * valid, without a call to the class when m has GMAT_NO_IDEAL. */                                                 \
    X(refraction_dir, REFRACTION_DIR, int, GENERIC_NODISCARD, GMAT_NO_IDEAL, call, pick,                               \
      (GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir), (sp, view, rel_index, dir))                   \
    /** Light emitted towards out. Default: black, without a call to the class when m has GMAT_NO_EMISSION. */         \
    X(emission, EMISSION, int, GENERIC_NODISCARD, GMAT_NO_EMISSION, call, pick,                                        \
      (GSurfPoint *sp, GVec3 out, GColor *result), (sp, out, result))                                                  \
    /** Ambient light illum reflected. Default: diffuse times illum. */                                                \
    X(ambient, AMBIENT, int, GENERIC_NODISCARD, 0, call, pick, (GSurfPoint *sp, const GColor *illum, GColor *result),  \
      (sp, illum, result))                                                                                             \
    /** What is left of illum after `length` through the material as a medium (sp may be NULL). Default: illum         \
     * (m == NULL: vacuum, nothing absorbed), without a call to the class when m has GMAT_CLEAR: result gets illum's   \
     * kind and samples bit for bit (nothing is copied when result is illum), for any length. */                       \
    X(absorption, ABSORPTION, int, GENERIC_NODISCARD, GMAT_CLEAR, call, pick,                                          \
      (GSurfPoint *sp, const GColor *illum, double length, GColor *result), (sp, illum, length, result))               \
    /** Shading normal, uncached (renderers call gsurfpoint_normal, which caches it). Default: sp->geometric_normal,   \
     * without a call to the class when m has GMAT_GEOMETRIC_NORMAL. */                                                \
    X(normal, NORMAL, int, GENERIC_NODISCARD, GMAT_GEOMETRIC_NORMAL, call, pick, (GSurfPoint *sp, GVec3 *n), (sp, n))  \
    /** Lambertian diffuse colour (previews, the default sampling). Default: black. */                                 \
    X(diffuse, DIFFUSE, int, GENERIC_NODISCARD, 0, call, pick, (GSurfPoint *sp, GColor *result), (sp, result))         \
    /** 1 when opaque, 0 when light passes through. Default: 1, without a call to the class when m has                 \
     * GMAT_OPAQUE. */                                                                                                 \
    X(opaque, OPAQUE, int, GENERIC_NODISCARD, GMAT_OPAQUE, call, pick, (GSurfPoint *sp), (sp))                         \
    /** Draws `in` for light leaving towards out from u1, u2 in [0, 1) (see the top of this file): fills s and         \
     * weight (value / pdf, storage of m's model); 1 when a direction was drawn, 0 when none (nothing is passed        \
     * on), or a negative status; rel_index as for refraction_dir. Default: the lobes of the methods above; m ==       \
     * NULL (vacuum) draws nothing. */                                                                                 \
    X(sample, SAMPLE, int, GENERIC_NODISCARD, 0, own, sampled,                                                         \
      (GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1, double u2, GMaterialSample *s, GColor *weight),  \
      (sp, out, rel_index, u1, u2, s, weight))                                                                         \
    /** The density (per unit solid angle) with which sample draws in for out, non-delta lobes only. Default: that     \
     * of the default sampling; 0 for m == NULL. */                                                                    \
    X(pdf, PDF, double, , 0, call, sampled, (GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index),            \
      (sp, in, out, rel_index))                                                                                        \
    /** 1 when every lobe at sp is ideal (a mirror, clear glass): light samples would reflect nothing. Default: 0,     \
     * without a call to the class when m has GMAT_LAMBERTIAN. */                                                      \
    X(is_delta, IS_DELTA, int, GENERIC_NODISCARD, GMAT_LAMBERTIAN, call, sampled, (GSurfPoint *sp), (sp))

/** (first, the list's items): a parameter or argument put before a parenthesised list of GMATERIAL_METHODS, e.g.
 * GMATERIAL_WITH(m, (sp, out)) is (m, sp, out). */
#define GMATERIAL_WITH(first, list) GMATERIAL_WITH_(first, GMATERIAL_UNPAREN_ list)
#define GMATERIAL_WITH_(first, ...) (first, __VA_ARGS__)
#define GMATERIAL_UNPAREN_(...) __VA_ARGS__

#define GMATERIAL_SLOT_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    type(*name) GMATERIAL_WITH(const GMaterial *self, params);

/** The material vtable: its header, destroy, and a slot `type (*name)(const GMaterial *self, params)` for each of
 * GMATERIAL_METHODS, in its order. A NULL slot takes the method's default. */
struct GMaterialClass {
    int abi_version;         /**< GMATERIAL_ABI_VERSION */
    const char *name;        /**< type keyword */
    const char *description; /**< one line for listings */
    /** Frees the instance (called when the last reference goes). */
    void (*destroy)(GMaterial *self);
    GMATERIAL_METHODS(GMATERIAL_SLOT_)
};

/** Fills the header of a new instance (refcount 1; flags: GMAT_NO_EMISSION when the class has no emission slot,
 * GMAT_OPAQUE when it has no opaque slot, GMAT_GEOMETRIC_NORMAL when it has no normal slot, GMAT_NO_IDEAL when it
 * has neither a reflection_dir nor a refraction_dir slot, GMAT_CONSTANT_INDEX when it has no refraction_index
 * slot, GMAT_CLEAR when it has no absorption slot); G_ERR_VERSION when
 * the class is of another version. */
GENERIC_API GENERIC_NODISCARD int gmaterial_init(GMaterial *m, const GMaterialClass *cls, const GColorModel *model,
                                                 GError *err);
/** Adds an owner; returns m. */
GENERIC_API GMaterial *gmaterial_ref(GMaterial *m);
/** Drops an owner and destroys the material with the last; NULL is a no-op. */
GENERIC_API void gmaterial_unref(GMaterial *m);
/** The material's type keyword. */
GENERIC_API const char *gmaterial_name(const GMaterial *m);

/** The dispatch of each method of GMATERIAL_METHODS: `type gmaterial_<name>(const GMaterial *m, params)` calls
 * m's slot, or answers the method's default (written beside it in the list) when the slot is NULL, m is NULL or m
 * has the method's `unless` bit. */
#define GMATERIAL_DECLARE_(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    GENERIC_API attr type gmaterial_##name GMATERIAL_WITH(const GMaterial *m, params);
GMATERIAL_METHODS(GMATERIAL_DECLARE_)

/** 1 when m may emit light (its emission slot is called), 0 when it has GMAT_NO_EMISSION or is NULL (vacuum):
 * a renderer may skip the emission of a 0 material altogether. */
GENERIC_API int gmaterial_emits(const GMaterial *m);
/** 1 when m has GMAT_OPAQUE, opaque at every point (gmaterial_opaque would say 1 wherever it is asked): a renderer
 * may then let any surface of m block a shadow ray without filling a surface point. 0 when it may let light
 * through somewhere (or cannot tell); NULL (vacuum) lets light through. */
GENERIC_API int gmaterial_opaque_everywhere(const GMaterial *m);
/** 1 when m has GMAT_LAMBERTIAN: its reflection of any light is diffuse(sp) times the light times
 * gmaterial_cos_in / pi, so the light of several samples may be summed (each times its cosine) and reflected at once.
 * 0 when it may not be (or cannot tell); NULL (vacuum) reflects nothing and is not. */
GENERIC_API int gmaterial_lambertian(const GMaterial *m);
/** 1 when m has GMAT_DIAGONAL: its reflection and refraction of any light are what they pass on of white light
 * times that light. 0 when they may not be (or it cannot tell); NULL (vacuum) passes nothing on and is not. */
GENERIC_API int gmaterial_diagonal(const GMaterial *m);
/** 1 when m has GMAT_NO_REL_INDEX: no method of m reads the relative index, so a renderer may skip computing it
 * and hand any colour (1 in every sample) as rel_index. 0 when some method may read it (or it cannot tell); NULL
 * (vacuum) reads none and is 1. */
GENERIC_API int gmaterial_no_rel_index(const GMaterial *m);
/** 1 when m has GMAT_CONSTANT_INDEX: its refraction_index is the same colour, bit for bit, at every point, so the
 * relative index between two such materials may be computed once. 0 when it may vary (or it cannot tell); NULL
 * (vacuum, index 1) is 1. */
GENERIC_API int gmaterial_constant_index(const GMaterial *m);
/** 1 when m has GMAT_CLEAR: as a medium it absorbs nothing, its absorption of any light is that light, bit for bit
 * (gmaterial_absorption writes it without calling the class), so a renderer may skip the call and the colour it
 * writes. 0 when it may absorb (or it cannot tell); NULL (vacuum) is 1. */
GENERIC_API int gmaterial_clear(const GMaterial *m);

/* ---- helpers for material implementations (lib/core/optics.c) ---- */

/** An orthonormal frame (t, b, n) around the unit vector n. */
GENERIC_API void goptics_frame(GVec3 n, GVec3 *t, GVec3 *b);
/** A cosine-distributed direction about the unit normal n from u1, u2 in [0, 1) (pdf cos / pi). */
GENERIC_API GVec3 goptics_sample_cosine(GVec3 n, double u1, double u2);
/** A uniformly distributed direction over the hemisphere about n from u1, u2 in [0, 1) (pdf 1 / (2 pi)). */
GENERIC_API GVec3 goptics_sample_hemisphere(GVec3 n, double u1, double u2);
/** A direction about the unit axis a distributed as cos^e(alpha) (alpha its angle with a, e >= 0) from u1, u2 in
 * [0, 1): a Phong lobe; its density is goptics_lobe_pdf. */
GENERIC_API GVec3 goptics_sample_lobe(GVec3 a, double e, double u1, double u2);
/** The density per unit solid angle of goptics_sample_lobe: (e + 1) / (2 pi) cos^e(alpha), 0 behind the axis. */
GENERIC_API double goptics_lobe_pdf(GVec3 a, double e, GVec3 dir);

/** 1 when out is the ideal mirror direction of in about n (within 1e-6 in cosine). */
GENERIC_API GENERIC_NODISCARD int gmaterial_is_mirror_pair(GVec3 in, GVec3 n, GVec3 out);
/** Ideal refraction of the incident direction view through normal n (facing the incident side) with
 * relative index eta = n_from / n_to; 0 on total internal reflection. */
GENERIC_API GENERIC_NODISCARD int goptics_refract(GVec3 view, GVec3 n, double eta, GVec3 *dir);
/** 1 when in is the ideal refraction of view through n with relative index eta (goptics_refract's direction,
 * within 1e-6 in cosine, as gmaterial_is_mirror_pair); 0 otherwise and on total internal reflection. No square
 * root but Snell's: what a material's refraction() asks of the pair it is given. */
GENERIC_API GENERIC_NODISCARD int goptics_is_refraction_pair(GVec3 view, GVec3 n, double eta, GVec3 in);
/** Unpolarised Fresnel reflectance for cos_i on the incident side and eta = n_from / n_to (1 past TIR). */
GENERIC_API double goptics_fresnel(double cos_i, double eta);

#ifdef __cplusplus
}
#endif
#endif
