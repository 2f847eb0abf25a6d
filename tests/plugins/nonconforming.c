/* nonconforming.c - modules that break one conformance property on purpose, for tests/scripts/conformance.sh
 * (gmat check and gcolor check must report them as failing, naming the property). Built once per variant by the
 * test plug-in table of tests/build.mk:
 *   -DGAIN       material "gain_lambert": f_r = 1.5 / pi, a Lambertian surface reflecting 1.5 times the light
 *                (albedo 1.5; reciprocal, finite);
 *   -DSKEWED     material "skewed_lambert": f_r = (0.25 + 0.5 cos^2(theta_in)) / pi, which depends on the
 *                incident direction only (albedo 0.25..0.75, not reciprocal);
 *   -DMISDRAWN   material "misdrawn_lambert": a Lambertian of albedo 0.8 whose pdf says cos / pi (and whose
 *                weights are reflection / that pdf) but whose sample() draws uniformly over the hemisphere: only
 *                the chi2 test of gmat check sees it;
 *   -DMISFLAGGED material "misflagged_lambert": a Lambertian of albedo 0.5 with an emission slot that glows (0.1
 *                of white everywhere) whose instances set GMAT_NO_EMISSION after gmaterial_init all the same, so
 *                renderers never see the glow: only the no-emission check of gmat check sees it;
 *   -DMISOPAQUE  material "misopaque_lambert": a Lambertian of albedo 0.5 whose opaque slot says 0 (it would let
 *                shadow rays through) while its instances set GMAT_OPAQUE: only the opaque-flag check sees it;
 *   -DMISNORMAL  material "misnormal_lambert": a Lambertian of albedo 0.5 whose normal slot tilts the normal 30
 *                degrees (as a bump would) while its instances set GMAT_GEOMETRIC_NORMAL, so renderers never see
 *                the tilt: only the geometric-normal check sees it;
 *   -DMISDIFFUSE material "misdiffuse_lambert": a Lambertian of albedo 0.5 whose diffuse slot says 0.8 while its
 *                instances set GMAT_LAMBERTIAN, so a renderer that reflects its lights through diffuse() shows it
 *                0.8 bright: only the lambertian check sees it;
 *   -DMISUV      material "misuv_lambert": a Lambertian whose albedo is 0.25 + 0.5 u (it reads the surface's u)
 *                while its instances set GMAT_NO_UV, so renderers give it u = 0: only the no-uv check sees it;
 *   -DMISDIAG    material "misdiag_lambert": a grey Lambertian of albedo 0.5 that reflects, in every sample, the
 *                mean of the light's samples (it moves light between samples, energy kept: a one-sample light's
 *                power leaves spread over all of them) while its instances set GMAT_DIAGONAL, so a renderer
 *                that weighs a ray by its pass-on of white gives it the light's colour: only the diagonal check
 *                sees it;
 *   -DMISIDEAL   material "misideal_lambert": a Lambertian of albedo 0.5 whose reflection_dir slot gives the mirror
 *                direction (an ideal ray a Whitted tracer would follow) while its instances set GMAT_NO_IDEAL, so
 *                renderers never ask it: only the no-ideal check sees it;
 *   -DMISRELINDEX material "misrelindex_lambert": a Lambertian of albedo 0.5 times the point's relative index
 *                (gsurfpoint_relative_index: 1 from vacuum onto it, as it has no index of its own) while its
 *                instances set GMAT_NO_REL_INDEX, so a renderer hands it no index: only the no-rel-index check sees
 *                it;
 *   -DMISCONSTINDEX material "misconstindex_lambert": a Lambertian of albedo 0.5 whose refraction index is
 *                1.4 + 0.1 u (1.4 for no point) while its instances set GMAT_CONSTANT_INDEX, so a renderer would keep
 *                one relative index for every point: only the constant-index check sees it;
 *   -DMISCLEAR   material "misclear_lambert": a Lambertian of albedo 0.5 that as a medium absorbs, exp(-0.1 length)
 *                of the light passing, while its instances set GMAT_CLEAR, so a renderer would skip the absorption:
 *                only the clear check sees it;
 *   -DGAIN_MIRROR material "gain_mirror": a mirror whose ideal ray passes on 1.2 times the light (albedo 1.2 on
 *                any surface, bumped or not);
 *   -DMISBENT    material "misbent_glass": clear glass of index 1.5 whose refraction_dir refracts about the
 *                geometric normal while its reflection and refraction use the shading normal: right on a flat
 *                surface, under a bump node only the snell check sees it;
 *   -DLEAKY      material "leaky_mirror": a mirror of reflectance 0.9 whose reflection asks only the shading
 *                normal, so that about a bumped normal it reflects light arriving from inside the body (the
 *                dielectric's error before it asked the geometric side): under a bump node only the weight check
 *                sees it (the default sampling draws that ray with the light it passes on);
 *   (these three for tests/scripts/bump_ideal_conformance.sh)
 *   -DBAD_BANDS  colour model "bad_bands": the built-in rgb model with two wavelength bands whose masks are
 *                both white, so the bands do not partition a value;
 *   -DBAD_ADD    colour model "bad_add": the built-in rgb model whose add returns 1.01 a + b, so
 *                a + black != a. */
