/* affine.c - 2D and 3D affine maps for transform nodes and CSG/CPG trees. */
#include "generic/kit/affine.h"

#include <math.h>

static double rad(double degrees) { return degrees * (M_PI / 180.0); }

GAffine2 gaffine2_identity(void) { return (GAffine2){{1, 0, 0, 0, 1, 0}}; }
GAffine2 gaffine2_translate(double tx, double ty) { return (GAffine2){{1, 0, tx, 0, 1, ty}}; }
GAffine2 gaffine2_scale(double sx, double sy) { return (GAffine2){{sx, 0, 0, 0, sy, 0}}; }

GAffine2 gaffine2_rotate(double degrees)
{
    double c = cos(rad(degrees)), s = sin(rad(degrees));
    return (GAffine2){{c, -s, 0, s, c, 0}};
}

GAffine2 gaffine2_mul(const GAffine2 *a, const GAffine2 *b)
{
    const double *x = a->m, *y = b->m;
    return (GAffine2){{x[0] * y[0] + x[1] * y[3], x[0] * y[1] + x[1] * y[4], x[0] * y[2] + x[1] * y[5] + x[2],
                       x[3] * y[0] + x[4] * y[3], x[3] * y[1] + x[4] * y[4], x[3] * y[2] + x[4] * y[5] + x[5]}};
}

int gaffine2_invert(const GAffine2 *a, GAffine2 *inv, GError *err)
{
    const double *m = a->m;
    double det = m[0] * m[4] - m[1] * m[3];
    double scale = fabs(m[0]) + fabs(m[1]) + fabs(m[3]) + fabs(m[4]);
    if (!isfinite(det) || !isfinite(m[2]) || !isfinite(m[5]) || fabs(det) <= 1e-12 * scale * scale)
        return gerror_set(err, G_ERR_INVALID, "2D transform is singular or not finite (determinant %g)", det);
    double id = 1.0 / det;
    double a0 = m[4] * id, a1 = -m[1] * id, a3 = -m[3] * id, a4 = m[0] * id;
    *inv = (GAffine2){{a0, a1, -(a0 * m[2] + a1 * m[5]), a3, a4, -(a3 * m[2] + a4 * m[5])}};
    return G_OK;
}

void gaffine2_apply(const GAffine2 *a, double x, double y, double *ox, double *oy)
{
    *ox = a->m[0] * x + a->m[1] * y + a->m[2];
    *oy = a->m[3] * x + a->m[4] * y + a->m[5];
}

GAffine3 gaffine3_identity(void) { return (GAffine3){{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}; }
GAffine3 gaffine3_translate(GVec3 t) { return (GAffine3){{1, 0, 0, t.x, 0, 1, 0, t.y, 0, 0, 1, t.z}}; }
GAffine3 gaffine3_scale(GVec3 s) { return (GAffine3){{s.x, 0, 0, 0, 0, s.y, 0, 0, 0, 0, s.z, 0}}; }

GAffine3 gaffine3_rotate(GVec3 axis, double degrees)
{
    GVec3 k = gvec3_normalize(axis);
    if (gvec3_length(k) == 0.0)
        return gaffine3_identity();
    double c = cos(rad(degrees)), s = sin(rad(degrees)), t = 1.0 - c;
    return (GAffine3){{t * k.x * k.x + c, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y, 0,
                       t * k.x * k.y + s * k.z, t * k.y * k.y + c, t * k.y * k.z - s * k.x, 0,
                       t * k.x * k.z - s * k.y, t * k.y * k.z + s * k.x, t * k.z * k.z + c, 0}};
}

GAffine3 gaffine3_mul(const GAffine3 *a, const GAffine3 *b)
{
    GAffine3 r;
    for (int i = 0; i < 3; i++) {
        const double *x = a->m + 4 * i;
        for (int j = 0; j < 4; j++)
            r.m[4 * i + j] = x[0] * b->m[j] + x[1] * b->m[4 + j] + x[2] * b->m[8 + j];
        r.m[4 * i + 3] += x[3];
    }
    return r;
}

int gaffine3_invert(const GAffine3 *a, GAffine3 *inv, GError *err)
{
    const double *m = a->m;
    double c00 = m[5] * m[10] - m[6] * m[9], c01 = m[6] * m[8] - m[4] * m[10], c02 = m[4] * m[9] - m[5] * m[8];
    double det = m[0] * c00 + m[1] * c01 + m[2] * c02;
    double scale = 0.0;
    int finite = 1;
    for (int i = 0; i < 12; i++) {
        finite &= isfinite(m[i]) != 0;
        if (i % 4 != 3)
            scale = fmax(scale, fabs(m[i]));
    }
    if (!finite || !isfinite(det) || fabs(det) <= 1e-12 * scale * scale * scale)
        return gerror_set(err, G_ERR_INVALID, "3D transform is singular or not finite (determinant %g)", det);
    double id = 1.0 / det;
    double l[9] = {c00 * id, (m[2] * m[9] - m[1] * m[10]) * id, (m[1] * m[6] - m[2] * m[5]) * id,
                   c01 * id, (m[0] * m[10] - m[2] * m[8]) * id, (m[2] * m[4] - m[0] * m[6]) * id,
                   c02 * id, (m[1] * m[8] - m[0] * m[9]) * id, (m[0] * m[5] - m[1] * m[4]) * id};
    for (int i = 0; i < 3; i++) {
        inv->m[4 * i] = l[3 * i];
        inv->m[4 * i + 1] = l[3 * i + 1];
        inv->m[4 * i + 2] = l[3 * i + 2];
        inv->m[4 * i + 3] = -(l[3 * i] * m[3] + l[3 * i + 1] * m[7] + l[3 * i + 2] * m[11]);
    }
    return G_OK;
}

GVec3 gaffine3_apply(const GAffine3 *a, GVec3 p)
{
    const double *m = a->m;
    return gvec3(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                 m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
}

GVec3 gaffine3_apply_dir(const GAffine3 *a, GVec3 d)
{
    const double *m = a->m;
    return gvec3(m[0] * d.x + m[1] * d.y + m[2] * d.z, m[4] * d.x + m[5] * d.y + m[6] * d.z,
                 m[8] * d.x + m[9] * d.y + m[10] * d.z);
}
