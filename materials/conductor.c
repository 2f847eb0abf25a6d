/* conductor.c - a metal: the Fresnel reflectance of a complex index n + i k (kit/fresnel.h), smooth (an ideal mirror
 * ray) or rough (a GGX or Beckmann microfacet distribution, kit/microfacet.h), with the energy that single scattering
 * loses on a rough surface given back (Kulla and Conty 2017).
 *
 * Rough reflection, for light from in towards out about the shading normal, h their half vector:
 *   f cos_in = F(in.h) D(h) G2(in, out, h) / (4 cos_out) + F_ms (1 - E(cos_out)) (1 - E(cos_in)) cos_in
 *              / (pi (1 - E_avg)),
 * E the directional albedo of the rough mirror with Fresnel 1 and E_avg its cosine-weighted mean (tabulated at
 * construction, gmicrofacet_albedo_table), F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) per sample, F_avg the
 * cosine-weighted mean of the Fresnel term: the light that leaves after more than one bounce. With Fresnel 1 the
 * albedo is then 1 at every angle. Sampling: visible normals (gmicrofacet_sample_visible) and, with probability
 * 1 - E(cos_out), a cosine lobe for the compensation. */
#include "generic/kit/color_map.h"
#include "generic/kit/fresnel.h"
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/metals.h"
#include "generic/kit/microfacet.h"
#include "generic/colorspec.h"
#include "generic/plugin.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Why a roughness stays constant (gtexparam_read_constant). */
#define ROUGH_WHY "the microfacet distribution and its albedo tables, made at creation"

/* The largest n and k a file may give. */
#define CONDUCTOR_INDEX_MAX 1000.0

/* The rough surface at one point: the distribution, its albedo table and the compensation's colour. */
typedef struct RoughAt {
    GMicrofacet mf;
    double alpha2; /* mf.alpha_x squared: what an isotropic GGX surface reads */
    const float *e;
    const GColor *ms;
} RoughAt;

typedef struct Conductor {
    GMaterial base;
    GColor eta, k; /* the complex index, unitless (GCOLOR_UNITLESS) */
    GColor f_avg;  /* 2 * integral of F(mu) mu dmu, per sample: the smooth albedo, for ambient() */
    GColor ms;     /* F_ms / (pi (1 - E_avg)): the compensation lobe's colour */
    GMicrofacet mf;
    RoughAt surface; /* the rough surface of a constant roughness: mf, its albedo table e and ms */
    float e[GMICROFACET_ALBEDO_N];
    double e_avg;
    int smooth, anisotropic, compensate;
    int distribution;
    /* the rough surface's Fresnel reflectance tabulated (kit/fresnel.h), or NULL where it is evaluated exactly
     * (fresnel exact, a smooth surface, a model whose vectors are not plain samples) */
    GFresnelTable *ftab;
    /* a textured (isotropic) roughness: its values at the point, and the albedo tables and compensation colours of
     * CONDUCTOR_LEVELS roughnesses evenly over its range [level_lo, level_hi], interpolated between */
    GTexNumber rough;
    int nlevels;
    double level_lo, level_hi;
    float (*level_e)[GMICROFACET_ALBEDO_N];
    GColor *level_ms;
} Conductor;

/* The roughnesses tabulated over a textured roughness's range. */
#define CONDUCTOR_LEVELS 17

/* Room for the rough surface at a point of a textured roughness: its albedo table and compensation colour. */
typedef struct RoughBuf {
    RoughAt at;
    float e[GMICROFACET_ALBEDO_N];
    GColor ms;
} RoughBuf;

static void conductor_destroy(GMaterial *self)
{
    Conductor *c = (Conductor *)self;
    gcolor_free(&c->eta);
    gcolor_free(&c->k);
    gcolor_free(&c->f_avg);
    gcolor_free(&c->ms);
    for (int i = 0; c->level_ms && i < c->nlevels; i++)
        gcolor_free(&c->level_ms[i]);
    gmem_free(c->level_ms);
    gmem_free(c->level_e);
    gmaterial_fresnel_table_destroy(c->ftab);
    gtexparam_number_release(&c->rough);
    gmem_free(c);
}

/* The rough surface at sp into *a: the material's own (nothing copied), or for a textured roughness the distribution
 * of its value there with the tables interpolated between the two nearest levels (exactly a level's at a level), in
 * buf; the colour on sp's arena (the caller marks and releases it). */
