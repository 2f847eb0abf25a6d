/* sg_fit.c - n spherical Gaussian lobes for a probe.
 *
 * Lobes (the same for every fit): the probe's pixels are clustered by the energy-weighted spherical k-means
 * of kmeans.c; each pixel then belongs to its nearest centre, and each cluster gives a lobe whose axis is
 * the cluster's energy-weighted mean direction and whose sharpness makes the lobe's own mean direction
 * equally long (the von Mises-Fisher moment estimate: |mean| = coth lambda - 1 / lambda). A probe that is
 * one lobe gives that lobe back. Sharpness is kept in [0.01, (H / 2 pi)^2]: the lobe's width 1 / sqrt(lambda)
 * is then at least two pixels, so that the pixel sums below integrate it (a sun, sharper than that, gets a
 * lobe of that width: its irradiance hardly differs, but least squares on narrower lobes sampled at pixel
 * centres inflates their amplitude by half). A cluster without energy gets its centre and sharpness n.
 * Amplitudes, per channel:
 *   naive       each lobe carries its cluster's power: amp = (sum of Q) / integral of the lobe;
 *   ls          least squares on the radiance, min sum over pixels of Omega (P - sum amp_k G_k)^2 (the
 *               normal equations G a = h with G_jk = sum Omega G_j G_k, h_k = sum Q G_k, Cholesky);
 *   nnls        the same with amp >= 0 (Lawson & Hanson, linalg.c);
 *   ls-ambient  least squares with a constant term beside the lobes. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <string.h>

/* Lobe values below this fraction are left out of the Gram sums (they cannot change the fit). */
#define SG_NEGLIGIBLE 1e-12

static int fit_lobes(const GProbe *p, int n, GProbeSGLobe *lobes, double (*power)[3], GError *err)
{
    GProbeLight *centres = gmem_calloc((size_t)n, sizeof *centres);
    double *acc = gmem_calloc((size_t)n * 4, sizeof *acc);
    if (!centres || !acc) {
        gmem_free(centres);
        gmem_free(acc);
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for %d lobes", n);
    }
    int rc = gprobe_kmeans(p, n, NULL, centres, err);
    for (int v = 0; v < p->h && rc == G_OK; v++)
        for (int u = 0; u < p->w; u++) {
            GVec3 d = probe_pixel_dir(p, u, v);
            int best = 0;
            double bd = -2.0;
            for (int k = 0; k < n; k++) {
                double c = gvec3_dot(d, centres[k].dir);
                if (c > bd)
                    bd = c, best = k;
            }
            const float *q = p->q + ((size_t)v * p->w + u) * 3;
            double e = probe_lum(q);
            acc[best * 4] += e;
            acc[best * 4 + 1] += e * d.x;
            acc[best * 4 + 2] += e * d.y;
            acc[best * 4 + 3] += e * d.z;
            for (int c = 0; c < 3; c++)
                power[best][c] += q[c];
        }
    double hi = fmax(1.0, (p->h / (2.0 * M_PI)) * (p->h / (2.0 * M_PI)));
    for (int k = 0; k < n && rc == G_OK; k++) {
        double *a = acc + 4 * k, len = sqrt(a[1] * a[1] + a[2] * a[2] + a[3] * a[3]);
        GProbeSGLobe *l = &lobes[k];
        memset(l, 0, sizeof *l);
        if (a[0] > 0.0 && len > 1e-12 * a[0]) {
            l->axis = gvec3(a[1] / len, a[2] / len, a[3] / len);
            l->sharpness = probe_sg_sharpness(len / a[0], 0.01, hi);
        } else {
            l->axis = centres[k].dir;
            l->sharpness = fmin((double)n, hi);
        }
    }
    gmem_free(centres);
    gmem_free(acc);
    return rc;
}

/* The least-squares system of the lobes (and the constant when ambient): G (dim x dim) and h (dim x 3). */
static void gram(const GProbe *p, int n, int ambient, const GProbeSGLobe *lobes, double *G, double *h, double *b,
                 int *active)
{
    const int dim = n + ambient;
    for (int v = 0; v < p->h; v++) {
        double omega = 2.0 * M_PI * M_PI * p->sin_theta[v] / ((double)p->w * p->h);
        for (int u = 0; u < p->w; u++) {
            GVec3 d = probe_pixel_dir(p, u, v);
            const float *q = p->q + ((size_t)v * p->w + u) * 3;
            int na = 0;
            for (int k = 0; k < n; k++) {
                double g = exp(lobes[k].sharpness * (gvec3_dot(d, lobes[k].axis) - 1.0));
                if (g > SG_NEGLIGIBLE) {
                    b[na] = g;
                    active[na++] = k;
                }
            }
            if (ambient) {
                b[na] = 1.0;
                active[na++] = n;
            }
            for (int i = 0; i < na; i++) {
                double wi = omega * b[i];
                double *row = G + (size_t)active[i] * dim;
                for (int j = 0; j < na; j++)
                    row[active[j]] += wi * b[j];
                for (int c = 0; c < 3; c++)
                    h[active[i] * 3 + c] += b[i] * q[c];
            }
        }
    }
}

