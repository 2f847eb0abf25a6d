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

#endif
