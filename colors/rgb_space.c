/* rgb_space.c - the colour literal `rgbspace SPACE R G B`: linear RGB in a named input colour space (srgb,
 * display-p3, rec2020, aces2065-1, acescg: generic/colorspace.h), kept as the linear sRGB of the same colour, which
 * lies outside [0, 1] where the space is wider; the spectral models uplift it from the narrowest of their tables
 * that holds it. A component below 0 in the colour's own space is refused: no colour of a space has one.
 *
 * A colour whose components lie within [0, 1] may be a reflectance; when no smooth reflectance within [0, 1] has
 * it (the sigmoid uplift leaves a CIELAB distance above OUTSIDE_DE: rec2020 0 0.8 0 leaves 33), a warning at the
 * literal's position says how it is mapped: as a reflectance the spectral models take the nearest smooth
 * reflectance, and rgb, where it has negative components, refuses it as a material's reflectance (the range
 * rule); as a light it is exact everywhere. The literal does not know its role, so the warning says both. */
#include "generic/colorspace.h"
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

#include <stdio.h>

enum { OUTSIDE_DE = 1 }; /* CIELAB distance the uplift may leave before a colour counts as outside the gamut */

/* Warns at line:col when rgb (linear sRGB, components in [0, 1] in its own space) is outside the reflectances. */
static void warn_outside_reflectances(GReader *r, int line, int col, int space, const double v[3],
                                      const double rgb[3])
{
    GSpectrumNM s;
    double de = 0.0;
    if (guplift_rgb_to_nm(rgb, GCOLOR_REFLECTANCE, &s, &de) != G_OK || !(de > OUTSIDE_DE))
        return;
    fprintf(stderr, "%s:%d:%d: warning: rgbspace %s %g %g %g lies outside the reflectances (no smooth reflectance "
            "within [0, 1] has it: CIELAB distance %.1f left): as a reflectance the spectral models take the nearest "
            "and rgb refuses its negative components; as a light it is exact\n", greader_file(r), line, col,
            gcolorspace_name(space), v[0], v[1], v[2], de);
}

static int parse_rgb_space(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    int line = 0, col = 0;
    greader_position(r, &line, &col);
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
    if (v[0] <= 1.0 && v[1] <= 1.0 && v[2] <= 1.0)
        warn_outside_reflectances(r, line, col, space, v, s->rgb);
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
