/* spectrum9.c - nine spectral samples at 380, 430, ..., 780 nm (the four-sample spline model of
 * Stürzlinger's example, with more samples). A vector is 9 floats; its operations work sample by sample.
 *
 * to_nm reconstructs the natural cubic spline through the nine samples (second derivative 0 at both
 * ends), evaluated from a table of the nine cardinal splines at every nm built once. from_nm takes the samples whose
 * spline is nearest the spectrum (least squares), then corrects their XYZ in the role through the corrected RGB basis
 * (the exact correction from_rgb's basis has), so a spectrum's colour is kept; a light that would need a negative
 * sample (a narrow line) gets 0 there. Sampling then reconstructing smooths a spectrum (features narrower than
 * ~100 nm are lost): this model trades accuracy for size. With the basis uplift, saturated reflectances get samples
 * outside [0, 1] (down to -0.13 and up to 1.13 for the sRGB primaries), which nine spline samples need to reach their
 * chroma. The grid is fixed; options other than its own values are refused.
 *
 * Matrices. A fluorescent reflectance is a 9 x 9 GCOLOR_MATRIX A[o * 9 + i] (row o the sample going out, column i
 * the sample coming in): its re-radiation matrix reduced onto the nine samples (gcolormodel_reduce_reradiation_by,
 * through the linear projection of from_nm), as rgb holds a 3 x 3 one. A vector v stands for diag(v); add, mul
 * (M*V the light A v), scale, axpy, div, pow and exp follow rgb's rules (colormodels/rgb.c); brightness, to_nm and
 * to_xyz read a matrix by its response to white (its row sums). Every value has room for 81 floats; a vector's
 * operations are the kit's kernels on the nine samples, in the body behind one test of the kinds. */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"
#include "generic/kit/spectral_kernels.h"

#include <math.h>
#include <string.h>

enum { N9 = 9 };

typedef struct Spectrum9 {
    GSpectral s;
    float spline[GNM_COUNT][N9]; /* cardinal natural splines at every nm */
    float project[N9][GNM_COUNT]; /* least squares: the samples whose spline is nearest an nm spectrum */
} Spectrum9;

/* project = (S^T S)^-1 S^T for the spline matrix S (GNM_COUNT x 9), by Gauss-Jordan on the 9 x 9 normal matrix
 * (symmetric positive definite: the cardinal splines are independent). */
static void build_projection(Spectrum9 *p)
{
    double a[N9][2 * N9];
    for (int r = 0; r < N9; r++)
        for (int c = 0; c < N9; c++) {
            double sum = 0.0;
            for (int i = 0; i < GNM_COUNT; i++)
                sum += (double)p->spline[i][r] * p->spline[i][c];
            a[r][c] = sum;
            a[r][N9 + c] = r == c;
        }
    for (int c = 0; c < N9; c++) {
        int piv = c;
        for (int r = c + 1; r < N9; r++)
            if (fabs(a[r][c]) > fabs(a[piv][c]))
                piv = r;
        for (int k = 0; k < 2 * N9; k++) {
            double t = a[c][k];
            a[c][k] = a[piv][k];
            a[piv][k] = t;
        }
        double d = a[c][c];
        for (int k = 0; k < 2 * N9; k++)
            a[c][k] /= d;
        for (int r = 0; r < N9; r++)
            if (r != c) {
                double f = a[r][c];
                for (int k = 0; k < 2 * N9; k++)
                    a[r][k] -= f * a[c][k];
            }
    }
    for (int k = 0; k < N9; k++)
        for (int i = 0; i < GNM_COUNT; i++) {
            double sum = 0.0;
            for (int j = 0; j < N9; j++)
                sum += a[k][N9 + j] * p->spline[i][j];
            p->project[k][i] = (float)sum;
        }
}

/* Natural cubic spline through y at x_i = i * h: second derivatives M with M_0 = M_{n-1} = 0 solve
 * M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i-1} - 2 y_i + y_{i+1}) / h^2 (Thomas algorithm). */
static void natural_spline_m(const double y[N9], double h, double mm[N9])
{
    double c[N9], d[N9];
    mm[0] = mm[N9 - 1] = 0.0;
    c[0] = d[0] = 0.0;
    for (int i = 1; i < N9 - 1; i++) {
        double rhs = 6.0 * (y[i - 1] - 2.0 * y[i] + y[i + 1]) / (h * h);
        double den = 4.0 - c[i - 1];
        c[i] = 1.0 / den;
        d[i] = (rhs - d[i - 1]) / den;
    }
    for (int i = N9 - 2; i >= 1; i--)
        mm[i] = d[i] - c[i] * mm[i + 1];
}