static inline int rough_at(const Conductor *c, GSurfPoint *sp, RoughBuf *buf, const RoughAt **a)
{
    *a = &c->surface;
    if (!c->rough.gen)
        return G_OK;
    RoughAt *b = &buf->at;
    *a = b;
    double r = gtexparam_number_at(&c->rough, sp), alpha = gmicrofacet_alpha_from_roughness(r);
    b->mf = gmicrofacet_make(c->distribution, alpha, alpha);
    b->alpha2 = b->mf.alpha_x * b->mf.alpha_x;
    double x = c->nlevels > 1 ? (r - c->level_lo) / (c->level_hi - c->level_lo) * (c->nlevels - 1) : 0.0;
    x = x > 0.0 ? (x < c->nlevels - 1 ? x : c->nlevels - 1) : 0.0;
    int j = (int)x;
    double w = x - j;
    b->e = c->level_e[j];
    b->ms = &c->level_ms[j];
    if (w == 0.0 || j + 1 >= c->nlevels)
        return G_OK;
    for (int i = 0; i < GMICROFACET_ALBEDO_N; i++)
        buf->e[i] = (float)((1.0 - w) * c->level_e[j][i] + w * c->level_e[j + 1][i]);
    b->e = buf->e;
    if (!sp->scratch)
        return G_ERR_INVALID;
    int rc = gcolor_scratch(&buf->ms, c->base.model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_scale(&buf->ms, &c->level_ms[j], 1.0 - w);
    if (rc == G_OK)
        rc = gcolor_add_scaled(&buf->ms, &c->level_ms[j + 1], w);
    b->ms = &buf->ms;
    return rc;
}

/* The local frame at sp: about the shading normal n, its first tangent along dpdu for an anisotropic surface. */
static GFrame frame_at(const Conductor *c, const GSurfPoint *sp, GVec3 n)
{
    return c->anisotropic ? gframe_from_normal_tangent(n, sp->dpdu) : gframe_from_normal(n);
}

/* A pair's geometry on a rough surface: the single-scattering term (gmicrofacet_reflect_cos), the cosine of the facet
 * (in.h) and the two cosines with the shading normal. */
typedef struct PairGeometry {
    double single, cos_h, cos_i, cos_o;
} PairGeometry;

/* The geometry of the rough surface a for light from in towards out about the shading normal n, cos_in = in.n > 0.
 * An isotropic surface needs no frame: two more dot products (gmicrofacet_reflect_cos_pair, GGX's inline). 0 when out
 * is below n. */
static inline int rough_geometry(const Conductor *c, const RoughAt *a, const GSurfPoint *sp, GVec3 n, double cos_in,
                                 GVec3 in, GVec3 out, PairGeometry *g)
{
    if (!c->anisotropic) {
        GMicrofacetPair p = {cos_in, gvec3_dot(out, n), gvec3_dot(in, out)};
        if (!(p.cos_o > 0.0))
            return 0;
        g->single = a->mf.distribution == GMICROFACET_GGX ? gmicrofacet_ggx_reflect_cos_pair(a->alpha2, p)
                                                          : gmicrofacet_reflect_cos_pair(&a->mf, p);
        g->cos_h = gmicrofacet_pair_cos_h(p);
        g->cos_i = p.cos_i;
        g->cos_o = p.cos_o;
        return 1;
    }
    GFrame fr = frame_at(c, sp, n);
    GVec3 wi = gframe_to_local(&fr, in), wo = gframe_to_local(&fr, out);
    if (!(wi.z > 0.0) || !(wo.z > 0.0))
        return 0;
    g->single = gmicrofacet_reflect_cos(&a->mf, wi, wo);
    g->cos_h = gvec3_dot(wi, gvec3_normalize(gvec3_add(wi, wo)));
    g->cos_i = wi.z;
    g->cos_o = wo.z;
    return 1;
}

/* scale * f cos_in of the rough surface a into f from a pair's geometry: the cosines with the normal and the
 * facet's cosine, the single-scattering term; the Fresnel colour and the compensation's in one pass, times light's
 * samples when light is given (only with the Fresnel table, for f of the material's model: fused_light). */
__attribute__((always_inline)) static inline int rough_mix(const Conductor *c, const RoughAt *a, double cos_i,
                                                            double cos_o, double cos_h, double single, double scale,
                                                            const GColor *light, GColor *f)
{
    double multiple = 0.0;
    if (single < 1e-30) /* far outside a narrow lobe: below what a float keeps to its precision */
        single = 0.0;
    if (c->compensate)
        multiple = (1.0 - gmicrofacet_albedo_lerp(a->e, cos_o)) * (1.0 - gmicrofacet_albedo_lerp(a->e, cos_i)) * cos_i;
    if (c->ftab && f->model == c->base.model)
        return gmaterial_fresnel_table_mix(c->ftab, cos_h, single * scale, c->compensate ? a->ms : NULL,
                                           multiple * scale, light, f);
    if (light)
        return G_ERR_INVALID;
    return gmaterial_fresnel_conductor_mix(f, cos_h, &c->eta, &c->k, single * scale, c->compensate ? a->ms : NULL,
                                           multiple * scale);
}

/* f cos_in for white light (light NULL; or times light's samples, rough surfaces only: fused_light) into f at a pair
 * that reflects (cos_in = in.n > 0 about the shading normal n; a mirror pair for the smooth surface). */
static int value_at(const Conductor *c, GSurfPoint *sp, GVec3 n, double cos_in, GVec3 in, GVec3 out,
                    const GColor *light, GColor *f)
{
    if (c->smooth)
        return gmaterial_fresnel_conductor(f, cos_in, &c->eta, &c->k);
    RoughBuf buf;
    const RoughAt *a;
    PairGeometry g;
    GScratchMark mark = {0};
    if (c->rough.gen) {
        if (!sp->scratch)
            return G_ERR_INVALID;
        mark = gscratch_mark(sp->scratch);
    }
    int rc = rough_at(c, sp, &buf, &a);
    if (rc == G_OK && rough_geometry(c, a, sp, n, cos_in, in, out, &g))
        rc = rough_mix(c, a, g.cos_i, g.cos_o, g.cos_h, g.single, 1.0, light, f);
    else if (rc == G_OK)
        gcolor_black(f);
    if (c->rough.gen)
        gscratch_release(sp->scratch, mark);
    return rc;
}

/* The pair's cosine about the shading normal n, 0 where the conductor reflects nothing from in towards out:
 * gmaterial_cos_in's rule (both directions on the geometric normal's outer side, in above n) written inline, as the
 * rough surface's evaluation is. */
static inline double reflecting_cos(const Conductor *c, GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n)
{
    *n = gsurfpoint_normal(sp);
    if (!(gvec3_dot(out, sp->geometric_normal) > 0.0) || !(gvec3_dot(in, sp->geometric_normal) > 0.0))
        return 0.0;
    double cos_in = gvec3_dot(in, *n);
    return cos_in > 0.0 && (!c->smooth || gmaterial_is_mirror_pair(in, *n, out)) ? cos_in : 0.0;
}

/* The light's samples where the rough surface's table can multiply them in as it mixes (a vector of the model into
 * a colour of the model: what gcolor_mul would compute, in one pass), else NULL. */
static const GColor *fused_light(const Conductor *c, const GColor *illum, const GColor *result)
{
    const GColorModel *m = c->base.model;
    return c->ftab && illum->kind == GCOLOR_VECTOR && illum->model == m && result->model == m ? illum : NULL;
}

static int conductor_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                GColor *result)
{
    const Conductor *c = (const Conductor *)self;
    GVec3 n;
    double cos_in = reflecting_cos(c, sp, in, out, &n);
    if (cos_in <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    const GColor *light = fused_light(c, illum, result);
    if (light) /* sample i of result read from light's sample i alone: result may be illum */
        return value_at(c, sp, n, cos_in, in, out, light, result);
    if (result->v != illum->v) { /* the value straight into result, then times the light */
        int rc = value_at(c, sp, n, cos_in, in, out, NULL, result);
        return rc == G_OK ? gcolor_mul(result, result, illum) : rc;
    }
    if (!sp->scratch)
        return G_ERR_INVALID;
    GScratchMark mark = gscratch_mark(sp->scratch);
    GColor f;
    int rc = gcolor_scratch_uncleared(&f, self->model, sp->scratch);
    if (rc == G_OK)
        rc = value_at(c, sp, n, cos_in, in, out, NULL, &f);
    if (rc == G_OK)
        rc = gcolor_mul(result, &f, illum);
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int conductor_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    if (!((const Conductor *)self)->smooth)
        return 0;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int conductor_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const Conductor *)self)->f_avg, illum);
}