#include <generic/plugin.h>
#include <generic/reader.h>

#include <math.h>

GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;

/* The material variants' entry: no parameters (any one given is refused at its place); a zeroed instance of `size`
 * bytes, the GMaterial header first, of class cls in the reader's colour model. */
__attribute__((unused)) static int new_bare(GReader *r, const GMaterialClass *cls, size_t size, const char *name,
                                            GMaterial **out, GError *err)
{
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0)
        if ((rc = greader_unknown_param(r, "(none)", err)) < 0)
            break;
    if (rc < 0)
        return rc;
    GMaterial *m = gmem_calloc(1, size);
    if (!m)
        return greader_error(r, err, "%s: out of memory", name);
    if ((rc = gmaterial_init(m, cls, greader_colormodel(r), err)) != G_OK) {
        gmem_free(m);
        return rc;
    }
    *out = m;
    return G_OK;
}

/* Registers a material variant: its name, class and entry (released by the material kind's default, unref). */
__attribute__((unused)) static int add_material(GModuleApi *api, const char *name, const GMaterialClass *cls,
                                                GParseFn parse, GError *err)
{
    const GTypeInfo type = {GKIND_MATERIAL, name, cls, parse, "breaks a conformance property on purpose (tests)",
                            NULL, NULL};
    return api->add_type(api, &type, err);
}

#if defined(GAIN) || defined(SKEWED) || defined(MISDRAWN) || defined(MISFLAGGED) || defined(MISOPAQUE) ||              \
    defined(MISNORMAL) || defined(MISDIFFUSE) || defined(MISUV) || defined(MISDIAG) || defined(MISIDEAL) ||           \
    defined(MISRELINDEX) || defined(MISCONSTINDEX) || defined(MISCLEAR)
typedef struct Flat {
    GMaterial base;
} Flat;

static void flat_destroy(GMaterial *self) { gmem_free(self); }

#ifdef MISDIAG
/* The deliberate error: the mean of the light's samples in every sample (a grey response to any light), not the
 * light sample by sample, times f_r * cos; the mean, not gcolor_brightness, so that a one-sample light's power
 * leaving over all samples stays f_r's albedo (0.5) and only the diagonal check fails. Reads the samples as plain
 * floats, as the built-in models keep them. */
static int grey_response(GColor *result, const GColor *illum, double f)
{
    const GColorModel *m = illum->model;
    double sum = 0.0;
    for (int j = 0; j < m->nvalues; j++)
        sum += illum->v[j];
    return gcolor_fill(result, f * sum / m->nvalues);
}
#endif

static int flat_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                           GColor *result)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp);
    double ci = gvec3_dot(in, n), co = gvec3_dot(out, n);
    if (ci <= 0.0 || co <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
#if defined(GAIN)
    double f = 1.5 / M_PI;
#elif defined(MISDRAWN)
    double f = 0.8 / M_PI;
#elif defined(MISFLAGGED) || defined(MISOPAQUE) || defined(MISNORMAL) || defined(MISDIFFUSE) || defined(MISDIAG) ||    \
    defined(MISIDEAL) || defined(MISCONSTINDEX) || defined(MISCLEAR)
    double f = 0.5 / M_PI;
#elif defined(MISUV)
    double f = (0.25 + 0.5 * fmin(1.0, fmax(0.0, sp->u))) / M_PI; /* reads u: GMAT_NO_UV is wrong */
#elif defined(MISRELINDEX)
    double f = 0.5 * gsurfpoint_relative_index(sp) / M_PI; /* reads the index: GMAT_NO_REL_INDEX is wrong */
#else
    double f = (0.25 + 0.5 * ci * ci) / M_PI;
#endif
#ifdef MISDIAG
    return grey_response(result, illum, f * ci);
#else
    return gcolor_scale(result, illum, f * ci);
#endif
}

