/* material_params.c - material parameters (generic/material_params.h): checking and converting parameter colours,
 * defaults for parameters a file leaves out. */
#include "generic/material_params.h"

#include <math.h>
#include <string.h>

static int value_count(const GColor *c)
{
    return c->kind == GCOLOR_MATRIX ? c->model->capacity : c->model->nvalues;
}

double gmatparam_max(const GColor *c, int *at)
{
    if (at)
        *at = 0;
    if (c->kind == GCOLOR_MATRIX)
        return gcolor_brightness(c);
    double mx = -INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        if (c->v[i] > mx) {
            mx = c->v[i];
            if (at)
                *at = i;
        }
    return mx;
}

int gmatparam_color(const GColorModel *m, const GColor *src, GColorRole role, double max, const char *material,
                    const char *param, GColor *dst, GError *err)
{
    *dst = (GColor){.model = NULL, .v = NULL, .storage = GCOLOR_STORAGE_NONE};
    if (!src || !src->model || !src->v)
        return gerror_set_param(err, G_ERR_INVALID, param, "%s: %s is missing", material, param);
    int n = value_count(src);
    for (int i = 0; i < n; i++) {
        float x = src->v[i];
        if (!isfinite(x) || x < 0.0f)
            return gerror_set_param(err, G_ERR_INVALID, param,
                                    "%s: %s has the value %g at sample %d (must be finite and >= 0)", material, param,
                                    (double)x, i);
    }
    if (max > 0.0) {
        int at;
        double mx = gmatparam_max(src, &at);
        /* an in-range colour may overshoot a little after conversion (rgb 1 1 1 gives 1.00015 in the spectral
         * models: the RGB round trip correction of lib/cie.c); such values are clamped below */
        if (mx > max * (1.0 + 1e-3))
            return gerror_set_param(err, G_ERR_INVALID, param, "%s: %s has the value %g at sample %d (must be <= %g)",
                                    material, param, mx, at, max);
    }
    if (gcolor_alloc(dst, m) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for %s", material, param);
    int rc = gcolor_convert(dst, src, role);
    if (rc != G_OK) {
        gcolor_free(dst);
        return gerror_set_param(err, rc, param, "%s: cannot convert %s from model '%s' to '%s'", material, param,
                                gcolormodel_name(src->model), gcolormodel_name(m));
    }
    if (dst->kind == GCOLOR_VECTOR)
        for (int i = 0; i < m->nvalues; i++) {
            if (!(dst->v[i] >= 0.0f))
                dst->v[i] = 0.0f;
            if (max > 0.0 && dst->v[i] > max)
                dst->v[i] = (float)max;
        }
    return G_OK;
}

int gmatparam_default(GReader *r, double grey, GColorRole role, GColor *c, GError *err)
{
    if (c->v)
        return G_OK;
    const GColorModel *m = greader_colormodel(r);
    double rgb[3] = {grey, grey, grey};
    if (!m || gcolor_alloc(c, m) != G_OK)
        return greader_error(r, err, "out of memory");
    return gcolor_from_rgb(c, rgb, role) == G_OK ? G_OK : greader_error(r, err, "invalid default colour");
}

int gmatparam_parse_one_color(GReader *r, const char *key, double grey, GColorRole role, GMatOneColorCreate create,
                              void **object, GError *err)
{
    GColor c = {0};
    const char *k;
    int rc;
    while ((rc = greader_param(r, &k, err)) > 0) {
        if (strcmp(k, key) == 0)
            rc = greader_color(r, role, &c, err);
        else
            rc = greader_unknown_param(r, key, err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK)
        rc = gmatparam_default(r, grey, role, &c, err);
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = create(greader_colormodel(r), &c, &m, err)) == G_OK)
        *object = m;
    gcolor_free(&c);
    return rc;
}
