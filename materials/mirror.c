/* mirror.c - the perfect specular reflector of the paper's example. */
#include "generic/kit/material_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"


/* The state is a GMaterialOneColor: c is the reflectance. */

static int mirror_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GVec3 n;
    if (gmaterial_cos_in(sp, in, out, &n) <= 0.0 || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_mul(result, &((const GMaterialOneColor *)self)->c, illum);
}

static int mirror_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int mirror_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const GMaterialOneColor *)self)->c, illum);
}

/* One delta lobe, chosen with probability 1: weight = the reflectance. */
static int mirror_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                         double u2, GMaterialSample *s, GColor *weight)
{
    (void)rel_index;
    (void)u1;
    (void)u2;
    GVec3 n = gsurfpoint_normal(sp);
    s->in = gvec3_reflect(gvec3_neg(out), n);
    s->pdf = 1.0;
    s->flags = GSAMPLE_REFLECT | GSAMPLE_DELTA;
    if (gmaterial_cos_in(sp, s->in, out, &n) <= 0.0) {
        gcolor_black(weight);
        return 1;
    }
    int rc = gmaterial_sample_weight(self, sp, s->in, out, NULL, 0, 1.0, weight);
    return rc ? rc : 1;
}

static double mirror_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)sp, (void)in, (void)out, (void)rel_index;
    return 0.0;
}

static int mirror_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 1;
}

static const GMaterialClass mirror_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "mirror",
    .description = "perfect specular reflector",
    .destroy = gmaterial_one_color_destroy,
    .reflection = mirror_reflection,
    .reflection_dir = mirror_reflection_dir,
    .ambient = mirror_ambient,
    .sample = mirror_sample,
    .pdf = mirror_pdf,
    .is_delta = mirror_is_delta,
};

int gmirror_create(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err)
{
    int rc = gmaterial_one_color_create(&mirror_class, model, sizeof(GMaterialOneColor), reflectance,
                                        GCOLOR_REFLECTANCE, 1.0, "reflectance", out, err);
    if (rc == G_OK) {
        (*out)->flags |= GMAT_NO_UV; /* its methods read none of the (u, v) parametrisation (material.h) */
        (*out)->flags |= GMAT_NO_REL_INDEX; /* nor the relative index: the mirror direction and rho */
        if (((GMaterialOneColor *)*out)->c.kind == GCOLOR_VECTOR) /* rho * illum: sample by sample (material.h) */
            (*out)->flags |= GMAT_DIAGONAL;
    }
    return rc;
}

/* mirror { reflectance COLOR }: grey 1.0 when not given */
static int parse_mirror(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return gmaterial_param_parse_one_color(r, "reflectance", 1.0, GCOLOR_REFLECTANCE, gmirror_create, object, err);
}

static const GParamInfo mirror_params[] = {
    {"reflectance", GPARAM_NAMED, "texcolor", "rgb 1 1 1", "[0, 1]", "the share of the light the mirror ray reflects"},
    {NULL},
};

GENERIC_TYPE_PARAMS(mirror, GKIND_MATERIAL, &mirror_class, parse_mirror, NULL, mirror_params);
