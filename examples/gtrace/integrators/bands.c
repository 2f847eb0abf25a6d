/* bands.c - the colour model's wavelength bands grouped for dispersion (bands.h). Only the colour
 * interface's band slots and generic operations are used: what a band is belongs to the model. */
#include "bands.h"

#include <generic/memory.h>
#include <generic/vec.h>

#include <math.h>

void bands_free(Bands *b)
{
    if (b->mask)
        for (int g = 0; g < b->n; g++)
            gcolor_free(&b->mask[g]);
    gmem_free(b->mask);
    gmem_free(b->first);
    *b = (Bands){0};
}

int bands_init(Bands *b, const GColorModel *m, int cap, GError *err)
{
    *b = (Bands){0};
    int nb = gcolormodel_band_count(m);
    if (cap <= 0)
        cap = BANDS_DEFAULT_CAP;
    b->n = nb < cap ? nb : cap;
    size_t per_mask = gcolormodel_value_bytes(m), most = per_mask > 0 ? BANDS_MASK_BUDGET / per_mask : 1;
    if (most < 1)
        most = 1;
    if ((size_t)b->n > most)
        b->n = (int)most;
    b->first = gmem_calloc((size_t)b->n + 1, sizeof *b->first);
    b->mask = gmem_calloc((size_t)b->n, sizeof *b->mask);
    if (!b->first || !b->mask) {
        bands_free(b);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d wavelength bands", nb);
    }
    int rc = G_OK;
    GColor one = {0};
    if ((rc = gcolor_alloc(&one, m)) != G_OK)
        goto fail;
    for (int g = 0; g < b->n && rc == G_OK; g++) {
        b->first[g] = (int)((long long)g * nb / b->n);
        b->first[g + 1] = (int)((long long)(g + 1) * nb / b->n);
        if ((rc = gcolor_alloc(&b->mask[g], m)) != G_OK)
            break;
        for (int k = b->first[g]; k < b->first[g + 1] && rc == G_OK; k++)
            if ((rc = gcolor_band_mask(&one, k)) == G_OK)
                rc = gcolor_add(&b->mask[g], &b->mask[g], &one);
    }
    gcolor_free(&one);
    if (rc == G_OK)
        return G_OK;
fail:
    bands_free(b);
    return gerror_set(err, rc, "the colour model '%s' cannot give the masks of its %d wavelength bands",
                      gcolormodel_name(m), nb);
}

double bands_value(const Bands *b, const GColor *ri, int g)
{
    double sum = 0.0;
    int k0 = b->first[g], k1 = b->first[g + 1];
    for (int k = k0; k < k1; k++)
        sum += gcolor_band_value(ri, k);
    return sum / (k1 - k0);
}

int bands_disperse(const Bands *b, const GColor *ri)
{
    if (b->n < 2 || ri->kind != GCOLOR_VECTOR)
        return 0;
    /* the index at the first, the middle and the last band: a refraction that does not disperse (every hit on
     * constant-index glass) costs three lookups (an index equal there but different in between is not split) */
    int last = b->first[b->n] - 1, probe[3] = {0, last / 2, last};
    double v[3];
    for (int k = 0; k < 3; k++)
        if (!isfinite(v[k] = gcolor_band_value(ri, probe[k])))
            return 0;
    double lo = gfmin(v[0], gfmin(v[1], v[2])), hi = gfmax(v[0], gfmax(v[1], v[2]));
    return hi - lo > BANDS_INDEX_TOLERANCE;
}
