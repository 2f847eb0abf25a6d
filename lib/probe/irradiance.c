/* irradiance.c - ground-truth irradiance from a probe (Eq. 4), irradiance of lights, error measures.
 *
 * The fast sum. Row v of the lat-long image is a circle of directions at height cos(theta_v). For a normal
 * n = (rho cos phi_n, rho sin phi_n, n_z) the pixel at phi is visible (n . omega > 0) when
 *     n_z cos(theta) + rho sin(theta) cos(phi - phi_n) > 0,
 * an arc |phi - phi_n| < acos(-n_z cos(theta) / (rho sin(theta))), and over that arc
 *     sum Q (n . omega) = n_z cos(theta) sum Q + rho-part: n_x sin(theta) sum Q cos(phi) + n_y sin(theta) sum Q
 * sin(phi). With per-row prefix sums of Q, Q cos(phi) and Q sin(phi) the arc costs O(1), so a normal costs O(H). Column
 * u has phi = pi - 2 pi (u + 0.5) / W (probe.h), so in columns the arc is centred on pi - phi_n. The arc's end pixels
 * are checked with the same dot product the pixel-by-pixel sum uses, so both sums take exactly the same pixels. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <string.h>

void gprobe_fibonacci(int m, GVec3 *normals)
{
    const double golden = M_PI * (3.0 - sqrt(5.0)); /* the golden angle */
    for (int i = 0; i < m; i++) {
        double z = 1.0 - (2.0 * i + 1.0) / m;
        double r = sqrt(fmax(0.0, 1.0 - z * z)), phi = golden * i;
        normals[i] = gvec3(r * cos(phi), r * sin(phi), z);
    }
}

static inline double pixel_dot(const GProbe *p, GVec3 n, int u, int v)
{
    double s = p->sin_theta[v];
    return n.x * (s * p->cos_phi[u]) + n.y * (s * p->sin_phi[u]) + n.z * p->cos_theta[v];
}

/* x in [-w, 3w) to [0, w) without a division. */
static inline int wrap(int x, int w)
{
    x += x < 0 ? w : 0;
    x -= x >= w ? w : 0;
    return x >= w ? x - w : x;
}

/* Adds row v's contribution for every normal into acc (3 per normal). pre is scratch of 9 (w + 1) doubles:
 * pre[u * 9 + c * 3 + k] = sum over columns < u of Q_c times {1, cos phi, sin phi}[k]. */
static void row_irradiance(const GProbe *p, int v, const GVec3 *normals, const double *rho, const double *phin,
                           int m, double *pre, double *acc)
{
    const int w = p->w;
    const float *q = p->q + (size_t)v * w * 3;
    for (int k = 0; k < 9; k++)
        pre[k] = 0.0;
    for (int u = 0; u < w; u++) {
        const double cp = p->cos_phi[u], sp = p->sin_phi[u];
        const double *a = pre + (size_t)u * 9;
        double *b = pre + (size_t)(u + 1) * 9;
        for (int c = 0; c < 3; c++) {
            const double qc = q[u * 3 + c];
            b[c * 3] = a[c * 3] + qc;
            b[c * 3 + 1] = a[c * 3 + 1] + qc * cp;
            b[c * 3 + 2] = a[c * 3 + 2] + qc * sp;
        }
    }
    const double *total = pre + (size_t)w * 9;
    const double st = p->sin_theta[v], ct = p->cos_theta[v], dphi = 2.0 * M_PI / w;
    for (int i = 0; i < m; i++) {
        const GVec3 n = normals[i];
        const double A = n.z * ct, B = rho[i] * st;
        double s[9];
        if (B <= 1e-300 || -A / B <= -1.0) { /* the whole row is visible, or none of it */
            if (B <= 1e-300 && A <= 0.0)
                continue;
            for (int k = 0; k < 9; k++)
                s[k] = total[k];
        } else {
            const double t = -A / B;
            if (t >= 1.0)
                continue;
            const double alpha = acos(t);
            int lo = (int)ceil((phin[i] - alpha) / dphi - 0.5);
            int count = (int)floor((phin[i] + alpha) / dphi - 0.5) - lo + 1;
            count = count > w ? w : count < 0 ? 0 : count;
            /* make the ends agree with the pixel-by-pixel test */
            while (count < w && pixel_dot(p, n, wrap(lo - 1, w), v) > 0.0) {
                lo--;
                count++;
            }
            while (count > 0 && !(pixel_dot(p, n, wrap(lo, w), v) > 0.0)) {
                lo++;
                count--;
            }
            while (count < w && pixel_dot(p, n, wrap(lo + count, w), v) > 0.0)
                count++;
            while (count > 0 && !(pixel_dot(p, n, wrap(lo + count - 1, w), v) > 0.0))
                count--;
            if (count == 0)
                continue;
            lo = wrap(lo, w);
            const int end = lo + count;
            const double *a = pre + (size_t)lo * 9;
            if (end <= w) {
                const double *b = pre + (size_t)end * 9;
                for (int k = 0; k < 9; k++)
                    s[k] = b[k] - a[k];
            } else {
                const double *b = pre + (size_t)(end - w) * 9;
                for (int k = 0; k < 9; k++)
                    s[k] = (total[k] - a[k]) + b[k];
            }
        }
        const double bx = st * n.x, by = st * n.y;
        for (int c = 0; c < 3; c++)
            acc[i * 3 + c] += A * s[c * 3] + bx * s[c * 3 + 1] + by * s[c * 3 + 2];
    }
}

