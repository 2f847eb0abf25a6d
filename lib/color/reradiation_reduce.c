/* reradiation_reduce.c - the non-orthogonal reduction of a re-radiation matrix onto the values of a colour model
 * (Fichet, Belcour and Barla 2024): the operator "light in -> light out" of a fluorescent surface, read through
 * the model's own conversions. Column j is the light that comes back when the model's unit light j (its to_nm in
 * the light role) falls on the matrix, converted back with the model's from_nm in the light role. Reconstruction
 * (the model's light basis) and projection (the colour matching functions behind from_nm) are different bases,
 * hence non-orthogonal; the reconstruction of rgb's white is D65, so the reduced matrix gives the bispectral
 * colour of a fluorescent surface under D65 exactly. A model whose from_nm is not linear for every light (spectrum9
 * keeps a narrow line's samples non-negative) hands its linear projection instead: a column of the operator may
 * need negative values, which the reduction itself then resolves. */
#include "generic/color.h"

#include <math.h>
#include <string.h>

enum { REDUCE_MAX = 16 }; /* the largest nvalues reduced: a matrix of 256 floats on the stack */

/* The value of s at nm (linear between whole nm), 0 outside the exchange range. */
static double nm_at(const GSpectrumNM *s, double nm)
{
    if (!(nm >= GNM_MIN - 1e-9 && nm <= GNM_MAX + 1e-9))
        return 0.0;
    double f = nm - GNM_MIN;
    int k = (int)floor(f);
    if (k >= GNM_COUNT - 1)
        return s->v[GNM_COUNT - 1];
    if (k < 0)
        return s->v[0];
    double t = f - k;
    return (1.0 - t) * s->v[k] + t * s->v[k + 1];
}

static double entry(const GReradiation *r, int o, int i)
{
    float v = r->data[(long)o * r->n_in + i];
    return v > 0.0f ? (double)v : 0.0; /* negative entries are measurement noise */
}

/* The excitation column at the emission wavelength of row o (within a millionth of a step), or -1. */
static int diagonal_column(const GReradiation *r, int o)
{
    double nm = r->out_min + o * r->out_step;
    double f = (nm - r->in_min) / r->in_step;
    long i = lround(f);
    return i >= 0 && i < r->n_in && fabs(f - (double)i) < 1e-6 ? (int)i : -1;
}

/* The largest energy r sends out per unit arriving at one excitation wavelength within the exchange range: the
 * column's sum times the emission step over the excitation step. */
static double energy(const GReradiation *r)
{
    double most = 0.0;
    for (int i = 0; i < r->n_in; i++) {
        double nm = r->in_min + i * r->in_step, sum = 0.0;
        if (nm < GNM_MIN - 1e-9 || nm > GNM_MAX + 1e-9)
            continue;
        for (int o = 0; o < r->n_out; o++)
            sum += entry(r, o, i);
        most = fmax(most, sum * r->out_step / r->in_step);
    }
    return most;
}

/* The diagonal (the plain reflectance) at every nm: linear between the emission samples that have one, held
 * beyond the first and the last; 0 when none has. */
static void diagonal_nm(const GReradiation *r, GSpectrumNM *d)
{
    double prev_nm = 0.0, prev_v = 0.0;
    int have = 0, k = 0;
    for (int o = 0; o < r->n_out; o++) {
        int i = diagonal_column(r, o);
        if (i < 0)
            continue;
        double nm = r->out_min + o * r->out_step, v = entry(r, o, i);
        for (; k < GNM_COUNT && GNM_MIN + k <= nm; k++) {
            double t = have && nm > prev_nm ? (GNM_MIN + k - prev_nm) / (nm - prev_nm) : 1.0;
            d->v[k] = (float)(have ? prev_v + fmax(0.0, t) * (v - prev_v) : v);
        }
        prev_nm = nm, prev_v = v, have = 1;
    }
    for (; k < GNM_COUNT; k++)
        d->v[k] = (float)prev_v;
}

/* out = the light r sends back from the light in (both per nm): the diagonal times the light at every nm, plus
 * the re-radiated part, sum over the excitation samples within the exchange range of entry(o, i) in(lambda_i),
 * linear between the emission samples (none further than one step beyond them). */
static void apply(const GReradiation *r, const GSpectrumNM *diag, const GSpectrumNM *in, GSpectrumNM *out)
{
    double shifted[1024];
    int n_out = r->n_out < 1024 ? r->n_out : 1024;
    for (int o = 0; o < n_out; o++) {
        int own = diagonal_column(r, o);
        double sum = 0.0;
        for (int i = 0; i < r->n_in; i++)
            if (i != own)
                sum += entry(r, o, i) * nm_at(in, r->in_min + i * r->in_step);
        shifted[o] = sum;
    }
    for (int k = 0; k < GNM_COUNT; k++) {
        double v = (double)diag->v[k] * in->v[k];
        double f = (GNM_MIN + k - r->out_min) / r->out_step;
        if (f > -1.0 && f < n_out) {
            int o = (int)floor(f);
            double t = f - o;
            if (o >= 0)
                v += (1.0 - t) * shifted[o];
            if (o + 1 < n_out && t > 0.0)
                v += t * shifted[o + 1];
        }
        out->v[k] = (float)v;
    }
}

