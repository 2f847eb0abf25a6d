/* scale.c - the scale node: the child's light-carrying colour results times a generator value. */
#include "node_common.h"
#include "textures_builtin.h"

typedef struct Scale {
    GMaterial base;
    GMaterial *child;
    GGenerator *factor;
} Scale;

static void scale_destroy(GMaterial *self)
{
    Scale *s = (Scale *)self;
    gmaterial_unref(s->child);
    ggenerator_unref(s->factor);
    gmem_free(s);
}

/* The factor at the point; 0 short-cuts the child (result black). */
static double factor(const GMaterial *self, GSurfPoint *sp)
{
    return sp ? ggenerator_cached_value(((const Scale *)self)->factor, sp) : 1.0;
}

static int finish(int rc, double f, GColor *result)
{
    return rc != G_OK || f == 1.0 ? rc : gcolor_scale(result, result, f);
}

static int scale_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_reflection(((const Scale *)self)->child, sp, in, illum, out, result), f, result);
}

static int scale_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                            const GColor *rel_index, GVec3 out, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_refraction(((const Scale *)self)->child, sp, in, illum, rel_index, out, result), f,
                  result);
}

static int scale_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_emission(((const Scale *)self)->child, sp, out, result), f, result);
}

static int scale_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_ambient(((const Scale *)self)->child, sp, illum, result), f, result);
}

static int scale_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_diffuse(((const Scale *)self)->child, sp, result), f, result);
}

static int scale_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(((const Scale *)self)->child, sp, result);
}

static int scale_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    return gmaterial_reflection_dir(((const Scale *)self)->child, sp, view, dir);
}

static int scale_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                GVec3 *dir)
{
    return gmaterial_refraction_dir(((const Scale *)self)->child, sp, view, rel_index, dir);
}

static int scale_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                            GColor *result)
{
    return gmaterial_absorption(((const Scale *)self)->child, sp, illum, length, result);
}

static int scale_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    return gmaterial_normal(((const Scale *)self)->child, sp, n);
}

static int scale_opaque(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_opaque(((const Scale *)self)->child, sp);
}

const GMaterialClass gnode_scale_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "scale",
    .description = "the child's reflected and emitted light times a generator value",
    .destroy = scale_destroy,
    .reflection = scale_reflection,
    .refraction = scale_refraction,
    .refraction_index = scale_refraction_index,
    .reflection_dir = scale_reflection_dir,
    .refraction_dir = scale_refraction_dir,
    .emission = scale_emission,
    .ambient = scale_ambient,
    .absorption = scale_absorption,
    .normal = scale_normal,
    .diffuse = scale_diffuse,
    .opaque = scale_opaque,
};

int gnode_scale_create(GMaterial *child, GGenerator *factor, GMaterial **out, GError *err)
{
    *out = NULL;
    const GColorModel *model;
    int rc = gtexnode_check("scale", &child, 1, factor, 1, &model, err);
    if (rc != G_OK)
        return rc;
    Scale *s = gmem_calloc(1, sizeof *s);
    if (!s)
        return gerror_set(err, G_ERR_NOMEM, "scale: out of memory");
    rc = gmaterial_init(&s->base, &gnode_scale_class, model, err);
    if (rc != G_OK) {
        gmem_free(s);
        return rc;
    }
    s->child = gmaterial_ref(child);
    s->factor = ggenerator_ref(factor);
    *out = &s->base;
    return G_OK;
}