static void build_spline(Spectrum9 *p, GSpectralGrid g)
{
    for (int k = 0; k < N9; k++) {
        double y[N9] = {0}, mm[N9];
        y[k] = 1.0;
        natural_spline_m(y, g.step, mm);
        for (int i = 0; i < GNM_COUNT; i++) {
            double f = (GNM_MIN + i - g.min) / g.step;
            int j = (int)f;
            if (j > N9 - 2)
                j = N9 - 2;
            double t = f - j, u = 1.0 - t, h2 = g.step * g.step / 6.0;
            p->spline[i][k] =
                (float)(u * y[j] + t * y[j + 1] + h2 * ((u * u * u - u) * mm[j] + (t * t * t - t) * mm[j + 1]));
        }
    }
}

static int spectrum9_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    GSpectralGrid grid = {380.0, 50.0, N9};
    int rc = gspectral_grid_check_fixed("spectrum9", opt, grid, err);
    if (rc == G_OK)
        rc = gspectral_model_alloc(self, sizeof(Spectrum9), N9 * N9, err); /* room for a 9 x 9 matrix */
    if (rc != G_OK)
        return rc;
    Spectrum9 *p = self->priv;
    build_spline(p, grid);
    build_projection(p);
    rc = gspectral_init(self, &p->s, grid, 0, err);
    return rc == G_OK ? gspectral_set_uplift(self, &p->s, opt, err) : rc;
}

static void fold(const GColor *a, float d[N9]);

static int spectrum9_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)role;
    const Spectrum9 *p = m->priv;
    float folded[N9];
    const float *v = a->v;
    if (a->kind == GCOLOR_MATRIX) { /* its response to white */
        fold(a, folded);
        v = folded;
    }
    for (int i = 0; i < GNM_COUNT; i++) {
        const float *w = p->spline[i];
        float s = 0.0f;
        for (int k = 0; k < N9; k++)
            s += w[k] * v[k];
        out->v[i] = s;
    }
    return G_OK;
}

/* The samples plus the correction of their XYZ in the role to want, through the corrected RGB basis. */
static int correct_xyz(const GColorModel *m, const double want[3], GColorRole role, GColor *out, float d[N9])
{
    const Spectrum9 *p = m->priv;
    double got[3], dx[3], rgb[3];
    int rc = gspectral_to_xyz(m, out, role, got);
    if (rc != G_OK)
        return rc;
    for (int c = 0; c < 3; c++)
        dx[c] = want[c] - got[c];
    gcie_xyz_to_rgb(dx, rgb);
    const float *b = p->s.rgb[role == GCOLOR_LIGHT];
    for (int k = 0; k < N9; k++)
        d[k] = (float)(rgb[0] * b[k] + rgb[1] * b[N9 + k] + rgb[2] * b[2 * N9 + k]);
    return G_OK;
}

/* The least-squares samples of the spline nearest the spectrum. */
static void least_squares(const Spectrum9 *p, const GSpectrumNM *in, GColor *out)
{
    out->kind = GCOLOR_VECTOR;
    for (int k = 0; k < N9; k++) {
        double sum = 0.0;
        for (int i = 0; i < GNM_COUNT; i++)
            sum += (double)p->project[k][i] * in->v[i];
        out->v[k] = (float)sum;
    }
}

/* The linear projection: the least-squares samples, then the rest of the spectrum's XYZ in the role through the
 * corrected RGB basis (the exact correction from_rgb's basis has), so the spectrum's colour is kept exactly, a
 * light's as a light and a reflectance's under D65. Samples may be negative (a narrow line). */
static int spectrum9_project(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    double want[3];
    float d[N9];
    least_squares(m->priv, in, out);
    gcie_nm_to_xyz(in, role, want);
    int rc = correct_xyz(m, want, role, out, d);
    for (int k = 0; rc == G_OK && k < N9; k++)
        out->v[k] += d[k];
    return rc;
}

