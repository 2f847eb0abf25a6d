/* dielectric.c - a dielectric interface: unpolarised Fresnel reflection and refraction, total internal reflection,
 * Beer-Lambert absorption inside; smooth (ideal rays), or rough (Walter et al. 2007 on the microfacet kit, with an
 * energy compensation of the multiple scattering it leaves out).
 *
 * A textured roughness (isotropic, a generator whose range lies in [GMICROFACET_ALPHA_MIN, 1], kit/texparam.h): the
 * distribution of its value at each point, and the compensation's albedo tables at DIELECTRIC_LEVELS roughnesses
 * evenly over the range, the compensation interpolated between the two nearest (exactly a level's at a level, as
 * conductor.c does). The index stays constant: it is the medium's (refraction_index), which the renderer reads
 * where a ray enters and keeps on its stack of media until it leaves. */
#include "generic/kit/dispersion.h"
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/microfacet_dielectric.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

/* Why an anisotropic roughness stays constant (gtexparam_read_constant). */
#define ROUGH_WHY "the anisotropic microfacet distribution and its albedo tables, made at creation"

/* Why the index stays constant (gtexparam_refuse_generator). */
#define INDEX_WHY "it is the medium's index, which a renderer reads where a ray enters and keeps until the ray leaves"

/* The roughnesses whose compensation tables a textured roughness tabulates over its range (each table costs about
 * 1.5 million evaluations: gmicrofacet_dielectric_albedo_init). */
#define DIELECTRIC_LEVELS 5

typedef struct Dielectric {
    GMaterial base;
    GDispersion disp;
    GColor index;         /* n(lambda) in the material's model */
    GColor transmittance; /* exp(-a): what one unit of length lets through */
    GColor tint;
    int absorbs, tinted;
    int rough, anisotropic; /* microfacet widths (rough); different along dpdu and dpdv (anisotropic) */
    GMicrofacet mf;
    GMicrofacetDielectricAlbedo *albedo; /* single-scattering albedos of the compensation (NULL: uncompensated) */
    /* a textured roughness: its value at the point; the compensation's tables (NULL: uncompensated) at nlevels
     * roughnesses evenly over [level_lo, level_hi] */
    GTexNumber tex_rough;
    int distribution, nlevels;
    double level_lo, level_hi;
    GMicrofacetDielectricAlbedo *level_albedo;
    GMaterialOnce made; /* the compensation's tables are filled on first use (tables_make) */
} Dielectric;

/* The rough interface at one point: the distribution and the compensation's tables a0, a1 with the weight w of a1. */
typedef struct RoughAt {
    GMicrofacet mf;
    const GMicrofacetDielectricAlbedo *a0, *a1;
    double w;
} RoughAt;

/* ---- the material ---- */

static void dielectric_destroy(GMaterial *self)
{
    Dielectric *d = (Dielectric *)self;
    gcolor_free(&d->index);
    gcolor_free(&d->transmittance);
    gcolor_free(&d->tint);
    gmem_free(d->albedo);
    gmem_free(d->level_albedo);
    gtexparam_number_release(&d->tex_rough);
    gmem_free(d);
}

static double eta_of(GSurfPoint *sp, const GColor *rel_index)
{
    return rel_index ? gsurfpoint_index_of(sp, rel_index) : gsurfpoint_relative_index(sp);
}

/* ---- the rough interface: Walter et al. 2007 in the shading frame (kit/microfacet_dielectric.h) ---- */

/* The shading frame at sp: the shading normal and, for anisotropic widths, dpdu as the first tangent. */
static GFrame rough_frame(const Dielectric *d, GSurfPoint *sp)
{
    GVec3 n = gsurfpoint_normal(sp);
    return d->anisotropic ? gframe_from_normal_tangent(n, sp->dpdu) : gframe_from_normal(n);
}

/* The rough interface at sp: the material's own, or for a textured roughness the distribution of its value there and
 * the two nearest levels' tables (exactly one level's at a level). */
