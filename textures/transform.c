/* transform.c - the transform node: the subtree is evaluated on a copy of the surface point whose (u, v)
 * and object-space point (with their tangents and footprints) are moved, which moves its patterns. The copy
 * caches its generator values in its own scope (gsurfpoint_cache_enter) and hands them back after each call,
 * so the subtree's generators run once per point however many methods are called through the node:
 *
 *   node NAME transform { child MATERIAL  uv { translate U V  rotate DEG  scale S [S2] ... }
 *                         xyz { translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... } }
 *
 * Transform steps apply in the order written, each moving the pattern further. */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Transform {
    GMaterial base;
    GMaterial *child;
    int has_uv, has_xyz;
    GAffine2 uv;      /* moves the pattern */
    GAffine2 uv_inv;  /* applied to the coordinates */
    double uv_area;   /* sqrt |det uv_inv|: footprint factor */
    GAffine3 xyz_inv; /* applied to the object point */
    double xyz_len;   /* cbrt |det xyz_inv| */
} Transform;

static void transform_destroy(GMaterial *self)
{
    Transform *t = (Transform *)self;
    gmaterial_unref(t->child);
    gmem_free(t);
}

static int is_zero(GVec3 a) { return a.x == 0.0 && a.y == 0.0 && a.z == 0.0; }

/* The tangents along the new (u, v) from those along the old ones (du, dv), by the (u, v) map's linear part m. */
static void uv_tangents(const double *m, GVec3 du, GVec3 dv, GVec3 *new_du, GVec3 *new_dv)
{
    *new_du = gvec3_add(gvec3_scale(du, m[0]), gvec3_scale(dv, m[3]));
    *new_dv = gvec3_add(gvec3_scale(du, m[1]), gvec3_scale(dv, m[4]));
}

/* Fills q with the moved copy of sp. Unless `for_normal`, the shading normal (and, where refraction needs
 * it and the subtree may read it, GMAT_NO_REL_INDEX unset, the relative index) is first computed on the original
 * point, so the copy carries the values of the untransformed tree instead of recomputing them from the root at moved
 * coordinates. */
static void move(const Transform *t, GSurfPoint *sp, GSurfPoint *q, int for_normal, int need_index)
{
    if (!for_normal) {
        gsurfpoint_normal(sp);
        if (need_index && (sp->from || sp->to) && !(t->base.flags & GMAT_NO_REL_INDEX))
            gsurfpoint_relative_index(sp);
    }
    *q = *sp;
    gsurfpoint_cache_enter(q, sp, t);
    /* object tangents known: the renderer's; else dpdu, dpdv stand for them (texture.h), moved below as they are */
    int have = !is_zero(sp->object_dpdu) || !is_zero(sp->object_dpdv);
    if (t->has_uv) {
        /* the tangents along the new (u, v), world and object alike: a bump's h_u, h_v (derivatives of an object-
         * space height along the object tangents) must be taken along the same directions as its dpdu, dpdv */
        const double *m = t->uv.m;
        gaffine2_apply(&t->uv_inv, sp->u, sp->v, &q->u, &q->v);
        uv_tangents(m, sp->dpdu, sp->dpdv, &q->dpdu, &q->dpdv);
        if (have)
            uv_tangents(m, sp->object_dpdu, sp->object_dpdv, &q->object_dpdu, &q->object_dpdv);
        q->uv_footprint = sp->uv_footprint * t->uv_area;
        const double *mi = t->uv_inv.m; /* the footprint's axes move with the coordinates */
        q->uv_axis1[0] = mi[0] * sp->uv_axis1[0] + mi[1] * sp->uv_axis1[1];
        q->uv_axis1[1] = mi[3] * sp->uv_axis1[0] + mi[4] * sp->uv_axis1[1];
        q->uv_axis2[0] = mi[0] * sp->uv_axis2[0] + mi[1] * sp->uv_axis2[1];
        q->uv_axis2[1] = mi[3] * sp->uv_axis2[0] + mi[4] * sp->uv_axis2[1];
    }
    if (t->has_xyz) {
        q->object_point = gaffine3_apply(&t->xyz_inv, sp->object_point);
        q->object_dpdu = gaffine3_apply_dir(&t->xyz_inv, have ? q->object_dpdu : q->dpdu);
        q->object_dpdv = gaffine3_apply_dir(&t->xyz_inv, have ? q->object_dpdv : q->dpdv);
        q->footprint = sp->footprint * t->xyz_len;
    }
}

#define CHILD(self) (((const Transform *)(self))->child)
#define T(self) ((const Transform *)(self))

static int transform_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                GColor *result)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 1);
    int rc = gmaterial_reflection(CHILD(self), &q, in, illum, out, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                                const GColor *rel_index, GVec3 out, GColor *result)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 1);
    int rc = gmaterial_refraction(CHILD(self), &q, in, illum, rel_index, out, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    if (!sp)
        return gmaterial_refraction_index(CHILD(self), NULL, result);
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_refraction_index(CHILD(self), &q, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_reflection_dir(CHILD(self), &q, view, dir);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                    GVec3 *dir)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 1);
    int rc = gmaterial_refraction_dir(CHILD(self), &q, view, rel_index, dir);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_emission(CHILD(self), &q, out, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_ambient(CHILD(self), &q, illum, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                                GColor *result)
{
    if (!sp)
        return gmaterial_absorption(CHILD(self), NULL, illum, length, result);
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_absorption(CHILD(self), &q, illum, length, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    GSurfPoint q;
    move(T(self), sp, &q, 1, 0);
    int rc = gmaterial_normal(CHILD(self), &q, n);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_diffuse(CHILD(self), &q, result);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_opaque(const GMaterial *self, GSurfPoint *sp)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_opaque(CHILD(self), &q);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static int transform_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                            double u2, GMaterialSample *s, GColor *weight)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 1);
    int rc = gmaterial_sample(CHILD(self), &q, out, rel_index, u1, u2, s, weight);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static double transform_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 1);
    double pdf = gmaterial_pdf(CHILD(self), &q, in, out, rel_index);
    gsurfpoint_cache_return(sp, &q);
    return pdf;
}

