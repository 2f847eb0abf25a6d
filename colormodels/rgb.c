/* rgb.c - the RGB colour model: linear Rec.709/sRGB primaries, D65 white. Conversions to XYZ use the
 * sRGB matrix directly; to and from spectra go through the spectral primary basis (lib/color/cie.c).
 *
 * Values. A VECTOR is r, g, b. A MATRIX is 3 x 3, A[o*3 + i], row o = the component going out, column i = the
 * component coming in: a re-radiation matrix reduced to rgb (gcolormodel_reduce_reradiation), so that blue light
 * falling on a day-glo orange comes back red. A vector v stands for diag(v). The operations follow bispectral's:
 *   add    V+V, M+M per entry; a matrix and a vector give A + diag(v).
 *   mul    V*V per component; M*M the product A B; V*M diag(a) B; M*V the light A v (a vector on the right is a
 *          light).
 *   scale, axpy  per entry.  div, pow, exp: the diagonals, a vector (a medium absorbs, it does not fluoresce).
 *   brightness  M: that of its response to white with entries taken by magnitude, sum_o w_o sum_i |A[o][i]|.
 *   to_nm, to_xyz  M: its response to white, A (1, 1, 1), read in the role asked for.
 * The vector paths are the same operations as before matrices existed, so vector values are unchanged. */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"
#include "generic/kit/spectral_kernels.h"
#include "generic/color.h"

#include <math.h>
#include <string.h>

static int rgb_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)opt;
    (void)err;
    self->nvalues = 3;
    self->capacity = 9; /* room for a 3 x 3 re-radiation matrix */
    return G_OK;
}

/* ---- matrices ---- */

/* a as a 3 x 3 matrix: itself, or diag(a) for a vector */
static void as_matrix(const GColor *a, float m[9])
{
    if (a->kind == GCOLOR_MATRIX) {
        memcpy(m, a->v, 9 * sizeof *m);
        return;
    }
    memset(m, 0, 9 * sizeof *m);
    m[0] = a->v[0], m[4] = a->v[1], m[8] = a->v[2];
}

/* the component-wise part: a vector itself, a matrix its diagonal */
static void diagonal(const GColor *a, float d[3])
{
    for (int k = 0; k < 3; k++)
        d[k] = a->kind == GCOLOR_MATRIX ? a->v[k * 4] : a->v[k];
}

/* response to white (1, 1, 1): a vector itself, a matrix its row sums */
static void fold(const GColor *a, double d[3])
{
    for (int o = 0; o < 3; o++)
        d[o] = a->kind == GCOLOR_MATRIX ? (double)a->v[o * 3] + a->v[o * 3 + 1] + a->v[o * 3 + 2] : a->v[o];
}

static void set_matrix(GColor *out, const float m[9])
{
    memcpy(out->v, m, 9 * sizeof *m);
    out->kind = GCOLOR_MATRIX;
}

static int rgb_add_matrix(GColor *out, const GColor *a, const GColor *b)
{
    float x[9], y[9];
    as_matrix(a, x);
    as_matrix(b, y);
    for (int k = 0; k < 9; k++)
        x[k] += y[k];
    set_matrix(out, x);
    return G_OK;
}

static int rgb_mul_matrix(GColor *out, const GColor *a, const GColor *b)
{
    if (b->kind == GCOLOR_VECTOR) { /* the light A b */
        float l[3] = {b->v[0], b->v[1], b->v[2]}, x[9];
        as_matrix(a, x);
        for (int o = 0; o < 3; o++)
            out->v[o] = x[o * 3] * l[0] + x[o * 3 + 1] * l[1] + x[o * 3 + 2] * l[2];
        out->kind = GCOLOR_VECTOR;
        return G_OK;
    }
    float x[9], y[9], p[9];
    as_matrix(a, x);
    as_matrix(b, y);
    for (int o = 0; o < 3; o++)
        for (int i = 0; i < 3; i++)
            p[o * 3 + i] = x[o * 3] * y[i] + x[o * 3 + 1] * y[3 + i] + x[o * 3 + 2] * y[6 + i];
    set_matrix(out, p);
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
    if (a->kind == GCOLOR_MATRIX || b->kind == GCOLOR_MATRIX)
        return rgb_add_matrix(out, a, b);
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] + b->v[0];
    out->v[1] = a->v[1] + b->v[1];
    out->v[2] = a->v[2] + b->v[2];
    return G_OK;
}

static int rgb_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    if (a->kind == GCOLOR_MATRIX || b->kind == GCOLOR_MATRIX)
        return rgb_mul_matrix(out, a, b);
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
    if (a->kind == GCOLOR_MATRIX) {
        for (int k = 0; k < 9; k++)
            out->v[k] = a->v[k] * f;
        out->kind = GCOLOR_MATRIX;
        return G_OK;
    }
    out->kind = GCOLOR_VECTOR;
    out->v[0] = a->v[0] * f;
    out->v[1] = a->v[1] * f;
    out->v[2] = a->v[2] * f;
    return G_OK;
}

static int rgb_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    float x[3], y[3];
    diagonal(a, x);
    diagonal(b, y);
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = y[i] != 0.0f ? x[i] / y[i] : 0.0f;
    return G_OK;
}

static int rgb_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    (void)m;
    float x[3];
    diagonal(a, x);
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = x[i] > 0.0f ? (float)pow(x[i], e) : (e == 0.0 ? 1.0f : 0.0f);
    return G_OK;
}

/* out = s a + b: two vectors as the library's default (the kit's kernel); otherwise per entry, a vector standing
 * for diag(v) */
static int rgb_axpy(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b)
{
    (void)m;
    if (a->kind == GCOLOR_VECTOR && b->kind == GCOLOR_VECTOR) {
        gspectral_kaxpyd(out->v, s, a->v, b->v, 3);
        out->kind = GCOLOR_VECTOR;
        return G_OK;
    }
    float x[9], y[9];
    as_matrix(a, x);
    as_matrix(b, y);
    for (int k = 0; k < 9; k++)
        x[k] = y[k] + (float)(x[k] * s);
    set_matrix(out, x);
    return G_OK;
}

/* exp(s a) per component of the diagonal (a medium absorbs, it does not fluoresce): for a vector the library's
 * default, computed the same way */
static int rgb_exp_scaled(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    (void)m;
    float x[3];
    diagonal(a, x);
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < 3; i++)
        out->v[i] = (float)exp(s * x[i]);
    return G_OK;
}

static double rgb_brightness(const GColorModel *m, const GColor *a)
{
    (void)m;
    if (a->kind == GCOLOR_MATRIX) {
        double w[3] = {0.2126729, 0.7151522, 0.0721750}, b = 0.0;
        for (int o = 0; o < 3; o++)
            b += w[o] * (fabsf(a->v[o * 3]) + fabsf(a->v[o * 3 + 1]) + fabsf(a->v[o * 3 + 2]));
        return b;
    }
    return 0.2126729 * fabsf(a->v[0]) + 0.7151522 * fabsf(a->v[1]) + 0.0721750 * fabsf(a->v[2]);
}

static int rgb_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)m;
    double rgb[3];
    fold(a, rgb);
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
    double rgb[3];
    fold(a, rgb);
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

static int rgb_from_reradiation(const GColorModel *m, const GReradiation *r, GColor *out, GError *err)
{
    return gcolormodel_reduce_reradiation(m, r, out, err);
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
    .from_reradiation = rgb_from_reradiation,
    .exp_scaled = rgb_exp_scaled,
    .axpy = rgb_axpy,
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
