/* texparam.h - textured parameters: a material parameter that is a constant or varies over the surface.
 *
 * A number parameter (GTexNumber) is a constant or a generator (texture.h; `range LO HI` maps its value, and the
 * reader applies it to every generator type). A colour parameter (GTexColor) is a constant colour, a mix of two
 * colours by a generator, or an image looked up at (u, v) (the texture system of services/texsys.h, the checks of
 * the image node) and uplifted in the parameter's role. Values at a point are memoised in the surface point's
 * cache (generators under their own address, an image's texel under the GTexColor's image), and a colour is
 * written into storage the caller takes from the point's scratch arena: nothing is allocated per ray. A constant
 * costs one test: gtexparam_number_at returns the constant, gtexparam_color_constant gives it.
 *
 * In a file:  NUMBER | GENERATOR                             exponent checker { dims 2 frequency 4 range 10 200 }
 *             COLOR | image { file PATH  wrap W  colorspace C  blur B } | mix { by GENERATOR  a COLOR  b COLOR } */
#ifndef GENERIC_TEXPARAM_H
#define GENERIC_TEXPARAM_H

#include "../export.h"
#include "../color.h"
#include "../error.h"
#include "../material.h"
#include "../nodes.h"
#include "../reader.h"
#include "../texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A number parameter: the constant `value`, or (gen != NULL) gen's value at the point clamped into [lo, hi]. */
typedef struct GTexNumber {
    double value;   /**< the constant (the generator's declared lower end when gen is set) */
    GGenerator *gen; /**< owned reference, or NULL for a constant */
    double lo, hi;  /**< the values the parameter accepts */
} GTexNumber;

/** A constant number parameter (no generator). */
static inline GTexNumber gtexparam_number_const(double value)
{
    GTexNumber n = {value, NULL, value, value};
    return n;
}
/** The value at sp: the constant, or the generator's value (memoised on sp: ggenerator_cached_value) clamped into
 * [lo, hi]. */
static inline double gtexparam_number_at(const GTexNumber *p, GSurfPoint *sp)
{
    if (!p->gen)
        return p->value;
    double v = ggenerator_cached_value(p->gen, sp);
    return v < p->lo ? p->lo : v > p->hi ? p->hi : v;
}
/** Reads a number parameter: a number in [lo, hi] (a constant) or a generator whose declared range
 * (ggenerator_declared_range) lies within [lo, hi] (else "<material>: <param> takes values in [lo, hi]; the
 * generator's range is [a, b]" at the generator). constant_only: a generator is refused at its position, "<material>:
 * <param> must be a constant number (it decides <why>)". *out is released first (gtexparam_number_release). */
GENERIC_API GENERIC_NODISCARD int gtexparam_read_number(GReader *r, double lo, double hi, int constant_only,
                                                        const char *material, const char *param, const char *why,
                                                        GTexNumber *out, GError *err);
/** Reads a parameter that must stay constant (it decides the material's structure at creation, or is used where no
 * surface point is known): a number in [lo, hi] into *out; a generator is refused at its position naming the
 * parameter and why (gtexparam_read_number with constant_only). */
GENERIC_API GENERIC_NODISCARD int gtexparam_read_constant(GReader *r, double lo, double hi, const char *material,
                                                          const char *param, const char *why, double *out,
                                                          GError *err);
/** Refuses a generator where a parameter read by other means (a formula, a choice) must stay constant: G_OK (nothing
 * read) when the next token does not begin a generator, else G_ERR_PARSE at it, "<material>: <param> must be
 * constant (<why>), not a generator". */
GENERIC_API GENERIC_NODISCARD int gtexparam_refuse_generator(GReader *r, const char *material, const char *param,
                                                             const char *why, GError *err);
/** Copies p into *out with a reference of its own to the generator. */
GENERIC_API void gtexparam_number_copy(GTexNumber *out, const GTexNumber *p);
/** Drops the generator's reference; *p becomes the constant 0. */
GENERIC_API void gtexparam_number_release(GTexNumber *p);
/** The smallest and largest values p takes: the constant twice, or the generator's declared range clamped into
 * [lo, hi]. */
