/* constant.c - the constant generator. */
#include "generic/plugin.h"
#include "generic/textures.h"
#include "textures_builtin.h"

#include <math.h>

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

const GGeneratorClass ggen_constant_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "constant",
    .description = "the same value everywhere",
    .destroy = gtexgen_free,
    .value = constant_value,
    .gradient = constant_gradient,
};

int ggen_constant_create(double value, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!isfinite(value))
        return gerror_set(err, G_ERR_INVALID, "constant: value must be finite, got %g", value);
    GGenerator *gen;
    int rc = gtexgen_new(&ggen_constant_class, GGENERATOR_SPACE_NONE, sizeof(Constant), &gen, err);
    if (rc != G_OK)
        return rc;
    Constant *c = (Constant *)gen;
    c->value = value;
    *out = &c->base;
    return G_OK;
}

GENERIC_TYPE(constant, GKIND_GENERATOR, &ggen_constant_class, gtexparse_constant, ggenerator_release);
