/* turbulence.c - the fbm (fractional Brownian motion) and turbulence (sum of |noise|) generators:
 *
 *   generator NAME fbm        { space object|world|uv  frequency F  seed N  octaves N  lacunarity L  gain G }
 *   generator NAME turbulence { the same }
 */
#include <generic/generators.h>
#include <generic/kit/noise.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>


typedef struct Fractal {
    GGenerator base;
    GNoiseParams p;
} Fractal;

static double fbm_value(const GGenerator *self, GSurfPoint *sp)
{
    double v = 0.5 + 0.5 * gnoise_fbm(&((const Fractal *)self)->p, ggenerator_coords(self, sp), NULL);
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

static int fbm_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    double v = 0.5 + 0.5 * gnoise_fbm(&((const Fractal *)self)->p, ggenerator_coords(self, sp), &d);
    *grad = v < 0.0 || v > 1.0 ? gvec3(0, 0, 0) : ggenerator_space_gradient(self, gvec3_scale(d, 0.5));
    return G_OK;
}

static double turbulence_value(const GGenerator *self, GSurfPoint *sp)
{
    return gnoise_turbulence(&((const Fractal *)self)->p, ggenerator_coords(self, sp), NULL);
}

static int turbulence_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    gnoise_turbulence(&((const Fractal *)self)->p, ggenerator_coords(self, sp), &d);
    *grad = ggenerator_space_gradient(self, d);
    return G_OK;
}

static const GGeneratorClass fbm_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "fbm",
    .description = "fractional Brownian motion: octaves of noise, in [0, 1]",
    .destroy = ggenerator_free,
    .value = fbm_value,
    .gradient = fbm_gradient,
};

static const GGeneratorClass turbulence_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "turbulence",
    .description = "Perlin's turbulence: octaves of |noise|, in [0, 1]",
    .destroy = ggenerator_free,
    .value = turbulence_value,
    .gradient = turbulence_gradient,
};

static int make(const GGeneratorClass *cls, const GNoiseParams *p, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gnoise_params(cls->name, p, &q, err);
    if (rc != G_OK)
        return rc;
    GGenerator *gen;
    rc = ggenerator_new(cls, q.space, sizeof(Fractal), &gen, err);
    if (rc != G_OK)
        return rc;
    Fractal *f = (Fractal *)gen;
    f->p = q;
    *out = &f->base;
    return G_OK;
}

int ggenerator_fbm_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    return make(&fbm_class, p, out, err);
}

int ggenerator_turbulence_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    return make(&turbulence_class, p, out, err);
}

/* Both take the noise parameters only; the vtable says which is made. */
static int parse_fractal(GReader *r, const void *vtable, void **object, GError *err)
{
    GNoiseParams p;
    int rc = gtexparse_noise(r, &p, err);
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = make(vtable, &p, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo fractal_params[] = {
    GTEXPARSE_NOISE_BASE_PARAMS,
    GTEXPARSE_NOISE_OCTAVE_PARAMS,
    {NULL},
};

GENERIC_TYPE_PARAMS(fbm, GKIND_GENERATOR, &fbm_class, parse_fractal, ggenerator_release, fractal_params);
GENERIC_TYPE_PARAMS(turbulence, GKIND_GENERATOR, &turbulence_class, parse_fractal, ggenerator_release, fractal_params);
