/* microfacet.h - microfacet distributions for rough surfaces: the distribution of normals D, the masking function
 * Lambda, the masking G1 and the height-correlated masking-shadowing G2 (Heitz 2014, "Understanding the
 * masking-shadowing function in microfacet-based BRDFs"), and sampling of the visible normals with its density.
 *
 * Every direction here is in the local shading frame: the macro surface's normal is +z, the first tangent +x (along
 * which alpha_x applies) and the second +y (GFrame, below, takes a vector to and from that frame). Directions are unit
 * vectors; the viewing direction wo points away from the surface and lies in the upper hemisphere (wo.z > 0): a
 * caller looking from below flips the frame first. A microfacet normal h is a unit vector with h.z > 0.
 *
 * Roughness. A file's `roughness` r in [0, 1] is the distribution's width itself: alpha = r
 * (gmicrofacet_alpha_from_roughness), so r = 1 is alpha = 1 (a very rough surface) and r = 0 a smooth one, which a
 * material renders as its ideal (delta) lobe; below GMICROFACET_ALPHA_MIN a distribution is too narrow to evaluate
 * in double precision and the material takes its smooth form. Every material of the library maps it the same way. */
#ifndef GENERIC_KIT_MICROFACET_H
#define GENERIC_KIT_MICROFACET_H

#include "../export.h"
#include "../material.h"
#include "../vec.h"

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The narrowest width a GMicrofacet evaluates: a roughness below it is smooth (an ideal lobe). */
#define GMICROFACET_ALPHA_MIN 1e-3

/** The shape of the distribution of microfacet normals. */
typedef enum GMicrofacetDistribution {
    GMICROFACET_GGX = 0,     /**< GGX / Trowbridge-Reitz: long tails; visible normals sampled exactly by spherical caps
                                  (Dupuy and Benyoub 2023) */
    GMICROFACET_BECKMANN = 1 /**< Beckmann: Gaussian slopes; visible normals sampled exactly by inverting the slope
                                  distribution seen from wo (Heitz and d'Eon 2014), numerically */
} GMicrofacetDistribution;

/** A microfacet distribution: its shape and its widths along the frame's x and y axes (isotropic when equal). A
 * plain value; make it with gmicrofacet_make, which keeps the widths in [GMICROFACET_ALPHA_MIN, 1e3]. */
typedef struct GMicrofacet {
    int distribution; /**< a GMicrofacetDistribution */
    double alpha_x;   /**< width along the frame's x axis (the first tangent) */
    double alpha_y;   /**< width along the frame's y axis */
} GMicrofacet;

/** alpha for a file's roughness r: r itself (see the top of this file), for r in [0, 1]; NAN elsewhere. */
GENERIC_API double gmicrofacet_alpha_from_roughness(double roughness);

/** A distribution of the given shape and widths, each clamped into [GMICROFACET_ALPHA_MIN, 1e3] (a NaN width becomes
 * GMICROFACET_ALPHA_MIN); an unknown shape is GGX. */
GENERIC_API GMicrofacet gmicrofacet_make(int distribution, double alpha_x, double alpha_y);

/** The distribution of normals D(h), per unit solid angle of h, normalised so that the integral of D(h) h.z over the
 * hemisphere is 1; 0 for h.z <= 0. */
GENERIC_API double gmicrofacet_d(const GMicrofacet *m, GVec3 h);

/** Smith's Lambda(w) of the distribution: G1 = 1 / (1 + Lambda); 0 at normal incidence, INFINITY for w.z <= 0. Only
 * |w.z| and the azimuth of w matter: it is the same for w and its mirror image below the surface. */
GENERIC_API double gmicrofacet_lambda(const GMicrofacet *m, GVec3 w);

/** The masking function G1(w, h) = 1 / (1 + Lambda(w)) where w sees the facet (w.h and w.z of one sign), else 0;
 * in [0, 1]. */
GENERIC_API double gmicrofacet_g1(const GMicrofacet *m, GVec3 w, GVec3 h);

/** The height-correlated masking-shadowing G2(wi, wo, h) = 1 / (1 + Lambda(wi) + Lambda(wo)) where each direction
 * sees the facet (w.h and w.z of one sign), else 0; in [0, min(G1(wi), G1(wo))]. wi may lie below the surface (a
 * transmitted direction): its Lambda is that of its mirror image. */
