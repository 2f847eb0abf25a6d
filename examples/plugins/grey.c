/* grey.c - a run-time module adding the colour model "grey": one value, the luminance Y.
 *
 * A reflectance v is the flat spectrum v; a light v is D65 scaled to Y = v (so an sRGB white light,
 * rgb 1 1 1, is grey 1). Spectra come in through their Y. Useful for fast previews and as the smallest
 * complete example of a colour model.
 *
 * Text format:  colormodel grey
 *
 * Built against the installed headers only; the library's functions come from the program that loads it. The
 * record and the GENERIC_MODULE line at the end make the file a module; without that line it would be a built-in
 * colour model in colormodels/. It is not a sampled spectrum, so it does not use the spectral kit
 * (include/generic/kit/spectral.h); docs/guide.md ("A first colour model") shows one that does. */
#include <generic/plugin.h>

#include <math.h>

static int grey_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)opt;
    (void)err;
    self->nvalues = 1;
    self->capacity = 1;
    return G_OK;
}

static void grey_black(const GColorModel *m, GColor *out)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = 0.0f;
}

#define OP2(fn, expr)                                                                                          \
    static int fn(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)                         \
    {                                                                                                          \
        (void)m;                                                                                               \
        float x = a->v[0], y = b->v[0];                                                                        \
        out->kind = GCOLOR_VECTOR;                                                                             \
        out->v[0] = (expr);                                                                                    \
        return G_OK;                                                                                           \
    }
OP2(grey_add, x + y)
OP2(grey_mul, x * y)
OP2(grey_div, y != 0.0f ? x / y : 0.0f)

static int grey_scale(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = (float)(a->v[0] * s);
    return G_OK;
}

static int grey_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] > 0.0f ? (float)pow(a->v[0], e) : (e == 0.0 ? 1.0f : 0.0f);
    return G_OK;
}

static double grey_brightness(const GColorModel *m, const GColor *a)
{
    (void)m;
    return fabs(a->v[0]);
}

static int grey_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)m;
    if (role == GCOLOR_LIGHT) {
        if (gcie_illuminant_nm("D65", out) != G_OK)
            return G_ERR_INVALID;
        for (int i = 0; i < GNM_COUNT; i++)
            out->v[i] *= a->v[0];
    } else {
        for (int i = 0; i < GNM_COUNT; i++)
            out->v[i] = a->v[0];
    }
    return G_OK;
}

static int grey_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    (void)m;
    double xyz[3];
    gcie_nm_to_xyz(in, role, xyz);
    out->kind = GCOLOR_VECTOR;
    out->v[0] = (float)xyz[1];
    return G_OK;
}

static int grey_to_xyz(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3])
{
    (void)m;
    (void)role; /* both roles are D65 white scaled to Y */
    double rgb[3] = {a->v[0], a->v[0], a->v[0]};
    gcie_rgb_to_xyz(rgb, xyz);
    return G_OK;
}

static int grey_from_rgb(const GColorModel *m, const double rgb[3], GColorRole role, GColor *out)
{
    (void)m;
    (void)role;
    double xyz[3];
    gcie_rgb_to_xyz(rgb, xyz);
    out->kind = GCOLOR_VECTOR;
    out->v[0] = (float)xyz[1];
    return G_OK;
}

static const GColorModelClass grey_class = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "grey",
    .description = "luminance only (plug-in)",
    .init = grey_init,
    .black = grey_black,
    .add = grey_add,
    .mul = grey_mul,
    .scale = grey_scale,
    .div = grey_div,
    .pow = grey_pow,
    .brightness = grey_brightness,
    .to_nm = grey_to_nm,
    .from_nm = grey_from_nm,
    .to_xyz = grey_to_xyz,
    .from_rgb = grey_from_rgb,
};

/* The reader reads the grid options of every `colormodel` entry; grey has no wavelength samples. */
static const GParamInfo grey_params[] = {
    {"step", GPARAM_NAMED, "number", "(ignored)", "[0.01, 400]", "read and ignored: grey has no wavelength samples"},
    {"min", GPARAM_NAMED, "number", "(ignored)", "[100, 2000]", "read and ignored"},
    {"max", GPARAM_NAMED, "number", "(ignored)", "[100, 2000]", "read and ignored"},
    {"uplift", GPARAM_NAMED, "choice", "(ignored)", "sigmoid, basis", "read and ignored: grey needs no uplifting"},
    {NULL},
};

GENERIC_TYPE_PARAMS(grey, GKIND_COLORMODEL, &grey_class, NULL, NULL, grey_params);
GENERIC_MODULE(&gtype_grey);
