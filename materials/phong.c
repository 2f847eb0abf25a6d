/* phong.c - energy-normalised Phong: f_r = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha), with an optional
 * ideal reflection ray of reflectance `mirror`. */
#include "generic/kit/material_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

typedef struct Phong {
    GMaterial base;
    GColor kd, ks, mirror;
    GColor albedo; /* kd + ks + mirror, for ambient() */
    double n;
    double lobe_norm; /* (n + 2) / (2 pi) */
    int has_ks, has_mirror;
} Phong;

static void phong_destroy(GMaterial *self)
{
    Phong *p = (Phong *)self;
    gcolor_free(&p->kd);
    gcolor_free(&p->ks);
    gcolor_free(&p->mirror);
    gcolor_free(&p->albedo);
    gmem_free(p);
}

static int phong_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    const Phong *p = (const Phong *)self;
    GVec3 n;
    double cos_in = gmaterial_cos_in(sp, in, out, &n);
    if (cos_in <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    if (p->has_mirror && gmaterial_is_mirror_pair(in, n, out))
        return gcolor_mul(result, &p->mirror, illum);
    double cos_alpha = 2.0 * cos_in * gvec3_dot(n, out) - gvec3_dot(in, out);
    double lobe = 0.0;
    if (p->has_ks && cos_alpha > 0.0)
        lobe = p->lobe_norm * pow(cos_alpha > 1.0 ? 1.0 : cos_alpha, p->n);
    if (lobe <= 0.0) {
        int rc = gcolor_mul(result, &p->kd, illum);
        return rc ? rc : gcolor_scale(result, result, cos_in / M_PI);
    }
    /* f_r as a reflectance on the arena, then applied to illum */
    if (!sp->scratch)
        return G_ERR_INVALID;
    GScratchMark mark = gscratch_mark(sp->scratch);
    GColor f;
    int rc = gcolor_scratch(&f, self->model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_scale(&f, &p->kd, 1.0 / M_PI);
    if (rc == G_OK)
        rc = gcolor_add_scaled(&f, &p->ks, lobe);
    if (rc == G_OK)
        rc = gcolor_mul(result, &f, illum);
    if (rc == G_OK)
        rc = gcolor_scale(result, result, cos_in);
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int phong_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    if (!((const Phong *)self)->has_mirror)
        return 0;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int phong_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const Phong *)self)->albedo, illum);
}

static int phong_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const Phong *)self)->kd);
}

/* ---- sampling: three lobes chosen by the brightness of kd, ks and mirror ---- */

/* The lobes' selection weights and the mirror direction of out. */
static void phong_lobes(const Phong *p, GSurfPoint *sp, GVec3 out, double w[3], GVec3 *r)
{
    GVec3 n = gsurfpoint_normal(sp);
    *r = gvec3_reflect(gvec3_neg(out), n);
    w[0] = gcolor_brightness(&p->kd);
    w[1] = p->has_ks ? gcolor_brightness(&p->ks) : 0.0;
    w[2] = p->has_mirror ? gcolor_brightness(&p->mirror) : 0.0;
    if (!(w[0] + w[1] + w[2] > 0.0))
        w[0] = 1.0; /* black: a cosine lobe that reflects nothing */
}

/* The density of the non-delta lobes (the diffuse cosine and the specular cos^n about r). */
static double phong_lobes_pdf(const Phong *p, GVec3 n, GVec3 r, const double w[3], GVec3 in)
{
    double total = w[0] + w[1] + w[2], c = gvec3_dot(in, n), pdf = 0.0;
    if (w[0] > 0.0 && c > 0.0)
        pdf += w[0] / total * c / M_PI;
    if (w[1] > 0.0)
        pdf += w[1] / total * goptics_lobe_pdf(r, p->n, in);
    return pdf;
}