static int tables_make(void *dielectric);

static RoughAt rough_at(const Dielectric *d, GSurfPoint *sp)
{
    if (d->albedo) /* (filling tables cannot fail) */
        gmaterial_once(&((Dielectric *)d)->made, tables_make, (void *)d);
    RoughAt a = {d->mf, d->albedo, d->albedo, 0.0};
    if (!d->tex_rough.gen)
        return a;
    double r = gtexparam_number_at(&d->tex_rough, sp), alpha = gmicrofacet_alpha_from_roughness(r);
    a.mf = gmicrofacet_make(d->distribution, alpha, alpha);
    double x = d->nlevels > 1 ? (r - d->level_lo) / (d->level_hi - d->level_lo) * (d->nlevels - 1) : 0.0;
    x = x > 0.0 ? (x < d->nlevels - 1 ? x : d->nlevels - 1) : 0.0;
    int j = (int)x;
    a.a0 = a.a1 = d->level_albedo ? &d->level_albedo[j] : NULL;
    if (a.a0 && j + 1 < d->nlevels && x > j) {
        a.a1 = &d->level_albedo[j + 1];
        a.w = x - j;
    }
    return a;
}

/* The energy compensation of the refraction: (1 - R) / T of the single-scattering albedos, so that the reflection
 * (single scattering, reciprocal) and the refraction together keep all the light; at most COMPENSATION_MAX (where the
 * refraction has almost no lobe to carry the light back in: near and past the critical angle from inside); 1 when
 * off. */
#define COMPENSATION_MAX 2.0
static double table_compensation(const GMicrofacetDielectricAlbedo *albedo, double cos_o, double eta)
{
    if (!albedo)
        return 1.0;
    double r, t;
    gmicrofacet_dielectric_albedo(albedo, cos_o, eta, &r, &t);
    if (!(t > 0.0) || !(r < 1.0))
        return 1.0;
    double k = (1.0 - r) / t;
    return k < 1.0 ? 1.0 : k > COMPENSATION_MAX ? COMPENSATION_MAX : k;
}

/* The compensation at a point: its table's, or interpolated between two levels' (linear in the roughness). */
static double compensation(const RoughAt *a, double cos_o, double eta)
{
    double k = table_compensation(a->a0, cos_o, eta);
    return a->w == 0.0 ? k : (1.0 - a->w) * k + a->w * table_compensation(a->a1, cos_o, eta);
}

/* An index-matched interface is none: the light goes straight on, whatever the roughness. */
static int index_matched(double eta) { return fabs(eta - 1.0) <= 1e-5; }

static int rough_reflection(const Dielectric *d, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    GFrame f = rough_frame(d, sp);
    GVec3 wo = gframe_to_local(&f, out), wi = gframe_to_local(&f, in);
    double eta = gsurfpoint_relative_index(sp);
    if (wo.z <= 0.0 || wi.z <= 0.0 || !gmaterial_sides_agree(sp, in, out, 0)) {
        gcolor_black(result);
        return G_OK;
    }
    RoughAt a = rough_at(d, sp);
    double v = gmicrofacet_dielectric_reflect(&a.mf, wi, wo, eta);
    int rc = gcolor_scale(result, illum, v);
    if (rc == G_OK && d->tinted)
        rc = gcolor_mul(result, &d->tint, result);
    return rc;
}

static int rough_refraction(const Dielectric *d, GSurfPoint *sp, GVec3 in, const GColor *illum, double eta,
                            GVec3 out, GColor *result)
{
    GFrame f = rough_frame(d, sp);
    GVec3 wo = gframe_to_local(&f, out), wi = gframe_to_local(&f, in);
    if (wo.z <= 0.0 || wi.z >= 0.0 || !gmaterial_sides_agree(sp, in, out, 1)) {
        gcolor_black(result);
        return G_OK;
    }
    if (index_matched(eta)) /* straight on, all of it */
        return goptics_is_refraction_pair(gvec3_neg(out), f.n, 1.0, in) ? gcolor_copy(result, illum)
                                                                       : (gcolor_black(result), G_OK);
    RoughAt a = rough_at(d, sp);
    double v = gmicrofacet_dielectric_refract(&a.mf, wi, wo, eta) * compensation(&a, wo.z, eta);
    return gcolor_scale(result, illum, v);
}

