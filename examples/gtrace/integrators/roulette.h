/* roulette.h - Russian roulette of the path tracer (path.c, whose header says why): the factor a sample's weight
 * scales a path's throughput by, and the probability that a path goes on. */
#ifndef GTRACE_ROULETTE_H
#define GTRACE_ROULETTE_H

#include <generic/color.h>

#include <math.h>

/* The probability that Russian roulette lets a path of throughput factor b (the product of roulette_factor's) go
 * on: min(1, sqrt(b)). */
static inline double roulette_survival(double b) { return fmin(1.0, sqrt(b)); }

/* The factor by which a sample's weight w scales the path's throughput for Russian roulette: its largest band (of at
 * most ROULETTE_PEAK_BANDS spread over the model's bands), or its brightness for a weight without bands (a matrix).
 * The product of these factors bounds every band of the throughput from above. */
double roulette_factor(const GColor *w);

#endif
