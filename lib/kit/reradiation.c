/* reradiation.c - tools on re-radiation matrices (GReradiation): checks, the parametric matrix of absorption and
 * emission bands, diagonals and column sums (include/generic/fluorescent.h, fluorescent_kit.h). */
#include "generic/kit/fluorescent_kit.h"

#include <math.h>
#include <string.h>

int gfluor_matrix_check(const GReradiation *r, const char *what, GError *err)
{
    if (!r || !r->data || r->n_in <= 0 || r->n_out <= 0 || !(r->in_step > 0.0) || !(r->out_step > 0.0) ||
        !isfinite(r->in_min) || !isfinite(r->out_min) || !isfinite(r->in_step) || !isfinite(r->out_step))
        return gerror_set(err, G_ERR_INVALID, "%s: the re-radiation matrix is missing or has an invalid grid", what);
    long n = (long)r->n_in * r->n_out;
    for (long k = 0; k < n; k++)
        if (!isfinite(r->data[k]))
            return gerror_set(err, G_ERR_INVALID, "%s: the re-radiation matrix holds a non-finite value at row %ld, "
                              "column %ld", what, k / r->n_in, k % r->n_in);
    return G_OK;
}

int gfluor_column_of(const GReradiation *r, double nm)
{
    double f = (nm - r->in_min) / r->in_step;
    double k = floor(f + 0.5);
    if (!(k >= 0.0 && k < r->n_in) || fabs(f - k) > 1e-6) /* also NaN */
        return -1;
    return (int)k;
}

void gfluor_bands_default(GFluorBands *b)
{
    b->absorb_peak = 470.0;
    b->absorb_width = 115.0;
    b->absorb_shape = 8.0;
    b->absorb_max = 0.97;
    b->emit_width = 20.0;
    b->stokes_shift = 135.0;
    b->quantum_yield = 0.65;
    b->reflectance = 0.92;
}

static int check_field(double v, double lo, double hi, int open_lo, const char *name, GError *err)
{
    if (!isfinite(v) || v < lo || v > hi || (open_lo && v == lo))
        return gerror_set(err, G_ERR_INVALID, "fluorescent matrix: %s is %g (must be in %s%g, %g])", name, v,
                          open_lo ? "(" : "[", lo, hi);
    return G_OK;
}

int gfluor_bands_check(const GFluorBands *b, GError *err)
{
    if (!b)
        return gerror_set(err, G_ERR_INVALID, "fluorescent matrix: no band parameters given");
    int rc = check_field(b->absorb_peak, 100.0, 2000.0, 0, "absorb_peak", err);
    if (rc == G_OK)
        rc = check_field(b->absorb_width, 0.0, 1000.0, 1, "absorb_width", err);
    if (rc == G_OK)
        rc = check_field(b->absorb_shape, 1.0, 64.0, 0, "absorb_shape", err);
    if (rc == G_OK)
        rc = check_field(b->absorb_max, 0.0, 1.0, 0, "absorb_max", err);
    if (rc == G_OK)
        rc = check_field(b->emit_width, 0.0, 1000.0, 1, "emit_width", err);
    if (rc == G_OK)
        rc = check_field(b->stokes_shift, 0.0, 1000.0, 0, "stokes_shift", err);
    if (rc == G_OK)
        rc = check_field(b->quantum_yield, 0.0, 1.0, 0, "quantum_yield", err);
    if (rc == G_OK)
        rc = check_field(b->reflectance, 0.0, 1.0, 0, "reflectance", err);
    return rc;
}

static int check_grid(double min_nm, double step_nm, int n, GError *err)
{
    if (!isfinite(min_nm) || !isfinite(step_nm) || step_nm <= 0.0 || min_nm <= 0.0 || n < 1 || n > 4096)
        return gerror_set(err, G_ERR_INVALID,
                          "fluorescent matrix: grid %g nm + k * %g nm, %d samples (need min > 0, step > 0, "
                          "1..4096 samples)", min_nm, step_nm, n);
    return G_OK;
}

