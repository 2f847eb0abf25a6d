/* plastic.c - a smooth or rough dielectric coating over a diffuse base, with the light's internal reflections
 * between them summed in closed form (Neumann and Neumann's layered model, the non-fluorescent case of the varnish).
 *
 *   f_r(i, o) = f_s(i, o) + T(cos_i) T(cos_o) / (pi eta^2) * rho / (1 - F_int rho)
 *
 *   f_s      the coat's reflection: smooth, the ideal ray with F(cos_o) (Fresnel, air -> coat of index eta); rough,
 *            Walter et al.'s microfacet reflection F(o.h) D(h) G2(i, o, h) / (4 cos_i cos_o) (kit/microfacet.h);
 *   T(c)     1 - R(c), R(c) the coat's directional albedo: F(c) when smooth; when rough, the integral of f_s cos,
 *            tabulated on first use over the visible normals (TABLE_N angles, TABLE_U^2 strata each);
 *   F_int    1 - (1 - R_avg) / eta^2, R_avg = 2 int R(c) c dc: the share of the diffuse light inside that the coat
 *            sends back down (reciprocity gives the share leaving, (1 - R_avg) / eta^2); the series of bounces
 *            base -> coat -> base ... sums to rho / (1 - F_int rho).
 * Energy: light from i is reflected R(cos_i) + T(cos_i) (1 - F_int) rho / (1 - F_int rho) <= R + T = 1, with
 * equality for rho = 1 (a white furnace). f_r is symmetric in i and o. Its own closed form rather than a preset of
 * `layer`: the sum is exact for a diffuse base, costs one evaluation and carries no Monte Carlo noise, where layer's
 * random walks cost some hundred calls an evaluation; layer (which agrees with it: tests/test_plastic.c) remains for
 * what has no closed form (re-radiating or glossy bases, media, any top).
 *
 * Sampling: the coat (its ideal ray, or visible normals when rough) with probability p = R(cos_o) kept in
 * [0.05, 0.95], else a cosine-weighted direction; pdf p pdf_coat + (1 - p) cos / pi.
 *
 * Textured (kit/texparam.h): rho may be a colour texture (the closed form is not linear in it, so body and albedo
 * are computed at each point from rho there, on the point's scratch arena); the roughness a generator whose range
 * lies in [GMICROFACET_ALPHA_MIN, 1], with R(c) and F_int tabulated at PLASTIC_LEVELS roughnesses evenly over the
 * range and interpolated between the two nearest (exactly a level's at a level, as conductor.c does). */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/material_params.h"
#include "generic/kit/microfacet.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

enum { TABLE_N = 128, TABLE_U = 64 };

/* The roughnesses tabulated over a textured roughness's range. */
#define PLASTIC_LEVELS 9

typedef float CoatTable[TABLE_N + 1]; /* R(c) at c = k / TABLE_N (rough) */

typedef struct Plastic {
    GMaterial base;
    GColor body;   /* rho / (1 - F_int rho) / (pi eta^2) */
    GColor albedo; /* (1 - F_int) rho / (1 - F_int rho): the body's albedo for light that enters */
    GColor rho;    /* the base's reflectance (constant) */
    double eta, f_int;
    int rough, distribution;
    GMicrofacet mf;
    CoatTable r_table;
    /* textured: the reflectance (a mix or an image, else empty) and the roughness (gen set), with the coat's tables
     * and F_int at nlevels roughnesses evenly over [level_lo, level_hi] */
    GTexColor tex_rho;
    GTexNumber tex_rough;
    int textured, nlevels;
    double level_lo, level_hi;
    CoatTable *level_r;
    double *level_f_int;
    /* the tables, F_int, body and albedo are made on first use (coat_make): a plastic defined but never rendered
     * costs no quadrature */
    GMaterialOnce made;
} Plastic;

/* The coat and body at one point: the distribution, R(c) as (1 - w) r0 + w r1, F_int, and (when asked) the body's
 * colours (the material's own, or on the point's scratch arena). */
typedef struct PlasticAt {
    GMicrofacet mf;
    const float *r0, *r1;
    double w, f_int;
    const GColor *body, *albedo;
    GColor body_buf, albedo_buf;
} PlasticAt;

