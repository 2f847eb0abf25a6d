/* constant.c - the constant generator:  generator NAME constant { value V } */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Constant {
    GGenerator base;
    double value;
} Constant;

static double constant_value(const GGenerator *self, GSurfPoint *sp)
{
    (void)sp;
    return ((const Constant *)self)->value;
}

static int constant_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    (void)self;
    (void)sp;
    *grad = gvec3(0, 0, 0);
    return G_OK;
}

static const GGeneratorClass constant_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "constant",
    .description = "the same value everywhere",
    .destroy = ggenerator_free,
    .value = constant_value,
    .gradient = constant_gradient,
};

int ggenerator_constant_create(double value, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!isfinite(value))
        return gerror_set(err, G_ERR_INVALID, "constant: value must be finite, got %g", value);
    GGenerator *gen;
    int rc = ggenerator_new(&constant_class, GGENERATOR_SPACE_NONE, sizeof(Constant), &gen, err);
    if (rc != G_OK)
        return rc;
    Constant *c = (Constant *)gen;
    c->value = value;
    *out = &c->base;
    return G_OK;
}

static int parse_constant(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    double v = 0.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = strcmp(key, "value") == 0 ? greader_number(r, &v, err) : greader_unknown_param(r, "value", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_constant_create(v, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo constant_params[] = {
    {"value", GPARAM_NAMED, "number", "0", "finite", "the value everywhere"},
    {NULL},
};

GENERIC_TYPE_PARAMS(constant, GKIND_GENERATOR, &constant_class, parse_constant, ggenerator_release,
                    constant_params);
