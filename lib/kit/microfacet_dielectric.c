/* microfacet_dielectric.c - the rough dielectric interface of Walter et al. 2007 on a microfacet distribution, its
 * sampling and densities, and the single-scattering albedo table of its energy compensation
 * (generic/kit/microfacet_dielectric.h). */
#include "generic/kit/microfacet_dielectric.h"

#include <math.h>

double gmicrofacet_dielectric_reflect(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta)
{
    if (!(wi.z > 0.0 && wo.z > 0.0))
        return 0.0;
    GVec3 h = gvec3_normalize(gvec3_add(wi, wo));
    return goptics_fresnel(gvec3_dot(wo, h), eta) * gmicrofacet_reflect_cos(m, wi, wo);
}

int gmicrofacet_dielectric_half_refract(GVec3 wi, GVec3 wo, double eta, GVec3 *h)
{
    if (!(wo.z > 0.0 && wi.z < 0.0))
        return 0;
    GVec3 s = gvec3_add(wi, gvec3_scale(wo, eta));
    double l = gvec3_length(s);
    if (!(l > 1e-12))
        return 0;
    GVec3 hh = gvec3_scale(s, (s.z > 0.0 ? 1.0 : -1.0) / l);
    if (!(gvec3_dot(wo, hh) > 0.0 && gvec3_dot(wi, hh) < 0.0))
        return 0;
    *h = hh;
    return 1;
}

/* (wi.h + eta wo.h)^2: the Jacobian's denominator of the refracted pair's half vector */
static double refract_denominator(GVec3 wi, GVec3 wo, GVec3 h, double eta)
{
    double d = gvec3_dot(wi, h) + eta * gvec3_dot(wo, h);
    return d * d;
}

double gmicrofacet_dielectric_refract(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta)
{
    GVec3 h;
    if (!gmicrofacet_dielectric_half_refract(wi, wo, eta, &h))
        return 0.0;
    double oh = gvec3_dot(wo, h), ih = gvec3_dot(wi, h), den = refract_denominator(wi, wo, h, eta);
    if (!(den > 0.0))
        return 0.0;
    double t = 1.0 - goptics_fresnel(oh, eta);
    return t * gmicrofacet_d(m, h) * gmicrofacet_g2(m, wi, wo, h) * fabs(ih) * oh / (wo.z * den);
}

double gmicrofacet_dielectric_pdf(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta)
{
    if (!(wo.z > 0.0))
        return 0.0;
    if (wi.z > 0.0) {
        GVec3 h = gvec3_normalize(gvec3_add(wi, wo));
        double oh = gvec3_dot(wo, h);
        if (!(oh > 0.0))
            return 0.0;
        return goptics_fresnel(oh, eta) * gmicrofacet_pdf_visible(m, wo, h) / (4.0 * oh);
    }
    GVec3 h;
    if (!gmicrofacet_dielectric_half_refract(wi, wo, eta, &h))
        return 0.0;
    double den = refract_denominator(wi, wo, h, eta);
    if (!(den > 0.0))
        return 0.0;
    double t = 1.0 - goptics_fresnel(gvec3_dot(wo, h), eta);
    return t * gmicrofacet_pdf_visible(m, wo, h) * fabs(gvec3_dot(wi, h)) / den;
}

int gmicrofacet_dielectric_sample(const GMicrofacet *m, GVec3 wo, double eta, double u1, double u2, GVec3 *wi)
{
    if (!(wo.z > 0.0))
        return 0;
    GVec3 h = gmicrofacet_sample_visible(m, wo, u1, u2);
    double oh = gvec3_dot(wo, h), fine = u1 * 16777216.0;
    double choice = fine - floor(fine);
    GVec3 t;
    int refracts = goptics_refract(gvec3_neg(wo), h, eta, &t);
    double f = refracts ? goptics_fresnel(oh, eta) : 1.0;
    if (choice < f || !refracts) {
        *wi = gvec3_sub(gvec3_scale(h, 2.0 * oh), wo);
        return wi->z > 0.0 ? 1 : 0;
    }
    *wi = t;
    return t.z < 0.0 ? 2 : 0;
}

/* R and T at (cos_o, eta) by quadrature of the visible normals: the mean of G2 / G1 over the reflected (weight F) and
 * the refracted (weight 1 - F) direction of each normal, those on their side of the surface. */
