/* cie.c - CIE 1931 colorimetry on the 1 nm exchange grid: XYZ of spectra, sRGB matrices, illuminants,
 * blackbody, and RGB -> spectrum through the spectral primary basis (docs/reference/colour.md, "RGB to
 * spectrum"). */
#include "generic/color.h"
#include "cie_tables.h"
#include "colorspace_matrix.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

/* IEC 61966-2-1 linear sRGB <-> XYZ (D65). */
static const double RGB2XYZ[3][3] = {
    {0.4124564, 0.3575761, 0.1804375},
    {0.2126729, 0.7151522, 0.0721750},
    {0.0193339, 0.1191920, 0.9503041},
};

static struct {
    double sum_ybar;       /* sum of ybar over the 1 nm grid */
    double sum_d65_ybar;   /* sum of D65 * ybar */
    double sum_a_ybar;     /* sum of A * ybar */
    double sum_named_ybar[GCIE_NAMED]; /* sum of each named illuminant * ybar */
    double xyz2rgb[3][3];  /* inverse of RGB2XYZ */
    float basis[3][GNM_COUNT]; /* basis at 1 nm */
    double pinv[3][3];     /* inverse of the basis' own RGB matrix (makes the round trip exact) */
} T;

static pthread_once_t once = PTHREAD_ONCE_INIT;

/* out = m v (out may be v), as three scalars: copying out an array read it 16 bytes at a time right after its
 * 8-byte stores (a store-forwarding stall, twice per pixel; 0.985x a render's CPU in 7 timed pairs, near the
 * noise). */
static void mat3_apply(const double m[3][3], const double v[3], double out[3])
{
    double r0 = m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2];
    double r1 = m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2];
    double r2 = m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2];
    out[0] = r0;
    out[1] = r1;
    out[2] = r2;
}

static void init_tables(void)
{
    for (int i = 0; i < GNM_COUNT; i++) {
        T.sum_ybar += gcie_ybar[i];
        T.sum_d65_ybar += (double)gcie_d65[i] * gcie_ybar[i];
        T.sum_a_ybar += (double)gcie_a[i] * gcie_ybar[i];
        for (int k = 0; k < GCIE_NAMED; k++)
            T.sum_named_ybar[k] += (double)gcie_named_spd[k][i] * gcie_ybar[i];
    }
    gcolorspace_invert3(RGB2XYZ, T.xyz2rgb);
    const float *b5[3] = {gcie_basis_r, gcie_basis_g, gcie_basis_b};
    for (int i = 0; i < GNM_COUNT; i++) {
        int k = i / 5 < GCIE_N5 - 1 ? i / 5 : GCIE_N5 - 2;
        double t = (i - 5.0 * k) / 5.0;
        for (int c = 0; c < 3; c++)
            T.basis[c][i] = (float)((1.0 - t) * b5[c][k] + t * b5[c][k + 1]);
    }
    /* P[:, c] = sRGB of basis c as a reflectance; the round trip uses P^-1 so it is exact. */
    double p[3][3];
    for (int c = 0; c < 3; c++) {
        double xyz[3] = {0, 0, 0};
        for (int i = 0; i < GNM_COUNT; i++) {
            double w = (double)T.basis[c][i] * gcie_d65[i];
            xyz[0] += w * gcie_xbar[i];
            xyz[1] += w * gcie_ybar[i];
            xyz[2] += w * gcie_zbar[i];
        }
        for (int k = 0; k < 3; k++)
            xyz[k] /= T.sum_d65_ybar;
        double rgb[3];
        mat3_apply(T.xyz2rgb, xyz, rgb);
        for (int r = 0; r < 3; r++)
            p[r][c] = rgb[r];
    }
    gcolorspace_invert3(p, T.pinv);
}

static void ensure(void) { pthread_once(&once, init_tables); }

void gcie_rgb_to_xyz(const double rgb[3], double xyz[3]) { mat3_apply(RGB2XYZ, rgb, xyz); }

void gcie_xyz_to_rgb(const double xyz[3], double rgb[3])
{
    ensure();
    mat3_apply(T.xyz2rgb, xyz, rgb);
}

void gcie_nm_to_xyz(const GSpectrumNM *s, GColorRole role, double xyz[3])
{
    ensure();
    /* the samples outside the first and last that are not 0 add +0 or -0 to sums that start at +0, which leaves
     * them as they are: skipped (a model's tables are made from spectra of one sample, or a few) */
    int lo = 0, hi = GNM_COUNT;
    while (lo < hi && s->v[lo] == 0.0f)
        lo++;
    while (hi > lo && s->v[hi - 1] == 0.0f)
        hi--;
    double x = 0, y = 0, z = 0;
    if (role == GCOLOR_LIGHT) {
        for (int i = lo; i < hi; i++) {
            x += (double)s->v[i] * gcie_xbar[i];
            y += (double)s->v[i] * gcie_ybar[i];
            z += (double)s->v[i] * gcie_zbar[i];
        }
        xyz[0] = x / T.sum_ybar;
        xyz[1] = y / T.sum_ybar;
        xyz[2] = z / T.sum_ybar;
    } else {
        for (int i = lo; i < hi; i++) {
            double w = (double)s->v[i] * gcie_d65[i];
            x += w * gcie_xbar[i];
            y += w * gcie_ybar[i];
            z += w * gcie_zbar[i];
        }
        xyz[0] = x / T.sum_d65_ybar;
        xyz[1] = y / T.sum_d65_ybar;
        xyz[2] = z / T.sum_d65_ybar;
    }
}

