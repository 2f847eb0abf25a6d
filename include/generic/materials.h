/* materials.h - constructors of the built-in materials (the files in materials/).
 *
 * Every constructor takes the colour model the material computes in, checks its parameters (NaN,
 * negative or energy-creating values are refused with a message naming the parameter and the value),
 * copies the colours it is given into storage it owns (converting them through the nm spectrum when
 * they are of another model), and returns a material with one reference: release it with
 * gmaterial_unref. The model must outlive the material.
 *
 * Conventions shared by all of them (see material.h for the interface itself):
 *   - directions are unit vectors; `in` and `out` point away from the surface;
 *   - the shading normal is gsurfpoint_normal(sp); a BRDF is zero unless `in` and `out` are both on the
 *     side of the geometric normal (which faces the incident ray), and cosines are taken with the
 *     shading normal and clamped at zero;
 *   - "aligned" means gmaterial_is_mirror_pair(in, n, out) (for refraction: `in` is the ideal refraction
 *     of -out within the same 1e-6 tolerance in cosine): the perfect specular case of the paper, where
 *     `illum` is the radiance traced along the ideal ray and the result is that radiance times the
 *     specular reflectance or transmittance;
 *   - a material that sums others (a texture node blending its children, node_kit.h) keeps the rule at a pair
 *     aligned with its own ideal ray: only the parts that have an ideal ray of their own there answer
 *     (reflection_dir, or refraction_dir, returns 1 for them), each with its own aligned case; a part without
 *     one (lambert, a Phong lobe without `mirror`, the fluorescent materials) has no delta part, and its BRDF
 *     value, a density, adds nothing there. Where the sum has no ideal ray every part is an ordinary BRDF, and
 *     all are summed;
 *   - the surface point must have its geometric normal set, and an arena (sp->scratch) for the methods
 *     that need temporaries (phong reflection; dielectric absorption in place uses it when there is one);
 *     temporaries are released before returning and nothing is allocated per call;
 *   - the dielectric reads the media on both sides from sp->from and sp->to (NULL = vacuum).
 */
#ifndef GENERIC_MATERIALS_H
#define GENERIC_MATERIALS_H

#include "export.h"
#include "color.h"
#include "material.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- lambert ---- */

/** Ideal diffuse reflector with reflectance rho in [0, 1]: f_r = rho / pi, so reflection is
 * rho / pi * cos(theta_in) * illum; diffuse() is rho and ambient() is rho * illum. */
GENERIC_API GENERIC_NODISCARD int glambert_create(const GColorModel *model, const GColor *reflectance, GMaterial **out,
                                                  GError *err);

/* ---- phong ---- */

/** Parameters of the energy-normalised Phong material. */
typedef struct GPhongParams {
    const GColor *kd;     /**< diffuse reflectance (NULL = black) */
    const GColor *ks;     /**< glossy reflectance (NULL = black) */
    double exponent;      /**< Phong exponent n >= 0 */
    const GColor *mirror; /**< reflectance of the ideal reflection ray (NULL = none: no reflection ray) */
} GPhongParams;

/** Normalised Phong: f_r = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha), alpha between out and the mirror
 * direction of in, which makes the directional-hemispherical reflectance kd + ks at normal incidence
 * (and less at grazing angles, where the lobe is cut by the horizon). With a non-black `mirror`
 * reflection_dir is valid and the aligned case of reflection returns mirror * illum. kd + ks + mirror
 * must not exceed 1 in any sample (energy conservation); when one of them is a re-radiation matrix, in what
 * the sum sends out per excitation sample, its column sums (gmaterial_param_check_sum). diffuse() is kd;
 * ambient() reflects (kd + ks + mirror) * illum, the material's albedo at normal incidence. */
GENERIC_API GENERIC_NODISCARD int gphong_create(const GColorModel *model, const GPhongParams *params, GMaterial **out,
                                                GError *err);

/* ---- mirror ---- */

