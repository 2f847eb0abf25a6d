/* spectral_kernels.h - element-wise kernels on float arrays (sums, products, scaling, dot products,
 * weighted magnitudes, division, powers) for colour models whose values are arrays of samples. Header only:
 * every kernel is static inline. The gspectral_* operations of spectral.h are built on them, and a model with
 * values of its own shape (bispectral's matrices) uses them directly.
 *
 * out may alias an operand in every kernel (each block is loaded before it is stored). With GCC or clang they
 * work on 4-float vectors (memcpy'd in and out, so no alignment is assumed): -O2 alone does not vectorise a
 * loop whose operands may alias. */
#ifndef GENERIC_SPECTRAL_KERNELS_H
#define GENERIC_SPECTRAL_KERNELS_H

#include <math.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
/** Defined when the kernels use 4-float vectors. */
#define GSPECTRAL_VECTOR 1
/** 4 floats in one vector register. */
typedef float gspectral_v4 __attribute__((vector_size(16)));
/** 4 ints, for bit masks on gspectral_v4. */
typedef int gspectral_v4i __attribute__((vector_size(16)));

/** The 4 floats at p, any alignment. */
static inline gspectral_v4 gspectral_vload(const float *p)
{
    gspectral_v4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/** Stores v at p, any alignment. */
static inline void gspectral_vstore(float *p, gspectral_v4 v) { memcpy(p, &v, sizeof v); }
#endif

/** The element-wise operations of gspectral_kmap. */
typedef enum GSpectralOp { GSPECTRAL_ADD, GSPECTRAL_MUL } GSpectralOp;

#ifdef GSPECTRAL_VECTOR
/** x op y on 4 lanes. */
static inline gspectral_v4 gspectral_vop(GSpectralOp op, gspectral_v4 x, gspectral_v4 y)
{
    return op == GSPECTRAL_ADD ? x + y : x * y;
}
#endif

/** o = a op b. The kernels pass op as a constant, so once inlined the choice costs nothing. */
static inline void gspectral_kmap(GSpectralOp op, float *o, const float *a, const float *b, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    for (; i + 8 <= n; i += 8) { /* both blocks are loaded before either is stored */
        gspectral_v4 x0 = gspectral_vop(op, gspectral_vload(a + i), gspectral_vload(b + i));
        gspectral_v4 x1 = gspectral_vop(op, gspectral_vload(a + i + 4), gspectral_vload(b + i + 4));
        gspectral_vstore(o + i, x0);
        gspectral_vstore(o + i + 4, x1);
    }
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, gspectral_vop(op, gspectral_vload(a + i), gspectral_vload(b + i)));
#endif
    for (; i < n; i++)
        o[i] = op == GSPECTRAL_ADD ? a[i] + b[i] : a[i] * b[i];
}

/** o = a + b */
static inline void gspectral_kadd(float *o, const float *a, const float *b, int n)
{
    gspectral_kmap(GSPECTRAL_ADD, o, a, b, n);
}

/** o = a * b */
static inline void gspectral_kmul(float *o, const float *a, const float *b, int n)
{
    gspectral_kmap(GSPECTRAL_MUL, o, a, b, n);
}

/** o = a * s */
static inline void gspectral_kscale(float *o, const float *a, float s, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 sv = {s, s, s, s};
    for (; i + 8 <= n; i += 8) { /* both blocks are loaded before either is stored */
        gspectral_v4 x0 = gspectral_vload(a + i) * sv, x1 = gspectral_vload(a + i + 4) * sv;
        gspectral_vstore(o + i, x0);
        gspectral_vstore(o + i + 4, x1);
    }
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, gspectral_vload(a + i) * sv);
#endif
    for (; i < n; i++)
        o[i] = a[i] * s;
}

/** o = (a * b) * s sample by sample, the product rounded to float before the scaling (mul, then scale) */
static inline void gspectral_kmul_scaled(float *o, const float *a, const float *b, float s, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 sv = {s, s, s, s};
    for (; i + 4 <= n; i += 4) {
        gspectral_v4 x = gspectral_vload(a + i) * gspectral_vload(b + i);
        gspectral_vstore(o + i, x * sv);
    }
#endif
    for (; i < n; i++) {
        float x = a[i] * b[i];
        o[i] = x * s;
    }
}

/** o += a * s */
static inline void gspectral_kaxpy(float *o, const float *a, float s, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 sv = {s, s, s, s};
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, gspectral_vload(o + i) + gspectral_vload(a + i) * sv);
#endif
    for (; i < n; i++)
        o[i] += a[i] * s;
}

