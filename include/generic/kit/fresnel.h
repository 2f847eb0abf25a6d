/* fresnel.h - Fresnel reflectance on colours, one pass over the samples (color_map.h says what a sample is in each
 * model): dielectric interfaces (a real relative index) and conductors (a complex index eta + i k), unpolarised.
 * The scalar forms are goptics_fresnel (material.h) and goptics_fresnel_conductor. */
#ifndef GENERIC_KIT_FRESNEL_H
#define GENERIC_KIT_FRESNEL_H

#include "../export.h"
#include "../color.h"

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

/** out = the dielectric Fresnel reflectance goptics_fresnel(cos_i, eta) sample by sample, eta the relative index
 * n(from) / n(to) in each sample (1 past total internal reflection). Status as gcolor_map. */
GENERIC_API GENERIC_NODISCARD int gmaterial_fresnel_dielectric(GColor *out, double cos_i, const GColor *eta);

#ifdef __cplusplus
}
#endif
#endif