static void albedo_at(const GMicrofacet *m, double cos_o, double eta, double *rs, double *ts)
{
    enum { N = 24 };
    GVec3 wo = gvec3(sqrt(fmax(0.0, 1.0 - cos_o * cos_o)), 0.0, cos_o);
    double r = 0.0, t = 0.0, g1 = 1.0 / (1.0 + gmicrofacet_lambda(m, wo));
    for (int a = 0; a < N; a++)
        for (int b = 0; b < N; b++) {
            GVec3 h = gmicrofacet_sample_visible(m, wo, (a + 0.5) / N, (b + 0.5) / N), wt;
            double oh = gvec3_dot(wo, h);
            int refracts = goptics_refract(gvec3_neg(wo), h, eta, &wt);
            double f = refracts ? goptics_fresnel(oh, eta) : 1.0;
            GVec3 wr = gvec3_sub(gvec3_scale(h, 2.0 * oh), wo);
            if (wr.z > 0.0)
                r += f * gmicrofacet_g2(m, wr, wo, h) / g1;
            if (refracts && wt.z < 0.0)
                t += (1.0 - f) * gmicrofacet_g2(m, wt, wo, h) / g1;
        }
    *rs = r / (N * N);
    *ts = t / (N * N);
}

void gmicrofacet_dielectric_albedo_init(GMicrofacetDielectricAlbedo *a, const GMicrofacet *m, double eta_max)
{
    double w = sqrt(m->alpha_x * m->alpha_y);
    GMicrofacet iso = gmicrofacet_make(m->distribution, w, w);
    a->ln_eta_max = log(eta_max > 1.01 ? eta_max : 1.01);
    for (int j = 0; j < GMICROFACET_DIELECTRIC_ALBEDO_ETA; j++) {
        double eta = exp(a->ln_eta_max * (2.0 * j / (GMICROFACET_DIELECTRIC_ALBEDO_ETA - 1) - 1.0));
        for (int i = 0; i < GMICROFACET_DIELECTRIC_ALBEDO_MU; i++) {
            double r, t;
            albedo_at(&iso, (i + 0.5) / GMICROFACET_DIELECTRIC_ALBEDO_MU, eta, &r, &t);
            a->r[j][i] = (float)r;
            a->t[j][i] = (float)t;
        }
    }
}

/* Bilinear in the table's cells. */
static double bilinear(const float v[GMICROFACET_DIELECTRIC_ALBEDO_ETA][GMICROFACET_DIELECTRIC_ALBEDO_MU], int i,
                       int j, double fx, double fy)
{
    double lo = v[j][i] * (1.0 - fx) + v[j][i + 1] * fx;
    double hi = v[j + 1][i] * (1.0 - fx) + v[j + 1][i + 1] * fx;
    return lo * (1.0 - fy) + hi * fy;
}

void gmicrofacet_dielectric_albedo(const GMicrofacetDielectricAlbedo *a, double cos_o, double eta, double *r, double *t)
{
    *r = 0.0;
    *t = 1.0;
    double x = cos_o * GMICROFACET_DIELECTRIC_ALBEDO_MU - 0.5;
    double y = (log(eta) / a->ln_eta_max + 1.0) * 0.5 * (GMICROFACET_DIELECTRIC_ALBEDO_ETA - 1);
    if (fabs(eta - 1.0) <= 1e-5 || x != x || y != y) /* index-matched; NaN */
        return;
    x = x < 0.0 ? 0.0 : x > GMICROFACET_DIELECTRIC_ALBEDO_MU - 1 ? GMICROFACET_DIELECTRIC_ALBEDO_MU - 1 : x;
    y = y < 0.0 ? 0.0 : y > GMICROFACET_DIELECTRIC_ALBEDO_ETA - 1 ? GMICROFACET_DIELECTRIC_ALBEDO_ETA - 1 : y;
    int i = x >= GMICROFACET_DIELECTRIC_ALBEDO_MU - 1 ? GMICROFACET_DIELECTRIC_ALBEDO_MU - 2 : (int)x;
    int j = y >= GMICROFACET_DIELECTRIC_ALBEDO_ETA - 1 ? GMICROFACET_DIELECTRIC_ALBEDO_ETA - 2 : (int)y;
    *r = bilinear(a->r, i, j, x - i, y - j);
    *t = bilinear(a->t, i, j, x - i, y - j);
}