static int rough_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double eta,
                        double u1, double u2, GMaterialSample *s, GColor *weight)
{
    const Dielectric *d = (const Dielectric *)self;
    GFrame f = rough_frame(d, sp);
    GVec3 wo = gframe_to_local(&f, out), wi;
    if (wo.z <= 0.0)
        return 0;
    int rc;
    if (index_matched(eta)) {
        s->in = gvec3_neg(out);
        s->pdf = 1.0;
        s->flags = GSAMPLE_TRANSMIT | GSAMPLE_DELTA;
        rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 1, 1.0, weight);
        return rc ? rc : 1;
    }
    RoughAt a = rough_at(d, sp);
    int k = gmicrofacet_dielectric_sample(&a.mf, wo, eta, u1, u2, &wi);
    if (!k)
        return 0;
    s->in = gframe_to_world(&f, wi);
    s->pdf = gmicrofacet_dielectric_pdf(&a.mf, wi, wo, eta);
    if (!(s->pdf > 0.0))
        return 0;
    s->flags = k == 1 ? GSAMPLE_REFLECT : GSAMPLE_TRANSMIT;
    rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, k == 2, s->pdf, weight);
    return rc ? rc : 1;
}

static double rough_pdf(const Dielectric *d, GSurfPoint *sp, GVec3 in, GVec3 out, double eta)
{
    if (index_matched(eta))
        return 0.0;
    GFrame f = rough_frame(d, sp);
    RoughAt a = rough_at(d, sp);
    return gmicrofacet_dielectric_pdf(&a.mf, gframe_to_local(&f, in), gframe_to_local(&f, out), eta);
}

/* ---- the methods: the rough interface where it is rough, else the smooth one's ideal rays ---- */

/* Both methods pass on nothing for a pair on the wrong sides of the geometric surface (gmaterial_sides_agree): about a
 * normal a bump tilts, the mirror or refracted ray may point back across the surface (into the body, or out of it),
 * where passing it on leaked light through the surface (gtrace traced the reflected ray inside the body in the
 * outside medium). Mirror and phong do the same through gmaterial_cos_in. */
static int dielectric_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                 GColor *result)
{
    const Dielectric *d = (const Dielectric *)self;
    if (d->rough)
        return rough_reflection(d, sp, in, illum, out, result);
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
    const Dielectric *d = (const Dielectric *)self;
    if (d->rough)
        return rough_refraction(d, sp, in, illum, eta_of(sp, rel_index), out, result);
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
    if (((const Dielectric *)self)->rough) /* no ideal ray */
        return 0;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int dielectric_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                     GVec3 *dir)
{
    if (((const Dielectric *)self)->rough) { /* no ideal ray, but where the index matches: straight on */
        if (!index_matched(eta_of(sp, rel_index)))
            return 0;
        *dir = view;
        return 1;
    }
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
    if (((const Dielectric *)self)->rough)
        return rough_sample(self, sp, out, rel_index, eta_of(sp, rel_index), u1, u2, s, weight);
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
    const Dielectric *d = (const Dielectric *)self;
    return d->rough ? rough_pdf(d, sp, in, out, eta_of(sp, rel_index)) : 0.0;
}

static int dielectric_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    return ((const Dielectric *)self)->rough ? index_matched(gsurfpoint_relative_index(sp)) : 1;
}

static const GMaterialClass dielectric_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "dielectric",
    .description = "dielectric: Fresnel reflection and refraction, smooth or rough, dispersion, Beer-Lambert "
                   "absorption",
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

/* The largest relative index the compensation's tables cover: the material's in vacuum (n and 1 / n over the
 * wavelengths), with a margin. */
