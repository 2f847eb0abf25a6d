/* interpolate_one.c - the interpolate-one node (its methods are interpolate's, textures/interpolate.c) and
 * the keywords of the material methods. */
#include "node_common.h"
#include "textures_builtin.h"

#include <string.h>

static const char *const method_names[GNODE_METHOD_COUNT] = {
    "reflection", "refraction", "refraction_index", "reflection_dir", "refraction_dir", "emission",
    "ambient",    "absorption", "normal",           "diffuse",        "opaque",
};

const char *gnode_method_name(GNodeMethod m)
{
    return (unsigned)m < GNODE_METHOD_COUNT ? method_names[m] : "?";
}

int gnode_method_from_name(const char *name)
{
    for (int i = 0; name && i < GNODE_METHOD_COUNT; i++)
        if (strcmp(name, method_names[i]) == 0)
            return i;
    return -1;
}

int gnode_interpolate_one_create(GMaterial *a, GMaterial *b, GGenerator *t, GNodeMethod method, GMaterial **out,
                                 GError *err)
{
    *out = NULL;
    if ((unsigned)method >= GNODE_METHOD_COUNT)
        return gerror_set(err, G_ERR_INVALID, "interpolate-one: unknown method %d", (int)method);
    return gtexnode_interpolate_make(&gnode_interpolate_one_class, a, b, t, (int)method, out, err);
}
