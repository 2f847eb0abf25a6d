/* surface.c - the surface index generator (for select nodes: a material per face):  generator NAME surface */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

static double surface_value(const GGenerator *self, GSurfPoint *sp)
{
    (void)self;
    return (double)sp->surface;
}

static const GGeneratorClass surface_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "surface",
    .description = "the index of the object's surface that was hit",
    .destroy = ggenerator_free,
    .value = surface_value,
    .gradient = NULL, /* piecewise constant: space NONE gives a zero gradient */
};

int ggenerator_surface_create(GGenerator **out, GError *err)
{
    *out = NULL;
    return ggenerator_new(&surface_class, GGENERATOR_SPACE_NONE, sizeof(GGenerator), out, err);
}

static int parse_surface(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    const char *key;
    int rc;
    if ((rc = greader_param(r, &key, err)) > 0)
        return greader_unknown_param(r, "(none)", err);
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_surface_create(&g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo surface_params[] = {
    {NULL}, /* none: its value is the surface index of the hit */
};

GENERIC_TYPE_PARAMS(surface, GKIND_GENERATOR, &surface_class, parse_surface, ggenerator_release, surface_params);