static double table_eta_max(const Dielectric *d)
{
    double hi = 1.0;
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm++) {
        double n = gdispersion_index(&d->disp, nm);
        hi = fmax(hi, fmax(n, 1.0 / n));
    }
    return 1.05 * hi;
}

/* The roughness: checked ([0, 1]), the distribution, and the albedo table of the compensation over the relative
 * indices the material meets in vacuum (n and 1 / n over the wavelengths, with a margin). */
static int rough_setup(Dielectric *d, const GDielectricRoughness *p, GError *err)
{
    if (!p)
        return G_OK;
    const double r[2] = {p->roughness_u, p->roughness_v};
    static const char *const names[2] = {"roughness_u", "roughness_v"};
    for (int i = 0; i < 2; i++)
        if (!(r[i] >= 0.0 && r[i] <= 1.0))
            return gerror_set_param(err, G_ERR_INVALID, names[i], "dielectric: %s is %g (must be in [0, 1])",
                                    names[i], r[i]);
    if (p->distribution != GMICROFACET_GGX && p->distribution != GMICROFACET_BECKMANN)
        return gerror_set_param(err, G_ERR_INVALID, "distribution", "dielectric: unknown distribution %d",
                                p->distribution);
    double ax = gmicrofacet_alpha_from_roughness(r[0]), ay = gmicrofacet_alpha_from_roughness(r[1]);
    if (!(ax >= GMICROFACET_ALPHA_MIN || ay >= GMICROFACET_ALPHA_MIN))
        return G_OK; /* smooth */
    d->rough = 1;
    d->anisotropic = ax != ay;
    d->mf = gmicrofacet_make(p->distribution, ax, ay);
    d->distribution = p->distribution;
    if (p->uncompensated)
        return G_OK;
    if (!(d->albedo = gmem_alloc(sizeof *d->albedo)))
        return gerror_set(err, G_ERR_NOMEM, "dielectric: out of memory");
    return G_OK;
}

/* Room for the compensation's tables at DIELECTRIC_LEVELS roughnesses evenly over a textured roughness's range (one
 * when it is a point; tables_make fills them). */
static int rough_levels(Dielectric *d, const GTexNumber *rough, GError *err)
{
    gtexparam_number_bounds(rough, &d->level_lo, &d->level_hi);
    d->nlevels = d->level_hi > d->level_lo ? DIELECTRIC_LEVELS : 1;
    if (d->albedo) {
        if (!(d->level_albedo = gmem_calloc((size_t)d->nlevels, sizeof *d->level_albedo)))
            return gerror_set(err, G_ERR_NOMEM, "dielectric: out of memory");
    }
    gtexparam_number_copy(&d->tex_rough, rough);
    return G_OK;
}

/* The compensation's tables: the material's own (at the textured range's lower end when textured), then the other
 * levels, exactly the range's upper end at the last: the dielectric's work on first use (gmaterial_once). */
static int tables_make(void *dielectric)
{
    Dielectric *d = dielectric;
    gmicrofacet_dielectric_albedo_init(d->albedo, &d->mf, table_eta_max(d));
    if (d->level_albedo)
        d->level_albedo[0] = *d->albedo;
    for (int j = 1; d->level_albedo && j < d->nlevels; j++) {
        double r = j == d->nlevels - 1 ? d->level_hi : d->level_lo + (d->level_hi - d->level_lo) * j /
                                                                      (d->nlevels - 1);
        double alpha = gmicrofacet_alpha_from_roughness(r);
        GMicrofacet mf = gmicrofacet_make(d->distribution, alpha, alpha);
        gmicrofacet_dielectric_albedo_init(&d->level_albedo[j], &mf, table_eta_max(d));
    }
    return G_OK;
}

static int dielectric_create(const GColorModel *model, const GDielectricParams *params,
                             const GDielectricRoughness *rough, const GTexNumber *tex_rough, GMaterial **out,
                             GError *err);