static int transform_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    GSurfPoint q;
    move(T(self), sp, &q, 0, 0);
    int rc = gmaterial_is_delta(CHILD(self), &q);
    gsurfpoint_cache_return(sp, &q);
    return rc;
}

static const GMaterialClass transform_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "transform",
    .description = "moves the (u, v) and object-space patterns of its subtree",
    .destroy = transform_destroy,
    .reflection = transform_reflection,
    .refraction = transform_refraction,
    .refraction_index = transform_refraction_index,
    .reflection_dir = transform_reflection_dir,
    .refraction_dir = transform_refraction_dir,
    .emission = transform_emission,
    .ambient = transform_ambient,
    .absorption = transform_absorption,
    .normal = transform_normal,
    .diffuse = transform_diffuse,
    .opaque = transform_opaque,
    .sample = transform_sample,
    .pdf = transform_pdf,
    .is_delta = transform_is_delta,
};

int gnode_transform_create(GMaterial *child, const GAffine2 *uv, const GAffine3 *xyz, GMaterial **out,
                           GError *err)
{
    *out = NULL;
    GMaterial *node;
    int rc = gnode_new_checked(&transform_class, &child, 1, NULL, 0, sizeof(Transform), &node, err);
    if (rc != G_OK)
        return rc;
    Transform *t = (Transform *)node;
    if (uv) {
        t->has_uv = 1;
        t->uv = *uv;
        if (gaffine2_invert(uv, &t->uv_inv, NULL) != G_OK)
            rc = gerror_set(err, G_ERR_INVALID, "transform: the (u, v) transform is singular or not finite");
        const double *m = t->uv_inv.m;
        t->uv_area = sqrt(fabs(m[0] * m[4] - m[1] * m[3]));
    }
    if (rc == G_OK && xyz) {
        t->has_xyz = 1;
        if (gaffine3_invert(xyz, &t->xyz_inv, NULL) != G_OK)
            rc = gerror_set(err, G_ERR_INVALID, "transform: the 3D transform is singular or not finite");
        const double *m = t->xyz_inv.m;
        double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                     m[2] * (m[4] * m[9] - m[5] * m[8]);
        t->xyz_len = cbrt(fabs(det));
    }
    if (rc != G_OK) {
        gmem_free(t);
        return rc;
    }
    t->child = gmaterial_ref(child);
    gnode_inherit_no_emission(&t->base, &child, 1); /* the child's emission at a moved point */
    gnode_inherit_opaque(&t->base, &child, 1);      /* the child's opacity at a moved point */
    gnode_inherit_diagonal(&t->base, &child, 1);    /* the child's pass-on at a moved point */
    gnode_inherit_no_ideal(&t->base, &child, 1);    /* the child's ideal rays at a moved point */
    /* the child's results at a moved point; move() takes the point's index only for a child that may read it */
    gnode_inherit_no_rel_index(&t->base, &child, 1);
    gnode_inherit_constant_index(&t->base, child); /* the child's index at a moved point, or for sp NULL */
    gnode_inherit_clear(&t->base, &child, 1); /* the child's absorption at a moved point, or for sp NULL */
    /* the child's normal at a moved point that keeps the geometric normal (move() leaves it) */
    gnode_inherit_geometric_normal(&t->base, &child, 1);
    /* reflection and diffuse colour: the child's at the moved copy, which carries sp's shading normal (move()
     * computes it on sp first) and geometric normal, so the child's gmaterial_cos_in is the node's */
    gnode_inherit_lambertian_child(&t->base, child);
    /* it moves (u, v) and the tangents for a child that, with the bit, never reads them */
    gnode_inherit_no_uv(&t->base, &child, 1, NULL);
    *out = &t->base;
    return G_OK;
}

static int parse_transform(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GAffine2 uv;
    GAffine3 xyz;
    int have_uv = 0, have_xyz = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "uv") == 0) {
            rc = gtexparse_uv_steps(r, &uv, err);
            have_uv = 1;
        } else if (strcmp(key, "xyz") == 0) {
            rc = gtexparse_xyz_steps(r, &xyz, err);
            have_xyz = 1;
        } else
            rc = greader_unknown_param(r, "child, uv, xyz", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child)
        return greader_error(r, err, "transform: needs child");
    GMaterial *m = NULL;
    rc = gnode_transform_create(child, have_uv ? &uv : NULL, have_xyz ? &xyz : NULL, &m, err);
    return gtexparse_finish(r, rc, m, object, err);
}

static const GParamInfo transform_params[] = {
    {"child", GPARAM_NAMED, "material", NULL, NULL, "the subtree whose patterns are moved"},
    {"uv", GPARAM_NAMED, "block", "none", "{ translate U V  rotate DEG  scale S [S2] ... }",
     "moves the patterns in (u, v), the steps in the order written"},
    {"xyz", GPARAM_NAMED, "block", "none", "{ translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... }",
     "moves the patterns in object space, the steps in the order written"},
    {NULL},
};

GENERIC_TYPE_PARAMS(transform, GKIND_NODE, &transform_class, parse_transform, NULL, transform_params);
