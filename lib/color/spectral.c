/* spectral.c - the spectral kit (include/generic/kit/spectral.h): grids, resampling, the colorimetric tables
 * and the operations of a plain sampled spectrum, for the built-in sampled models and for modules.
 *
 * Sampling (from_nm and every other change of grid onto a coarser one) is a hat-weighted average: the
 * destination sample at x takes the source samples within one destination step of x, weighted by the
 * triangle 1 - |x' - x| / step and normalised by the weight it covers. The triangles of neighbouring
 * samples add up to one everywhere, so every source sample hands out all of its energy (a 1 nm line
 * between two samples splits between them in proportion to its distance instead of being missed), and
 * a constant stays the same constant; on an equal grid the map is the identity. Going onto a finer grid
 * is plain linear interpolation, the adjoint operation, which keeps the trapezoid integral. */
#include "generic/kit/spectral.h"
#include "generic/kit/spectral_kernels.h"
#include "spectral_uplift.h"
#include "uplift.h"
#include "uplift_fit.h"
#include "uplift_memo.h"
#include "colorspace_matrix.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#define EPS 1e-9

int gspectral_grid_from_options(const char *model, const GColorModelOptions *opt, double def_step, int max_n,
                                GSpectralGrid *grid, GError *err)
{
    double step = opt && opt->step_nm != 0.0 ? opt->step_nm : def_step;
    double lo = opt && opt->min_nm != 0.0 ? opt->min_nm : GNM_MIN;
    double hi = opt && opt->max_nm != 0.0 ? opt->max_nm : GNM_MAX;
    if (!isfinite(step) || !isfinite(lo) || !isfinite(hi))
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': grid options must be finite numbers", model);
    if (!(step >= 1.0 && step <= 100.0))
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': step %g nm is outside 1..100 nm", model, step);
    if (!(lo >= 300.0 && hi <= 830.0 && lo < hi))
        return gerror_set(err, G_ERR_INVALID,
                          "colour model '%s': range %g..%g nm must lie inside 300..830 nm with min < max", model, lo,
                          hi);
    double steps = (hi - lo) / step;
    double whole = floor(steps + 0.5);
    if (fabs(steps - whole) > 1e-6 * (1.0 + steps))
        return gerror_set(err, G_ERR_INVALID,
                          "colour model '%s': range %g..%g nm is not a whole number of %g nm steps", model, lo, hi,
                          step);
    if (whole + 1.0 > max_n)
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': %.0f samples exceed the model's limit of %d", model,
                          whole + 1.0, max_n);
    grid->min = lo;
    grid->step = step;
    grid->n = (int)whole + 1;
    return G_OK;
}

int gspectral_grid_check_fixed(const char *model, const GColorModelOptions *opt, GSpectralGrid grid, GError *err)
{
    if (!(grid.n >= 1 && grid.n <= GSPECTRAL_MAX_SAMPLES && isfinite(grid.min) && isfinite(grid.step) &&
          grid.step > 0.0))
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': its fixed grid (%d samples at %g nm every %g nm) "
                          "is not a grid", model, grid.n, grid.min, grid.step);
    double max = gspectral_grid_nm(grid, grid.n - 1);
    if (opt && ((opt->step_nm != 0.0 && opt->step_nm != grid.step) ||
                (opt->min_nm != 0.0 && opt->min_nm != grid.min) || (opt->max_nm != 0.0 && opt->max_nm != max)))
        return gerror_set(err, G_ERR_INVALID,
                          "colour model '%s' has a fixed grid (%g..%g nm every %g nm); use 'spectrum' for another "
                          "grid",
                          model, grid.min, max, grid.step);
    return G_OK;
}

/* ---- resampling ---- */

/* The source samples feeding destination sample k: returns their count, sets *first, and when w is
 * not NULL stores their normalised weights. */
