/* params.c - parameter checks, construction and shading helpers shared by the built-in materials and the
 * texture nodes. */
#include "params.h"

#include <math.h>

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
        return gerror_set(err, G_ERR_INVALID, "%s: %s is missing", material, param);
    int n = value_count(src);
    for (int i = 0; i < n; i++) {
        float x = src->v[i];
        if (!isfinite(x) || x < 0.0f)
            return gerror_set(err, G_ERR_INVALID, "%s: %s has the value %g at sample %d (must be finite and >= 0)",
                              material, param, (double)x, i);
    }
    if (max > 0.0) {
        int at;
        double mx = gmatparam_max(src, &at);
        /* an in-range colour may overshoot a little after conversion (rgb 1 1 1 gives 1.00015 in the spectral
         * models: the RGB round trip correction of lib/cie.c); such values are clamped below */
        if (mx > max * (1.0 + 1e-3))
            return gerror_set(err, G_ERR_INVALID, "%s: %s has the value %g at sample %d (must be <= %g)", material,
                              param, mx, at, max);
    }
    if (gcolor_alloc(dst, m) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for %s", material, param);
    int rc = gcolor_convert(dst, src, role);
    if (rc != G_OK) {
        gcolor_free(dst);
        return gerror_set(err, rc, "%s: cannot convert %s from model '%s' to '%s'", material, param,
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

int gmat_new(const GMaterialClass *cls, const GColorModel *model, size_t size, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *m = gmem_calloc(1, size);
    if (!m)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", cls->name);
    int rc = gmaterial_init(m, cls, model, err);
    if (rc != G_OK) {
        gmem_free(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

void gmat_one_color_destroy(GMaterial *self)
{
    gcolor_free(&((GMatOneColor *)self)->c);
    gmem_free(self);
}

int gmat_one_color_create(const GMaterialClass *cls, const GColorModel *model, size_t size, const GColor *src,
                          GColorRole role, double max, const char *param, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "%s: no colour model given", cls->name);
    GMaterial *m;
    int rc = gmat_new(cls, model, size, &m, err);
    if (rc != G_OK)
        return rc;
    rc = gmatparam_color(model, src, role, max, cls->name, param, &((GMatOneColor *)m)->c, err);
    if (rc != G_OK) {
        gmat_one_color_destroy(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

double gmat_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n)
{
    *n = gsurfpoint_normal(sp);
    GVec3 ng = sp->geometric_normal;
    if (gvec3_dot(in, ng) <= 0.0 || gvec3_dot(out, ng) <= 0.0)
        return 0.0;
    double c = gvec3_dot(in, *n);
    return c > 0.0 ? c : 0.0;
}