/** The terms the sums below add up: |a| (b is not used: pass a), a * b, and a * |b| (weights a). */
typedef enum GSpectralTerm { GSPECTRAL_ABS, GSPECTRAL_DOT, GSPECTRAL_WABS } GSpectralTerm;

/** One term t of a and b. */
static inline float gspectral_term(GSpectralTerm t, float a, float b)
{
    return t == GSPECTRAL_ABS ? fabsf(a) : t == GSPECTRAL_DOT ? a * b : a * fabsf(b);
}

#ifdef GSPECTRAL_VECTOR
/** |x| on 4 lanes (the sign bits cleared). */
static inline gspectral_v4 gspectral_vabs(gspectral_v4 x)
{
    gspectral_v4i mask = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
    return (gspectral_v4)((gspectral_v4i)x & mask);
}

/** The terms t of a and b on 4 lanes. */
static inline gspectral_v4 gspectral_vterm(GSpectralTerm t, gspectral_v4 a, gspectral_v4 b)
{
    return t == GSPECTRAL_ABS ? gspectral_vabs(a) : t == GSPECTRAL_DOT ? a * b : a * gspectral_vabs(b);
}

/** The terms of the first multiple of 8 samples summed in four lanes (two accumulators: the sum's latency,
 * not the loads, bounds a single one); *done receives how many samples that was. */
static inline gspectral_v4 gspectral_vsum(GSpectralTerm t, const float *a, const float *b, int n, int *done)
{
    gspectral_v4 acc0 = {0, 0, 0, 0}, acc1 = {0, 0, 0, 0};
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        acc0 += gspectral_vterm(t, gspectral_vload(a + i), gspectral_vload(b + i));
        acc1 += gspectral_vterm(t, gspectral_vload(a + i + 4), gspectral_vload(b + i + 4));
    }
    *done = i;
    return acc0 + acc1;
}
#endif

/** The sum of the terms t of a and b in float; the kernels pass t as a constant. */
static inline float gspectral_ksum(GSpectralTerm t, const float *a, const float *b, int n)
{
    int i = 0;
    float s = 0.0f;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 acc = gspectral_vsum(t, a, b, n, &i);
    s = (acc[0] + acc[1]) + (acc[2] + acc[3]);
#endif
    for (; i < n; i++)
        s += gspectral_term(t, a[i], b[i]);
    return s;
}

/** sum of w * |a|, in double after the vector part */
static inline double gspectral_kbright(const float *w, const float *a, int n)
{
    int i = 0;
    double s = 0.0;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 acc = gspectral_vsum(GSPECTRAL_WABS, w, a, n, &i);
    s = (double)acc[0] + acc[1] + acc[2] + acc[3];
#endif
    for (; i < n; i++)
        s += w[i] * fabsf(a[i]);
    return s;
}

/** sum of |a| */
static inline float gspectral_kabs(const float *a, int n) { return gspectral_ksum(GSPECTRAL_ABS, a, a, n); }

/** sum of a * b */
static inline float gspectral_kdot(const float *a, const float *b, int n)
{
    return gspectral_ksum(GSPECTRAL_DOT, a, b, n);
}

#ifdef GSPECTRAL_VECTOR
/** a / b on 4 lanes, 0 where b is 0 (those lanes divide by 1 and are cleared) */
static inline gspectral_v4 gspectral_vdiv(gspectral_v4 a, gspectral_v4 b)
{
    const gspectral_v4 one = {1, 1, 1, 1}, zero = {0, 0, 0, 0};
    gspectral_v4i nz = b != zero;
    gspectral_v4 safe = (gspectral_v4)(((gspectral_v4i)b & nz) | ((gspectral_v4i)one & ~nz));
    return (gspectral_v4)((gspectral_v4i)(a / safe) & nz);
}
#endif

/** o = a / b sample by sample, zero where b is zero (no lane divides by zero: those divide by 1 and are
 * cleared, so the results equal the scalar loop's bit for bit) */
static inline void gspectral_kdiv(float *o, const float *a, const float *b, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, gspectral_vdiv(gspectral_vload(a + i), gspectral_vload(b + i)));
#endif
    for (; i < n; i++)
        o[i] = b[i] != 0.0f ? a[i] / b[i] : 0.0f;
}

/** o = b + a * s with the product in double and rounded to float once per sample, then the float sum (the
 * library's rounding for gcolor_axpy); out may alias a or b */
static inline void gspectral_kaxpyd(float *o, double s, const float *a, const float *b, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    typedef double v4d __attribute__((vector_size(32)));
    const v4d sv = {s, s, s, s};
    for (; i + 4 <= n; i += 4) {
        v4d p = __builtin_convertvector(gspectral_vload(a + i), v4d) * sv;
        gspectral_vstore(o + i, gspectral_vload(b + i) + __builtin_convertvector(p, gspectral_v4));
    }
#endif
    for (; i < n; i++)
        o[i] = b[i] + (float)(a[i] * s);
}

