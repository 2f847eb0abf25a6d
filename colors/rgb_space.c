/* rgb_space.c - the colour literal `rgbspace SPACE R G B`: linear RGB in a named input colour space (srgb,
 * display-p3, rec2020, aces2065-1, acescg: generic/colorspace.h), kept as the linear sRGB of the same colour, which
 * lies outside [0, 1] where the space is wider; the spectral models uplift it from the narrowest of their tables
 * that holds it. A component below 0 in the colour's own space is refused: no colour of a space has one. */
#include "generic/colorspace.h"
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_rgb_space(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    char name[32];
    int rc = greader_ident(r, name, sizeof name, err);
    if (rc != G_OK)
        return rc;
    int space = gcolorspace_find(name);
    if (space < 0)
        return greader_error(r, err, "unknown colour space '%s' (known: %s)", name, gcolorspace_names());
    double v[3];
    static const char *const comp[3] = {"R", "G", "B"};
    for (int i = 0; i < 3; i++) {
        if ((rc = greader_number(r, &v[i], err)) != G_OK)
            return rc;
        if (!(v[i] >= 0.0))
            return greader_error(r, err, "%s = %g of a colour in %s is below 0 (every component of a colour of a "
                                 "space is >= 0; a colour outside %s is written in a wider space)",
                                 comp[i], v[i], gcolorspace_name(space), gcolorspace_name(space));
    }
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_RGB;
    if (gcolorspace_to_srgb(space, v, s->rgb) != G_OK) {
        gcolorspec_destroy(s);
        return greader_error(r, err, "colour space '%s' cannot be converted", name);
    }
    *object = s;
    return G_OK;
}

static const GParamInfo rgb_space_params[] = {
    {"SPACE", GPARAM_POSITIONAL, "choice", NULL, "srgb, display-p3, rec2020, aces2065-1, acescg",
     "the colour space (also rec709, p3, aces, ap1); every one with the D65 white (ACES's adapted by Bradford)"},
    {"R", GPARAM_POSITIONAL, "number", NULL, ">= 0", "red, linear, in the space's primaries"},
    {"G", GPARAM_POSITIONAL, "number", NULL, ">= 0", "green"},
    {"B", GPARAM_POSITIONAL, "number", NULL, ">= 0", "blue; as a light, 1 1 1 is D65 of luminance Y = 1"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_rgb_space, GKIND_COLOR, "rgbspace", parse_rgb_space,
                          "linear RGB in a named colour space: rgbspace SPACE R G B", NULL, rgb_space_params);
