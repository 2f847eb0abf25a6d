/* fresnel.h - Fresnel reflectance on colours, one pass over the samples (color_map.h says what a sample is in each
 * model): dielectric interfaces (a real relative index) and conductors (a complex index eta + i k), unpolarised.
 * The scalar forms are goptics_fresnel (material.h) and goptics_fresnel_conductor. */
#ifndef GENERIC_KIT_FRESNEL_H
#define GENERIC_KIT_FRESNEL_H

#include "../export.h"
#include "../color.h"
#include "../colorspec.h"
#include "../error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Unpolarised Fresnel reflectance of a conductor of complex index eta + i k (relative to the medium the light
 * arrives in) for light arriving at cos_i (its absolute value is used, clamped to 1): the exact form for an
 * absorbing medium, the mean of the s and p reflectances. At normal incidence ((eta - 1)^2 + k^2) / ((eta + 1)^2 +
 * k^2); with k = 0 it is goptics_fresnel(cos_i, 1 / eta). In [0, 1] for eta > 0 and k >= 0. */
GENERIC_API double goptics_fresnel_conductor(double cos_i, double eta, double k);

/** out = the conductor's Fresnel reflectance at cos_i sample by sample, eta and k being colours of out's model that
 * hold the real and imaginary parts of the relative index in each sample (unitless values, not reflectances). Status
 * as gcolor_map (color_map.h). */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_conductor(GColor *out, double cos_i, const GColor *eta,
                                                              const GColor *k);

/** out = s * F + t * add sample by sample, F the conductor's Fresnel reflectance at cos_i of
 * gmaterial_fresnel_conductor (add may be NULL: out = s * F): a rough conductor's single-scattering term and its
 * multiple-scattering colour in one pass, in float arithmetic that the compiler vectorises (within 1e-6 of the double
 * form). Status as gcolor_map. */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_conductor_mix(GColor *out, double cos_i, const GColor *eta,
                                                                  const GColor *k, double s, const GColor *add,
                                                                  double t);

/** out = the dielectric Fresnel reflectance goptics_fresnel(cos_i, eta) sample by sample, eta the relative index
 * n(from) / n(to) in each sample (1 past total internal reflection). Status as gcolor_map. */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_dielectric(GColor *out, double cos_i, const GColor *eta);

/** A complex index n + i k measured over wavelength (eta_nm, k_nm on the nm exchange grid) as colours of eta's model (k
 * of the same model), by the rule for unitless quantities (GCOLOR_UNITLESS, color.h) with one addition for the pair:
 * in a model without wavelength samples (nsamples 0: rgb), or whose samples lie more than 10 nm apart (spectrum9), n
 * is reduced as the role says and k is then chosen sample by sample so that the normal-incidence reflectance ((n -
 * 1)^2 + k^2) / ((n + 1)^2 + k^2) is the model's reduction of the measured normal-incidence reflectance (k = 0 where n
 * alone reflects more). Measured against the spectral result (docs/reference/colour.md, "Unitless quantities",
 * tests/test_metals.c), this halves rgb's error for gold, divides copper's by six, and takes spectrum9's gold from
 * 0.98 to 0.07. G_ERR_MISMATCH for colours of two models; a conversion's status otherwise. */
GENERIC_API GENERIC_NODISCARD int gmaterial_complex_index_from_nm(GColor *eta, GColor *k, const GSpectrumNM *eta_nm,
                                                                  const GSpectrumNM *k_nm);

/** The complex index eta + i k (colours of one model, with storage) from two colour literals of n and k
 * (colorspec.h): two spectra by gmaterial_complex_index_from_nm (the pair's rule); otherwise each as a unitless colour
 * (gcolorspec_to_color, GCOLOR_UNITLESS). A literal its conversion refuses is named as the parameter "eta" or "k"
 * (gerror_set_param, the message "eta: why"); a failure of the pair's rule says the model it failed in. */
GENERIC_API GENERIC_NODISCARD int gmaterial_complex_index_from_specs(const GColorSpec *eta_spec,
                                                                     const GColorSpec *k_spec, GColor *eta, GColor *k,
                                                                     GError *err);

/* ---- a conductor's Fresnel reflectance tabulated per sample ---- */

/** Intervals of a GFresnelTable over u = sqrt(cos_h) (nodes at cos_h = (j / K)^2, dense towards grazing): with 1024
 * the lerp keeps within 1e-5 of the exact reflectance for every measured metal (kit/metals.h) at every 5 nm (the
 * worst, zinc at 560 nm, 6.7e-6 near grazing; tests/test_conductor.c measures it). */
#define GFRESNEL_TABLE_K 1024

/** A conductor's Fresnel reflectance (gmaterial_fresnel_conductor_mix's F) tabulated per sample at creation at
 * GFRESNEL_TABLE_K + 1 facet angles, for a rough surface that reads it at every evaluation: a lookup is the lerp of
 * two nodes per sample, exact at the nodes and at normal incidence; 4 bytes per sample and node. */
typedef struct GFresnelTable GFresnelTable;

/** Tabulates the conductor of complex index eta + i k (vectors of one model, as gmaterial_fresnel_conductor reads
 * them) into *out. G_ERR_UNSUPPORTED (nothing made) for a model whose values are not plain samples or an index that
 * is not a vector; G_ERR_MISMATCH for colours of two models; G_ERR_NOMEM. */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_table_create(const GColor *eta, const GColor *k,
                                                                 GFresnelTable **out);

/** Frees a table; NULL is a no-op. */
GENERIC_API void gmaterial_fresnel_table_destroy(GFresnelTable *t);

/** out = (s F(cos_h) + t_add add) light sample by sample in one pass, F the tabulated reflectance between the two
 * nodes about cos_h (clamped to [0, 1]); add NULL adds nothing, light NULL is white. add and light are vectors of
 * the table's model and out a colour of it, which may be light (sample i read before it is written); each step
 * rounds to float as gcolor_mul after the mix would. G_ERR_MISMATCH otherwise. */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_table_mix(const GFresnelTable *t, double cos_h, double s,
                                                              const GColor *add, double t_add, const GColor *light,
                                                              GColor *out);

#ifdef __cplusplus
}
#endif
#endif
