/* spectrum9.c - nine spectral samples at 380, 430, ..., 780 nm (the four-sample spline model of
 * Stürzlinger's example, with more samples). A value is 9 floats; operations work sample by sample.
 *
 * to_nm reconstructs the natural cubic spline through the nine samples (second derivative 0 at both
 * ends), evaluated from a table of the nine cardinal splines at every nm built once. from_nm samples
 * with the hat-weighted average of half-width 50 nm (include/generic/kit/spectral.h): each nm hands its energy to
 * the two samples around it in proportion to its distance, so a narrow emission line is kept with its
 * full energy instead of being missed between samples, and a constant stays constant. Sampling then
 * reconstructing smooths a spectrum (features narrower than ~100 nm are lost): this model trades
 * accuracy for size: the hat-sampled spectral primaries come back up to 0.12 off in RGB. from_rgb is
 * therefore corrected to be exact (include/generic/kit/spectral.h), at a price: saturated reflectances get samples
 * outside [0, 1] (down to -0.13 and up to 1.13 for the sRGB primaries), which nine spline samples need
 * to reach their chroma. The grid is fixed; options other than its own values are refused. */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"

#include <math.h>

enum { N9 = 9 };

typedef struct Spectrum9 {
    GSpectral s;
    float spline[GNM_COUNT][N9]; /* cardinal natural splines at every nm */
    float project[N9][GNM_COUNT]; /* least squares: the samples whose spline is nearest an nm spectrum */
} Spectrum9;

/* project = (S^T S)^-1 S^T for the spline matrix S (GNM_COUNT x 9), by Gauss-Jordan on the 9 x 9 normal matrix
 * (symmetric positive definite: the cardinal splines are independent). */
static void build_projection(Spectrum9 *p)
{
    double a[N9][2 * N9];
    for (int r = 0; r < N9; r++)
        for (int c = 0; c < N9; c++) {
            double sum = 0.0;
            for (int i = 0; i < GNM_COUNT; i++)
                sum += (double)p->spline[i][r] * p->spline[i][c];
            a[r][c] = sum;
            a[r][N9 + c] = r == c;
        }
    for (int c = 0; c < N9; c++) {
        int piv = c;
        for (int r = c + 1; r < N9; r++)
            if (fabs(a[r][c]) > fabs(a[piv][c]))
                piv = r;
        for (int k = 0; k < 2 * N9; k++) {
            double t = a[c][k];
            a[c][k] = a[piv][k];
            a[piv][k] = t;
        }
        double d = a[c][c];
        for (int k = 0; k < 2 * N9; k++)
            a[c][k] /= d;
        for (int r = 0; r < N9; r++)
            if (r != c) {
                double f = a[r][c];
                for (int k = 0; k < 2 * N9; k++)
                    a[r][k] -= f * a[c][k];
            }
    }
    for (int k = 0; k < N9; k++)
        for (int i = 0; i < GNM_COUNT; i++) {
            double sum = 0.0;
            for (int j = 0; j < N9; j++)
                sum += a[k][N9 + j] * p->spline[i][j];
            p->project[k][i] = (float)sum;
        }
}

/* Natural cubic spline through y at x_i = i * h: second derivatives M with M_0 = M_{n-1} = 0 solve
 * M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i-1} - 2 y_i + y_{i+1}) / h^2 (Thomas algorithm). */
static void natural_spline_m(const double y[N9], double h, double mm[N9])
{
    double c[N9], d[N9];
    mm[0] = mm[N9 - 1] = 0.0;
    c[0] = d[0] = 0.0;
    for (int i = 1; i < N9 - 1; i++) {
        double rhs = 6.0 * (y[i - 1] - 2.0 * y[i] + y[i + 1]) / (h * h);
        double den = 4.0 - c[i - 1];
        c[i] = 1.0 / den;
        d[i] = (rhs - d[i - 1]) / den;
    }
    for (int i = N9 - 2; i >= 1; i--)
        mm[i] = d[i] - c[i] * mm[i + 1];
}

static void build_spline(Spectrum9 *p, GSpectralGrid g)
{
    for (int k = 0; k < N9; k++) {
        double y[N9] = {0}, mm[N9];
        y[k] = 1.0;
        natural_spline_m(y, g.step, mm);
        for (int i = 0; i < GNM_COUNT; i++) {
            double f = (GNM_MIN + i - g.min) / g.step;
            int j = (int)f;
            if (j > N9 - 2)
                j = N9 - 2;
            double t = f - j, u = 1.0 - t, h2 = g.step * g.step / 6.0;
            p->spline[i][k] =
                (float)(u * y[j] + t * y[j + 1] + h2 * ((u * u * u - u) * mm[j] + (t * t * t - t) * mm[j + 1]));
        }
    }
}

static int spectrum9_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    GSpectralGrid grid = {380.0, 50.0, N9};
    int rc = gspectral_grid_check_fixed("spectrum9", opt, grid, err);
    if (rc == G_OK)
        rc = gspectral_model_alloc(self, sizeof(Spectrum9), N9, err);
    if (rc != G_OK)
        return rc;
    Spectrum9 *p = self->priv;
    build_spline(p, grid);
    build_projection(p);
    rc = gspectral_init(self, &p->s, grid, 0, err);
    return rc == G_OK ? gspectral_set_uplift(self, &p->s, opt, err) : rc;
}

