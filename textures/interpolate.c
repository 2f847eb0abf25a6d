/* interpolate.c - the interpolate node (two children blended by a generator) and, sharing every method,
 * the interpolate-one node (one method blended, the rest from the first child). */
#include "generic/plugin.h"
#include "node_common.h"
#include "textures_builtin.h"

typedef struct Interp {
    GMaterial base;
    GMaterial *a, *b;
    GGenerator *t;
    int only; /* -1: every method is blended; else the one GNodeMethod that is */
} Interp;

static void interp_destroy(GMaterial *self)
{
    Interp *n = (Interp *)self;
    gmaterial_unref(n->a);
    gmaterial_unref(n->b);
    ggenerator_unref(n->t);
    gmem_free(n);
}

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GTexBlend *blend)
{
    const Interp *n = (const Interp *)self;
    if (!sp || (n->only >= 0 && n->only != (int)m)) {
        blend->n = 1;
        blend->m[0] = n->a;
        blend->w[0] = 1.0;
        return;
    }
    gtexblend_pair(blend, n->a, n->b, ggenerator_cached_value(n->t, sp));
}

static int interp_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gtexblend_reflection(&b, sp, in, illum, out, result);
}

static int interp_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                             const GColor *rel_index, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION, &b);
    return gtexblend_refraction(&b, sp, in, illum, rel_index, out, result);
}

static int interp_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION_INDEX, &b);
    return gtexblend_refraction_index(&b, sp, result);
}

static int interp_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION_DIR, &b);
    return gtexblend_reflection_dir(&b, sp, view, dir);
}

static int interp_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                 GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION_DIR, &b);
    return gtexblend_refraction_dir(&b, sp, view, rel_index, dir);
}

static int interp_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_EMISSION, &b);
    return gtexblend_emission(&b, sp, out, result);
}

static int interp_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_AMBIENT, &b);
    return gtexblend_ambient(&b, sp, illum, result);
}

static int interp_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_ABSORPTION, &b);
    return gtexblend_absorption(&b, sp, illum, length, result);
}

static int interp_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *nrm)
{
    GTexBlend b;
    pick(self, sp, GNODE_NORMAL, &b);
    return gtexblend_normal(&b, sp, nrm);
}

static int interp_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_DIFFUSE, &b);
    return gtexblend_diffuse(&b, sp, result);
}

static int interp_opaque(const GMaterial *self, GSurfPoint *sp)
{
    GTexBlend b;
    pick(self, sp, GNODE_OPAQUE, &b);
    return gtexblend_opaque(&b, sp);
}

#define INTERP_METHODS                                                                                       \
    .destroy = interp_destroy, .reflection = interp_reflection, .refraction = interp_refraction,              \
    .refraction_index = interp_refraction_index, .reflection_dir = interp_reflection_dir,                     \
    .refraction_dir = interp_refraction_dir, .emission = interp_emission, .ambient = interp_ambient,          \
    .absorption = interp_absorption, .normal = interp_normal, .diffuse = interp_diffuse, .opaque = interp_opaque

const GMaterialClass gnode_interpolate_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "interpolate",
    .description = "two children blended by a generator value in [0, 1]",
    INTERP_METHODS,
};

const GMaterialClass gnode_interpolate_one_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "interpolate-one",
    .description = "one method blended by a generator, the others from the first child",
    INTERP_METHODS,
};

int gtexnode_interpolate_make(const GMaterialClass *cls, GMaterial *a, GMaterial *b, GGenerator *t, int only,
                              GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *children[2] = {a, b};
    GMaterial *node;
    int rc = gtexnode_new_checked(cls, children, 2, t, 1, sizeof(Interp), &node, err);
    if (rc != G_OK)
        return rc;
    Interp *n = (Interp *)node;
    n->a = gmaterial_ref(a);
    n->b = gmaterial_ref(b);
    n->t = ggenerator_ref(t);
    n->only = only;
    *out = &n->base;
    return G_OK;
}

int gnode_interpolate_create(GMaterial *a, GMaterial *b, GGenerator *t, GMaterial **out, GError *err)
{
    return gtexnode_interpolate_make(&gnode_interpolate_class, a, b, t, -1, out, err);
}

GENERIC_TYPE(interpolate, GKIND_NODE, &gnode_interpolate_class, gtexparse_interpolate, NULL);
GENERIC_TYPE(interpolate_one, GKIND_NODE, &gnode_interpolate_one_class, gtexparse_interpolate_one, NULL);
