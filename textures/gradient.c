/* gradient.c - the linear field generator: offset + slope . c; a height field for bump nodes or a ramp:
 *
 *   generator NAME gradient { space uv|object|world  slope X Y Z  offset O }
 */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Field {
    GGenerator base;
    GVec3 slope;
    double offset;
} Field;

static double field_value(const GGenerator *self, GSurfPoint *sp)
{
    const Field *f = (const Field *)self;
    return f->offset + gvec3_dot(f->slope, ggenerator_coords(self, sp));
}

static int field_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    (void)sp;
    const Field *f = (const Field *)self;
    *grad = self->space == GGENERATOR_SPACE_UV ? gvec3(f->slope.x, f->slope.y, 0.0) : f->slope;
    return G_OK;
}

static const GGeneratorClass gradient_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "gradient",
    .description = "linear field offset + slope . (u, v) or the point (height field or ramp)",
    .destroy = ggenerator_free,
    .value = field_value,
    .gradient = field_gradient,
};

int ggenerator_gradient_create(GGeneratorSpace space, GVec3 slope, double offset, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!isfinite(slope.x) || !isfinite(slope.y) || !isfinite(slope.z) || !isfinite(offset))
        return gerror_set(err, G_ERR_INVALID, "gradient: slope and offset must be finite");
    if (space == GGENERATOR_SPACE_NONE)
        space = GGENERATOR_SPACE_OBJECT;
    GGenerator *gen;
    int rc = ggenerator_new(&gradient_class, space, sizeof(Field), &gen, err);
    if (rc != G_OK)
        return rc;
    Field *f = (Field *)gen;
    f->slope = space == GGENERATOR_SPACE_UV ? gvec3(slope.x, slope.y, 0.0) : slope;
    f->offset = offset;
    *out = &f->base;
    return G_OK;
}

static int parse_gradient(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GGeneratorSpace space = GGENERATOR_SPACE_UV;
    GVec3 slope = gvec3(1, 0, 0);
    double offset = 0.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "space") == 0)
            rc = gtexparse_space(r, &space, err);
        else if (strcmp(key, "slope") == 0)
            rc = greader_vec3(r, &slope, err);
        else if (strcmp(key, "offset") == 0)
            rc = greader_number(r, &offset, err);
        else
            rc = greader_unknown_param(r, "space, slope, offset", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_gradient_create(space, slope, offset, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo gradient_params[] = {
    {"space", GPARAM_NAMED, "choice", "uv", "uv, object, world",
     "the coordinates c: (u, v, 0), the object-space point or the world point"},
    {"slope", GPARAM_NAMED, "vector", "<1, 0, 0>", "finite", "the field's gradient (its z is dropped in uv)"},
    {"offset", GPARAM_NAMED, "number", "0", "finite", "the value at c = 0: the field is offset + slope . c"},
    {NULL},
};

GENERIC_TYPE_PARAMS(gradient, GKIND_GENERATOR, &gradient_class, parse_gradient, ggenerator_release,
                    gradient_params);
