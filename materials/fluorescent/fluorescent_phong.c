/* fluorescent_phong.c - Phong plus fluorescent Lambert (Wilkie et al., section 5.1):
 *
 *   f_r(i, o) = (1 - ks) M / pi
 *             + d * ks * sum_k w_k (n_k + 1) / (2 pi) cos^n_k(alpha) / max(cos_i, cos_o)
 *
 * M the full re-radiation matrix, d its main diagonal (a plain reflectance made once at creation), alpha the
 * angle between o and the mirror direction of i. The max() denominator makes each lobe reciprocal and its
 * directional albedo w_k ks (at most, and nearly exactly until the lobe meets the horizon) at every angle, as
 * (n + 1) / (2 pi) cos^n integrates to 1 over the whole sphere. So the split between the unshifted specular
 * light and the shifted diffuse light does not follow the angle of incidence, the shortcoming the paper
 * points out. The code uses only generic colour operations: M is a matrix in the bispectral model, its 3 x 3
 * reduction in rgb and a folded reflectance in the others. */
#include "generic/kit/fluorescent_kit.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

typedef struct FPhong {
    GMaterial base;
    GColor m;      /* (1 - ks) M */
    GColor d;      /* ks * diagonal */
    GColor albedo; /* (1 - ks) M + ks d, for ambient() */
    double n[3], norm[3];
} FPhong;

void gfluor_phong_default(GFluorPhongParams *p)
{
    p->ks = 0.04;
    p->exponent[0] = 30.0;
    p->exponent[1] = 120.0;
    p->exponent[2] = 480.0;
    p->weight[0] = 0.2;
    p->weight[1] = 0.3;
    p->weight[2] = 0.5;
}

static void fphong_destroy(GMaterial *self)
{
    FPhong *p = (FPhong *)self;
    gcolor_free(&p->m);
    gcolor_free(&p->d);
    gcolor_free(&p->albedo);
    gmem_free(p);
}

static int fphong_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    const FPhong *p = (const FPhong *)self;
    GVec3 n;
    double ci, co;
    if (!gfluor_cosines(sp, in, out, result, &n, &ci, &co))
        return G_OK;
    double ca = 2.0 * ci * co - gvec3_dot(in, out); /* cos(alpha) = r.o, r the mirror direction of in */
    double lobe = 0.0;
    if (ca > 0.0) {
        double lc = log(ca > 1.0 ? 1.0 : ca); /* cos^n = exp(n log cos): one log for the three lobes */
        for (int k = 0; k < 3; k++)
            if (p->norm[k] > 0.0)
                lobe += p->norm[k] * exp(p->n[k] * lc);
        lobe /= fmax(ci, co);
    }
    if (lobe <= 1e-12) {
        int rc = gcolor_mul(result, &p->m, illum);
        return rc ? rc : gcolor_scale(result, result, ci / M_PI);
    }
    return gfluor_two_parts(sp, self->model, illum, &p->m, ci / M_PI, &p->d, lobe * ci, result);
}

static int fphong_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const FPhong *)self)->m);
}

static int fphong_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const FPhong *)self)->albedo, illum);
}

/* ---- sampling: the fluorescent Lambertian's cosine lobe and the three cos^n lobes about the mirror direction,
 * chosen by their brightness; the weight is reflection(in, white, out) / pdf (a vector in every model) ---- */

static void fphong_lobes(const FPhong *p, GSurfPoint *sp, GVec3 out, double w[4], GVec3 *r)
{
    *r = gvec3_reflect(gvec3_neg(out), gsurfpoint_normal(sp));
    w[0] = gcolor_brightness(&p->m);
    double spec = gcolor_brightness(&p->d);
    for (int k = 0; k < 3; k++)
        w[1 + k] = spec * p->norm[k] * 2.0 * M_PI / (p->n[k] + 1.0); /* the lobe's weight w_k */
    if (!(w[0] + w[1] + w[2] + w[3] > 0.0))
        w[0] = 1.0;
}

static double fphong_lobes_pdf(const FPhong *p, GVec3 n, GVec3 r, const double w[4], GVec3 in)
{
    double total = w[0] + w[1] + w[2] + w[3], c = gvec3_dot(in, n), pdf = 0.0;
    if (w[0] > 0.0 && c > 0.0)
        pdf += w[0] / total * c / M_PI;
    for (int k = 0; k < 3; k++)
        if (w[1 + k] > 0.0)
            pdf += w[1 + k] / total * goptics_lobe_pdf(r, p->n[k], in);
    return pdf;
}

static int fphong_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                         double u2, GMaterialSample *s, GColor *weight)
{
    const FPhong *p = (const FPhong *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    double w[4], prob;
    GVec3 r, n = gsurfpoint_normal(sp);
    fphong_lobes(p, sp, out, w, &r);
    int lobe = gmaterial_pick_lobe(w, 4, &u1, &prob);
    s->in = lobe == 0 ? goptics_sample_cosine(n, u1, u2) : goptics_sample_lobe(r, p->n[lobe - 1], u1, u2);
    s->pdf = fphong_lobes_pdf(p, n, r, w, s->in);
    s->flags = GSAMPLE_REFLECT;
    if (!(s->pdf > 0.0))
        return 0;
    int rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, s->pdf, weight);
    return rc ? rc : 1;
}

static double fphong_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const FPhong *p = (const FPhong *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double w[4];
    GVec3 r;
    fphong_lobes(p, sp, out, w, &r);
    return fphong_lobes_pdf(p, gsurfpoint_normal(sp), r, w, in);
}