static int map_sample(GSpectralGrid src, GSpectralGrid dst, int interpolate, int k, int *first, float *w)
{
    double x = dst.min + k * dst.step;
    *first = 0;
    if (!interpolate && dst.step >= src.step * (1.0 - EPS)) {
        double lo = fmax(x - dst.step, dst.min), hi = fmin(x + dst.step, dst.min + (dst.n - 1) * dst.step);
        /* clamped to the source's samples as doubles: a source grid far away (a BFC grid at 1e300 nm) puts
         * these positions beyond any integer type */
        double a0 = ceil((lo - src.min) / src.step - EPS), a1 = floor((hi - src.min) / src.step + EPS);
        if (!(a1 >= 0.0 && a0 <= src.n - 1.0 && a0 <= a1)) /* no source sample in reach (or NaN) */
            return 0;
        int p0 = a0 > 0.0 ? (int)a0 : 0, p1 = a1 < src.n - 1.0 ? (int)a1 : src.n - 1;
        double raw[2048], sum = 0.0;
        int count = 0;
        for (int p = p0; p <= p1; p++) {
            double wt = 1.0 - fabs(src.min + p * src.step - x) / dst.step;
            if (wt <= EPS) {
                if (count)
                    break;
                continue;
            }
            if (!count)
                *first = p;
            if (count < 2048)
                raw[count] = wt;
            count++;
            sum += wt;
        }
        if (w)
            for (int j = 0; j < count; j++)
                w[j] = (float)(raw[j] / sum);
        return count;
    }
    double f = (x - src.min) / src.step;
    if (!(f >= -EPS && f <= src.n - 1 + EPS)) /* outside the source, or NaN */
        return 0;
    int p = (int)floor(f + EPS);
    if (p > src.n - 2)
        p = src.n - 2;
    if (p < 0)
        p = 0;
    double t = f - p;
    if (src.n == 1 || t <= EPS) {
        *first = p;
        if (w)
            w[0] = 1.0f;
        return 1;
    }
    if (t >= 1.0 - EPS) {
        *first = p + 1;
        if (w)
            w[0] = 1.0f;
        return 1;
    }
    *first = p;
    if (w) {
        w[0] = (float)(1.0 - t);
        w[1] = (float)t;
    }
    return 2;
}

int gspectral_resample_build(GSpectralResample *r, GSpectralGrid src, GSpectralGrid dst, int interpolate)
{
    memset(r, 0, sizeof *r);
    /* the hat of a coarse destination step covers at most 2 * ratio + 1 source samples */
    if (dst.step / src.step > 1000.0)
        return G_ERR_INVALID;
    r->n = dst.n;
    r->first = gmem_calloc((size_t)dst.n, sizeof(int));
    r->count = gmem_calloc((size_t)dst.n, sizeof(int));
    r->off = gmem_calloc((size_t)dst.n, sizeof(int));
    if (!r->first || !r->count || !r->off)
        goto nomem;
    size_t total = 0;
    for (int k = 0; k < dst.n; k++) {
        r->off[k] = (int)total;
        r->count[k] = map_sample(src, dst, interpolate, k, &r->first[k], NULL);
        total += (size_t)r->count[k];
    }
    r->w = gmem_calloc(total ? total : 1, sizeof(float));
    if (!r->w)
        goto nomem;
    for (int k = 0; k < dst.n; k++)
        map_sample(src, dst, interpolate, k, &r->first[k], r->w + r->off[k]);
    return G_OK;
nomem:
    gspectral_resample_free(r);
    return G_ERR_NOMEM;
}

void gspectral_resample_apply(const GSpectralResample *r, const float *src, int src_stride, float *dst,
                              int dst_stride)
{
    for (int k = 0; k < r->n; k++) {
        const float *w = r->w + r->off[k];
        const float *s = src + (ptrdiff_t)r->first[k] * src_stride;
        double acc = 0.0;
        for (int j = 0; j < r->count[k]; j++)
            acc += (double)w[j] * s[(ptrdiff_t)j * src_stride];
        dst[(ptrdiff_t)k * dst_stride] = (float)acc;
    }
}