/* The probability of the compensation's cosine lobe for wo in the local frame. */
static double cosine_share(const Conductor *c, const RoughAt *a, GVec3 wo)
{
    return c->compensate ? 1.0 - gmicrofacet_albedo_at(a->e, wo.z) : 0.0;
}

static double rough_pdf(const Conductor *c, const RoughAt *a, GVec3 wi, GVec3 wo)
{
    double q = cosine_share(c, a, wo);
    return (1.0 - q) * gmicrofacet_pdf_reflect(&a->mf, wo, wi) + q * gfmax(wi.z, 0.0) / M_PI;
}

static int conductor_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                            double u2, GMaterialSample *s, GColor *weight)
{
    (void)rel_index;
    const Conductor *c = (const Conductor *)self;
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    GVec3 n = gsurfpoint_normal(sp);
    if (c->smooth) { /* one delta lobe, chosen with probability 1: weight = F */
        s->in = gvec3_reflect(gvec3_neg(out), n);
        s->pdf = 1.0;
        s->flags = GSAMPLE_REFLECT | GSAMPLE_DELTA;
        double cos_in = gmaterial_cos_in(sp, s->in, out, &n);
        if (cos_in <= 0.0) {
            gcolor_black(weight);
            return 1;
        }
        int rc = gmaterial_fresnel_conductor(weight, cos_in, &c->eta, &c->k);
        return rc ? rc : 1;
    }
    GFrame fr = frame_at(c, sp, n);
    GVec3 wo = gframe_to_local(&fr, out), wi;
    if (!(wo.z > 0.0))
        return 0;
    RoughBuf buf;
    const RoughAt *a;
    GScratchMark mark = {0};
    if (c->rough.gen && sp->scratch)
        mark = gscratch_mark(sp->scratch);
    int rc = rough_at(c, sp, &buf, &a);
    if (rc != G_OK) {
        if (c->rough.gen && sp->scratch)
            gscratch_release(sp->scratch, mark);
        return rc;
    }
    double q = cosine_share(c, a, wo);
    if (u1 < q) {
        u1 /= q;
        double r = sqrt(u1), phi = 2.0 * M_PI * u2;
        wi = gvec3(r * cos(phi), r * sin(phi), sqrt(gfmax(0.0, 1.0 - u1)));
    } else {
        u1 = (u1 - q) / (1.0 - q);
        GVec3 h = gmicrofacet_sample_visible(&a->mf, wo, u1 < 1.0 ? u1 : 0.0, u2);
        wi = gvec3_sub(gvec3_scale(h, 2.0 * gvec3_dot(wo, h)), wo);
    }
    int drawn = 0;
    if (wi.z > 0.0) { /* else reflected below the surface: nothing drawn */
        double pdf_mf, single = gmicrofacet_reflect_cos_pdf(&a->mf, wi, wo, &pdf_mf);
        s->in = gframe_to_world(&fr, wi);
        s->pdf = (1.0 - q) * pdf_mf + q * wi.z / M_PI;
        s->flags = GSAMPLE_REFLECT;
        drawn = s->pdf > 0.0;
        /* f cos_in / pdf as gmaterial_sample_weight gives it, from the geometry just computed: black where the
         * reflection is (an infinite density, or a direction the geometric normal or the shading normal refuses) */
        if (drawn && (!isfinite(s->pdf) || !gmaterial_sides_agree(sp, s->in, out, 0) || !(gvec3_dot(s->in, n) > 0.0)))
            gcolor_black(weight);
        else if (drawn) /* the facet's cosine from the pair's (gmicrofacet_pair_cos_h) */
            rc = rough_mix(c, a, wi.z, wo.z, gmicrofacet_pair_cos_h((GMicrofacetPair){wi.z, wo.z, gvec3_dot(wi, wo)}),
                           single, 1.0 / s->pdf, NULL, weight);
    }
    if (c->rough.gen && sp->scratch)
        gscratch_release(sp->scratch, mark);
    return rc != G_OK ? rc : drawn;
}

