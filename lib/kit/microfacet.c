/* microfacet.c - GGX and Beckmann microfacet distributions (generic/kit/microfacet.h): D, Lambda, G1, G2 and the
 * sampling of visible normals. */
#include "generic/kit/microfacet.h"

#include <math.h>

#define INV_SQRT_PI 0.56418958354775628695
#define ALPHA_MAX 1e3

double gmicrofacet_alpha_from_roughness(double roughness)
{
    return roughness >= 0.0 && roughness <= 1.0 ? roughness : NAN;
}

static double clamp_alpha(double a)
{
    if (!(a >= GMICROFACET_ALPHA_MIN)) /* also NaN */
        return GMICROFACET_ALPHA_MIN;
    return a > ALPHA_MAX ? ALPHA_MAX : a;
}

GMicrofacet gmicrofacet_make(int distribution, double alpha_x, double alpha_y)
{
    GMicrofacet m;
    m.distribution = distribution == GMICROFACET_BECKMANN ? GMICROFACET_BECKMANN : GMICROFACET_GGX;
    m.alpha_x = clamp_alpha(alpha_x);
    m.alpha_y = clamp_alpha(alpha_y);
    return m;
}

double gmicrofacet_d(const GMicrofacet *m, GVec3 h)
{
    if (!(h.z > 0.0))
        return 0.0;
    double ax = m->alpha_x, ay = m->alpha_y;
    double sx = h.x / ax, sy = h.y / ay, z2 = h.z * h.z;
    if (m->distribution == GMICROFACET_BECKMANN) {
        double e = (sx * sx + sy * sy) / z2; /* tan^2 theta scaled by the widths */
        return exp(-e) / (M_PI * ax * ay * z2 * z2);
    }
    double q = sx * sx + sy * sy + z2;
    return 1.0 / (M_PI * ax * ay * q * q);
}

/* Lambda of a distribution for t2 = alpha^2 tan^2 theta of the direction (scaled by the widths along its azimuth). */
static double lambda_t2(int distribution, double t2)
{
    if (distribution == GMICROFACET_BECKMANN) {
        if (t2 == 0.0)
            return 0.0;
        double a = 1.0 / sqrt(t2);
        return 0.5 * (-erfc(a) + exp(-a * a) * INV_SQRT_PI / a);
    }
    return t2 / (2.0 * (sqrt(1.0 + t2) + 1.0)); /* (sqrt(1 + t2) - 1) / 2 without cancellation */
}

double gmicrofacet_lambda(const GMicrofacet *m, GVec3 w)
{
    double z2 = w.z * w.z;
    if (!(z2 > 0.0))
        return INFINITY;
    double t2 = (m->alpha_x * m->alpha_x * w.x * w.x + m->alpha_y * m->alpha_y * w.y * w.y) / z2; /* alpha^2 tan^2 */
    return lambda_t2(m->distribution, t2);
}

/* 1 when w sees the facet h from its own side of the surface: w.h and w.z of one sign */
static int sees(GVec3 w, GVec3 h) { return gvec3_dot(w, h) * w.z > 0.0; }

double gmicrofacet_g1(const GMicrofacet *m, GVec3 w, GVec3 h)
{
    if (!sees(w, h))
        return 0.0;
    return 1.0 / (1.0 + gmicrofacet_lambda(m, w));
}

double gmicrofacet_g2(const GMicrofacet *m, GVec3 wi, GVec3 wo, GVec3 h)
{
    if (!sees(wi, h) || !sees(wo, h))
        return 0.0;
    return 1.0 / (1.0 + gmicrofacet_lambda(m, wi) + gmicrofacet_lambda(m, wo));
}

/* GGX's visible normals by spherical caps (Dupuy and Benyoub 2023): in the configuration stretched to alpha 1, a
 * visible normal is wo plus a point drawn uniformly on the spherical cap of the unit sphere beyond the plane
 * z = -wo.z; unstretched and normalised. */
static GVec3 ggx_sample_visible(const GMicrofacet *m, GVec3 wo, double u1, double u2)
{
    GVec3 ws = gvec3_normalize(gvec3(m->alpha_x * wo.x, m->alpha_y * wo.y, wo.z));
    double phi = 2.0 * M_PI * u1;
    double z = (1.0 - u2) * (1.0 + ws.z) - ws.z;
    double s = sqrt(gfmax(0.0, 1.0 - z * z));
    GVec3 hs = gvec3_add(gvec3(s * cos(phi), s * sin(phi), z), ws);
    GVec3 h = gvec3_normalize(gvec3(m->alpha_x * hs.x, m->alpha_y * hs.y, gfmax(hs.z, 0.0)));
    if (!(h.z > 0.0)) /* only when the cap's point is -ws itself: a measure-zero draw */
        h = gvec3(0.0, 0.0, 1.0);
    return h;
}