static void plastic_destroy(GMaterial *self)
{
    Plastic *p = (Plastic *)self;
    gcolor_free(&p->body);
    gcolor_free(&p->albedo);
    gcolor_free(&p->rho);
    gtexparam_color_release(&p->tex_rho);
    gtexparam_number_release(&p->tex_rough);
    gmem_free(p->level_r);
    gmem_free(p->level_f_int);
    gmem_free(p);
}

/* A table's R(c), linear between its nodes, for c in [0, 1]. */
static double table_at(const float *t, double c)
{
    double x = c * TABLE_N;
    int k = (int)x;
    if (k >= TABLE_N)
        return t[TABLE_N];
    return t[k] + (x - k) * (t[k + 1] - t[k]);
}

/* The coat's directional albedo R(c) at a point. */
static double coat_albedo(const Plastic *p, const PlasticAt *a, double c)
{
    c = fmin(1.0, fmax(0.0, c));
    if (!p->rough)
        return goptics_fresnel(c, 1.0 / p->eta);
    double r = table_at(a->r0, c);
    return a->w == 0.0 ? r : (1.0 - a->w) * r + a->w * table_at(a->r1, c);
}

/* R(c) of the rough coat mf of index eta by the visible normals: the mean of F(o.h) G2 / G1(o) over TABLE_U^2
 * strata. */
static double rough_albedo(const GMicrofacet *mf, double eta, double c)
{
    c = fmax(c, 1e-4);
    GVec3 o = gvec3(sqrt(fmax(0.0, 1.0 - c * c)), 0.0, c);
    double sum = 0.0, g1o = 1.0 / (1.0 + gmicrofacet_lambda(mf, o));
    for (int a = 0; a < TABLE_U; a++)
        for (int b = 0; b < TABLE_U; b++) {
            GVec3 h = gmicrofacet_sample_visible(mf, o, (a + 0.5) / TABLE_U, (b + 0.5) / TABLE_U);
            double oh = gvec3_dot(o, h);
            GVec3 i = gvec3_sub(gvec3_scale(h, 2.0 * oh), o);
            if (i.z <= 0.0 || oh <= 0.0)
                continue;
            sum += goptics_fresnel(oh, 1.0 / eta) * gmicrofacet_g2(mf, i, o, h) / g1o;
        }
    return sum / (TABLE_U * TABLE_U);
}

/* The coat's table R(c) (rough: mf; smooth: Fresnel at the nodes) and F_int = 1 - (1 - R_avg) / eta^2, R_avg =
 * 2 int R(c) c dc by Simpson's rule over the table's nodes. */
static double coat_table(const GMicrofacet *mf, int rough, double eta, float *table)
{
    double r_avg = 0.0;
    for (int k = 0; k <= TABLE_N; k++) {
        double c = (double)k / TABLE_N;
        double r = rough ? rough_albedo(mf, eta, c) : goptics_fresnel(c, 1.0 / eta);
        table[k] = (float)r;
        r_avg += r * c * (k == 0 || k == TABLE_N ? 1.0 : (k & 1) ? 4.0 : 2.0);
    }
    r_avg = 2.0 * r_avg / (3.0 * TABLE_N);
    return 1.0 - (1.0 - r_avg) / (eta * eta);
}

/* body = rho / (1 - F_int rho) / (pi eta^2) and albedo = (1 - F_int) rho / (1 - F_int rho), per sample; denom is
 * storage of the model (it may be albedo). */
static int body_colours(const GColor *rho, double f_int, double eta, GColor *denom, GColor *body, GColor *albedo)
{
    int rc = gcolor_fill(denom, 1.0);
    if (rc == G_OK)
        rc = gcolor_axpy(denom, -f_int, rho, denom);
    if (rc == G_OK)
        rc = gcolor_div(body, rho, denom);
    if (rc == G_OK)
        rc = gcolor_scale(albedo, body, 1.0 - f_int);
    if (rc == G_OK)
        rc = gcolor_scale(body, body, 1.0 / (M_PI * eta * eta));
    return rc;
}

/* The coat and (colours: 1) the body at sp into *a; colours on sp's arena when textured (the caller marks and
 * releases it). */
static int coat_make(void *plastic);