static double conductor_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Conductor *c = (const Conductor *)self;
    if (c->smooth || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    GVec3 n = gsurfpoint_normal(sp);
    GFrame fr = {0};
    if (c->anisotropic)
        fr = frame_at(c, sp, n);
    GVec3 wo = c->anisotropic ? gframe_to_local(&fr, out) : gvec3(0.0, 0.0, gvec3_dot(out, n));
    if (!(wo.z > 0.0))
        return 0.0;
    RoughBuf buf;
    const RoughAt *a;
    GScratchMark mark = {0};
    if (c->rough.gen && sp->scratch)
        mark = gscratch_mark(sp->scratch);
    double pdf = 0.0;
    if (rough_at(c, sp, &buf, &a) != G_OK)
        pdf = 0.0;
    else if (c->anisotropic)
        pdf = rough_pdf(c, a, gframe_to_local(&fr, in), wo);
    else { /* isotropic: the pair's cosines, no frame */
        GMicrofacetPair p = {gvec3_dot(in, n), wo.z, gvec3_dot(in, out)};
        double q = cosine_share(c, a, wo);
        pdf = (1.0 - q) * gmicrofacet_pdf_reflect_pair(&a->mf, p) + q * gfmax(p.cos_i, 0.0) / M_PI;
    }
    if (c->rough.gen && sp->scratch)
        gscratch_release(sp->scratch, mark);
    return pdf;
}

