/* color_shortcuts.c - what compositions of the generic colour operations give, found with less work for the
 * vectors of models that the library reads as plain samples (their class has no fill of its own, as lib/color/color.c's
 * defaults decide): gcolor_is_black (brightness == 0) and gcolor_mul_scaled (mul, then scale). Other models and
 * matrices take the composition itself. Two bodies as in lib/color/color_vector_ops.c: on 4-float vectors and,
 * compiled for AVX2, on 8-float vectors (whole blocks as straight-line code, GSPECTRAL_EACH_BLOCK8 of
 * spectral_kernels8.h), with the same results. */
#include "generic/color.h"
#include "generic/kit/spectral_kernels.h"

#include <stdint.h>
#include <string.h>

/* 1 when the model's class leaves fill to the library, which then reads its vectors as nvalues plain samples. */
static int plain_samples(const GColorModel *m) { return m->cls->fill == NULL; }

/* gcolor_is_black's test of a vector read as plain samples: 1 when the n floats at v are all zero (+0 or -0; a
 * NaN is not), by their bits less the sign: sixteen floats at a time, stopping at the first group that holds a
 * non-zero one (the AVX2 body ORs all its 8-float blocks, then tests). */
static int all_zero(const float *v, int n);

/* The floats from i on, one at a time (the tail of all_zero, and short vectors). */
static inline int all_zero_from(const float *v, int i, int n)
{
    uint32_t acc = 0, b;
    for (; i < n; i++) {
        memcpy(&b, v + i, sizeof b);
        acc |= b;
    }
    return (acc << 1) == 0;
}

static int all_zero_v4(const float *v, int n)
{
    int i = 0;
#ifdef GSPECTRAL_VECTOR
    typedef unsigned int bits4 __attribute__((vector_size(16)));
    bits4 x[4];
    for (; i + 16 <= n; i += 16) {
        memcpy(x, v + i, sizeof x);
        bits4 a = (x[0] | x[1] | x[2] | x[3]) << 1;
        if (a[0] | a[1] | a[2] | a[3])
            return 0;
    }
#endif
    return all_zero_from(v, i, n);
}

int gcolor_is_black(const GColor *c)
{
    const GColorModel *m = c->model;
    if (!plain_samples(m) || c->kind != GCOLOR_VECTOR) /* the model's own measure */
        return m->cls->brightness(m, c) == 0.0;
    return m->nvalues < 8 ? all_zero_from(c->v, 0, m->nvalues) : all_zero(c->v, m->nvalues);
}

/* out = (a * b) * s sample by sample, each product rounded to float as the models' mul and scale round it. */
static void mul_scaled(float *out, const float *a, const float *b, float s, int n);

/* The samples from i on, one at a time (the tail of the kernels, and short vectors). */
static inline void mul_scaled_from(float *out, const float *a, const float *b, float s, int i, int n)
{
    for (; i < n; i++) {
        float x = a[i] * b[i];
        out[i] = x * s;
    }
}

static void mul_scaled_v4(float *out, const float *a, const float *b, float s, int n)
{
    gspectral_kmul_scaled(out, a, b, s, n);
}

/* gcolor_mul_scaled as the composition it stands for (apart, so that the common case saves no registers). */
__attribute__((noinline)) static int mul_then_scale(const GColorModel *m, GColor *out, const GColor *a,
                                                     const GColor *b, double s)
{
    int rc = m->cls->mul(m, out, a, b);
    return rc ? rc : m->cls->scale(m, out, out, s);
}

int gcolor_mul_scaled(GColor *out, const GColor *a, const GColor *b, double s)
{
    if (a->model != b->model || out->model != a->model)
        return G_ERR_MISMATCH;
    const GColorModel *m = a->model;
    if (!plain_samples(m) || a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)
        return mul_then_scale(m, out, a, b, s);
    if (m->nvalues < 8)
        mul_scaled_from(out->v, a->v, b->v, (float)s, 0, m->nvalues);
    else
        mul_scaled(out->v, a->v, b->v, (float)s, m->nvalues);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

#ifdef GSPECTRAL_AVX2
/* n >= 8 (gcolor_is_black takes shorter vectors to all_zero_from) */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 int all_zero_n8(const float *v, int n)
{
    /* the whole blocks' bits ORed together and tested once (straight-line code costs less than a test per group),
     * then the last floats' */
    __m256i acc = _mm256_setzero_si256();
#define ALL_ZERO_BLOCK(i, k) acc = _mm256_or_si256(acc, _mm256_loadu_si256((const __m256i *)(v + (i) + (k))))
    GSPECTRAL_EACH_BLOCK8(n, ALL_ZERO_BLOCK);
#undef ALL_ZERO_BLOCK
    return _mm256_testz_si256(acc, _mm256_set1_epi32(0x7fffffff)) && all_zero_from(v, n & ~7, n);
}

/* the common grids' lengths as constants, as the kit's operations take them (spectral_kernels8.h) */
static GSPECTRAL_TARGET_AVX2 int all_zero_v8(const float *v, int n)
{
#define ALL_ZERO(len) all_zero_n8(v, len)
    return GSPECTRAL_ON_COMMON_LENGTH(n, ALL_ZERO);
#undef ALL_ZERO
}

static GSPECTRAL_TARGET_AVX2 void mul_scaled_v8(float *out, const float *a, const float *b, float s, int n)
{
#define MUL_SCALED(len) gspectral_kmul_scaled8(out, a, b, s, len)
    GSPECTRAL_ON_COMMON_LENGTH(n, MUL_SCALED);
#undef MUL_SCALED
}

GSPECTRAL_PICK(all_zero);
GSPECTRAL_PICK(mul_scaled);
#else
static int all_zero(const float *v, int n) { return all_zero_v4(v, n); }

static void mul_scaled(float *out, const float *a, const float *b, float s, int n)
{
    mul_scaled_v4(out, a, b, s, n);
}
#endif
