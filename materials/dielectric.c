/* dielectric.c - a smooth dielectric interface: dispersion formulas, unpolarised Fresnel reflection and
 * refraction, total internal reflection, Beer-Lambert absorption inside. */
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

/* ---- dispersion formulas ---- */

GDispersion gdispersion_constant(double n)
{
    GDispersion d = {GDISPERSION_CONSTANT, {n, 0, 0, 0, 0, 0}};
    return d;
}

GDispersion gdispersion_cauchy(double a, double b, double c)
{
    GDispersion d = {GDISPERSION_CAUCHY, {a, b, c, 0, 0, 0}};
    return d;
}

GDispersion gdispersion_sellmeier(const double b[3], const double c[3])
{
    GDispersion d = {GDISPERSION_SELLMEIER, {b[0], b[1], b[2], c[0], c[1], c[2]}};
    return d;
}

double gdispersion_index(const GDispersion *d, double nm)
{
    double l = nm * 1e-3, l2 = l * l;
    switch (d->kind) {
    case GDISPERSION_CONSTANT:
        return d->c[0];
    case GDISPERSION_CAUCHY:
        return d->c[0] + d->c[1] / l2 + d->c[2] / (l2 * l2);
    case GDISPERSION_SELLMEIER: {
        double n2 = 1.0;
        for (int i = 0; i < 3; i++)
            n2 += d->c[i] * l2 / (l2 - d->c[3 + i]);
        return n2 > 0.0 ? sqrt(n2) : NAN;
    }
    }
    return NAN;
}

int gdispersion_check(const GDispersion *d, GError *err)
{
    static const char *const names[3][6] = {
        {"n", "", "", "", "", ""},
        {"A", "B", "C", "", "", ""},
        {"B1", "B2", "B3", "C1", "C2", "C3"},
    };
    static const int counts[3] = {1, 3, 6};
    static const char *const kinds[3] = {"constant", "Cauchy", "Sellmeier"};
    if (!d || (unsigned)d->kind > GDISPERSION_SELLMEIER)
        return gerror_set(err, G_ERR_INVALID, "dielectric: unknown dispersion formula %d", d ? (int)d->kind : -1);
    for (int i = 0; i < counts[d->kind]; i++)
        if (!isfinite(d->c[i]))
            return gerror_set(err, G_ERR_INVALID, "dielectric: %s coefficient %s is %g (must be finite)",
                              kinds[d->kind], names[d->kind][i], d->c[i]);
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm++) {
        double n = gdispersion_index(d, nm);
        if (!isfinite(n) || n <= 0.0)
            return gerror_set(err, G_ERR_INVALID,
                              "dielectric: the %s formula gives the index %g at %d nm (must be finite and > 0)",
                              kinds[d->kind], n, nm);
    }
    return G_OK;
}

/* The index as a colour: the nm spectrum for spectral models, n at 610/550/465 nm for the others. */
static int index_color(const GDispersion *d, GColor *out)
{
    if (out->model->nsamples > 0) {
        GSpectrumNM s;
        for (int i = 0; i < GNM_COUNT; i++)
            s.v[i] = (float)gdispersion_index(d, GNM_MIN + i);
        return gcolor_from_nm(out, &s, GCOLOR_REFLECTANCE);
    }
    double rgb[3] = {gdispersion_index(d, 610.0), gdispersion_index(d, 550.0), gdispersion_index(d, 465.0)};
    return gcolor_from_rgb(out, rgb, GCOLOR_REFLECTANCE);
}

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
    if (rc == G_OK && (rc = index_color(&d->disp, &d->index)) != G_OK)
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

/* index N | index cauchy A B [C] | index sellmeier B1 B2 B3 C1 C2 C3 */
static int read_index(GReader *r, GDispersion *d, GError *err)
{
    int rc = greader_at_number(r, err); /* a number or a constant */
    if (rc < 0)
        return rc;
    if (rc == 1) {
        double n;
        rc = greader_number_in(r, 0.01, 100.0, &n, err);
        if (rc == G_OK)
            *d = gdispersion_constant(n);
        return rc;
    }
    static const char *const forms[] = {"cauchy", "sellmeier", NULL};
    int which = 0;
    if ((rc = greader_choice(r, forms, &which, err)) != G_OK)
        return rc;
    double c[6] = {0, 0, 0, 0, 0, 0};
    int n = which == 0 ? 2 : 6;
    for (int i = 0; i < n && rc == G_OK; i++)
        rc = greader_number(r, &c[i], err);
    if (rc == G_OK && which == 0 && (rc = greader_at_number(r, err)) == 1)
        rc = greader_number(r, &c[2], err);
    if (rc != G_OK)
        return rc;
    *d = which == 0 ? gdispersion_cauchy(c[0], c[1], c[2]) : gdispersion_sellmeier(c, c + 3);
    GError check; /* a bad formula is reported at its last coefficient */
    if (gdispersion_check(d, &check) != G_OK)
        return greader_error(r, err, "%s", check.message);
    return G_OK;
}

/* dielectric { index N | cauchy A B [C] | sellmeier B1 B2 B3 C1 C2 C3  absorption COLOR  tint COLOR }:
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
            rc = read_index(r, &index, err);
        else if (strcmp(key, "absorption") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &absorption, err);
        else if (strcmp(key, "tint") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &tint, err);
        else
            rc = greader_unknown_param(r, "index, absorption, tint", err);
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
     "N in [0.01, 100]; cauchy A B [C]; sellmeier B1 B2 B3 C1 C2 C3",
     "the refraction index: a constant, or Cauchy's or Sellmeier's formula of the wavelength in micrometres "
     "(dispersion)"},
    {"absorption", GPARAM_NAMED, "color", "none (clear)", ">= 0, not a matrix",
     "the absorption coefficient per unit length inside (Beer-Lambert: exp(-a d) of the light passes)"},
    {"tint", GPARAM_NAMED, "color", "none (untinted)", "[0, 1]", "multiplies the light the surface reflects"},
    {NULL},
};

GENERIC_TYPE_PARAMS(dielectric, GKIND_MATERIAL, &dielectric_class, parse_dielectric, NULL, dielectric_params);