static int conductor_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)sp;
    return ((const Conductor *)self)->smooth;
}

static const GMaterialClass conductor_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "conductor",
    .description = "a metal: Fresnel of a complex index (measured or given), smooth or GGX / Beckmann rough",
    .destroy = conductor_destroy,
    .reflection = conductor_reflection,
    .reflection_dir = conductor_reflection_dir,
    .ambient = conductor_ambient,
    .sample = conductor_sample,
    .pdf = conductor_pdf,
    .is_delta = conductor_is_delta,
};

/* ---- construction ---- */

/* F_ms / (pi (1 - E_avg)) from F_avg, per sample (params: E_avg). */
static double ms_colour(double f_avg, double unused1, double unused2, const void *params)
{
    (void)unused1, (void)unused2;
    double e = *(const double *)params;
    double fms = f_avg * f_avg * e / (1.0 - f_avg * (1.0 - e));
    return e < 1.0 ? fms / (M_PI * (1.0 - e)) : 0.0;
}

/* f_avg and ms from eta, k and the albedo table. */
static int energy_terms(Conductor *c, GError *err)
{
    const GColorModel *m = c->base.model;
    GColor f = {0};
    int rc = gcolor_alloc(&c->f_avg, m);
    if (rc == G_OK)
        rc = gcolor_alloc(&c->ms, m);
    if (rc == G_OK)
        rc = gcolor_alloc(&f, m);
    enum { K = 64 }; /* midpoints in mu^2: 2 mu dmu = d(mu^2) */
    for (int j = 0; j < K && rc == G_OK; j++) {
        rc = gmaterial_fresnel_conductor(&f, sqrt((j + 0.5) / K), &c->eta, &c->k);
        if (rc == G_OK)
            rc = gcolor_add_scaled(&c->f_avg, &f, 1.0 / K);
    }
    gcolor_free(&f);
    if (rc == G_OK && !c->smooth) {
        gmicrofacet_albedo_table(&c->mf, c->e, &c->e_avg);
        rc = gcolor_map(&c->ms, ms_colour, &c->e_avg, &c->f_avg, NULL, NULL);
    }
    return rc == G_OK ? G_OK : gerror_set(err, rc, "conductor: cannot compute its albedo (%s)", gstatus_string(rc));
}

/* What a file gave. */
typedef struct ConductorSpec {
    GColorSpec *eta, *k;
    int metal;                     /* index into the metal table, or -1 */
    double roughness_u, roughness_v;
    int distribution, compensate;
    int exact_fresnel; /* 1: the rough surface's Fresnel evaluated exactly at each call, not tabulated */
    GTexNumber rough; /* a textured isotropic roughness (gen set; roughness_u and _v: its range's lower end) */
} ConductorSpec;

/* n and k into c's colours: the metal's table, or the two literals (gmaterial_complex_index_from_specs). */
static int index_colours(Conductor *c, const ConductorSpec *p, GError *err)
{
    const GColorModel *m = c->base.model;
    int rc = gcolor_alloc(&c->eta, m);
    if (rc == G_OK)
        rc = gcolor_alloc(&c->k, m);
    if (rc != G_OK)
        return gerror_set(err, rc, "conductor: out of memory");
    if (p->metal < 0) {
        GError why;
        rc = gmaterial_complex_index_from_specs(p->eta, p->k, &c->eta, &c->k, &why);
        return rc == G_OK ? G_OK : gerror_set_param(err, rc, why.param, "conductor: %s", why.message);
    }
    rc = gmetal_colors(p->metal, &c->eta, &c->k);
    return rc == G_OK ? G_OK : gerror_set(err, rc, "conductor: cannot express n and k in model '%s' (%s)",
                                          gcolormodel_name(m), gstatus_string(rc));
}

