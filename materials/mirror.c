/* mirror.c - the perfect specular reflector of the paper's example. */
#include "generic/materials.h"
#include "materials_builtin.h"
#include "params.h"

typedef struct Mirror {
    GMaterial base;
    GColor r;
} Mirror;

static void mirror_destroy(GMaterial *self)
{
    Mirror *m = (Mirror *)self;
    gcolor_free(&m->r);
    gmem_free(m);
}

static int mirror_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GVec3 n;
    if (gmat_cos_in(sp, in, out, &n) <= 0.0 || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_mul(result, &((const Mirror *)self)->r, illum);
}

static int mirror_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int mirror_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const Mirror *)self)->r, illum);
}

const GMaterialClass gmaterial_mirror = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "mirror",
    .description = "perfect specular reflector",
    .destroy = mirror_destroy,
    .reflection = mirror_reflection,
    .reflection_dir = mirror_reflection_dir,
    .ambient = mirror_ambient,
};

int gmirror_create(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "mirror: no colour model given");
    Mirror *m = gmem_calloc(1, sizeof *m);
    if (!m)
        return gerror_set(err, G_ERR_NOMEM, "mirror: out of memory");
    int rc = gmaterial_init(&m->base, &gmaterial_mirror, model, err);
    if (rc == G_OK)
        rc = gmatparam_color(model, reflectance, GCOLOR_REFLECTANCE, 1.0, "mirror", "reflectance", &m->r, err);
    if (rc != G_OK) {
        mirror_destroy(&m->base);
        return rc;
    }
    *out = &m->base;
    return G_OK;
}
