/* line.c - the colour literal `line NM [POWER]`: a monochromatic line of light (power 1 when not given), spread
 * where it is used over a triangle one sample step wide, so its energy and centre survive any sampling. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_line(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    double nm = 0.0, power = 1.0;
    int rc = greader_number_in(r, GNM_MIN, GNM_MAX, &nm, err);
    if (rc == G_OK && (rc = greader_at_number(r, err)) == 1)
        rc = greader_number_in(r, 0.0, 1e30, &power, err);
    if (rc != G_OK)
        return rc;
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_LINE;
    s->line_nm = nm;
    s->line_power = power;
    *object = s;
    return G_OK;
}

static const GParamInfo line_params[] = {
    {"NM", GPARAM_POSITIONAL, "number", NULL, "[380, 780]", "the wavelength of a monochromatic line"},
    {"POWER", GPARAM_POSITIONAL, "number", "1", "[0, 1e30]", "its radiant power (optional)"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_line, GKIND_COLOR, "line", parse_line, "monochromatic line: line NM [POWER]", NULL,
                          line_params);
