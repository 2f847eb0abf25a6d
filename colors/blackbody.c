/* blackbody.c - the colour literal `blackbody KELVIN`: a Planck radiator's spectrum, scaled to luminance Y = 1. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_blackbody(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    double kelvin = 0.0;
    int rc = greader_number_in(r, 100.0, 1e6, &kelvin, err);
    if (rc != G_OK)
        return rc;
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_NM;
    gcie_blackbody_nm(kelvin, &s->nm);
    *object = s;
    return G_OK;
}

static const GParamInfo blackbody_params[] = {
    {"KELVIN", GPARAM_POSITIONAL, "number", NULL, "[100, 1e6]", "the temperature of a Planck radiator of Y = 1"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_blackbody, GKIND_COLOR, "blackbody", parse_blackbody,
                          "Planck radiator, Y = 1: blackbody KELVIN", NULL, blackbody_params);
