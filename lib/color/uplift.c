/* uplift.c - sigmoid uplifting (generic/colorspace.h): table lookup with trilinear interpolation, the three
 * forms (bounded reflectance, scaled reflectance, light), and the spectrum on the nm exchange grid refined against
 * the 1 nm CIE tables. The tables are the build's (build/gen/uplift_tables.c, lib/color/uplift_tables.h). */
#include "generic/colorspace.h"
#include "colorspace_matrix.h"
#include "uplift.h"
#include "uplift_fit.h"
#include "uplift_tables.h"
#include "generic/kit/spectral_kernels.h"

#include <math.h>
#include <pthread.h>
#include <string.h>

static struct {
    double srgb_to[GUPLIFT_TABLES][3][3]; /* linear sRGB -> table space */
    double to_xyz[GUPLIFT_TABLES][3][3];  /* table space -> XYZ */
    double u[GNM_COUNT], w[3][GNM_COUNT], white[3]; /* the 1 nm discretisation, reflectance under D65 */
} U;

static pthread_once_t once = PTHREAD_ONCE_INIT, once_nm = PTHREAD_ONCE_INIT;

/* The table spaces' matrices (every uplift needs them). */
static void init_uplift(void)
{
    static const int space[GUPLIFT_TABLES] = {GCOLORSPACE_SRGB, GCOLORSPACE_REC2020, GCOLORSPACE_ACES2065_1};
    double srgb[3][3], inv[3][3];
    gcolorspace_matrix(GCOLORSPACE_SRGB, srgb);
    for (int t = 0; t < GUPLIFT_TABLES; t++) {
        gcolorspace_matrix(space[t], U.to_xyz[t]);
        gcolorspace_invert3(U.to_xyz[t], inv);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                U.srgb_to[t][r][c] = inv[r][0] * srgb[0][c] + inv[r][1] * srgb[1][c] + inv[r][2] * srgb[2][c];
    }
}

/* The 1 nm discretisation (guplift_rgb_to_nm alone needs it). */
static void init_uplift_nm(void)
{
    GSpectrumNM e;
    for (int i = 0; i < GNM_COUNT; i++)
        e.v[i] = 0.0f;
    for (int i = 0; i < GNM_COUNT; i++) {
        double xyz[3];
        e.v[i] = 1.0f;
        gcie_nm_to_xyz(&e, GCOLOR_REFLECTANCE, xyz);
        e.v[i] = 0.0f;
        U.u[i] = (GNM_MIN + i - GUPLIFT_NM0) / GUPLIFT_NM_SPAN;
        for (int c = 0; c < 3; c++) {
            U.w[c][i] = xyz[c];
            U.white[c] += xyz[c];
        }
    }
}

/* The largest z_k <= z (k < res - 1). */
static int z_interval(float z)
{
    int lo = 0, hi = guplift_res - 2;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (guplift_z[mid] <= z)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* Coefficients of rgb (components in [0, 1], not all 0) in table t. */
static void lookup(int t, const double rgb[3], double c[3])
{
    int l = rgb[0] >= rgb[1] ? (rgb[0] >= rgb[2] ? 0 : 2) : (rgb[1] >= rgb[2] ? 1 : 2);
    int res = guplift_res;
    double z = rgb[l], sx = (res - 1) / z;
    double x = rgb[(l + 1) % 3] * sx, y = rgb[(l + 2) % 3] * sx;
    int xi = (int)x, yi = (int)y, zi = z_interval((float)z);
    if (xi > res - 2)
        xi = res - 2;
    if (yi > res - 2)
        yi = res - 2;
    double fx = x - xi, fy = y - yi, fz = (z - guplift_z[zi]) / (guplift_z[zi + 1] - guplift_z[zi]);
    for (int a = 0; a < 3; a++)
        c[a] = 0.0;
    for (int dz = 0; dz < 2; dz++)
        for (int dy = 0; dy < 2; dy++)
            for (int dx = 0; dx < 2; dx++) {
                double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy) * (dz ? fz : 1.0 - fz);
                const float *p = guplift_coeffs + guplift_table_index(res, t, l, zi + dz, yi + dy, xi + dx);
                for (int a = 0; a < 3; a++)
                    c[a] += w * p[a];
            }
}

