/* illuminant.c - the colour literal `illuminant D65|A|E`: a CIE standard illuminant, scaled to luminance Y = 1. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_illuminant(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    static const char *const names[] = {"D65", "A", "E", NULL};
    int which = 0;
    int rc = greader_choice(r, names, &which, err);
    if (rc != G_OK)
        return rc;
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_NM;
    if (gcie_illuminant_nm(names[which], &s->nm) != G_OK) {
        gcolorspec_destroy(s);
        return greader_error(r, err, "illuminant %s is not available", names[which]);
    }
    *object = s;
    return G_OK;
}

static const GParamInfo illuminant_params[] = {
    {"NAME", GPARAM_POSITIONAL, "choice", NULL, "D65, A, E", "the CIE illuminant, of Y = 1"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_illuminant, GKIND_COLOR, "illuminant", parse_illuminant,
                          "CIE illuminant, Y = 1: illuminant D65|A|E", NULL, illuminant_params);