/** o = value in each of n floats */
static inline void gspectral_kfill(float *o, float value, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    const gspectral_v4 v = {value, value, value, value};
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, v);
#endif
    for (; i < n; i++)
        o[i] = value;
}

/** 1 when every one of the n samples is finite (not infinite, not NaN) and, when nonnegative is set, none is
 * below 0; 0 otherwise */
static inline int gspectral_kfinite(const float *a, int n, int nonnegative)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    /* x - x is 0 for a finite x and NaN otherwise, and a NaN stays in the sum; neg collects x < 0 per lane */
    const gspectral_v4 zero = {0, 0, 0, 0};
    gspectral_v4 acc = zero;
    gspectral_v4i neg = {0, 0, 0, 0};
    for (; i + 4 <= n; i += 4) {
        gspectral_v4 x = gspectral_vload(a + i);
        acc += x - x;
        neg |= x < zero;
    }
    for (int k = 0; k < 4 && i > 0; k++)
        if (acc[k] != 0.0f || (nonnegative && neg[k]))
            return 0;
#endif
    for (; i < n; i++)
        if (!isfinite(a[i]) || (nonnegative && a[i] < 0.0f))
            return 0;
    return 1;
}

/** o = a ^ e sample by sample; non-positive samples give 0 (1 for e = 0), as in the rgb model */
static inline void gspectral_kpow(float *o, const float *a, double e, int n)
{
    float fe = (float)e, zero = e == 0.0 ? 1.0f : 0.0f;
    for (int i = 0; i < n; i++)
        o[i] = a[i] > 0.0f ? powf(a[i], fe) : zero;
}


/** o = r * b0 + g * b1 + bl * b2 sample by sample, in that order in float (the vector part equals the scalar
 * loop bit for bit). */
static inline void gspectral_kmix3(float *o, const float *b0, const float *b1, const float *b2, float r, float g,
                                   float bl, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    const gspectral_v4 rv = {r, r, r, r}, gv = {g, g, g, g}, bv = {bl, bl, bl, bl};
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, rv * gspectral_vload(b0 + i) + gv * gspectral_vload(b1 + i) +
                                    bv * gspectral_vload(b2 + i));
#endif
    for (; i < n; i++)
        o[i] = r * b0[i] + g * b1[i] + bl * b2[i];
}

/** Floats of the colour matching table of gspectral_kxyz for n samples: 24 per block of 8 samples, the last
 * block padded with zeros. */
static inline int gspectral_xyz_table_floats(int n) { return (n + 7) / 8 * 24; }

/** Lays out the colour matching weights wx, wy, wz (n each) as gspectral_kxyz reads them: per block of 8
 * samples the 8 x weights, the 8 y weights and the 8 z weights, in float; zeros past n. */
static inline void gspectral_xyz_table(float *t, const double *wx, const double *wy, const double *wz, int n)
{
    for (int k = 0; k < (n + 7) / 8 * 8; k++) {
        float *b = t + (k / 8) * 24 + k % 8;
        b[0] = k < n ? (float)wx[k] : 0.0f;
        b[8] = k < n ? (float)wy[k] : 0.0f;
        b[16] = k < n ? (float)wz[k] : 0.0f;
    }
}

/** The samples i..n-1 of gspectral_kxyz (fewer than 8) in a float sum per coordinate, added in double to the
 * lanes of the whole blocks' sums x, y, z (NULL: none). */
static inline void gspectral_kxyz_tail(const float *t, const float *a, int i, int n, const float *x, const float *y,
                                       const float *z, double xyz[3])
{
    float tail[3] = {0.0f, 0.0f, 0.0f};
    for (; i < n; i++) {
        const float *b = t + (i >> 3) * 24 + (i & 7); /* i >= 0: block i / 8, lane i % 8 */
        tail[0] += a[i] * b[0];
        tail[1] += a[i] * b[8];
        tail[2] += a[i] * b[16];
    }
    const float *lanes[3] = {x, y, z};
    for (int c = 0; c < 3; c++) {
        const float *l = lanes[c];
        xyz[c] = (l ? ((double)l[0] + l[1]) + ((double)l[2] + l[3]) : 0.0) + tail[c];
    }
}

/** xyz = the sums over the n samples of a[k] times the weights of table t (gspectral_xyz_table): float
 * products, summed in float on 8 lanes per coordinate over the whole blocks of 8 (two 4-float accumulators)
 * and in a float sum over the last 1 to 7 samples; the lanes (in pairs) and that sum added in double. */