/** Perfect specular reflector with reflectance R in [0, 1]: reflection_dir is the ideal direction,
 * reflection returns R * illum for an aligned pair and black otherwise. As in the paper's example of a
 * perfect mirror, ambient() reflects R * illum; diffuse() is black. */
GENERIC_API GENERIC_NODISCARD int gmirror_create(const GColorModel *model, const GColor *reflectance, GMaterial **out,
                                                 GError *err);

/* ---- dielectric ---- */

/** How a refraction index depends on the wavelength. */
typedef enum GDispersionKind {
    GDISPERSION_CONSTANT = 0, /**< n = c[0] */
    GDISPERSION_CAUCHY,       /**< n = A + B / l^2 + C / l^4, l in micrometres; c = {A, B, C} */
    GDISPERSION_SELLMEIER     /**< n^2 = 1 + sum_i B_i l^2 / (l^2 - C_i), l in micrometres;
                                   c = {B1, B2, B3, C1, C2, C3} (C in square micrometres) */
} GDispersionKind;

/** A dispersion formula and its coefficients. */
typedef struct GDispersion {
    GDispersionKind kind;
    double c[6];
} GDispersion;

/** A wavelength-independent index n. */
GENERIC_API GDispersion gdispersion_constant(double n);
/** Cauchy's formula n = A + B / l^2 + C / l^4 (l in micrometres; B in um^2, C in um^4). */
GENERIC_API GDispersion gdispersion_cauchy(double a, double b, double c);
/** Sellmeier's formula with three terms (b: dimensionless, c: um^2), e.g. the Schott glass catalogue's. */
GENERIC_API GDispersion gdispersion_sellmeier(const double b[3], const double c[3]);
/** The index at a wavelength in nm (NaN for an unknown kind). */
GENERIC_API double gdispersion_index(const GDispersion *d, double nm);
/** Checks that the coefficients are finite and that the index is finite and positive over the nm
 * exchange range (GNM_MIN..GNM_MAX); G_ERR_INVALID with a message naming the coefficient otherwise. */
GENERIC_API GENERIC_NODISCARD int gdispersion_check(const GDispersion *d, GError *err);

/** Parameters of a dielectric (glass, water, ...). */
typedef struct GDielectricParams {
    GDispersion index;        /**< refraction index of the material */
    const GColor *absorption; /**< absorption coefficient per unit length, >= 0 (NULL = clear) */
    const GColor *tint;       /**< factor on the reflected light in [0, 1] (NULL = none) */
} GDielectricParams;

/** The roughness of a rough dielectric (gdielectric_create_rough). */
typedef struct GDielectricRoughness {
    double roughness_u; /**< microfacet roughness in [0, 1] along dpdu (alpha = roughness, kit/microfacet.h); both
                             widths below GMICROFACET_ALPHA_MIN: smooth */
    double roughness_v; /**< the same along dpdv (equal to roughness_u: isotropic) */
    int distribution;   /**< GMicrofacetDistribution (kit/microfacet.h): 0 GGX, 1 Beckmann */
    int uncompensated;  /**< 1: single scattering only; 0: the multiple scattering compensated */
} GDielectricRoughness;

