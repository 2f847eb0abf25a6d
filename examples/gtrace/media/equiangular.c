/* equiangular.c - equiangular distance sampling (equiangular.h). With h = t - delta the distance along the ray from
 * the point's foot, theta = atan(h / D) is uniform between the ends' angles: t = delta + D tan(theta), of density
 * D / ((theta_b - theta_a) (D^2 + h^2)). */
#include "equiangular.h"

#include <math.h>

int equiangular_setup(Equiangular *e, GVec3 o, GVec3 d, double tmax, GVec3 c)
{
    GVec3 oc = gvec3_sub(c, o);
    double delta = gvec3_dot(oc, d);
    double dist = gvec3_length(gvec3_sub(oc, gvec3_scale(d, delta)));
    double scale = fmax(fabs(delta), gvec3_length(oc));
    if (!(dist > 1e-9 * scale) || !(tmax > 0.0))
        return 0;
    e->delta = delta;
    e->dist = dist;
    e->theta_a = atan2(-delta, dist);
    e->theta_b = isfinite(tmax) ? atan2(tmax - delta, dist) : 0.5 * M_PI;
    return e->theta_b > e->theta_a;
}

double equiangular_sample(const Equiangular *e, double u, double *pdf)
{
    double theta = e->theta_a + u * (e->theta_b - e->theta_a);
    double h = e->dist * tan(theta);
    *pdf = e->dist / ((e->theta_b - e->theta_a) * (e->dist * e->dist + h * h));
    return e->delta + h;
}

double equiangular_pdf(const Equiangular *e, double t)
{
    double h = t - e->delta;
    double theta = atan2(h, e->dist);
    if (!(theta >= e->theta_a && theta <= e->theta_b))
        return 0.0;
    return e->dist / ((e->theta_b - e->theta_a) * (e->dist * e->dist + h * h));
}
