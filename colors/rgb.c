/* rgb.c - the colour literal `rgb R G B`: a linear sRGB triple (a reflectance, or a light of D65's chromaticity),
 * written `R G B` or `<R, G, B>`. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static int parse_rgb(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GVec3 v;
    int rc = greader_vec3(r, &v, err);
    if (rc != G_OK)
        return rc;
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_RGB;
    s->rgb[0] = v.x;
    s->rgb[1] = v.y;
    s->rgb[2] = v.z;
    *object = s;
    return G_OK;
}

static const GParamInfo rgb_params[] = {
    {"R", GPARAM_POSITIONAL, "number", NULL, NULL, "red, linear sRGB (Rec.709 primaries); also written <R, G, B>"},
    {"G", GPARAM_POSITIONAL, "number", NULL, NULL, "green"},
    {"B", GPARAM_POSITIONAL, "number", NULL, NULL, "blue; as a light, rgb 1 1 1 is D65 of luminance Y = 1"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_rgb, GKIND_COLOR, "rgb", parse_rgb, "linear sRGB: rgb R G B", NULL,
                          rgb_params);