/* The inverse error function: a closed-form first guess (Winitzki 2008), refined by Newton steps on erf. */
static double erfinv_d(double y)
{
    if (!(y > -1.0))
        return -INFINITY;
    if (!(y < 1.0))
        return INFINITY;
    double l = log((1.0 - y) * (1.0 + y)), a = 0.147, t = 2.0 / (M_PI * a) + 0.5 * l;
    double x = copysign(sqrt(sqrt(t * t - l / a) - t), y);
    for (int i = 0; i < 4; i++) {
        double d = 2.0 * INV_SQRT_PI * exp(-x * x);
        if (!(d > 0.0))
            break;
        x -= (erf(x) - y) / d;
    }
    return x;
}

/* Beckmann's visible slopes at alpha 1 seen from a direction at cot theta, in the frame where the direction lies in
 * the xz plane: x has the density proportional to (cot - x) exp(-x^2) for x < cot, whose cumulative integral is
 * F(x) = cot erfc(-x) / 2 + exp(-x^2) / (2 sqrt(pi)); x solves F(x) = u F(cot) by Newton steps kept inside a
 * shrinking bracket. y is independent of x, Gaussian. */
static double beckmann_visible_slope_x(double cot, double u)
{
    double target = u * (cot * erfc(-cot) * 0.5 + exp(-cot * cot) * 0.5 * INV_SQRT_PI);
    double lo = -12.0, hi = cot, x = gfmin(gfmax(erfinv_d(2.0 * u - 1.0), lo), hi);
    for (int i = 0; i < 100; i++) {
        double f = cot * erfc(-x) * 0.5 + exp(-x * x) * 0.5 * INV_SQRT_PI - target;
        if (f > 0.0)
            hi = x;
        else
            lo = x;
        double d = (cot - x) * exp(-x * x) * INV_SQRT_PI, next = x - f / d;
        if (!(d > 0.0) || !(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (fabs(next - x) < 1e-13 * (1.0 + fabs(x)) || hi - lo < 1e-13)
            return next;
        x = next;
    }
    return x;
}

static GVec3 beckmann_sample_visible(const GMicrofacet *m, GVec3 wo, double u1, double u2)
{
    GVec3 ws = gvec3_normalize(gvec3(m->alpha_x * wo.x, m->alpha_y * wo.y, wo.z));
    double sin_t = sqrt(ws.x * ws.x + ws.y * ws.y), sx, sy = erfinv_d(2.0 * u2 - 1.0);
    if (sin_t < 1e-9) { /* seen from the normal: the slopes' own Gaussian */
        sx = erfinv_d(2.0 * u1 - 1.0);
    } else {
        double x = beckmann_visible_slope_x(ws.z / sin_t, u1);
        double c = ws.x / sin_t, s = ws.y / sin_t; /* rotate from the xz plane to wo's azimuth */
        sx = c * x - s * sy;
        sy = s * x + c * sy;
    }
    if (!isfinite(sx) || !isfinite(sy)) /* u at the end of [0, 1): a slope beyond any double */
        return gvec3(0.0, 0.0, 1.0);
    return gvec3_normalize(gvec3(-m->alpha_x * sx, -m->alpha_y * sy, 1.0));
}

GVec3 gmicrofacet_sample_visible(const GMicrofacet *m, GVec3 wo, double u1, double u2)
{
    if (m->distribution == GMICROFACET_BECKMANN)
        return beckmann_sample_visible(m, wo, u1, u2);
    return ggx_sample_visible(m, wo, u1, u2);
}

double gmicrofacet_pdf_visible(const GMicrofacet *m, GVec3 wo, GVec3 h)
{
    if (!(wo.z > 0.0))
        return 0.0;
    double c = gvec3_dot(wo, h);
    if (!(c > 0.0))
        return 0.0;
    return gmicrofacet_g1(m, wo, h) * c * gmicrofacet_d(m, h) / wo.z;
}

/* D(h) as a fraction num / den, so that a caller dividing by more divides once. */
typedef struct Fraction {
    double num, den;
} Fraction;

/* D(h) of the half vector H = wi + wo left unnormalised (h = H / |H|: D depends on the direction only), from |H|^2
 * (l2), its slopes scaled by the widths, slope2 = (Hx / ax)^2 + (Hy / ay)^2, and Hz^2 (hz2 > 0): with q = slope2 + hz2,
 * GGX's 1 / (pi ax ay (|H|^-2 q)^2) is |H|^4 / (pi ax ay q^2), no square root to normalise H. */
static inline Fraction d_of_half(const GMicrofacet *m, double l2, double slope2, double hz2)
{
    double axy = M_PI * m->alpha_x * m->alpha_y;
    if (m->distribution == GMICROFACET_BECKMANN)
        return (Fraction){exp(-slope2 / hz2) * l2 * l2, axy * hz2 * hz2};
    double q = slope2 + hz2;
    return (Fraction){l2 * l2, axy * q * q};
}

/* The single-scattering rough mirror for a pair of directions above the surface, from their cosines ci, co, the
 * widths-scaled squares of their tangential parts (ti = ax^2 wi.x^2 + ay^2 wi.y^2, to likewise) and D(h): GGX in
 * Heitz's form with Lambda = (S / z - 1) / 2, S = sqrt(z^2 + t): G2 / (4 co) = ci / (2 (Si co + So ci)), one
 * division in all; Beckmann through its Lambda. The pdf of the reflected direction likewise: G1(wo) D / (4 co),
 * with GGX's G1(wo) = 2 co / (co + So). */
static inline double reflect_cos_of(const GMicrofacet *m, double ci, double co, double ti, double to, Fraction d)
{
    if (m->distribution == GMICROFACET_BECKMANN)
        return d.num / (d.den * (1.0 + lambda_t2(m->distribution, ti / (ci * ci)) +
                                 lambda_t2(m->distribution, to / (co * co))) * 4.0 * co);
    return d.num * ci / (d.den * 2.0 * (sqrt(ci * ci + ti) * co + sqrt(co * co + to) * ci));
}

static inline double pdf_reflect_of(const GMicrofacet *m, double co, double to, Fraction d)
{
    if (m->distribution == GMICROFACET_BECKMANN)
        return d.num / (d.den * (1.0 + lambda_t2(m->distribution, to / (co * co))) * 4.0 * co);
    return d.num / (d.den * 2.0 * (co + sqrt(co * co + to)));
}

/* D and the tangential terms of a pair in the local frame. */
static inline Fraction local_d(const GMicrofacet *m, GVec3 wi, GVec3 wo, double *ti, double *to)
{
    GVec3 h = gvec3_add(wo, wi);
    double sx = h.x / m->alpha_x, sy = h.y / m->alpha_y;
    double ix = m->alpha_x * wi.x, iy = m->alpha_y * wi.y, ox = m->alpha_x * wo.x, oy = m->alpha_y * wo.y;
    *ti = ix * ix + iy * iy;
    *to = ox * ox + oy * oy;
    return d_of_half(m, gvec3_dot(h, h), sx * sx + sy * sy, h.z * h.z);
}

double gmicrofacet_pdf_reflect(const GMicrofacet *m, GVec3 wo, GVec3 wi)
{
    if (!(wo.z > 0.0) || !(wi.z > 0.0))
        return 0.0;
    double ti, to;
    Fraction d = local_d(m, wi, wo, &ti, &to);
    return pdf_reflect_of(m, wo.z, to, d);
}

double gmicrofacet_reflect_cos(const GMicrofacet *m, GVec3 wi, GVec3 wo)
{
    if (!(wo.z > 0.0) || !(wi.z > 0.0))
        return 0.0;
    double ti, to;
    Fraction d = local_d(m, wi, wo, &ti, &to);
    return reflect_cos_of(m, wi.z, wo.z, ti, to, d);
}

double gmicrofacet_reflect_cos_pdf(const GMicrofacet *m, GVec3 wi, GVec3 wo, double *pdf)
{
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) {
        *pdf = 0.0;
        return 0.0;
    }
    double ti, to;
    Fraction d = local_d(m, wi, wo, &ti, &to);
    *pdf = pdf_reflect_of(m, wo.z, to, d);
    return reflect_cos_of(m, wi.z, wo.z, ti, to, d);
}

/* D(h) and the tangential terms of an isotropic pair: |H|^2 = 2 + 2 cos_io, Hz = cos_i + cos_o, the slopes
 * (|H|^2 - Hz^2, not below 0) over alpha^2, and alpha^2 (1 - cos^2) for each direction. GGX's D with both sides
 * times alpha^4: |H|^4 alpha^2 / (pi Q^2), Q = |H|^2 - Hz^2 + alpha^2 Hz^2, no division. */
static inline Fraction pair_d(const GMicrofacet *m, GMicrofacetPair p, double *ti, double *to)
{
    double a2 = m->alpha_x * m->alpha_x, l2 = 2.0 + 2.0 * p.cos_io, hz = p.cos_i + p.cos_o, hz2 = hz * hz;
    double tangential = gfmax(0.0, l2 - hz2);
    *ti = a2 * gfmax(0.0, 1.0 - p.cos_i * p.cos_i);
    *to = a2 * gfmax(0.0, 1.0 - p.cos_o * p.cos_o);
    if (m->distribution == GMICROFACET_BECKMANN)
        return d_of_half(m, l2, tangential / a2, hz2);
    double q = tangential + a2 * hz2;
    return (Fraction){l2 * l2 * a2, M_PI * q * q};
}

double gmicrofacet_reflect_cos_pair(const GMicrofacet *m, GMicrofacetPair p)
{
    if (m->distribution != GMICROFACET_BECKMANN)
        return gmicrofacet_ggx_reflect_cos_pair(m->alpha_x * m->alpha_x, p);
    if (!(p.cos_o > 0.0) || !(p.cos_i > 0.0))
        return 0.0;
    double ti, to;
    Fraction d = pair_d(m, p, &ti, &to);
    return reflect_cos_of(m, p.cos_i, p.cos_o, ti, to, d);
}

double gmicrofacet_pdf_reflect_pair(const GMicrofacet *m, GMicrofacetPair p)
{
    if (!(p.cos_o > 0.0) || !(p.cos_i > 0.0))
        return 0.0;
    double ti, to;
    Fraction d = pair_d(m, p, &ti, &to);
    return pdf_reflect_of(m, p.cos_o, to, d);
}
