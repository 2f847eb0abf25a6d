/* colormodel_by_name.c - colour models created by the name of a registered colour model type. */
#include "generic/color.h"
#include "generic/registry.h"

int gcolormodel_create(const char *name, const GColorModelOptions *opt, GColorModel **out, GError *err)
{
    *out = NULL;
    const GTypeInfo *t = gregistry_find(GKIND_COLORMODEL, name ? name : "");
    if (!t) {
        char names[256];
        gregistry_names(GKIND_COLORMODEL, names, sizeof names);
        return gerror_set(err, G_ERR_NOTFOUND, "unknown colour model '%s' (known: %s)", name ? name : "", names);
    }
    return gcolormodel_create_class(t->vtable, opt, out, err);
}