GENERIC_API double gmicrofacet_g2(const GMicrofacet *m, GVec3 wi, GVec3 wo, GVec3 h);

/** A microfacet normal drawn from the distribution of normals visible from wo (wo.z > 0), from u1, u2 in [0, 1):
 * density gmicrofacet_pdf_visible. Always in the upper hemisphere and seen by wo (wo.h >= 0). */
GENERIC_API GVec3 gmicrofacet_sample_visible(const GMicrofacet *m, GVec3 wo, double u1, double u2);

/** The density per unit solid angle of h drawn by gmicrofacet_sample_visible for wo:
 * D_wo(h) = G1(wo, h) max(0, wo.h) D(h) / wo.z; it integrates to 1 over h. 0 for wo.z <= 0. */
GENERIC_API double gmicrofacet_pdf_visible(const GMicrofacet *m, GVec3 wo, GVec3 h);

/** The density per unit solid angle of the reflected direction wi = reflect(wo, h) when h is drawn by
 * gmicrofacet_sample_visible: D_wo(h) / (4 wo.h), h the half vector of wo and wi; 0 when wi and wo are not both above
 * the surface. */
GENERIC_API double gmicrofacet_pdf_reflect(const GMicrofacet *m, GVec3 wo, GVec3 wi);

/** The single-scattering rough-mirror BRDF times the incident cosine, without Fresnel:
 * D(h) G2(wi, wo, h) / (4 wo.z) for wi and wo above the surface, h their half vector; 0 otherwise. A conductor's
 * reflection is this times its Fresnel reflectance F(wi.h). */
GENERIC_API double gmicrofacet_reflect_cos(const GMicrofacet *m, GVec3 wi, GVec3 wo);

/** gmicrofacet_reflect_cos(m, wi, wo), with *pdf = gmicrofacet_pdf_reflect(m, wo, wi): the two share D(h), so a
 * sampler weighing the direction it drew computes it once. Both 0 unless wi and wo are above the surface. */
GENERIC_API double gmicrofacet_reflect_cos_pdf(const GMicrofacet *m, GVec3 wi, GVec3 wo, double *pdf);

/** A pair of unit directions above the surface as an isotropic distribution sees them, without a frame: their
 * cosines with the shading normal (wi.z and wo.z of the local frame) and with each other (wi.wo). */
typedef struct GMicrofacetPair {
    double cos_i;  /**< wi.n */
    double cos_o;  /**< wo.n */
    double cos_io; /**< wi.wo */
} GMicrofacetPair;

/** gmicrofacet_reflect_cos for an isotropic m (alpha_x is read) from the pair's cosines alone: the same value up to
 * rounding, without a frame or a normalised half vector; 0 unless both cosines are > 0. */
GENERIC_API double gmicrofacet_reflect_cos_pair(const GMicrofacet *m, GMicrofacetPair p);

/** gmicrofacet_pdf_reflect (wi = the pair's wi, drawn for its wo) for an isotropic m from the pair's cosines alone;
 * 0 unless both cosines are > 0. */
GENERIC_API double gmicrofacet_pdf_reflect_pair(const GMicrofacet *m, GMicrofacetPair p);

/** gmicrofacet_reflect_cos_pair of an isotropic GGX distribution whose width squared is alpha2, inline, for a caller
 * that evaluates many pairs of one surface (the exported function computes GGX with it: the same value bit for bit).
 * Heitz's form: D of the unnormalised half vector and G2 / (4 cos_o) from the two directions' sqrt(cos^2 + alpha^2
 * sin^2), one division in all. 0 unless both cosines are > 0. */
static inline double gmicrofacet_ggx_reflect_cos_pair(double alpha2, GMicrofacetPair p)
{
    if (!(p.cos_o > 0.0) || !(p.cos_i > 0.0))
        return 0.0;
    double ci = p.cos_i, co = p.cos_o, l2 = 2.0 + 2.0 * p.cos_io, hz = ci + co, hz2 = hz * hz;
    double tangential = gfmax(0.0, l2 - hz2); /* |H|^2 - Hz^2 of the half vector H = wi + wo */
    double ti = alpha2 * gfmax(0.0, 1.0 - ci * ci), to = alpha2 * gfmax(0.0, 1.0 - co * co);
    double q = tangential + alpha2 * hz2; /* D = |H|^4 alpha^2 / (pi q^2) */
    double num = l2 * l2 * alpha2, den = M_PI * q * q;
    return num * ci / (den * 2.0 * (sqrt(ci * ci + ti) * co + sqrt(co * co + to) * ci));
}