int gprobe_irradiance(const GProbe *p, const GVec3 *normals, int m, double *E, GError *err)
{
    if (m < 0 || (m > 0 && (!normals || !E)))
        return gerror_set(err, G_ERR_INVALID, "gprobe_irradiance: bad arguments");
    if (m == 0)
        return G_OK;
    double *rho = gmem_calloc((size_t)m * 2, sizeof(double));
    if (!rho)
        return gerror_set(err, G_ERR_NOMEM, "out of memory computing irradiance");
    double *phin = rho + m;
    for (int i = 0; i < m; i++) {
        rho[i] = sqrt(normals[i].x * normals[i].x + normals[i].y * normals[i].y);
        phin[i] = M_PI - atan2(normals[i].y, normals[i].x); /* the column phase of the normal, in [0, 2 pi] */
    }
    /* Rows are summed in a fixed number of blocks (each block's rows in order, then the blocks in order), so
     * the result does not depend on the threads' timing: fits built on it repeat exactly. The block count
     * keeps the partial sums under 64 MiB. */
    int blocks = p->h < 32 ? p->h : 32;
    while (blocks > 1 && (double)blocks * m * 3 * sizeof(double) > 64.0 * 1024 * 1024)
        blocks /= 2;
    double *part = gmem_calloc((size_t)blocks * m * 3, sizeof(double));
    if (!part) {
        gmem_free(rho);
        return gerror_set(err, G_ERR_NOMEM, "out of memory computing irradiance");
    }
    int failed = 0;
    #pragma omp parallel
    {
        double *pre = gmem_alloc(sizeof(double) * 9 * (size_t)(p->w + 1));
        if (!pre) {
            #pragma omp atomic write
            failed = 1;
        }
        #pragma omp for schedule(dynamic, 1)
        for (int b = 0; b < blocks; b++)
            if (pre)
                for (int v = (int)((long)p->h * b / blocks); v < (int)((long)p->h * (b + 1) / blocks); v++)
                    row_irradiance(p, v, normals, rho, phin, m, pre, part + (size_t)b * m * 3);
        gmem_free(pre);
    }
    for (size_t i = 0; i < (size_t)m * 3; i++) {
        double e = 0.0;
        for (int b = 0; b < blocks; b++)
            e += part[(size_t)b * m * 3 + i];
        E[i] = e;
    }
    gmem_free(part);
    gmem_free(rho);
    if (failed)
        return gerror_set(err, G_ERR_NOMEM, "out of memory computing irradiance");
    for (int i = 0; i < 3 * m; i++) /* an arc sum can cancel to a tiny negative */
        if (E[i] < 0.0)
            E[i] = 0.0;
    return G_OK;
}

int gprobe_irradiance_direct(const GProbe *p, const GVec3 *normals, int m, double *E, GError *err)
{
    if (m < 0 || (m > 0 && (!normals || !E)))
        return gerror_set(err, G_ERR_INVALID, "gprobe_irradiance_direct: bad arguments");
    #pragma omp parallel for schedule(dynamic, 1)
    for (int i = 0; i < m; i++) {
        double e[3] = {0, 0, 0};
        for (int v = 0; v < p->h; v++) {
            const float *q = p->q + (size_t)v * p->w * 3;
            double r[3] = {0, 0, 0};
            for (int u = 0; u < p->w; u++) {
                double d = pixel_dot(p, normals[i], u, v);
                if (d > 0.0)
                    for (int c = 0; c < 3; c++)
                        r[c] += q[u * 3 + c] * d;
            }
            for (int c = 0; c < 3; c++)
                e[c] += r[c];
        }
        for (int c = 0; c < 3; c++)
            E[i * 3 + c] = e[c];
    }
    return G_OK;
}

void gprobe_lights_irradiance(const GProbeLight *lights, int n, const GVec3 *normals, int m, double *E)
{
    #pragma omp parallel for schedule(static) if (m * (long)n > 100000)
    for (int i = 0; i < m; i++) {
        double e[3] = {0, 0, 0};
        for (int j = 0; j < n; j++) {
            double d = gvec3_dot(normals[i], lights[j].dir);
            if (d > 0.0)
                for (int c = 0; c < 3; c++)
                    e[c] += lights[j].rgb[c] * d;
        }
        for (int c = 0; c < 3; c++)
            E[i * 3 + c] = e[c];
    }
}

void gprobe_compare(const double *truth, const double *approx, int m, GProbeErrors *out)
{
    memset(out, 0, sizeof *out);
    for (int c = 0; c < 3; c++) {
        double emax = 0.0;
        for (int i = 0; i < m; i++)
            emax = fmax(emax, truth[i * 3 + c]);
        double sum_rel = 0.0, max_rel = 0.0, sum_abs = 0.0, max_abs = 0.0, sum_sym = 0.0;
        long nrel = 0;
        for (int i = 0; i < m; i++) {
            double t = truth[i * 3 + c], d = fabs(approx[i * 3 + c] - t), s = fabs(t) + fabs(approx[i * 3 + c]);
            sum_abs += d;
            sum_sym += s > 0.0 ? 2.0 * d / s : 0.0;
            max_abs = fmax(max_abs, d);
            if (t > 1e-6 * emax && t > 0.0) {
                double r = d / t;
                sum_rel += r;
                max_rel = fmax(max_rel, r);
                nrel++;
            }
        }
        out->mean_rel += nrel ? 100.0 * sum_rel / nrel / 3.0 : 0.0;
        out->max_rel += 100.0 * max_rel / 3.0;
        out->mean_norm += emax > 0.0 && m > 0 ? 100.0 * sum_abs / m / emax / 3.0 : 0.0;
        out->max_norm += emax > 0.0 ? 100.0 * max_abs / emax / 3.0 : 0.0;
        out->smape += m > 0 ? 100.0 * sum_sym / m / 3.0 : 0.0;
    }
}
