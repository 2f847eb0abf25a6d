/* kmeans.c - LightGen-style clustering (after Cohen & Debevec's LightGen plug-in, 2001).
 *
 * Spherical k-means of the pixel directions weighted by their energy (luminance of Q): each cluster's
 * centre is the normalised energy-weighted mean of its directions, points go to the centre with the largest
 * dot product. Seeding is deterministic: the heaviest point first, then k-means++ (probability proportional
 * to weight times squared chord distance to the nearest centre) from a fixed-seed generator. Probes larger
 * than 2^16 pixels are clustered on blocks of B x B pixels (B a power of two, energy and energy-weighted
 * direction summed per block); a final assignment of every pixel to the converged centres gives the lights'
 * directions and colours at full resolution, so each light carries exactly the Q of its pixels. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct {
    double x, y, z, w;
} Point;

static uint64_t rng_next(uint64_t *s) /* splitmix64 */
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static int nearest(const double *cx, const double *cy, const double *cz, int n, double x, double y, double z,
                   double *best_dot)
{
    int best = 0;
    double bd = -2.0;
    for (int j = 0; j < n; j++) {
        double d = cx[j] * x + cy[j] * y + cz[j] * z;
        if (d > bd) {
            bd = d;
            best = j;
        }
    }
    if (best_dot)
        *best_dot = bd;
    return best;
}

/* Block-aggregated points with energy > 0; returns their number or -1 when out of memory. */
static long make_points(const GProbe *p, Point **out)
{
    int b = 1;
    while ((long)(p->w / b) * (p->h / b) > 65536 && b < p->h)
        b *= 2;
    const int bw = (p->w + b - 1) / b, bh = (p->h + b - 1) / b;
    Point *pts = gmem_calloc((size_t)bw * bh, sizeof *pts);
    if (!pts)
        return -1;
    long n = 0;
    for (int j = 0; j < bh; j++)
        for (int i = 0; i < bw; i++) {
            double s[PROBE_SAT];
            int u1 = (i + 1) * b < p->w ? (i + 1) * b : p->w, v1 = (j + 1) * b < p->h ? (j + 1) * b : p->h;
            probe_sat_sum(p, i * b, j * b, u1, v1, s);
            double len = sqrt(s[1] * s[1] + s[2] * s[2] + s[3] * s[3]);
            if (!(s[0] > 0.0) || !(len > 0.0))
                continue;
            pts[n++] = (Point){s[1] / len, s[2] / len, s[3] / len, s[0]};
        }
    *out = pts;
    return n;
}

