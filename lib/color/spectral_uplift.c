/* spectral_uplift.c - RGB to a sampled spectrum (gspectral_from_rgb, kit/spectral.h): the sigmoid uplift onto the
 * model's grid through the thread's memo, or the corrected basis (`uplift basis`); and the exact XYZ sums the kit
 * checks against. */
#include "spectral_uplift.h"
#include "generic/kit/spectral_kernels.h"
#include "uplift.h"
#include "uplift_fit.h"
#include "uplift_memo.h"

#include <string.h>

void spectral_xyz_exact(const GSpectral *s, GColorRole role, const float *v, double xyz[3])
{
    int n = s->grid.n;
    const double *w = s->xyz[role == GCOLOR_LIGHT];
    double x = 0.0, y = 0.0, z = 0.0;
    for (int k = 0; k < n; k++) {
        x += w[k] * v[k];
        y += w[n + k] * v[k];
        z += w[2 * n + k] * v[k];
    }
    xyz[0] = x;
    xyz[1] = y;
    xyz[2] = z;
}

/* The sigmoid uplift at the grid's wavelengths, refined against the model's own weights (no allocation). A grid
 * too coarse for a sigmoid to reach a colour that sigmoid spectra do reach at 1 nm (spectrum9's nine samples and
 * the saturated corners of the cube) gets the rest through the corrected basis: the round trip stays exact, and
 * only those colours' samples may leave [0, 1]. A colour no sigmoid spectrum reaches (a wide-gamut colour beyond
 * the reflectances) keeps the nearest one: mapped, within [0, 1]. */
static int from_rgb_sigmoid(const GSpectral *s, const double rgb[3], GColorRole role, float *out)
{
    GUplift u;
    int rc = guplift_from_rgb(rgb, role, &u);
    if (rc != G_OK)
        return rc;
    int n = s->grid.n, light = role == GCOLOR_LIGHT;
    const double *f = s->fit[light];
    const double *w[3] = {f + n, f + 2 * n, f + 3 * n};
    double left = 0.0;
    rc = guplift_refine(&u, n, f, w, f + 5 * n, &left);
    guplift_sigmoid_samples(&u, n, f, f + 4 * n, out);
    GSpectrumNM nm;
    double reach = 0.0;
    if (rc != G_OK || !(left > 1e-3) || guplift_rgb_to_nm(rgb, role, &nm, &reach) != G_OK || reach > 1e-3)
        return rc;
    double xyz[3], want[3], d[3], drgb[3];
    spectral_xyz_exact(s, role, out, xyz);
    for (int c = 0; c < 3; c++) {
        want[c] = u.scale * u.xyz[c];
        d[c] = want[c] - xyz[c];
    }
    gcie_xyz_to_rgb(d, drgb);
    const float *b = s->rgb[light];
    for (int k = 0; k < n; k++)
        out[k] = (float)(out[k] + drgb[0] * b[k] + drgb[1] * b[n + k] + drgb[2] * b[2 * n + k]);
    return G_OK;
}

/* from_rgb_sigmoid through the thread's memo (lib/color/uplift_memo.h): an image texture's texels come back
 * again and again, and each costs a fit; the memo holds exactly what the fit gave. */
static int from_rgb_sigmoid_memo(const GSpectral *s, const double rgb[3], GColorRole role, float *out)
{
    int n = s->grid.n;
    unsigned long epoch;
    const float *kept = guplift_memo_find(s, (int)role, rgb, n, &epoch);
    if (kept) {
        memcpy(out, kept, (size_t)n * sizeof *out);
        return G_OK;
    }
    int rc = from_rgb_sigmoid(s, rgb, role, out);
    if (rc == G_OK)
        guplift_memo_store(s, (int)role, rgb, n, out, epoch);
    return rc;
}

int gspectral_from_rgb(const GColorModel *m, const double rgb[3], GColorRole role, GColor *out)
{
    const GSpectral *s = m->priv;
    if (s->uplift != GCOLOR_UPLIFT_BASIS) {
        out->kind = GCOLOR_VECTOR;
        return from_rgb_sigmoid_memo(s, rgb, role, out->v);
    }
    int n = m->nvalues;
    const float *b = s->rgb[role == GCOLOR_LIGHT];
    float r = (float)rgb[0], g = (float)rgb[1], bl = (float)rgb[2];
    out->kind = GCOLOR_VECTOR;
    gspectral_kmix3(out->v, b, b + n, b + 2 * n, r, g, bl, n);
    return G_OK;
}