int gdielectric_create(const GColorModel *model, const GDielectricParams *params, GMaterial **out, GError *err)
{
    return dielectric_create(model, params, NULL, NULL, out, err);
}

int gdielectric_create_rough(const GColorModel *model, const GDielectricParams *params,
                             const GDielectricRoughness *rough, GMaterial **out, GError *err)
{
    return dielectric_create(model, params, rough, NULL, out, err);
}

/* The dielectric of params and rough; tex_rough (NULL, or a generator whose range rough's widths start: rough
 * everywhere, isotropic) makes its roughness vary over the surface. */
static int dielectric_create(const GColorModel *model, const GDielectricParams *params,
                             const GDielectricRoughness *rough, const GTexNumber *tex_rough, GMaterial **out,
                             GError *err)
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
    rc = rough_setup(d, rough, err);
    if (rc == G_OK && tex_rough && tex_rough->gen)
        rc = d->rough && !d->anisotropic ? rough_levels(d, tex_rough, err)
                                         : gerror_set_param(err, G_ERR_INVALID, "roughness", "dielectric: a textured "
                                                            "roughness must be isotropic and rough everywhere");
    if (rc != G_OK) {
        dielectric_destroy(&d->base);
        return rc;
    }
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
    if (!d->anisotropic && !gtexparam_number_reads_uv(&d->tex_rough)) /* no (u, v) read (material.h) */
        d->base.flags |= GMAT_NO_UV;
    if (!d->tinted || d->tint.kind == GCOLOR_VECTOR) /* F * illum (* tint), (1 - F) * illum: sample by sample */
        d->base.flags |= GMAT_DIAGONAL;
    d->base.flags |= GMAT_CONSTANT_INDEX; /* its index is a colour made once, read at no point */
    if (!d->absorbs) /* dielectric_absorption copies the light */
        d->base.flags |= GMAT_CLEAR;
    *out = &d->base;
    return G_OK;
}

/* ---- the text format ---- */

/* `roughness R`: a number in [0, 1] or a generator whose range lies in [GMICROFACET_ALPHA_MIN, 1] (rough
 * everywhere: whether the interface is smooth is decided at creation). */
static int read_roughness(GReader *r, GTexNumber *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK)
        rc = gtexparam_read_number(r, 0.0, 1.0, 0, "dielectric", "roughness", NULL, out, err);
    double lo, hi;
    gtexparam_number_bounds(out, &lo, &hi);
    if (rc == G_OK && out->gen && lo < GMICROFACET_ALPHA_MIN)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "dielectric: a textured roughness must stay >= %g, rough everywhere (the generator's "
                                "range starts at %g; whether the interface is smooth is decided at creation)",
                                GMICROFACET_ALPHA_MIN, lo);
    return rc;
}

/* dielectric { index N | cauchy A B [C] | sellmeier B1 B2 B3 C1 C2 C3 | glass NAME  glass NAME  absorption COLOR
 *              tint COLOR  roughness R | roughness_u R roughness_v R  distribution ggx|beckmann  compensate on|off }:
 * index 1.5, clear, untinted, smooth when not given; GGX, compensated */
