/* halfvector.c - a correct sampler whose pdf has an integrable singularity, for tests/scripts/check_gaps.sh.
 *   -DGGX   material "halfvector_ggx": a GGX microfacet reflector of roughness alpha 0.2 (Fresnel 1, Smith's
 *           height-correlated masking and shadowing) that draws the half vector h from D(h) cos(theta_h) and
 *           mirrors out about it; pdf(in) = D(h) cos(theta_h) / (4 |out.h|), whose 1/(out.h) peak at grazing
 *           incidence defeats a midpoint rule over the chi2 bins: gmat check must pass it all the same. */
#include <generic/plugin.h>
#include <generic/reader.h>

#include <math.h>

GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;

#define ALPHA 0.2

typedef struct HalfVector {
    GMaterial base;
} HalfVector;

static void halfvector_destroy(GMaterial *self) { gmem_free(self); }

/* The GGX distribution of normals about +z in the frame of n, at cos(theta_h) c. */
static double ggx_d(double c)
{
    if (c <= 0.0)
        return 0.0;
    double c2 = c * c, t = c2 * (ALPHA * ALPHA - 1.0) + 1.0;
    return ALPHA * ALPHA / (M_PI * t * t);
}

/* Smith's Lambda of GGX at cos(theta) c. */
static double ggx_lambda(double c)
{
    double t2 = (1.0 - c * c) / (c * c);
    return 0.5 * (sqrt(1.0 + ALPHA * ALPHA * t2) - 1.0);
}

static int halfvector_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                 GColor *result)
{
    (void)self;
    GVec3 n = gsurfpoint_normal(sp);
    double ci = gvec3_dot(in, n), co = gvec3_dot(out, n);
    if (ci <= 0.0 || co <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    GVec3 h = gvec3_normalize(gvec3_add(in, out));
    double g2 = 1.0 / (1.0 + ggx_lambda(ci) + ggx_lambda(co));
    double f = ggx_d(gvec3_dot(h, n)) * g2 / (4.0 * ci * co);
    return gcolor_scale(result, illum, f * ci);
}

static double halfvector_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)rel_index;
    GVec3 n = gsurfpoint_normal(sp), sum = gvec3_add(in, out);
    double len = gvec3_length(sum);
    if (!(len > 0.0))
        return 0.0;
    GVec3 h = gvec3_scale(sum, 1.0 / len);
    double ch = gvec3_dot(h, n), oh = gvec3_dot(out, h);
    if (ch <= 0.0 || oh <= 0.0)
        return 0.0;
    return ggx_d(ch) * ch / (4.0 * oh);
}

static int halfvector_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                             double u2, GMaterialSample *s, GColor *weight)
{
    GVec3 n = gsurfpoint_normal(sp), t, b;
    goptics_frame(n, &t, &b);
    /* tan^2(theta_h) = alpha^2 u1 / (1 - u1): the inverse of D(h) cos(theta_h)'s distribution */
    double ct = 1.0 / sqrt(1.0 + ALPHA * ALPHA * u1 / (1.0 - u1)), st = sqrt(fmax(0.0, 1.0 - ct * ct));
    double phi = 2.0 * M_PI * u2;
    GVec3 h = gvec3_add(gvec3_scale(n, ct), gvec3_add(gvec3_scale(t, st * cos(phi)), gvec3_scale(b, st * sin(phi))));
    double oh = gvec3_dot(out, h);
    if (oh <= 0.0)
        return 0;
    s->in = gvec3_sub(gvec3_scale(h, 2.0 * oh), out);
    s->flags = GSAMPLE_REFLECT;
    s->pdf = halfvector_pdf(self, sp, s->in, out, rel_index);
    if (!(s->pdf > 0.0) || !isfinite(s->pdf))
        return 0;
    int rc = gcolor_fill(weight, 1.0);
    if (rc == G_OK)
        rc = halfvector_reflection(self, sp, s->in, weight, out, weight);
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / s->pdf);
    return rc ? rc : 1;
}

static const GMaterialClass halfvector_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "halfvector_ggx",
    .description = "GGX reflector sampled by half vectors from D(h) cos(theta_h) (tests)",
    .destroy = halfvector_destroy,
    .reflection = halfvector_reflection,
    .sample = halfvector_sample,
    .pdf = halfvector_pdf,
};

static int parse_halfvector(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0)
        if ((rc = greader_unknown_param(r, "(none)", err)) < 0)
            break;
    if (rc < 0)
        return rc;
    GMaterial *m = gmem_calloc(1, sizeof(HalfVector));
    if (!m)
        return greader_error(r, err, "halfvector_ggx: out of memory");
    if ((rc = gmaterial_init(m, &halfvector_class, greader_colormodel(r), err)) != G_OK) {
        gmem_free(m);
        return rc;
    }
    m->flags |= GMAT_NO_UV | GMAT_DIAGONAL;
    *object = m;
    return G_OK;
}

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    const GTypeInfo type = {GKIND_MATERIAL, "halfvector_ggx", &halfvector_class, parse_halfvector,
                            "GGX reflector sampled by half vectors (tests)", NULL, NULL};
    return api->add_type(api, &type, err);
}
