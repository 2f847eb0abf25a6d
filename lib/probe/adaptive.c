/* adaptive.c - adaptive median cut: any number of lights.
 *
 * Regions are split one at a time (with median cut's rule: longest side, energy halved) and the region
 * split next is the one with the largest energy-weighted angular spread
 *     S = sum E_i (1 - d . omega_i) = E - |sum E_i omega_i|,   d the region's centroid direction,
 * which is half the energy-weighted squared chord distance of its pixels from the light that replaces them.
 * Collapsing a region into one light changes the irradiance only for normals whose horizon cuts the region
 * (and by the cosine's curvature elsewhere); both effects grow with energy times angular spread, so S ranks
 * regions by the error their light makes. Splitting by energy alone (the classic choice) keeps cutting the
 * sun's tiny region, whose light is already exact, while a wide dim sky stays one light. Ties (regions
 * without spread, e.g. black ones) go to the larger region. The first n - 1 splits give n lights, so the
 * results for growing n are nested. */
#include "probe_internal.h"
#include "generic/memory.h"

typedef struct {
    double key, area;
    int index;
} HeapItem;

static int heap_less(const HeapItem *a, const HeapItem *b)
{
    return a->key < b->key || (a->key == b->key && a->area < b->area);
}

static void heap_push(HeapItem *h, int *n, HeapItem it)
{
    int i = (*n)++;
    h[i] = it;
    while (i > 0 && heap_less(&h[(i - 1) / 2], &h[i])) {
        HeapItem t = h[i];
        h[i] = h[(i - 1) / 2];
        h[(i - 1) / 2] = t;
        i = (i - 1) / 2;
    }
}

static HeapItem heap_pop(HeapItem *h, int *n)
{
    HeapItem top = h[0];
    h[0] = h[--(*n)];
    for (int i = 0;;) {
        int l = 2 * i + 1, r = l + 1, m = i;
        if (l < *n && heap_less(&h[m], &h[l]))
            m = l;
        if (r < *n && heap_less(&h[m], &h[r]))
            m = r;
        if (m == i)
            break;
        HeapItem t = h[i];
        h[i] = h[m];
        h[m] = t;
        i = m;
    }
    return top;
}

static HeapItem item(const ProbeRegion *r, int index)
{
    HeapItem it = {probe_region_spread(r), (double)(r->u1 - r->u0) * (r->v1 - r->v0), index};
    return it;
}

int probe_adaptive_regions(const GProbe *p, int n, ProbeRegion *regions, GError *err)
{
    if (n < 1)
        return gerror_set(err, G_ERR_INVALID, "adaptive median cut needs at least one light, not %d", n);
    HeapItem *heap = gmem_calloc((size_t)n, sizeof *heap);
    if (!heap)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    int count = 1, hn = 0;
    probe_region_init(p, &regions[0], 0, 0, p->w, p->h);
    heap_push(heap, &hn, item(&regions[0], 0));
    while (count < n) {
        HeapItem top = heap_pop(heap, &hn);
        ProbeRegion a, b;
        probe_region_split(p, &regions[top.index], &a, &b);
        regions[top.index] = a;
        regions[count] = b;
        heap_push(heap, &hn, item(&a, top.index));
        heap_push(heap, &hn, item(&b, count));
        count++;
    }
    gmem_free(heap);
    return G_OK;
}

int gprobe_adaptive_median_cut(const GProbe *p, int n, GProbeLight *lights, GError *err)
{
    if (n < 1 || !lights)
        return gerror_set(err, G_ERR_INVALID, "adaptive median cut needs at least one light, not %d", n);
    ProbeRegion *regions = gmem_calloc((size_t)n, sizeof *regions);
    if (!regions)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d regions", n);
    int rc = probe_adaptive_regions(p, n, regions, err);
    if (rc == G_OK)
        probe_regions_to_lights(p, regions, n, lights);
    gmem_free(regions);
    return rc;
}
