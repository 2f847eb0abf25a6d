/* phong.c - energy-normalised Phong: f_r = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha), with an optional
 * ideal reflection ray of reflectance `mirror`. Every parameter may be textured (kit/texparam.h). */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

typedef struct Phong {
    GMaterial base;
    GColor kd, ks, mirror;
    GColor albedo; /* kd + ks + mirror, for ambient() */
    GColor kd_pi;  /* kd / pi, the diffuse part of f_r (the constant kd's) */
    double bright[3]; /* the brightness of the constant kd, ks and mirror: the lobes' selection weights */
    double n;
    double lobe_norm; /* (n + 2) / (2 pi) */
    int has_ks, has_mirror;
    GTexColor tex[3];  /* kd, ks, mirror when textured (else GTEXCOLOR_CONSTANT, empty: the colours above) */
    int textured;      /* one of tex[] is textured */
    GTexNumber tex_n;  /* the exponent when textured (else no generator: n) */
} Phong;

/* The parameters at one point: the constants, or the textured ones' values there. */
typedef struct PhongAt {
    const GColor *kd, *ks, *mirror;
    double n, lobe_norm;
    GColor tmp[3]; /* storage of textured colours on sp's arena */
} PhongAt;

/* The parameters at sp into *a; textured colours on sp's arena (the caller marks and releases it). */
static int phong_at(const Phong *p, GSurfPoint *sp, PhongAt *a)
{
    a->kd = &p->kd;
    a->ks = &p->ks;
    a->mirror = &p->mirror;
    a->n = p->n;
    a->lobe_norm = p->lobe_norm;
    if (p->tex_n.gen) {
        a->n = gtexparam_number_at(&p->tex_n, sp);
        a->lobe_norm = (a->n + 2.0) / (2.0 * M_PI);
    }
    if (!p->textured)
        return G_OK;
    if (!sp->scratch)
        return G_ERR_INVALID;
    const GColor **dst[3] = {&a->kd, &a->ks, &a->mirror};
    for (int i = 0; i < 3; i++) {
        if (p->tex[i].kind == GTEXCOLOR_CONSTANT)
            continue;
        int rc = gcolor_scratch(&a->tmp[i], p->base.model, sp->scratch);
        if (rc == G_OK)
            rc = gtexparam_color_at(&p->tex[i], sp, &a->tmp[i]);
        if (rc != G_OK)
            return rc;
        *dst[i] = &a->tmp[i];
    }
    return G_OK;
}

/* Marks sp's arena when p is textured (phong_at may then take colours from it). */
static GScratchMark phong_mark(const Phong *p, GSurfPoint *sp)
{
    GScratchMark m;
    memset(&m, 0, sizeof m);
    if (p->textured && sp->scratch)
        m = gscratch_mark(sp->scratch);
    return m;
}

static void phong_release(const Phong *p, GSurfPoint *sp, GScratchMark m)
{
    if (p->textured && sp->scratch)
        gscratch_release(sp->scratch, m);
}

static void phong_destroy(GMaterial *self)
{
    Phong *p = (Phong *)self;
    for (int i = 0; i < 3; i++)
        gtexparam_color_release(&p->tex[i]);
    gtexparam_number_release(&p->tex_n);
    gcolor_free(&p->kd);
    gcolor_free(&p->ks);
    gcolor_free(&p->mirror);
    gcolor_free(&p->albedo);
    gcolor_free(&p->kd_pi);
    gmem_free(p);
}

