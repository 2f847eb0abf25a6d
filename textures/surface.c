/* surface.c - the surface index generator (for select nodes: a material per face). */
#include "generic/textures.h"
#include "textures_builtin.h"

static void surface_destroy(GGenerator *self) { gmem_free(self); }

static double surface_value(const GGenerator *self, GSurfPoint *sp)
{
    (void)self;
    return (double)sp->surface;
}

const GGeneratorClass ggen_surface_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "surface",
    .description = "the index of the object's surface that was hit",
    .destroy = surface_destroy,
    .value = surface_value,
    .gradient = NULL, /* piecewise constant: space NONE gives a zero gradient */
};

int ggen_surface_create(GGenerator **out, GError *err)
{
    *out = NULL;
    GGenerator *g = gmem_calloc(1, sizeof *g);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "surface: out of memory");
    int rc = ggenerator_init(g, &ggen_surface_class, GGENERATOR_SPACE_NONE, err);
    if (rc != G_OK) {
        gmem_free(g);
        return rc;
    }
    *out = g;
    return G_OK;
}