/* The linear projection (spectrum9_project); a light that would need a negative sample (a narrow line) has those
 * samples set to 0, the rest as they are: the colour nearest the line's that non-negative samples hold, brighter
 * than the line (restoring the luminance instead would darken the samples that remain and move the colour far
 * more: measured in tests/test_gtrace_fluorescent_rgb.c). */
static int spectrum9_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    int rc = spectrum9_project(m, in, role, out);
    for (int k = 0; rc == G_OK && role == GCOLOR_LIGHT && k < N9; k++)
        out->v[k] = fmaxf(out->v[k], 0.0f); /* a reflectance keeps its colour; the parameter range rule judges it */
    return rc;
}

/* ---- re-radiation matrices (9 x 9, A[o * 9 + i]); a vector v stands for diag(v) ---- */

/* The plain part: a vector itself, a matrix its diagonal. */
static void diagonal(const GColor *a, float d[N9])
{
    for (int k = 0; k < N9; k++)
        d[k] = a->kind == GCOLOR_MATRIX ? a->v[k * N9 + k] : a->v[k];
}

/* The response to the unit light of every sample (the samples' white): a vector itself, a matrix its row sums. */
static void fold(const GColor *a, float d[N9])
{
    for (int o = 0; o < N9; o++) {
        double s = 0.0;
        for (int i = 0; a->kind == GCOLOR_MATRIX && i < N9; i++)
            s += a->v[o * N9 + i];
        d[o] = a->kind == GCOLOR_MATRIX ? (float)s : a->v[o];
    }
}

static void as_matrix(const GColor *a, float x[N9 * N9])
{
    if (a->kind == GCOLOR_MATRIX) {
        memcpy(x, a->v, N9 * N9 * sizeof *x);
        return;
    }
    memset(x, 0, N9 * N9 * sizeof *x);
    for (int k = 0; k < N9; k++)
        x[k * N9 + k] = a->v[k];
}

/* A stack vector of the model around d. */
static GColor vector_of(const GColorModel *m, float *d)
{
    return (GColor){.model = m, .v = d, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_CALLER, .capacity = N9 * N9};
}

/* add, mul, scale, div, axpy and brightness with a matrix operand (the per-ray bodies below take two vectors
 * themselves): out of line, so that the vector path keeps no stack for them. */
