/* turbulence.c - the fbm (fractional Brownian motion) and turbulence (sum of |noise|) generators. */
#include "generic/plugin.h"
#include "noise.h"
#include "textures_builtin.h"

typedef struct Fractal {
    GGenerator base;
    GNoiseParams p;
} Fractal;

static double fbm_value(const GGenerator *self, GSurfPoint *sp)
{
    double v = 0.5 + 0.5 * gtexnoise_fbm(&((const Fractal *)self)->p, gtexnoise_coords(self, sp), NULL);
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

static int fbm_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    double v = 0.5 + 0.5 * gtexnoise_fbm(&((const Fractal *)self)->p, gtexnoise_coords(self, sp), &d);
    *grad = v < 0.0 || v > 1.0 ? gvec3(0, 0, 0) : gtexnoise_space_grad(self, gvec3_scale(d, 0.5));
    return G_OK;
}

static double turbulence_value(const GGenerator *self, GSurfPoint *sp)
{
    return gtexnoise_turbulence(&((const Fractal *)self)->p, gtexnoise_coords(self, sp), NULL);
}

static int turbulence_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    gtexnoise_turbulence(&((const Fractal *)self)->p, gtexnoise_coords(self, sp), &d);
    *grad = gtexnoise_space_grad(self, d);
    return G_OK;
}

const GGeneratorClass ggen_fbm_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "fbm",
    .description = "fractional Brownian motion: octaves of noise, in [0, 1]",
    .destroy = gtexgen_free,
    .value = fbm_value,
    .gradient = fbm_gradient,
};

const GGeneratorClass ggen_turbulence_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "turbulence",
    .description = "Perlin's turbulence: octaves of |noise|, in [0, 1]",
    .destroy = gtexgen_free,
    .value = turbulence_value,
    .gradient = turbulence_gradient,
};

static int make(const GGeneratorClass *cls, const GNoiseParams *p, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gtexnoise_params(cls->name, p, &q, err);
    if (rc != G_OK)
        return rc;
    GGenerator *gen;
    rc = gtexgen_new(cls, q.space, sizeof(Fractal), &gen, err);
    if (rc != G_OK)
        return rc;
    Fractal *f = (Fractal *)gen;
    f->p = q;
    *out = &f->base;
    return G_OK;
}

int ggen_fbm_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    return make(&ggen_fbm_class, p, out, err);
}

int ggen_turbulence_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    return make(&ggen_turbulence_class, p, out, err);
}

GENERIC_TYPE(fbm, GKIND_GENERATOR, &ggen_fbm_class, gtexparse_fbm, ggenerator_release);
GENERIC_TYPE(turbulence, GKIND_GENERATOR, &ggen_turbulence_class, gtexparse_turbulence, ggenerator_release);
