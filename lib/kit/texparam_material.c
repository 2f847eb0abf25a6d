/* texparam_material.c - a material times a textured colour (gtexparam_scaled_material, generic/kit/texparam.h):
 * how a material whose results are linear in its one colour gets that colour from a texture. */
#include "generic/kit/texparam.h"
#include "generic/kit/material_kit.h"
#include "generic/kit/node_kit.h"

#include <string.h>

typedef struct Scaled {
    GNodeTimes node; /* base, child and the factor's function; first */
    GTexColor color;
} Scaled;

static void scaled_destroy(GMaterial *self)
{
    Scaled *s = (Scaled *)self;
    gmaterial_unref(s->node.node.child);
    gtexparam_color_release(&s->color);
    gmem_free(s);
}

/* result = colour at the point * result. */
static int apply(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GNodeTemps t;
    gnode_temps_init(&t);
    GColor c;
    int rc = gnode_temps_color(&t, sp, result->model, 0, &c);
    if (rc == G_OK)
        rc = gtexparam_color_at(&((const Scaled *)self)->color, sp, &c);
    if (rc == G_OK)
        rc = gcolor_mul(result, &c, result);
    gnode_temps_release(&t);
    return rc;
}

static const GMaterialClass scaled_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "textured",
    .description = "a material whose one colour parameter is textured: its results times the colour at the point",
    .destroy = scaled_destroy,
    GNODE_TIMES_METHODS,
};

int gtexparam_scaled_material(GMaterial *child, GTexColor *p, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *mat = NULL;
    int rc = G_OK;
    if (p->kind == GTEXCOLOR_CONSTANT || (p->kind == GTEXCOLOR_MIX && (!p->a.v || !p->b.v)))
        rc = gerror_set(err, G_ERR_INVALID, "textured: a mix or an image is needed");
    if (rc == G_OK)
        rc = gnode_child_new(&scaled_class, child, NULL, 0, sizeof(Scaled), &mat, err);
    if (rc != G_OK) {
        gmaterial_unref(child);
        gtexparam_color_release(p);
        return rc;
    }
    Scaled *s = (Scaled *)mat;
    gmaterial_unref(child); /* the node's own reference was taken by gnode_child_new */
    s->color = *p;
    s->node.times = apply;
    memset(p, 0, sizeof *p);
    GMaterial *c = s->node.node.child;
    gnode_inherit_no_emission(mat, &c, 1); /* the child's emission times a finite colour */
    gnode_inherit_diagonal(mat, &c, 1);    /* the child's pass-on times a vector */
    gnode_inherit_lambertian_child(mat, c);
    gnode_inherit_no_rel_index(mat, &c, 1); /* the child's results times a colour at the point, not the index */
    if (!gtexparam_color_reads_uv(&s->color))
        gnode_inherit_no_uv(mat, &c, 1, NULL);
    *out = mat;
    return G_OK;
}

int gtexparam_one_color_material(const GColorModel *model, GTexColor *p, GTexParamCreate create, void *ctx,
                                 GMaterial **out, GError *err)
{
    *out = NULL;
    GColor ext[2];
    int n = 0;
    int rc = gtexparam_color_extremes(p, ext, &n, err);
    for (int i = 0; i < n; i++) { /* the material's own rule, at each extreme */
        GMaterial *probe = NULL;
        if (rc == G_OK)
            rc = create(model, &ext[i], ctx, &probe, err);
        gmaterial_unref(probe);
        gcolor_free(&ext[i]);
    }
    GColor unit = {0};
    GMaterial *child = NULL;
    if (rc == G_OK && gtexparam_unit_color(model, &unit) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    if (rc == G_OK)
        rc = create(model, &unit, ctx, &child, err);
    gcolor_free(&unit);
    if (rc == G_OK)
        return gtexparam_scaled_material(child, p, out, err);
    gtexparam_color_release(p);
    return rc;
}

int gtexparam_texture_material(GMaterial *m, GTexColor *p, const char *material, const char *param,
                               GMaterial **out, GError *err)
{
    *out = NULL;
    int rc = G_OK;
    if (!m || m->cls->destroy != gmaterial_one_color_destroy)
        rc = gerror_set_param(err, G_ERR_UNSUPPORTED, param,
                              "%s: %s cannot be textured (only the colour of a material built on GMaterialOneColor, "
                              "whose results are linear in it, or a parameter its type reads as a texture)",
                              material, param);
    GColor ext[2];
    int n = 0;
    if (rc == G_OK)
        rc = gtexparam_color_extremes(p, ext, &n, err);
    double max = p->role == GCOLOR_REFLECTANCE ? 1.0 : 0.0;
    for (int i = 0; i < n; i++) { /* within the unit colour the material was checked with */
        GColor checked = {0};
        if (rc == G_OK)
            rc = gmaterial_param_color(m->model, &ext[i], p->role, max, material, param, &checked, err);
        gcolor_free(&checked);
        gcolor_free(&ext[i]);
    }
    if (rc == G_OK)
        return gtexparam_scaled_material(m, p, out, err);
    gmaterial_unref(m);
    gtexparam_color_release(p);
    return rc;
}