static int plastic_at(const Plastic *p, GSurfPoint *sp, int colours, PlasticAt *a)
{
    int made = gmaterial_once(&((Plastic *)p)->made, coat_make, (void *)p);
    if (made != G_OK)
        return made;
    a->mf = p->mf;
    a->r0 = a->r1 = p->r_table;
    a->w = 0.0;
    a->f_int = p->f_int;
    a->body = &p->body;
    a->albedo = &p->albedo;
    if (!p->textured)
        return G_OK;
    if (p->tex_rough.gen) {
        double r = gtexparam_number_at(&p->tex_rough, sp), alpha = gmicrofacet_alpha_from_roughness(r);
        a->mf = gmicrofacet_make(p->distribution, alpha, alpha);
        double x = p->nlevels > 1 ? (r - p->level_lo) / (p->level_hi - p->level_lo) * (p->nlevels - 1) : 0.0;
        x = x > 0.0 ? (x < p->nlevels - 1 ? x : p->nlevels - 1) : 0.0;
        int j = (int)x;
        a->r0 = a->r1 = p->level_r[j];
        a->f_int = p->level_f_int[j];
        if (j + 1 < p->nlevels && x > j) {
            a->w = x - j;
            a->r1 = p->level_r[j + 1];
            a->f_int = (1.0 - a->w) * p->level_f_int[j] + a->w * p->level_f_int[j + 1];
        }
    }
    if (!colours)
        return G_OK;
    if (!sp->scratch)
        return G_ERR_INVALID;
    const GColorModel *m = p->base.model;
    GColor rho = p->rho;
    int rc = G_OK;
    if (p->tex_rho.kind != GTEXCOLOR_CONSTANT) { /* the texture's colour at sp, within [0, 1] as at creation */
        rc = gcolor_scratch_uncleared(&rho, m, sp->scratch);
        if (rc == G_OK)
            rc = gtexparam_color_at(&p->tex_rho, sp, &rho);
        for (int i = 0; rc == G_OK && i < m->nvalues; i++)
            rho.v[i] = rho.v[i] > 0.0f ? (rho.v[i] < 1.0f ? rho.v[i] : 1.0f) : 0.0f;
    }
    if (rc == G_OK)
        rc = gcolor_scratch_uncleared(&a->body_buf, m, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch_uncleared(&a->albedo_buf, m, sp->scratch);
    if (rc == G_OK)
        rc = body_colours(&rho, a->f_int, p->eta, &a->albedo_buf, &a->body_buf, &a->albedo_buf);
    a->body = &a->body_buf;
    a->albedo = &a->albedo_buf;
    return rc;
}

/* The coat's own reflection times cos_i for the local directions i, o (rough only). */
static double coat_reflect_cos(const Plastic *p, const PlasticAt *a, GVec3 i, GVec3 o)
{
    GVec3 h = gvec3_add(i, o);
    double len = gvec3_length(h);
    if (!(len > 0.0))
        return 0.0;
    h = gvec3_scale(h, 1.0 / len);
    return goptics_fresnel(fmax(0.0, gvec3_dot(o, h)), 1.0 / p->eta) * gmicrofacet_reflect_cos(&a->mf, i, o);
}

static int plastic_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                              GColor *result)
{
    const Plastic *p = (const Plastic *)self;
    GVec3 n;
    double ci = gmaterial_cos_in(sp, in, out, &n), co = gvec3_dot(out, n);
    if (ci <= 0.0 || co <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    if (!p->rough && gmaterial_is_mirror_pair(in, n, out)) /* the ideal ray alone (material.h) */
        return gcolor_scale(result, illum, goptics_fresnel(co, 1.0 / p->eta));
    GScratchMark mark = {0};
    if (p->textured && sp->scratch)
        mark = gscratch_mark(sp->scratch);
    PlasticAt a;
    int rc = plastic_at(p, sp, 1, &a);
    if (rc == G_OK) {
        double t = (1.0 - coat_albedo(p, &a, ci)) * (1.0 - coat_albedo(p, &a, co));
        rc = gcolor_mul_scaled(result, a.body, illum, t * ci);
    }
    if (rc == G_OK && p->rough) {
        GFrame f = gframe_from_normal(n);
        double s = coat_reflect_cos(p, &a, gframe_to_local(&f, in), gframe_to_local(&f, out));
        rc = gcolor_axpy(result, s, illum, result);
    }
    if (p->textured && sp->scratch)
        gscratch_release(sp->scratch, mark);
    return rc;
}

static int plastic_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    if (((const Plastic *)self)->rough)
        return 0;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

/* The body's albedo at normal incidence, for previews and the ambient term. */
static int plastic_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const Plastic *p = (const Plastic *)self;
    GScratchMark mark = {0};
    if (p->textured && sp->scratch)
        mark = gscratch_mark(sp->scratch);
    PlasticAt a;
    int rc = plastic_at(p, sp, 1, &a);
    if (rc == G_OK)
        rc = gcolor_scale(result, a.albedo, 1.0 - coat_albedo(p, &a, 1.0));
    if (p->textured && sp->scratch)
        gscratch_release(sp->scratch, mark);
    return rc;
}

