/* fluorescent.h - fluorescent materials after Wilkie, Weidlich, Larboulette and Purgathofer, "A Reflectance
 * Model for Diffuse Fluorescent Surfaces": a parametric re-radiation matrix, the fluorescent Phong-Lambert
 * and layered-varnish materials.
 *
 * Re-radiation matrices come in as GReradiation (color.h): measured (a Labsphere BFC file) or made by
 * gfluor_matrix_create from a few band parameters. A material turns the matrix into a colour of its model
 * with gcolor_from_reradiation: a GCOLOR_MATRIX in the bispectral model (light changes wavelength), a 3 x 3
 * GCOLOR_MATRIX in rgb (the non-orthogonal reduction, gcolormodel_reduce_reradiation: blue light falling on a
 * day-glo orange comes back red, and the colour under D65 is the bispectral one), a plain reflectance in spectrum9
 * and spectrum: the matrix's response to an equal-energy light, i.e. for each emission wavelength the sum of its
 * row over the excitations within 380..780 nm, converted as a reflectance. fluorescent-varnish hands over its whole
 * base term (I - F_int M)^-1 M, so the re-fluorescence of internally reflected light is kept in every model.
 * The materials' code only uses the generic colour operations (mul, scale, add, add_scaled on values of the
 * material's model), so the same code serves a matrix and a vector value.
 *
 * Matrix convention (color.h): data[o * n_in + i] maps excitation sample i to emission sample o, so a
 * light L sampled on the excitation grid gives L_out(o) = sum_i data[o][i] L(i). With equal in and out steps
 * the column sum sum_o data[o][i] is the share of the energy at excitation i that is reflected or
 * re-emitted; an energy-conserving matrix has column sums <= 1. Measured matrices carry small negative
 * noise: everything here clamps negative entries to 0 before use. */
#ifndef GENERIC_FLUORESCENT_H
#define GENERIC_FLUORESCENT_H

#include "export.h"
#include "color.h"
#include "material.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================================================
 * Parametric re-radiation matrix
 * ====================================================================================================== */

/** A fluorescent pigment described by its bands. All lengths in nm.
 *
 * The absorption band is a flat-topped (super-Gaussian) band
 *     a(l) = absorb_max exp(-|l - absorb_peak|^absorb_shape / (2 absorb_width^absorb_shape)),
 * a Gaussian of standard deviation absorb_width for absorb_shape 2, flatter with sharper edges above (pigments
 * such as day-glo orange absorb evenly from the ultraviolet to an edge). Light that is not absorbed is
 * reflected at its own wavelength with `reflectance` (the diagonal: reflectance * (1 - a(l))). Of the photons
 * absorbed at l_in, a share quantum_yield is re-emitted with the emission band's shape, a Gaussian of standard
 * deviation emit_width centred at absorb_peak + stokes_shift, restricted to l_out > l_in (emission at longer
 * wavelengths only) and renormalised over that range; each photon carries the energy ratio l_in / l_out.
 * So the column sum at l_in is
 *     reflectance (1 - a) + a * quantum_yield * <l_in / l_out>  <=  1:
 * the matrix never creates energy (the Stokes loss l_in / l_out < 1 goes to heat). */
typedef struct GFluorBands {
    double absorb_peak;   /**< centre of the absorption band (default 470) */
    double absorb_width;  /**< half width: a falls to absorb_max e^(-1/2) this far from the peak (default 115) */
    double absorb_shape;  /**< edge exponent, in [1, 64]: 2 a Gaussian, larger flatter (default 8) */
    double absorb_max;    /**< share of the light absorbed at the peak, in [0, 1] (default 0.97) */
    double emit_width;    /**< standard deviation of the emission band (default 20) */
    double stokes_shift;  /**< emission peak minus absorption peak, >= 0 (default 135) */
    double quantum_yield; /**< photons emitted per photon absorbed, in [0, 1] (default 0.65) */
    double reflectance;   /**< reflectance of the light that is not absorbed, in [0, 1] (default 0.92) */
} GFluorBands;

/** Fills b with the defaults: a day-glo orange close to the measured HERPIORA.BFC (absorbs up to an edge near
 * 580 nm, emits around 605 nm). */
GENERIC_API void gfluor_bands_default(GFluorBands *b);
/** Checks every field (finite and within the documented ranges, widths > 0); G_ERR_INVALID with a message
 * naming the field otherwise. */
GENERIC_API GENERIC_NODISCARD int gfluor_bands_check(const GFluorBands *b, GError *err);
/** Makes the matrix of b on the square grid min_nm + k * step_nm, k = 0..n-1 (in and out alike) into new
 * storage (free it with gfluor_matrix_free). */
GENERIC_API GENERIC_NODISCARD int gfluor_matrix_create(const GFluorBands *b, double min_nm, double step_nm, int n,
                                                       GReradiation *out, GError *err);
/** Copies only the main diagonal of src (the entries whose excitation and emission wavelengths coincide;
 * negatives clamped to 0) into a new matrix on src's grid: a non-fluorescent version of the same pigment. */
GENERIC_API GENERIC_NODISCARD int gfluor_matrix_diagonal(const GReradiation *src, GReradiation *out, GError *err);
/** Frees storage from gfluor_matrix_create/gfluor_matrix_diagonal and clears r; NULL and cleared are no-ops. */
GENERIC_API void gfluor_matrix_free(GReradiation *r);
/** The main diagonal of r (negatives clamped to 0) as a reflectance on the nm exchange grid: linear between
 * the emission samples, held constant beyond the ends; 0 where no excitation sample coincides. */