#if defined(GAIN)
#define FLAT_NAME "gain_lambert"
#elif defined(MISDRAWN)
#define FLAT_NAME "misdrawn_lambert"
#elif defined(MISFLAGGED)
#define FLAT_NAME "misflagged_lambert"
#elif defined(MISOPAQUE)
#define FLAT_NAME "misopaque_lambert"
#elif defined(MISNORMAL)
#define FLAT_NAME "misnormal_lambert"
#elif defined(MISDIFFUSE)
#define FLAT_NAME "misdiffuse_lambert"
#elif defined(MISUV)
#define FLAT_NAME "misuv_lambert"
#elif defined(MISDIAG)
#define FLAT_NAME "misdiag_lambert"
#elif defined(MISIDEAL)
#define FLAT_NAME "misideal_lambert"
#elif defined(MISRELINDEX)
#define FLAT_NAME "misrelindex_lambert"
#elif defined(MISCONSTINDEX)
#define FLAT_NAME "misconstindex_lambert"
#elif defined(MISCLEAR)
#define FLAT_NAME "misclear_lambert"
#else
#define FLAT_NAME "skewed_lambert"
#endif

#ifdef MISDRAWN
static double flat_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)out, (void)rel_index;
    double c = gvec3_dot(in, gsurfpoint_normal(sp));
    return c > 0.0 ? c / M_PI : 0.0;
}

/* The deliberate error: uniform over the hemisphere, not cosine-distributed as flat_pdf says. */
static int flat_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                       double u2, GMaterialSample *s, GColor *weight)
{
    s->in = goptics_sample_hemisphere(gsurfpoint_normal(sp), u1, u2);
    s->pdf = flat_pdf(self, sp, s->in, out, rel_index);
    s->flags = GSAMPLE_REFLECT;
    if (!(s->pdf > 0.0))
        return 0;
    int rc = gcolor_fill(weight, 1.0);
    if (rc == G_OK)
        rc = gmaterial_reflection(self, sp, s->in, weight, out, weight);
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / s->pdf);
    return rc ? rc : 1;
}
#endif

#ifdef MISCONSTINDEX
/* An index that follows u; the instances are flagged GMAT_CONSTANT_INDEX all the same (the error). */
static int flat_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)self;
    return gcolor_fill(result, 1.4 + (sp ? 0.1 * fmin(1.0, fmax(0.0, sp->u)) : 0.0));
}
#endif

#ifdef MISCLEAR
/* Beer-Lambert absorption of coefficient 0.1 in every sample; the instances are flagged GMAT_CLEAR all the same (the
 * error). */
static int flat_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    (void)self, (void)sp;
    return gcolor_scale(result, illum, exp(-0.1 * length));
}
#endif

#ifdef MISFLAGGED
/* A faint glow that gmaterial_emission never shows: the instances are flagged GMAT_NO_EMISSION (the error). */
static int flat_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    (void)self, (void)sp, (void)out;
    return gcolor_fill(result, 0.1);
}
#endif

#ifdef MISOPAQUE
/* Transparent by its own slot; the instances are flagged GMAT_OPAQUE all the same (the error). */
static int flat_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 0;
}
#endif

#ifdef MISNORMAL
/* The geometric normal tilted 30 degrees about a tangent; the instances are flagged GMAT_GEOMETRIC_NORMAL all the
 * same (the error). */
static int flat_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    (void)self;
    GVec3 g = sp->geometric_normal, t, b;
    goptics_frame(g, &t, &b);
    *n = gvec3_normalize(gvec3_add(gvec3_scale(g, cos(M_PI / 6)), gvec3_scale(t, sin(M_PI / 6))));
    return G_OK;
}
#endif

#ifdef MISDIFFUSE
/* A diffuse colour brighter than the reflection's 0.5; the instances are flagged GMAT_LAMBERTIAN all the same (the
 * error). */
static int flat_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)self, (void)sp;
    return gcolor_fill(result, 0.8);
}
#endif

#ifdef MISIDEAL
/* The mirror direction of the view about the shading normal; the instances are flagged GMAT_NO_IDEAL all the same
 * (the error). */