/* The probability of drawing from the coat for light leaving at cos_o. */
static double coat_share(const Plastic *p, const PlasticAt *a, double co)
{
    return fmin(0.95, fmax(0.05, coat_albedo(p, a, co)));
}

static double plastic_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Plastic *p = (const Plastic *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n), ci = gvec3_dot(in, n);
    if (co <= 0.0 || ci <= 0.0 || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    PlasticAt a;
    if (plastic_at(p, sp, 0, &a) != G_OK)
        return 0.0;
    double q = coat_share(p, &a, co), pdf = (1.0 - q) * ci / M_PI;
    if (p->rough) {
        GFrame f = gframe_from_normal(n);
        pdf += q * gmicrofacet_pdf_reflect(&a.mf, gframe_to_local(&f, out), gframe_to_local(&f, in));
    }
    return pdf;
}

static int plastic_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                          double u2, GMaterialSample *s, GColor *weight)
{
    const Plastic *p = (const Plastic *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (co <= 0.0 || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    PlasticAt a;
    int rc = plastic_at(p, sp, 0, &a);
    if (rc != G_OK)
        return rc;
    double q = coat_share(p, &a, co);
    s->flags = GSAMPLE_REFLECT;
    if (u1 < q && !p->rough) {
        s->in = gvec3_reflect(gvec3_neg(out), n);
        s->pdf = q;
        s->flags |= GSAMPLE_DELTA;
    } else if (u1 < q) {
        GFrame f = gframe_from_normal(n);
        GVec3 o = gframe_to_local(&f, out);
        GVec3 h = gmicrofacet_sample_visible(&a.mf, o, fmin(u1 / q, 0x1.fffffffffffffp-1), u2);
        GVec3 i = gvec3_sub(gvec3_scale(h, 2.0 * gvec3_dot(o, h)), o);
        if (i.z <= 0.0) /* reflected below the surface: nothing drawn (pdf counts only the upper hemisphere) */
            return 0;
        s->in = gframe_to_world(&f, i);
        s->pdf = plastic_pdf(self, sp, s->in, out, rel_index);
    } else {
        s->in = goptics_sample_cosine(n, (u1 - q) / (1.0 - q), u2);
        s->pdf = plastic_pdf(self, sp, s->in, out, rel_index);
    }
    if (!(s->pdf > 0.0))
        return 0;
    rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, s->pdf, weight);
    return rc ? rc : 1;
}

static const GMaterialClass plastic_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "plastic",
    .description = "smooth or rough dielectric coat over a diffuse base, internal reflections in closed form",
    .destroy = plastic_destroy,
    .reflection = plastic_reflection,
    .reflection_dir = plastic_reflection_dir,
    .diffuse = plastic_diffuse,
    .sample = plastic_sample,
    .pdf = plastic_pdf,
};

/* What a file gave: the reflectance (a colour, a mix or an image), the index, the roughness (a number or a
 * generator) and the distribution. */
typedef struct PlasticSpec {
    GTexColor rho;
    double eta;
    GTexNumber rough;
    int distribution;
} PlasticSpec;

/* Room for the coat's tables at PLASTIC_LEVELS roughnesses evenly over the textured roughness's range (one when the
 * range is a point; coat_make fills them). */