/* The albedo tables and compensation colours of CONDUCTOR_LEVELS roughnesses evenly over the textured roughness's
 * range (one when the range is a point), after energy_terms (f_avg). */
static int rough_levels(Conductor *c, const GTexNumber *rough, GError *err)
{
    gtexparam_number_bounds(rough, &c->level_lo, &c->level_hi);
    c->nlevels = c->level_hi > c->level_lo ? CONDUCTOR_LEVELS : 1;
    c->level_e = gmem_calloc((size_t)c->nlevels, sizeof *c->level_e);
    c->level_ms = gmem_calloc((size_t)c->nlevels, sizeof *c->level_ms);
    if (!c->level_e || !c->level_ms)
        return gerror_set(err, G_ERR_NOMEM, "conductor: out of memory");
    int rc = G_OK;
    for (int j = 0; j < c->nlevels && rc == G_OK; j++) {
        double r = c->nlevels > 1 ? c->level_lo + (c->level_hi - c->level_lo) * j / (c->nlevels - 1) : c->level_lo;
        if (j == c->nlevels - 1)
            r = c->level_hi; /* exactly the range's ends */
        double alpha = gmicrofacet_alpha_from_roughness(r), e_avg;
        GMicrofacet mf = gmicrofacet_make(c->distribution, alpha, alpha);
        gmicrofacet_albedo_table(&mf, c->level_e[j], &e_avg);
        rc = gcolor_alloc(&c->level_ms[j], c->base.model);
        if (rc == G_OK)
            rc = gcolor_map(&c->level_ms[j], ms_colour, &e_avg, &c->f_avg, NULL, NULL);
    }
    if (rc != G_OK)
        return gerror_set(err, rc, "conductor: cannot tabulate its textured roughness (%s)", gstatus_string(rc));
    gtexparam_number_copy(&c->rough, rough);
    if (gtexparam_number_reads_uv(rough))
        c->base.flags &= ~(unsigned)GMAT_NO_UV;
    return G_OK;
}

/* The rough surface's Fresnel table (Conductor.ftab) where the kit makes one (gmaterial_fresnel_table_create) and the
 * compensation's colour is a vector too; otherwise none: exact evaluation. */
static int fresnel_table(Conductor *c, GError *err)
{
    if (c->compensate && c->ms.kind != GCOLOR_VECTOR)
        return G_OK;
    int rc = gmaterial_fresnel_table_create(&c->eta, &c->k, &c->ftab);
    if (rc == G_OK || rc == G_ERR_UNSUPPORTED)
        return G_OK;
    return gerror_set(err, rc, "conductor: cannot tabulate its Fresnel term (%s)", gstatus_string(rc));
}

