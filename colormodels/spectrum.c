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
/** Samples of the default grid, and those in its whole 8-float blocks. */
enum { FAST_N = 81, FAST_BLOCKS = 80 };

/** Before a loop over the default grid's blocks: unrolled whole. */
#define FAST_UNROLL _Pragma("GCC unroll 10")

static GSPECTRAL_TARGET_AVX2 int spectrum_add_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (m->nvalues != FAST_N)
        return gspectral_add(m, out, a, b);
    float *o = out->v;
    const float *x = a->v, *y = b->v;
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8) /* out may be a or b: each block is loaded before it is stored */
        gspectral_vstore8(o + i, gspectral_vload8(x + i) + gspectral_vload8(y + i));
    o[FAST_BLOCKS] = x[FAST_BLOCKS] + y[FAST_BLOCKS];
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int spectrum_mul_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (m->nvalues != FAST_N)
        return gspectral_mul(m, out, a, b);
    float *o = out->v;
    const float *x = a->v, *y = b->v;
    FAST_UNROLL
    for (int i = 0; i < FAST_BLOCKS; i += 8)
        gspectral_vstore8(o + i, gspectral_vload8(x + i) * gspectral_vload8(y + i));
    o[FAST_BLOCKS] = x[FAST_BLOCKS] * y[FAST_BLOCKS];
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

static void spectrum_black(const GColorModel *m, GColor *out);
static int spectrum_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
static double spectrum_brightness(const GColorModel *m, const GColor *a);
GSPECTRAL_PICK(spectrum_black);
GSPECTRAL_PICK(spectrum_div);
GSPECTRAL_PICK(spectrum_add);
GSPECTRAL_PICK(spectrum_mul);
GSPECTRAL_PICK(spectrum_scale);
GSPECTRAL_PICK(spectrum_brightness);
#else
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
    .to_xyz = gspectral_to_xyz,
    .from_rgb = gspectral_from_rgb,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

GENERIC_TYPE(spectrum, GKIND_COLORMODEL, &gcolormodel_spectrum, NULL, NULL);
