/* dielectric.c - a smooth dielectric interface: dispersion formulas, unpolarised Fresnel reflection and
 * refraction, total internal reflection, Beer-Lambert absorption inside. */
#include "generic/kit/dispersion.h"
#include "generic/kit/material_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

typedef struct Dielectric {
    GMaterial base;
    GDispersion disp;
    GColor index;         /* n(lambda) in the material's model */
    GColor transmittance; /* exp(-a): what one unit of length lets through */
    GColor tint;
    int absorbs, tinted;
} Dielectric;

/* ---- the material ---- */

static void dielectric_destroy(GMaterial *self)
{
    Dielectric *d = (Dielectric *)self;
    gcolor_free(&d->index);
    gcolor_free(&d->transmittance);
    gcolor_free(&d->tint);
    gmem_free(d);
}

static double eta_of(GSurfPoint *sp, const GColor *rel_index)
{
    return rel_index ? gsurfpoint_index_of(sp, rel_index) : gsurfpoint_relative_index(sp);
}

/* Both methods pass on nothing for a pair on the wrong sides of the geometric surface (gmaterial_sides_agree): about a
 * normal a bump tilts, the mirror or refracted ray may point back across the surface (into the body, or out of it),
 * where passing it on leaked light through the surface (gtrace traced the reflected ray inside the body in the
 * outside medium). Mirror and phong do the same through gmaterial_cos_in. */
static int dielectric_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                 GColor *result)
{
    const Dielectric *d = (const Dielectric *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double cos_o = gvec3_dot(out, n);
    if (cos_o <= 0.0 || !gmaterial_sides_agree(sp, in, out, 0) || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
    double f = goptics_fresnel(cos_o, gsurfpoint_relative_index(sp));
    int rc = gcolor_scale(result, illum, f);
    if (rc == G_OK && d->tinted)
        rc = gcolor_mul(result, &d->tint, result);
    return rc;
}

static int dielectric_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                                 const GColor *rel_index, GVec3 out, GColor *result)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp);
    double cos_o = gvec3_dot(out, n);
    double eta = eta_of(sp, rel_index);
    if (cos_o <= 0.0 || !gmaterial_sides_agree(sp, in, out, 1) ||
        !goptics_is_refraction_pair(gvec3_neg(out), n, eta, in)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_scale(result, illum, 1.0 - goptics_fresnel(cos_o, eta));
}

static int dielectric_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const Dielectric *)self)->index);
}

static int dielectric_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int dielectric_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                     GVec3 *dir)
{
    (void)self;
    return goptics_refract(view, gsurfpoint_normal(sp), eta_of(sp, rel_index), dir);
}

static int dielectric_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                                 GColor *result)
{
    const Dielectric *d = (const Dielectric *)self;
    if (!(length >= 0.0))
        return G_ERR_INVALID;
    if (!d->absorbs || length == 0.0)
        return gcolor_copy(result, illum);
    if (result->v != illum->v) {
        int rc = gcolor_pow(result, &d->transmittance, length);
        return rc ? rc : gcolor_mul(result, result, illum);
    }
    /* result aliases illum: T^length needs a temporary */
    const GColorModel *m = self->model;
    if (sp && sp->scratch) {
        GColor t;
        GScratchMark mark = gscratch_mark(sp->scratch);
        int rc = gcolor_scratch(&t, m, sp->scratch);
        if (rc == G_OK)
            rc = gcolor_pow(&t, &d->transmittance, length);
        if (rc == G_OK)
            rc = gcolor_mul(result, &t, illum);
        gscratch_release(sp->scratch, mark);
        return rc;
    }
    /* no arena: a temporary on the heap (the per-ray path always passes one) */
    GColor t;
    int rc = gcolor_alloc(&t, m);
    if (rc == G_OK)
        rc = gcolor_pow(&t, &d->transmittance, length);
    if (rc == G_OK)
        rc = gcolor_mul(result, &t, illum);
    gcolor_free(&t);
    return rc;
}

static int dielectric_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self;
    (void)sp;
    return 0;
}

/* ---- sampling: the two delta lobes, reflection with probability F (the Fresnel reflectance for the relative
 * index refraction_dir uses) and refraction with 1 - F; past the critical angle reflection alone ---- */

static int dielectric_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index,
                             double u1, double u2, GMaterialSample *s, GColor *weight)
{
    (void)u2;
    GVec3 n = gsurfpoint_normal(sp), view = gvec3_neg(out), t;
    double cos_o = gvec3_dot(out, n);
    if (cos_o <= 0.0)
        return 0;
    double eta = eta_of(sp, rel_index);
    int refracts = goptics_refract(view, n, eta, &t);
    double f = refracts ? goptics_fresnel(cos_o, eta) : 1.0;
    int rc;
    if (u1 < f || !refracts) {
        s->in = gvec3_reflect(view, n);
        s->pdf = f;
        s->flags = GSAMPLE_REFLECT | GSAMPLE_DELTA;
        rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, f, weight);
    } else {
        s->in = t;
        s->pdf = 1.0 - f;
        s->flags = GSAMPLE_TRANSMIT | GSAMPLE_DELTA;
        rc = gmaterial_sample_weight(self, sp, t, out, rel_index, 1, 1.0 - f, weight);
    }
    return rc ? rc : 1;
}

static double dielectric_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)sp, (void)in, (void)out, (void)rel_index;
    return 0.0;
}

static int dielectric_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 1;
}

