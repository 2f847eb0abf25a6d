/* illuminant.c - the colour literal `illuminant NAME`: a CIE illuminant (A, B, C, D50, D55, D65, D75, E, F1..F12,
 * LED-B1..B5, LED-BH1, LED-RGB1, LED-V1, LED-V2; gcie_illuminant_name lists them), scaled to luminance Y = 1. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

#define ILLUMINANT_MAX_NAMES 64

static int parse_illuminant(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    const char *names[ILLUMINANT_MAX_NAMES + 1];
    int n = 0;
    while (n < ILLUMINANT_MAX_NAMES && gcie_illuminant_name(n))
        names[n] = gcie_illuminant_name(n), n++;
    names[n] = NULL;
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
    {"NAME", GPARAM_POSITIONAL, "choice", NULL,
     "A, B, C, D50, D55, D65, D75, E, F1..F12, LED-B1..B5, LED-BH1, LED-RGB1, LED-V1, LED-V2",
     "the CIE illuminant (CIE 15:2004 and CIE 015:2018 tables), of Y = 1"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_illuminant, GKIND_COLOR, "illuminant", parse_illuminant,
                          "CIE illuminant, Y = 1: illuminant D65|A|F11|LED-B3|...", NULL, illuminant_params);
