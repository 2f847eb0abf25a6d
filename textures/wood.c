/* wood.c - the wood generator: growth rings around the z axis, displaced by fbm:
 *
 *   generator NAME wood { NOISE  rings R  turbulence T  latewood W }
 *
 * NOISE: the noise parameters (space, frequency, seed, octaves, lacunarity, gain; generic/kit/texture_parse.h). */
#include <generic/generators.h>
#include <generic/kit/noise.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Wood {
    GGenerator base;
    GNoiseParams p;
    double rings, turbulence, latewood;
} Wood;

static double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }
static double dsmoothstep(double t) { return 6.0 * t * (1.0 - t); }

/* The ring profile at the point and, with grad, its gradient. */
static double profile(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Wood *w = (const Wood *)self;
    GVec3 x = ggenerator_coords(self, sp), d = gvec3(0, 0, 0);
    double rho = sqrt(x.x * x.x + x.y * x.y);
    double r = w->rings * rho;
    if (w->turbulence != 0.0)
        r += w->turbulence * gnoise_fbm(&w->p, x, grad ? &d : NULL);
    double g = r - floor(r), early = 1.0 - w->latewood;
    double v, slope;
    if (g < early) {
        v = smoothstep(g / early);
        slope = dsmoothstep(g / early) / early;
    } else {
        v = 1.0 - smoothstep((g - early) / w->latewood);
        slope = -dsmoothstep((g - early) / w->latewood) / w->latewood;
    }
    if (grad) {
        GVec3 dr = gvec3_scale(d, w->turbulence);
        if (rho > 0.0)
            dr = gvec3_madd(dr, gvec3(x.x / rho, x.y / rho, 0.0), w->rings);
        *grad = ggenerator_space_gradient(self, gvec3_scale(dr, slope));
    }
    return v;
}

static double wood_value(const GGenerator *self, GSurfPoint *sp) { return profile(self, sp, NULL); }

static int wood_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    profile(self, sp, grad);
    return G_OK;
}

static const GGeneratorClass wood_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "wood",
    .description = "growth rings around the z axis displaced by noise, in [0, 1]",
    .destroy = ggenerator_free,
    .value = wood_value,
    .gradient = wood_gradient,
};

int ggenerator_wood_create(const GNoiseParams *p, double rings, double turbulence, double latewood, GGenerator **out,
                     GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gnoise_params("wood", p, &q, err);
    if (rc != G_OK)
        return rc;
    if (!(rings > 0.0) || !isfinite(rings))
        return gerror_set(err, G_ERR_INVALID, "wood: rings must be positive and finite, got %g", rings);
    if (!isfinite(turbulence))
        return gerror_set(err, G_ERR_INVALID, "wood: turbulence must be finite, got %g", turbulence);
    if (latewood == 0.0)
        latewood = 0.2;
    if (!(latewood > 0.0 && latewood < 1.0))
        return gerror_set(err, G_ERR_INVALID, "wood: latewood must be within (0, 1), got %g", latewood);
    GGenerator *gen;
    rc = ggenerator_new(&wood_class, q.space, sizeof(Wood), &gen, err);
    if (rc != G_OK)
        return rc;
    Wood *w = (Wood *)gen;
    w->p = q;
    w->rings = rings;
    w->turbulence = turbulence;
    w->latewood = latewood;
    *out = &w->base;
    return G_OK;
}

static int parse_wood(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GNoiseParams p;
    memset(&p, 0, sizeof p);
    double rings = 8.0, turbulence = 0.5, latewood = 0.2;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = gtexparse_noise_param(r, key, &p, err);
        if (rc == 0) {
            if (strcmp(key, "rings") == 0)
                rc = greader_number_in(r, 1e-9, 1e9, &rings, err);
            else if (strcmp(key, "latewood") == 0)
                rc = greader_number_in(r, 0.001, 0.999, &latewood, err);
            else if (strcmp(key, "turbulence") == 0)
                rc = greader_number(r, &turbulence, err);
            else
                rc = greader_unknown_param(r, GTEXPARSE_NOISE_KEYS ", rings, turbulence, latewood", err);
        }
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_wood_create(&p, rings, turbulence, latewood, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo wood_params[] = {
    GTEXPARSE_NOISE_BASE_PARAMS,
    GTEXPARSE_NOISE_OCTAVE_PARAMS,
    {"rings", GPARAM_NAMED, "number", "8", "[1e-9, 1e9]", "growth rings per unit of distance from the z axis"},
    {"turbulence", GPARAM_NAMED, "number", "0.5", "finite", "how far fbm displaces the rings"},
    {"latewood", GPARAM_NAMED, "number", "0.2", "[0.001, 0.999]",
     "the share of each ring in which the value falls back from 1 to 0 (the dark latewood)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(wood, GKIND_GENERATOR, &wood_class, parse_wood, ggenerator_release, wood_params);
