/* color_wavelengths.c - a colour's values at its model's own wavelengths, for writers of spectral images
 * (generic/color.h: gcolormodel_wavelengths, gcolor_at_wavelengths). Generic: the model's grid comes from its
 * public sizes, the values from its nm exchange spectrum. */
#include "generic/color.h"

#include <math.h>

/* The model's k-th sample wavelength, and the range of k that lies within GNM_MIN..GNM_MAX. */
static void grid_range(const GColorModel *m, int *first, int *count)
{
    *first = *count = 0;
    if (!m || m->nsamples <= 0 || !(m->lambda_step > 0.0) || !isfinite(m->lambda_min))
        return;
    int k0 = 0, k1 = m->nsamples; /* [k0, k1) */
    while (k0 < k1 && m->lambda_min + k0 * m->lambda_step < GNM_MIN - 1e-9)
        k0++;
    while (k1 > k0 && m->lambda_min + (k1 - 1) * m->lambda_step > GNM_MAX + 1e-9)
        k1--;
    *first = k0;
    *count = k1 - k0;
}

int gcolormodel_wavelengths(const GColorModel *m, double *nm, int max)
{
    int first, count;
    grid_range(m, &first, &count);
    for (int k = 0; k < count && k < max; k++)
        nm[k] = m->lambda_min + (first + k) * m->lambda_step;
    return count;
}

int gcolor_at_wavelengths(const GColor *c, GColorRole role, float *out, int n)
{
    if (!c || !c->model || !out)
        return G_ERR_INVALID;
    const GColorModel *m = c->model;
    int first, count;
    grid_range(m, &first, &count);
    if (count == 0 || n != count)
        return G_ERR_INVALID;
    GSpectrumNM s;
    int rc = gcolor_to_nm(c, role, &s);
    if (rc != G_OK)
        return rc;
    for (int k = 0; k < n; k++) { /* linear between the exchange spectrum's whole nm */
        double x = m->lambda_min + (first + k) * m->lambda_step - GNM_MIN;
        int i = (int)floor(x);
        if (i < 0)
            i = 0;
        if (i > GNM_COUNT - 2)
            i = GNM_COUNT - 2;
        double t = x - i;
        t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
        out[k] = (float)((1.0 - t) * s.v[i] + t * s.v[i + 1]);
    }
    return G_OK;
}