/** Smooth dielectric interface with unpolarised Fresnel reflection and Beer-Lambert absorption.
 *  - refraction_index: n(lambda) in the material's model. Spectral models (nsamples > 0) get the nm
 *    spectrum of n(lambda) through gcolor_from_nm; non-spectral models get the three values
 *    n(610 nm), n(550 nm), n(465 nm) through gcolor_from_rgb, which the rgb model stores as they are
 *    (converting the spectrum to rgb would integrate it against D65 and mix the channels, which is
 *    meaningless for an index).
 *  - reflection_dir: always valid; refraction_dir: Snell's law with the scalar eta =
 *    brightness(rel_index) (n_from / n_to), 0 past the critical angle.
 *  - reflection, aligned: F * illum (* tint), F = goptics_fresnel(cos, gsurfpoint_relative_index(sp)),
 *    which is 1 under total internal reflection; black when not aligned.
 *  - refraction, aligned: (1 - F) * illum with eta from rel_index (NULL rel_index: the surface
 *    point's relative index); black when not aligned. Radiance is not rescaled by eta^2.
 *  - absorption: illum * exp(-a * length) per sample (the transmittance exp(-a) is computed once).
 *  - opaque: no; diffuse and ambient: black.
 * Rough (gdielectric_create_rough with a roughness at or above GMICROFACET_ALPHA_MIN): no ideal rays
 * (reflection_dir and refraction_dir say none, but refraction_dir goes straight on where the relative index is 1);
 * reflection and refraction are Walter et al.'s
 * microfacet BSDF with the scalar relative index (kit/microfacet_dielectric.h: radiance not rescaled by eta^2, as
 * above), sampled by visible normals with a Fresnel choice; pdf is that density; is_delta only where the relative
 * index is 1 (the light goes straight on, all of it). Unless uncompensated, the refraction is multiplied by
 * (1 - R) / T, R and T the single-scattering albedos of the lossless interface's reflection and refraction at
 * (cos theta_out, eta) (a table made at creation, kit/microfacet_dielectric.h): the light the microfacet model loses
 * to multiple scattering is given back in the refraction's lobe, so that a lossless interface keeps all of it while
 * its reflection stays single scattering and reciprocal. The error of this simple form: all of the multiply
 * scattered light leaves as refracted light (part of it would leave as reflected light), and the factor is held
 * within [1, 2], so that near and past the critical angle from inside, where the refraction has almost no lobe to
 * carry it, part of the light stays lost. Anisotropic widths use
 * the table of their geometric mean, and need dpdu (not GMAT_NO_UV). A roughness outside [0, 1] or an unknown
 * distribution is refused naming the parameter (roughness_u, roughness_v, distribution); rough NULL is smooth
 * (gdielectric_create). */
GENERIC_API GENERIC_NODISCARD int gdielectric_create_rough(const GColorModel *model, const GDielectricParams *params,
                                                           const GDielectricRoughness *rough, GMaterial **out,
                                                           GError *err);
/** The smooth dielectric: gdielectric_create_rough without roughness. */
GENERIC_API GENERIC_NODISCARD int gdielectric_create(const GColorModel *model, const GDielectricParams *params,
                                                     GMaterial **out, GError *err);

/* ---- thindielectric ---- */

/** A thin dielectric pane of index n (the brightness of `index` in the model, checked by gdispersion_check) with
 * the same medium on both sides: one face reflects F = goptics_fresnel(cos, 1 / n), and the light reflected between
 * the two faces sums to the pane's reflectance R = F + (1 - F)^2 F / (1 - F^2) = 2 F / (1 + F) and transmittance
 * 1 - R (no absorption). reflection_dir: the mirror direction; refraction_dir: the view direction itself (no
 * offset, no refraction). reflection, aligned: R * illum; refraction, aligned (in = -out): (1 - R) * illum, whatever
 * rel_index; black when not aligned. Delta lobes only (is_delta); not opaque; refraction_index: the default 1 (the
 * pane changes no medium). */
GENERIC_API GENERIC_NODISCARD int gthindielectric_create(const GColorModel *model, const GDispersion *index,
                                                         GMaterial **out, GError *err);

/* ---- emitter ---- */

/** Light source surface with radiance L (a light colour, finite and >= 0). emission is L towards out
 * on the front of the surface, the object's outside (the side of the geometric normal when
 * sp->entering, the other side when not), or on both sides with two_sided != 0; reflection and
 * diffuse are black. */
GENERIC_API GENERIC_NODISCARD int gemitter_create(const GColorModel *model, const GColor *radiance, int two_sided,
                                                  GMaterial **out, GError *err);

#ifdef __cplusplus
}
#endif
#endif
