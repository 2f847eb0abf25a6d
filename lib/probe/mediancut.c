/* mediancut.c - Debevec's median cut (2005) and the region operations it shares with adaptive.c.
 *
 * Energy is the Rec. 709 luminance of the weights Q (so the sin(theta) of the lat-long mapping is already
 * in it). A summed-area table (built with the probe) of the energy, of energy times the pixel direction and
 * of Q's channels makes the energy, centroid and colour of any rectangle O(1); the cut that halves a
 * region's energy is found by bisection, so n lights cost O(n log W) after the table. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void probe_region_init(const GProbe *p, ProbeRegion *r, int u0, int v0, int u1, int v1)
{
    r->u0 = u0;
    r->v0 = v0;
    r->u1 = u1;
    r->v1 = v1;
    if (u1 > u0 && v1 > v0)
        probe_sat_sum(p, u0, v0, u1, v1, r->sum);
    else
        memset(r->sum, 0, sizeof r->sum);
}

double probe_region_spread(const ProbeRegion *r)
{
    double s = r->sum[0] - sqrt(r->sum[1] * r->sum[1] + r->sum[2] * r->sum[2] + r->sum[3] * r->sum[3]);
    return s > 0.0 ? s : 0.0;
}

/* Energy of the first c columns (along u) or rows (along v) of r. */
static double part_energy(const GProbe *p, const ProbeRegion *r, int along_u, int c)
{
    double s[PROBE_SAT];
    if (along_u)
        probe_sat_sum(p, r->u0, r->v0, r->u0 + c, r->v1, s);
    else
        probe_sat_sum(p, r->u0, r->v0, r->u1, r->v0 + c, s);
    return s[0];
}

int probe_region_split(const GProbe *p, const ProbeRegion *r, ProbeRegion *a, ProbeRegion *b)
{
    const int nu = r->u1 - r->u0, nv = r->v1 - r->v0;
    if (nu <= 1 && nv <= 1) {
        *a = *r;
        probe_region_init(p, b, r->u1, r->v0, r->u1, r->v1); /* empty */
        return 0;
    }
    /* the width in angle is nu * (2 pi / W) * sin(theta) = nu * (pi / H) * sin(theta); the height nv * pi / H */
    double sin_mid = sin(M_PI * 0.5 * (r->v0 + r->v1) / p->h);
    int along_u = nv <= 1 || (nu > 1 && nu * sin_mid >= nv);
    int n = along_u ? nu : nv;
    int cut;
    double half = 0.5 * r->sum[0];
    if (!(half > 0.0)) {
        cut = n / 2;
    } else {
        int lo = 1, hi = n - 1; /* smallest cut whose first part holds at least half the energy */
        while (lo < hi) {
            int mid = (lo + hi) / 2;
            if (part_energy(p, r, along_u, mid) >= half)
                hi = mid;
            else
                lo = mid + 1;
        }
        cut = lo;
        if (cut > 1) { /* the cut one before may be closer to the half */
            double e1 = fabs(part_energy(p, r, along_u, cut) - half);
            double e0 = fabs(part_energy(p, r, along_u, cut - 1) - half);
            if (e0 < e1 || (e0 == e1 && abs(cut - 1 - n / 2) < abs(cut - n / 2)))
                cut--;
        }
    }
    if (along_u) {
        probe_region_init(p, a, r->u0, r->v0, r->u0 + cut, r->v1);
        probe_region_init(p, b, r->u0 + cut, r->v0, r->u1, r->v1);
    } else {
        probe_region_init(p, a, r->u0, r->v0, r->u1, r->v0 + cut);
        probe_region_init(p, b, r->u0, r->v0 + cut, r->u1, r->v1);
    }
    return 1;
}

void probe_regions_to_lights(const GProbe *p, const ProbeRegion *regions, int n, GProbeLight *lights)
{
    for (int i = 0; i < n; i++) {
        const ProbeRegion *r = &regions[i];
        GProbeLight *l = &lights[i];
        double s = sqrt(r->sum[1] * r->sum[1] + r->sum[2] * r->sum[2] + r->sum[3] * r->sum[3]);
        if (r->sum[0] > 0.0 && s > 1e-12 * r->sum[0])
            l->dir = gvec3(r->sum[1] / s, r->sum[2] / s, r->sum[3] / s);
        else /* no energy: the rectangle's centre */
            l->dir = gprobe_direction(p, 0.5 * (r->u0 + r->u1), 0.5 * (r->v0 + r->v1));
        for (int c = 0; c < 3; c++)
            l->rgb[c] = r->sum[4 + c];
    }
}

int probe_median_cut_regions(const GProbe *p, int n, ProbeRegion *out, GError *err)
{
    if (n < 1 || (n & (n - 1)) != 0)
        return gerror_set(err, G_ERR_INVALID, "median cut makes a power of two of lights, not %d", n);
    ProbeRegion *cur = gmem_calloc((size_t)n * 2, sizeof *cur);
    if (!cur)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    ProbeRegion *next = cur + n;
    probe_region_init(p, &cur[0], 0, 0, p->w, p->h);
    for (int count = 1; count < n; count *= 2) {
        for (int i = 0; i < count; i++)
            probe_region_split(p, &cur[i], &next[2 * i], &next[2 * i + 1]);
        ProbeRegion *t = cur;
        cur = next;
        next = t;
    }
    memcpy(out, cur, (size_t)n * sizeof *out);
    gmem_free(cur < next ? cur : next);
    return G_OK;
}

int gprobe_median_cut(const GProbe *p, int n, GProbeLight *lights, GError *err)
{
    if (n < 1 || (n & (n - 1)) != 0)
        return gerror_set(err, G_ERR_INVALID, "median cut makes a power of two of lights, not %d", n);
    if (!lights)
        return gerror_set(err, G_ERR_INVALID, "median cut: no output given");
    ProbeRegion *regions = gmem_calloc((size_t)n, sizeof *regions);
    if (!regions)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    int rc = probe_median_cut_regions(p, n, regions, err);
    if (rc == G_OK)
        probe_regions_to_lights(p, regions, n, lights);
    gmem_free(regions);
    return rc;
}