static int flat_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp);
    *dir = gvec3_sub(view, gvec3_scale(n, 2.0 * gvec3_dot(view, n)));
    return 1;
}
#endif

static const GMaterialClass flat_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = FLAT_NAME,
    .description = "breaks a conformance property on purpose (tests)",
    .destroy = flat_destroy,
    .reflection = flat_reflection,
#ifdef MISDRAWN
    .sample = flat_sample,
    .pdf = flat_pdf,
#endif
#ifdef MISFLAGGED
    .emission = flat_emission,
#endif
#ifdef MISOPAQUE
    .opaque = flat_opaque,
#endif
#ifdef MISNORMAL
    .normal = flat_normal,
#endif
#ifdef MISDIFFUSE
    .diffuse = flat_diffuse,
#endif
#ifdef MISIDEAL
    .reflection_dir = flat_reflection_dir,
#endif
#ifdef MISCONSTINDEX
    .refraction_index = flat_refraction_index,
#endif
#ifdef MISCLEAR
    .absorption = flat_absorption,
#endif
};

static int parse_flat(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *base = NULL;
    int rc = new_bare(r, &flat_class, sizeof(Flat), FLAT_NAME, &base, err);
    if (rc != G_OK)
        return rc;
    Flat *m = (Flat *)base;
#ifdef MISFLAGGED
    m->base.flags |= GMAT_NO_EMISSION; /* the deliberate error: the class's emission is not black */
#endif
#ifdef MISOPAQUE
    m->base.flags |= GMAT_OPAQUE; /* the deliberate error: the class's opaque slot says 0 */
#endif
#ifdef MISNORMAL
    m->base.flags |= GMAT_GEOMETRIC_NORMAL; /* the deliberate error: the class's normal slot tilts the normal */
#endif
#ifdef MISDIFFUSE
    m->base.flags |= GMAT_LAMBERTIAN; /* the deliberate error: reflection is 0.5 / pi, diffuse says 0.8 */
#endif
#ifdef MISUV
    m->base.flags |= GMAT_NO_UV; /* the deliberate error: the class's reflection reads u */
#endif
#ifdef MISIDEAL
    m->base.flags |= GMAT_NO_IDEAL; /* the deliberate error: the class's reflection_dir gives a ray */
#endif
#ifdef MISRELINDEX
    m->base.flags |= GMAT_NO_REL_INDEX; /* the deliberate error: the class's reflection reads the relative index */
#endif
#ifdef MISCONSTINDEX
    m->base.flags |= GMAT_CONSTANT_INDEX; /* the deliberate error: the class's refraction_index follows u */
#endif
#ifdef MISCLEAR
    m->base.flags |= GMAT_CLEAR; /* the deliberate error: the class's absorption takes exp(-0.1 length) */
#endif
#ifdef MISDIAG
    m->base.flags |= GMAT_DIAGONAL; /* the deliberate error: the class's reflection mixes the light's samples */
#endif
    *object = &m->base;
    return G_OK;
}

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    return add_material(api, FLAT_NAME, &flat_class, parse_flat, err);
}
#endif

#if defined(GAIN_MIRROR) || defined(MISBENT) || defined(LEAKY)
/* An ideal reflector (and for misbent_glass refractor), wrong in one way each. */
typedef struct Ideal {
    GMaterial base;
} Ideal;

#if defined(GAIN_MIRROR)
#define IDEAL_NAME "gain_mirror"
#define IDEAL_RHO 1.2 /* the deliberate error: more light than arrives */
#elif defined(LEAKY)
#define IDEAL_NAME "leaky_mirror"
#define IDEAL_RHO 0.9
#else
#define IDEAL_NAME "misbent_glass"
#define IDEAL_INDEX 1.5
#endif

static void ideal_destroy(GMaterial *self) { gmem_free(self); }

/* in and out on the incident side of the geometric normal, where one interface can reflect (gmaterial_cos_in). */
static int incident_side(const GSurfPoint *sp, GVec3 in, GVec3 out)
{
#ifdef LEAKY
    (void)sp, (void)in, (void)out;
    return 1; /* the deliberate error: light from inside the body is reflected too */
#else
    return gvec3_dot(in, sp->geometric_normal) > 0.0 && gvec3_dot(out, sp->geometric_normal) > 0.0;
#endif
}

