/* lambert.c - the ideal diffuse reflector: f_r = rho / pi. */
#include "generic/kit/material_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>

/* The state is a GMaterialOneColor: c is rho. */

static int lambert_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                              GColor *result)
{
    const GMaterialOneColor *l = (const GMaterialOneColor *)self;
    GVec3 n;
    double c = gmaterial_cos_in(sp, in, out, &n);
    if (c <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_mul_scaled(result, &l->c, illum, c / M_PI);
}

static int lambert_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const GMaterialOneColor *)self)->c, illum);
}

static int lambert_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const GMaterialOneColor *)self)->c);
}

/* Cosine-weighted sampling: pdf cos / pi, so the weight f cos / pdf is rho exactly (a re-radiation matrix rho:
 * what it makes of white light, a vector, as the weight is defined: material.h). */
static int lambert_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                          double u2, GMaterialSample *s, GColor *weight)
{
    (void)rel_index;
    GVec3 n = gsurfpoint_normal(sp);
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    s->in = goptics_sample_cosine(n, u1, u2);
    s->pdf = gvec3_dot(s->in, n) / M_PI;
    s->flags = GSAMPLE_REFLECT;
    if (!(s->pdf > 0.0))
        return 0;
    if (gmaterial_cos_in(sp, s->in, out, &n) <= 0.0) { /* below the geometric surface (a bumped normal) */
        gcolor_black(weight);
        return 1;
    }
    const GColor *rho = &((const GMaterialOneColor *)self)->c;
    int rc = rho->kind == GCOLOR_VECTOR ? gcolor_copy(weight, rho)
                                        : gmaterial_sample_weight(self, sp, s->in, out, NULL, 0, s->pdf, weight);
    return rc ? rc : 1;
}

static double lambert_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self;
    (void)rel_index;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double c = gvec3_dot(in, gsurfpoint_normal(sp));
    return c > 0.0 ? c / M_PI : 0.0;
}

static const GMaterialClass lambert_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "lambert",
    .description = "ideal diffuse reflector (f = rho / pi)",
    .destroy = gmaterial_one_color_destroy,
    .reflection = lambert_reflection,
    .ambient = lambert_ambient,
    .diffuse = lambert_diffuse,
    .sample = lambert_sample,
    .pdf = lambert_pdf,
};

int glambert_create(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err)
{
    int rc = gmaterial_one_color_create(&lambert_class, model, sizeof(GMaterialOneColor), reflectance,
                                        GCOLOR_REFLECTANCE, 1.0, "reflectance", out, err);
    if (rc == G_OK) { /* reflection is diffuse (rho) * illum * gmaterial_cos_in / pi, as the bit says, and no method
                       * reads the (u, v) parametrisation (material.h) */
        (*out)->flags |= GMAT_LAMBERTIAN | GMAT_NO_UV | GMAT_NO_REL_INDEX; /* no method reads an index */
        if (((GMaterialOneColor *)*out)->c.kind == GCOLOR_VECTOR) /* rho * illum: sample by sample (material.h) */
            (*out)->flags |= GMAT_DIAGONAL;
    }
    return rc;
}

/* lambert { reflectance COLOR }: grey 0.8 when not given */
static int parse_lambert(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return gmaterial_param_parse_one_color(r, "reflectance", 0.8, GCOLOR_REFLECTANCE, glambert_create, object, err);
}

static const GParamInfo lambert_params[] = {
    {"reflectance", GPARAM_NAMED, "texcolor", "rgb 0.8 0.8 0.8", "[0, 1]", "the albedo rho (f = rho / pi)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(lambert, GKIND_MATERIAL, &lambert_class, parse_lambert, NULL, lambert_params);