__attribute__((noinline)) static int add_matrix(GColor *out, const GColor *a, const GColor *b)
{
    float x[N9 * N9], y[N9 * N9];
    as_matrix(a, x);
    as_matrix(b, y);
    for (int k = 0; k < N9 * N9; k++)
        out->v[k] = x[k] + y[k];
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

/* M*M the product A B; V*M diag(a) B; M*V the light A v (a vector on the right is a light). */
__attribute__((noinline)) static int mul_matrix(GColor *out, const GColor *a, const GColor *b)
{
    float x[N9 * N9], y[N9 * N9];
    as_matrix(a, x);
    if (b->kind == GCOLOR_VECTOR) {
        float l[N9];
        memcpy(l, b->v, sizeof l);
        for (int o = 0; o < N9; o++) {
            float s = 0.0f;
            for (int i = 0; i < N9; i++)
                s += x[o * N9 + i] * l[i];
            out->v[o] = s;
        }
        out->kind = GCOLOR_VECTOR;
        return G_OK;
    }
    as_matrix(b, y);
    for (int o = 0; o < N9; o++)
        for (int i = 0; i < N9; i++) {
            float s = 0.0f;
            for (int k = 0; k < N9; k++)
                s += x[o * N9 + k] * y[k * N9 + i];
            out->v[o * N9 + i] = s;
        }
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

__attribute__((noinline)) static int scale_matrix(GColor *out, const GColor *a, double s)
{
    for (int k = 0; k < N9 * N9; k++)
        out->v[k] = a->v[k] * (float)s;
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

/* div, pow, exp: the diagonals, a vector (a medium absorbs, it does not fluoresce). */
__attribute__((noinline)) static int div_matrix(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    float x[N9], y[N9];
    diagonal(a, x);
    diagonal(b, y);
    GColor va = vector_of(m, x), vb = vector_of(m, y);
    return gspectral_div(m, out, &va, &vb);
}

static int spectrum9_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    if (a->kind == GCOLOR_VECTOR)
        return gspectral_pow(m, out, a, e);
    float x[N9];
    diagonal(a, x);
    GColor va = vector_of(m, x);
    return gspectral_pow(m, out, &va, e);
}

/* exp(s a) per sample of the plain part: for a vector the library's default, computed the same way */
static int spectrum9_exp_scaled(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    (void)m;
    float x[N9];
    diagonal(a, x);
    for (int k = 0; k < N9; k++)
        out->v[k] = (float)exp(s * x[k]);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

/* out = s a + b with a matrix operand: per entry (two vectors: the library's default, the kit's kernel) */
__attribute__((noinline)) static int axpy_matrix(GColor *out, double s, const GColor *a, const GColor *b)
{
    float x[N9 * N9], y[N9 * N9];
    as_matrix(a, x);
    as_matrix(b, y);
    for (int k = 0; k < N9 * N9; k++)
        out->v[k] = y[k] + (float)(x[k] * s);
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

/* A matrix: the brightness of its response to white with entries taken by magnitude, sum_o w_o sum_i |A[o][i]|. */
__attribute__((noinline)) static double brightness_matrix(const GColorModel *m, const GColor *a)
{
    float r[N9];
    for (int o = 0; o < N9; o++) {
        float s = 0.0f;
        for (int i = 0; i < N9; i++)
            s += fabsf(a->v[o * N9 + i]);
        r[o] = s;
    }
    GColor vr = vector_of(m, r);
    return gspectral_brightness(m, &vr);
}

/* The per-ray operations, two vectors in the body itself: on 4-float vectors and, compiled for AVX2, on 8-float ones
 * with the nine samples as a constant (straight-line code: one block and one sample), the kit's kernels either
 * way, so the same results bit for bit as the kit's operations; GSPECTRAL_PICK (spectral_kernels.h) binds each
 * name to one of the two when the library is loaded, so a call from the class table goes straight to it. */
#define S9_VECTORS(a, b) ((a)->kind == GCOLOR_VECTOR && (b)->kind == GCOLOR_VECTOR)
#define S9_ADD(map)                                                                                            \
    do {                                                                                                       \
        (void)m;                                                                                               \
        if (!S9_VECTORS(a, b))                                                                                 \
            return add_matrix(out, a, b);                                                                      \
        out->kind = GCOLOR_VECTOR;                                                                             \
        map(GSPECTRAL_ADD, out->v, a->v, b->v, N9);                                                            \
        return G_OK;                                                                                           \
    } while (0)
#define S9_MUL(map)                                                                                            \
    do {                                                                                                       \
        (void)m;                                                                                               \
        if (!S9_VECTORS(a, b))                                                                                 \
            return mul_matrix(out, a, b);                                                                      \
        out->kind = GCOLOR_VECTOR;                                                                             \
        map(GSPECTRAL_MUL, out->v, a->v, b->v, N9);                                                            \
        return G_OK;                                                                                           \
    } while (0)
#define S9_SCALE(scale)                                                                                        \
    do {                                                                                                       \
        (void)m;                                                                                               \
        if (a->kind != GCOLOR_VECTOR)                                                                          \
            return scale_matrix(out, a, s);                                                                    \
        out->kind = GCOLOR_VECTOR;                                                                             \
        scale(out->v, a->v, (float)s, N9);                                                                     \
        return G_OK;                                                                                           \
    } while (0)
#define S9_DIV(div)                                                                                            \
    do {                                                                                                       \
        if (!S9_VECTORS(a, b))                                                                                 \
            return div_matrix(m, out, a, b);                                                                   \
        out->kind = GCOLOR_VECTOR;                                                                             \
        div(out->v, a->v, b->v, N9);                                                                           \
        return G_OK;                                                                                           \
    } while (0)
#define S9_AXPY(axpyd)                                                                                         \
    do {                                                                                                       \
        (void)m;                                                                                               \
        if (!S9_VECTORS(a, b))                                                                                 \
            return axpy_matrix(out, s, a, b);                                                                  \
        axpyd(out->v, s, a->v, b->v, N9);                                                                      \
        out->kind = GCOLOR_VECTOR;                                                                             \
        return G_OK;                                                                                           \
    } while (0)
#define S9_BRIGHTNESS(bright)                                                                                  \
    do {                                                                                                       \
        if (a->kind != GCOLOR_VECTOR)                                                                          \
            return brightness_matrix(m, a);                                                                    \
        const Spectrum9 *p = m->priv;                                                                          \
        return bright(p->s.lum, a->v, N9);                                                                     \
    } while (0)

static int spectrum9_add_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    S9_ADD(gspectral_kmap);
}

static int spectrum9_mul_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    S9_MUL(gspectral_kmap);
}

static int spectrum9_scale_v4(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    S9_SCALE(gspectral_kscale);
}

static int spectrum9_div_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    S9_DIV(gspectral_kdiv);
}

static int spectrum9_axpy_v4(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b)
{
    S9_AXPY(gspectral_kaxpyd);
}

static double spectrum9_brightness_v4(const GColorModel *m, const GColor *a) { S9_BRIGHTNESS(gspectral_kbright); }

#ifdef GSPECTRAL_AVX2
static int spectrum9_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum9_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum9_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
static int spectrum9_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int spectrum9_axpy(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b);
static double spectrum9_brightness(const GColorModel *m, const GColor *a);

static GSPECTRAL_TARGET_AVX2 int spectrum9_add_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    S9_ADD(gspectral_kmap8);
}