/** wi.h = wo.h for the pair's half vector h: sqrt((1 + wi.wo) / 2), the cosine a Fresnel term of the facet reads. */
static inline double gmicrofacet_pair_cos_h(GMicrofacetPair p)
{
    double x = 0.5 * (1.0 + p.cos_io);
    return x > 0.0 ? sqrt(x) : 0.0;
}

/* ---- energy of single scattering (multiple-scattering compensation, Kulla and Conty 2017) ---- */

/** Nodes of an albedo table: E(mu) at mu = i / (GMICROFACET_ALBEDO_N - 1). */
#define GMICROFACET_ALBEDO_N 32

/** The directional albedo of the single-scattering rough mirror with Fresnel 1 (gmicrofacet_reflect_cos integrated
 * over the incident hemisphere), E(mu_o) at the GMICROFACET_ALBEDO_N nodes mu_o = i / (N - 1), into e, for m's shape
 * and width (an anisotropic m is read at alpha = sqrt(alpha_x alpha_y), clamped to [0, 1]); *e_avg (may be NULL) gets
 * the cosine-weighted mean E_avg = 2 * integral of E(mu) mu dmu of the table's linear interpolation. From tables
 * precomputed at N x N nodes of (mu, alpha) by scripts/gen_microfacet_albedo.c (quadrature over the half vector,
 * exact to about 1e-5 at the nodes), linear in alpha between them: no work but the interpolation. */
GENERIC_API void gmicrofacet_albedo_table(const GMicrofacet *m, float e[GMICROFACET_ALBEDO_N], double *e_avg);

/** E(mu) from a table of gmicrofacet_albedo_table, linear between the nodes (mu clamped to [0, 1]). */
GENERIC_API double gmicrofacet_albedo_at(const float e[GMICROFACET_ALBEDO_N], double mu);

/** gmicrofacet_albedo_at inline, for a caller that reads a table per evaluation (the exported function is this: the
 * same value bit for bit). */
static inline double gmicrofacet_albedo_lerp(const float e[GMICROFACET_ALBEDO_N], double mu)
{
    double x = gfmin(gfmax(mu, 0.0), 1.0) * (GMICROFACET_ALBEDO_N - 1);
    int i = (int)x;
    if (i > GMICROFACET_ALBEDO_N - 2)
        i = GMICROFACET_ALBEDO_N - 2;
    double t = x - i;
    return (1.0 - t) * e[i] + t * e[i + 1];
}

/* ---- the local shading frame ---- */

/** An orthonormal frame: t and b the tangents (the microfacet frame's x and y), n the normal (its z). */
typedef struct GFrame {
    GVec3 t, b, n;
} GFrame;

/** The frame about the unit normal n with goptics_frame's tangents (for isotropic distributions). */
static inline GFrame gframe_from_normal(GVec3 n)
{
    GFrame f;
    f.n = n;
    goptics_frame(n, &f.t, &f.b);
    return f;
}

/** The frame about the unit normal n whose first tangent is tangent made perpendicular to n (for anisotropic
 * distributions: alpha_x along it); goptics_frame's when tangent is (nearly) parallel to n or zero. */
static inline GFrame gframe_from_normal_tangent(GVec3 n, GVec3 tangent)
{
    GVec3 t = gvec3_sub(tangent, gvec3_scale(n, gvec3_dot(tangent, n)));
    double l = gvec3_length(t);
    if (!(l > 1e-9 * gvec3_length(tangent)) || !(l > 0.0))
        return gframe_from_normal(n);
    GFrame f;
    f.n = n;
    f.t = gvec3_scale(t, 1.0 / l);
    f.b = gvec3_cross(n, f.t);
    return f;
}

/** v in the frame's coordinates (x along t, y along b, z along n). */
static inline GVec3 gframe_to_local(const GFrame *f, GVec3 v)
{
    return gvec3(gvec3_dot(v, f->t), gvec3_dot(v, f->b), gvec3_dot(v, f->n));
}

/** The vector whose frame coordinates are v. */
static inline GVec3 gframe_to_world(const GFrame *f, GVec3 v)
{
    return gvec3_add(gvec3_add(gvec3_scale(f->t, v.x), gvec3_scale(f->b, v.y)), gvec3_scale(f->n, v.z));
}

#ifdef __cplusplus
}
#endif
#endif
