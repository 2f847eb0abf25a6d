/* color_map.h - per-sample kernels: a material computes a function of one, two or three colours sample by sample
 * (a Fresnel term of n and k, an interference term of a film's index) without knowing the colour model. The kit owns
 * the loop over the model's samples.
 *
 * What a sample is, by model:
 *   - a model whose vectors the library reads as plain samples (its class gives no fill of its own: rgb, spectrum9,
 *     spectrum, bispectral and the kit-based models of gspectral_model_init) is mapped over its nvalues floats:
 *     rgb's three channels, spectrum9's nine knots, spectrum's and bispectral's wavelength samples. For rgb and
 *     spectrum9 that is the function applied to reduced values, not the reduction of the function (the rule by which
 *     a model reduces a spectral curve is the caller's to choose; see docs/reference/colour.md);
 *   - a re-radiation matrix (bispectral) operand is read by its plain part, the vector the model's pow(a, 1) gives
 *     (bispectral: the diagonal); the result is always a vector: a function of indices or reflectances re-radiates
 *     nothing;
 *   - any other model (one that gives its own fill, so its floats are not samples the library may read) takes the
 *     fallback: every operand is converted to the 1 nm exchange spectrum as a reflectance (gcolor_to_nm), the
 *     function is applied at each nm, and the result converted back (gcolor_from_nm): exact for a model that
 *     represents the result, a projection otherwise, and slower.
 * No call allocates: temporaries (a matrix's plain part) come from the thread's scratch arena (gscratch_thread). */
#ifndef GENERIC_KIT_COLOR_MAP_H
#define GENERIC_KIT_COLOR_MAP_H

#include "../export.h"
#include "../color.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A function of one sample of up to three colours (a, b, c: their values at one sample, 0 for an operand not
 * given) and the caller's parameters. */
typedef double (*GColorSampleFn)(double a, double b, double c, const void *params);

/** A function of n samples at once: out[i] = f(a[i], b[i], c[i]) for i < n (b or c NULL when not given); out may be
 * a, b or c. For kernels that a per-sample call would slow down. */
typedef void (*GColorSamplesFn)(float *out, const float *a, const float *b, const float *c, int n,
                                const void *params);

/** out = f(a, b, c, params) sample by sample (see the top of this file for what a sample is in each model); b and c
 * may be NULL, out may alias any operand. Status: G_OK; G_ERR_MISMATCH when the operands and out are not of one
 * model; G_ERR_INVALID for a NULL a, out or f; G_ERR_NOMEM when a matrix's temporary cannot be had; a conversion's
 * status in the fallback. */
GENERIC_API GENERIC_NODISCARD int gcolor_map(GColor *out, GColorSampleFn f, const void *params, const GColor *a,
                                             const GColor *b, const GColor *c);

/** gcolor_map with a kernel over arrays: f is called once with the model's samples (or, in the fallback, once with
 * the GNM_COUNT values of the nm spectrum). */
GENERIC_API GENERIC_NODISCARD int gcolor_map_samples(GColor *out, GColorSamplesFn f, const void *params,
                                                     const GColor *a, const GColor *b, const GColor *c);

#ifdef __cplusplus
}
#endif
#endif
