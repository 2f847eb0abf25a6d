/* kit.c - building material instances (generic/material_kit.h): allocation, the one-colour material, the
 * incident cosine. */
#include "generic/material_kit.h"

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
