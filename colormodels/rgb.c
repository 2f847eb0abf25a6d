/* rgb.c - the RGB colour model: linear Rec.709/sRGB primaries, D65 white. Conversions to XYZ use the
 * sRGB matrix directly; to and from spectra go through the spectral primary basis (lib/color/cie.c). */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"
#include "generic/color.h"

#include <math.h>

static int rgb_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)opt;
    (void)err;
    self->nvalues = 3;
    self->capacity = 3;
    return G_OK;
}

static void rgb_black(const GColorModel *m, GColor *out)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = out->v[1] = out->v[2] = 0.0f;
}

static int rgb_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] + b->v[0];
    out->v[1] = a->v[1] + b->v[1];
    out->v[2] = a->v[2] + b->v[2];
    return G_OK;
}

static int rgb_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] * b->v[0];
    out->v[1] = a->v[1] * b->v[1];
    out->v[2] = a->v[2] * b->v[2];
    return G_OK;
}

static int rgb_scale(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    (void)m;
    float f = (float)s;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] * f;
    out->v[1] = a->v[1] * f;
    out->v[2] = a->v[2] * f;
    return G_OK;
}

static int rgb_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = b->v[i] != 0.0f ? a->v[i] / b->v[i] : 0.0f;
    return G_OK;
}

static int rgb_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = a->v[i] > 0.0f ? (float)pow(a->v[i], e) : (e == 0.0 ? 1.0f : 0.0f);
    return G_OK;
}

static double rgb_brightness(const GColorModel *m, const GColor *a)
{
    (void)m;
    return 0.2126729 * fabsf(a->v[0]) + 0.7151522 * fabsf(a->v[1]) + 0.0721750 * fabsf(a->v[2]);
}

static int rgb_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)m;
    double rgb[3] = {a->v[0], a->v[1], a->v[2]};
    gcie_rgb_to_nm(rgb, role, out);
    return G_OK;
}

static int rgb_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    (void)m;
    double xyz[3], rgb[3];
    gcie_nm_to_xyz(in, role, xyz);
    gcie_xyz_to_rgb(xyz, rgb);
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = (float)rgb[i];
    return G_OK;
}

static int rgb_to_xyz(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    (void)m;
    (void)role;
    double rgb[3] = {a->v[0], a->v[1], a->v[2]};
    gcie_rgb_to_xyz(rgb, xyz);
    return G_OK;
}

static int rgb_from_rgb(const GColorModel *m, const double rgb[3], GColorRole role, GColor *out)
{
    (void)m;
    (void)role;
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = (float)rgb[i];
    return G_OK;
}

static const GColorModelClass gcolormodel_rgb = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "rgb",
    .description = "linear Rec.709/sRGB primaries, D65 white",
    .init = rgb_init,
    .black = rgb_black,
    .add = rgb_add,
    .mul = rgb_mul,
    .scale = rgb_scale,
    .div = rgb_div,
    .pow = rgb_pow,
    .brightness = rgb_brightness,
    .to_nm = rgb_to_nm,
    .from_nm = rgb_from_nm,
    .to_xyz = rgb_to_xyz,
    .from_rgb = rgb_from_rgb,
    /* three bands: the light of each primary, refracted with the index the model holds for it (materials
     * give the index at 610, 550 and 465 nm) */
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

/* The reader reads the grid options of every `colormodel` entry; rgb has no wavelength samples. */
static const GParamInfo rgb_params[] = {
    {"step", GPARAM_NAMED, "number", "(ignored)", "[0.01, 400]", "read and ignored: rgb has no wavelength samples"},
    {"min", GPARAM_NAMED, "number", "(ignored)", "[100, 2000]", "read and ignored"},
    {"max", GPARAM_NAMED, "number", "(ignored)", "[100, 2000]", "read and ignored"},
    {"uplift", GPARAM_NAMED, "choice", "(ignored)", "sigmoid, basis", "read and ignored: rgb needs no uplifting"},
    {NULL},
};

GENERIC_TYPE_PARAMS(rgb, GKIND_COLORMODEL, &gcolormodel_rgb, NULL, NULL, rgb_params);