static GSPECTRAL_TARGET_AVX2 int spectrum9_mul_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    S9_MUL(gspectral_kmap8);
}

static GSPECTRAL_TARGET_AVX2 int spectrum9_scale_v8(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    S9_SCALE(gspectral_kscale8);
}

static GSPECTRAL_TARGET_AVX2 int spectrum9_div_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    S9_DIV(gspectral_kdiv8);
}

static GSPECTRAL_TARGET_AVX2 int spectrum9_axpy_v8(const GColorModel *m, GColor *out, double s, const GColor *a,
                                                   const GColor *b)
{
    S9_AXPY(gspectral_kaxpyd8);
}

static GSPECTRAL_TARGET_AVX2 double spectrum9_brightness_v8(const GColorModel *m, const GColor *a)
{
    S9_BRIGHTNESS(gspectral_kbright8);
}

GSPECTRAL_PICK(spectrum9_add);
GSPECTRAL_PICK(spectrum9_mul);
GSPECTRAL_PICK(spectrum9_scale);
GSPECTRAL_PICK(spectrum9_div);
GSPECTRAL_PICK(spectrum9_axpy);
GSPECTRAL_PICK(spectrum9_brightness);
#else
#define spectrum9_add spectrum9_add_v4
#define spectrum9_mul spectrum9_mul_v4
#define spectrum9_scale spectrum9_scale_v4
#define spectrum9_div spectrum9_div_v4
#define spectrum9_axpy spectrum9_axpy_v4
#define spectrum9_brightness spectrum9_brightness_v4
#endif

static int spectrum9_from_reradiation(const GColorModel *m, const GReradiation *r, GColor *out, GError *err)
{
    return gcolormodel_reduce_reradiation_by(m, r, spectrum9_project, out, err);
}

static const GColorModelClass gcolormodel_spectrum9 = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "spectrum9",
    .description = "9 samples 380..780 nm every 50 nm, natural cubic spline in between",
    .init = spectrum9_init,
    .fini = gspectral_model_fini,
    .black = gspectral_black,
    .add = spectrum9_add,
    .mul = spectrum9_mul,
    .scale = spectrum9_scale,
    .div = spectrum9_div,
    .pow = spectrum9_pow,
    .brightness = spectrum9_brightness,
    .to_nm = spectrum9_to_nm,
    .from_nm = spectrum9_from_nm,
    .to_xyz = gspectral_to_xyz_folded, /* a matrix reads as its response to white (the row sums) */
    .from_rgb = gspectral_from_rgb,
    .from_reradiation = spectrum9_from_reradiation,
    .exp_scaled = spectrum9_exp_scaled,
    .axpy = spectrum9_axpy,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

/* The grid is fixed: the options may only repeat it. */
static const GParamInfo spectrum9_params[] = {
    {"step", GPARAM_NAMED, "number", "50", "50", "the spacing of the samples, in nm (fixed; another is refused)"},
    {"min", GPARAM_NAMED, "number", "380", "380", "the first sample, in nm (fixed)"},
    {"max", GPARAM_NAMED, "number", "780", "780", "the last sample, in nm (fixed)"},
    {"uplift", GPARAM_NAMED, "choice", "sigmoid", "sigmoid, basis",
     "how RGB colours become spectra: sigmoid (smooth, a reflectance within [0, 1]) or basis (the exact linear basis)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(spectrum9, GKIND_COLORMODEL, &gcolormodel_spectrum9, NULL, NULL, spectrum9_params);
