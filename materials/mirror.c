/* mirror.c - the perfect specular reflector of the paper's example. */
#include "generic/plugin.h"
#include "material_parsers.h"
#include "generic/materials.h"
#include "materials_builtin.h"
#include "params.h"

/* The state is a GMatOneColor: c is the reflectance. */

static int mirror_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GVec3 n;
    if (gmat_cos_in(sp, in, out, &n) <= 0.0 || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_mul(result, &((const GMatOneColor *)self)->c, illum);
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
    return gcolor_mul(result, &((const GMatOneColor *)self)->c, illum);
}

const GMaterialClass gmaterial_mirror = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "mirror",
    .description = "perfect specular reflector",
    .destroy = gmat_one_color_destroy,
    .reflection = mirror_reflection,
    .reflection_dir = mirror_reflection_dir,
    .ambient = mirror_ambient,
};

int gmirror_create(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err)
{
    return gmat_one_color_create(&gmaterial_mirror, model, sizeof(GMatOneColor), reflectance, GCOLOR_REFLECTANCE,
                                 1.0, "reflectance", out, err);
}

GENERIC_TYPE(mirror, GKIND_MATERIAL, &gmaterial_mirror, gparse_mirror, NULL);