int gfluor_matrix_create(const GFluorBands *b, double min_nm, double step_nm, int n, GReradiation *out,
                         GError *err)
{
    memset(out, 0, sizeof *out);
    int rc = gfluor_bands_check(b, err);
    if (rc == G_OK)
        rc = check_grid(min_nm, step_nm, n, err);
    if (rc != G_OK)
        return rc;
    float *data = gmem_calloc((size_t)n * (size_t)n, sizeof(float));
    double *emit = gmem_calloc((size_t)n, sizeof(double));
    if (!data || !emit) {
        gmem_free(data);
        gmem_free(emit);
        return gerror_set(err, G_ERR_NOMEM, "fluorescent matrix: out of memory for %d x %d samples", n, n);
    }
    double emit_peak = b->absorb_peak + b->stokes_shift;
    for (int o = 0; o < n; o++) {
        double d = (min_nm + o * step_nm - emit_peak) / b->emit_width;
        emit[o] = exp(-0.5 * d * d);
    }
    for (int i = 0; i < n; i++) {
        double li = min_nm + i * step_nm;
        double d = fabs(li - b->absorb_peak) / b->absorb_width;
        double a = b->absorb_max * exp(-0.5 * pow(d, b->absorb_shape));
        data[(long)i * n + i] = (float)(b->reflectance * (1.0 - a));
        /* photons absorbed at li re-emitted at longer wavelengths with the emission band's shape */
        double norm = 0.0;
        for (int o = i + 1; o < n; o++)
            norm += emit[o];
        if (norm <= 1e-300 || a * b->quantum_yield <= 0.0)
            continue;
        for (int o = i + 1; o < n; o++) {
            double lo = min_nm + o * step_nm;
            data[(long)o * n + i] = (float)(a * b->quantum_yield * emit[o] / norm * (li / lo));
        }
    }
    gmem_free(emit);
    out->in_min = out->out_min = min_nm;
    out->in_step = out->out_step = step_nm;
    out->n_in = out->n_out = n;
    out->data = data;
    return G_OK;
}

int gfluor_matrix_diagonal(const GReradiation *src, GReradiation *out, GError *err)
{
    memset(out, 0, sizeof *out);
    int rc = gfluor_matrix_check(src, "diagonal", err);
    if (rc != G_OK)
        return rc;
    float *data = gmem_calloc((size_t)src->n_in * (size_t)src->n_out, sizeof(float));
    if (!data)
        return gerror_set(err, G_ERR_NOMEM, "diagonal: out of memory");
    int found = 0;
    for (int o = 0; o < src->n_out; o++) {
        int i = gfluor_column_of(src, src->out_min + o * src->out_step);
        if (i >= 0) {
            data[(long)o * src->n_in + i] = (float)gfluor_entry(src, o, i);
            found++;
        }
    }
    if (!found) {
        gmem_free(data);
        return gerror_set(err, G_ERR_INVALID, "diagonal: the excitation and emission grids share no wavelength");
    }
    *out = *src;
    out->data = data;
    return G_OK;
}

void gfluor_matrix_free(GReradiation *r)
{
    if (!r)
        return;
    gmem_free((void *)r->data);
    memset(r, 0, sizeof *r);
}

int gfluor_matrix_diagonal_nm(const GReradiation *r, GSpectrumNM *out, GError *err)
{
    int rc = gfluor_matrix_check(r, "diagonal", err);
    if (rc != G_OK)
        return rc;
    for (int k = 0; k < GNM_COUNT; k++) {
        double f = (GNM_MIN + k - r->out_min) / r->out_step;
        if (f < 0.0)
            f = 0.0;
        if (f > r->n_out - 1)
            f = r->n_out - 1;
        int o = (int)floor(f);
        if (o >= r->n_out - 1)
            o = r->n_out > 1 ? r->n_out - 2 : 0;
        double t = f - o, v = 0.0;
        for (int s = 0; s < 2 && o + s < r->n_out; s++) {
            double w = s ? t : 1.0 - t;
            int i = gfluor_column_of(r, r->out_min + (o + s) * r->out_step);
            if (w != 0.0 && i >= 0)
                v += w * gfluor_entry(r, o + s, i);
        }
        out->v[k] = (float)v;
    }
    return G_OK;
}

double gfluor_matrix_max_column_sum(const GReradiation *r, double lo_nm, double hi_nm)
{
    if (!r || !r->data)
        return 0.0;
    double best = 0.0;
    for (int i = 0; i < r->n_in; i++) {
        double nm = r->in_min + i * r->in_step;
        if (nm < lo_nm - 1e-9 || nm > hi_nm + 1e-9)
            continue;
        double s = 0.0;
        for (int o = 0; o < r->n_out; o++)
            s += gfluor_entry(r, o, i);
        s *= r->out_step / r->in_step;
        if (s > best)
            best = s;
    }
    return best;
}
