/* scale.c - the scale node: the child's light-carrying colour results times a generator value:
 *
 *   node NAME scale { child MATERIAL  factor GENERATOR }
 */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <string.h>

typedef struct Scale {
    GNodeChild node; /* base and child; first */
    GGenerator *factor;
} Scale;

static void scale_destroy(GMaterial *self)
{
    Scale *s = (Scale *)self;
    gmaterial_unref(s->node.child);
    ggenerator_unref(s->factor);
    gmem_free(s);
}

/* The factor at the point, 0 where the generator's value is negative (or NaN): noise and gradients go below 0, and
 * light times a negative factor is no light at all, not negative light. 0 short-cuts the child (result black). */
static double factor(const GMaterial *self, GSurfPoint *sp)
{
    double f = sp ? ggenerator_cached_value(((const Scale *)self)->factor, sp) : 1.0;
    return f > 0.0 ? f : 0.0;
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
    return finish(gmaterial_reflection(gnode_child_of(self), sp, in, illum, out, result), f, result);
}

static int scale_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                            const GColor *rel_index, GVec3 out, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_refraction(gnode_child_of(self), sp, in, illum, rel_index, out, result), f,
                  result);
}

static int scale_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_emission(gnode_child_of(self), sp, out, result), f, result);
}

static int scale_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_ambient(gnode_child_of(self), sp, illum, result), f, result);
}

static int scale_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    double f = factor(self, sp);
    if (f == 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return finish(gmaterial_diffuse(gnode_child_of(self), sp, result), f, result);
}

/* The child's direction and density; the weight times the factor, as reflection and refraction are. */
static int scale_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                        double u2, GMaterialSample *s, GColor *weight)
{
    int rc = gmaterial_sample(gnode_child_of(self), sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        return rc;
    rc = finish(G_OK, factor(self, sp), weight);
    return rc ? rc : 1;
}

static const GMaterialClass scale_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "scale",
    .description = "the child's reflected and emitted light times a generator value",
    .destroy = scale_destroy,
    .reflection = scale_reflection,
    .refraction = scale_refraction,
    .refraction_index = gnode_child_refraction_index,
    .reflection_dir = gnode_child_reflection_dir,
    .refraction_dir = gnode_child_refraction_dir,
    .emission = scale_emission,
    .ambient = scale_ambient,
    .absorption = gnode_child_absorption,
    .normal = gnode_child_normal,
    .diffuse = scale_diffuse,
    .opaque = gnode_child_opaque,
    .sample = scale_sample,
    .pdf = gnode_child_pdf,
    .is_delta = gnode_child_is_delta,
};

int gnode_scale_create(GMaterial *child, GGenerator *factor, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *mat;
    int rc = gnode_child_new(&scale_class, child, factor, 1, sizeof(Scale), &mat, err);
    if (rc != G_OK)
        return rc;
    Scale *s = (Scale *)mat;
    s->factor = ggenerator_ref(factor);
    gnode_inherit_no_emission(&s->node.base, &child, 1); /* the child's emission times the factor */
    gnode_inherit_diagonal(&s->node.base, &child, 1);    /* the child's pass-on times the factor */
    gnode_inherit_no_uv(&s->node.base, &child, 1, factor); /* reads the point only through the factor */
    gnode_inherit_no_rel_index(&s->node.base, &child, 1); /* hands rel_index to the child, reads no index */
    /* reflection and diffuse colour: the child's at the same point times the same factor (both black at 0) */
    gnode_inherit_lambertian_child(&s->node.base, child);
    *out = &s->node.base;
    return G_OK;
}

static int parse_scale(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GGenerator *g = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "factor") == 0)
            rc = gtexparse_generator(r, &g, err);
        else
            rc = greader_unknown_param(r, "child, factor", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child || !g)
        return greader_error(r, err, "scale: needs child and factor");
    GMaterial *m = NULL;
    rc = gnode_scale_create(child, g, &m, err);
    return gtexparse_finish(r, rc, m, object, err);
}

static const GParamInfo scale_params[] = {
    {"child", GPARAM_NAMED, "material", NULL, NULL, "the material whose reflected and emitted light is scaled"},
    {"factor", GPARAM_NAMED, "generator", NULL, NULL, "multiplies the child's light"},
    {NULL},
};

GENERIC_TYPE_PARAMS(scale, GKIND_NODE, &scale_class, parse_scale, NULL, scale_params);
