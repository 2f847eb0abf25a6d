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

GENERIC_TYPE_NAMED(color_blackbody, GKIND_COLOR, "blackbody", parse_blackbody,
                   "Planck radiator, Y = 1: blackbody KELVIN", NULL);