/* reflection with the parameters a at the point */
static int reflection_at(const Phong *p, const PhongAt *a, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         GVec3 out, GColor *result)
{
    GVec3 n;
    double cos_in = gmaterial_cos_in(sp, in, out, &n);
    if (cos_in <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    if (p->has_mirror && gmaterial_is_mirror_pair(in, n, out))
        return gcolor_mul(result, a->mirror, illum);
    double cos_alpha = 2.0 * cos_in * gvec3_dot(n, out) - gvec3_dot(in, out);
    double lobe = 0.0;
    if (p->has_ks && cos_alpha > 0.0)
        lobe = a->lobe_norm * pow(cos_alpha > 1.0 ? 1.0 : cos_alpha, a->n);
    if (lobe <= 0.0) /* kd / pi applied to illum, times the cosine: gcolor_mul then gcolor_scale in one pass */
        return gcolor_mul_scaled(result, a->kd, illum, cos_in / M_PI);
    /* f_r as a reflectance (kd / pi + lobe ks: the constant kd's quotient made at creation), then applied to illum
     * times the cosine; f in result itself unless result is illum, else on the arena */
    GColor f = *result;
    GScratchMark mark = {0};
    int rc = G_OK, own = result->v == illum->v;
    if (own) {
        if (!sp->scratch)
            return G_ERR_INVALID;
        mark = gscratch_mark(sp->scratch);
        rc = gcolor_scratch_uncleared(&f, p->base.model, sp->scratch); /* written in full below */
    }
    if (rc == G_OK && a->kd == &p->kd)
        rc = gcolor_axpy(&f, lobe, a->ks, &p->kd_pi);
    else if (rc == G_OK && (rc = gcolor_scale(&f, a->kd, 1.0 / M_PI)) == G_OK)
        rc = gcolor_add_scaled(&f, a->ks, lobe);
    if (rc == G_OK)
        rc = gcolor_mul_scaled(result, &f, illum, cos_in);
    if (own)
        gscratch_release(sp->scratch, mark);
    return rc;
}

static int phong_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    const Phong *p = (const Phong *)self;
    PhongAt a;
    GScratchMark mark = phong_mark(p, sp);
    int rc = phong_at(p, sp, &a);
    if (rc == G_OK)
        rc = reflection_at(p, &a, sp, in, illum, out, result);
    phong_release(p, sp, mark);
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
    const Phong *p = (const Phong *)self;
    if (!p->textured)
        return gcolor_mul(result, &p->albedo, illum);
    PhongAt a;
    GScratchMark mark = phong_mark(p, sp);
    GColor sum;
    int rc = phong_at(p, sp, &a);
    if (rc == G_OK)
        rc = gcolor_scratch(&sum, p->base.model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_add(&sum, a.kd, a.ks);
    if (rc == G_OK)
        rc = gcolor_add(&sum, &sum, a.mirror);
    if (rc == G_OK)
        rc = gcolor_mul(result, &sum, illum);
    phong_release(p, sp, mark);
    return rc;
}

static int phong_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const Phong *p = (const Phong *)self;
    if (p->tex[0].kind == GTEXCOLOR_CONSTANT)
        return gcolor_copy(result, &p->kd);
    return gtexparam_color_at(&p->tex[0], sp, result);
}

/* ---- sampling: three lobes chosen by the brightness of kd, ks and mirror ---- */

/* The lobes' selection weights and the mirror direction of out. */
static void phong_lobes(const Phong *p, const PhongAt *a, GSurfPoint *sp, GVec3 out, double w[3], GVec3 *r)
{
    GVec3 n = gsurfpoint_normal(sp);
    *r = gvec3_reflect(gvec3_neg(out), n);
    /* a constant colour's brightness was taken at creation */
    w[0] = a->kd == &p->kd ? p->bright[0] : gcolor_brightness(a->kd);
    w[1] = !p->has_ks ? 0.0 : a->ks == &p->ks ? p->bright[1] : gcolor_brightness(a->ks);
    w[2] = !p->has_mirror ? 0.0 : a->mirror == &p->mirror ? p->bright[2] : gcolor_brightness(a->mirror);
    if (!(w[0] + w[1] + w[2] > 0.0))
        w[0] = 1.0; /* black: a cosine lobe that reflects nothing */
}

/* The density of the non-delta lobes (the diffuse cosine and the specular cos^n about r). */
static double phong_lobes_pdf(const PhongAt *p, GVec3 n, GVec3 r, const double w[3], GVec3 in)
{
    double total = w[0] + w[1] + w[2], c = gvec3_dot(in, n), pdf = 0.0;
    if (w[0] > 0.0 && c > 0.0)
        pdf += w[0] / total * c / M_PI;
    if (w[1] > 0.0)
        pdf += w[1] / total * goptics_lobe_pdf(r, p->n, in);
    return pdf;
}

/* sample with the parameters a at the point */
static int sample_at(const Phong *p, const PhongAt *a, GSurfPoint *sp, GVec3 out, double u1, double u2,
                     GMaterialSample *s, GColor *weight)
{
    const GMaterial *self = &p->base;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    double w[3], prob;
    GVec3 r, n = gsurfpoint_normal(sp);
    phong_lobes(p, a, sp, out, w, &r);
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
        int rc = a->mirror->kind == GCOLOR_VECTOR ? gcolor_scale(weight, a->mirror, 1.0 / prob)
                                                  : gmaterial_sample_weight(self, sp, r, out, NULL, 0, prob, weight);
        return rc ? rc : 1;
    }
    s->in = lobe == 0 ? goptics_sample_cosine(n, u1, u2) : goptics_sample_lobe(r, a->n, u1, u2);
    s->pdf = phong_lobes_pdf(a, n, r, w, s->in);
    if (!(s->pdf > 0.0))
        return 0;
    /* the value f cos without the ideal part (which only the delta lobe carries) */
    double ci = gmaterial_cos_in(sp, s->in, out, &n);
    if (ci <= 0.0) {
        gcolor_black(weight);
        return 1;
    }
    if (a->kd->kind != GCOLOR_VECTOR || a->ks->kind != GCOLOR_VECTOR) { /* re-radiation: what it makes of white */
        int rc = gmaterial_sample_weight(self, sp, s->in, out, NULL, 0, s->pdf, weight);
        return rc ? rc : 1;
    }
    int rc = gcolor_scale(weight, a->kd, ci / M_PI / s->pdf);
    if (rc == G_OK && p->has_ks) {
        double ca = gvec3_dot(r, s->in);
        if (ca > 0.0)
            rc = gcolor_add_scaled(weight, a->ks, a->lobe_norm * pow(ca > 1.0 ? 1.0 : ca, a->n) * ci / s->pdf);
    }
    return rc ? rc : 1;
}