GENERIC_API void gtexparam_number_bounds(const GTexNumber *p, double *min, double *max);

/** What a colour parameter is. */
typedef enum GTexColorKind {
    GTEXCOLOR_CONSTANT = 0, /**< the colour a */
    GTEXCOLOR_MIX,          /**< a (1 - t) + b t, t the generator's value clamped into [0, 1] */
    GTEXCOLOR_IMAGE         /**< an image's linear RGB at (u, v), uplifted in the role */
} GTexColorKind;

typedef struct GTexImage GTexImage;

/** A colour parameter in one colour model; vectors only (no re-radiation matrix varies over a surface). */
typedef struct GTexColor {
    GTexColorKind kind;
    GColorRole role;  /**< the role its colours are uplifted in */
    GColor a, b;      /**< the constant; a mix's two colours */
    GGenerator *by;   /**< a mix's weight (owned reference) */
    GTexImage *image; /**< an image lookup (owned) */
} GTexColor;

/** Reads a colour parameter in role: a colour (greader_color), `image { ... }` or `mix { ... }` (the top of this
 * file), into *out (released first), in the file's colour model. An image that cannot be read is refused at its
 * file name with the reason (the image node's checks: size, decode, memory budget). */
GENERIC_API GENERIC_NODISCARD int gtexparam_read_color(GReader *r, GColorRole role, GTexColor *out, GError *err);
/** Frees what *p holds (the colours, the generator's reference, the image); *p becomes empty. */
GENERIC_API void gtexparam_color_release(GTexColor *p);
/** The constant colour when p is constant, else NULL. */
static inline const GColor *gtexparam_color_constant(const GTexColor *p)
{
    return p->kind == GTEXCOLOR_CONSTANT ? &p->a : NULL;
}
/** The colour at sp into out (a colour of p's model, e.g. from sp's scratch arena): the constant copied, the mix,
 * or the image's texel (looked up once per point, then taken from sp's cache) uplifted in p's role. */
GENERIC_API GENERIC_NODISCARD int gtexparam_color_at(const GTexColor *p, GSurfPoint *sp, GColor *out);
/** The colours p can take at its extremes, for energy checks made once at creation: the constant; a mix's a and
 * b (every value between is their convex combination); an image's largest value in each channel
 * (gtexparam_image_channel_max), uplifted in the role. *n receives their number (1 or 2); each of out[0..*n-1]
 * is new storage of p's model (free with gcolor_free). */
GENERIC_API GENERIC_NODISCARD int gtexparam_color_extremes(const GTexColor *p, GColor out[2], int *n, GError *err);

/** Opens an image for lookups at (u, v) with the image node's loading and checks (gnode_image_create, nodes.h:
 * the texture system's size limit and decode, then one lookup of the finest level, so a truncated file fails here);
 * the colours of the three linear primaries in model m (role reflectance, as the image node reads a texel).
 * A spectral OpenEXR (services/image.h: reflective channels T.<nm>nm) is read whole instead, its texels' spectra
 * kept as floats at the file's wavelengths against the memory budget, looked up bilinearly (no MIP-mapping, no
 * blur) and converted per lookup with gcolor_from_nm; a `image { }` colour in the light role reads the emissive
 * channels (S0.<nm>nm); a file with only the other layer gives that one. An OpenEXR without spectral channels is
 * read as RGB. G_ERR_IO naming the file when it
 * cannot be read or decoded, or when a spectral value is NaN, infinite or negative; G_ERR_INVALID for unknown
 * options. */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_open(const char *path, const GImageNodeOptions *opt,
                                                       const GColorModel *m, GTexImage **out, GError *err);
/** Frees an image; NULL is a no-op. */
GENERIC_API void gtexparam_image_free(GTexImage *im);
/** Reads the value of an image option into *o when key is one (wrap, swrap, twrap, colorspace, blur: the image
 * node's and `image { }` colours' options): G_OK, or a G_ERR_ status placed at the value; 1 when key is none of
 * them (nothing read). */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_option(GReader *r, const char *key, GImageNodeOptions *o,
                                                         GError *err);
