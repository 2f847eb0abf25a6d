/* noise.h - noise sums shared by the noise-based generators (textures/noise.c). Internal. */
#ifndef GENERIC_TEXTURES_NOISE_H
#define GENERIC_TEXTURES_NOISE_H

#include "generic/textures.h"

/** Signed improved Perlin noise in about [-1, 1] (0 on the lattice); grad may be NULL. */
double gtexnoise_signed(unsigned seed, GVec3 p, GVec3 *grad);
/** Fractional Brownian motion: sum of octaves gain^i n(lacunarity^i p) over the sum of amplitudes, in
 * about [-1, 1]; every octave has its own seed so the lattices do not line up. grad (may be NULL) gets
 * the analytic gradient with respect to x. */
double gtexnoise_fbm(const GNoiseParams *p, GVec3 x, GVec3 *grad);
/** Perlin's turbulence: the same sum of |n|, in [0, 1] (grad: its gradient, one-sided at the creases). */
double gtexnoise_turbulence(const GNoiseParams *p, GVec3 x, GVec3 *grad);
/** Fills defaults into a copy of the parameters (frequency 1, octaves 4, lacunarity 2, gain 0.5, object
 * space) and checks them; messages name the generator. */
int gtexnoise_params(const char *name, const GNoiseParams *in, GNoiseParams *out, GError *err);
/** The gradient in the generator's space from one with respect to the coordinates (z dropped for uv). */
static inline GVec3 gtexnoise_space_grad(const GGenerator *g, GVec3 d)
{
    if (g->space == GGENERATOR_SPACE_UV)
        d.z = 0.0;
    return d;
}
/** The coordinates the generator reads in its space (u, v, 0 / object point / world point). */
GVec3 gtexnoise_coords(const GGenerator *g, const GSurfPoint *sp);

#endif