static int spectrum9_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)role;
    const Spectrum9 *p = m->priv;
    const float *v = a->v;
    for (int i = 0; i < GNM_COUNT; i++) {
        const float *w = p->spline[i];
        float s = 0.0f;
        for (int k = 0; k < N9; k++)
            s += w[k] * v[k];
        out->v[i] = s;
    }
    return G_OK;
}

/* The least-squares samples of the spline nearest the spectrum, then the rest of its XYZ in the role through the
 * corrected RGB basis (the exact correction from_rgb's basis has): the spectrum's colour is kept exactly, a light's
 * as a light and a reflectance's under D65; a light that would need a negative sample (a narrow line) keeps its
 * luminance and as much of its colour as non-negative samples hold instead. */
static int spectrum9_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    const Spectrum9 *p = m->priv;
    out->kind = GCOLOR_VECTOR;
    for (int k = 0; k < N9; k++) {
        double sum = 0.0;
        for (int i = 0; i < GNM_COUNT; i++)
            sum += (double)p->project[k][i] * in->v[i];
        out->v[k] = (float)sum;
    }
    double want[3], got[3], dx[3], rgb[3];
    gcie_nm_to_xyz(in, role, want);
    int rc = gspectral_to_xyz(m, out, role, got);
    if (rc != G_OK)
        return rc;
    for (int c = 0; c < 3; c++)
        dx[c] = want[c] - got[c];
    gcie_xyz_to_rgb(dx, rgb);
    const float *b = p->s.rgb[role == GCOLOR_LIGHT];
    float d[N9];
    int negative = 0;
    for (int k = 0; k < N9; k++) {
        d[k] = (float)(rgb[0] * b[k] + rgb[1] * b[N9 + k] + rgb[2] * b[2 * N9 + k]);
        out->v[k] += d[k];
        negative |= out->v[k] < 0.0f;
    }
    if (!negative || role != GCOLOR_LIGHT)
        return G_OK; /* a reflectance keeps its colour; the parameter range rule judges its samples */
    /* a light beyond what nine non-negative samples hold (a narrow line): from its least-squares samples with the
     * negative ones set to 0, as much of the correction to its XYZ as keeps every sample >= 0, then its luminance */
    for (int k = 0; k < N9; k++) {
        double sum = 0.0;
        for (int i = 0; i < GNM_COUNT; i++)
            sum += (double)p->project[k][i] * in->v[i];
        out->v[k] = sum > 0.0 ? (float)sum : 0.0f;
    }
    if ((rc = gspectral_to_xyz(m, out, role, got)) != G_OK)
        return rc;
    for (int c = 0; c < 3; c++)
        dx[c] = want[c] - got[c];
    gcie_xyz_to_rgb(dx, rgb);
    double t = 1.0;
    for (int k = 0; k < N9; k++) {
        d[k] = (float)(rgb[0] * b[k] + rgb[1] * b[N9 + k] + rgb[2] * b[2 * N9 + k]);
        if (d[k] < 0.0f && out->v[k] + d[k] < 0.0f)
            t = fmin(t, out->v[k] > 0.0f ? out->v[k] / -d[k] : 0.0);
    }
    for (int k = 0; k < N9; k++)
        out->v[k] = fmaxf(0.0f, (float)(out->v[k] + t * d[k]));
    if ((rc = gspectral_to_xyz(m, out, role, got)) != G_OK)
        return rc;
    if (want[1] > 0.0 && got[1] > 0.0)
        for (int k = 0; k < N9; k++)
            out->v[k] = (float)(out->v[k] * (want[1] / got[1]));
    return G_OK;
}

static const GColorModelClass gcolormodel_spectrum9 = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "spectrum9",
    .description = "9 samples 380..780 nm every 50 nm, natural cubic spline in between",
    .init = spectrum9_init,
    .fini = gspectral_model_fini,
    .black = gspectral_black,
    .add = gspectral_add,
    .mul = gspectral_mul,
    .scale = gspectral_scale,
    .div = gspectral_div,
    .pow = gspectral_pow,
    .brightness = gspectral_brightness,
    .to_nm = spectrum9_to_nm,
    .from_nm = spectrum9_from_nm,
    .to_xyz = gspectral_to_xyz,
    .from_rgb = gspectral_from_rgb,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

/* The grid is fixed: the options may only repeat it. */
static const GParamInfo spectrum9_params[] = {
    {"step", GPARAM_NAMED, "number", "50", "50", "the spacing of the samples, in nm (fixed; another is refused)"},
    {"min", GPARAM_NAMED, "number", "380", "380", "the first sample, in nm (fixed)"},
    {"max", GPARAM_NAMED, "number", "780", "780", "the last sample, in nm (fixed)"},
    {"uplift", GPARAM_NAMED, "choice", "sigmoid", "sigmoid, basis",
     "how RGB colours become spectra: sigmoid (smooth, a reflectance within [0, 1]) or basis (the exact linear basis)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(spectrum9, GKIND_COLORMODEL, &gcolormodel_spectrum9, NULL, NULL, spectrum9_params);