static int phong_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                        double u2, GMaterialSample *s, GColor *weight)
{
    (void)rel_index;
    const Phong *p = (const Phong *)self;
    PhongAt a;
    GScratchMark mark = phong_mark(p, sp);
    int rc = phong_at(p, sp, &a);
    if (rc == G_OK)
        rc = sample_at(p, &a, sp, out, u1, u2, s, weight);
    phong_release(p, sp, mark);
    return rc;
}

static double phong_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Phong *p = (const Phong *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double w[3], pdf = 0.0;
    GVec3 r;
    PhongAt a;
    GScratchMark mark = phong_mark(p, sp);
    if (phong_at(p, sp, &a) == G_OK) {
        phong_lobes(p, &a, sp, out, w, &r);
        pdf = phong_lobes_pdf(&a, gsurfpoint_normal(sp), r, w, in);
    }
    phong_release(p, sp, mark);
    return pdf;
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
    if (rc == G_OK && (gcolor_alloc(&p->albedo, model) != G_OK || gcolor_alloc(&p->kd_pi, model) != G_OK))
        rc = gerror_set(err, G_ERR_NOMEM, "phong: out of memory");
    if (rc == G_OK && (rc = gcolor_scale(&p->kd_pi, &p->kd, 1.0 / M_PI)) != G_OK)
        rc = gerror_set(err, rc, "phong: cannot scale kd (%s)", gstatus_string(rc));
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
    p->bright[0] = gcolor_brightness(&p->kd);
    p->bright[1] = gcolor_brightness(&p->ks);
    p->bright[2] = gcolor_brightness(&p->mirror);
    p->has_ks = p->bright[1] > 0.0;
    p->has_mirror = p->bright[2] > 0.0;
    p->base.flags |= GMAT_NO_UV; /* its methods read none of the (u, v) parametrisation (material.h) */
    p->base.flags |= GMAT_NO_REL_INDEX; /* nor the relative index: no refraction, no Fresnel term */
    /* reflection is (a sum of its colours) * illum: sample by sample unless one of them re-radiates */
    if (p->kd.kind == GCOLOR_VECTOR && p->ks.kind == GCOLOR_VECTOR && p->mirror.kind == GCOLOR_VECTOR)
        p->base.flags |= GMAT_DIAGONAL;
    *out = &p->base;
    return G_OK;
}

/* Up to 2 colours a textured (or constant) colour parameter takes at its extremes, into ext (*n of them); a
 * parameter not given: none (*n = 1, ext[0] empty: black). */
static int extremes(const GTexColor *t, GColor ext[2], int *n, GError *err)
{
    if (t->kind == GTEXCOLOR_CONSTANT && !t->a.v) {
        ext[0] = (GColor){0};
        *n = 1;
        return G_OK;
    }
    return gtexparam_color_extremes(t, ext, n, err);
}

/* The phong of the file's parameters: textured colours and exponent are checked at every combination of their
 * extremes by gphong_create (each colour and kd + ks + mirror within 1, the exponent's bounds), then the material
 * is made with the first extremes and takes the textures. Takes the contents of tex and tex_n. */
