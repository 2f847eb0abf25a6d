/* rng.h - the tracer's random numbers (camera.c). */
#ifndef GTRACE_RNG_H
#define GTRACE_RNG_H

#include <stdint.h>

/** Small fast generator (PCG32), one per pixel so images do not depend on the thread count. */
typedef struct Rng {
    uint64_t state, inc;
} Rng;
/** Starts the generator at a seed on one of its streams. */
void rng_seed(Rng *r, uint64_t seed, uint64_t stream);
/** Uniform in [0,1). */
double rng_next(Rng *r);
/** SplitMix64's finaliser: a bijection of 64-bit integers that decorrelates neighbouring indices (pixels, samples,
 * photons) before they seed or index a sequence. */
static inline uint64_t rng_mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

#endif
