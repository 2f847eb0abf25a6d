/* marble.c - the marble generator: sine veins across x displaced by Perlin's turbulence:
 *
 *   generator NAME marble { NOISE  stripes S  turbulence T }
 *
 * NOISE: the noise parameters (space, frequency, seed, octaves, lacunarity, gain; generic/kit/texture_parse.h). */
#include <generic/generators.h>
#include <generic/kit/noise.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Marble {
    GGenerator base;
    GNoiseParams p;
    double stripes, turbulence;
} Marble;

/* The phase 2 pi (stripes x + turbulence T) and, with grad, its gradient. */
static double phase(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Marble *m = (const Marble *)self;
    GVec3 x = ggenerator_coords(self, sp), d = gvec3(0, 0, 0);
    double s = m->stripes * x.x;
    if (m->turbulence != 0.0)
        s += m->turbulence * gnoise_turbulence(&m->p, x, grad ? &d : NULL);
    if (grad)
        *grad = gvec3_scale(gvec3(m->stripes + m->turbulence * d.x, m->turbulence * d.y, m->turbulence * d.z),
                            2.0 * M_PI);
    return 2.0 * M_PI * s;
}

static double marble_value(const GGenerator *self, GSurfPoint *sp) { return 0.5 + 0.5 * sin(phase(self, sp, NULL)); }

static int marble_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    double ph = phase(self, sp, &d);
    *grad = ggenerator_space_gradient(self, gvec3_scale(d, 0.5 * cos(ph)));
    return G_OK;
}

static const GGeneratorClass marble_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "marble",
    .description = "sine veins across x displaced by turbulence, in [0, 1]",
    .destroy = ggenerator_free,
    .value = marble_value,
    .gradient = marble_gradient,
};

int ggenerator_marble_create(const GNoiseParams *p, double stripes, double turbulence, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gnoise_params("marble", p, &q, err);
    if (rc != G_OK)
        return rc;
    if (!isfinite(stripes) || !isfinite(turbulence))
        return gerror_set(err, G_ERR_INVALID, "marble: stripes and turbulence must be finite");
    GGenerator *gen;
    rc = ggenerator_new(&marble_class, q.space, sizeof(Marble), &gen, err);
    if (rc != G_OK)
        return rc;
    Marble *m = (Marble *)gen;
    m->p = q;
    m->stripes = stripes;
    m->turbulence = turbulence;
    *out = &m->base;
    return G_OK;
}

static int parse_marble(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GNoiseParams p;
    memset(&p, 0, sizeof p);
    double stripes = 1.0, turbulence = 2.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = gtexparse_noise_param(r, key, &p, err);
        if (rc == 0) {
            if (strcmp(key, "stripes") == 0)
                rc = greader_number(r, &stripes, err);
            else if (strcmp(key, "turbulence") == 0)
                rc = greader_number(r, &turbulence, err);
            else
                rc = greader_unknown_param(r, GTEXPARSE_NOISE_KEYS ", stripes, turbulence", err);
        }
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_marble_create(&p, stripes, turbulence, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo marble_params[] = {
    GTEXPARSE_NOISE_BASE_PARAMS,
    GTEXPARSE_NOISE_OCTAVE_PARAMS,
    {"stripes", GPARAM_NAMED, "number", "1", "finite",
     "veins per unit along x: the value is 0.5 + 0.5 sin(2 pi (stripes x + turbulence N)), N Perlin's turbulence"},
    {"turbulence", GPARAM_NAMED, "number", "2", "finite", "how far the turbulence N displaces the veins"},
    {NULL},
};

GENERIC_TYPE_PARAMS(marble, GKIND_GENERATOR, &marble_class, parse_marble, ggenerator_release, marble_params);
