/* gradient.c - the linear field generator: offset + slope . c; a height field for bump nodes or a ramp. */
#include "generic/plugin.h"
#include "generic/textures.h"
#include "textures_builtin.h"

#include <math.h>

typedef struct Field {
    GGenerator base;
    GVec3 slope;
    double offset;
} Field;

static GVec3 coords(const GGenerator *g, const GSurfPoint *sp)
{
    switch (g->space) {
    case GGENERATOR_SPACE_UV: return gvec3(sp->u, sp->v, 0.0);
    case GGENERATOR_SPACE_WORLD: return sp->point;
    default: return sp->object_point;
    }
}

static double field_value(const GGenerator *self, GSurfPoint *sp)
{
    const Field *f = (const Field *)self;
    return f->offset + gvec3_dot(f->slope, coords(self, sp));
}

static int field_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    (void)sp;
    const Field *f = (const Field *)self;
    *grad = self->space == GGENERATOR_SPACE_UV ? gvec3(f->slope.x, f->slope.y, 0.0) : f->slope;
    return G_OK;
}

const GGeneratorClass ggen_gradient_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "gradient",
    .description = "linear field offset + slope . (u, v) or the point (height field or ramp)",
    .destroy = gtexgen_free,
    .value = field_value,
    .gradient = field_gradient,
};

int ggen_gradient_create(GGeneratorSpace space, GVec3 slope, double offset, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!isfinite(slope.x) || !isfinite(slope.y) || !isfinite(slope.z) || !isfinite(offset))
        return gerror_set(err, G_ERR_INVALID, "gradient: slope and offset must be finite");
    if (space == GGENERATOR_SPACE_NONE)
        space = GGENERATOR_SPACE_OBJECT;
    GGenerator *gen;
    int rc = gtexgen_new(&ggen_gradient_class, space, sizeof(Field), &gen, err);
    if (rc != G_OK)
        return rc;
    Field *f = (Field *)gen;
    f->slope = space == GGENERATOR_SPACE_UV ? gvec3(slope.x, slope.y, 0.0) : slope;
    f->offset = offset;
    *out = &f->base;
    return G_OK;
}

GENERIC_TYPE(gradient, GKIND_GENERATOR, &ggen_gradient_class, gtexparse_gradient, ggenerator_release);
