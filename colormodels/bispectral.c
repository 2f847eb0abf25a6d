/* bispectral.c - spectra and re-radiation matrices: the colour model for fluorescence.
 *
 * Grid. n samples from min_nm to max_nm every step_nm: 380..780 nm at 10 nm (n = 41) by default, any
 * grid the spectrum model accepts with at most 128 samples otherwise. Start it lower (min_nm = 300) to
 * keep ultraviolet excitation.
 *
 * Values. A VECTOR holds n floats: a light, or a plain reflectance applied sample by sample. A MATRIX
 * holds n*n floats A[o*n + i], row o = emission (out), column i = excitation (in); light L reflected by
 * it is (A L)[o] = sum_i A[o][i] L[i]. The diagonal is the plain reflectance; an off-diagonal entry is
 * the share of the light in excitation bin i (one grid step wide) re-radiated at o, so off-diagonal
 * entries scale with the step. A vector v stands for the operator diag(v); applied to the equal-energy
 * light 1 an operator gives a light, diag(v) 1 = v. Every value has capacity for n*n floats.
 *
 * Operations (V vector, M matrix). out may alias any operand; no operation allocates (matrix products
 * that alias use a stack buffer, hence the 128-sample limit).
 *   add    V+V per sample; M+M per entry; M+V and V+M give the matrix A + diag(v).
 *   mul    reflection of b by a, "a applied after b":
 *          V*V per sample; M*M the matrix product A B (B first, then A);
 *          V*M diag(a) B (each row of B scaled); M*V the light A v (a vector).
 *          mul cannot tell a light from a plain reflectance, so a vector on the right is always taken
 *          as a light. For a reflectance r, A r is the response of A diag(r) to equal-energy light:
 *          right where r is later lit by a flat light, an approximation otherwise. To compose exactly,
 *          put the reflectance on the left (V*M = diag(r) A) or turn it into a matrix first (add it to
 *          a zero matrix).
 *   scale  per entry, either kind.
 *   div    relative refraction index, per sample on diagonals (a matrix counts by its diagonal); the
 *          result is the vector d(a) / d(b), zero where d(b) is zero.
 *   pow    absorption, per sample on the diagonal; the result is a vector: a medium absorbs, it does
 *          not fluoresce, so transmittance^distance keeps only the plain part of a matrix.
 *   exp    exp(s a) per sample on the diagonal, a vector, for the same reason as pow.
 *   axpy   s a + b: per sample or entry for two values of one kind; a matrix and a vector give the matrix
 *          (s A + diag(b) or diag(s a) + B), as add does.
 *   fill   the constant c is the vector c (the operator c I); the library's default.
 *   brightness  V: sum_k w_k |v_k| with the kit's brightness weights (Y under D65, all > 0, sum 1).
 *          M: the brightness of its response to equal-energy light with entries taken by magnitude,
 *          sum_o w_o sum_i |A[o][i]| (for the non-negative matrices from_reradiation makes, exactly the
 *          brightness of A 1). 0 only for black; the constant c and c*I give c.
 *   black  a zero vector.
 *   to_nm, to_xyz  V: as the spectrum model (linear interpolation). M: the folded reflectance, its
 *          response to equal-energy light A 1 (the row sums), read in the role asked for. (The colour a
 *          fluorescent sample shows under D65 is that of the light mul(A, D65), converted as a light.)
 *   from_nm, from_rgb  vectors, as the spectrum model.
 *   from_reradiation  a GReradiation on any grid, resampled onto the model's grid:
 *          - negative entries are measurement noise and are clamped to 0;
 *          - the diagonal (excitation and emission wavelengths equal) is a reflectance: linearly
 *            interpolated at the model's wavelengths (0 outside the measured range);
 *          - off-diagonal entries are shares per excitation bin: divided by the source's excitation step
 *            they become a density, which is resampled along both axes the same way and multiplied by
 *            the model's step, so the re-radiated energy is preserved; energy whose shift is below one
 *            model step lands on the model's diagonal and stays there;
 *          - excitation and emission outside the model's range are dropped;
 *          - a matrix whose excitation and emission grids share no wavelength has no diagonal and is
 *            refused. */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"
#include "generic/kit/spectral_kernels.h"

#include <math.h>
#include <string.h>

enum { BI_MAX = 128 };