static const GMaterialClass dielectric_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "dielectric",
    .description = "smooth dielectric: Fresnel reflection and refraction, dispersion, Beer-Lambert absorption",
    .destroy = dielectric_destroy,
    .reflection = dielectric_reflection,
    .refraction = dielectric_refraction,
    .refraction_index = dielectric_refraction_index,
    .reflection_dir = dielectric_reflection_dir,
    .refraction_dir = dielectric_refraction_dir,
    .absorption = dielectric_absorption,
    .opaque = dielectric_opaque,
    .sample = dielectric_sample,
    .pdf = dielectric_pdf,
    .is_delta = dielectric_is_delta,
};

int gdielectric_create(const GColorModel *model, const GDielectricParams *params, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model || !params)
        return gerror_set(err, G_ERR_INVALID, "dielectric: no colour model or parameters given");
    int rc = gdispersion_check(&params->index, err);
    GMaterial *m;
    if (rc == G_OK)
        rc = gmaterial_new(&dielectric_class, model, sizeof(Dielectric), &m, err);
    if (rc != G_OK)
        return rc;
    Dielectric *d = (Dielectric *)m;
    d->disp = params->index;
    if (gcolor_alloc(&d->index, model) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "dielectric: out of memory");
    if (rc == G_OK && (rc = gdispersion_color(&d->disp, &d->index)) != G_OK)
        rc = gerror_set_param(err, rc, "index", "dielectric: cannot express the index in model '%s'",
                              gcolormodel_name(model));
    if (rc == G_OK && params->absorption) {
        rc = gmaterial_param_color(model, params->absorption, GCOLOR_REFLECTANCE, 0.0, "dielectric", "absorption",
                             &d->transmittance, err);
        if (rc == G_OK) {
            if (d->transmittance.kind != GCOLOR_VECTOR)
                rc = gerror_set_param(err, G_ERR_INVALID, "absorption",
                                      "dielectric: absorption must be a plain colour, not a matrix");
            else {
                d->absorbs = gcolor_brightness(&d->transmittance) > 0.0;
                rc = gcolor_exp(&d->transmittance, &d->transmittance, -1.0);
                if (rc != G_OK)
                    rc = gerror_set(err, rc, "dielectric: cannot take exp of the absorption in model '%s'",
                                    gcolormodel_name(model));
            }
        }
    }
    if (rc == G_OK && params->tint) {
        rc = gmaterial_param_color(model, params->tint, GCOLOR_REFLECTANCE, 1.0, "dielectric", "tint", &d->tint, err);
        d->tinted = rc == G_OK;
    }
    if (rc != G_OK) {
        dielectric_destroy(&d->base);
        return rc;
    }
    d->base.flags |= GMAT_NO_UV; /* its methods read none of the (u, v) parametrisation (material.h) */
    if (!d->tinted || d->tint.kind == GCOLOR_VECTOR) /* F * illum (* tint), (1 - F) * illum: sample by sample */
        d->base.flags |= GMAT_DIAGONAL;
    *out = &d->base;
    return G_OK;
}

/* ---- the text format ---- */

/* dielectric { index N | cauchy A B [C] | sellmeier B1 B2 B3 C1 C2 C3 | glass NAME  glass NAME  absorption COLOR
 *              tint COLOR }:
 * index 1.5, clear, untinted when not given */
static int parse_dielectric(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor absorption = {0}, tint = {0};
    GDispersion index = gdispersion_constant(1.5);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "index") == 0)
            rc = gdispersion_read(r, &index, err);
        else if (strcmp(key, "glass") == 0)
            rc = gdispersion_read_glass(r, &index, err);
        else if (strcmp(key, "absorption") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &absorption, err);
        else if (strcmp(key, "tint") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &tint, err);
        else
            rc = greader_unknown_param(r, "index, glass, absorption, tint", err);
        if (rc < 0)
            break;
    }
    GMaterial *m = NULL;
    if (rc == G_OK) {
        GDielectricParams p = {index, absorption.v ? &absorption : NULL, tint.v ? &tint : NULL};
        if ((rc = gdielectric_create(greader_colormodel(r), &p, &m, err)) == G_OK)
            *object = m;
    }
    gcolor_free(&absorption);
    gcolor_free(&tint);
    return rc;
}

static const GParamInfo dielectric_params[] = {
    {"index", GPARAM_NAMED, "formula", "1.5",
     "N in [0.01, 100]; cauchy A B [C]; sellmeier B1 B2 B3 C1 C2 C3; glass NAME",
     "the refraction index: a constant, Cauchy's or Sellmeier's formula of the wavelength in micrometres "
     "(dispersion), or a named glass (`gmat glasses` lists them)"},
    {"glass", GPARAM_NAMED, "name", "none", "a name `gmat glasses` lists",
     "the same as `index glass NAME`: BK7, BAF10, F5, F10, F11, FK51A, LASF9, SF5, SF10, SF11, fused_silica, "
     "water, diamond"},
    {"absorption", GPARAM_NAMED, "color", "none (clear)", ">= 0, not a matrix",
     "the absorption coefficient per unit length inside (Beer-Lambert: exp(-a d) of the light passes)"},
    {"tint", GPARAM_NAMED, "color", "none (untinted)", "[0, 1]", "multiplies the light the surface reflects"},
    {NULL},
};

GENERIC_TYPE_PARAMS(dielectric, GKIND_MATERIAL, &dielectric_class, parse_dielectric, NULL, dielectric_params);
