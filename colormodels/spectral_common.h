/* spectral_common.h - what the spectral colour models (spectrum9, spectrum, bispectral) share: their
 * uniform wavelength grid, resampling between grids, and the colorimetric tables built once per model
 * (brightness weights, colour matching weights, the RGB basis with its exact round-trip correction).
 * Private to colormodels/. */
#ifndef GENERIC_SPECTRAL_COMMON_H
#define GENERIC_SPECTRAL_COMMON_H

#include "generic/color.h"

#include <math.h>
#include <string.h>

/** A uniform wavelength grid: n samples at min + k * step nm. */
typedef struct GSpectralGrid {
    double min, step;
    int n;
} GSpectralGrid;

/** A sparse linear map between two grids: dst[k] = sum_j w[off[k] + j] * src[first[k] + j], j < count[k].
 * Onto a grid at least as coarse as the source (unless built with interpolate) it is a hat-weighted average (triangle of half-width
 * dst.step around each destination sample, normalised by the weight it covers, source samples outside
 * the destination's range dropped); onto a finer grid it is linear interpolation (0 outside the source).
 * Both coincide for equal steps, and on the same grid the map is the identity. */
typedef struct GSpectralResample {
    int n;
    int *first, *count, *off;
    float *w;
} GSpectralResample;

/** What every spectral model keeps; the model's priv struct begins with it. */
typedef struct GSpectral {
    GSpectralGrid grid;
    GSpectralResample from_nm; /**< 1 nm exchange grid -> model grid */
    GSpectralResample to_nm;   /**< model grid -> 1 nm, linear interpolation (unused by spline models) */
    float *lum;                /**< brightness weights: > 0 everywhere, sum 1 */
    double *xyz[2];            /**< per GColorRole: 3 * n colour matching weights, [c * n + k] */
    float *rgb[2];             /**< per GColorRole: 3 * n RGB basis on the grid, corrected so the round trip
                                    rgb -> model -> rgb is exact */
} GSpectral;

/** A sanity limit on a spectral grid's samples (300..830 nm at 1 nm has 531). */
#define GSPECTRAL_MAX_SAMPLES 1024

/** Reads the grid from the options (zero fields take the defaults) and checks it: step in [1, 100] nm,
 * the range inside 300..830 nm and a whole number of steps, at most max_n samples. */
int gspectral_grid_from_options(const char *model, const GColorModelOptions *opt, double def_step, int max_n,
                                GSpectralGrid *grid, GError *err);

/** Builds a resampling map from src to dst (G_ERR_NOMEM when out of memory); with interpolate the map is
 * linear interpolation whatever the steps (for reflectances, which carry no energy to preserve). */
int gspectral_resample_build(GSpectralResample *r, GSpectralGrid src, GSpectralGrid dst, int interpolate);
/** Applies a map: dst[k * dst_stride] from src[j * src_stride]. */
void gspectral_resample_apply(const GSpectralResample *r, const float *src, int src_stride, float *dst,
                              int dst_stride);
/** Frees a map; a zeroed map is a no-op. */
void gspectral_resample_free(GSpectralResample *r);

/** Fills s for model m (m->priv must already point at the struct holding s, and everything the class's
 * to_nm needs must be ready): the resampling maps (the to_nm map only with linear_to_nm), then the
 * colorimetric tables; the colour matching weights come from m->cls->to_nm, so to_xyz agrees with the nm
 * path exactly. */
int gspectral_init(GColorModel *m, GSpectral *s, GSpectralGrid grid, int linear_to_nm, GError *err);
/** Frees what gspectral_init allocated. */
void gspectral_fini(GSpectral *s);

/** For a model's init: allocates its zeroed priv struct of `size` bytes (one that begins with its GSpectral)
 * into m->priv and sets m->capacity; G_ERR_NOMEM "out of memory creating colour model '<name>'". */
int gspectral_model_alloc(GColorModel *m, size_t size, int capacity, GError *err);
/** The init of a model whose priv struct is a plain GSpectral (spectrum, bispectral): the grid from the
 * options (gspectral_grid_from_options with def_step and max_n), n values per colour (n * n with
 * matrices), the linear to_nm map. */
int gspectral_model_init(GColorModel *m, const GColorModelOptions *opt, double def_step, int max_n, int matrices,
                         GError *err);
/** The fini of every spectral model: gspectral_fini on the priv struct, which is then freed. */
void gspectral_model_fini(GColorModel *m);

/* Operations of a plain sampled spectrum (vectors only), shared by the class tables. */
void gspectral_black(const GColorModel *m, GColor *out);
int gspectral_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
int gspectral_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
int gspectral_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
int gspectral_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
int gspectral_pow(const GColorModel *m, GColor *out, const GColor *a, double e);
double gspectral_brightness(const GColorModel *m, const GColor *a);
/** to_nm by linear interpolation (the GSpectral to_nm map). */
int gspectral_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out);
/** from_nm by the hat-weighted average. */
int gspectral_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out);
/** XYZ of a vector from the precomputed colour matching weights. */
int gspectral_to_xyz(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3]);
/** A vector from linear sRGB through the corrected RGB basis. */
int gspectral_from_rgb(const GColorModel *m, const double rgb[3], GColorRole role, GColor *out);

/* Kernels on float arrays, out may alias an operand (each block is loaded before it is stored). With GCC
 * or clang they work on 4-float vectors (memcpy'd in and out, so no alignment is assumed): -O2 alone does
 * not vectorise a loop whose operands may alias. */
#if defined(__GNUC__)
#define GSPECTRAL_VECTOR 1
typedef float gspectral_v4 __attribute__((vector_size(16)));
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
    for (; i + 4 <= n; i += 4)
        gspectral_vstore(o + i, gspectral_vload(a + i) * sv);
#endif
    for (; i < n; i++)
        o[i] = a[i] * s;
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

static inline float gspectral_term(GSpectralTerm t, float a, float b)
{
    return t == GSPECTRAL_ABS ? fabsf(a) : t == GSPECTRAL_DOT ? a * b : a * fabsf(b);
}

#ifdef GSPECTRAL_VECTOR
static inline gspectral_v4 gspectral_vabs(gspectral_v4 x)
{
    gspectral_v4i mask = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
    return (gspectral_v4)((gspectral_v4i)x & mask);
}

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

/** o = a / b sample by sample, zero where b is zero */
static inline void gspectral_kdiv(float *o, const float *a, const float *b, int n)
{
    for (int i = 0; i < n; i++)
        o[i] = b[i] != 0.0f ? a[i] / b[i] : 0.0f;
}

/** o = a ^ e sample by sample; non-positive samples give 0 (1 for e = 0), as in the rgb model */
static inline void gspectral_kpow(float *o, const float *a, double e, int n)
{
    float fe = (float)e, zero = e == 0.0 ? 1.0f : 0.0f;
    for (int i = 0; i < n; i++)
        o[i] = a[i] > 0.0f ? powf(a[i], fe) : zero;
}

#endif
