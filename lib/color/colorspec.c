/* colorspec.c - colour literals apart from any colour model (GColorSpec): made, copied, and converted into a
 * model in a role where they are used. */
#include "generic/colorspec.h"
#include "generic/memory.h"

#include <math.h>
#include <string.h>

GColorSpec *gcolorspec_create(void)
{
    GColorSpec *s = gmem_calloc(1, sizeof *s);
    if (s)
        s->scale = 1.0;
    return s;
}

/* The bytes of a spec's owned matrix, as gcolorspec_own_matrix charged them. */
static size_t matrix_bytes(const GReradiation *m)
{
    return (size_t)m->n_in * (size_t)m->n_out * sizeof(float);
}

void gcolorspec_destroy(GColorSpec *s)
{
    if (!s)
        return;
    if (s->owned_data)
        gmem_budget_release(matrix_bytes(&s->rerad));
    gmem_free(s->owned_data);
    gmem_free(s);
}

int gcolorspec_own_matrix(GColorSpec *s, const GReradiation *m, float *data, const char *what, GError *err)
{
    if (m->n_in < 1 || m->n_out < 1) {
        gmem_free(data);
        return gerror_set(err, G_ERR_INVALID, "%s: an empty re-radiation matrix", what);
    }
    int rc = gmem_budget_reserve(matrix_bytes(m), what, err);
    if (rc != G_OK) {
        gmem_free(data);
        return rc;
    }
    if (s->owned_data) {
        gmem_budget_release(matrix_bytes(&s->rerad));
        gmem_free(s->owned_data);
    }
    s->form = GCOLORSPEC_RERADIATION;
    s->rerad = *m;
    s->rerad.data = data;
    s->owned_data = data;
    return G_OK;
}

int gcolorspec_copy(const GColorSpec *src, GColorSpec **out, GError *err)
{
    *out = NULL;
    GColorSpec *s = gmem_alloc(sizeof *s);
    if (!s)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    *s = *src;
    s->owned_data = NULL;
    if (src->form == GCOLORSPEC_RERADIATION && src->rerad.data) {
        size_t n = (size_t)src->rerad.n_in * (size_t)src->rerad.n_out;
        float *data = gmem_calloc(n, sizeof(float));
        if (!data) {
            gmem_free(s);
            return gerror_set(err, G_ERR_NOMEM, "out of memory");
        }
        memcpy(data, src->rerad.data, n * sizeof(float));
        s->rerad.data = NULL;
        int rc = gcolorspec_own_matrix(s, &src->rerad, data, "a copy of a re-radiation matrix", err);
        if (rc != G_OK) {
            gmem_free(s);
            return rc;
        }
    }
    *out = s;
    return G_OK;
}

/* A line of `power` at nm: a triangle of half-width h (the model's sample step, 1 to 10 nm) on the 1 nm grid,
 * normalised so the samples sum to power: energy and centre survive any resampling to the model's grid. */
static void line_nm(double nm, double power, double h, GSpectrumNM *out)
{
    double sum = 0.0;
    for (int i = 0; i < GNM_COUNT; i++) {
        double w = 1.0 - fabs(GNM_MIN + i - nm) / h;
        out->v[i] = w > 0.0 ? (float)w : 0.0f;
        sum += out->v[i];
    }
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = sum > 0.0 ? (float)(out->v[i] * power / sum) : 0.0f;
}

int gcolorspec_to_color(const GColorSpec *s, GColorRole role, GColor *out, GError *err)
{
    if (!s || !out || !out->model || !out->v)
        return gerror_set(err, G_ERR_INVALID, "no colour to convert into");
    GSpectrumNM nm;
    int rc;
    switch (s->form) {
    case GCOLORSPEC_RGB: {
        double v[3] = {s->rgb[0] * s->scale, s->rgb[1] * s->scale, s->rgb[2] * s->scale};
        rc = gcolor_from_rgb(out, v, role);
        break;
    }
    case GCOLORSPEC_NM:
        for (int i = 0; i < GNM_COUNT; i++)
            nm.v[i] = (float)(s->nm.v[i] * s->scale);
        rc = gcolor_from_nm(out, &nm, role);
        break;
    case GCOLORSPEC_LINE: {
        const GColorModel *m = out->model;
        /* at most 10 nm wide: a model on a coarser grid (spectrum9's 50 nm) keeps the colour of what it is handed
         * (its from_nm keeps XYZ), and a triangle 50 nm wide is no longer the line's colour */
        double h = m->nsamples > 0 && m->lambda_step > 1.0 ? fmin(m->lambda_step, 10.0) : 1.0;
        line_nm(s->line_nm, s->line_power * s->scale, h, &nm);
        rc = gcolor_from_nm(out, &nm, role);
        break;
    }
    case GCOLORSPEC_RERADIATION:
        if (role == GCOLOR_LIGHT)
            return gerror_set(err, G_ERR_INVALID, "a re-radiation matrix is a reflectance and cannot be a light");
        rc = gcolor_from_reradiation(out, &s->rerad, err);
        if (rc == G_OK && s->scale != 1.0)
            rc = gcolor_scale(out, out, s->scale);
        if (rc != G_OK)
            return rc;
        break;
    default:
        return gerror_set(err, G_ERR_INVALID, "unknown colour form %d", s->form);
    }
    if (rc != G_OK)
        return gerror_set(err, rc, "the colour cannot be converted into model '%s' (%s)", gcolormodel_name(out->model),
                          gstatus_string(rc));
    if (!gcolor_is_finite(out)) { /* finite factors whose product overflows a float: nothing infinite gets out */
        gcolor_black(out);
        return gerror_set(err, G_ERR_INVALID, "the colour is too large: a value overflows in model '%s'",
                          gcolormodel_name(out->model));
    }
    return G_OK;
}
