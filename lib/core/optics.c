/* optics.c - geometric optics shared by material implementations: the ideal-direction check, Snell
 * refraction and the unpolarised Fresnel reflectance. */
#include "generic/material.h"

#include <math.h>

int gmaterial_is_mirror_pair(GVec3 in, GVec3 n, GVec3 out)
{
    /* cos(ideal, out) > 1 - 1e-6 without square roots: compare squares once the dot product is positive */
    GVec3 ideal = gvec3_sub(gvec3_scale(n, 2.0 * gvec3_dot(in, n)), in);
    double d = gvec3_dot(ideal, out), c = 1.0 - 1e-6;
    if (!(d > 0.0))
        return 0;
    return d * d > c * c * gvec3_dot(ideal, ideal) * gvec3_dot(out, out);
}

int goptics_refract(GVec3 view, GVec3 n, double eta, GVec3 *dir)
{
    double cos_i = -gvec3_dot(view, n);
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0)
        return 0;
    double cos_t = sqrt(1.0 - sin2_t);
    *dir = gvec3_normalize(gvec3_add(gvec3_scale(view, eta), gvec3_scale(n, eta * cos_i - cos_t)));
    return 1;
}

int goptics_is_refraction_pair(GVec3 view, GVec3 n, double eta, GVec3 in)
{
    /* goptics_refract's direction t before it is normalised, then cos(t, in) > 1 - 1e-6 as
     * gmaterial_is_mirror_pair compares it: squares once the dot product is positive */
    double cos_i = -gvec3_dot(view, n);
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0)
        return 0;
    double cos_t = sqrt(1.0 - sin2_t);
    GVec3 t = gvec3_add(gvec3_scale(view, eta), gvec3_scale(n, eta * cos_i - cos_t));
    double d = gvec3_dot(t, in), c = 1.0 - 1e-6;
    if (!(d > 0.0))
        return 0;
    return d * d > c * c * gvec3_dot(t, t) * gvec3_dot(in, in);
}

double goptics_fresnel(double cos_i, double eta)
{
    cos_i = fabs(cos_i);
    if (cos_i > 1.0)
        cos_i = 1.0;
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0)
        return 1.0;
    double cos_t = sqrt(1.0 - sin2_t);
    /* eta = n1 / n2 */
    double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

void goptics_frame(GVec3 n, GVec3 *t, GVec3 *b)
{
    /* Duff et al. 2017, "Building an orthonormal basis, revisited" */
    double sign = n.z >= 0.0 ? 1.0 : -1.0;
    double a = -1.0 / (sign + n.z), c = n.x * n.y * a;
    *t = gvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = gvec3(c, sign + n.y * n.y * a, -n.y);
}

static GVec3 from_frame(GVec3 n, double x, double y, double z)
{
    GVec3 t, b;
    goptics_frame(n, &t, &b);
    return gvec3_add(gvec3_add(gvec3_scale(t, x), gvec3_scale(b, y)), gvec3_scale(n, z));
}

GVec3 goptics_sample_cosine(GVec3 n, double u1, double u2)
{
    double r = sqrt(u1), phi = 2.0 * M_PI * u2;
    return from_frame(n, r * cos(phi), r * sin(phi), sqrt(fmax(0.0, 1.0 - u1)));
}

GVec3 goptics_sample_hemisphere(GVec3 n, double u1, double u2)
{
    double z = u1, r = sqrt(fmax(0.0, 1.0 - z * z)), phi = 2.0 * M_PI * u2;
    return from_frame(n, r * cos(phi), r * sin(phi), z);
}

GVec3 goptics_sample_lobe(GVec3 a, double e, double u1, double u2)
{
    double z = pow(1.0 - u1, 1.0 / (e + 1.0)), r = sqrt(fmax(0.0, 1.0 - z * z)), phi = 2.0 * M_PI * u2;
    return from_frame(a, r * cos(phi), r * sin(phi), z);
}

double goptics_lobe_pdf(GVec3 a, double e, GVec3 dir)
{
    double c = gvec3_dot(a, dir);
    if (!(c > 0.0))
        return 0.0;
    return (e + 1.0) / (2.0 * M_PI) * pow(c > 1.0 ? 1.0 : c, e);
}
