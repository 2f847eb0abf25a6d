/* sampler.h - the path tracer's sample values: a low-discrepancy sequence per pixel, or independent numbers
 * (sampler.c). */
#ifndef GTRACE_SAMPLER_H
#define GTRACE_SAMPLER_H

#include <stdint.h>

/** How a camera sample's random numbers are drawn (--sampler). */
enum {
    SAMPLER_SOBOL = 0,      /**< Owen-scrambled Sobol points, shuffled per pixel and per group of 4 dimensions */
    SAMPLER_INDEPENDENT = 1 /**< the pixel's PCG32 generator, seeded by the pixel's and the sample's index */
};

/** Dimensions in one group: the sequence's first four, which every group shares under its own shuffle and
 * scrambling. */
#define SAMPLER_GROUP_DIMS 4

/** The point of one camera sample: the pixel's seed (from its index in the full image) and the sample's index
 * among the pixel's samples; a value depends on these and its dimension only, never on the thread or the order of
 * the work. */
typedef struct SamplePoint {
    uint64_t pixel_seed;
    uint32_t index;
} SamplePoint;

/** The point of sample `index` of the pixel with index `pixel` (y * full width + x). */
SamplePoint sample_point(uint64_t pixel, uint32_t index);

/** The value of dimension `dim` (0 .. 2^31 - 1) of point p, in [0, 1). Dimensions 4g .. 4g + 3 form group g: the
 * first four dimensions of the Sobol sequence at an index shuffled for (pixel, g) by a nested uniform scramble
 * (so the pixel's first 2^m samples are one aligned block of 2^m Sobol points, a (0,m,2)-net in the group's first
 * two dimensions), each coordinate Owen-scrambled (hashed nested uniform scrambling) with its own seed: every
 * value is uniform on [0, 1) over the seeds, groups are mutually independent in that sense, and the net properties
 * of the block hold after scrambling. */
double sample_value(const SamplePoint *p, uint32_t dim);

/** One group of a sample point: the shuffled index and the group's seed, so that its four values cost one shuffle. */
typedef struct SampleGroup {
    uint32_t group; /**< the group's number (dimensions 4 group .. 4 group + 3) */
    uint32_t index; /**< the sample's index shuffled for the pixel and the group */
    uint32_t seed[SAMPLER_GROUP_DIMS]; /**< each dimension's scrambling seed */
} SampleGroup;

/** Group `group` of point p. */
SampleGroup sample_group(const SamplePoint *p, uint32_t group);
/** Dimension d (0 .. 3) of group g: sample_value of dimension 4 g->group + d. */
double sample_group_value(const SampleGroup *g, int d);

/** Dimension d (0 .. 3) of the unscrambled Sobol point `index`, as a 32-bit fraction (value * 2^32). Dimension 0
 * is the van der Corput sequence, 1 .. 3 use Joe and Kuo's primitive polynomials and initial direction numbers
 * (x + 1; x^2 + x + 1, m = 1, 3; x^3 + x + 1, m = 1, 3, 1). */
uint32_t sobol_bits(uint32_t index, int d);

/** Owen scrambling of the 32-bit fraction v with seed: each bit flipped by a hash of the seed and the bits above it
 * (a Laine-Karras style permutation on the reversed bits). A bijection of the 32-bit values for every seed. */
uint32_t owen_scramble(uint32_t v, uint32_t seed);

#endif