static int parse_dielectric(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor absorption = {0}, tint = {0};
    GDielectricParams p = {gdispersion_constant(1.5), NULL, NULL};
    GDielectricRoughness rough = {0.0, 0.0, GMICROFACET_GGX, 0};
    GTexNumber tex_rough = gtexparam_number_const(0.0);
    const char *key;
    int rc, compensate = 1, have_r = 0, have_uv = 0;
    static const char *const distributions[] = {"ggx", "beckmann", NULL};
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "roughness") == 0) {
            if ((rc = read_roughness(r, &tex_rough, err)) == G_OK)
                rough.roughness_u = rough.roughness_v = tex_rough.value;
            have_r = 1;
        } else if (strcmp(key, "roughness_u") == 0) {
            rc = gtexparam_read_constant(r, 0.0, 1.0, "dielectric", "roughness_u", ROUGH_WHY, &rough.roughness_u, err);
            have_uv = 1;
        } else if (strcmp(key, "roughness_v") == 0) {
            rc = gtexparam_read_constant(r, 0.0, 1.0, "dielectric", "roughness_v", ROUGH_WHY, &rough.roughness_v, err);
            have_uv = 1;
        }
        else if (strcmp(key, "distribution") == 0)
            rc = greader_choice(r, distributions, &rough.distribution, err);
        else if (strcmp(key, "compensate") == 0)
            rc = greader_bool(r, &compensate, err);
        else if (strcmp(key, "index") == 0) {
            if ((rc = gtexparam_refuse_generator(r, "dielectric", "index", INDEX_WHY, err)) == G_OK)
                rc = gdispersion_read(r, &p.index, err);
        }
        else if (strcmp(key, "glass") == 0)
            rc = gdispersion_read_glass(r, &p.index, err);
        else if (strcmp(key, "absorption") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &absorption, err);
        else if (strcmp(key, "tint") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &tint, err);
        else
            rc = greader_unknown_param(r, "index, glass, absorption, tint, roughness, roughness_u, roughness_v, "
                                                 "distribution, compensate", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && have_r && have_uv && tex_rough.gen)
        rc = greader_error(r, err, "dielectric: a textured roughness and roughness_u/roughness_v exclude each other");
    GMaterial *m = NULL;
    if (rc == G_OK) {
        p.absorption = absorption.v ? &absorption : NULL;
        p.tint = tint.v ? &tint : NULL;
        rough.uncompensated = !compensate;
        if ((rc = dielectric_create(greader_colormodel(r), &p, &rough, &tex_rough, &m, err)) == G_OK)
            *object = m;
    }
    gcolor_free(&absorption);
    gcolor_free(&tint);
    gtexparam_number_release(&tex_rough);
    return rc;
}

static const GParamInfo dielectric_params[] = {
    {"index", GPARAM_NAMED, "formula", "1.5",
     "N in [0.01, 100]; cauchy A B [C]; sellmeier B1 B2 B3 C1 C2 C3; glass NAME",
     "the refraction index: a constant, Cauchy's or Sellmeier's formula of the wavelength in micrometres "
     "(dispersion), or a named glass (`gmat glasses` lists them)"},
    {"glass", GPARAM_NAMED, "choice", "none", "a name `gmat glasses` lists",
     "the same as `index glass NAME`: BK7, BAF10, F5, F10, F11, FK51A, LASF9, SF5, SF10, SF11, fused_silica, "
     "water, diamond"},
    {"absorption", GPARAM_NAMED, "color", "none (clear)", ">= 0, not a matrix",
     "the absorption coefficient per unit length inside (Beer-Lambert: exp(-a d) of the light passes)"},
    {"tint", GPARAM_NAMED, "color", "none (untinted)", "[0, 1]", "multiplies the light the surface reflects"},
    {"roughness", GPARAM_NAMED, "texnumber", "0 (smooth)", "[0, 1]; textured: a range within [0.001, 1]",
     "the microfacet width alpha (the same along both tangents): rough reflection and refraction (Walter et al. "
     "2007); below 0.001 smooth"},
    {"roughness_u", GPARAM_NAMED, "number", "0", "[0, 1]", "the width along dpdu (anisotropic)"},
    {"roughness_v", GPARAM_NAMED, "number", "0", "[0, 1]", "the width along dpdv (anisotropic)"},
    {"distribution", GPARAM_NAMED, "choice", "ggx", "ggx, beckmann", "the distribution of the microfacet normals"},
    {"compensate", GPARAM_NAMED, "bool", "on", "on, off",
     "divide the rough lobes by the single-scattering albedo: no light lost to multiple scattering"},
    {NULL},
};

GENERIC_TYPE_PARAMS(dielectric, GKIND_MATERIAL, &dielectric_class, parse_dielectric, NULL, dielectric_params);
