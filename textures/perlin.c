/* perlin.c - the perlin generator: improved Perlin noise mapped to [0, 1], with its analytic gradient:
 *
 *   generator NAME perlin { space object|world|uv  frequency F  seed N }
 */
#include <generic/generators.h>
#include <generic/kit/noise.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>


typedef struct Perlin {
    GGenerator base;
    GNoiseParams p;
} Perlin;

static double perlin_value(const GGenerator *self, GSurfPoint *sp)
{
    const Perlin *n = (const Perlin *)self;
    GVec3 x = gvec3_scale(ggenerator_coords(self, sp), n->p.frequency);
    return gnoise_perlin3(n->p.seed, x.x, x.y, x.z, NULL);
}

static int perlin_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Perlin *n = (const Perlin *)self;
    GVec3 x = gvec3_scale(ggenerator_coords(self, sp), n->p.frequency);
    gnoise_perlin3(n->p.seed, x.x, x.y, x.z, grad);
    *grad = gvec3_scale(*grad, n->p.frequency);
    if (self->space == GGENERATOR_SPACE_UV)
        grad->z = 0.0;
    return G_OK;
}

static const GGeneratorClass perlin_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "perlin",
    .description = "improved Perlin noise (2002) in [0, 1]",
    .destroy = ggenerator_free,
    .value = perlin_value,
    .gradient = perlin_gradient,
};

int ggenerator_perlin_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gnoise_params("perlin", p, &q, err);
    if (rc != G_OK)
        return rc;
    GGenerator *gen;
    rc = ggenerator_new(&perlin_class, q.space, sizeof(Perlin), &gen, err);
    if (rc != G_OK)
        return rc;
    Perlin *n = (Perlin *)gen;
    n->p = q;
    *out = &n->base;
    return G_OK;
}

static int parse_perlin(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GNoiseParams p;
    int rc = gtexparse_noise(r, &p, err);
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_perlin_create(&p, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

/* gtexparse_noise reads every noise parameter; perlin is one octave and uses the first three. */
static const GParamInfo perlin_params[] = {
    GTEXPARSE_NOISE_BASE_PARAMS,
    {"octaves", GPARAM_NAMED, "integer", "4", "[1, 16]", "read and ignored: perlin is one octave"},
    {"lacunarity", GPARAM_NAMED, "number", "2", "[1e-3, 1e3]", "read and ignored"},
    {"gain", GPARAM_NAMED, "number", "0.5", "[1e-6, 1e3]", "read and ignored"},
    {NULL},
};

GENERIC_TYPE_PARAMS(perlin, GKIND_GENERATOR, &perlin_class, parse_perlin, ggenerator_release, perlin_params);
