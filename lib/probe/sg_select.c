/* sg_select.c - how well a set of spherical Gaussian lobes gives the probe's irradiance, the measure by which
 * sg_fit.c chooses between its candidate lobes.
 *
 * The error is the mean over validation normals and channels of |E' - E| / E, E the probe's irradiance
 * (gprobe_irradiance) and E' the fit's. The difference E' - E is the irradiance of the residual radiance
 * (the fit's minus the probe's), integrated over the pixels (the same pixel sums the least squares
 * minimises). To keep large probes cheap the residual is first summed into at most VALIDATION_COLUMNS x
 * VALIDATION_ROWS cells of the lat-long image, each at its solid-angle-weighted mean direction; irradiance
 * is smooth, so the cells change the measure far less than the choice it makes. The validation normals
 * (a Fibonacci lattice of VALIDATION_NORMALS) are not the lobes' axes for any lobe count the fits accept. */
#include "probe_internal.h"
#include "generic/memory.h"

#define VALIDATION_NORMALS 257
#define VALIDATION_COLUMNS 128
#define VALIDATION_ROWS 64

int probe_sg_validation_error(const GProbe *p, int n, const GProbeSGLobe *lobes, const double ambient[3],
                              double *error, GError *err)
{
    const int cw = p->w < VALIDATION_COLUMNS ? p->w : VALIDATION_COLUMNS;
    const int ch = p->h < VALIDATION_ROWS ? p->h : VALIDATION_ROWS;
    const size_t cells = (size_t)cw * ch;
    GVec3 *normals = gmem_alloc(VALIDATION_NORMALS * sizeof *normals);
    double *E = gmem_alloc(VALIDATION_NORMALS * 3 * sizeof *E);
    double *cell = gmem_calloc(cells * 6, sizeof *cell); /* residual per channel, then Omega * direction */
    if (!normals || !E || !cell) {
        gmem_free(normals);
        gmem_free(E);
        gmem_free(cell);
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for the validation");
    }
    gprobe_fibonacci(VALIDATION_NORMALS, normals);
    int rc = gprobe_irradiance(p, normals, VALIDATION_NORMALS, E, err);
    for (int v = 0; v < p->h && rc == G_OK; v++) {
        double omega = 2.0 * M_PI * M_PI * p->sin_theta[v] / ((double)p->w * p->h);
        int cv = (int)((long)v * ch / p->h);
        for (int u = 0; u < p->w; u++) {
            GVec3 d = probe_pixel_dir(p, u, v);
            double fit[3] = {0.0, 0.0, 0.0};
            for (int c = 0; c < 3; c++)
                fit[c] = ambient ? ambient[c] : 0.0;
            for (int k = 0; k < n; k++) {
                double g = exp(lobes[k].sharpness * (gvec3_dot(d, lobes[k].axis) - 1.0));
                for (int c = 0; c < 3; c++)
                    fit[c] += lobes[k].amp[c] * g;
            }
            const float *q = p->q + ((size_t)v * p->w + u) * 3;
            double *a = cell + ((size_t)cv * cw + (size_t)((long)u * cw / p->w)) * 6;
            for (int c = 0; c < 3; c++)
                a[c] += omega * fit[c] - q[c];
            a[3] += omega * d.x;
            a[4] += omega * d.y;
            a[5] += omega * d.z;
        }
    }
    for (size_t j = 0; j < cells; j++) { /* the cell's mean direction, made a unit vector */
        double *a = cell + j * 6, len = sqrt(a[3] * a[3] + a[4] * a[4] + a[5] * a[5]);
        for (int c = 3; c < 6; c++)
            a[c] = len > 0.0 ? a[c] / len : 0.0;
    }
    double emax = 0.0, sum = 0.0;
    for (int i = 0; i < VALIDATION_NORMALS * 3; i++)
        emax = fmax(emax, E[i]);
    for (int i = 0; i < VALIDATION_NORMALS && rc == G_OK; i++) {
        double diff[3] = {0.0, 0.0, 0.0};
        for (size_t j = 0; j < cells; j++) {
            const double *a = cell + j * 6;
            double cosine = normals[i].x * a[3] + normals[i].y * a[4] + normals[i].z * a[5];
            if (cosine > 0.0)
                for (int c = 0; c < 3; c++)
                    diff[c] += a[c] * cosine;
        }
        for (int c = 0; c < 3; c++)
            sum += fabs(diff[c]) / fmax(E[i * 3 + c], 1e-9 * emax + 1e-300);
    }
    *error = sum / (VALIDATION_NORMALS * 3.0);
    gmem_free(normals);
    gmem_free(E);
    gmem_free(cell);
    return rc;
}