static int ideal_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (co <= 0.0 || !incident_side(sp, in, out) || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
#ifdef IDEAL_INDEX
    return gcolor_scale(result, illum, goptics_fresnel(co, gsurfpoint_relative_index(sp)));
#else
    return gcolor_scale(result, illum, IDEAL_RHO);
#endif
}

static int ideal_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

#ifdef IDEAL_INDEX
static double eta_of(GSurfPoint *sp, const GColor *rel_index)
{
    return rel_index ? gsurfpoint_index_of(sp, rel_index) : gsurfpoint_relative_index(sp);
}

static int glass_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                            const GColor *rel_index, GVec3 out, GColor *result)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp), ng = sp->geometric_normal;
    double co = gvec3_dot(out, n), eta = eta_of(sp, rel_index);
    if (co <= 0.0 || gvec3_dot(out, ng) <= 0.0 || gvec3_dot(in, ng) >= 0.0 ||
        !goptics_is_refraction_pair(gvec3_neg(out), n, eta, in)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_scale(result, illum, 1.0 - goptics_fresnel(co, eta));
}

/* The deliberate error: about the geometric normal, where reflection and refraction take the shading one. */
static int glass_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                GVec3 *dir)
{
    (void)self;
    return goptics_refract(view, sp->geometric_normal, eta_of(sp, rel_index), dir);
}

static int glass_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)self, (void)sp;
    return gcolor_fill(result, IDEAL_INDEX);
}

static int glass_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 0;
}
#endif

static const GMaterialClass ideal_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = IDEAL_NAME,
    .description = "breaks a conformance property on purpose (tests)",
    .destroy = ideal_destroy,
    .reflection = ideal_reflection,
    .reflection_dir = ideal_reflection_dir,
#ifdef IDEAL_INDEX
    .refraction = glass_refraction,
    .refraction_dir = glass_refraction_dir,
    .refraction_index = glass_refraction_index,
    .opaque = glass_opaque,
#endif
};

static int parse_ideal(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *base = NULL;
    int rc = new_bare(r, &ideal_class, sizeof(Ideal), IDEAL_NAME, &base, err);
    if (rc == G_OK)
        *object = base;
    return rc;
}

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    return add_material(api, IDEAL_NAME, &ideal_class, parse_ideal, err);
}
#endif

#if defined(BAD_ADD) || defined(BAD_BANDS)
#include <generic/registry.h>

/* The built-in rgb model's class, copied at init with one deliberate error; its other slots are rgb's. */
static GColorModelClass derived;
static const GColorModelClass *rgb;

#ifdef BAD_ADD
#define DERIVED_NAME "bad_add"
#define DERIVED_SUMMARY "rgb with a wrong add: a + b = 1.01 a + b (tests)"
static int wrong_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    float v[16]; /* out may alias a or b: 1.01 a goes to storage of its own */
    if (m->capacity > 16)
        return G_ERR_INVALID;
    GColor scaled = *out;
    scaled.v = v;
    scaled.capacity = 16;
    int rc = rgb->scale(m, &scaled, a, 1.01);
    return rc ? rc : rgb->add(m, out, &scaled, b);
}
#else
#define DERIVED_NAME "bad_bands"
#define DERIVED_SUMMARY "rgb with two overlapping wavelength bands (tests)"
static int two_bands(const GColorModel *m)
{
    (void)m;
    return 2;
}

/* both masks white: the bands do not partition a value */
static int white_mask(const GColorModel *m, int band, GColor *out)
{
    (void)band;
    rgb->black(m, out);
    for (int i = 0; i < m->nvalues; i++)
        out->v[i] = 1.0f;
    return G_OK;
}
#endif

static void release(void *p) { gcolormodel_destroy(p); }

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    const GTypeInfo *builtin = gregistry_find(GKIND_COLORMODEL, "rgb");
    if (!builtin)
        return G_ERR_NOTFOUND;
    rgb = builtin->vtable;
    derived = *rgb;
    derived.name = DERIVED_NAME;
    derived.description = DERIVED_SUMMARY;
#ifdef BAD_ADD
    derived.add = wrong_add;
    derived.band_count = NULL; /* one band: the band check adds too, and must not see the error */
    derived.band_mask = NULL;
    derived.band_value = NULL;
#else
    derived.band_count = two_bands;
    derived.band_mask = white_mask;
#endif
    static const GTypeInfo type = {GKIND_COLORMODEL, DERIVED_NAME, &derived, NULL, DERIVED_SUMMARY, release, NULL};
    return api->add_type(api, &type, err);
}
#endif