static int conductor_create(const GColorModel *model, const ConductorSpec *p, GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *m;
    int rc = gmaterial_new(&conductor_class, model, sizeof(Conductor), &m, err);
    if (rc != G_OK)
        return rc;
    Conductor *c = (Conductor *)m;
    double ax = gmicrofacet_alpha_from_roughness(p->roughness_u);
    double ay = gmicrofacet_alpha_from_roughness(p->roughness_v);
    c->smooth = !(ax >= GMICROFACET_ALPHA_MIN || ay >= GMICROFACET_ALPHA_MIN); /* both below it: the ideal mirror */
    c->mf = gmicrofacet_make(p->distribution, ax, ay);
    c->surface = (RoughAt){c->mf, c->mf.alpha_x * c->mf.alpha_x, c->e, &c->ms};
    c->anisotropic = !c->smooth && ax != ay;
    c->compensate = p->compensate && !c->smooth;
    c->distribution = p->distribution;
    rc = index_colours(c, p, err);
    if (rc == G_OK)
        rc = energy_terms(c, err);
    if (!c->anisotropic)
        m->flags |= GMAT_NO_UV; /* only an anisotropic surface reads its tangent dpdu (material.h) */
    m->flags |= GMAT_DIAGONAL;  /* f * illum: n and k are vectors, nothing re-radiates */
    m->flags |= GMAT_NO_REL_INDEX; /* its Fresnel term is of its own n and k, not of the relative index */
    if (rc == G_OK && p->rough.gen)
        rc = rough_levels(c, &p->rough, err);
    if (rc == G_OK && !c->smooth && !p->exact_fresnel)
        rc = fresnel_table(c, err);
    if (rc != G_OK) {
        conductor_destroy(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

/* ---- the text format ---- */

/* Checks a literal of n (positive: lo_open) or k (non-negative) at the parameter; refuses matrices and lines. */
static int check_index_spec(GReader *r, const GColorSpec *s, const char *param, int positive, int line, int col,
                            GError *err)
{
    const char *bound = positive ? "> 0" : ">= 0";
    if (s->form != GCOLORSPEC_RGB && s->form != GCOLORSPEC_NM)
        return greader_error_at(r, err, G_ERR_PARSE, line, col,
                                "conductor: %s must be an rgb triple or a spectrum (a unitless curve of the "
                                "wavelength)", param);
    int count = s->form == GCOLORSPEC_RGB ? 3 : GNM_COUNT;
    for (int i = 0; i < count; i++) {
        double v = (s->form == GCOLORSPEC_RGB ? s->rgb[i] : s->nm.v[i]) * s->scale;
        if (!isfinite(v) || (positive ? !(v > 0.0) : !(v >= 0.0)) || v > CONDUCTOR_INDEX_MAX)
            return greader_error_at(r, err, G_ERR_PARSE, line, col,
                                    "conductor: %s has the value %g %s %d (must be %s and <= %g)", param, v,
                                    s->form == GCOLORSPEC_RGB ? "in component" : "at", s->form == GCOLORSPEC_RGB ? i
                                    : GNM_MIN + i, bound, CONDUCTOR_INDEX_MAX);
    }
    return G_OK;
}

static int read_index_spec(GReader *r, const char *param, int positive, GColorSpec **out, GError *err)
{
    GToken first;
    int rc = greader_peek(r, &first, err);
    if (rc == G_OK) {
        gcolorspec_destroy(*out);
        *out = NULL;
        rc = greader_color_spec(r, out, err);
    }
    return rc == G_OK ? check_index_spec(r, *out, param, positive, first.line, first.col, err) : rc;
}

static int read_metal(GReader *r, int *metal, GError *err)
{
    GToken tok;
    char name[64];
    int rc = greader_peek(r, &tok, err);
    if (rc == G_OK)
        rc = greader_ident(r, name, sizeof name, err);
    if (rc != G_OK)
        return rc;
    *metal = gmetal_find(name);
    if (*metal >= 0)
        return G_OK;
    char names[1024];
    gmetal_names(names, sizeof names);
    return greader_error_at(r, err, G_ERR_PARSE, tok.line, tok.col, "conductor: unknown metal '%s' (known: %s)", name,
                            names);
}

/* `roughness R`: a number in [0, 1] or a generator whose range lies in [GMICROFACET_ALPHA_MIN, 1] (a rough surface
 * everywhere: whether the surface is an ideal mirror is decided at creation). */
static int read_roughness(GReader *r, GTexNumber *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK)
        rc = gtexparam_read_number(r, 0.0, 1.0, 0, "conductor", "roughness", NULL, out, err);
    double lo, hi;
    gtexparam_number_bounds(out, &lo, &hi);
    if (rc == G_OK && out->gen && lo < GMICROFACET_ALPHA_MIN)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "conductor: a textured roughness must stay >= %g, rough everywhere (the generator's "
                                "range starts at %g; whether the surface is an ideal mirror is decided at creation)",
                                GMICROFACET_ALPHA_MIN, lo);
    return rc;
}

/* conductor { eta COLOR k COLOR | metal NAME  roughness R | roughness_u R roughness_v R  distribution ggx|beckmann
 * compensate on|off  fresnel table|exact }: metal Cu, smooth, GGX, compensated, Fresnel tabulated when not given */
static int parse_conductor(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    ConductorSpec p = {NULL, NULL, -1, 0.0, 0.0, GMICROFACET_GGX, 1, 0, {0.0, NULL, 0.0, 0.0}};
    static const char *const distributions[] = {"ggx", "beckmann", NULL};
    static const char *const fresnel_modes[] = {"table", "exact", NULL};
    int have_metal = 0, have_r = 0, have_uv = 0, metal_line = 0, metal_col = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "eta") == 0)
            rc = read_index_spec(r, "eta", 1, &p.eta, err);
        else if (strcmp(key, "k") == 0)
            rc = read_index_spec(r, "k", 0, &p.k, err);
        else if (strcmp(key, "metal") == 0) {
            greader_position(r, &metal_line, &metal_col);
            rc = read_metal(r, &p.metal, err);
            have_metal = 1;
        } else if (strcmp(key, "roughness") == 0) {
            rc = read_roughness(r, &p.rough, err);
            p.roughness_u = p.roughness_v = p.rough.value;
            have_r = 1;
        } else if (strcmp(key, "roughness_u") == 0) {
            rc = gtexparam_read_constant(r, 0.0, 1.0, "conductor", "roughness_u", ROUGH_WHY, &p.roughness_u, err);
            have_uv = 1;
        } else if (strcmp(key, "roughness_v") == 0) {
            rc = gtexparam_read_constant(r, 0.0, 1.0, "conductor", "roughness_v", ROUGH_WHY, &p.roughness_v, err);
            have_uv = 1;
        } else if (strcmp(key, "distribution") == 0)
            rc = greader_choice(r, distributions, &p.distribution, err);
        else if (strcmp(key, "compensate") == 0)
            rc = greader_bool(r, &p.compensate, err);
        else if (strcmp(key, "fresnel") == 0)
            rc = greader_choice(r, fresnel_modes, &p.exact_fresnel, err);
        else
            rc = greader_unknown_param(r, "eta, k, metal, roughness, roughness_u, roughness_v, distribution, "
                                          "compensate, fresnel", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && have_metal && (p.eta || p.k))
        rc = greader_error_at(r, err, G_ERR_PARSE, metal_line, metal_col,
                              "conductor: metal and eta/k exclude each other (give one)");
    else if (rc == G_OK && !have_metal && (!p.eta) != (!p.k))
        rc = greader_error(r, err, "conductor: %s given without %s (give both, or a metal)", p.eta ? "eta" : "k",
                           p.eta ? "k" : "eta");
    else if (rc == G_OK && have_r && have_uv)
        rc = greader_error(r, err, "conductor: roughness and roughness_u/roughness_v exclude each other");
    if (rc == G_OK && !have_metal && !p.eta)
        p.metal = gmetal_find("Cu");
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = conductor_create(greader_colormodel(r), &p, &m, err)) == G_OK)
        *object = m;
    gcolorspec_destroy(p.eta);
    gcolorspec_destroy(p.k);
    gtexparam_number_release(&p.rough);
    return rc;
}

