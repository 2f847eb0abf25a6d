/* bands.c - a run-time module adding the texture generator "bands": smooth parallel bands,
 *     value = 0.5 + 0.5 * sin(2 pi * dot(p, axis) / period)   over the object-space point p,
 * with its analytic gradient. Text format:  generator stripes bands { period 0.5 axis <1, 0, 0> }
 *
 * Built against the installed headers only (the generator kit: ggenerator_new, ggenerator_free, gtexparse_finish);
 * the library's functions come from the program that loads it. Its last line makes the file a module. */
#include <generic/plugin.h>
#include <generic/texture.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Bands {
    GGenerator base;
    GVec3 axis; /* unit */
    double period;
} Bands;

static double bands_value(const GGenerator *self, GSurfPoint *sp)
{
    const Bands *b = (const Bands *)self;
    return 0.5 + 0.5 * sin(2.0 * M_PI * gvec3_dot(sp->object_point, b->axis) / b->period);
}

static int bands_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Bands *b = (const Bands *)self;
    double k = 2.0 * M_PI / b->period;
    *grad = gvec3_scale(b->axis, 0.5 * k * cos(k * gvec3_dot(sp->object_point, b->axis)));
    return G_OK;
}

static const GGeneratorClass bands_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "bands",
    .description = "smooth parallel bands (plug-in)",
    .destroy = ggenerator_free,
    .value = bands_value,
    .gradient = bands_gradient,
};

static int parse_bands(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    double period = 1.0;
    GVec3 axis = gvec3(1, 0, 0);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "period") == 0)
            rc = greader_number_in(r, 1e-9, 1e9, &period, err);
        else if (strcmp(key, "axis") == 0) {
            rc = greader_vec3(r, &axis, err);
            if (rc == G_OK && gvec3_length(axis) == 0.0)
                rc = greader_error(r, err, "bands: axis must not be zero");
        } else
            rc = greader_unknown_param(r, "period, axis", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_new(&bands_class, GGENERATOR_SPACE_OBJECT, sizeof(Bands), &g, err);
    if (rc == G_OK) {
        ((Bands *)g)->axis = gvec3_normalize(axis);
        ((Bands *)g)->period = period;
    }
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo bands_params[] = {
    {"period", GPARAM_NAMED, "number", "1", "[1e-9, 1e9]", "the distance from one band to the next"},
    {"axis", GPARAM_NAMED, "vector", "<1, 0, 0>", "not zero", "the direction across the bands, in object space"},
    {NULL},
};

GENERIC_TYPE_PARAMS(bands, GKIND_GENERATOR, &bands_class, parse_bands, ggenerator_release, bands_params);
GENERIC_MODULE(&gtype_bands);
