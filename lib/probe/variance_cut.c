/* variance_cut.c - median cut by variance minimisation (Viriyothai & Debevec, "Variance Minimization Light
 * Probe Sampling", SIGGRAPH 2009 poster), and the regions of the cutting techniques.
 *
 * Median cut halves each region's energy; a region that holds a bright spot and a dim sky then gets one
 * light between the two. Here the quantity a cut lowers is the energy-weighted variance of the pixel
 * positions, sum over the region of e |x - mean x|^2 (e the luminance of Q, x = ((u + 0.5 - W / 2) sin theta,
 * v + 0.5): the sinusoidal projection, so distances along a row shrink with sin theta as on the sphere).
 * Each region's best cut is searched over both axes and every position (column and row sums of e, e x,
 * e x^2, e y, e y^2, so one region costs its pixel count), and the region whose best cut lowers the summed
 * variance most is split next, so any number of lights can be made. Lights sit at the regions' energy
 * centroids with their summed Q, as in median cut. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <string.h>

typedef struct Moments {
    double e, ex, exx, ey, eyy;
} Moments;

typedef struct VarRegion {
    int u0, v0, u1, v1;
    double gain;  /* how much the best cut lowers the summed variance */
    int along_u;  /* the best cut: along the columns (1, position u0 + cut) or the rows */
    int cut;
} VarRegion;

static double moments_variance(const Moments *m)
{
    if (!(m->e > 0.0))
        return 0.0;
    double v = m->exx - m->ex * m->ex / m->e + m->eyy - m->ey * m->ey / m->e;
    return v > 0.0 ? v : 0.0;
}

/* Position of pixel (u, v) relative to a point near the region's centre (a shift leaves variances alone). */
static void pixel_xy(const GProbe *p, int u, int v, double x0, double y0, double *x, double *y)
{
    *x = (u + 0.5 - 0.5 * p->w) * p->sin_theta[v] - x0;
    *y = v + 0.5 - y0;
}

static void region_origin(const GProbe *p, int u0, int v0, int u1, int v1, double *x0, double *y0)
{
    *y0 = 0.5 * (v0 + v1);
    *x0 = (0.5 * (u0 + u1) - 0.5 * p->w) * sin(M_PI * *y0 / p->h);
}

double gprobe_region_variance(const GProbe *p, const GProbeRect *r)
{
    if (!p || !r || r->u0 < 0 || r->v0 < 0 || r->u1 > p->w || r->v1 > p->h)
        return 0.0;
    double x0, y0;
    region_origin(p, r->u0, r->v0, r->u1, r->v1, &x0, &y0);
    Moments m = {0};
    for (int v = r->v0; v < r->v1; v++)
        for (int u = r->u0; u < r->u1; u++) {
            double e = probe_lum(p->q + ((size_t)v * p->w + u) * 3), x, y;
            pixel_xy(p, u, v, x0, y0, &x, &y);
            m.e += e;
            m.ex += e * x;
            m.exx += e * x * x;
            m.ey += e * y;
            m.eyy += e * y * y;
        }
    return moments_variance(&m);
}

static void moments_add(Moments *a, const Moments *b, double sign)
{
    a->e += sign * b->e;
    a->ex += sign * b->ex;
    a->exx += sign * b->exx;
    a->ey += sign * b->ey;
    a->eyy += sign * b->eyy;
}

/* Finds r's best cut; cols and rows hold at least W and H moments. */
static void best_cut(const GProbe *p, VarRegion *r, Moments *cols, Moments *rows)
{
    const int nu = r->u1 - r->u0, nv = r->v1 - r->v0;
    r->gain = -1.0;
    if (nu * (long)nv <= 1)
        return;
    double x0, y0;
    region_origin(p, r->u0, r->v0, r->u1, r->v1, &x0, &y0);
    memset(cols, 0, (size_t)nu * sizeof *cols);
    memset(rows, 0, (size_t)nv * sizeof *rows);
    Moments all = {0};
    for (int v = r->v0; v < r->v1; v++)
        for (int u = r->u0; u < r->u1; u++) {
            double e = probe_lum(p->q + ((size_t)v * p->w + u) * 3), x, y;
            pixel_xy(p, u, v, x0, y0, &x, &y);
            Moments m = {e, e * x, e * x * x, e * y, e * y * y};
            moments_add(&cols[u - r->u0], &m, 1.0);
            moments_add(&rows[v - r->v0], &m, 1.0);
            moments_add(&all, &m, 1.0);
        }
    double total = moments_variance(&all);
    /* the default (no energy anywhere): halve the longer side, as median cut would */
    double sin_mid = sin(M_PI * 0.5 * (r->v0 + r->v1) / p->h);
    r->along_u = nv <= 1 || (nu > 1 && nu * sin_mid >= nv);
    r->cut = (r->along_u ? nu : nv) / 2;
    double best = total;
    for (int axis = 1; axis >= 0; axis--) {
        int n = axis ? nu : nv;
        const Moments *line = axis ? cols : rows;
        Moments left = {0};
        for (int c = 1; c < n; c++) {
            moments_add(&left, &line[c - 1], 1.0);
            Moments right = all;
            moments_add(&right, &left, -1.0);
            double var = moments_variance(&left) + moments_variance(&right);
            if (var < best - 1e-12 * total) {
                best = var;
                r->along_u = axis;
                r->cut = c;
            }
        }
    }
    r->gain = total - best;
}