static int rough_levels(Plastic *p, const GTexNumber *rough, GError *err)
{
    gtexparam_number_bounds(rough, &p->level_lo, &p->level_hi);
    p->nlevels = p->level_hi > p->level_lo ? PLASTIC_LEVELS : 1;
    p->level_r = gmem_calloc((size_t)p->nlevels, sizeof *p->level_r);
    p->level_f_int = gmem_calloc((size_t)p->nlevels, sizeof *p->level_f_int);
    if (!p->level_r || !p->level_f_int)
        return gerror_set(err, G_ERR_NOMEM, "plastic: out of memory");
    gtexparam_number_copy(&p->tex_rough, rough);
    return G_OK;
}

/* The coat's tables (at each level, exactly the range's ends at the first and last, the first being the material's
 * own; or the material's one) and F_int, then the body's colours: the plastic's work on first use (gmaterial_once). */
static int coat_make(void *plastic)
{
    Plastic *p = plastic;
    for (int j = 0; j < p->nlevels; j++) {
        double r = p->nlevels > 1 ? p->level_lo + (p->level_hi - p->level_lo) * j / (p->nlevels - 1) : p->level_lo;
        if (j == p->nlevels - 1)
            r = p->level_hi;
        double alpha = gmicrofacet_alpha_from_roughness(r);
        GMicrofacet mf = gmicrofacet_make(p->distribution, alpha, alpha);
        p->level_f_int[j] = coat_table(&mf, 1, p->eta, p->level_r[j]);
    }
    if (p->nlevels) {
        memcpy(p->r_table, p->level_r[0], sizeof p->r_table);
        p->f_int = p->level_f_int[0];
    } else
        p->f_int = coat_table(&p->mf, p->rough, p->eta, p->r_table);
    return body_colours(&p->rho, p->f_int, p->eta, &p->albedo, &p->body, &p->albedo);
}

/* The extremes of a textured reflectance within [0, 1] and plain colours (the closed form's energy rule holds for
 * every rho in [0, 1]). */
static int check_textured_rho(const GColorModel *model, const GTexColor *rho, GError *err)
{
    GColor ext[2];
    int n = 0;
    int rc = gtexparam_color_extremes(rho, ext, &n, err);
    for (int i = 0; i < n; i++) {
        GColor checked = {0};
        if (rc == G_OK)
            rc = gmaterial_param_color(model, &ext[i], GCOLOR_REFLECTANCE, 1.0, "plastic", "reflectance", &checked,
                                       err);
        gcolor_free(&checked);
        gcolor_free(&ext[i]);
    }
    return rc;
}