/* The model's priv struct is a plain GSpectral. */
static int bispectral_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    return gspectral_model_init(self, opt, 10.0, BI_MAX, 1, err);
}

/* ---- helpers ---- */

/* The samples a value stands for per wavelength: a vector itself, a matrix its diagonal. */
static void diagonal(const GColor *a, int n, float *d)
{
    if (a->kind == GCOLOR_MATRIX)
        for (int k = 0; k < n; k++)
            d[k] = a->v[k * n + k];
    else
        memcpy(d, a->v, (size_t)n * sizeof *d);
}

/* Response to equal-energy light: a vector itself, a matrix its row sums. */
static void fold(const GColor *a, int n, float *d)
{
    if (a->kind == GCOLOR_MATRIX)
        for (int o = 0; o < n; o++) {
            const float *row = a->v + o * n;
            double s = 0.0;
            for (int i = 0; i < n; i++)
                s += row[i];
            d[o] = (float)s;
        }
    else
        memcpy(d, a->v, (size_t)n * sizeof *d);
}

/* o = A B for n x n matrices; o must not alias A or B. */
static void matmul(float *o, const float *a, const float *b, int n)
{
    memset(o, 0, (size_t)n * n * sizeof *o);
    for (int r = 0; r < n; r++)
        for (int k = 0; k < n; k++) {
            float s = a[r * n + k];
            if (s != 0.0f)
                gspectral_kaxpy(o + r * n, b + k * n, s, n);
        }
}

/* ---- operations ---- */

static int bi_add_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    int n = m->nsamples;
    if (a->kind == GCOLOR_VECTOR && b->kind == GCOLOR_VECTOR) {
        out->kind = GCOLOR_VECTOR;
        gspectral_kadd(out->v, a->v, b->v, n);
        return G_OK;
    }
    if (a->kind == GCOLOR_MATRIX && b->kind == GCOLOR_MATRIX) {
        gspectral_kadd(out->v, a->v, b->v, n * n);
        out->kind = GCOLOR_MATRIX;
        return G_OK;
    }
    const GColor *mat = a->kind == GCOLOR_MATRIX ? a : b, *vec = a->kind == GCOLOR_MATRIX ? b : a;
    float d[BI_MAX];
    memcpy(d, vec->v, (size_t)n * sizeof *d);
    if (out->v != mat->v)
        memcpy(out->v, mat->v, (size_t)n * n * sizeof *out->v);
    for (int k = 0; k < n; k++)
        out->v[k * n + k] += d[k];
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

static int bi_mul_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    int n = m->nsamples;
    if (a->kind == GCOLOR_VECTOR && b->kind == GCOLOR_VECTOR) {
        out->kind = GCOLOR_VECTOR;
        gspectral_kmul(out->v, a->v, b->v, n);
        return G_OK;
    }
    if (a->kind == GCOLOR_MATRIX && b->kind == GCOLOR_MATRIX) {
        if (out->v == a->v || out->v == b->v) {
            float tmp[BI_MAX * BI_MAX];
            matmul(tmp, a->v, b->v, n);
            memcpy(out->v, tmp, (size_t)n * n * sizeof *tmp);
        } else {
            matmul(out->v, a->v, b->v, n);
        }
        out->kind = GCOLOR_MATRIX;
        return G_OK;
    }
    if (a->kind == GCOLOR_VECTOR) { /* diag(a) B */
        float d[BI_MAX];
        memcpy(d, a->v, (size_t)n * sizeof *d);
        for (int r = 0; r < n; r++)
            gspectral_kscale(out->v + r * n, b->v + r * n, d[r], n);
        out->kind = GCOLOR_MATRIX;
        return G_OK;
    }
    float t[BI_MAX]; /* A v */
    for (int r = 0; r < n; r++)
        t[r] = gspectral_kdot(a->v + r * n, b->v, n);
    memcpy(out->v, t, (size_t)n * sizeof *t);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int bi_scale_v4(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    int n = m->nsamples;
    gspectral_kscale(out->v, a->v, (float)s, a->kind == GCOLOR_MATRIX ? n * n : n);
    out->kind = a->kind;
    return G_OK;
}

