/* lanes2.h - two doubles side by side for the direct list's box tests: SSE2 where the compiler
 * targets it (x86-64's baseline), two scalars elsewhere, with the same result in each lane either way. */
#ifndef GTRACE_LANES2_H
#define GTRACE_LANES2_H

#include <math.h>

#if defined(__SSE2__)
#include <emmintrin.h>

/** Two doubles. */
typedef __m128d Lanes2;

/** (x, x). */
static inline Lanes2 lanes2_set1(double x) { return _mm_set1_pd(x); }
/** a - b, lane by lane. */
static inline Lanes2 lanes2_sub(Lanes2 a, Lanes2 b) { return _mm_sub_pd(a, b); }
/** a * b, lane by lane. */
static inline Lanes2 lanes2_mul(Lanes2 a, Lanes2 b) { return _mm_mul_pd(a, b); }
/** a < b ? a : b, lane by lane (minpd: b when either is a NaN). */
static inline Lanes2 lanes2_min(Lanes2 a, Lanes2 b) { return _mm_min_pd(a, b); }
/** a > b ? a : b, lane by lane (maxpd: b when either is a NaN). */
static inline Lanes2 lanes2_max(Lanes2 a, Lanes2 b) { return _mm_max_pd(a, b); }
/** Bit k set when a <= b in lane k (false for a NaN). */
static inline unsigned lanes2_le(Lanes2 a, Lanes2 b) { return (unsigned)_mm_movemask_pd(_mm_cmple_pd(a, b)); }
/** Stores the two lanes at p (any alignment). */
static inline void lanes2_store(double *p, Lanes2 a) { _mm_storeu_pd(p, a); }
#else
typedef struct Lanes2 {
    double lane[2];
} Lanes2;

static inline Lanes2 lanes2_set1(double x) { return (Lanes2){{x, x}}; }
static inline Lanes2 lanes2_sub(Lanes2 a, Lanes2 b) { return (Lanes2){{a.lane[0] - b.lane[0], a.lane[1] - b.lane[1]}}; }
static inline Lanes2 lanes2_mul(Lanes2 a, Lanes2 b) { return (Lanes2){{a.lane[0] * b.lane[0], a.lane[1] * b.lane[1]}}; }
static inline Lanes2 lanes2_min(Lanes2 a, Lanes2 b)
{
    return (Lanes2){{a.lane[0] < b.lane[0] ? a.lane[0] : b.lane[0], a.lane[1] < b.lane[1] ? a.lane[1] : b.lane[1]}};
}
static inline Lanes2 lanes2_max(Lanes2 a, Lanes2 b)
{
    return (Lanes2){{a.lane[0] > b.lane[0] ? a.lane[0] : b.lane[0], a.lane[1] > b.lane[1] ? a.lane[1] : b.lane[1]}};
}
static inline unsigned lanes2_le(Lanes2 a, Lanes2 b)
{
    return (unsigned)(a.lane[0] <= b.lane[0]) | (unsigned)(a.lane[1] <= b.lane[1]) << 1;
}
static inline void lanes2_store(double *p, Lanes2 a)
{
    p[0] = a.lane[0];
    p[1] = a.lane[1];
}
#endif

#endif
