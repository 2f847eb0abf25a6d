/* alias_table.c - Walker's alias method (Walker 1977) with Vose's construction (Vose 1991): the outcomes whose scaled
 * probability is below 1 are filled up by those above, one pair at a time, so each slot holds at most two. */
#include "alias_table.h"

#include <generic/error.h>
#include <generic/memory.h>

int alias_table_build(const double *prob, int n, double *q, int *alias)
{
    int *small = gmem_alloc(sizeof *small * (size_t)n), *large = gmem_alloc(sizeof *large * (size_t)n);
    if (!small || !large) {
        gmem_free(small);
        gmem_free(large);
        return G_ERR_NOMEM;
    }
    int ns = 0, nl = 0;
    for (int i = 0; i < n; i++) {
        q[i] = prob[i] * n;
        alias[i] = i;
        if (q[i] < 1.0)
            small[ns++] = i;
        else
            large[nl++] = i;
    }
    while (ns > 0 && nl > 0) {
        int s = small[--ns], l = large[--nl];
        alias[s] = l;
        q[l] -= 1.0 - q[s];
        if (q[l] < 1.0)
            small[ns++] = l;
        else
            large[nl++] = l;
    }
    while (nl > 0) /* rounding: what is left keeps its slot */
        q[large[--nl]] = 1.0;
    while (ns > 0)
        q[small[--ns]] = 1.0;
    gmem_free(small);
    gmem_free(large);
    return G_OK;
}

int alias_table_pick(const double *q, const int *alias, int n, double u, double *u_rest)
{
    double f = u * n;
    int i = (int)f;
    if (i >= n)
        i = n - 1;
    double v = f - i; /* uniform in [0, 1) within the slot */
    int keep = v < q[i];
    if (u_rest) { /* the part of [0, 1) the outcome took, stretched back to [0, 1) */
        double r = keep ? v / q[i] : (v - q[i]) / (1.0 - q[i]);
        *u_rest = r < 1.0 ? (r > 0.0 ? r : 0.0) : 0x1.fffffffffffffp-1;
    }
    return keep ? i : alias[i];
}
