/* sg_fit.c - n spherical Gaussian lobes for a probe.
 *
 * Lobes (axes and sharpnesses):
 *   clustered   the probe's pixels are clustered by the energy-weighted spherical k-means of kmeans.c; each
 *               pixel belongs to its nearest centre, and each cluster gives a lobe whose axis is the cluster's
 *               energy-weighted mean direction and whose sharpness makes the lobe's own mean direction equally
 *               long (the von Mises-Fisher moment estimate: |mean| = coth lambda - 1 / lambda). A probe that is
 *               one lobe gives that lobe back. Sharpness is kept in [0.01, (H / 2 pi)^2]: the lobe's width
 *               1 / sqrt(lambda) is then at least two pixels, so that the pixel sums below integrate it. A
 *               cluster without energy gets its centre and sharpness n.
 *   even        axes on the Fibonacci lattice (gprobe_fibonacci: Vogel's spiral), one sharpness (as
 *               Probulator places them), within the same bounds.
 * sg-naive uses the clustered lobes. The fits that solve for amplitudes (ls, nnls, ls-ambient) choose by the
 * irradiance error at validation normals (sg_select.c, best_fit below): up to SG_FOLLOWING lobes the clustered
 * ones, which follow the light; above, the better of the n clustered lobes and the best fit of n / 2 lobes
 * with n - n / 2 even lobes of sharpness n / 2 beside it (refitted, or at amplitude 0 when refitting does not
 * help), so that doubling the lobes never raises the validation error. Clustered lobes alone stop covering the
 * sphere as n grows, and the fit then stops preserving power.
 * Amplitudes, per channel:
 *   naive       each lobe carries its cluster's power: amp = (sum of Q) / integral of the lobe;
 *   ls          least squares: min sum over pixels of Omega (P - sum amp_k G_k)^2 plus SG_HELD_WEIGHT times the
 *               squared error of the fit's projection on the spherical harmonics of order <= 4, band l weighted
 *               by (A_l / pi)^2 (A_l the clamped cosine's band factors: pi, 2 pi / 3, pi / 4, 0, -pi / 24):
 *               those bands carry the irradiance, so the fit holds them and spends the rest of its freedom on
 *               the radiance (normal equations, Cholesky);
 *   nnls        the same with amp >= 0 (Lawson & Hanson, linalg.c);
 *   ls-ambient  the same as nnls with a constant term beside the lobes: every amplitude and the constant are
 *               >= 0, so the irradiance is never negative. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <string.h>

/* Lobe values below this fraction are left out of the Gram sums (they cannot change the fit). */
#define SG_NEGLIGIBLE 1e-12
/* Lobes that follow the light (clustered) before the rest are spread evenly. */
#define SG_FOLLOWING 8

/* Largest sharpness of a lobe: its width 1 / sqrt(lambda) at least two pixels of a probe of h rows. */
static double max_sharpness(const GProbe *p)
{
    return fmax(1.0, (p->h / (2.0 * M_PI)) * (p->h / (2.0 * M_PI)));
}

static int clustered_lobes(const GProbe *p, int n, GProbeSGLobe *lobes, double (*power)[3], GError *err)
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
    double hi = max_sharpness(p);
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

/* n lobes on the Fibonacci lattice with sharpness lambda (amplitudes 0). */
static int even_lobes(const GProbe *p, int n, double lambda, GProbeSGLobe *lobes, GError *err)
{
    GVec3 *axes = gmem_alloc((size_t)n * sizeof *axes);
    if (!axes)
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for %d lobes", n);
    gprobe_fibonacci(n, axes);
    lambda = fmin(fmax(lambda, 0.01), max_sharpness(p));
    for (int k = 0; k < n; k++) {
        memset(&lobes[k], 0, sizeof lobes[k]);
        lobes[k].axis = axes[k];
        lobes[k].sharpness = lambda;
    }
    gmem_free(axes);
    return G_OK;
}

/* Irradiance bands the fits hold: the real spherical harmonics of order <= SG_HELD_ORDER. */
#define SG_HELD_ORDER 4
#define SG_HELD ((SG_HELD_ORDER + 1) * (SG_HELD_ORDER + 1))
/* Weight of the held bands against the radiance. */
#define SG_HELD_WEIGHT 1e6

/* The least-squares system of the lobes (and the constant when ambient): G (dim x dim) and h (dim x 3), the
 * radiance's normal equations plus held times those of the fit's projection on the bands 0..2 (band l weighted
 * by (A_l / pi)^2, A_l the clamped cosine's band factor). */
