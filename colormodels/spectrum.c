/* spectrum.c - the nm-sampled spectrum colour model: n samples from min_nm to max_nm every step_nm
 * (default 380..780 nm at 5 nm, 81 samples; any step from 1 to 100 nm that divides the range, inside
 * 300..830 nm). A value is n floats, a light or a reflectance; every operation works sample by sample.
 *
 * to_nm interpolates linearly between samples (0 outside the grid); from_nm takes the hat-weighted
 * average around each sample (energy conserving, the identity at 1 nm; see include/generic/spectral.h). to_xyz
 * and brightness use weights computed once from the CIE tables through that same interpolation, so
 * they agree with the nm path while costing n multiply-adds. */
#include "generic/plugin.h"
#include "generic/spectral.h"
#include "generic/spectral_kernels.h"

#include <math.h>

/** Samples of the default grid (380..780 nm every 5 nm), which has operations of its own below. */
enum { FAST_N = 81 };

/* The model's priv struct is a plain GSpectral. */
static int spectrum_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    return gspectral_model_init(self, opt, 5.0, GSPECTRAL_MAX_SAMPLES, 0, err);
}

/* ---- the default grid's operations ----
 *
 * The operations run per ray, on the default grid (81 samples: ten 8-float blocks and one sample), as loops of
 * a constant count unrolled whole: the kit's loops over any count spend about a third of their instructions on
 * the index, the compare and the branch. Each computes what the kit's operation does, in the same order, so the
 * results are equal bit for bit (tests/test_spectrum_fast.c); another grid, or a processor without AVX2, takes
 * the kit's. */
#ifdef GSPECTRAL_AVX2
/** Samples in the default grid's whole 8-float blocks. */
enum { FAST_BLOCKS = 80 };

/** Before a loop over the default grid's blocks: unrolled whole. */
#define FAST_UNROLL _Pragma("GCC unroll 10")

/* o = a op b on the default grid (op a constant once inlined, as in the kit's gspectral_kmap8) */
static inline GSPECTRAL_TARGET_AVX2 void map81(GSpectralOp op, float *o, const float *x, const float *y)
{
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8) { /* o may be x or y: each block is loaded before it is stored */
        gspectral_v8 a = gspectral_vload8(x + i), b = gspectral_vload8(y + i);
        gspectral_vstore8(o + i, op == GSPECTRAL_ADD ? a + b : a * b);
    }
    o[FAST_BLOCKS] = op == GSPECTRAL_ADD ? x[FAST_BLOCKS] + y[FAST_BLOCKS] : x[FAST_BLOCKS] * y[FAST_BLOCKS];
}

static GSPECTRAL_TARGET_AVX2 int spectrum_add_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (m->nvalues != FAST_N)
        return gspectral_add(m, out, a, b);
    map81(GSPECTRAL_ADD, out->v, a->v, b->v);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int spectrum_mul_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (m->nvalues != FAST_N)
        return gspectral_mul(m, out, a, b);
    map81(GSPECTRAL_MUL, out->v, a->v, b->v);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int spectrum_scale_v8(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    if (m->nvalues != FAST_N)
        return gspectral_scale(m, out, a, s);
    float *o = out->v, f = (float)s;
    const float *x = a->v;
    const gspectral_v8 sv = {f, f, f, f, f, f, f, f};
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8)
        gspectral_vstore8(o + i, gspectral_vload8(x + i) * sv);
    o[FAST_BLOCKS] = x[FAST_BLOCKS] * f;
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

/* +0.0 in every sample, as the kit's memset gives */
static GSPECTRAL_TARGET_AVX2 void spectrum_black_v8(const GColorModel *m, GColor *out)
{
    if (m->nvalues != FAST_N) {
        gspectral_black(m, out);
        return;
    }
    float *o = out->v;
    const gspectral_v8 zero = {0, 0, 0, 0, 0, 0, 0, 0};
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8)
        gspectral_vstore8(o + i, zero);
    o[FAST_BLOCKS] = 0.0f;
    out->kind = GCOLOR_VECTOR;
}

/* gspectral_kdiv8's quotients: 0 where the divisor is 0 (that lane divides by 1 and is cleared) */
static GSPECTRAL_TARGET_AVX2 int spectrum_div_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (m->nvalues != FAST_N)
        return gspectral_div(m, out, a, b);
    float *o = out->v;
    const float *x = a->v, *y = b->v;
    const gspectral_v8 one = {1, 1, 1, 1, 1, 1, 1, 1}, zero = {0, 0, 0, 0, 0, 0, 0, 0};
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8) {
        gspectral_v8 d = gspectral_vload8(y + i);
        gspectral_v8i nz = d != zero;
        gspectral_v8 safe = (gspectral_v8)(((gspectral_v8i)d & nz) | ((gspectral_v8i)one & ~nz));
        gspectral_vstore8(o + i, (gspectral_v8)((gspectral_v8i)(gspectral_vload8(x + i) / safe) & nz));
    }
    o[FAST_BLOCKS] = y[FAST_BLOCKS] != 0.0f ? x[FAST_BLOCKS] / y[FAST_BLOCKS] : 0.0f;
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

/* gspectral_kbright8's sum: the blocks one after another into 8 lanes, the halves added, the 4 lanes in double,
 * then the last sample's product. */
