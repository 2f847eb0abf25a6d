/* bump.c - the bump node: Blinn's (1978) perturbation of the normal by the gradient of a height field
 * along the surface tangents; every other method is the child's:
 *
 *   node NAME bump { child MATERIAL  height GENERATOR  strength 1 }
 */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Bump {
    GNodeChild node; /* base and child; first */
    GGenerator *height;
    double strength;
} Bump;

static void bump_destroy(GMaterial *self)
{
    Bump *b = (Bump *)self;
    gmaterial_unref(b->node.child);
    ggenerator_unref(b->height);
    gmem_free(b);
}

/* Two unit tangents with t1 x t2 = m. */
static void frame(GVec3 m, GVec3 *t1, GVec3 *t2)
{
    GVec3 a = fabs(m.x) < 0.9 ? gvec3(1, 0, 0) : gvec3(0, 1, 0);
    *t1 = gvec3_normalize(gvec3_cross(a, m));
    *t2 = gvec3_cross(m, *t1);
}

static int bump_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    const Bump *b = (const Bump *)self;
    int rc = gmaterial_normal(b->node.child, sp, n);
    if (rc != G_OK || b->strength == 0.0)
        return rc;
    double hu, hv;
    rc = ggenerator_surface_derivatives(b->height, sp, &hu, &hv);
    if (rc != G_OK)
        return rc;
    double side = sp->entering ? 1.0 : -1.0;
    GVec3 m = gvec3_scale(*n, side); /* the outside's normal: bumps rise towards the outside */
    GVec3 pu = sp->dpdu, pv = sp->dpdv;
    GVec3 cross = gvec3_cross(pu, pv);
    double area = gvec3_length(cross);
    double scale = fmax(gvec3_dot(pu, pu), gvec3_dot(pv, pv));
    if (!(area > 1e-12 * scale) || !isfinite(area)) {
        frame(m, &pu, &pv);
        cross = m;
        area = 1.0;
    }
    double tau = gvec3_dot(m, cross) < 0.0 ? -1.0 : 1.0;
    GVec3 d = gvec3_add(gvec3_scale(gvec3_cross(m, pv), hu), gvec3_scale(gvec3_cross(pu, m), hv));
    GVec3 np = gvec3_madd(gvec3_scale(m, area), d, tau * b->strength);
    double len = gvec3_length(np);
    if (!(len > 0.0) || !isfinite(len))
        return G_OK; /* a degenerate perturbation keeps the child's normal */
    *n = gvec3_scale(np, side / len);
    return G_OK;
}

static const GMaterialClass bump_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "bump",
    .description = "normal perturbed by the gradient of a height field (Blinn)",
    .destroy = bump_destroy,
    .reflection = gnode_child_reflection,
    .refraction = gnode_child_refraction,
    .refraction_index = gnode_child_refraction_index,
    .reflection_dir = gnode_child_reflection_dir,
    .refraction_dir = gnode_child_refraction_dir,
    .emission = gnode_child_emission,
    .ambient = gnode_child_ambient,
    .absorption = gnode_child_absorption,
    .normal = bump_normal,
    .diffuse = gnode_child_diffuse,
    .opaque = gnode_child_opaque,
    .sample = gnode_child_sample, /* the child samples about the bumped normal, which it reads from sp */
    .pdf = gnode_child_pdf,
    .is_delta = gnode_child_is_delta,
};

int gnode_bump_create(GMaterial *child, GGenerator *height, double strength, GMaterial **out, GError *err)
{
    *out = NULL;
    const GColorModel *model;
    int rc = gnode_check("bump", &child, 1, height, 1, &model, err);
    if (rc != G_OK)
        return rc;
    if (!isfinite(strength))
        return gerror_set(err, G_ERR_INVALID, "bump: strength must be finite, got %g", strength);
    GMaterial *mat;
    rc = gnode_child_new(&bump_class, child, height, 1, sizeof(Bump), &mat, err);
    if (rc != G_OK)
        return rc;
    Bump *b = (Bump *)mat;
    b->height = ggenerator_ref(height);
    b->strength = strength;
    /* reflection and diffuse colour: the child's at sp itself, whose cached shading normal (the bumped one when the
     * bump is the point's material) the child's gmaterial_cos_in reads as the node's does */
    gnode_inherit_lambertian_child(&b->node.base, child);
    gnode_inherit_no_rel_index(&b->node.base, &child, 1); /* its normal reads the height, not the index */
    *out = &b->node.base;
    return G_OK;
}

static int parse_bump(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GGenerator *h = NULL;
    double strength = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "height") == 0)
            rc = gtexparse_generator(r, &h, err);
        else if (strcmp(key, "strength") == 0)
            rc = greader_number(r, &strength, err);
        else
            rc = greader_unknown_param(r, "child, height, strength", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child || !h)
        return greader_error(r, err, "bump: needs child and height");
    GMaterial *m = NULL;
    rc = gnode_bump_create(child, h, strength, &m, err);
    return gtexparse_finish(r, rc, m, object, err);
}

static const GParamInfo bump_params[] = {
    {"child", GPARAM_NAMED, "material", NULL, NULL, "the material seen with the bumped normal"},
    {"height", GPARAM_NAMED, "generator", NULL, NULL,
     "the height field: its gradient along the u and v tangents tilts the normal (Blinn 1978)"},
    {"strength", GPARAM_NAMED, "number", "1", "finite", "multiplies the height"},
    {NULL},
};

GENERIC_TYPE_PARAMS(bump, GKIND_NODE, &bump_class, parse_bump, NULL, bump_params);
