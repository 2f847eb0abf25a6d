/* color_named_light.c - a named light as a colour of any model (color.h, gcolor_named_light): a CIE illuminant or a
 * blackbody, read as a light with Y = 1. */
#include "generic/color.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int gcolor_named_light(GColor *c, const char *name, GError *err)
{
    GSpectrumNM s;
    if (!name)
        return gerror_set(err, G_ERR_INVALID, "no light named");
    if (strncmp(name, "blackbody", 9) == 0 && (name[9] == ' ' || name[9] == '\0')) {
        char *end;
        errno = 0;
        double k = strtod(name + 9, &end);
        while (*end == ' ')
            end++;
        if (errno || end == name + 9 || *end || !(k >= 100.0 && k <= 100000.0))
            return gerror_set(err, G_ERR_INVALID, "light '%s': blackbody expects a temperature in kelvin, "
                              "100..100000 (e.g. 'blackbody 2856')", name);
        gcie_blackbody_nm(k, &s);
    } else if (gcie_illuminant_nm(name, &s) != G_OK) {
        char known[1024];
        size_t used = 0;
        known[0] = '\0';
        for (int i = 0; gcie_illuminant_name(i) && used < sizeof known; i++)
            used += (size_t)snprintf(known + used, sizeof known - used, "%s, ", gcie_illuminant_name(i));
        return gerror_set(err, G_ERR_NOTFOUND, "unknown illuminant '%s' (known: %sblackbody K)", name, known);
    }
    if (!c)
        return G_OK;
    int rc = gcolor_from_nm(c, &s, GCOLOR_LIGHT);
    return rc == G_OK ? G_OK
                      : gerror_set(err, rc, "light '%s' cannot be converted into the colour model '%s'", name,
                                   gcolormodel_name(c->model));
}