static int bi_div_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    int n = m->nsamples;
    float da[BI_MAX], db[BI_MAX];
    diagonal(a, n, da);
    diagonal(b, n, db);
    gspectral_kdiv(out->v, da, db, n);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int bi_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    int n = m->nsamples;
    float d[BI_MAX];
    diagonal(a, n, d);
    gspectral_kpow(out->v, d, e, n);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int bi_exp(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    int n = m->nsamples;
    float d[BI_MAX];
    diagonal(a, n, d);
    for (int k = 0; k < n; k++)
        out->v[k] = (float)exp(s * d[k]);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int bi_axpy_v4(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b)
{
    int n = m->nsamples;
    if (a->kind == b->kind) {
        gspectral_kaxpyd(out->v, s, a->v, b->v, a->kind == GCOLOR_MATRIX ? n * n : n);
        out->kind = a->kind;
        return G_OK;
    }
    float d[BI_MAX]; /* the vector, kept before out (which may alias it) becomes the matrix */
    if (a->kind == GCOLOR_MATRIX) { /* s A + diag(b) */
        memcpy(d, b->v, (size_t)n * sizeof *d);
        gspectral_kscale(out->v, a->v, (float)s, n * n);
        for (int k = 0; k < n; k++)
            out->v[k * n + k] += d[k];
    } else { /* diag(s a) + B */
        memcpy(d, a->v, (size_t)n * sizeof *d);
        if (out->v != b->v)
            memcpy(out->v, b->v, (size_t)n * n * sizeof *out->v);
        for (int k = 0; k < n; k++)
            out->v[k * n + k] += (float)(d[k] * s);
    }
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

static double bi_brightness_v4(const GColorModel *m, const GColor *a)
{
    const GSpectral *p = m->priv;
    int n = m->nsamples;
    if (a->kind == GCOLOR_VECTOR)
        return gspectral_kbright(p->lum, a->v, n);
    double s = 0.0;
    for (int o = 0; o < n; o++)
        s += p->lum[o] * gspectral_kabs(a->v + o * n, n);
    return s;
}

/* The per-ray operations again, compiled for AVX2 on 8-float vectors where the work is a kernel over the
 * samples or entries (the rest is the 4-float body): the same results bit for bit; the loader binds each name to
 * one of the two (GSPECTRAL_PICK, spectral_kernels.h). */
static int bi_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int bi_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int bi_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
static int bi_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
static int bi_axpy(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b);
static double bi_brightness(const GColorModel *m, const GColor *a);

#ifdef GSPECTRAL_AVX2
/* A vector's kernel with the common grids' lengths as constants (GSPECTRAL_ON_COMMON_LENGTH: 41 samples by default),
 * as the kit's operations take them; a matrix's n * n entries take the kernels' jump. */
#define BI_ON_LENGTH(n, CALL) GSPECTRAL_ON_COMMON_LENGTH(n, CALL)

static GSPECTRAL_TARGET_AVX2 int bi_add_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    int n = m->nsamples;
    if (a->kind != b->kind)
        return bi_add_v4(m, out, a, b);
    if (a->kind == GCOLOR_MATRIX) {
        gspectral_kmap8(GSPECTRAL_ADD, out->v, a->v, b->v, n * n);
    } else {
#define ADD(len) gspectral_kmap8(GSPECTRAL_ADD, out->v, a->v, b->v, len)
        BI_ON_LENGTH(n, ADD);
#undef ADD
    }
    out->kind = a->kind;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int bi_mul_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)
        return bi_mul_v4(m, out, a, b);
    out->kind = GCOLOR_VECTOR;
#define MUL(len) gspectral_kmap8(GSPECTRAL_MUL, out->v, a->v, b->v, len)
    BI_ON_LENGTH(m->nsamples, MUL);
#undef MUL
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int bi_scale_v8(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    int n = m->nsamples;
    if (a->kind == GCOLOR_MATRIX) {
        gspectral_kscale8(out->v, a->v, (float)s, n * n);
    } else {
#define SCALE(len) gspectral_kscale8(out->v, a->v, (float)s, len)
        BI_ON_LENGTH(n, SCALE);
#undef SCALE
    }
    out->kind = a->kind;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int bi_div_v8(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    if (a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)
        return bi_div_v4(m, out, a, b);
#define DIV(len) gspectral_kdiv8(out->v, a->v, b->v, len)
    BI_ON_LENGTH(m->nsamples, DIV);
#undef DIV
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int bi_axpy_v8(const GColorModel *m, GColor *out, double s, const GColor *a,
                                            const GColor *b)
{
    int n = m->nsamples;
    if (a->kind != b->kind)
        return bi_axpy_v4(m, out, s, a, b);
    if (a->kind == GCOLOR_MATRIX) {
        gspectral_kaxpyd8(out->v, s, a->v, b->v, n * n);
    } else {
#define AXPY(len) gspectral_kaxpyd8(out->v, s, a->v, b->v, len)
        BI_ON_LENGTH(n, AXPY);
#undef AXPY
    }
    out->kind = a->kind;
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 double bi_brightness_v8(const GColorModel *m, const GColor *a)
{
    const GSpectral *p = m->priv;
    if (a->kind != GCOLOR_VECTOR)
        return bi_brightness_v4(m, a);
#define BRIGHT(len) gspectral_kbright8(p->lum, a->v, len)
    return BI_ON_LENGTH(m->nsamples, BRIGHT);
#undef BRIGHT
}

GSPECTRAL_PICK(bi_add);
GSPECTRAL_PICK(bi_mul);
GSPECTRAL_PICK(bi_scale);
GSPECTRAL_PICK(bi_div);
GSPECTRAL_PICK(bi_axpy);
GSPECTRAL_PICK(bi_brightness);
#else
static int bi_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return bi_add_v4(m, out, a, b);
}

static int bi_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return bi_mul_v4(m, out, a, b);
}

static int bi_scale(const GColorModel *m, GColor *out, const GColor *a, double s) { return bi_scale_v4(m, out, a, s); }

static int bi_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return bi_div_v4(m, out, a, b);
}

static int bi_axpy(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b)
{
    return bi_axpy_v4(m, out, s, a, b);
}

static double bi_brightness(const GColorModel *m, const GColor *a) { return bi_brightness_v4(m, a); }
#endif

static int bi_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    if (a->kind == GCOLOR_VECTOR)
        return gspectral_to_nm(m, a, role, out);
    float d[BI_MAX];
    fold(a, m->nsamples, d);
    GColor v = {.model = m, .v = d, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_CALLER, .capacity = BI_MAX};
    return gspectral_to_nm(m, &v, role, out);
}