void gspectral_resample_free(GSpectralResample *r)
{
    gmem_free(r->first);
    gmem_free(r->count);
    gmem_free(r->off);
    gmem_free(r->w);
    memset(r, 0, sizeof *r);
}

/* ---- colorimetric tables ---- */

/* The allocation of s->xyz[role] holds the 3 * n double weights, then (from an even index, so 16-byte aligned
 * in a malloc'd block) the float table of gspectral_kxyz (gspectral_xyz_table). */
static size_t xyz_table_offset(int n) { return ((size_t)3 * n + 1) / 2 * 2; }

static size_t xyz_doubles(int n) { return xyz_table_offset(n) + ((size_t)gspectral_xyz_table_floats(n) + 1) / 2; }

static float *xyz_table(const GSpectral *s, int role) { return (float *)(s->xyz[role] + xyz_table_offset(s->grid.n)); }

const float *gspectral_xyz_floats(const GSpectral *s, GColorRole role) { return xyz_table(s, role == GCOLOR_LIGHT); }

/* Brightness weights (color.h: Y of the value as a reflectance under D65): the model's own Y weights of the
 * reflectance role, which come from its to_nm, so that the brightness of a reflectance is its Y in this model, as
 * in every other. Negative weights (a spline's lobes) become 0, and a floor of 1e-6 of the peak makes a sample
 * outside the eye's range (or where ybar is negligible) still count: brightness is 0 only for black. Normalised to
 * sum 1 (the Y of the perfect white reflector: the sum moves by the floor only), so a constant c has brightness
 * c. */
static void init_lum(const GSpectral *s, float *lum)
{
    int n = s->grid.n;
    const double *yw = s->xyz[GCOLOR_REFLECTANCE] + n;
    for (int k = 0; k < n; k++)
        lum[k] = (float)yw[k];
    double peak = 0.0, sum = 0.0;
    for (int k = 0; k < n; k++)
        peak = fmax(peak, lum[k]);
    for (int k = 0; k < n; k++)
        sum += fmax(lum[k], 0.0) + 1e-6 * peak;
    for (int k = 0; k < n; k++)
        lum[k] = (float)((fmax(lum[k], 0.0) + 1e-6 * peak) / sum);
}

/* The value of an nm spectrum at x nm: linear between the 1 nm samples, 0 outside 380..780. */
static double nm_at(const GSpectrumNM *s, double x)
{
    double f = x - GNM_MIN;
    if (!(f >= -EPS && f <= GNM_COUNT - 1 + EPS))
        return 0.0;
    int i = (int)floor(f + EPS);
    if (i > GNM_COUNT - 2)
        i = GNM_COUNT - 2;
    if (i < 0)
        i = 0;
    double t = f - i;
    return (1.0 - t) * s->v[i] + t * s->v[i + 1];
}

/* Colour matching weights from the class's own to_nm (so to_xyz equals the nm path), then the RGB basis:
 * the spectral primaries (lib/color/cie.c) taken at the grid's wavelengths - they are smooth by construction, so
 * point values keep their shape where a hat average would blur it (on a 5 nm grid they are the basis
 * itself) - mixed by the inverse of their RGB in this model, which makes rgb -> model -> rgb exact. The
 * correction is tiny on fine grids (reflectances stay within [-0.0001, 1.0004] at 5 nm, [-0.003, 1.003] at
 * 10 nm); on spectrum9's 50 nm spline it is not (saturated primaries reach -0.13 and 1.13). */
