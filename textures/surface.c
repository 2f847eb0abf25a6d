/* surface.c - the surface index generator (for select nodes: a material per face). */
#include "generic/plugin.h"
#include "generic/textures.h"
#include "textures_builtin.h"

static double surface_value(const GGenerator *self, GSurfPoint *sp)
{
    (void)self;
    return (double)sp->surface;
}

const GGeneratorClass ggen_surface_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "surface",
    .description = "the index of the object's surface that was hit",
    .destroy = gtexgen_free,
    .value = surface_value,
    .gradient = NULL, /* piecewise constant: space NONE gives a zero gradient */
};

int ggen_surface_create(GGenerator **out, GError *err)
{
    *out = NULL;
    return gtexgen_new(&ggen_surface_class, GGENERATOR_SPACE_NONE, sizeof(GGenerator), out, err);
}

GENERIC_TYPE(surface, GKIND_GENERATOR, &ggen_surface_class, gtexparse_surface, ggenerator_release);
