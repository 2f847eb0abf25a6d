/* ambient_cube.c - the ambient cube (McTaggart, "Half-Life 2 / Valve Source Shading", GDC 2004): six colours
 * on the +-x, +-y, +-z axes blended by the squared components of the normal. It stores irradiance, so it is
 * fitted to the ground-truth irradiance: least squares over fit normals spread evenly on the sphere (the
 * six unknowns share one 6 x 6 system for the three channels). */
#include "probe_internal.h"
#include "generic/memory.h"

#include <string.h>

/* The six weights of a direction: n_i^2 on the face of the sign of n_i, 0 on the other. */
static void cube_weights(GVec3 d, double w[6])
{
    const double a[3] = {d.x, d.y, d.z};
    for (int i = 0; i < 3; i++) {
        w[2 * i] = a[i] > 0.0 ? a[i] * a[i] : 0.0;
        w[2 * i + 1] = a[i] < 0.0 ? a[i] * a[i] : 0.0;
    }
}

void gprobe_ambient_cube_eval(const GProbeAmbientCube *cube, GVec3 d, double rgb[3])
{
    double w[6];
    cube_weights(d, w);
    for (int c = 0; c < 3; c++) {
        double e = 0.0;
        for (int k = 0; k < 6; k++)
            e += w[k] * cube->c[k][c];
        rgb[c] = e;
    }
}

int gprobe_ambient_cube_fit(const GProbe *p, int fit_normals, GProbeAmbientCube *cube, GError *err)
{
    if (!p || !cube)
        return gerror_set(err, G_ERR_INVALID, "gprobe_ambient_cube_fit: no probe or output given");
    int m = fit_normals > 0 ? fit_normals : 2000;
    if (m < 6 || m > 1000000)
        return gerror_set(err, G_ERR_INVALID, "ambient cube: %d fit normals (expected 6..1000000)", m);
    GVec3 *normals = gmem_calloc((size_t)m, sizeof *normals);
    double *E = gmem_calloc((size_t)m * 3, sizeof *E);
    if (!normals || !E) {
        gmem_free(normals);
        gmem_free(E);
        return gerror_set(err, G_ERR_NOMEM, "ambient cube: out of memory for %d fit normals", m);
    }
    gprobe_fibonacci(m, normals);
    int rc = gprobe_irradiance(p, normals, m, E, err);
    double G[36] = {0}, h[6][3] = {{0}};
    for (int i = 0; i < m && rc == G_OK; i++) {
        double w[6];
        cube_weights(normals[i], w);
        for (int a = 0; a < 6; a++) {
            for (int b = 0; b < 6; b++)
                G[a * 6 + b] += w[a] * w[b];
            for (int c = 0; c < 3; c++)
                h[a][c] += w[a] * E[i * 3 + c];
        }
    }
    if (rc == G_OK && probe_cholesky(G, 6) != 0)
        rc = gerror_set(err, G_ERR_INVALID, "ambient cube: the fit normals do not reach every face");
    if (rc == G_OK) {
        for (int c = 0; c < 3; c++) {
            double x[6];
            for (int a = 0; a < 6; a++)
                x[a] = h[a][c];
            probe_cholesky_solve(G, 6, x);
            for (int a = 0; a < 6; a++)
                cube->c[a][c] = x[a];
        }
    }
    gmem_free(normals);
    gmem_free(E);
    return rc;
}