/** The linear texel at sp's (u, v) over its footprint, looked up once per point and then taken from sp's cache
 * (key: im); NaN, infinite and negative values become 0. A failed lookup is its status, never a black texel. */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_rgb(const GTexImage *im, GSurfPoint *sp, double rgb[3]);
/** rgb (a texel) as a colour of out's model in role: the primaries' colours mixed when the model's RGB uplift is
 * linear and role is reflectance (the image node's colour), else uplifted (gcolor_from_rgb). */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_uplift(const GTexImage *im, const double rgb[3], GColorRole role,
                                                         GColor *out);
/** The texel at sp's (u, v) as a colour of out's model in role: a spectral image's spectrum through gcolor_from_nm,
 * else gtexparam_image_rgb then gtexparam_image_uplift. */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_color(const GTexImage *im, GSurfPoint *sp, GColorRole role,
                                                        GColor *out);
/** The largest linear value of each channel, from the whole image read once (services/image.h: in the decoder
 * process, within the memory budget) on the first call; a status (the read's). Not thread safe: for creation. */
GENERIC_API GENERIC_NODISCARD int gtexparam_image_channel_max(GTexImage *im, double rgb[3], GError *err);

/** 1 when p's value reads the surface point's (u, v): a generator of (u, v); else 0 (for GMAT_NO_UV). */
GENERIC_API int gtexparam_number_reads_uv(const GTexNumber *p);
/** 1 when p's value reads the surface point's (u, v): an image, a mix by a generator of (u, v); else 0. */
GENERIC_API int gtexparam_color_reads_uv(const GTexColor *p);

/** The colour each of whose samples is 1 in model m, into new storage c: the unit of the sample-wise product. */
GENERIC_API GENERIC_NODISCARD int gtexparam_unit_color(const GColorModel *m, GColor *c);

/** A material that is child (made with the unit colour for its one colour parameter) times the colour p at each
 * point: every light-carrying result (reflection, refraction, emission, ambient, diffuse, a sample's weight) is
 * multiplied by p's colour at the point; directions, densities, normals and indices are the child's. Right for
 * a material whose results are linear in its one colour (lambert, mirror, emitter: gmaterial_param_parse_one_color).
 * Takes the child's reference and p's contents (also on failure; *p becomes empty). */
GENERIC_API GENERIC_NODISCARD int gtexparam_scaled_material(GMaterial *child, GTexColor *p, GMaterial **out,
                                                            GError *err);

/** What the reader does when the parse routine of a material reads a colour with greader_color and the file gives a
 * texture there (`image { ... }`, `mix { ... }`; one parameter per entry): the routine got the unit colour and made
 * m; m must be built on GMaterialOneColor (material_kit.h: its class's destroy is gmaterial_one_color_destroy),
 * whose results are linear in its colour, and each of p's extremes must lie in [0, 1] for a reflectance (>= 0
 * for a light), so that a material that holds the energy rule with the unit colour holds it with every value p
 * takes. Then *out is m scaled by p (gtexparam_scaled_material); else G_ERR_UNSUPPORTED or G_ERR_INVALID naming
 * param ("<material>: <param> cannot be textured ..."). Takes m's reference and p's contents in every case. */
GENERIC_API GENERIC_NODISCARD int gtexparam_texture_material(GMaterial *m, GTexColor *p, const char *material,
                                                             const char *param, GMaterial **out, GError *err);

/** A constructor of a material from one colour c in model m (ctx: the caller's other arguments). */
typedef int (*GTexParamCreate)(const GColorModel *m, const GColor *c, void *ctx, GMaterial **out, GError *err);
/** The material create makes with a textured colour p (a mix or an image) whose results are linear in it: create
 * is first called with each of p's extremes (gtexparam_color_extremes), so that the material's own checks (energy
 * conservation) hold for every value p takes, then with the unit colour, and that material is scaled by p at each
 * point (gtexparam_scaled_material). Takes p's contents (*p becomes empty). */
GENERIC_API GENERIC_NODISCARD int gtexparam_one_color_material(const GColorModel *model, GTexColor *p,
                                                               GTexParamCreate create, void *ctx, GMaterial **out,
                                                               GError *err);

#ifdef __cplusplus
}
#endif
#endif