/* A negative entry would send out negative light for light arriving in its component alone. Each is set to 0 and
 * the entries of the same row take it instead, nearest component first (the values are in wavelength order, so the
 * nearest holds the most similar light), each down to 0 at most: the row sums, the response to white (D65 in
 * rgb), are kept, and a light that is not white moves least. A row whose sum is negative (a colour outside the
 * model's gamut) becomes 0. */
static void keep_nonnegative(double *a, int n)
{
    for (int o = 0; o < n; o++) {
        double *row = a + o * n;
        for (int j = 0; j < n; j++) {
            if (!(row[j] < 0.0))
                continue;
            double owed = -row[j];
            row[j] = 0.0;
            for (int d = 1; d < n && owed > 0.0; d++)
                for (int side = -1; side <= 1 && owed > 0.0; side += 2) {
                    int k = j + side * d;
                    if (k < 0 || k >= n || !(row[k] > 0.0))
                        continue;
                    double t = fmin(owed, row[k]);
                    row[k] -= t, owed -= t;
                }
        }
    }
}

/* Energy, as material_params.h counts it for a matrix: a column sums all that leaves per unit arriving in one
 * value. The sum of components is not a spectrum's energy, and a reduction can exceed what the matrix itself sends
 * out (green light re-radiated as red counts more in rgb), so each column is held to cap, the matrix's own energy
 * (at least 1: a conserving matrix may send out all). With entries >= 0: when all entries together exceed n cap
 * they are scaled by n cap / total, which keeps the colour of the response to white and lowers its luminance;
 * then the excess of each column above cap moves, row by row, to the columns with room in the same row, which
 * keeps every row sum and so the response to white. */
static void conserve(double *a, int n, double cap)
{
    double total = 0.0;
    for (int k = 0; k < n * n; k++)
        total += a[k];
    if (total > n * cap)
        for (int k = 0; k < n * n; k++)
            a[k] *= n * cap / total;
    double col[REDUCE_MAX];
    for (int i = 0; i < n; i++) {
        col[i] = 0.0;
        for (int o = 0; o < n; o++)
            col[i] += a[o * n + i];
    }
    for (int j = 0; j < n; j++)
        for (int o = 0; o < n && col[j] > cap; o++)
            for (int k = 0; k < n && col[j] > cap; k++) {
                double t = fmin(fmin(col[j] - cap, cap - col[k]), a[o * n + j]);
                if (k == j || !(t > 0.0))
                    continue;
                a[o * n + j] -= t, a[o * n + k] += t;
                col[j] -= t, col[k] += t;
            }
}

int gcolormodel_reduce_reradiation_by(const GColorModel *m, const GReradiation *r, GColorProjectNM project, GColor *out,
                                      GError *err)
{
    int n = m->nvalues;
    if (n > REDUCE_MAX || m->capacity < n * n || !out->v || out->model != m)
        return gerror_set(err, G_ERR_UNSUPPORTED,
                          "re-radiation matrix: the colour model '%s' has no room for a matrix of its %d values",
                          gcolormodel_name(m), n);
    if (r->n_out > 1024)
        return gerror_set(err, G_ERR_INVALID, "re-radiation matrix: %d emission samples (at most 1024)", r->n_out);
    float unit_v[REDUCE_MAX * REDUCE_MAX], back_v[REDUCE_MAX * REDUCE_MAX];
    double reduced[REDUCE_MAX * REDUCE_MAX];
    GColor unit, back;
    if (gcolor_wrap(&unit, m, unit_v, (size_t)m->capacity) != G_OK ||
        gcolor_wrap(&back, m, back_v, (size_t)m->capacity) != G_OK)
        return gerror_set(err, G_ERR_UNSUPPORTED, "re-radiation matrix: no room in model '%s'", gcolormodel_name(m));
    GSpectrumNM diag, basis, sent;
    diagonal_nm(r, &diag);
    for (int j = 0; j < n; j++) {
        gcolor_black(&unit);
        unit.v[j] = 1.0f;
        int rc = gcolor_to_nm(&unit, GCOLOR_LIGHT, &basis);
        if (rc == G_OK) {
            apply(r, &diag, &basis, &sent);
            rc = project ? project(m, &sent, GCOLOR_LIGHT, &back) : gcolor_from_nm(&back, &sent, GCOLOR_LIGHT);
        }
        if (rc != G_OK || back.kind != GCOLOR_VECTOR)
            return gerror_set(err, rc != G_OK ? rc : G_ERR_UNSUPPORTED,
                              "re-radiation matrix: the colour model '%s' cannot convert its unit light %d",
                              gcolormodel_name(m), j);
        for (int o = 0; o < n; o++)
            reduced[o * n + j] = back.v[o];
    }
    keep_nonnegative(reduced, n);
    conserve(reduced, n, fmax(1.0, energy(r)));
    for (int k = 0; k < n * n; k++) {
        if (!isfinite(reduced[k]))
            return gerror_set(err, G_ERR_INVALID, "re-radiation matrix: its reduction to model '%s' is not finite",
                              gcolormodel_name(m));
        out->v[k] = (float)reduced[k];
    }
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

int gcolormodel_reduce_reradiation(const GColorModel *m, const GReradiation *r, GColor *out, GError *err)
{
    return gcolormodel_reduce_reradiation_by(m, r, NULL, out, err);
}
