/* viewing.c - the viewing illuminant: a named light's white as the colour model has it, and the Bradford chromatic
 * adaptation from that white to D65 (viewing.h). */
#include "viewing.h"

#include <math.h>
#include <string.h>

/* The Bradford cone response matrix (Lam 1985, as published by Lindbloom). */
static const double bradford[9] = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};

/* inv = the inverse of a (row by row), by its cofactors; a is invertible (the Bradford matrix). */
static void invert3(const double a[9], double inv[9])
{
    double c[9] = {a[4] * a[8] - a[5] * a[7], a[2] * a[7] - a[1] * a[8], a[1] * a[5] - a[2] * a[4],
                   a[5] * a[6] - a[3] * a[8], a[0] * a[8] - a[2] * a[6], a[2] * a[3] - a[0] * a[5],
                   a[3] * a[7] - a[4] * a[6], a[1] * a[6] - a[0] * a[7], a[0] * a[4] - a[1] * a[3]};
    double det = a[0] * c[0] + a[1] * c[3] + a[2] * c[6];
    for (int i = 0; i < 9; i++)
        inv[i] = c[i] / det;
}

void viewing_apply(const double M[9], const double xyz[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = M[3 * i] * xyz[0] + M[3 * i + 1] * xyz[1] + M[3 * i + 2] * xyz[2];
    memcpy(out, r, sizeof r);
}

int viewing_adaptation(const GColorModel *m, const char *name, double out[9], GError *err)
{
    GColor c = {0};
    double src[3], dst[3];
    static const double one[3] = {1.0, 1.0, 1.0};
    int rc = gcolor_alloc(&c, m);
    if (rc != G_OK)
        return gerror_set(err, rc, "no memory for the viewing illuminant");
    if ((rc = gcolor_named_light(&c, name, err)) == G_OK && (rc = gcolor_to_xyz(&c, GCOLOR_LIGHT, src)) != G_OK)
        gerror_set(err, rc, "the viewing illuminant cannot be converted in the colour model '%s'",
                   gcolormodel_name(m));
    gcolor_free(&c);
    if (rc != G_OK)
        return rc;
    if (!(src[0] > 0.0 && src[1] > 0.0 && src[2] > 0.0) || !isfinite(src[0] + src[1] + src[2]))
        return gerror_set(err, G_ERR_INVALID, "the viewing illuminant's white is XYZ %g %g %g in the colour model "
                          "'%s': not positive", src[0], src[1], src[2], gcolormodel_name(m));
    /* the white gcie_xyz_to_rgb maps to equal components (its matrix, read column by column, inverted), at the
     * source's luminance */
    double to_out[9], to_xyz[9];
    for (int j = 0; j < 3; j++) {
        double e[3] = {j == 0, j == 1, j == 2}, col[3];
        gcie_xyz_to_rgb(e, col);
        for (int i = 0; i < 3; i++)
            to_out[3 * i + j] = col[i];
    }
    invert3(to_out, to_xyz);
    viewing_apply(to_xyz, one, dst);
    const double luminance = src[1] / dst[1];
    for (int i = 0; i < 3; i++)
        dst[i] *= luminance;
    double cs[3], cd[3], scaled[9], bradford_inv[9];
    invert3(bradford, bradford_inv);
    viewing_apply(bradford, src, cs);
    viewing_apply(bradford, dst, cd);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            scaled[3 * i + j] = cd[i] / cs[i] * bradford[3 * i + j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] = bradford_inv[3 * i] * scaled[j] + bradford_inv[3 * i + 1] * scaled[3 + j] +
                             bradford_inv[3 * i + 2] * scaled[6 + j];
    return G_OK;
}
