/* area_light.c - sphere and rectangle lights as rays meet them and next-event estimation samples them
 * (area_light.h): where a ray meets one and with what density the light sample draws that direction, and the light
 * sample itself (a sphere uniformly in the solid angle it subtends, a rectangle uniformly by area). */
#include "area_light.h"

#include <math.h>

double area_light_hit(const Light *l, const Ray *r, double tmax, double *pdf)
{
    if (l->kind == LIGHT_SPHERE) {
        GVec3 oc = gvec3_sub(l->position, r->o);
        double dc2 = gvec3_dot(oc, oc), r2 = l->radius * l->radius, b = gvec3_dot(oc, r->d);
        double disc = b * b - (dc2 - r2);
        if (dc2 <= r2 || b <= 0.0 || disc < 0.0)
            return INFINITY;
        double t = b - sqrt(disc);
        if (!(t > 0.0 && t < tmax))
            return INFINITY;
        double omega = 2.0 * M_PI * (1.0 - sqrt(fmax(0.0, 1.0 - r2 / dc2)));
        *pdf = omega > 0.0 ? 1.0 / omega : 0.0;
        return t;
    }
    if (l->kind == LIGHT_RECT) {
        GVec3 nl = gvec3_cross(l->edge1, l->edge2);
        double area = gvec3_length(nl);
        if (!(area > 0.0))
            return INFINITY;
        nl = gvec3_scale(nl, 1.0 / area);
        double dn = gvec3_dot(r->d, nl);
        if (!(dn < 0.0)) /* one-sided: only the lit side faces the ray */
            return INFINITY;
        double t = gvec3_dot(gvec3_sub(l->position, r->o), nl) / dn;
        if (!(t > 0.0 && t < tmax))
            return INFINITY;
        /* parallelogram coordinates of the hit */
        GVec3 q = gvec3_sub(gvec3_madd(r->o, r->d, t), l->position);
        double aa = gvec3_dot(l->edge1, l->edge1), ab = gvec3_dot(l->edge1, l->edge2);
        double bb = gvec3_dot(l->edge2, l->edge2), det = aa * bb - ab * ab;
        double qa = gvec3_dot(q, l->edge1), qb = gvec3_dot(q, l->edge2);
        double a = (bb * qa - ab * qb) / det, b = (aa * qb - ab * qa) / det;
        if (!(a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0))
            return INFINITY;
        *pdf = t * t / (area * -dn);
        return t;
    }
    return INFINITY;
}

int path_light_sample(TraceCtx *c, const Light *l, GVec3 x, GVec3 *in, double *dist, double *pdf, GColor *L)
{
    double u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
    return path_light_sample_at(l, x, u1, u2, in, dist, pdf, L);
}

int path_light_sample_at(const Light *l, GVec3 x, double u1, double u2, GVec3 *in, double *dist, double *pdf,
                         GColor *L)
{
    int got = path_light_direction_at(l, x, u1, u2, in, dist, pdf), rc;
    if (got <= 0)
        return got;
    return (rc = gcolor_copy(L, &l->color)) < 0 ? rc : 1;
}

int path_light_direction_at(const Light *l, GVec3 x, double u1, double u2, GVec3 *in, double *dist, double *pdf)
{
    if (l->kind == LIGHT_SPHERE) {
        GVec3 axis = gvec3_sub(l->position, x);
        double dc = gvec3_length(axis);
        if (!(dc > l->radius))
            return 0;
        axis = gvec3_scale(axis, 1.0 / dc);
        double sin_max = l->radius / dc, cos_max = sqrt(fmax(0.0, 1.0 - sin_max * sin_max));
        double omega = 2.0 * M_PI * (1.0 - cos_max);
        if (!(omega > 0.0))
            return 0;
        GVec3 t1, t2;
        goptics_frame(axis, &t1, &t2);
        double ct = 1.0 - u1 * (1.0 - cos_max), st = sqrt(fmax(0.0, 1.0 - ct * ct)), ph = 2.0 * M_PI * u2;
        *in = gvec3_add(gvec3_scale(axis, ct), gvec3_add(gvec3_scale(t1, st * cos(ph)), gvec3_scale(t2, st * sin(ph))));
        double b = dc * ct, disc = b * b - (dc * dc - l->radius * l->radius);
        *dist = b - sqrt(fmax(0.0, disc));
        *pdf = 1.0 / omega;
        return 1;
    }
    if (l->kind == LIGHT_RECT) {
        GVec3 nl = gvec3_cross(l->edge1, l->edge2);
        double area = gvec3_length(nl);
        if (!(area > 0.0))
            return 0;
        nl = gvec3_scale(nl, 1.0 / area);
        GVec3 y = gvec3_add(l->position, gvec3_add(gvec3_scale(l->edge1, u1), gvec3_scale(l->edge2, u2)));
        GVec3 w = gvec3_sub(y, x);
        double d = gvec3_length(w);
        if (!(d > 0.0))
            return 0;
        *in = gvec3_scale(w, 1.0 / d);
        double cos_l = -gvec3_dot(*in, nl);
        if (!(cos_l > 0.0))
            return 0;
        *dist = d;
        *pdf = d * d / (area * cos_l);
        return 1;
    }
    return 0;
}
