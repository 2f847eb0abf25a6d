/* plastic.c - a smooth or rough dielectric coating over a diffuse base, with the light's internal reflections
 * between them summed in closed form (Neumann and Neumann's layered model, the non-fluorescent case of the varnish).
 *
 *   f_r(i, o) = f_s(i, o) + T(cos_i) T(cos_o) / (pi eta^2) * rho / (1 - F_int rho)
 *
 *   f_s      the coat's reflection: smooth, the ideal ray with F(cos_o) (Fresnel, air -> coat of index eta); rough,
 *            Walter et al.'s microfacet reflection F(o.h) D(h) G2(i, o, h) / (4 cos_i cos_o) (kit/microfacet.h);
 *   T(c)     1 - R(c), R(c) the coat's directional albedo: F(c) when smooth; when rough, the integral of f_s cos,
 *            tabulated at creation over the visible normals (TABLE_N angles, TABLE_U^2 strata each);
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
 * [0.05, 0.95], else a cosine-weighted direction; pdf p pdf_coat + (1 - p) cos / pi. */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/material_params.h"
#include "generic/kit/microfacet.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

enum { TABLE_N = 128, TABLE_U = 64 };

typedef struct Plastic {
    GMaterial base;
    GColor body;   /* rho / (1 - F_int rho) / (pi eta^2) */
    GColor albedo; /* (1 - F_int) rho / (1 - F_int rho): the body's albedo for light that enters */
    double eta, f_int;
    int rough;
    GMicrofacet mf;
    float r_table[TABLE_N + 1]; /* R(c) at c = k / TABLE_N (rough) */
} Plastic;

static void plastic_destroy(GMaterial *self)
{
    Plastic *p = (Plastic *)self;
    gcolor_free(&p->body);
    gcolor_free(&p->albedo);
    gmem_free(p);
}

/* The coat's directional albedo R(c). */
static double coat_albedo(const Plastic *p, double c)
{
    c = fmin(1.0, fmax(0.0, c));
    if (!p->rough)
        return goptics_fresnel(c, 1.0 / p->eta);
    double x = c * TABLE_N;
    int k = (int)x;
    if (k >= TABLE_N)
        return p->r_table[TABLE_N];
    return p->r_table[k] + (x - k) * (p->r_table[k + 1] - p->r_table[k]);
}

/* R(c) of the rough coat by the visible normals: the mean of F(o.h) G2 / G1(o) over TABLE_U^2 strata. */
static double rough_albedo(const Plastic *p, double c)
{
    c = fmax(c, 1e-4);
    GVec3 o = gvec3(sqrt(fmax(0.0, 1.0 - c * c)), 0.0, c);
    double sum = 0.0, g1o = 1.0 / (1.0 + gmicrofacet_lambda(&p->mf, o));
    for (int a = 0; a < TABLE_U; a++)
        for (int b = 0; b < TABLE_U; b++) {
            GVec3 h = gmicrofacet_sample_visible(&p->mf, o, (a + 0.5) / TABLE_U, (b + 0.5) / TABLE_U);
            double oh = gvec3_dot(o, h);
            GVec3 i = gvec3_sub(gvec3_scale(h, 2.0 * oh), o);
            if (i.z <= 0.0 || oh <= 0.0)
                continue;
            sum += goptics_fresnel(oh, 1.0 / p->eta) * gmicrofacet_g2(&p->mf, i, o, h) / g1o;
        }
    return sum / (TABLE_U * TABLE_U);
}

/* The coat's own reflection times cos_i for the local directions i, o (rough only). */
static double coat_reflect_cos(const Plastic *p, GVec3 i, GVec3 o)
{
    GVec3 h = gvec3_add(i, o);
    double len = gvec3_length(h);
    if (!(len > 0.0))
        return 0.0;
    h = gvec3_scale(h, 1.0 / len);
    return goptics_fresnel(fmax(0.0, gvec3_dot(o, h)), 1.0 / p->eta) * gmicrofacet_reflect_cos(&p->mf, i, o);
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
    double t = (1.0 - coat_albedo(p, ci)) * (1.0 - coat_albedo(p, co));
    int rc = gcolor_mul_scaled(result, &p->body, illum, t * ci);
    if (rc == G_OK && p->rough) {
        GFrame f = gframe_from_normal(n);
        double s = coat_reflect_cos(p, gframe_to_local(&f, in), gframe_to_local(&f, out));
        rc = gcolor_axpy(result, s, illum, result);
    }
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
    (void)sp;
    const Plastic *p = (const Plastic *)self;
    return gcolor_scale(result, &p->albedo, 1.0 - coat_albedo(p, 1.0));
}

/* The probability of drawing from the coat for light leaving at cos_o. */
static double coat_share(const Plastic *p, double co)
{
    return fmin(0.95, fmax(0.05, coat_albedo(p, co)));
}

