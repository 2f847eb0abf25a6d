/* spectral_kernels8.h - the 8-float (AVX2) versions of the kernels of spectral_kernels.h, for functions compiled
 * for AVX2 (GSPECTRAL_TARGET_AVX2) and chosen when the library is loaded (GSPECTRAL_PICK). Header only, included
 * at the end of spectral_kernels.h (include that one); empty where GSPECTRAL_AVX2 is not defined.
 *
 * Each gives its 4-float version's results bit for bit: the element-wise ones trivially, the sums because the
 * 4-float versions already add in two accumulators of alternate blocks (8 lanes) and the 8-float versions add
 * the blocks into one 8-lane accumulator in the same order and its two halves the same way at the end.
 *
 * The whole 8-float blocks of a vector run as straight-line code entered by one jump, for any number of samples
 * (GSPECTRAL_EACH_BLOCK8, which lib/color/color_shortcuts.c uses too): on a spectrum of tens of samples a loop spent
 * about a third of a kernel's instructions on its index, compare and branch. The last 1 to 7 samples (the common
 * grids have one: 81, 41, 9) are never an 8-float block that overlaps the whole blocks: a block load that spans
 * two earlier stores (the overlapping block's and the whole block's) cannot take its data from the store buffer
 * and waits for both to retire, and colour operations read what the one before just wrote. So every kernel
 * stores and loads the same pieces: the 8-float blocks at multiples of 8, then in the element-wise kernels pieces
 * of 4, 2 and 1 floats as n % 8 has them (the 4 and the 2 one vector operation each: GSPECTRAL_EACH_PIECE8), and
 * single floats in the sums, whose order they define. */
#ifndef GENERIC_SPECTRAL_KERNELS8_H
#define GENERIC_SPECTRAL_KERNELS8_H

#include <stddef.h>

#include "spectral_kernels.h"

