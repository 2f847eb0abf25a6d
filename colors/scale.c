/* scale.c - the colour literal `scale FACTOR COLOR`: any colour (a literal or a name) times a factor. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_scale(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    double f = 0.0;
    int rc = greader_number_in(r, 0.0, 1e30, &f, err);
    GColorSpec *s = NULL;
    if (rc == G_OK)
        rc = greader_color_spec(r, &s, err);
    if (rc != G_OK)
        return rc;
    s->scale *= f;
    *object = s;
    return G_OK;
}

static const GParamInfo scale_params[] = {
    {"FACTOR", GPARAM_POSITIONAL, "number", NULL, "[0, 1e30]", "multiplies the colour"},
    {"COLOR", GPARAM_POSITIONAL, "color", NULL, NULL, "any colour value: a literal or a name"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_scale, GKIND_COLOR, "scale", parse_scale, "scaled colour: scale FACTOR COLOR", NULL,
                          scale_params);