void gcie_rgb_to_nm(const double rgb[3], GColorRole role, GSpectrumNM *out)
{
    ensure();
    double c[3];
    mat3_apply(T.pinv, rgb, c);
    double light = T.sum_ybar / T.sum_d65_ybar;
    for (int i = 0; i < GNM_COUNT; i++) {
        double v = c[0] * T.basis[0][i] + c[1] * T.basis[1][i] + c[2] * T.basis[2][i];
        if (role == GCOLOR_LIGHT)
            v *= gcie_d65[i] * light;
        out->v[i] = (float)v;
    }
}

void gcie_cmf(double nm, double xyz[3])
{
    xyz[0] = xyz[1] = xyz[2] = 0.0;
    if (!(nm >= GNM_MIN && nm <= GNM_MAX))
        return;
    double f = nm - GNM_MIN;
    int i = (int)f;
    if (i >= GNM_COUNT - 1)
        i = GNM_COUNT - 2;
    double t = f - i;
    xyz[0] = (1 - t) * gcie_xbar[i] + t * gcie_xbar[i + 1];
    xyz[1] = (1 - t) * gcie_ybar[i] + t * gcie_ybar[i + 1];
    xyz[2] = (1 - t) * gcie_zbar[i] + t * gcie_zbar[i + 1];
}

static double table_at(const float *tab, double nm)
{
    if (!(nm >= GNM_MIN && nm <= GNM_MAX))
        return 0.0;
    double f = nm - GNM_MIN;
    int i = (int)f;
    if (i >= GNM_COUNT - 1)
        i = GNM_COUNT - 2;
    double t = f - i;
    return (1 - t) * tab[i] + t * tab[i + 1];
}

double gcie_illuminant(const char *name, double nm)
{
    ensure();
    if (strcmp(name, "D65") == 0)
        return table_at(gcie_d65, nm) * T.sum_ybar / T.sum_d65_ybar;
    if (strcmp(name, "A") == 0)
        return table_at(gcie_a, nm) * T.sum_ybar / T.sum_a_ybar;
    if (strcmp(name, "E") == 0)
        return (nm >= GNM_MIN && nm <= GNM_MAX) ? 1.0 : 0.0;
    for (int k = 0; k < GCIE_NAMED; k++)
        if (strcmp(name, gcie_named_names[k]) == 0)
            return table_at(gcie_named_spd[k], nm) * T.sum_ybar / T.sum_named_ybar[k];
    return -1.0;
}

/* The illuminants in the order gcie_illuminant_name lists them: CIE order, A, B, C, the D series, E, F, LED. */
static const char *const ILLUMINANT_ORDER[] = {
    "A", "B", "C", "D50", "D55", "D65", "D75", "E", "F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10",
    "F11", "F12", "LED-B1", "LED-B2", "LED-B3", "LED-B4", "LED-B5", "LED-BH1", "LED-RGB1", "LED-V1", "LED-V2",
};

const char *gcie_illuminant_name(int i)
{
    int n = (int)(sizeof ILLUMINANT_ORDER / sizeof *ILLUMINANT_ORDER);
    return i >= 0 && i < n ? ILLUMINANT_ORDER[i] : NULL;
}

int gcie_illuminant_nm(const char *name, GSpectrumNM *out)
{
    int known = 0;
    for (int i = 0; name && gcie_illuminant_name(i); i++)
        known |= strcmp(name, gcie_illuminant_name(i)) == 0;
    if (!known)
        return G_ERR_NOTFOUND;
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = (float)gcie_illuminant(name, GNM_MIN + i);
    return G_OK;
}

void gcie_blackbody_nm(double kelvin, GSpectrumNM *out)
{
    ensure();
    const double c1 = 3.741771852e-16, c2 = 1.438776877e-2;
    double y = 0.0;
    for (int i = 0; i < GNM_COUNT; i++) {
        double l = (GNM_MIN + i) * 1e-9;
        double v = c1 / (pow(l, 5.0) * expm1(c2 / (l * kelvin)));
        out->v[i] = (float)v;
        y += v * gcie_ybar[i];
    }
    double k = y > 0 ? T.sum_ybar / y : 0.0;
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = (float)(out->v[i] * k);
}

double gcie_luminance_weight(int nm_index)
{
    ensure();
    if (nm_index < 0 || nm_index >= GNM_COUNT)
        return 0.0;
    return gcie_ybar[nm_index] / T.sum_ybar;
}