/* ---- measured matrices ---- */

/* The excitation column on emission row o's diagonal (the one at the same wavelength), or -1. Both the
 * diagonal's grid and the split below ask this one question, so they always agree on how many there are. */
static int diagonal_column(const GReradiation *r, int o)
{
    double tol = 1e-6 * fmin(r->in_step, r->out_step);
    double x = r->out_min + o * r->out_step;
    double i = floor((x - r->in_min) / r->in_step + 0.5);
    if (!(i >= 0 && i < r->n_in) || fabs(r->in_min + i * r->in_step - x) > tol) /* also NaN */
        return -1;
    return (int)i;
}

/* The wavelengths where an excitation sample meets an emission sample: a uniform grid (n = 0: none). */
static int coincident_grid(const GReradiation *r, GSpectralGrid *d, GError *err)
{
    double tol = 1e-6 * fmax(r->in_step, r->out_step);
    double first = 0.0, last = 0.0, spacing = 0.0;
    int count = 0;
    for (int p = 0; p < r->n_out; p++) {
        double x = r->out_min + p * r->out_step;
        if (diagonal_column(r, p) < 0)
            continue;
        if (count == 1)
            spacing = x - first;
        else if (count > 1 && fabs(x - last - spacing) > tol)
            return gerror_set(err, G_ERR_INVALID, "re-radiation matrix: excitation and emission grids meet at "
                                                  "irregular wavelengths, so its diagonal is undefined");
        if (!count)
            first = x;
        last = x;
        count++;
    }
    if (!count)
        return gerror_set(err, G_ERR_INVALID, "re-radiation matrix: excitation and emission grids share no "
                                              "wavelength, so it has no diagonal (plain reflectance)");
    d->min = first;
    d->step = count > 1 ? spacing : r->out_step;
    d->n = count;
    return G_OK;
}