int gprobe_kmeans(const GProbe *p, int n, const GProbeOptions *opt, GProbeLight *lights, GError *err)
{
    if (n < 1 || !lights)
        return gerror_set(err, G_ERR_INVALID, "k-means needs at least one light, not %d", n);
    const int rounds = opt && opt->max_iterations > 0 ? opt->max_iterations : 60;
    Point *pts = NULL;
    long np = make_points(p, &pts);
    double *c = gmem_calloc((size_t)n * 7, sizeof(double));
    int *assign = np > 0 ? gmem_calloc((size_t)np, sizeof(int)) : NULL;
    double *dist = np > 0 ? gmem_calloc((size_t)np, sizeof(double)) : NULL;
    if (np < 0 || !c || (np > 0 && (!assign || !dist))) {
        gmem_free(pts);
        gmem_free(c);
        gmem_free(assign);
        gmem_free(dist);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for k-means with %d clusters", n);
    }
    double *cx = c, *cy = c + n, *cz = c + 2 * n, *sx = c + 3 * n, *sy = c + 4 * n, *sz = c + 5 * n, *sw = c + 6 * n;

    /* seeding: heaviest point, then k-means++ with a fixed seed */
    int k = 0;
    if (np > 0) {
        long heavy = 0;
        for (long i = 1; i < np; i++)
            if (pts[i].w > pts[heavy].w)
                heavy = i;
        cx[0] = pts[heavy].x;
        cy[0] = pts[heavy].y;
        cz[0] = pts[heavy].z;
        k = 1;
        for (long i = 0; i < np; i++)
            dist[i] = pts[i].w * fmax(0.0, 2.0 - 2.0 * (cx[0] * pts[i].x + cy[0] * pts[i].y + cz[0] * pts[i].z));
        uint64_t seed = 0x5EED0F11u;
        for (; k < n; k++) {
            double total = 0.0;
            for (long i = 0; i < np; i++)
                total += dist[i];
            if (!(total > 0.0))
                break;
            double target = (rng_next(&seed) >> 11) * (1.0 / 9007199254740992.0) * total, acc = 0.0;
            long pick = np - 1;
            for (long i = 0; i < np; i++) {
                acc += dist[i];
                if (acc > target && dist[i] > 0.0) {
                    pick = i;
                    break;
                }
            }
            cx[k] = pts[pick].x;
            cy[k] = pts[pick].y;
            cz[k] = pts[pick].z;
            for (long i = 0; i < np; i++) {
                double d = pts[i].w * fmax(0.0, 2.0 - 2.0 * (cx[k] * pts[i].x + cy[k] * pts[i].y + cz[k] * pts[i].z));
                if (d < dist[i])
                    dist[i] = d;
            }
        }
    }
    if (k < n) { /* fewer distinct energetic points than clusters: park the rest evenly (they stay black) */
        GVec3 *f = gmem_calloc((size_t)(n - k), sizeof *f);
        if (!f) {
            gmem_free(pts);
            gmem_free(c);
            gmem_free(assign);
            gmem_free(dist);
            return gerror_set(err, G_ERR_NOMEM, "out of memory for k-means with %d clusters", n);
        }
        gprobe_fibonacci(n - k, f);
        for (int j = k; j < n; j++) {
            cx[j] = f[j - k].x;
            cy[j] = f[j - k].y;
            cz[j] = f[j - k].z;
        }
        gmem_free(f);
    }

    /* Lloyd rounds on the (aggregated) points */
    for (long i = 0; i < np; i++)
        assign[i] = -1;
    for (int it = 0; it < rounds && np > 0; it++) {
        long changed = 0;
        #pragma omp parallel for schedule(static) reduction(+ : changed)
        for (long i = 0; i < np; i++) {
            double bd;
            int j = nearest(cx, cy, cz, n, pts[i].x, pts[i].y, pts[i].z, &bd);
            dist[i] = pts[i].w * fmax(0.0, 2.0 - 2.0 * bd);
            if (j != assign[i]) {
                assign[i] = j;
                changed++;
            }
        }
        if (changed == 0)
            break;
        memset(sx, 0, sizeof(double) * 4 * n);
        for (long i = 0; i < np; i++) {
            int j = assign[i];
            sx[j] += pts[i].w * pts[i].x;
            sy[j] += pts[i].w * pts[i].y;
            sz[j] += pts[i].w * pts[i].z;
            sw[j] += pts[i].w;
        }
        for (int j = 0; j < n; j++) {
            double len = sqrt(sx[j] * sx[j] + sy[j] * sy[j] + sz[j] * sz[j]);
            if (sw[j] > 0.0 && len > 0.0) {
                cx[j] = sx[j] / len;
                cy[j] = sy[j] / len;
                cz[j] = sz[j] / len;
            } else if (k == n) { /* an empty cluster takes the point its own centre serves worst */
                long far = 0;
                for (long i = 1; i < np; i++)
                    if (dist[i] > dist[far])
                        far = i;
                if (dist[far] > 0.0) {
                    cx[j] = pts[far].x;
                    cy[j] = pts[far].y;
                    cz[j] = pts[far].z;
                    dist[far] = 0.0;
                }
            }
        }
        probe_progress(opt, "kmeans", (it + 1.0) / rounds);
    }

    /* final assignment of every pixel: directions and colours at full resolution */
    memset(sx, 0, sizeof(double) * 4 * n);
    double *rgb = gmem_calloc((size_t)n * 3, sizeof(double));
    if (!rgb) {
        gmem_free(pts);
        gmem_free(c);
        gmem_free(assign);
        gmem_free(dist);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for k-means with %d clusters", n);
    }
    for (int v = 0; v < p->h; v++)
        for (int u = 0; u < p->w; u++) {
            const float *q = p->q + ((size_t)v * p->w + u) * 3;
            double e = probe_lum(q);
            if (!(e > 0.0))
                continue;
            GVec3 d = probe_pixel_dir(p, u, v);
            int j = nearest(cx, cy, cz, n, d.x, d.y, d.z, NULL);
            sx[j] += e * d.x;
            sy[j] += e * d.y;
            sz[j] += e * d.z;
            for (int ch = 0; ch < 3; ch++)
                rgb[j * 3 + ch] += q[ch];
        }
    for (int j = 0; j < n; j++) {
        double len = sqrt(sx[j] * sx[j] + sy[j] * sy[j] + sz[j] * sz[j]);
        lights[j].dir = len > 0.0 ? gvec3(sx[j] / len, sy[j] / len, sz[j] / len) : gvec3(cx[j], cy[j], cz[j]);
        for (int ch = 0; ch < 3; ch++)
            lights[j].rgb[ch] = rgb[j * 3 + ch];
    }
    gmem_free(rgb);
    gmem_free(pts);
    gmem_free(c);
    gmem_free(assign);
    gmem_free(dist);
    return G_OK;
}