static GSPECTRAL_TARGET_AVX2 double spectrum_brightness_v8(const GColorModel *m, const GColor *a)
{
    if (m->nvalues != FAST_N)
        return gspectral_brightness(m, a);
    const float *w = ((const GSpectral *)m->priv)->lum, *x = a->v;
    gspectral_v8 acc = {0, 0, 0, 0, 0, 0, 0, 0};
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8)
        acc += gspectral_vterm8(GSPECTRAL_WABS, gspectral_vload8(w + i), gspectral_vload8(x + i));
    gspectral_v4 f = gspectral_vfold8(acc);
    double sum = (double)f[0] + f[1] + f[2] + f[3];
    return sum + w[FAST_BLOCKS] * fabsf(x[FAST_BLOCKS]);
}

static void spectrum_black_v4(const GColorModel *m, GColor *out) { gspectral_black(m, out); }

static int spectrum_div_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_div(m, out, a, b);
}

/* gspectral_kxyz8's sums: per coordinate the blocks one after another into 8 lanes, the last sample's product in
 * a float, the lanes' halves added, the 4 lanes in pairs and that float added in double. */
static GSPECTRAL_TARGET_AVX2 int spectrum_to_xyz_v8(const GColorModel *m, const GColor *a, GColorRole role,
                                                    double xyz[3])
{
    if (m->nvalues != FAST_N)
        return gspectral_to_xyz(m, a, role, xyz);
    const float *t = gspectral_xyz_floats(m->priv, role), *v = a->v;
    gspectral_v8 x = {0, 0, 0, 0, 0, 0, 0, 0}, y = x, z = x;
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8) {
        gspectral_v8 s = gspectral_vload8(v + i);
        x += s * gspectral_vload8(t + i * 3);
        y += s * gspectral_vload8(t + i * 3 + 8);
        z += s * gspectral_vload8(t + i * 3 + 16);
    }
    const float *b = t + FAST_BLOCKS * 3; /* the last sample: lane 0 of the table's last block */
    float tail[3] = {0.0f, 0.0f, 0.0f};
    tail[0] += v[FAST_BLOCKS] * b[0];
    tail[1] += v[FAST_BLOCKS] * b[8];
    tail[2] += v[FAST_BLOCKS] * b[16];
    __m256d dx = _mm256_cvtps_pd((__m128)gspectral_vfold8(x)), dy = _mm256_cvtps_pd((__m128)gspectral_vfold8(y));
    __m256d dz = _mm256_cvtps_pd((__m128)gspectral_vfold8(z));
    __m256d xy = _mm256_hadd_pd(dx, dy), zz = _mm256_hadd_pd(dz, dz);
    __m128d sxy = _mm_add_pd(_mm256_castpd256_pd128(xy), _mm256_extractf128_pd(xy, 1));
    __m128d sz = _mm_add_sd(_mm256_castpd256_pd128(zz), _mm256_extractf128_pd(zz, 1));
    __m128d txy = _mm_cvtps_pd(_mm_setr_ps(tail[0], tail[1], 0.0f, 0.0f));
    _mm_storeu_pd(xyz, _mm_add_pd(sxy, txy));
    xyz[2] = _mm_cvtsd_f64(sz) + (double)tail[2];
    return G_OK;
}

static int spectrum_to_xyz_v4(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    return gspectral_to_xyz(m, a, role, xyz);
}

static int spectrum_add_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_add(m, out, a, b);
}

static int spectrum_mul_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_mul(m, out, a, b);
}

static int spectrum_scale_v4(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    return gspectral_scale(m, out, a, s);
}

static double spectrum_brightness_v4(const GColorModel *m, const GColor *a) { return gspectral_brightness(m, a); }

static int spectrum_to_xyz(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3]);
static void spectrum_black(const GColorModel *m, GColor *out);
static int spectrum_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
static double spectrum_brightness(const GColorModel *m, const GColor *a);
GSPECTRAL_PICK(spectrum_to_xyz);
GSPECTRAL_PICK(spectrum_black);
GSPECTRAL_PICK(spectrum_div);
GSPECTRAL_PICK(spectrum_add);
GSPECTRAL_PICK(spectrum_mul);
GSPECTRAL_PICK(spectrum_scale);
GSPECTRAL_PICK(spectrum_brightness);
#else
#define spectrum_to_xyz gspectral_to_xyz
#define spectrum_black gspectral_black
#define spectrum_div gspectral_div
#define spectrum_add gspectral_add
#define spectrum_mul gspectral_mul
#define spectrum_scale gspectral_scale
#define spectrum_brightness gspectral_brightness
#endif

static const GColorModelClass gcolormodel_spectrum = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "spectrum",
    .description = "spectrum sampled every step_nm (default 380..780 nm at 5 nm)",
    .init = spectrum_init,
    .fini = gspectral_model_fini,
    .black = spectrum_black,
    .add = spectrum_add,
    .mul = spectrum_mul,
    .scale = spectrum_scale,
    .div = spectrum_div,
    .pow = gspectral_pow,
    .brightness = spectrum_brightness,
    .to_nm = gspectral_to_nm,
    .from_nm = gspectral_from_nm,
    .to_xyz = spectrum_to_xyz,
    .from_rgb = gspectral_from_rgb,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

GENERIC_TYPE(spectrum, GKIND_COLORMODEL, &gcolormodel_spectrum, NULL, NULL);