static void gram(const GProbe *p, int n, int ambient, const GProbeSGLobe *lobes, double held, double *G, double *h,
                 double *b, int *active)
{
    const int dim = n + ambient;
    double *proj = gmem_calloc((size_t)dim * SG_HELD + SG_HELD * 3, sizeof *proj);
    double *target = proj + (size_t)dim * SG_HELD;
    for (int v = 0; v < p->h; v++) {
        double omega = 2.0 * M_PI * M_PI * p->sin_theta[v] / ((double)p->w * p->h);
        for (int u = 0; u < p->w; u++) {
            GVec3 d = probe_pixel_dir(p, u, v);
            const float *q = p->q + ((size_t)v * p->w + u) * 3;
            double y[SG_HELD] = {0};
            gprobe_sh_basis(SG_HELD_ORDER, d, y);
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
                if (proj)
                    for (int j = 0; j < SG_HELD; j++)
                        proj[(size_t)active[i] * SG_HELD + j] += wi * y[j];
            }
            if (proj)
                for (int j = 0; j < SG_HELD; j++)
                    for (int c = 0; c < 3; c++)
                        target[j * 3 + c] += q[c] * y[j];
        }
    }
    if (!proj || !(held > 0.0)) {
        gmem_free(proj);
        return;
    }
    static const double band_factor[5] = {1.0, 2.0 / 3.0, 0.25, 0.0, -1.0 / 24.0}; /* A_l / pi */
    double band_weight[SG_HELD] = {0};
    for (int l = 0; l <= SG_HELD_ORDER; l++)
        for (int j = l * l; j < (l + 1) * (l + 1); j++)
            band_weight[j] = band_factor[l] * band_factor[l];
    for (int j = 0; j < SG_HELD; j++) {
        double w = held * band_weight[j];
        for (int a = 0; a < dim; a++) {
            double pa = w * proj[(size_t)a * SG_HELD + j];
            for (int bb = 0; bb < dim; bb++)
                G[(size_t)a * dim + bb] += pa * proj[(size_t)bb * SG_HELD + j];
            for (int c = 0; c < 3; c++)
                h[a * 3 + c] += pa * target[j * 3 + c];
        }
    }
    gmem_free(proj);
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

/* Amplitudes (and the ambient constant) of the given lobes by the fit's least squares. */
static int fit_amplitudes(const GProbe *p, int n, GProbeSGFit fit, GProbeSGLobe *lobes, double ambient[3],
                          GError *err)
{
    int amb = fit == GPROBE_SG_LS_AMBIENT, dim = n + amb;
    double *G = gmem_calloc((size_t)dim * dim + (size_t)dim * 3 * 2 + dim, sizeof *G);
    int *active = gmem_calloc((size_t)dim, sizeof *active);
    int rc = G_OK;
    if (!G || !active) {
        rc = gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for the fit of %d lobes", n);
    } else {
        double *h = G + (size_t)dim * dim, *x = h + (size_t)dim * 3, *b = x + (size_t)dim * 3;
        gram(p, n, amb, lobes, SG_HELD_WEIGHT, G, h, b, active);
        rc = solve_ls(dim, G, h, x, fit != GPROBE_SG_LS, err);
        for (int k = 0; k < n && rc == G_OK; k++)
            for (int c = 0; c < 3; c++)
                lobes[k].amp[c] = x[k * 3 + c];
        if (rc == G_OK && amb)
            for (int c = 0; c < 3; c++)
                ambient[c] = x[n * 3 + c];
    }
    gmem_free(G);
    gmem_free(active);
    return rc;
}

/* The fit of n lobes with the least validation error (probe_sg_validation_error, into *best) among: the n
 * clustered lobes; and, above SG_FOLLOWING lobes, the best fit of n / 2 lobes with n - n / 2 even lobes
 * (sharpness n / 2) beside it, refitted, or kept with the added lobes at amplitude 0. The last makes the
 * validation error of 2n lobes at most that of n. */
static int best_fit(const GProbe *p, int n, GProbeSGFit fit, GProbeSGLobe *lobes, double ambient[3], double *best,
                    GError *err)
{
    double(*power)[3] = gmem_calloc((size_t)n, sizeof *power);
    GProbeSGLobe *cand = gmem_calloc((size_t)n, sizeof *cand);
    if (!power || !cand) {
        gmem_free(power);
        gmem_free(cand);
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for %d lobes", n);
    }
    ambient[0] = ambient[1] = ambient[2] = 0.0;
    int rc = clustered_lobes(p, n, lobes, power, err);
    if (rc == G_OK)
        rc = fit_amplitudes(p, n, fit, lobes, ambient, err);
    if (rc == G_OK)
        rc = probe_sg_validation_error(p, n, lobes, ambient, best, err);
    const int half = n / 2;
    double amb[3], error;
    if (rc == G_OK && n > SG_FOLLOWING)
        rc = best_fit(p, half, fit, cand, amb, &error, err);
    if (rc == G_OK && n > SG_FOLLOWING)
        rc = even_lobes(p, n - half, 0.5 * n, cand + half, err);
    if (rc == G_OK && n > SG_FOLLOWING && error < *best) {
        *best = error;
        memcpy(lobes, cand, (size_t)n * sizeof *lobes);
        memcpy(ambient, amb, sizeof amb);
    }
    if (rc == G_OK && n > SG_FOLLOWING)
        rc = fit_amplitudes(p, n, fit, cand, amb, err);
    if (rc == G_OK && n > SG_FOLLOWING)
        rc = probe_sg_validation_error(p, n, cand, amb, &error, err);
    if (rc == G_OK && n > SG_FOLLOWING && error < *best) {
        *best = error;
        memcpy(lobes, cand, (size_t)n * sizeof *lobes);
        memcpy(ambient, amb, sizeof amb);
    }
    gmem_free(power);
    gmem_free(cand);
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
    if (fit != GPROBE_SG_NAIVE) {
        double amb[3], best;
        int rc = best_fit(p, n, fit, lobes, amb, &best, err);
        if (rc == G_OK && ambient)
            memcpy(ambient, amb, sizeof amb);
        return rc;
    }
    double(*power)[3] = gmem_calloc((size_t)n, sizeof *power);
    if (!power)
        return gerror_set(err, G_ERR_NOMEM, "spherical Gaussians: out of memory for %d lobes", n);
    int rc = clustered_lobes(p, n, lobes, power, err);
    for (int k = 0; k < n && rc == G_OK; k++)
        for (int c = 0; c < 3; c++)
            lobes[k].amp[c] = power[k][c] / probe_sg_integral(lobes[k].sharpness);
    gmem_free(power);
    return rc;
}
