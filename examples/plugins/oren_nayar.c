/* oren_nayar.c - a run-time module adding the Oren-Nayar rough diffuse material (the qualitative model of
 * Oren and Nayar, "Generalization of Lambert's Reflectance Model", SIGGRAPH 1994):
 *
 *     f_r = rho / pi * (A + B * max(0, cos(phi_in - phi_out)) * sin(alpha) * tan(beta))
 *     A = 1 - 0.5 s^2 / (s^2 + 0.33),  B = 0.45 s^2 / (s^2 + 0.09),
 *     alpha = max(theta_in, theta_out), beta = min(theta_in, theta_out),
 *
 * with s the standard deviation of the facet slope angle (radians). s = 0 is Lambert's law.
 *
 * Text format:  material clay oren_nayar { reflectance rgb 0.6 0.4 0.3  sigma 20 }   (sigma in degrees)
 *
 * Built against the installed headers only (<generic/...>); the library's functions come from the program
 * that loads the module. */
#include <generic/plugin.h>
#include <generic/reader.h>

#include <math.h>
#include <string.h>

typedef struct OrenNayar {
    GMaterial base;
    GColor rho;
    double a, b;
} OrenNayar;

static void on_destroy(GMaterial *self)
{
    OrenNayar *m = (OrenNayar *)self;
    gcolor_free(&m->rho);
    gmem_free(m);
}

static int on_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    const OrenNayar *m = (const OrenNayar *)self;
    GVec3 n = gsurfpoint_normal(sp), g = sp->geometric_normal;
    double ci = gvec3_dot(in, n), co = gvec3_dot(out, n);
    if (ci <= 0.0 || co <= 0.0 || gvec3_dot(in, g) <= 0.0 || gvec3_dot(out, g) <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    ci = fmin(ci, 1.0);
    co = fmin(co, 1.0);
    /* cosine of the azimuth difference: the tangential parts of in and out */
    GVec3 ti = gvec3_madd(in, n, -ci), to = gvec3_madd(out, n, -co);
    double li = gvec3_length(ti), lo = gvec3_length(to);
    double cphi = li > 1e-12 && lo > 1e-12 ? gvec3_dot(ti, to) / (li * lo) : 0.0;
    double cos_alpha = fmin(ci, co), cos_beta = fmax(ci, co);
    double sin_alpha = sqrt(fmax(0.0, 1.0 - cos_alpha * cos_alpha));
    double tan_beta = sqrt(fmax(0.0, 1.0 - cos_beta * cos_beta)) / cos_beta;
    double f = (m->a + m->b * fmax(0.0, cphi) * sin_alpha * tan_beta) / M_PI;
    int rc = gcolor_mul(result, &m->rho, illum);
    return rc ? rc : gcolor_scale(result, result, f * ci);
}

static int on_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const OrenNayar *)self)->rho, illum);
}

static int on_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const OrenNayar *)self)->rho);
}

static const GMaterialClass oren_nayar_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "oren_nayar",
    .description = "Oren-Nayar rough diffuse reflector",
    .destroy = on_destroy,
    .reflection = on_reflection,
    .ambient = on_ambient,
    .diffuse = on_diffuse,
};

static int parse_oren_nayar(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor rho = {0};
    double sigma = 20.0;
    int rl = 0, rcol = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "reflectance") == 0) {
            greader_position(r, &rl, &rcol);
            rc = greader_color(r, GCOLOR_REFLECTANCE, &rho, err);
        } else if (strcmp(key, "sigma") == 0) {
            rc = greader_number_in(r, 0.0, 90.0, &sigma, err);
        } else {
            rc = greader_unknown_param(r, "reflectance, sigma", err);
        }
        if (rc < 0)
            break;
    }
    const GColorModel *model = greader_colormodel(r);
    if (rc == G_OK && !rho.v) {
        double grey[3] = {0.8, 0.8, 0.8};
        rc = gcolor_alloc(&rho, model) == G_OK && gcolor_from_rgb(&rho, grey, GCOLOR_REFLECTANCE) == G_OK
                 ? G_OK
                 : greader_error(r, err, "oren_nayar: out of memory");
    }
    if (rc == G_OK) {
        if (rho.kind != GCOLOR_VECTOR)
            rc = greader_error_at(r, err, G_ERR_INVALID, rl, rcol, "oren_nayar: reflectance must be a plain reflectance");
        for (int i = 0; rc == G_OK && i < model->nvalues; i++)
            if (!(rho.v[i] >= 0.0f && rho.v[i] <= 1.0f))
                rc = greader_error_at(r, err, G_ERR_INVALID, rl, rcol,
                                      "oren_nayar: reflectance value %g is outside [0, 1]", rho.v[i]);
    }
    OrenNayar *m = NULL;
    if (rc == G_OK && !(m = gmem_calloc(1, sizeof *m)))
        rc = greader_error(r, err, "oren_nayar: out of memory");
    if (rc == G_OK && (rc = gmaterial_init(&m->base, &oren_nayar_class, model, err)) != G_OK) {
        gmem_free(m);
        m = NULL;
    }
    if (rc != G_OK) {
        gcolor_free(&rho);
        return rc;
    }
    double s2 = (sigma * M_PI / 180.0) * (sigma * M_PI / 180.0);
    m->a = 1.0 - 0.5 * s2 / (s2 + 0.33);
    m->b = 0.45 * s2 / (s2 + 0.09);
    m->rho = rho; /* the storage moves into the material */
    *object = &m->base;
    return G_OK;
}

static void release(void *p) { gmaterial_unref(p); }

GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    static const GTypeInfo type = {GKIND_MATERIAL, "oren_nayar", &oren_nayar_class, parse_oren_nayar,
                                   "Oren-Nayar rough diffuse reflector (plug-in)", release};
    return api->add_type(api, &type, err);
}
