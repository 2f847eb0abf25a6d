/* kit.c - building material instances (generic/kit/material_kit.h): allocation, the one-colour material, the
 * incident cosine. */
#include "generic/kit/material_kit.h"

#include <math.h>

int gmaterial_new(const GMaterialClass *cls, const GColorModel *model, size_t size, GMaterial **out, GError *err)
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

void gmaterial_one_color_destroy(GMaterial *self)
{
    gcolor_free(&((GMaterialOneColor *)self)->c);
    gmem_free(self);
}

int gmaterial_one_color_create(const GMaterialClass *cls, const GColorModel *model, size_t size, const GColor *src,
                          GColorRole role, double max, const char *param, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "%s: no colour model given", cls->name);
    GMaterial *m;
    int rc = gmaterial_new(cls, model, size, &m, err);
    if (rc != G_OK)
        return rc;
    rc = gmaterial_param_color(model, src, role, max, cls->name, param, &((GMaterialOneColor *)m)->c, err);
    if (rc != G_OK) {
        gmaterial_one_color_destroy(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

int gmaterial_sides_agree(const GSurfPoint *sp, GVec3 in, GVec3 out, int transmit)
{
    double ci = gvec3_dot(in, sp->geometric_normal), co = gvec3_dot(out, sp->geometric_normal);
    return co > 0.0 && (transmit ? ci < 0.0 : ci > 0.0);
}

double gmaterial_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n)
{
    *n = gsurfpoint_normal(sp);
    if (!gmaterial_sides_agree(sp, in, out, 0))
        return 0.0;
    double c = gvec3_dot(in, *n);
    return c > 0.0 ? c : 0.0;
}

int gmaterial_sample_weight(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index,
                       int transmit, double pdf, GColor *weight)
{
    if (!(pdf > 0.0) || !isfinite(pdf)) {
        gcolor_black(weight);
        return G_OK;
    }
    GScratch *arena = sp && sp->scratch ? sp->scratch : gscratch_thread();
    if (!arena)
        return G_ERR_NOMEM;
    GScratchMark mark = gscratch_mark(arena);
    GColor white;
    int rc = gcolor_scratch(&white, weight->model, arena);
    if (rc == G_OK)
        rc = gcolor_fill(&white, 1.0);
    if (rc == G_OK)
        rc = transmit ? gmaterial_refraction(self, sp, in, &white, rel_index, out, weight)
                      : gmaterial_reflection(self, sp, in, &white, out, weight);
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / pdf);
    gscratch_release(arena, mark);
    return rc;
}

int gmaterial_pick_lobe(const double *w, int n, double *u, double *p)
{
    double total = 0.0;
    for (int i = 0; i < n; i++)
        total += w[i] > 0.0 ? w[i] : 0.0;
    double x = *u * total, acc = 0.0;
    int last = 0;
    for (int i = 0; i < n; i++) {
        if (!(w[i] > 0.0))
            continue;
        last = i;
        if (x < acc + w[i] || i == n - 1) {
            *p = w[i] / total;
            *u = fmin(fmax((x - acc) / w[i], 0.0), 0x1.fffffffffffffp-1);
            return i;
        }
        acc += w[i];
    }
    /* rounding left x past the last lobe */
    *p = total > 0.0 ? w[last] / total : 1.0;
    *u = 0x1.fffffffffffffp-1;
    return last;
}