static int create_textured(const GColorModel *model, GTexColor tex[3], GTexNumber *tex_n, GMaterial **out,
                           GError *err)
{
    GColor ext[3][2];
    int n[3] = {0, 0, 0}, rc = G_OK;
    for (int i = 0; i < 3 && rc == G_OK; i++)
        rc = extremes(&tex[i], ext[i], &n[i], err);
    double nlo, nhi;
    gtexparam_number_bounds(tex_n, &nlo, &nhi);
    for (int c = 0; c < n[0] * n[1] * n[2] * 2 && rc == G_OK; c++) {
        int i = c % n[0], j = c / n[0] % n[1], k = c / (n[0] * n[1]) % n[2];
        GPhongParams p = {ext[0][i].v ? &ext[0][i] : NULL, ext[1][j].v ? &ext[1][j] : NULL,
                          c / (n[0] * n[1] * n[2]) ? nhi : nlo, ext[2][k].v ? &ext[2][k] : NULL};
        GMaterial *probe = NULL;
        rc = gphong_create(model, &p, &probe, err);
        if (c == 0 && rc == G_OK)
            *out = probe; /* the material itself: the first extremes, the exponent's lower bound */
        else
            gmaterial_unref(probe);
    }
    for (int i = 0; i < 3; i++)
        for (int e = 0; e < n[i]; e++)
            gcolor_free(&ext[i][e]);
    if (rc != G_OK) {
        gmaterial_unref(*out);
        *out = NULL;
        for (int i = 0; i < 3; i++)
            gtexparam_color_release(&tex[i]);
        gtexparam_number_release(tex_n);
        return rc;
    }
    Phong *ph = (Phong *)*out;
    int reads_uv = gtexparam_number_reads_uv(tex_n);
    for (int i = 0; i < 3; i++) {
        ph->tex[i] = tex[i];
        memset(&tex[i], 0, sizeof tex[i]);
        if (ph->tex[i].kind != GTEXCOLOR_CONSTANT) {
            ph->textured = 1;
            reads_uv |= gtexparam_color_reads_uv(&ph->tex[i]);
        } else {
            gtexparam_color_release(&ph->tex[i]); /* the constant lives in kd, ks or mirror */
        }
    }
    ph->has_ks |= ph->tex[1].kind != GTEXCOLOR_CONSTANT;
    ph->has_mirror |= ph->tex[2].kind != GTEXCOLOR_CONSTANT;
    ph->tex_n = *tex_n;
    *tex_n = gtexparam_number_const(0.0);
    if (reads_uv)
        ph->base.flags &= ~(unsigned)GMAT_NO_UV;
    return G_OK;
}

/* phong { diffuse COLOR specular COLOR exponent N mirror COLOR }: diffuse grey 0.5 when neither diffuse nor
 * specular is given, exponent 20; each may be textured */
static int parse_phong(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GTexColor tex[3] = {{0}, {0}, {0}}; /* kd, ks, mirror */
    GTexNumber exponent = gtexparam_number_const(20.0);
    int given[3] = {0, 0, 0};
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        int which = strcmp(key, "diffuse") == 0 ? 0 : strcmp(key, "specular") == 0 ? 1
                  : strcmp(key, "mirror") == 0  ? 2 : -1;
        if (which >= 0) {
            rc = gtexparam_read_color(r, GCOLOR_REFLECTANCE, &tex[which], err);
            given[which] = 1;
        } else if (strcmp(key, "exponent") == 0)
            rc = gtexparam_read_number(r, 0.0, 1e6, 0, "phong", "exponent", NULL, &exponent, err);
        else
            rc = greader_unknown_param(r, "diffuse, specular, exponent, mirror", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !given[0] && !given[1])
        rc = gmaterial_param_default(r, 0.5, GCOLOR_REFLECTANCE, &tex[0].a, err);
    GMaterial *m = NULL;
    int textured = exponent.gen != NULL;
    for (int i = 0; i < 3; i++)
        textured |= tex[i].kind != GTEXCOLOR_CONSTANT;
    if (rc == G_OK && textured) {
        if ((rc = create_textured(greader_colormodel(r), tex, &exponent, &m, err)) == G_OK)
            *object = m;
    } else if (rc == G_OK) {
        GPhongParams p = {tex[0].a.v ? &tex[0].a : NULL, tex[1].a.v ? &tex[1].a : NULL, exponent.value,
                          tex[2].a.v ? &tex[2].a : NULL};
        if ((rc = gphong_create(greader_colormodel(r), &p, &m, err)) == G_OK)
            *object = m;
    }
    for (int i = 0; i < 3; i++)
        gtexparam_color_release(&tex[i]);
    gtexparam_number_release(&exponent);
    return rc;
}

static const GParamInfo phong_params[] = {
    {"diffuse", GPARAM_NAMED, "texcolor", "rgb 0.5 0.5 0.5 without specular, else black", "[0, 1]",
     "kd, the Lambertian part; kd + ks + mirror must not exceed 1"},
    {"specular", GPARAM_NAMED, "texcolor", "black", "[0, 1]", "ks, the albedo of the energy-normalised cos^n lobe"},
    {"exponent", GPARAM_NAMED, "texnumber", "20", "[0, 1e6]", "n, the lobe's sharpness about the mirror direction"},
    {"mirror", GPARAM_NAMED, "texcolor", "black", "[0, 1]", "the reflectance of an ideal mirror ray"},
    {NULL},
};

GENERIC_TYPE_PARAMS(phong, GKIND_MATERIAL, &phong_class, parse_phong, NULL, phong_params);