static int init_colorimetry(GColorModel *m, GSpectral *s, GError *err)
{
    int n = s->grid.n;
    float *tmp = gmem_calloc((size_t)m->capacity, sizeof(float));
    if (!tmp)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating colour model '%s'", m->cls->name);
    GColor c = {.model = m, .v = tmp, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_CALLER, .capacity = m->capacity};
    GSpectrumNM spec;
    for (int k = 0; k < n; k++) {
        memset(tmp, 0, (size_t)n * sizeof *tmp);
        tmp[k] = 1.0f;
        m->cls->to_nm(m, &c, GCOLOR_LIGHT, &spec);
        for (int role = 0; role < 2; role++) {
            double xyz[3];
            gcie_nm_to_xyz(&spec, (GColorRole)role, xyz);
            for (int j = 0; j < 3; j++)
                s->xyz[role][j * n + k] = xyz[j];
        }
    }
    for (int role = 0; role < 2; role++) {
        const double *w = s->xyz[role];
        gspectral_xyz_table(xyz_table(s, role), w, w + n, w + 2 * n, n);
    }
    int rc = G_OK;
    for (int role = 0; role < 2 && rc == G_OK; role++) {
        float *basis = s->rgb[role];
        double p[3][3], pinv[3][3];
        for (int b = 0; b < 3; b++) {
            double e[3] = {b == 0, b == 1, b == 2};
            gcie_rgb_to_nm(e, (GColorRole)role, &spec);
            for (int k = 0; k < n; k++)
                basis[b * n + k] = tmp[k] = (float)nm_at(&spec, s->grid.min + k * s->grid.step);
            double xyz[3], rgb[3];
            spectral_xyz_exact(s, (GColorRole)role, tmp, xyz);
            gcie_xyz_to_rgb(xyz, rgb);
            for (int j = 0; j < 3; j++)
                p[j][b] = rgb[j];
        }
        if (gcolorspace_invert3(p, pinv) != 0) {
            rc = gerror_set(err, G_ERR_INVALID, "colour model '%s': its grid cannot represent RGB colours",
                            m->cls->name);
            break;
        }
        /* basis'_b = sum_d pinv[d][b] * basis_d, so sum_b rgb_b basis'_b = sum_d (pinv rgb)_d basis_d */
        for (int k = 0; k < n; k++) {
            double v[3] = {basis[k], basis[n + k], basis[2 * n + k]};
            for (int b = 0; b < 3; b++)
                basis[b * n + k] = (float)(pinv[0][b] * v[0] + pinv[1][b] * v[1] + pinv[2][b] * v[2]);
        }
    }
    gmem_free(tmp);
    return rc;
}

/* The sigmoid uplift's discretisation per role: normalised wavelengths, the XYZ weights of the role (a light's
 * times D65 of Y = 1, which multiplies the sigmoid), the D65 factor (1 for a reflectance). */
static void init_fit(GSpectral *s)
{
    int n = s->grid.n;
    for (int role = 0; role < 2; role++) {
        double *f = s->fit[role];
        const double *w = s->xyz[role];
        for (int k = 0; k < n; k++) {
            double nm = gspectral_grid_nm(s->grid, k);
            double light = role == GCOLOR_LIGHT ? gcie_illuminant("D65", nm) : 1.0;
            f[k] = (nm - GUPLIFT_NM0) / GUPLIFT_NM_SPAN;
            for (int c = 0; c < 3; c++)
                f[(1 + c) * n + k] = w[c * n + k] * light;
            f[4 * n + k] = light;
        }
        for (int c = 0; c < 3; c++) { /* the white of guplift_refine, summed as it would */
            f[5 * n + c] = 0.0;
            for (int k = 0; k < n; k++)
                f[5 * n + c] += f[(1 + c) * n + k];
        }
    }
}

int gspectral_set_uplift(const GColorModel *m, GSpectral *s, const GColorModelOptions *opt, GError *err)
{
    int u = opt ? opt->uplift : GCOLOR_UPLIFT_DEFAULT;
    if (u != GCOLOR_UPLIFT_DEFAULT && u != GCOLOR_UPLIFT_SIGMOID && u != GCOLOR_UPLIFT_BASIS)
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': uplift %d is not one of sigmoid (1), basis (2)",
                          m->cls->name, u);
    s->uplift = u == GCOLOR_UPLIFT_BASIS ? GCOLOR_UPLIFT_BASIS : GCOLOR_UPLIFT_SIGMOID;
    return G_OK;
}