static const GMaterialClass fluorescent_phong_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "fluorescent-phong",
    .description = "three Phong lobes (matrix diagonal) over a fluorescent Lambertian (Wilkie et al. 5.1)",
    .destroy = fphong_destroy,
    .reflection = fphong_reflection,
    .ambient = fphong_ambient,
    .diffuse = fphong_diffuse,
    .sample = fphong_sample,
    .pdf = fphong_pdf,
};

static int check_params(const GFluorPhongParams *p, GError *err)
{
    if (!isfinite(p->ks) || p->ks < 0.0 || p->ks >= 1.0)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-phong: ks is %g (must be in [0, 1))", p->ks);
    double sum = 0.0;
    for (int k = 0; k < 3; k++) {
        if (!isfinite(p->exponent[k]) || p->exponent[k] < 1.0 || p->exponent[k] > 1e6)
            return gerror_set(err, G_ERR_INVALID, "fluorescent-phong: exponent %d is %g (must be in [1, 1e6])",
                              k + 1, p->exponent[k]);
        if (!isfinite(p->weight[k]) || p->weight[k] < 0.0)
            return gerror_set(err, G_ERR_INVALID, "fluorescent-phong: weight %d is %g (must be >= 0)", k + 1,
                              p->weight[k]);
        sum += p->weight[k];
    }
    if (fabs(sum - 1.0) > 1e-6)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-phong: the lobe weights sum to %g (must sum to 1)", sum);
    return G_OK;
}

int gfluor_phong_create(const GColorModel *model, const GReradiation *matrix, const GFluorPhongParams *params,
                        GMaterial **out, GError *err)
{
    *out = NULL;
    GFluorPhongParams p;
    gfluor_phong_default(&p);
    if (params)
        p = *params;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-phong: no colour model given");
    int rc = gfluor_matrix_check(matrix, "fluorescent-phong", err);
    if (rc == G_OK)
        rc = check_params(&p, err);
    GMaterial *m;
    if (rc == G_OK)
        rc = gmaterial_new(&fluorescent_phong_class, model, sizeof(FPhong), &m, err);
    if (rc != G_OK)
        return rc;
    FPhong *f = (FPhong *)m;
    for (int k = 0; k < 3; k++) {
        f->n[k] = p.exponent[k];
        f->norm[k] = p.weight[k] * (p.exponent[k] + 1.0) / (2.0 * M_PI);
    }
    if (gcolor_alloc(&f->m, model) != G_OK || gcolor_alloc(&f->d, model) != G_OK ||
        gcolor_alloc(&f->albedo, model) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "fluorescent-phong: out of memory");
    if (rc == G_OK)
        rc = gcolor_from_reradiation(&f->m, matrix, err);
    if (rc == G_OK)
        rc = gcolor_scale(&f->m, &f->m, 1.0 - p.ks);
    GSpectrumNM diag;
    if (rc == G_OK)
        rc = gfluor_matrix_diagonal_nm(matrix, &diag, err);
    if (rc == G_OK && (rc = gcolor_from_nm(&f->d, &diag, GCOLOR_REFLECTANCE)) != G_OK)
        gerror_set(err, rc, "fluorescent-phong: cannot convert the matrix's diagonal into model '%s'",
                   gcolormodel_name(model));
    if (rc == G_OK)
        rc = gcolor_scale(&f->d, &f->d, p.ks);
    if (rc == G_OK)
        rc = gcolor_add(&f->albedo, &f->m, &f->d);
    if (rc != G_OK) {
        fphong_destroy(&f->base);
        return rc;
    }
    f->base.flags |= GMAT_NO_UV | GMAT_NO_REL_INDEX; /* they read no (u, v) parametrisation, no index (material.h) */
    *out = &f->base;
    return G_OK;
}

/* ---- the text format ---- */

static const GFluorParam phong_params[] = {
    {"ks", 0.0, 0.999, offsetof(GFluorPhongParams, ks), 1},
    {"exponents", 1.0, 1e6, offsetof(GFluorPhongParams, exponent), 3},
    {"weights", 0.0, 1.0, offsetof(GFluorPhongParams, weight), 3},
    {NULL, 0.0, 0.0, 0, 0},
};

static int parse_fluorescent_phong(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorPhongParams p;
    gfluor_phong_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = gfluor_read_params(r, phong_params, "matrix, ks, exponents, weights", &p, &mat, err);
    if (rc == G_OK)
        rc = gfluor_phong_create(greader_colormodel(r), &mat, &p, &m, err);
    return gfluor_finish(rc, &mat, m, object);
}

static const GParamInfo fluorescent_phong_doc[] = {
    {"matrix", GPARAM_NAMED, "color", "reradiation (a day-glo orange)",
     "a re-radiation matrix (bfc, reradiation) or a reflectance; not a line",
     "the pigment of the Lambertian term; a plain reflectance makes a non-fluorescent matrix of it"},
    {"ks", GPARAM_NAMED, "number", "0.04", "[0, 0.999]", "the albedo of the three specular lobes together"},
    {"exponents", GPARAM_NAMED, "numbers", "30 120 480", "each in [1, 1e6]",
     "three numbers: the exponents of the Phong lobes"},
    {"weights", GPARAM_NAMED, "numbers", "0.2 0.3 0.5", "each in [0, 1], summing to 1",
     "three numbers: each lobe's share of ks"},
    {NULL},
};

GENERIC_TYPE_PARAMS(fluorescent_phong, GKIND_MATERIAL, &fluorescent_phong_class, parse_fluorescent_phong, NULL,
                    fluorescent_phong_doc);