GENERIC_API GENERIC_NODISCARD int gfluor_matrix_diagonal_nm(const GReradiation *r, GSpectrumNM *out, GError *err);
/** Largest column sum of r (negatives clamped to 0) over the excitation samples within [lo_nm, hi_nm]:
 * the most energy the matrix returns per unit of incident energy (<= 1 for a conserving matrix). */
GENERIC_API double gfluor_matrix_max_column_sum(const GReradiation *r, double lo_nm, double hi_nm);

/* ======================================================================================================
 * The normalised Blinn microfacet distribution
 * ====================================================================================================== */

/** D(h) = (m + 2) / (2 pi) (h.n)^m for cos_h = h.n > 0, else 0; normalised so that the integral of
 * D(h) (h.n) over the hemisphere of h is 1. */
GENERIC_API double gfluor_blinn_d(double m, double cos_h);
/** Mean slope angle in degrees of the Blinn distribution with exponent m: the mean of the facet tilt
 * theta_h under the distribution of projected facet area D(h) (h.n) dw_h. m = 15.3 gives the paper's 17 degrees. */
GENERIC_API double gfluor_blinn_mean_slope(double m);
/** The exponent m whose mean slope angle (gfluor_blinn_mean_slope) is slope_deg, for 0 < slope_deg < 45
 * (45 degrees is the mean slope of m = 0); NaN outside that range. */
GENERIC_API double gfluor_blinn_exponent(double slope_deg);

/* ======================================================================================================
 * Materials
 * ====================================================================================================== */

/** Parameters of fluorescent-phong. */
typedef struct GFluorPhongParams {
    double ks;          /**< albedo of the specular lobes together, in [0, 1) (default 0.04) */
    double exponent[3]; /**< exponents of the three Phong lobes, >= 1 (default 30, 120, 480) */
    double weight[3];   /**< share of ks per lobe, >= 0, summing to 1 (default 0.2, 0.3, 0.5) */
} GFluorPhongParams;

/** Fills p with the defaults: a weak, small specular lobe as in the paper's Fig. 6. */
GENERIC_API void gfluor_phong_default(GFluorPhongParams *p);

/** fluorescent-phong, the paper's section 5.1: a Lambertian term with the full matrix M plus a weak
 * specular lobe of three Phong lobes that reflect with the matrix's main diagonal d only:
 *     f_r = (1 - ks) M / pi + d * ks * sum_k w_k (n_k + 1) / (2 pi) cos^n_k(alpha) / max(cos_in, cos_out),
 * alpha between out and the mirror direction of in. The max() denominator (as in Ashikhmin-Shirley's
 * lobe) keeps the lobe reciprocal and makes its directional albedo about w_k ks at every angle of incidence
 * until the lobe reaches the horizon, and at most w_k ks: the split between specular and diffuse stays the
 * same at every angle, which is what the paper criticises in this model. Energy: albedo <= ks d + (1 - ks)
 * colsum(M) <= 1 for a conserving M. diffuse() is (1 - ks) M; ambient() is ((1 - ks) M + ks d) illum.
 * In rgb M arrives reduced to a 3 x 3 matrix, in spectrum9 and spectrum folded into a reflectance, and d as a
 * reflectance: nothing changes in the code. `matrix` may be freed after the call. */
GENERIC_API GENERIC_NODISCARD int gfluor_phong_create(const GColorModel *model, const GReradiation *matrix,
                                                      const GFluorPhongParams *params, GMaterial **out, GError *err);

/** Parameters of fluorescent-varnish. */
typedef struct GFluorVarnishParams {
    double ior;        /**< refraction index of the varnish, in (1, 4] (default 1.5) */
    double exponent;   /**< Blinn exponent m >= 0; when 0 the exponent comes from slope_deg */
    double slope_deg;  /**< mean slope angle of the facets (default 17, the paper's Fig. 10) */
} GFluorVarnishParams;

/** Fills p with the defaults (index 1.5, mean slope 17 degrees, exponent 0 = from the slope). */
GENERIC_API void gfluor_varnish_default(GFluorVarnishParams *p);

/** fluorescent-varnish, the paper's section 5.2: rough transparent Fresnel facets (normalised Blinn
 * distribution) over a thin clear varnish over a fluorescent Lambertian base with the full matrix; the
 * energy leaves where it enters. The formula is in the comment block at the top of
 * materials/fluorescent/fluorescent_varnish.c; in short
 *     f_r = F(i.h) D(h) G / (4 cos_in cos_out)
 *         + (1 - R(cos_in)) (1 - R(cos_out)) / (pi ior^2) * (I - F_int M)^-1 M,
 * R the directional albedo of the facet reflection, F_int = 1 - (1 - R_avg) / ior^2 the share of the
 * diffuse light inside the varnish that the top boundary sends back to the base. Reciprocal, and energy
 * conserving for a conserving M. diffuse() is the base part's albedo for diffuse light; ambient() is
 * diffuse() times illum. `matrix` may be freed after the call. */
GENERIC_API GENERIC_NODISCARD int gfluor_varnish_create(const GColorModel *model, const GReradiation *matrix,
                                                        const GFluorVarnishParams *params, GMaterial **out,
                                                        GError *err);

#ifdef __cplusplus
}
#endif
#endif