int gspectral_init(GColorModel *m, GSpectral *s, GSpectralGrid grid, int linear_to_nm, GError *err)
{
    memset(s, 0, sizeof *s);
    s->grid = grid;
    int n = grid.n;
    m->nsamples = n;
    m->nvalues = n;
    if (m->capacity < n)
        m->capacity = n;
    m->lambda_min = grid.min;
    m->lambda_step = grid.step;
    GSpectralGrid nm = {GNM_MIN, 1.0, GNM_COUNT};
    int rc = gspectral_resample_build(&s->from_nm, nm, grid, 0);
    if (rc == G_OK && linear_to_nm)
        rc = gspectral_resample_build(&s->to_nm, grid, nm, 1);
    if (rc == G_OK) {
        s->lum = gmem_calloc((size_t)n, sizeof(float));
        for (int role = 0; role < 2; role++) {
            s->xyz[role] = gmem_calloc(xyz_doubles(n), sizeof(double));
            s->rgb[role] = gmem_calloc((size_t)n * 3, sizeof(float));
            s->fit[role] = gmem_calloc((size_t)n * 5 + 3, sizeof(double));
            if (!s->xyz[role] || !s->rgb[role] || !s->fit[role])
                rc = G_ERR_NOMEM;
        }
        if (!s->lum)
            rc = G_ERR_NOMEM;
    }
    if (rc != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating colour model '%s'", m->cls->name);
    s->uplift = GCOLOR_UPLIFT_SIGMOID;
    rc = init_colorimetry(m, s, err);
    if (rc == G_OK) {
        init_lum(s, s->lum);
        init_fit(s);
    }
    return rc;
}

void gspectral_fini(GSpectral *s)
{
    if (!s)
        return;
    guplift_memo_forget_all(); /* another model may be made at this address */
    gspectral_resample_free(&s->from_nm);
    gspectral_resample_free(&s->to_nm);
    gmem_free(s->lum);
    for (int role = 0; role < 2; role++) {
        gmem_free(s->xyz[role]);
        gmem_free(s->rgb[role]);
        gmem_free(s->fit[role]);
    }
    memset(s, 0, sizeof *s);
}

int gspectral_model_alloc(GColorModel *m, size_t size, int capacity, GError *err)
{
    m->priv = gmem_calloc(1, size);
    if (!m->priv)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating colour model '%s'", m->cls->name);
    m->capacity = capacity;
    return G_OK;
}

int gspectral_model_init(GColorModel *m, const GColorModelOptions *opt, double def_step, int max_n, int matrices,
                         GError *err)
{
    GSpectralGrid grid;
    int rc = gspectral_grid_from_options(m->cls->name, opt, def_step, max_n, &grid, err);
    if (rc == G_OK)
        rc = gspectral_model_alloc(m, sizeof(GSpectral), matrices ? grid.n * grid.n : grid.n, err);
    if (rc == G_OK)
        rc = gspectral_init(m, m->priv, grid, 1, err);
    return rc == G_OK ? gspectral_set_uplift(m, m->priv, opt, err) : rc;
}

int gspectral_model_init_fixed(GColorModel *m, const GColorModelOptions *opt, GSpectralGrid grid, GError *err)
{
    int rc = gspectral_grid_check_fixed(m->cls->name, opt, grid, err);
    if (rc == G_OK)
        rc = gspectral_model_alloc(m, sizeof(GSpectral), grid.n, err);
    if (rc == G_OK)
        rc = gspectral_init(m, m->priv, grid, 1, err);
    return rc == G_OK ? gspectral_set_uplift(m, m->priv, opt, err) : rc;
}

void gspectral_model_fini(GColorModel *m)
{
    gspectral_fini(m->priv);
    gmem_free(m->priv);
    m->priv = NULL;
}

/* ---- operations on sampled spectra ---- */

/* The operations run per ray have two bodies: _v4 on 4-float vectors, and _v8 compiled for AVX2 on 8-float
 * vectors (spectral_kernels8.h), with the same results bit for bit; GSPECTRAL_PICK (spectral_kernels.h) binds the
 * public name to one of them when the library is loaded. */

static void gspectral_black_v4(const GColorModel *m, GColor *out)
{
    out->kind = GCOLOR_VECTOR;
    memset(out->v, 0, (size_t)m->nvalues * sizeof(float));
}

static int gspectral_add_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
    gspectral_kadd(out->v, a->v, b->v, m->nvalues);
    return G_OK;
}

