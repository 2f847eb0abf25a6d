/* sh.c - spherical harmonics of any order up to GPROBE_SH_MAX_ORDER (L1..L4), their projection, irradiance
 * and Hanning window; the nine of order 2 equal sh9.c's (test_probe_basis checks it).
 *
 * Real harmonics without the Condon-Shortley phase: Y_lm = K_lm sqrt2 cos(m phi) P_l^m(cos theta) for m > 0,
 * K_l0 P_l(cos theta) for m = 0, K_l|m| sqrt2 sin(|m| phi) P_l^|m| for m < 0, K_lm = sqrt((2l + 1) / 4 pi
 * (l - m)! / (l + m)!). The sin^m theta of P_l^m and the cos / sin (m phi) are taken together as the real and
 * imaginary part of (x + i y)^m, so the basis is a polynomial in the direction and needs no trigonometry.
 * Irradiance convolves with the clamped cosine, whose bands are A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4,
 * A_3 = 0, A_4 = -pi / 24 (Ramamoorthi & Hanrahan 2001, Eq. 8). */
#include "probe_internal.h"

#include <string.h>

static const double band_A[GPROBE_SH_MAX_ORDER + 1] = {M_PI, 2.0 * M_PI / 3.0, M_PI / 4.0, 0.0, -M_PI / 24.0};

static double factorial(int n)
{
    double f = 1.0;
    for (int i = 2; i <= n; i++)
        f *= i;
    return f;
}

void gprobe_sh_basis(int order, GVec3 d, double *y)
{
    if (order < 0)
        return;
    if (order > GPROBE_SH_MAX_ORDER)
        order = GPROBE_SH_MAX_ORDER;
    double z = d.z, re = 1.0, im = 0.0; /* (x + i y)^m */
    for (int m = 0; m <= order; m++) {
        /* P~_l^m = P_l^m / sin^m theta, by the recurrence in l */
        double pmm = 1.0;
        for (int i = 1; i <= m; i++)
            pmm *= 2 * i - 1;
        double p_prev = 0.0, p = pmm;
        for (int l = m; l <= order; l++) {
            if (l == m + 1) {
                p_prev = pmm;
                p = z * (2 * m + 1) * pmm;
            } else if (l > m + 1) {
                double next = ((2 * l - 1) * z * p - (l + m - 1) * p_prev) / (l - m);
                p_prev = p;
                p = next;
            }
            double k = sqrt((2 * l + 1) / (4.0 * M_PI) * factorial(l - m) / factorial(l + m));
            if (m == 0) {
                y[l * (l + 1)] = k * p;
            } else {
                y[l * (l + 1) + m] = M_SQRT2 * k * p * re;
                y[l * (l + 1) - m] = M_SQRT2 * k * p * im;
            }
        }
        double nre = re * d.x - im * d.y, nim = re * d.y + im * d.x;
        re = nre;
        im = nim;
    }
}

int gprobe_sh_project(const GProbe *p, int order, GProbeSH *sh, GError *err)
{
    if (!p || !sh)
        return gerror_set(err, G_ERR_INVALID, "gprobe_sh_project: no probe or output given");
    if (order < 1 || order > GPROBE_SH_MAX_ORDER)
        return gerror_set(err, G_ERR_INVALID, "spherical harmonics of order %d: expected 1..%d", order,
                          GPROBE_SH_MAX_ORDER);
    memset(sh, 0, sizeof *sh);
    sh->order = order;
    const int nc = GPROBE_SH_COEFFS(order);
    for (int v = 0; v < p->h; v++) {
        double row[GPROBE_SH_COEFFS(GPROBE_SH_MAX_ORDER)][3];
        memset(row, 0, sizeof row);
        for (int u = 0; u < p->w; u++) {
            const float *q = p->q + ((size_t)v * p->w + u) * 3; /* Q = P times the pixel's solid angle */
            double y[GPROBE_SH_COEFFS(GPROBE_SH_MAX_ORDER)];
            gprobe_sh_basis(order, probe_pixel_dir(p, u, v), y);
            for (int k = 0; k < nc; k++)
                for (int c = 0; c < 3; c++)
                    row[k][c] += y[k] * q[c];
        }
        for (int k = 0; k < nc; k++)
            for (int c = 0; c < 3; c++)
                sh->c[k][c] += row[k][c];
    }
    return G_OK;
}

void gprobe_sh_window_hanning(GProbeSH *sh)
{
    for (int l = 1; l <= sh->order; l++) {
        double w = 0.5 * (1.0 + cos(M_PI * l / (2 * sh->order + 1)));
        for (int k = l * l; k < (l + 1) * (l + 1); k++)
            for (int c = 0; c < 3; c++)
                sh->c[k][c] *= w;
    }
}

void gprobe_sh_irradiance(const GProbeSH *sh, const GVec3 *normals, int m, double *E)
{
    int order = sh->order < 0 ? 0 : sh->order > GPROBE_SH_MAX_ORDER ? GPROBE_SH_MAX_ORDER : sh->order;
    for (int i = 0; i < m; i++) {
        double y[GPROBE_SH_COEFFS(GPROBE_SH_MAX_ORDER)];
        gprobe_sh_basis(order, normals[i], y);
        for (int c = 0; c < 3; c++) {
            double e = 0.0;
            for (int l = 0; l <= order; l++)
                for (int k = l * l; k < (l + 1) * (l + 1); k++)
                    e += band_A[l] * sh->c[k][c] * y[k];
            E[i * 3 + c] = e;
        }
    }
}

void gprobe_sh_radiance(const GProbeSH *sh, GVec3 d, double rgb[3])
{
    int order = sh->order < 0 ? 0 : sh->order > GPROBE_SH_MAX_ORDER ? GPROBE_SH_MAX_ORDER : sh->order;
    double y[GPROBE_SH_COEFFS(GPROBE_SH_MAX_ORDER)];
    gprobe_sh_basis(order, d, y);
    for (int c = 0; c < 3; c++) {
        double e = 0.0;
        for (int k = 0; k < GPROBE_SH_COEFFS(order); k++)
            e += sh->c[k][c] * y[k];
        rgb[c] = e;
    }
}