static const GParamInfo conductor_params[] = {
    {"eta", GPARAM_NAMED, "color", "none", "(0, 1000], an rgb triple or a spectrum",
     "n, the real part of the complex refractive index, per wavelength (a unitless colour); with k"},
    {"k", GPARAM_NAMED, "color", "none", "[0, 1000], an rgb triple or a spectrum",
     "k, the extinction coefficient (imaginary part of the index), per wavelength; with eta"},
    {"metal", GPARAM_NAMED, "choice", "Cu (without eta and k)", "a name of `gmat metals`",
     "measured n and k of a metal or compound (docs/reference/metals.md); excludes eta and k"},
    {"roughness", GPARAM_NAMED, "texnumber", "0 (smooth)", "[0, 1]; textured: a range within [0.001, 1]",
     "the microfacet width alpha (alpha = roughness); below 0.001 (both ways) an ideal mirror"},
    {"roughness_u", GPARAM_NAMED, "number", "0", "[0, 1]", "alpha along the surface's dP/du (anisotropic)"},
    {"roughness_v", GPARAM_NAMED, "number", "0", "[0, 1]", "alpha across it"},
    {"distribution", GPARAM_NAMED, "choice", "ggx", "ggx, beckmann", "the microfacet distribution"},
    {"compensate", GPARAM_NAMED, "bool", "on", "on, off",
     "give back the energy single scattering loses on a rough surface (Kulla and Conty 2017)"},
    {"fresnel", GPARAM_NAMED, "choice", "table", "table, exact",
     "a rough surface's Fresnel reflectance: table, per sample at 1025 facet angles made at creation and "
     "interpolated (within 1e-5 of exact for every metal of the table; 4 bytes per sample and angle), or exact at "
     "each evaluation; a smooth surface and a model whose values are not plain samples are always exact"},
    {NULL},
};

GENERIC_TYPE_PARAMS(conductor, GKIND_MATERIAL, &conductor_class, parse_conductor, NULL, conductor_params);