/* The plastic the spec describes into *out; takes the spec's textures (its rho and rough become empty). */
static int plastic_create(const GColorModel *model, PlasticSpec *s, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *m = NULL;
    int rc = gmaterial_new(&plastic_class, model, sizeof(Plastic), &m, err);
    if (rc != G_OK)
        return rc;
    Plastic *p = (Plastic *)m;
    p->eta = s->eta;
    p->distribution = s->distribution;
    double alpha = gmicrofacet_alpha_from_roughness(s->rough.value);
    p->rough = alpha >= GMICROFACET_ALPHA_MIN || s->rough.gen;
    p->mf = gmicrofacet_make(s->distribution, alpha, alpha);
    if (s->rough.gen) /* the range's lower end: level 0 */
        rc = rough_levels(p, &s->rough, err);
    const GColor *rho = gtexparam_color_constant(&s->rho);
    if (rc == G_OK && !rho) { /* textured: checked at its extremes; the unit colour stands in for the constant parts */
        rc = check_textured_rho(model, &s->rho, err);
        GColor unit = {0};
        if (rc == G_OK && gtexparam_unit_color(model, &unit) != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "plastic: out of memory");
        if (rc == G_OK)
            rc = gmaterial_param_color(model, &unit, GCOLOR_REFLECTANCE, 1.0, "plastic", "reflectance", &p->rho, err);
        gcolor_free(&unit);
    } else if (rc == G_OK)
        rc = gmaterial_param_color(model, rho, GCOLOR_REFLECTANCE, 1.0, "plastic", "reflectance", &p->rho, err);
    if (rc == G_OK && p->rho.kind != GCOLOR_VECTOR)
        rc = gerror_set_param(err, G_ERR_INVALID, "reflectance",
                              "plastic: reflectance must be a plain colour, not a re-radiation matrix (a "
                              "re-radiating base under a coat is a layer)");
    if (rc == G_OK && ((rc = gcolor_alloc(&p->body, model)) != G_OK || (rc = gcolor_alloc(&p->albedo, model)) != G_OK))
        rc = gerror_set(err, rc, "plastic: out of memory");
    m->flags |= GMAT_NO_UV | GMAT_DIAGONAL; /* plain colours sample by sample; no (u, v) read */
    m->flags |= GMAT_NO_REL_INDEX; /* the coat's Fresnel term is of its own index, not the relative one */
    if (rc == G_OK && !rho) {
        p->tex_rho = s->rho;
        memset(&s->rho, 0, sizeof s->rho);
    }
    p->textured = p->tex_rho.kind != GTEXCOLOR_CONSTANT || p->tex_rough.gen;
    if (gtexparam_color_reads_uv(&p->tex_rho) || gtexparam_number_reads_uv(&p->tex_rough))
        m->flags &= ~(unsigned)GMAT_NO_UV;
    if (rc != G_OK) {
        plastic_destroy(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

/* `roughness R`: a number in [0, 1] or a generator whose range lies in [GMICROFACET_ALPHA_MIN, 1] (rough
 * everywhere: whether the coat is smooth is decided at creation). */
static int read_roughness(GReader *r, GTexNumber *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK)
        rc = gtexparam_read_number(r, 0.0, 1.0, 0, "plastic", "roughness", NULL, out, err);
    double lo, hi;
    gtexparam_number_bounds(out, &lo, &hi);
    if (rc == G_OK && out->gen && lo < GMICROFACET_ALPHA_MIN)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "plastic: a textured roughness must stay >= %g, rough everywhere (the generator's "
                                "range starts at %g; whether the coat is smooth is decided at creation)",
                                GMICROFACET_ALPHA_MIN, lo);
    return rc;
}

/* plastic { reflectance COLOR index N roughness R distribution ggx|beckmann } */
static int parse_plastic(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    PlasticSpec s = {.eta = 1.5, .rough = gtexparam_number_const(0.0), .distribution = GMICROFACET_GGX};
    static const char *const shapes[] = {"ggx", "beckmann", NULL};
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "reflectance") == 0)
            rc = gtexparam_read_color(r, GCOLOR_REFLECTANCE, &s.rho, err);
        else if (strcmp(key, "index") == 0)
            rc = gtexparam_read_constant(r, 1.0, 4.0, "plastic", "index", "the coat's Fresnel tables, made at creation",
                                         &s.eta, err);
        else if (strcmp(key, "roughness") == 0)
            rc = read_roughness(r, &s.rough, err);
        else if (strcmp(key, "distribution") == 0)
            rc = greader_choice(r, shapes, &s.distribution, err);
        else
            rc = greader_unknown_param(r, "reflectance, index, roughness, distribution", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && s.rho.kind == GTEXCOLOR_CONSTANT && !s.rho.a.v)
        rc = gmaterial_param_default(r, 0.5, GCOLOR_REFLECTANCE, &s.rho.a, err);
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = plastic_create(greader_colormodel(r), &s, &m, err)) == G_OK)
        *object = m;
    gtexparam_color_release(&s.rho);
    gtexparam_number_release(&s.rough);
    return rc;
}

static const GParamInfo plastic_params[] = {
    {"reflectance", GPARAM_NAMED, "texcolor", "rgb 0.5 0.5 0.5", "[0, 1], not a matrix", "the diffuse base's albedo"},
    {"index", GPARAM_NAMED, "number", "1.5", "[1, 4]", "the coat's refraction index"},
    {"roughness", GPARAM_NAMED, "texnumber", "0 (smooth)", "[0, 1]; textured: a range within [0.001, 1]",
     "the coat's microfacet width alpha (kit/microfacet.h); below 0.001 smooth"},
    {"distribution", GPARAM_NAMED, "choice", "ggx", "ggx, beckmann", "the coat's distribution of microfacets"},
    {NULL},
};

GENERIC_TYPE_PARAMS(plastic, GKIND_MATERIAL, &plastic_class, parse_plastic, NULL, plastic_params);
