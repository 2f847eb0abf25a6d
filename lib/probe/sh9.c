/* sh9.c - irradiance from nine spherical harmonics (Ramamoorthi & Hanrahan, "An Efficient Representation
 * for Irradiance Environment Maps", SIGGRAPH 2001): project the radiance onto the real harmonics of order
 * l <= 2, then E(n) = sum_lm A_l L_lm Y_lm(n) with A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4. */
#include "probe_internal.h"

#include <string.h>

static void sh9_basis(GVec3 d, double y[9])
{
    y[0] = 0.282094791773878;
    y[1] = 0.488602511902920 * d.y;
    y[2] = 0.488602511902920 * d.z;
    y[3] = 0.488602511902920 * d.x;
    y[4] = 1.092548430592079 * d.x * d.y;
    y[5] = 1.092548430592079 * d.y * d.z;
    y[6] = 0.315391565252520 * (3.0 * d.z * d.z - 1.0);
    y[7] = 1.092548430592079 * d.x * d.z;
    y[8] = 0.546274215296040 * (d.x * d.x - d.y * d.y);
}

void gprobe_sh9_project(const GProbe *p, GProbeSH9 *sh)
{
    memset(sh, 0, sizeof *sh);
    for (int v = 0; v < p->h; v++) {
        double row[9][3];
        memset(row, 0, sizeof row);
        for (int u = 0; u < p->w; u++) {
            const float *q = p->q + ((size_t)v * p->w + u) * 3; /* Q = P times the pixel's solid angle */
            double y[9];
            sh9_basis(probe_pixel_dir(p, u, v), y);
            for (int k = 0; k < 9; k++)
                for (int c = 0; c < 3; c++)
                    row[k][c] += y[k] * q[c];
        }
        for (int k = 0; k < 9; k++)
            for (int c = 0; c < 3; c++)
                sh->c[k][c] += row[k][c];
    }
}

void gprobe_sh9_irradiance(const GProbeSH9 *sh, const GVec3 *normals, int m, double *E)
{
    static const double A[9] = {M_PI, 2.0 * M_PI / 3.0, 2.0 * M_PI / 3.0, 2.0 * M_PI / 3.0,
                                M_PI / 4.0, M_PI / 4.0, M_PI / 4.0, M_PI / 4.0, M_PI / 4.0};
    for (int i = 0; i < m; i++) {
        double y[9];
        sh9_basis(normals[i], y);
        for (int c = 0; c < 3; c++) {
            double e = 0.0;
            for (int k = 0; k < 9; k++)
                e += A[k] * sh->c[k][c] * y[k];
            E[i * 3 + c] = e;
        }
    }
}
