/* emitter.c - a surface that emits radiance L from its front (or both sides). */
#include "generic/plugin.h"
#include "material_parsers.h"
#include "generic/materials.h"
#include "materials_builtin.h"
#include "params.h"

typedef struct Emitter {
    GMatOneColor radiance; /* first: the class's destroy is gmat_one_color_destroy */
    int two_sided;
} Emitter;

static int emitter_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    const Emitter *e = (const Emitter *)self;
    if (!e->two_sided) {
        /* the geometric normal faces the incident ray; the front is the object's outside */
        double c = gvec3_dot(out, sp->geometric_normal);
        if (!sp->entering)
            c = -c;
        if (c <= 0.0) {
            gcolor_black(result);
            return G_OK;
        }
    }
    return gcolor_copy(result, &e->radiance.c);
}

const GMaterialClass gmaterial_emitter = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "emitter",
    .description = "emits a radiance from its front (or both sides)",
    .destroy = gmat_one_color_destroy,
    .emission = emitter_emission,
};

int gemitter_create(const GColorModel *model, const GColor *radiance, int two_sided, GMaterial **out, GError *err)
{
    int rc = gmat_one_color_create(&gmaterial_emitter, model, sizeof(Emitter), radiance, GCOLOR_LIGHT, 0.0, "radiance",
                                   out, err);
    if (rc == G_OK)
        ((Emitter *)*out)->two_sided = two_sided != 0;
    return rc;
}

GENERIC_TYPE(emitter, GKIND_MATERIAL, &gmaterial_emitter, gparse_emitter, NULL);