static void apply(const double m[3][3], const double v[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    for (int i = 0; i < 3; i++)
        out[i] = r[i];
}

int guplift_from_rgb(const double srgb[3], GColorRole role, GUplift *out)
{
    if (!isfinite(srgb[0]) || !isfinite(srgb[1]) || !isfinite(srgb[2]))
        return G_ERR_INVALID;
    pthread_once(&once, init_uplift);
    int t = 0;
    double v[3];
    for (t = 0; t < GUPLIFT_TABLES; t++) {
        if (t == GUPLIFT_TABLE_SRGB)
            v[0] = srgb[0], v[1] = srgb[1], v[2] = srgb[2];
        else
            apply(U.srgb_to[t], srgb, v);
        if (t == GUPLIFT_TABLES - 1 || (v[0] >= -1e-9 && v[1] >= -1e-9 && v[2] >= -1e-9))
            break;
    }
    double m = 0.0;
    for (int i = 0; i < 3; i++) {
        v[i] = v[i] > 0.0 ? v[i] : 0.0;
        m = fmax(m, v[i]);
    }
    out->light = role == GCOLOR_LIGHT;
    out->scale = out->light || m > 1.0 + 1e-9 ? 2.0 * m : 1.0;
    if (out->scale == 1.0)
        for (int i = 0; i < 3; i++)
            v[i] = fmin(v[i], 1.0);
    if (m > 0.0 && out->scale != 1.0)
        for (int i = 0; i < 3; i++)
            v[i] /= out->scale;
    apply(U.to_xyz[t], v, out->xyz);
    out->c[0] = out->c[1] = 0.0;
    if (v[0] == v[1] && v[1] == v[2]) /* grey: S(c2) = v exactly */
        out->c[2] = v[0] <= 0.0 ? -INFINITY : v[0] >= 1.0 ? INFINITY : (v[0] - 0.5) / sqrt(v[0] * (1.0 - v[0]));
    else
        lookup(t, v, out->c);
    return G_OK;
}

double guplift_sigmoid_at(const GUplift *u, double x)
{
    return u->scale * guplift_sigmoid((u->c[0] * x + u->c[1]) * x + u->c[2]);
}

void guplift_sigmoid_samples_scalar(const GUplift *u, int n, const double *x, const double *f, float *out)
{
    for (int k = 0; k < n; k++)
        out[k] = (float)(guplift_sigmoid_at(u, x[k]) * f[k]);
}

#ifdef GSPECTRAL_AVX2
typedef double upl_v4d __attribute__((vector_size(32)));
typedef long long upl_v4l __attribute__((vector_size(32)));

/* guplift_sigmoid_samples_scalar on 4 samples a vector: the same operations (guplift_sigmoid's, then the scale and
 * f, then the rounding to float), so the same bits; an infinite polynomial gives S's limits as guplift_sigmoid does. */
static GSPECTRAL_TARGET_AVX2 void sigmoid_samples_avx2(const GUplift *u, int n, const double *x, const double *f,
                                                       float *out)
{
    const upl_v4d c0 = {u->c[0], u->c[0], u->c[0], u->c[0]}, c1 = {u->c[1], u->c[1], u->c[1], u->c[1]};
    const upl_v4d c2 = {u->c[2], u->c[2], u->c[2], u->c[2]}, scale = {u->scale, u->scale, u->scale, u->scale};
    const upl_v4d one = {1, 1, 1, 1}, half = {0.5, 0.5, 0.5, 0.5}, zero = {0, 0, 0, 0};
    const upl_v4d inf = {INFINITY, INFINITY, INFINITY, INFINITY};
    int k = 0;
    for (; k + 4 <= n; k += 4) {
        upl_v4d xv, fv;
        memcpy(&xv, x + k, sizeof xv);
        memcpy(&fv, f + k, sizeof fv);
        upl_v4d p = (c0 * xv + c1) * xv + c2;
        upl_v4d sig = half + half * p / (upl_v4d)_mm256_sqrt_pd((__m256d)(one + p * p));
        upl_v4l infinite = (p == inf) | (p == -inf);
        upl_v4d limit = (upl_v4d)((upl_v4l)one & (p > zero));
        sig = (upl_v4d)(((upl_v4l)limit & infinite) | ((upl_v4l)sig & ~infinite));
        __m128 r = _mm256_cvtpd_ps((__m256d)(scale * sig * fv));
        memcpy(out + k, &r, sizeof r);
    }
    guplift_sigmoid_samples_scalar(u, n - k, x + k, f + k, out + k);
}
#endif

void guplift_sigmoid_samples(const GUplift *u, int n, const double *x, const double *f, float *out)
{
#ifdef GSPECTRAL_AVX2
    if (__builtin_cpu_supports("avx2")) {
        sigmoid_samples_avx2(u, n, x, f, out);
        return;
    }
#endif
    guplift_sigmoid_samples_scalar(u, n, x, f, out);
}

double guplift_value(const GUplift *u, double nm)
{
    double s = guplift_sigmoid_at(u, (nm - GUPLIFT_NM0) / GUPLIFT_NM_SPAN);
    return u->light ? s * gcie_illuminant("D65", nm) : s;
}

int guplift_refine(GUplift *u, int n, const double *x, const double *const w[3], const double white[3],
                   double *delta_e)
{
    if (u->c[0] == 0.0 && u->c[1] == 0.0 && isinf(u->c[2])) { /* black or white: exact already */
        if (delta_e)
            *delta_e = 0.0;
        return G_OK;
    }
    GUpliftFit f = {n, x, {w[0], w[1], w[2]}, {0, 0, 0}};
    for (int c = 0; c < 3; c++) {
        if (white)
            f.white[c] = white[c];
        else
            for (int k = 0; k < n; k++)
                f.white[c] += w[c][k];
    }
    double d = guplift_fit_solve(&f, u->xyz, u->c, 20, 2e-5);
    if (delta_e)
        *delta_e = d;
    return G_OK;
}

int guplift_rgb_to_nm(const double srgb[3], GColorRole role, GSpectrumNM *out, double *delta_e)
{
    GUplift u;
    int rc = guplift_from_rgb(srgb, role, &u);
    if (rc != G_OK)
        return rc;
    pthread_once(&once_nm, init_uplift_nm);
    const double *w[3] = {U.w[0], U.w[1], U.w[2]};
    rc = guplift_refine(&u, GNM_COUNT, U.u, w, U.white, delta_e);
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = (float)guplift_value(&u, GNM_MIN + i);
    return rc;
}