static int bi_from_reradiation(const GColorModel *m, const GReradiation *r, GColor *out, GError *err)
{
    const GSpectral *p = m->priv;
    GSpectralGrid g = p->grid, gd;
    GSpectralGrid gin = {r->in_min, r->in_step, r->n_in}, gout = {r->out_min, r->out_step, r->n_out};
    int n = g.n;
    int rc = coincident_grid(r, &gd, err);
    if (rc != G_OK)
        return rc;
    GSpectralResample rd, rin, rout;
    memset(&rd, 0, sizeof rd);
    memset(&rin, 0, sizeof rin);
    memset(&rout, 0, sizeof rout);
    size_t nf = (size_t)r->n_out * r->n_in;
    float *f = gmem_alloc(nf * sizeof *f);
    float *gx = gmem_alloc((size_t)r->n_out * n * sizeof *gx);
    float *dv = gmem_alloc((size_t)gd.n * sizeof *dv);
    if (!f || !gx || !dv) {
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory reading a re-radiation matrix");
        goto done;
    }
    rc = gspectral_resample_build(&rd, gd, g, 1);
    if (rc == G_OK)
        rc = gspectral_resample_build(&rin, gin, g, 0);
    if (rc == G_OK)
        rc = gspectral_resample_build(&rout, gout, g, 0);
    if (rc != G_OK) {
        rc = gerror_set(err, rc, rc == G_ERR_NOMEM ? "out of memory reading a re-radiation matrix"
                                                   : "re-radiation matrix: its steps are too fine for this grid");
        goto done;
    }
    /* split: clamped diagonal reflectance, and the off-diagonal density per nm of excitation */
    int nd = 0;
    for (int o = 0; o < r->n_out; o++) {
        int diag = diagonal_column(r, o);
        for (int i = 0; i < r->n_in; i++) {
            float v = r->data[(size_t)o * r->n_in + i];
            v = v > 0.0f ? v : 0.0f;
            if (i == diag) {
                dv[nd++] = v;
                v = 0.0f;
            }
            f[(size_t)o * r->n_in + i] = (float)(v / r->in_step);
        }
    }
    for (int o = 0; o < r->n_out; o++) /* along excitation: row by row */
        gspectral_resample_apply(&rin, f + (size_t)o * r->n_in, 1, gx + (size_t)o * n, 1);
    for (int j = 0; j < n; j++) /* along emission: column by column */
        gspectral_resample_apply(&rout, gx + j, n, out->v + j, n);
    gspectral_kscale(out->v, out->v, (float)g.step, n * n);
    float d[BI_MAX];
    gspectral_resample_apply(&rd, dv, 1, d, 1);
    for (int k = 0; k < n; k++)
        out->v[k * n + k] += d[k];
    out->kind = GCOLOR_MATRIX;
done:
    gspectral_resample_free(&rd);
    gspectral_resample_free(&rin);
    gspectral_resample_free(&rout);
    gmem_free(f);
    gmem_free(gx);
    gmem_free(dv);
    return rc;
}

static const GColorModelClass gcolormodel_bispectral = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "bispectral",
    .description = "spectra and fluorescent re-radiation matrices (default 380..780 nm at 10 nm)",
    .init = bispectral_init,
    .fini = gspectral_model_fini,
    .black = gspectral_black,
    .add = bi_add,
    .mul = bi_mul,
    .scale = bi_scale,
    .div = bi_div,
    .pow = bi_pow,
    .brightness = bi_brightness,
    .to_nm = bi_to_nm,
    .from_nm = gspectral_from_nm,
    .to_xyz = gspectral_to_xyz_folded, /* a matrix: its folded reflectance, the row sums */
    .from_rgb = gspectral_from_rgb,
    .from_reradiation = bi_from_reradiation,
    .exp_scaled = bi_exp,
    .axpy = bi_axpy,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

static const GParamInfo bispectral_params[] = {
    {"step", GPARAM_NAMED, "number", "10", "[1, 100], a whole number of steps from min to max",
     "the spacing of the samples (and of the matrices' rows and columns), in nm"},
    {"min", GPARAM_NAMED, "number", "380", "[300, 830], below max",
     "the first sample, in nm; start lower (300) to keep ultraviolet excitation"},
    {"max", GPARAM_NAMED, "number", "780", "[300, 830], at most 127 steps above min", "the last sample, in nm"},
    {"uplift", GPARAM_NAMED, "choice", "sigmoid", "sigmoid, basis",
     "how RGB colours become spectra: sigmoid (smooth, a reflectance within [0, 1]) or basis (the exact linear basis)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(bispectral, GKIND_COLORMODEL, &gcolormodel_bispectral, NULL, NULL, bispectral_params);