static int gspectral_mul_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
    gspectral_kmul(out->v, a->v, b->v, m->nvalues);
    return G_OK;
}

static int gspectral_scale_v4(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    out->kind = GCOLOR_VECTOR;
    gspectral_kscale(out->v, a->v, (float)s, m->nvalues);
    return G_OK;
}

static int gspectral_div_v4(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
    gspectral_kdiv(out->v, a->v, b->v, m->nvalues);
    return G_OK;
}

static double gspectral_brightness_v4(const GColorModel *m, const GColor *a)
{
    const GSpectral *s = m->priv;
    return gspectral_kbright(s->lum, a->v, m->nvalues);
}

static int gspectral_to_xyz_v4(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    const GSpectral *s = m->priv;
    gspectral_kxyz(xyz_table(s, role == GCOLOR_LIGHT), a->v, m->nvalues, xyz);
    return G_OK;
}

/* gspectral_to_xyz_folded of a matrix: its row sums (each in double, in order, rounded to float), converted as a
 * vector. Out of line, so that the vector path keeps no stack for them. */
__attribute__((noinline)) static int to_xyz_matrix(const GColorModel *m, const GColor *a, GColorRole role,
                                                   double xyz[3])
{
    int n = m->nvalues;
    float d[GSPECTRAL_MAX_SAMPLES];
    for (int o = 0; o < n; o++) {
        const float *row = a->v + (size_t)o * n;
        double s = 0.0;
        for (int i = 0; i < n; i++)
            s += row[i];
        d[o] = (float)s;
    }
    GColor v = {.model = m, .v = d, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_CALLER, .capacity = n};
    return gspectral_to_xyz(m, &v, role, xyz);
}

static int gspectral_to_xyz_folded_v4(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    if (a->kind == GCOLOR_MATRIX)
        return to_xyz_matrix(m, a, role, xyz);
    return gspectral_to_xyz_v4(m, a, role, xyz);
}

#ifdef GSPECTRAL_AVX2
/* The 8-float bodies take the common grids' lengths as constants (GSPECTRAL_ON_COMMON_LENGTH): any kit-based
 * model on them gets straight-line code, plug-ins included; every other length takes the kernels' jump. */
#define ON_GRID(m, CALL) GSPECTRAL_ON_COMMON_LENGTH((m)->nvalues, CALL)

/* +0.0 in every sample, as memset gives: the straight-line stores take fewer instructions than its call */
static GSPECTRAL_TARGET_AVX2 void gspectral_black_v8(const GColorModel *m, GColor *out)
{
    out->kind = GCOLOR_VECTOR;
#define BLACK(n) gspectral_kfill8(out->v, 0.0f, n)
    ON_GRID(m, BLACK);
#undef BLACK
}

static GSPECTRAL_TARGET_AVX2 int gspectral_add_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
#define ADD(n) gspectral_kmap8(GSPECTRAL_ADD, out->v, a->v, b->v, n)
    ON_GRID(m, ADD);
#undef ADD
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int gspectral_mul_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
#define MUL(n) gspectral_kmap8(GSPECTRAL_MUL, out->v, a->v, b->v, n)
    ON_GRID(m, MUL);