static int solve_ls(int dim, double *G, double *h, double *x, int nonneg, GError *err)
{
    double *a = gmem_alloc(((size_t)dim * dim + probe_nnls_work_size(dim) + dim) * sizeof *a);
    if (!a)
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for the fit");
    double *work = a + (size_t)dim * dim, *rhs = work + probe_nnls_work_size(dim);
    double dmax = 0.0;
    for (int i = 0; i < dim; i++)
        dmax = fmax(dmax, G[(size_t)i * dim + i]);
    int rc = G_OK;
    for (int c = 0; c < 3 && rc == G_OK; c++) {
        for (int i = 0; i < dim; i++)
            rhs[i] = h[i * 3 + c];
        if (nonneg) {
            double *sol = gmem_calloc((size_t)dim, sizeof *sol);
            if (!sol) {
                rc = gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for the fit");
                break;
            }
            memcpy(a, G, (size_t)dim * dim * sizeof *a);
            for (int i = 0; i < dim; i++)
                a[(size_t)i * dim + i] += 1e-12 * dmax;
            probe_nnls(dim, a, rhs, sol, work);
            for (int i = 0; i < dim; i++)
                x[i * 3 + c] = sol[i] > 0.0 ? sol[i] : 0.0;
            gmem_free(sol);
            continue;
        }
        int ok = 0;
        for (double ridge = 1e-10; ridge < 1.0 && !ok; ridge *= 100.0) { /* Tikhonov only as far as needed */
            memcpy(a, G, (size_t)dim * dim * sizeof *a);
            for (int i = 0; i < dim; i++)
                a[(size_t)i * dim + i] += ridge * (dmax > 0.0 ? dmax : 1.0);
            ok = probe_cholesky(a, dim) == 0;
        }
        if (!ok) {
            rc = gerror_set(err, G_ERR_INVALID, "spherical Gaussians: the least-squares system is singular");
            break;
        }
        probe_cholesky_solve(a, dim, rhs);
        for (int i = 0; i < dim; i++)
            x[i * 3 + c] = rhs[i];
    }
    gmem_free(a);
    return rc;
}

int gprobe_sg_fit(const GProbe *p, int n, GProbeSGFit fit, GProbeSGLobe *lobes, double ambient[3], GError *err)
{
    if (!p || !lobes)
        return gerror_set(err, G_ERR_INVALID, "gprobe_sg_fit: no probe or output given");
    if (n < 1 || n > GPROBE_SG_MAX_LOBES)
        return gerror_set(err, G_ERR_INVALID, "spherical Gaussians: %d lobes (expected 1..%d)", n, GPROBE_SG_MAX_LOBES);
    if ((unsigned)fit > GPROBE_SG_LS_AMBIENT)
        return gerror_set(err, G_ERR_INVALID, "spherical Gaussians: unknown fit %d", (int)fit);
    if (fit == GPROBE_SG_LS_AMBIENT && !ambient)
        return gerror_set(err, G_ERR_INVALID, "spherical Gaussians: the ambient fit needs somewhere to put the term");
    if (ambient)
        ambient[0] = ambient[1] = ambient[2] = 0.0;
    double(*power)[3] = gmem_calloc((size_t)n, sizeof *power);
    if (!power)
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for %d lobes", n);
    int rc = fit_lobes(p, n, lobes, power, err);
    if (rc == G_OK && fit == GPROBE_SG_NAIVE) {
        for (int k = 0; k < n; k++)
            for (int c = 0; c < 3; c++)
                lobes[k].amp[c] = power[k][c] / probe_sg_integral(lobes[k].sharpness);
    } else if (rc == G_OK) {
        int amb = fit == GPROBE_SG_LS_AMBIENT, dim = n + amb;
        double *G = gmem_calloc((size_t)dim * dim + (size_t)dim * 3 * 2 + dim, sizeof *G);
        int *active = gmem_calloc((size_t)dim, sizeof *active);
        if (!G || !active) {
            rc = gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for the fit of %d lobes", n);
        } else {
            double *h = G + (size_t)dim * dim, *x = h + (size_t)dim * 3, *b = x + (size_t)dim * 3;
            gram(p, n, amb, lobes, G, h, b, active);
            rc = solve_ls(dim, G, h, x, fit == GPROBE_SG_NNLS, err);
            for (int k = 0; k < n && rc == G_OK; k++)
                for (int c = 0; c < 3; c++)
                    lobes[k].amp[c] = x[k * 3 + c];
            if (rc == G_OK && amb)
                for (int c = 0; c < 3; c++)
                    ambient[c] = x[n * 3 + c];
        }
        gmem_free(G);
        gmem_free(active);
    }
    gmem_free(power);
    return rc;
}
