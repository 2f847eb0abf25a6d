/* emitter.c - a surface that emits radiance L from its front (or both sides). */
#include "generic/materials.h"
#include "materials_builtin.h"
#include "params.h"

typedef struct Emitter {
    GMaterial base;
    GColor radiance;
    int two_sided;
} Emitter;

static void emitter_destroy(GMaterial *self)
{
    Emitter *e = (Emitter *)self;
    gcolor_free(&e->radiance);
    gmem_free(e);
}

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
    return gcolor_copy(result, &e->radiance);
}

const GMaterialClass gmaterial_emitter = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "emitter",
    .description = "emits a radiance from its front (or both sides)",
    .destroy = emitter_destroy,
    .emission = emitter_emission,
};

int gemitter_create(const GColorModel *model, const GColor *radiance, int two_sided, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "emitter: no colour model given");
    Emitter *e = gmem_calloc(1, sizeof *e);
    if (!e)
        return gerror_set(err, G_ERR_NOMEM, "emitter: out of memory");
    int rc = gmaterial_init(&e->base, &gmaterial_emitter, model, err);
    if (rc == G_OK)
        rc = gmatparam_color(model, radiance, GCOLOR_LIGHT, 0.0, "emitter", "radiance", &e->radiance, err);
    if (rc != G_OK) {
        emitter_destroy(&e->base);
        return rc;
    }
    e->two_sided = two_sided != 0;
    *out = &e->base;
    return G_OK;
}