static int phong_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                        double u2, GMaterialSample *s, GColor *weight)
{
    (void)rel_index;
    const Phong *p = (const Phong *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    double w[3], prob;
    GVec3 r, n = gsurfpoint_normal(sp);
    phong_lobes(p, sp, out, w, &r);
    int lobe = gmaterial_pick_lobe(w, 3, &u1, &prob);
    s->flags = GSAMPLE_REFLECT;
    if (lobe == 2) { /* the ideal mirror ray: mirror / its probability */
        s->in = r;
        s->pdf = prob;
        s->flags |= GSAMPLE_DELTA;
        if (gmaterial_cos_in(sp, r, out, &n) <= 0.0) {
            gcolor_black(weight);
            return 1;
        }
        int rc = p->mirror.kind == GCOLOR_VECTOR ? gcolor_scale(weight, &p->mirror, 1.0 / prob)
                                                 : gmaterial_sample_weight(self, sp, r, out, NULL, 0, prob, weight);
        return rc ? rc : 1;
    }
    s->in = lobe == 0 ? goptics_sample_cosine(n, u1, u2) : goptics_sample_lobe(r, p->n, u1, u2);
    s->pdf = phong_lobes_pdf(p, n, r, w, s->in);
    if (!(s->pdf > 0.0))
        return 0;
    /* the value f cos without the ideal part (which only the delta lobe carries) */
    double ci = gmaterial_cos_in(sp, s->in, out, &n);
    if (ci <= 0.0) {
        gcolor_black(weight);
        return 1;
    }
    if (p->kd.kind != GCOLOR_VECTOR || p->ks.kind != GCOLOR_VECTOR) { /* re-radiation: what it makes of white */
        int rc = gmaterial_sample_weight(self, sp, s->in, out, NULL, 0, s->pdf, weight);
        return rc ? rc : 1;
    }
    int rc = gcolor_scale(weight, &p->kd, ci / M_PI / s->pdf);
    if (rc == G_OK && p->has_ks) {
        double ca = gvec3_dot(r, s->in);
        if (ca > 0.0)
            rc = gcolor_add_scaled(weight, &p->ks, p->lobe_norm * pow(ca > 1.0 ? 1.0 : ca, p->n) * ci / s->pdf);
    }
    return rc ? rc : 1;
}

static double phong_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Phong *p = (const Phong *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double w[3];
    GVec3 r;
    phong_lobes(p, sp, out, w, &r);
    return phong_lobes_pdf(p, gsurfpoint_normal(sp), r, w, in);
}

static const GMaterialClass phong_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "phong",
    .description = "energy-normalised Phong (kd, ks, exponent) with an optional mirror ray",
    .destroy = phong_destroy,
    .reflection = phong_reflection,
    .reflection_dir = phong_reflection_dir,
    .ambient = phong_ambient,
    .diffuse = phong_diffuse,
    .sample = phong_sample,
    .pdf = phong_pdf,
};

/* A parameter colour, or black when it is not given. */
static int param_or_black(const GColorModel *m, const GColor *src, const char *name, GColor *dst, GError *err)
{
    if (src)
        return gmaterial_param_color(m, src, GCOLOR_REFLECTANCE, 1.0, "phong", name, dst, err);
    if (gcolor_alloc(dst, m) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "phong: out of memory for %s", name);
    return G_OK;
}