#ifdef GSPECTRAL_AVX2
#ifdef __cplusplus
extern "C" {
#endif

/* One case of GSPECTRAL_EACH_BLOCK8's jump: the block k blocks before end, then on to the next one. */
#define GSPECTRAL_BLOCK8_CASE(k, end, BLOCK)                                                                   \
    case k:                                                                                                    \
        BLOCK(end, -8 * (k));                                                                                  \
        __attribute__((fallthrough));

/* The 16 blocks from sample b on, in order. */
#define GSPECTRAL_BLOCKS8_16(b, BLOCK)                                                                         \
    do {                                                                                                       \
        BLOCK(b, 0);                                                                                           \
        BLOCK(b, 8);                                                                                           \
        BLOCK(b, 16);                                                                                          \
        BLOCK(b, 24);                                                                                          \
        BLOCK(b, 32);                                                                                          \
        BLOCK(b, 40);                                                                                          \
        BLOCK(b, 48);                                                                                          \
        BLOCK(b, 56);                                                                                          \
        BLOCK(b, 64);                                                                                          \
        BLOCK(b, 72);                                                                                          \
        BLOCK(b, 80);                                                                                          \
        BLOCK(b, 88);                                                                                          \
        BLOCK(b, 96);                                                                                          \
        BLOCK(b, 104);                                                                                         \
        BLOCK(b, 112);                                                                                         \
        BLOCK(b, 120);                                                                                         \
    } while (0)

/** Runs BLOCK(b, k) (a macro) on each whole 8-float block of n >= 0 samples (none for n < 8), in order, so that a
 * sum over the blocks keeps its order: the block of samples b + k to b + k + 7, b a ptrdiff_t base shared by up to
 * 16 blocks and k a constant, so that an address written p + b + k (or t + m * b + m * k in a table of m floats a
 * sample) is a base computed once and a constant offset. All straight-line code: 16 blocks a step while 16 or more
 * are left (more than 127 samples), then the last 0 to 15 entered by one jump, with b = n & ~7. Constants the
 * blocks use are best built before and kept in registers (GSPECTRAL_KEEP8): else GCC builds them again in each
 * block the jump may enter at. */
#define GSPECTRAL_EACH_BLOCK8(n, BLOCK)                                                                        \
    do {                                                                                                       \
        ptrdiff_t gspectral_end_ = (ptrdiff_t)(n) & ~(ptrdiff_t)7, gspectral_i_ = 0;                           \
        for (; gspectral_i_ + 128 <= gspectral_end_; gspectral_i_ += 128) {                                    \
            __asm__("" : "+r"(gspectral_i_)); /* one index for all operands, not a pointer each */             \
            GSPECTRAL_BLOCKS8_16(gspectral_i_, BLOCK);                                                         \
        }                                                                                                      \
        /* the blocks' byte offset, computed before the jump (else GCC computes it on each edge of the jump,   \
         * each then a second jump) */                                                                         \
        __asm__("" ::"r"((size_t)gspectral_end_ * sizeof(float)));                                             \
        switch ((gspectral_end_ >> 3) & 15) { /* the blocks the loop left */                                   \
            GSPECTRAL_BLOCK8_CASE(15, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(14, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(13, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(12, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(11, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(10, gspectral_end_, BLOCK)                                                   \
            GSPECTRAL_BLOCK8_CASE(9, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(8, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(7, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(6, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(5, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(4, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(3, gspectral_end_, BLOCK)                                                    \
            GSPECTRAL_BLOCK8_CASE(2, gspectral_end_, BLOCK)                                                    \
        case 1:                                                                                                \
            BLOCK(gspectral_end_, -8);                                                                         \
            break;                                                                                             \
        default: /* none */                                                                                    \
            break;                                                                                             \
        }                                                                                                      \
    } while (0)

/** A loop over the samples after GSPECTRAL_EACH_BLOCK8's whole blocks (ptrdiff_t i from n & ~7 to n - 1), as
 * the head of the statement that follows: the last samples one at a time (gspectral_kfinite8). */
#define GSPECTRAL_TAIL8(n, i) for (ptrdiff_t i = (ptrdiff_t)(n) & ~(ptrdiff_t)7; i < (ptrdiff_t)(n); i++)

/** Runs PIECE(i, k) (a macro) on the samples after GSPECTRAL_EACH_BLOCK8's whole blocks in pieces of k = 4 and 2
 * samples from sample i (a ptrdiff_t), then ONE(i) on a last single one, in that order, as n % 8 has them (7: 4, 2,
 * then 1). k is a constant. An element-wise kernel's PIECE is one 4-lane operation on vectors loaded and stored in
 * the piece's size, so that the next kernel's loads of the same pieces take their data from the store buffer (a
 * masked 8-lane store is not forwarded on an AMD EPYC, Zen 4: bench/README.md), and its ONE a float operation,
 * fewer instructions than a vector one on a float loaded alone; each loads its operands before it stores, so the
 * result may alias an operand. The brightness and colour matching sums take their last samples' terms a piece at a
 * time too, and add them one by one in their order. */
#define GSPECTRAL_EACH_PIECE8(n, PIECE, ONE)                                                                   \
    do {                                                                                                       \
        ptrdiff_t gspectral_at_ = (ptrdiff_t)(n) & ~(ptrdiff_t)7;                                              \
        const int gspectral_rest_ = (int)(n) & 7;                                                              \
        if (gspectral_rest_ & 4)                                                                               \
            PIECE(gspectral_at_, 4);                                                                           \
        gspectral_at_ += gspectral_rest_ & 4;                                                                  \
        if (gspectral_rest_ & 2)                                                                               \
            PIECE(gspectral_at_, 2);                                                                           \
        gspectral_at_ += gspectral_rest_ & 2;                                                                  \
        if (gspectral_rest_ & 1)                                                                               \
            ONE(gspectral_at_);                                                                                \
    } while (0)

/** The k = 1, 2 or 4 floats at p in the first k lanes (any alignment), 0 in the others: one load of k floats
 * (k a constant; not a memcpy into a vector of zeros, which GCC builds on the stack). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v4 gspectral_vload_piece(const float *p,
                                                                                                   int k)
{
    if (k == 4)
        return (gspectral_v4)_mm_loadu_ps(p);
    if (k == 2)
        return (gspectral_v4)_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)(const void *)p));
    return (gspectral_v4)_mm_load_ss(p);
}

/** Stores the first k = 1, 2 or 4 lanes of v at p (any alignment): one store of k floats (k a constant). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_vstore_piece(float *p,
                                                                                               gspectral_v4 v, int k)
{
    if (k == 4)
        _mm_storeu_ps(p, (__m128)v);
    else if (k == 2)
        _mm_storel_epi64((__m128i *)(void *)p, _mm_castps_si128((__m128)v));
    else
        _mm_store_ss(p, (__m128)v);
}

/** CALL(n) with n a constant when it is one of the common grids' lengths (81: 380..780 nm every 5 nm, 41: every
 * 10 nm, 9: spectrum9), else CALL(n) as it is: with the kernels inlined, a constant length folds
 * GSPECTRAL_EACH_BLOCK8's jump away into straight-line code (spectrum's render: 0.97x the instructions), for any
 * model on those grids. The same kernels either way, so the same results bit for bit. */
#define GSPECTRAL_ON_COMMON_LENGTH(n, CALL)                                                                    \
    ((n) == 81 ? CALL(81) : (n) == 41 ? CALL(41) : (n) == 9 ? CALL(9) : CALL(n))

/** Keeps the vector v in a register from here on (an empty asm that may change it): a constant that every block
 * of GSPECTRAL_EACH_BLOCK8 uses is then built once before the jump, not in each block. */
#define GSPECTRAL_KEEP8(v) __asm__("" : "+x"(v))

/** x op y on 8 lanes. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v8 gspectral_vop8(GSpectralOp op,
                                                                                             gspectral_v8 x,
                                                                                             gspectral_v8 y)
{
    return op == GSPECTRAL_ADD ? x + y : x * y;
}

/** gspectral_kmap on 8-float vectors. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kmap8(GSpectralOp op, float *o,
                                                                                        const float *a,
                                                                                        const float *b, int n)
{
#define GSPECTRAL_MAP8_BLOCK(i, k)                                                                             \
    gspectral_vstore8(o + (i) + (k),                                                                           \
                      gspectral_vop8(op, gspectral_vload8(a + (i) + (k)), gspectral_vload8(b + (i) + (k))))
#define GSPECTRAL_MAP8_PIECE(i, k)                                                                             \
    gspectral_vstore_piece(o + (i),                                                                            \
                           gspectral_vop(op, gspectral_vload_piece(a + (i), k), gspectral_vload_piece(b + (i), k)), k)
#define GSPECTRAL_MAP8_ONE(i) o[i] = op == GSPECTRAL_ADD ? a[i] + b[i] : a[i] * b[i]
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_MAP8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_MAP8_PIECE, GSPECTRAL_MAP8_ONE);
#undef GSPECTRAL_MAP8_BLOCK
#undef GSPECTRAL_MAP8_PIECE
#undef GSPECTRAL_MAP8_ONE
}

/** gspectral_kscale on 8-float vectors. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kscale8(float *o, const float *a,
                                                                                          float s, int n)
{
    gspectral_v8 sv = {s, s, s, s, s, s, s, s};
    GSPECTRAL_KEEP8(sv);
    const gspectral_v4 sv4 = {s, s, s, s};
#define GSPECTRAL_SCALE8_BLOCK(i, k) gspectral_vstore8(o + (i) + (k), gspectral_vload8(a + (i) + (k)) * sv)
#define GSPECTRAL_SCALE8_PIECE(i, k) gspectral_vstore_piece(o + (i), gspectral_vload_piece(a + (i), k) * sv4, k)
#define GSPECTRAL_SCALE8_ONE(i) o[i] = a[i] * s
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_SCALE8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_SCALE8_PIECE, GSPECTRAL_SCALE8_ONE);
#undef GSPECTRAL_SCALE8_BLOCK
#undef GSPECTRAL_SCALE8_PIECE
#undef GSPECTRAL_SCALE8_ONE
}

/** gspectral_kmul_scaled on 8-float vectors. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kmul_scaled8(float *o, const float *a,
                                                                                               const float *b, float s,
                                                                                               int n)
{
    gspectral_v8 sv = {s, s, s, s, s, s, s, s};
    GSPECTRAL_KEEP8(sv);
    const gspectral_v4 sv4 = {s, s, s, s};
#define GSPECTRAL_MUL_SCALED8_BLOCK(i, k)                                                                      \
    gspectral_vstore8(o + (i) + (k), gspectral_vload8(a + (i) + (k)) * gspectral_vload8(b + (i) + (k)) * sv)
#define GSPECTRAL_MUL_SCALED8_PIECE(i, k)                                                                      \
    gspectral_vstore_piece(o + (i), gspectral_vload_piece(a + (i), k) * gspectral_vload_piece(b + (i), k) * sv4, k)
#define GSPECTRAL_MUL_SCALED8_ONE(i)                                                                           \
    do {                                                                                                       \
        float x_ = a[i] * b[i];                                                                                \
        o[i] = x_ * s;                                                                                         \
    } while (0)
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_MUL_SCALED8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_MUL_SCALED8_PIECE, GSPECTRAL_MUL_SCALED8_ONE);
#undef GSPECTRAL_MUL_SCALED8_BLOCK
#undef GSPECTRAL_MUL_SCALED8_PIECE
#undef GSPECTRAL_MUL_SCALED8_ONE
}

/** gspectral_vdiv on 8 lanes: a / b, 0 where b is 0 (those lanes divide by 1 and are cleared); zero and one hold
 * 0 and 1 in every lane. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v8
gspectral_vdiv8(gspectral_v8 a, gspectral_v8 b, gspectral_v8 zero, gspectral_v8 one)
{
    gspectral_v8i nz = b != zero;
    gspectral_v8 safe = (gspectral_v8)(((gspectral_v8i)b & nz) | ((gspectral_v8i)one & ~nz));
    return (gspectral_v8)((gspectral_v8i)(a / safe) & nz);
}

/** gspectral_kdiv on 8-float vectors. The lanes a piece leaves out hold 0: they divide by 1 and are cleared. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kdiv8(float *o, const float *a,
                                                                                        const float *b, int n)
{
    gspectral_v8 zero = {0, 0, 0, 0, 0, 0, 0, 0}, one = {1, 1, 1, 1, 1, 1, 1, 1};
    GSPECTRAL_KEEP8(zero);
    GSPECTRAL_KEEP8(one);
#define GSPECTRAL_DIV8_BLOCK(i, k)                                                                             \
    gspectral_vstore8(o + (i) + (k),                                                                           \
                      gspectral_vdiv8(gspectral_vload8(a + (i) + (k)), gspectral_vload8(b + (i) + (k)), zero, one))
#define GSPECTRAL_DIV8_PIECE(i, k)                                                                             \
    gspectral_vstore_piece(o + (i),                                                                            \
                           gspectral_vdiv(gspectral_vload_piece(a + (i), k), gspectral_vload_piece(b + (i), k)), k)
#define GSPECTRAL_DIV8_ONE(i) o[i] = b[i] != 0.0f ? a[i] / b[i] : 0.0f
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_DIV8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_DIV8_PIECE, GSPECTRAL_DIV8_ONE);
#undef GSPECTRAL_DIV8_BLOCK
#undef GSPECTRAL_DIV8_PIECE
#undef GSPECTRAL_DIV8_ONE
}

/** gspectral_kfill on 8-float vectors. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kfill8(float *o, float value,
                                                                                         int n)
{
    gspectral_v8 v = {value, value, value, value, value, value, value, value};
    GSPECTRAL_KEEP8(v);
    const gspectral_v4 v4 = {value, value, value, value};
#define GSPECTRAL_FILL8_BLOCK(i, k) gspectral_vstore8(o + (i) + (k), v)
#define GSPECTRAL_FILL8_PIECE(i, k) gspectral_vstore_piece(o + (i), v4, k)
#define GSPECTRAL_FILL8_ONE(i) o[i] = value
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_FILL8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_FILL8_PIECE, GSPECTRAL_FILL8_ONE);
#undef GSPECTRAL_FILL8_BLOCK
#undef GSPECTRAL_FILL8_PIECE
#undef GSPECTRAL_FILL8_ONE
}

/** o = a, n >= 0 floats, in the pieces every kernel here uses (libc's memcpy stores blocks that straddle them,
 * and the next kernel's loads would wait for those stores to retire); o and a do not overlap. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kcopy8(float *o, const float *a,
                                                                                         int n)
{
#define GSPECTRAL_COPY8_BLOCK(i, k) gspectral_vstore8(o + (i) + (k), gspectral_vload8(a + (i) + (k)))
#define GSPECTRAL_COPY8_PIECE(i, k) gspectral_vstore_piece(o + (i), gspectral_vload_piece(a + (i), k), k)
#define GSPECTRAL_COPY8_ONE(i) o[i] = a[i]
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_COPY8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_COPY8_PIECE, GSPECTRAL_COPY8_ONE);
#undef GSPECTRAL_COPY8_BLOCK
#undef GSPECTRAL_COPY8_PIECE
#undef GSPECTRAL_COPY8_ONE
}

/** gspectral_kaxpyd's 8 results at a and b: each product in double (two 4-double halves), rounded to float, then
 * the float sum. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 __m256 gspectral_vaxpyd8(__m256d sv,
                                                                                           const float *a,
                                                                                           const float *b)
{
    __m128 q0 = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(a)), sv));
    __m128 q1 = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtps_pd(_mm_loadu_ps(a + 4)), sv));
    return _mm256_add_ps(_mm256_loadu_ps(b), _mm256_insertf128_ps(_mm256_castps128_ps256(q0), q1, 1));
}

/** gspectral_kaxpyd's 4 results on the samples a and b in registers (4 products in double). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v4 gspectral_vaxpyd4_lanes(__m256d sv,
                                                                                                      gspectral_v4 a,
                                                                                                      gspectral_v4 b)
{
    return (gspectral_v4)_mm_add_ps((__m128)b, _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtps_pd((__m128)a), sv)));
}

/** gspectral_kaxpyd on 8-float vectors. When s is a float (it converts to float and back unchanged), each product
 * is taken in float: a float times a float is exact in double, so its rounding to float is the float product, the
 * same bits at a third of the instructions. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kaxpyd8(float *o, double s,
                                                                                          const float *a,
                                                                                          const float *b, int n)
{
    const float sf = (float)s;
    if ((double)sf == s) {
        gspectral_v8 sv = {sf, sf, sf, sf, sf, sf, sf, sf};
        GSPECTRAL_KEEP8(sv);
        const gspectral_v4 sv4 = {sf, sf, sf, sf};
#define GSPECTRAL_AXPYF8_BLOCK(i, k)                                                                           \
    gspectral_vstore8(o + (i) + (k), gspectral_vload8(b + (i) + (k)) + gspectral_vload8(a + (i) + (k)) * sv)
#define GSPECTRAL_AXPYF8_PIECE(i, k)                                                                           \
    gspectral_vstore_piece(o + (i), gspectral_vload_piece(b + (i), k) + gspectral_vload_piece(a + (i), k) * sv4, k)
#define GSPECTRAL_AXPYF8_ONE(i) o[i] = b[i] + a[i] * sf
        GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_AXPYF8_BLOCK);
        GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_AXPYF8_PIECE, GSPECTRAL_AXPYF8_ONE);
#undef GSPECTRAL_AXPYF8_BLOCK
#undef GSPECTRAL_AXPYF8_PIECE
#undef GSPECTRAL_AXPYF8_ONE
        return;
    }
    const __m256d sv = _mm256_set1_pd(s);
#define GSPECTRAL_AXPYD8_BLOCK(i, k)                                                                           \
    _mm256_storeu_ps(o + (i) + (k), gspectral_vaxpyd8(sv, a + (i) + (k), b + (i) + (k)))
#define GSPECTRAL_AXPYD8_PIECE(i, k)                                                                           \
    gspectral_vstore_piece(o + (i), gspectral_vaxpyd4_lanes(sv, gspectral_vload_piece(a + (i), k),            \
                                                            gspectral_vload_piece(b + (i), k)),                \
                           k)
#define GSPECTRAL_AXPYD8_ONE(i) o[i] = b[i] + (float)(a[i] * s)
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_AXPYD8_BLOCK);
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_AXPYD8_PIECE, GSPECTRAL_AXPYD8_ONE);
#undef GSPECTRAL_AXPYD8_BLOCK
#undef GSPECTRAL_AXPYD8_PIECE
#undef GSPECTRAL_AXPYD8_ONE
}

/** 0x7fffffff in each of 8 lanes: the initializer of the mask of gspectral_vterm8_mask, which clears sign bits. */
#define GSPECTRAL_ABS8                                                                                         \
    {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff}

/** The terms t of a and b on 8 lanes, |x| as x & abs (abs = GSPECTRAL_ABS8). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v8
gspectral_vterm8_mask(GSpectralTerm t, gspectral_v8 a, gspectral_v8 b, gspectral_v8i abs)
{
    return t == GSPECTRAL_ABS ? (gspectral_v8)((gspectral_v8i)a & abs)
           : t == GSPECTRAL_DOT ? a * b
                                : a * (gspectral_v8)((gspectral_v8i)b & abs);
}

/** gspectral_vsum on 8-float vectors: the terms of the whole blocks added block after block into 8 lanes, folded
 * to the 4 lanes the 4-float version's two accumulators give. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 gspectral_v4
gspectral_vsum8(GSpectralTerm t, const float *a, const float *b, int n, int *done)
{
    gspectral_v8 acc = {0, 0, 0, 0, 0, 0, 0, 0};
    gspectral_v8i abs = GSPECTRAL_ABS8;
    GSPECTRAL_KEEP8(acc);
    GSPECTRAL_KEEP8(abs);
    const int end = n >= 8 ? n & ~7 : 0; /* the samples in whole blocks */
#define GSPECTRAL_SUM8_BLOCK(i, k)                                                                             \
    acc += gspectral_vterm8_mask(t, gspectral_vload8(a + (i) + (k)), gspectral_vload8(b + (i) + (k)), abs)
    if (end)
        GSPECTRAL_EACH_BLOCK8(end, GSPECTRAL_SUM8_BLOCK);
#undef GSPECTRAL_SUM8_BLOCK
    *done = end;
    return gspectral_vfold8(acc);
}

/** gspectral_ksum on 8-float vectors (equal bit for bit). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 float gspectral_ksum8(GSpectralTerm t,
                                                                                        const float *a,
                                                                                        const float *b, int n)
{
    if (n < 8)
        return gspectral_ksum(t, a, b, n);
    int i;
    gspectral_v4 acc = gspectral_vsum8(t, a, b, n, &i);
    float s = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    for (; i < n; i++)
        s += gspectral_term(t, a[i], b[i]);
    return s;
}

/** s plus the first k = 2 or 4 lanes of p, each converted to double, one after the other (k a constant). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 double gspectral_add_lanes_d(double s,
                                                                                              gspectral_v4 p, int k)
{
    typedef double v2d __attribute__((vector_size(16)));
    v2d lo = (v2d)_mm_cvtps_pd((__m128)p);
    s += lo[0];
    s += lo[1];
    if (k == 4) {
        v2d hi = (v2d)_mm_cvtps_pd(_mm_movehl_ps((__m128)p, (__m128)p));
        s += hi[0];
        s += hi[1];
    }
    return s;
}

/** s plus the first k = 2 or 4 lanes of p, one after the other in float (k a constant). */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 float gspectral_add_lanes_f(float s, gspectral_v4 p,
                                                                                             int k)
{
    s += p[0];
    s += p[1];
    if (k == 4) {
        s += p[2];
        s += p[3];
    }
    return s;
}

/** gspectral_kbright on 8-float vectors (equal bit for bit). The last samples' terms are taken a piece at a time
 * as vectors (GSPECTRAL_EACH_PIECE8), then added to the sum one by one in their order. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 double gspectral_kbright8(const float *w,
                                                                                           const float *a, int n)
{
    if (n < 8)
        return gspectral_kbright(w, a, n);
    int i;
    gspectral_v4 acc = gspectral_vsum8(GSPECTRAL_WABS, w, a, n, &i);
    double s = (double)acc[0] + acc[1] + acc[2] + acc[3];
#define GSPECTRAL_BRIGHT8_PIECE(j, k)                                                                          \
    s = gspectral_add_lanes_d(                                                                                 \
        s, gspectral_vterm(GSPECTRAL_WABS, gspectral_vload_piece(w + (j), k), gspectral_vload_piece(a + (j), k)), k)
#define GSPECTRAL_BRIGHT8_ONE(j) s += w[j] * fabsf(a[j])
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_BRIGHT8_PIECE, GSPECTRAL_BRIGHT8_ONE);
#undef GSPECTRAL_BRIGHT8_PIECE
#undef GSPECTRAL_BRIGHT8_ONE
    return s;
}

/** gspectral_kfinite on 8-float vectors: the whole blocks, then the last samples one by one. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 int gspectral_kfinite8(const float *a, int n,
                                                                                         int nonnegative)
{
    if (n < 8)
        return gspectral_kfinite(a, n, nonnegative);
    /* x - x is 0 for a finite x and NaN otherwise, and a NaN stays in the sum; neg collects x < 0 per lane */
    gspectral_v8 zero = {0, 0, 0, 0, 0, 0, 0, 0}, acc = zero;
    gspectral_v8i neg = {0, 0, 0, 0, 0, 0, 0, 0};
    GSPECTRAL_KEEP8(zero);
    GSPECTRAL_KEEP8(acc);
    GSPECTRAL_KEEP8(neg);
#define GSPECTRAL_FINITE8_BLOCK(i, k)                                                                          \
    do {                                                                                                       \
        gspectral_v8 x_ = gspectral_vload8(a + (i) + (k));                                                     \
        acc += x_ - x_;                                                                                        \
        if (nonnegative)                                                                                       \
            neg |= x_ < zero;                                                                                  \
    } while (0)
    GSPECTRAL_EACH_BLOCK8(n, GSPECTRAL_FINITE8_BLOCK);
#undef GSPECTRAL_FINITE8_BLOCK
    float tail = 0.0f;
    int tail_neg = 0;
    GSPECTRAL_TAIL8(n, i)
    {
        tail += a[i] - a[i];
        tail_neg |= a[i] < 0.0f;
    }
    gspectral_v8i bad = acc != zero;
    if (nonnegative)
        bad |= neg;
    return _mm256_movemask_ps((__m256)bad) == 0 && tail == 0.0f && !(nonnegative && tail_neg);
}

/** gspectral_kxyz on 8-float vectors (equal bit for bit): per coordinate the blocks' products added block after
 * block into 8 lanes, the last 1 to 7 samples in a float sum (as gspectral_kxyz_tail), the lanes' halves added,
 * then in double the 4 lanes in pairs and that sum. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void gspectral_kxyz8(const float *t,
                                                                                        const float *a, int n,
                                                                                        double xyz[3])
{
    gspectral_v8 x = {0, 0, 0, 0, 0, 0, 0, 0}, y = x, z = x;
    GSPECTRAL_KEEP8(x);
    GSPECTRAL_KEEP8(y);
    GSPECTRAL_KEEP8(z);
    const ptrdiff_t end = n >= 8 ? n & ~7 : 0; /* the samples in whole blocks */
    const float *te = t + 3 * end;             /* the table's block after them (the last samples' weights) */
#define GSPECTRAL_XYZ8_BLOCK(i, k)                                                                             \
    do {                                                                                                       \
        const float *b_ = te + 3 * ((i) - end) + 3 * (k);                                                      \
        gspectral_v8 v_ = gspectral_vload8(a + (i) + (k));                                                     \
        x += v_ * gspectral_vload8(b_);                                                                        \
        y += v_ * gspectral_vload8(b_ + 8);                                                                    \
        z += v_ * gspectral_vload8(b_ + 16);                                                                   \
    } while (0)
    if (end)
        GSPECTRAL_EACH_BLOCK8(end, GSPECTRAL_XYZ8_BLOCK);
#undef GSPECTRAL_XYZ8_BLOCK
    float tail[3] = {0.0f, 0.0f, 0.0f};
    /* the products a piece at a time, added one by one */
#define GSPECTRAL_XYZ8_PIECE(j, k)                                                                             \
    do {                                                                                                       \
        const float *w_ = te + ((j) - end); /* the piece's lanes of block te, whose 8 lanes all exist */       \
        gspectral_v4 v_ = gspectral_vload_piece(a + (j), k);                                                   \
        tail[0] = gspectral_add_lanes_f(tail[0], v_ * gspectral_vload(w_), k);                                 \
        tail[1] = gspectral_add_lanes_f(tail[1], v_ * gspectral_vload(w_ + 8), k);                             \
        tail[2] = gspectral_add_lanes_f(tail[2], v_ * gspectral_vload(w_ + 16), k);                            \
    } while (0)
#define GSPECTRAL_XYZ8_ONE(j)                                                                                  \
    do {                                                                                                       \
        tail[0] += a[j] * te[(j) - end];                                                                       \
        tail[1] += a[j] * te[(j) - end + 8];                                                                   \
        tail[2] += a[j] * te[(j) - end + 16];                                                                  \
    } while (0)
    GSPECTRAL_EACH_PIECE8(n, GSPECTRAL_XYZ8_PIECE, GSPECTRAL_XYZ8_ONE);
#undef GSPECTRAL_XYZ8_PIECE
#undef GSPECTRAL_XYZ8_ONE
    /* the lanes in double: hadd gives (l0 + l1) in the low half and (l2 + l3) in the high one, per coordinate */
    __m256d dx = _mm256_cvtps_pd((__m128)gspectral_vfold8(x)), dy = _mm256_cvtps_pd((__m128)gspectral_vfold8(y));
    __m256d dz = _mm256_cvtps_pd((__m128)gspectral_vfold8(z));
    __m256d xy = _mm256_hadd_pd(dx, dy), zz = _mm256_hadd_pd(dz, dz); /* x01 y01 x23 y23, z01 z01 z23 z23 */
    __m128d sxy = _mm_add_pd(_mm256_castpd256_pd128(xy), _mm256_extractf128_pd(xy, 1));
    __m128d sz = _mm_add_sd(_mm256_castpd256_pd128(zz), _mm256_extractf128_pd(zz, 1));
    __m128d txy = _mm_cvtps_pd(_mm_setr_ps(tail[0], tail[1], 0.0f, 0.0f));
    _mm_storeu_pd(xyz, _mm_add_pd(sxy, txy));
    xyz[2] = _mm_cvtsd_f64(sz) + (double)tail[2];
}

#ifdef __cplusplus
}
#endif
#endif
#endif