#undef MUL
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int gspectral_scale_v8(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    out->kind = GCOLOR_VECTOR;
#define SCALE(n) gspectral_kscale8(out->v, a->v, (float)s, n)
    ON_GRID(m, SCALE);
#undef SCALE
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int gspectral_div_v8(const GColorModel *m, GColor *out, const GColor *a,
                                                  const GColor *b)
{
    out->kind = GCOLOR_VECTOR;
#define DIV(n) gspectral_kdiv8(out->v, a->v, b->v, n)
    ON_GRID(m, DIV);
#undef DIV
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 double gspectral_brightness_v8(const GColorModel *m, const GColor *a)
{
    const GSpectral *s = m->priv;
#define BRIGHT(n) gspectral_kbright8(s->lum, a->v, n)
    return ON_GRID(m, BRIGHT);
#undef BRIGHT
}

static GSPECTRAL_TARGET_AVX2 int gspectral_to_xyz_v8(const GColorModel *m, const GColor *a, GColorRole role,
                                                     double xyz[3])
{
    const GSpectral *s = m->priv;
    const float *t = xyz_table(s, role == GCOLOR_LIGHT);
#define XYZ(n) gspectral_kxyz8(t, a->v, n, xyz)
    ON_GRID(m, XYZ);
#undef XYZ
    return G_OK;
}

static GSPECTRAL_TARGET_AVX2 int gspectral_to_xyz_folded_v8(const GColorModel *m, const GColor *a, GColorRole role,
                                                            double xyz[3])
{
    if (a->kind == GCOLOR_MATRIX)
        return to_xyz_matrix(m, a, role, xyz);
    return gspectral_to_xyz_v8(m, a, role, xyz);
}

GSPECTRAL_PICK(gspectral_black);
GSPECTRAL_PICK(gspectral_add);
GSPECTRAL_PICK(gspectral_mul);
GSPECTRAL_PICK(gspectral_scale);
GSPECTRAL_PICK(gspectral_div);
GSPECTRAL_PICK(gspectral_brightness);
GSPECTRAL_PICK(gspectral_to_xyz);
GSPECTRAL_PICK(gspectral_to_xyz_folded);
#else
void gspectral_black(const GColorModel *m, GColor *out) { gspectral_black_v4(m, out); }

int gspectral_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_add_v4(m, out, a, b);
}

int gspectral_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_mul_v4(m, out, a, b);
}

int gspectral_scale(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    return gspectral_scale_v4(m, out, a, s);
}

int gspectral_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    return gspectral_div_v4(m, out, a, b);
}

double gspectral_brightness(const GColorModel *m, const GColor *a) { return gspectral_brightness_v4(m, a); }

int gspectral_to_xyz(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    return gspectral_to_xyz_v4(m, a, role, xyz);
}

int gspectral_to_xyz_folded(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    return gspectral_to_xyz_folded_v4(m, a, role, xyz);
}
#endif

int gspectral_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    out->kind = GCOLOR_VECTOR;
    gspectral_kpow(out->v, a->v, e, m->nvalues);
    return G_OK;
}

int gspectral_band_count(const GColorModel *m) { return m->nvalues; }

int gspectral_band_mask(const GColorModel *m, int band, GColor *out)
{
    gspectral_black(m, out);
    out->v[band] = 1.0f;
    return G_OK;
}

double gspectral_band_value(const GColorModel *m, const GColor *a, int band)
{
    (void)m;
    return a->v[band];
}

int gspectral_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)role;
    const GSpectral *s = m->priv;
    gspectral_resample_apply(&s->to_nm, a->v, 1, out->v, 1);
    return G_OK;
}

int gspectral_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    (void)role;
    const GSpectral *s = m->priv;
    out->kind = GCOLOR_VECTOR;
    gspectral_resample_apply(&s->from_nm, in->v, 1, out->v, 1);
    return G_OK;
}
