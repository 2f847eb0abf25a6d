/* light_seen.c - area lights seen by camera rays: a sphere or rectangle light with `visible on` appears as its
 * radiance where a camera ray meets it before any object (whitted_trace asks for camera rays only; reflections
 * and refractions show the light through the materials' highlights, as before). */
#include "lighting.h"

#include <math.h>

/* Distance along r to the light's surface in (tmin, tmax), or INFINITY. */
static double light_distance(const Light *l, const Ray *r, double tmax)
{
    if (l->kind == LIGHT_SPHERE) {
        GVec3 oc = gvec3_sub(r->o, l->position);
        double b = gvec3_dot(oc, r->d), c = gvec3_dot(oc, oc) - l->radius * l->radius, disc = b * b - c;
        if (c <= 0.0 || disc < 0.0) /* inside the light, or a miss */
            return INFINITY;
        double t = -b - sqrt(disc);
        return t > r->tmin && t < tmax ? t : INFINITY;
    }
    /* rectangle: corner + a edge1 + b edge2, (a, b) in [0,1]^2, seen from the side edge1 x edge2 faces */
    GVec3 n = gvec3_cross(l->edge1, l->edge2);
    double dn = gvec3_dot(r->d, n);
    if (!(dn < 0.0))
        return INFINITY;
    double t = gvec3_dot(gvec3_sub(l->position, r->o), n) / dn;
    if (!(t > r->tmin && t < tmax))
        return INFINITY;
    GVec3 q = gvec3_sub(gvec3_madd(r->o, r->d, t), l->position);
    double e11 = gvec3_dot(l->edge1, l->edge1), e12 = gvec3_dot(l->edge1, l->edge2),
           e22 = gvec3_dot(l->edge2, l->edge2);
    double q1 = gvec3_dot(q, l->edge1), q2 = gvec3_dot(q, l->edge2), det = e11 * e22 - e12 * e12;
    double a = (e22 * q1 - e12 * q2) / det, b = (e11 * q2 - e12 * q1) / det;
    return a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0 ? t : INFINITY;
}

int light_seen(const Scene *s, const Ray *r, double tmax, GColor *out, int *status)
{
    const Light *best = NULL;
    double bt = tmax;
    *status = G_OK;
    for (int i = 0; i < s->nlights; i++) {
        const Light *l = s->lights[i];
        if (!l->visible || (l->kind != LIGHT_SPHERE && l->kind != LIGHT_RECT))
            continue;
        double t = light_distance(l, r, bt);
        if (t < bt) {
            bt = t;
            best = l;
        }
    }
    if (!best)
        return 0;
    *status = gcolor_copy(out, &best->color);
    return 1;
}
