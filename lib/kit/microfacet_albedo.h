/* microfacet_albedo.h - the precomputed albedo tables behind gmicrofacet_albedo_table (generic/kit/microfacet.h),
 * written by scripts/gen_microfacet_albedo.c (lib/kit/microfacet_albedo_data.c). */
#ifndef GENERIC_LIB_KIT_MICROFACET_ALBEDO_H
#define GENERIC_LIB_KIT_MICROFACET_ALBEDO_H

#include "generic/kit/microfacet.h"

/** E(mu, alpha) per distribution (GGX 0, Beckmann 1): [d][a][i] at alpha = a / (N - 1), mu = i / (N - 1). */
extern const float gmicrofacet_albedo_e[2][GMICROFACET_ALBEDO_N][GMICROFACET_ALBEDO_N];
/** E_avg(alpha) = 2 * integral of E(mu) mu dmu of each row's linear interpolation: [d][a]. */
extern const float gmicrofacet_albedo_avg[2][GMICROFACET_ALBEDO_N];

#endif
