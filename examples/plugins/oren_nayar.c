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
 * that loads the module. The material kit (generic/kit/material_kit.h) checks the reflectance, builds the instance
 * and places a complaint at the parameter it is about. */
#include <generic/kit/material_kit.h>
#include <generic/plugin.h>

#include <math.h>
#include <string.h>

typedef struct OrenNayar {
    GMaterialOneColor rho; /* first: the class's destroy is gmaterial_one_color_destroy */
    double a, b;
} OrenNayar;

static int on_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    const OrenNayar *m = (const OrenNayar *)self;
    GVec3 n;
    double ci = fmin(gmaterial_cos_in(sp, in, out, &n), 1.0), co = fmin(gvec3_dot(out, n), 1.0);
    if (ci <= 0.0 || co <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    /* cosine of the azimuth difference: the tangential parts of in and out */
    GVec3 ti = gvec3_madd(in, n, -ci), to = gvec3_madd(out, n, -co);
    double li = gvec3_length(ti), lo = gvec3_length(to);
    double cphi = li > 1e-12 && lo > 1e-12 ? gvec3_dot(ti, to) / (li * lo) : 0.0;
    double cos_alpha = fmin(ci, co), cos_beta = fmax(ci, co);
    double sin_alpha = sqrt(fmax(0.0, 1.0 - cos_alpha * cos_alpha));
    double tan_beta = sqrt(fmax(0.0, 1.0 - cos_beta * cos_beta)) / cos_beta;
    double f = (m->a + m->b * fmax(0.0, cphi) * sin_alpha * tan_beta) / M_PI;
    int rc = gcolor_mul(result, &m->rho.c, illum);
    return rc ? rc : gcolor_scale(result, result, f * ci);
}

static int on_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const OrenNayar *)self)->rho.c);
}

static const GMaterialClass oren_nayar_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "oren_nayar",
    .description = "Oren-Nayar rough diffuse reflector (plug-in)",
    .destroy = gmaterial_one_color_destroy,
    .reflection = on_reflection,
    .diffuse = on_diffuse, /* ambient: the default, diffuse * illum */
};

static int parse_oren_nayar(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor rho = {0};
    double sigma = 20.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "reflectance") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &rho, err);
        else if (strcmp(key, "sigma") == 0)
            rc = greader_number_in(r, 0.0, 90.0, &sigma, err);
        else
            rc = greader_unknown_param(r, "reflectance, sigma", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK)
        rc = gmaterial_param_default(r, 0.8, GCOLOR_REFLECTANCE, &rho, err);
    GMaterial *m = NULL;
    if (rc == G_OK)
        rc = gmaterial_one_color_create(&oren_nayar_class, greader_colormodel(r), sizeof(OrenNayar), &rho,
                                   GCOLOR_REFLECTANCE, 1.0, "reflectance", &m, err);
    gcolor_free(&rho);
    if (rc != G_OK)
        return rc;
    double s2 = (sigma * M_PI / 180.0) * (sigma * M_PI / 180.0);
    ((OrenNayar *)m)->a = 1.0 - 0.5 * s2 / (s2 + 0.33);
    ((OrenNayar *)m)->b = 0.45 * s2 / (s2 + 0.09);
    *object = m;
    return G_OK;
}

static const GParamInfo oren_nayar_params[] = {
    {"reflectance", GPARAM_NAMED, "color", "rgb 0.8 0.8 0.8", "[0, 1]", "the albedo rho"},
    {"sigma", GPARAM_NAMED, "number", "20", "[0, 90]", "the standard deviation of the facets' slope, in degrees"},
    {NULL},
};

GENERIC_TYPE_PARAMS(oren_nayar, GKIND_MATERIAL, &oren_nayar_class, parse_oren_nayar, NULL, oren_nayar_params);
GENERIC_MODULE(&gtype_oren_nayar);