int gphong_create(const GColorModel *model, const GPhongParams *params, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model || !params)
        return gerror_set(err, G_ERR_INVALID, "phong: no colour model or parameters given");
    if (!isfinite(params->exponent) || params->exponent < 0.0)
        return gerror_set_param(err, G_ERR_INVALID, "exponent", "phong: exponent is %g (must be finite and >= 0)",
                                params->exponent);
    GMaterial *m;
    int rc = gmaterial_new(&phong_class, model, sizeof(Phong), &m, err);
    if (rc != G_OK)
        return rc;
    Phong *p = (Phong *)m;
    rc = param_or_black(model, params->kd, "diffuse", &p->kd, err); /* the text format's names */
    if (rc == G_OK)
        rc = param_or_black(model, params->ks, "specular", &p->ks, err);
    if (rc == G_OK)
        rc = param_or_black(model, params->mirror, "mirror", &p->mirror, err);
    if (rc == G_OK && gcolor_alloc(&p->albedo, model) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "phong: out of memory");
    if (rc == G_OK) {
        rc = gcolor_add(&p->albedo, &p->kd, &p->ks);
        if (rc == G_OK)
            rc = gcolor_add(&p->albedo, &p->albedo, &p->mirror);
        if (rc != G_OK)
            rc = gerror_set(err, rc, "phong: cannot add kd, ks and mirror (%s)", gstatus_string(rc));
    }
    if (rc == G_OK) { /* a matrix sum is named by the parameter that re-radiates */
        const char *matrix = p->mirror.kind == GCOLOR_MATRIX ? "mirror"
                             : p->ks.kind == GCOLOR_MATRIX   ? "specular"
                                                             : "diffuse";
        rc = gmaterial_param_check_sum(&p->albedo, "phong", "kd + ks + mirror", matrix, err);
    }
    if (rc != G_OK) {
        phong_destroy(&p->base);
        return rc;
    }
    p->n = params->exponent;
    p->lobe_norm = (p->n + 2.0) / (2.0 * M_PI);
    p->has_ks = gcolor_brightness(&p->ks) > 0.0;
    p->has_mirror = gcolor_brightness(&p->mirror) > 0.0;
    p->base.flags |= GMAT_NO_UV; /* its methods read none of the (u, v) parametrisation (material.h) */
    /* reflection is (a sum of its colours) * illum: sample by sample unless one of them re-radiates */
    if (p->kd.kind == GCOLOR_VECTOR && p->ks.kind == GCOLOR_VECTOR && p->mirror.kind == GCOLOR_VECTOR)
        p->base.flags |= GMAT_DIAGONAL;
    *out = &p->base;
    return G_OK;
}

/* phong { diffuse COLOR specular COLOR exponent N mirror COLOR }: diffuse grey 0.5 when neither diffuse nor
 * specular is given, exponent 20 */
static int parse_phong(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor kd = {0}, ks = {0}, mirror = {0};
    double exponent = 20.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "diffuse") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &kd, err);
        else if (strcmp(key, "specular") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &ks, err);
        else if (strcmp(key, "exponent") == 0)
            rc = greader_number_in(r, 0.0, 1e6, &exponent, err);
        else if (strcmp(key, "mirror") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &mirror, err);
        else
            rc = greader_unknown_param(r, "diffuse, specular, exponent, mirror", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !kd.v && !ks.v)
        rc = gmaterial_param_default(r, 0.5, GCOLOR_REFLECTANCE, &kd, err);
    GMaterial *m = NULL;
    if (rc == G_OK) {
        GPhongParams p = {kd.v ? &kd : NULL, ks.v ? &ks : NULL, exponent, mirror.v ? &mirror : NULL};
        if ((rc = gphong_create(greader_colormodel(r), &p, &m, err)) == G_OK)
            *object = m;
    }
    gcolor_free(&kd);
    gcolor_free(&ks);
    gcolor_free(&mirror);
    return rc;
}

static const GParamInfo phong_params[] = {
    {"diffuse", GPARAM_NAMED, "color", "rgb 0.5 0.5 0.5 without specular, else black", "[0, 1]",
     "kd, the Lambertian part; kd + ks + mirror must not exceed 1"},
    {"specular", GPARAM_NAMED, "color", "black", "[0, 1]", "ks, the albedo of the energy-normalised cos^n lobe"},
    {"exponent", GPARAM_NAMED, "number", "20", "[0, 1e6]", "n, the lobe's sharpness about the mirror direction"},
    {"mirror", GPARAM_NAMED, "color", "black", "[0, 1]", "the reflectance of an ideal mirror ray"},
    {NULL},
};

GENERIC_TYPE_PARAMS(phong, GKIND_MATERIAL, &phong_class, parse_phong, NULL, phong_params);