static inline void gspectral_kxyz(const float *t, const float *a, int n, double xyz[3])
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    gspectral_v4 x0 = {0, 0, 0, 0}, x1 = x0, y0 = x0, y1 = x0, z0 = x0, z1 = x0;
    for (; i + 8 <= n; i += 8) {
        const float *b = t + i * 3;
        gspectral_v4 v0 = gspectral_vload(a + i), v1 = gspectral_vload(a + i + 4);
        x0 += v0 * gspectral_vload(b);
        x1 += v1 * gspectral_vload(b + 4);
        y0 += v0 * gspectral_vload(b + 8);
        y1 += v1 * gspectral_vload(b + 12);
        z0 += v0 * gspectral_vload(b + 16);
        z1 += v1 * gspectral_vload(b + 20);
    }
    float x[4], y[4], z[4];
    gspectral_vstore(x, x0 + x1);
    gspectral_vstore(y, y0 + y1);
    gspectral_vstore(z, z0 + z1);
    gspectral_kxyz_tail(t, a, i, n, x, y, z, xyz);
#else
    gspectral_kxyz_tail(t, a, i, n, NULL, NULL, NULL, xyz);
#endif
}

/** Asks the compiler to vectorise the loop that follows: OpenMP's simd where the file is compiled with OpenMP (the
 * library), else GCC's ivdep (a type file compiled as a module without it). */
#ifdef _OPENMP
#define GSPECTRAL_SIMD _Pragma("omp simd")
#else
#define GSPECTRAL_SIMD _Pragma("GCC ivdep")
#endif

/* ---- 8-float versions (AVX2), for functions compiled for AVX2 and chosen when the library is loaded ----
 *
 * On x86-64 the kernels above have versions on 8-float vectors (spectral_kernels8.h, included at the end) that
 * give the same results bit for bit, so a picture does not depend on the processor. An operation gets both
 * bodies, the second marked GSPECTRAL_TARGET_AVX2, and GSPECTRAL_PICK makes its name an indirect function (ELF
 * ifunc) that the dynamic loader resolves once, to the 8-float body where the processor has AVX2: no test on
 * each call. What the 8-float kernels share is defined here. */
#if defined(GSPECTRAL_VECTOR) && defined(__x86_64__) && defined(__ELF__)
/** Defined when the 8-float (AVX2) kernels and GSPECTRAL_PICK exist. */
#define GSPECTRAL_AVX2 1
#include <immintrin.h>
/** Compiles a function for AVX2 (no FMA: a contracted multiply-add would round differently). */
#define GSPECTRAL_TARGET_AVX2 __attribute__((target("avx2")))
/** 8 floats in one AVX register. */
typedef float gspectral_v8 __attribute__((vector_size(32)));
/** 8 ints, for bit masks on gspectral_v8. */
typedef int gspectral_v8i __attribute__((vector_size(32)));

/** 1 when the processor runs AVX2 (for the resolvers, which run before the sanitizers' run-times start). */
__attribute__((always_inline, no_sanitize_address)) static inline int gspectral_have_avx2(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}

/** Defines the function `name` (declared before) as the indirect function choosing name##_v8 (AVX2) or name##_v4,
 * both defined before with name's type. */
#define GSPECTRAL_PICK(name)                                                                                   \
    __attribute__((used, no_sanitize_address)) static __typeof__(name) *name##_pick(void)                    \
    {                                                                                                          \
        return gspectral_have_avx2() ? name##_v8 : name##_v4;                                                  \
    }                                                                                                          \
    __typeof__(name) name __attribute__((ifunc(#name "_pick")))

/** The 8 floats at p, any alignment. */
static inline GSPECTRAL_TARGET_AVX2 gspectral_v8 gspectral_vload8(const float *p)
{
    gspectral_v8 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/** Stores v at p, any alignment. */
static inline GSPECTRAL_TARGET_AVX2 void gspectral_vstore8(float *p, gspectral_v8 v) { memcpy(p, &v, sizeof v); }

/** The lanes 0-3 plus the lanes 4-7: what the 4-float versions' two accumulators add up to. */
static inline GSPECTRAL_TARGET_AVX2 gspectral_v4 gspectral_vfold8(gspectral_v8 x)
{
    return __builtin_shufflevector(x, x, 0, 1, 2, 3) + __builtin_shufflevector(x, x, 4, 5, 6, 7);
}
#endif

#ifdef __cplusplus
}
#endif

#include "spectral_kernels8.h" /* the 8-float versions of the kernels */
#endif
