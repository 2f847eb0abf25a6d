/* select.c - the select node: an integer generator (e.g. the surface index) picks one of n children. */
#include "generic/plugin.h"
#include "node_common.h"
#include "textures_builtin.h"

#include <math.h>

/* The state is a GTexList: gen is the index. */

static const GMaterial *chosen(const GMaterial *self, GSurfPoint *sp)
{
    const GTexList *s = (const GTexList *)self;
    if (!sp)
        return s->children[0];
    double v = floor(ggenerator_cached_value(s->gen, sp));
    int i = !(v > 0.0) ? 0 : v >= s->n - 1 ? s->n - 1 : (int)v; /* NaN picks the first */
    return s->children[i];
}

static int select_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    return gmaterial_reflection(chosen(self, sp), sp, in, illum, out, result);
}

static int select_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                             const GColor *rel_index, GVec3 out, GColor *result)
{
    return gmaterial_refraction(chosen(self, sp), sp, in, illum, rel_index, out, result);
}

static int select_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(chosen(self, sp), sp, result);
}

static int select_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    return gmaterial_reflection_dir(chosen(self, sp), sp, view, dir);
}

static int select_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                 GVec3 *dir)
{
    return gmaterial_refraction_dir(chosen(self, sp), sp, view, rel_index, dir);
}

static int select_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    return gmaterial_emission(chosen(self, sp), sp, out, result);
}

static int select_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    return gmaterial_ambient(chosen(self, sp), sp, illum, result);
}

static int select_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                             GColor *result)
{
    return gmaterial_absorption(chosen(self, sp), sp, illum, length, result);
}

static int select_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    return gmaterial_normal(chosen(self, sp), sp, n);
}

static int select_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_diffuse(chosen(self, sp), sp, result);
}

static int select_opaque(const GMaterial *self, GSurfPoint *sp) { return gmaterial_opaque(chosen(self, sp), sp); }

const GMaterialClass gnode_select_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "select",
    .description = "one of n children picked by an integer generator (e.g. the surface index)",
    .destroy = gtexlist_destroy,
    .reflection = select_reflection,
    .refraction = select_refraction,
    .refraction_index = select_refraction_index,
    .reflection_dir = select_reflection_dir,
    .refraction_dir = select_refraction_dir,
    .emission = select_emission,
    .ambient = select_ambient,
    .absorption = select_absorption,
    .normal = select_normal,
    .diffuse = select_diffuse,
    .opaque = select_opaque,
};

int gnode_select_create(GMaterial *const *children, int n, GGenerator *index, GMaterial **out, GError *err)
{
    return gtexlist_new(&gnode_select_class, children, n, index, sizeof(GTexList), out, err);
}

GENERIC_TYPE(select, GKIND_NODE, &gnode_select_class, gtexparse_select, NULL);