/* The n regions of the variance cut; returns how many could be made (fewer when the probe has fewer pixels). */
static int variance_regions(const GProbe *p, int n, VarRegion *regs, GError *err)
{
    Moments *work = gmem_calloc((size_t)p->w + p->h, sizeof *work);
    if (!work)
        return gerror_set(err, G_ERR_NOMEM, "variance cut: out of memory");
    regs[0] = (VarRegion){0, 0, p->w, p->h, 0.0, 1, 0};
    best_cut(p, &regs[0], work, work + p->w);
    int count = 1;
    while (count < n) {
        int pick = -1;
        for (int i = 0; i < count; i++) {
            if (regs[i].gain < 0.0)
                continue;
            long area = (long)(regs[i].u1 - regs[i].u0) * (regs[i].v1 - regs[i].v0);
            long parea = pick < 0 ? 0 : (long)(regs[pick].u1 - regs[pick].u0) * (regs[pick].v1 - regs[pick].v0);
            if (pick < 0 || regs[i].gain > regs[pick].gain || (regs[i].gain == regs[pick].gain && area > parea))
                pick = i;
        }
        if (pick < 0)
            break; /* every region is a single pixel */
        VarRegion a = regs[pick], b = regs[pick];
        if (a.along_u)
            a.u1 = b.u0 = a.u0 + a.cut;
        else
            a.v1 = b.v0 = a.v0 + a.cut;
        best_cut(p, &a, work, work + p->w);
        best_cut(p, &b, work, work + p->w);
        regs[pick] = a;
        regs[count++] = b;
    }
    gmem_free(work);
    return count;
}

int gprobe_variance_cut(const GProbe *p, int n, GProbeLight *lights, GError *err)
{
    if (!p || !lights || n < 1)
        return gerror_set(err, G_ERR_INVALID, "variance cut needs a probe and at least one light, not %d", n);
    VarRegion *regs = gmem_calloc((size_t)n, sizeof *regs);
    ProbeRegion *pr = gmem_calloc((size_t)n, sizeof *pr);
    if (!regs || !pr) {
        gmem_free(regs);
        gmem_free(pr);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    }
    int count = variance_regions(p, n, regs, err);
    if (count > 0) {
        for (int i = 0; i < count; i++)
            probe_region_init(p, &pr[i], regs[i].u0, regs[i].v0, regs[i].u1, regs[i].v1);
        probe_regions_to_lights(p, pr, count, lights);
        for (int i = count; i < n; i++) /* more lights than pixels: the rest carry nothing */
            lights[i] = (GProbeLight){gvec3(0.0, 0.0, 1.0), {0.0, 0.0, 0.0}};
    }
    gmem_free(regs);
    gmem_free(pr);
    return count > 0 ? G_OK : count;
}

int gprobe_cut_regions(const GProbe *p, GProbeTechnique t, int n, GProbeRect *rects, GError *err)
{
    if (!p || !rects || n < 1)
        return gerror_set(err, G_ERR_INVALID, "gprobe_cut_regions: no probe or output, or %d regions", n);
    if (t != GPROBE_MEDIANCUT && t != GPROBE_ADAPTIVE && t != GPROBE_VARIANCE)
        return gerror_set(err, G_ERR_INVALID, "%s makes no regions (mediancut, adaptive and variance do)",
                          gprobe_technique_name(t));
    int rc = G_OK;
    if (t == GPROBE_VARIANCE) {
        VarRegion *regs = gmem_calloc((size_t)n, sizeof *regs);
        if (!regs)
            return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
        int count = variance_regions(p, n, regs, err);
        if (count >= 0 && count < n)
            rc = gerror_set(err, G_ERR_INVALID, "variance cut: %d regions from %d pixels", n, p->w * p->h);
        else if (count < 0)
            rc = count;
        for (int i = 0; i < n && rc == G_OK; i++)
            rects[i] = (GProbeRect){regs[i].u0, regs[i].v0, regs[i].u1, regs[i].v1};
        gmem_free(regs);
        return rc;
    }
    ProbeRegion *regs = gmem_calloc((size_t)n, sizeof *regs);
    if (!regs)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    rc = t == GPROBE_MEDIANCUT ? probe_median_cut_regions(p, n, regs, err) : probe_adaptive_regions(p, n, regs, err);
    for (int i = 0; i < n && rc == G_OK; i++)
        rects[i] = (GProbeRect){regs[i].u0, regs[i].v0, regs[i].u1, regs[i].v1};
    gmem_free(regs);
    return rc;
}