static double plastic_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Plastic *p = (const Plastic *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n), ci = gvec3_dot(in, n);
    if (co <= 0.0 || ci <= 0.0 || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double q = coat_share(p, co), pdf = (1.0 - q) * ci / M_PI;
    if (p->rough) {
        GFrame f = gframe_from_normal(n);
        pdf += q * gmicrofacet_pdf_reflect(&p->mf, gframe_to_local(&f, out), gframe_to_local(&f, in));
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
    double q = coat_share(p, co);
    s->flags = GSAMPLE_REFLECT;
    if (u1 < q && !p->rough) {
        s->in = gvec3_reflect(gvec3_neg(out), n);
        s->pdf = q;
        s->flags |= GSAMPLE_DELTA;
    } else if (u1 < q) {
        GFrame f = gframe_from_normal(n);
        GVec3 o = gframe_to_local(&f, out);
        GVec3 h = gmicrofacet_sample_visible(&p->mf, o, fmin(u1 / q, 0x1.fffffffffffffp-1), u2);
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
    int rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, s->pdf, weight);
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

/* The plastic of base reflectance rho, coat index eta, roughness r (0: smooth) and distribution into *out. */
static int plastic_create(const GColorModel *model, const GColor *rho, double eta, double roughness,
                          int distribution, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *m = NULL;
    int rc = gmaterial_new(&plastic_class, model, sizeof(Plastic), &m, err);
    if (rc != G_OK)
        return rc;
    Plastic *p = (Plastic *)m;
    p->eta = eta;
    double alpha = gmicrofacet_alpha_from_roughness(roughness);
    p->rough = alpha >= GMICROFACET_ALPHA_MIN;
    p->mf = gmicrofacet_make(distribution, alpha, alpha);
    /* R_avg = 2 int R(c) c dc, Simpson's rule over the table's nodes (smooth: Fresnel at the same nodes) */
    double r_avg = 0.0;
    for (int k = 0; k <= TABLE_N; k++) {
        double c = (double)k / TABLE_N;
        double r = p->rough ? rough_albedo(p, c) : goptics_fresnel(c, 1.0 / eta);
        p->r_table[k] = (float)r;
        r_avg += r * c * (k == 0 || k == TABLE_N ? 1.0 : (k & 1) ? 4.0 : 2.0);
    }
    r_avg = 2.0 * r_avg / (3.0 * TABLE_N);
    p->f_int = 1.0 - (1.0 - r_avg) / (eta * eta);
    GColor denom = {0};
    rc = gmaterial_param_color(model, rho, GCOLOR_REFLECTANCE, 1.0, "plastic", "reflectance", &p->albedo, err);
    if (rc == G_OK && p->albedo.kind != GCOLOR_VECTOR)
        rc = gerror_set_param(err, G_ERR_INVALID, "reflectance",
                              "plastic: reflectance must be a plain colour, not a re-radiation matrix (a "
                              "re-radiating base under a coat is a layer)");
    if (rc == G_OK && ((rc = gcolor_alloc(&denom, model)) != G_OK || (rc = gcolor_alloc(&p->body, model)) != G_OK))
        rc = gerror_set(err, rc, "plastic: out of memory");
    /* albedo = (1 - F_int) rho / (1 - F_int rho), body = rho / (1 - F_int rho) / (pi eta^2) */
    if (rc == G_OK && (rc = gcolor_fill(&denom, 1.0)) == G_OK && (rc = gcolor_axpy(&denom, -p->f_int, &p->albedo,
                                                                                    &denom)) == G_OK &&
        (rc = gcolor_div(&p->body, &p->albedo, &denom)) == G_OK)
        rc = gcolor_scale(&p->albedo, &p->body, 1.0 - p->f_int);
    if (rc == G_OK)
        rc = gcolor_scale(&p->body, &p->body, 1.0 / (M_PI * eta * eta));
    gcolor_free(&denom);
    if (rc != G_OK) {
        plastic_destroy(m);
        return rc;
    }
    m->flags |= GMAT_NO_UV | GMAT_DIAGONAL; /* plain colours sample by sample; no (u, v) read */
    *out = m;
    return G_OK;
}

/* plastic { reflectance COLOR index N roughness R distribution ggx|beckmann } */
static int parse_plastic(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor rho = {0};
    double eta = 1.5, roughness = 0.0;
    int distribution = GMICROFACET_GGX;
    static const char *const shapes[] = {"ggx", "beckmann", NULL};
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "reflectance") == 0) {
            gcolor_free(&rho);
            rc = greader_color(r, GCOLOR_REFLECTANCE, &rho, err);
        } else if (strcmp(key, "index") == 0)
            rc = gtexparam_read_constant(r, 1.0, 4.0, "plastic", "index", "the coat's Fresnel tables, made at creation",
                                         &eta, err);
        else if (strcmp(key, "roughness") == 0)
            rc = gtexparam_read_constant(r, 0.0, 1.0, "plastic", "roughness",
                                         "the coat's microfacet distribution and albedo tables, made at creation",
                                         &roughness, err);
        else if (strcmp(key, "distribution") == 0)
            rc = greader_choice(r, shapes, &distribution, err);
        else
            rc = greader_unknown_param(r, "reflectance, index, roughness, distribution", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !rho.v)
        rc = gmaterial_param_default(r, 0.5, GCOLOR_REFLECTANCE, &rho, err);
    GMaterial *m = NULL;
    if (rc == G_OK &&
        (rc = plastic_create(greader_colormodel(r), &rho, eta, roughness, distribution, &m, err)) == G_OK)
        *object = m;
    gcolor_free(&rho);
    return rc;
}

static const GParamInfo plastic_params[] = {
    {"reflectance", GPARAM_NAMED, "color", "rgb 0.5 0.5 0.5", "[0, 1], not a matrix", "the diffuse base's albedo"},
    {"index", GPARAM_NAMED, "number", "1.5", "[1, 4]", "the coat's refraction index"},
    {"roughness", GPARAM_NAMED, "number", "0 (smooth)", "[0, 1]",
     "the coat's microfacet width alpha (kit/microfacet.h); below 0.001 smooth"},
    {"distribution", GPARAM_NAMED, "choice", "ggx", "ggx, beckmann", "the coat's distribution of microfacets"},
    {NULL},
};

GENERIC_TYPE_PARAMS(plastic, GKIND_MATERIAL, &plastic_class, parse_plastic, NULL, plastic_params);
