/* transform.c - affine object transforms (object -> world) and their inverses. */
#include "transform.h"

#include <generic/error.h>

#include <math.h>
#include <string.h>

void xform_identity(Xform *x)
{
    memset(x, 0, sizeof *x);
    for (int i = 0; i < 3; i++)
        x->m[i][i] = x->inv[i][i] = 1.0;
}

/* Inverse of an affine 3x4 matrix; G_ERR_INVALID when singular. */
static int invert(const double a[3][4], double r[3][4])
{
    double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    double scale = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            scale = fmax(scale, fabs(a[i][j]));
    if (!isfinite(det) || scale == 0.0 || fabs(det) < 1e-12 * scale * scale * scale)
        return G_ERR_INVALID;
    double id = 1.0 / det;
    r[0][0] = c00 * id;
    r[1][0] = c01 * id;
    r[2][0] = c02 * id;
    r[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * id;
    r[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * id;
    r[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * id;
    r[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * id;
    r[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * id;
    r[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * id;
    for (int i = 0; i < 3; i++)
        r[i][3] = -(r[i][0] * a[0][3] + r[i][1] * a[1][3] + r[i][2] * a[2][3]);
    return G_OK;
}

int xform_matrix(Xform *x, const double rows[3][4])
{
    double r[3][4], inv[3][4];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += rows[i][k] * x->m[k][j];
            r[i][j] = s + (j == 3 ? rows[i][3] : 0.0);
        }
    }
    if (invert(r, inv) != G_OK)
        return G_ERR_INVALID;
    memcpy(x->m, r, sizeof r);
    memcpy(x->inv, inv, sizeof inv);
    return G_OK;
}

int xform_translate(Xform *x, GVec3 t)
{
    const double r[3][4] = {{1, 0, 0, t.x}, {0, 1, 0, t.y}, {0, 0, 1, t.z}};
    return xform_matrix(x, r);
}

int xform_rotate(Xform *x, GVec3 axis, double degrees)
{
    GVec3 a = gvec3_normalize(axis);
    if (gvec3_length(a) == 0.0)
        return G_ERR_INVALID;
    double th = degrees * (M_PI / 180.0), c = cos(th), s = sin(th), t = 1.0 - c;
    const double r[3][4] = {
        {t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y, 0},
        {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x, 0},
        {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c, 0},
    };
    return xform_matrix(x, r);
}

int xform_scale(Xform *x, GVec3 s)
{
    const double r[3][4] = {{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}};
    return xform_matrix(x, r);
}

static GVec3 apply(const double m[3][4], GVec3 p, double w)
{
    return gvec3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + w * m[0][3],
                 m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + w * m[1][3],
                 m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + w * m[2][3]);
}

GVec3 xform_point(const Xform *x, GVec3 p) { return apply(x->m, p, 1.0); }
GVec3 xform_vector(const Xform *x, GVec3 v) { return apply(x->m, v, 0.0); }
GVec3 xform_inv_point(const Xform *x, GVec3 p) { return apply(x->inv, p, 1.0); }
GVec3 xform_inv_vector(const Xform *x, GVec3 v) { return apply(x->inv, v, 0.0); }

GVec3 xform_normal(const Xform *x, GVec3 n)
{
    /* inverse transpose */
    const double (*i)[4] = x->inv;
    return gvec3(i[0][0] * n.x + i[1][0] * n.y + i[2][0] * n.z, i[0][1] * n.x + i[1][1] * n.y + i[2][1] * n.z,
                 i[0][2] * n.x + i[1][2] * n.y + i[2][2] * n.z);
}

void frame_from_normal(GVec3 n, GVec3 *t1, GVec3 *t2)
{
    /* the world axis least aligned with n, projected: floors (n = +y) get u along +x, v along -z */
    GVec3 ref = fabs(n.x) < 0.9 ? gvec3(1, 0, 0) : gvec3(0, 1, 0);
    GVec3 a = gvec3_normalize(gvec3_madd(ref, n, -gvec3_dot(ref, n)));
    *t1 = a;
    *t2 = gvec3_cross(n, a);
}

static void mul34(const double a[3][4], const double b[3][4], double r[3][4])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + (j == 3 ? a[i][3] : 0.0);
}

void xform_compose(const Xform *outer, const Xform *inner, Xform *out)
{
    mul34(outer->m, inner->m, out->m);
    mul34(inner->inv, outer->inv, out->inv);
}
