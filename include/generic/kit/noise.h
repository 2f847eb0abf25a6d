/* noise.h - the noise functions of the noise-based generators (textures/noise.c): improved Perlin noise with
 * its analytic gradient and its fractal sums, for the built-in perlin, fbm, turbulence, wood and marble
 * generators and for generators of one's own. */
#ifndef GENERIC_NOISE_H
#define GENERIC_NOISE_H

#include "../export.h"
#include "../error.h"
#include "../texture.h"
#include "../vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Parameters shared by the noise generators; zero fields take the defaults. */
typedef struct GNoiseParams {
    GGeneratorSpace space; /**< NONE (0) means object space */
    double frequency;      /**< features per unit (default 1) */
    unsigned seed;         /**< picks the permutation (default 0: the same noise in every run) */
    int octaves;           /**< fbm, turbulence, wood, marble (default 4 for wood/marble/fbm/turbulence) */
    double lacunarity;     /**< frequency factor per octave (default 2) */
    double gain;           /**< amplitude factor per octave (default 0.5) */
} GNoiseParams;

/** The improved gradient noise of Perlin (2002) mapped to [0, 1] as (1 + n) / 2; 0.5 at every lattice point.
 * The gradient is analytic. */
GENERIC_API double gnoise_perlin3(unsigned seed, double x, double y, double z, GVec3 *grad);

/** Signed improved Perlin noise in about [-1, 1] (0 on the lattice); grad (may be NULL) gets its gradient.
 * Defined for every point: the lattice wraps every 2^32 cells, and a non-finite point gives 0 (gradient 0). */
GENERIC_API double gnoise_signed(unsigned seed, GVec3 p, GVec3 *grad);

/** Fractional Brownian motion: sum of octaves gain^i n(lacunarity^i frequency x) over the sum of amplitudes,
 * in about [-1, 1]; every octave has its own seed so the lattices do not line up. grad (may be NULL) gets
 * the analytic gradient with respect to x. p must be complete (gnoise_params). */
GENERIC_API double gnoise_fbm(const GNoiseParams *p, GVec3 x, GVec3 *grad);

/** Perlin's turbulence: the same sum of |n|, in [0, 1] (grad: its gradient, one-sided at the creases). */
GENERIC_API double gnoise_turbulence(const GNoiseParams *p, GVec3 x, GVec3 *grad);

/** Fills the defaults into a copy of the parameters (frequency 1, octaves 4, lacunarity 2, gain 0.5, object
 * space; in may be NULL for all defaults) and checks them: G_ERR_INVALID, the message naming the generator
 * `name`, for an unknown space, a negative or non-finite frequency, lacunarity or gain, or octaves beyond 16. */
GENERIC_API GENERIC_NODISCARD int gnoise_params(const char *name, const GNoiseParams *in, GNoiseParams *out,
                                                GError *err);

#ifdef __cplusplus
}
#endif
#endif
