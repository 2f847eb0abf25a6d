/* microfacet_dielectric.h - a rough dielectric interface (Walter, Marschner, Li, Torrance 2007, "Microfacet models
 * for refraction through rough surfaces") on a microfacet distribution (microfacet.h): reflection and refraction with
 * the generalised half vector, sampling of the visible normals with a Fresnel choice between them, the densities, and
 * a table of the single-scattering albedo for the compensation of multiple scattering.
 *
 * Directions are in the local shading frame (microfacet.h): wo, towards the viewer, lies above the surface
 * (wo.z > 0), where the medium has index n_o; wi, towards the light, lies above for a reflection and below (wi.z < 0,
 * index n_i) for a refraction. eta is the relative index n_o / n_i (n(from) / n(to) of material.h's rel_index).
 *
 * Radiance is not rescaled by eta^2 when it crosses, as the smooth dielectric does (materials.h): the refraction is
 * Walter's BTDF times (n_i / n_o)^2, the form whose lobe carries 1 - F as the smooth interface's ray does, so a rough
 * dielectric tends to the smooth one as its roughness falls. Values are f * |wi.z| (what reflection() and
 * refraction() multiply the light by), single scattering only. */
#ifndef GENERIC_KIT_MICROFACET_DIELECTRIC_H
#define GENERIC_KIT_MICROFACET_DIELECTRIC_H

#include "../export.h"
#include "microfacet.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Rough reflection times |wi.z|: F(wo.h, eta) D(h) G2(wi, wo, h) / (4 wo.z), h the half vector of wi and wo; 0 unless
 * both lie above the surface. */
GENERIC_API double gmicrofacet_dielectric_reflect(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta);

/** The microfacet normal of a refracted pair: h along -(wi + eta wo), turned to the upper hemisphere; 0 (and h
 * untouched) when wo.z <= 0, wi.z >= 0, the pair is degenerate (wi = -eta wo) or a direction does not lie on its side
 * of the facet (wo.h > 0 and wi.h < 0 are required). */
GENERIC_API int gmicrofacet_dielectric_half_refract(GVec3 wi, GVec3 wo, double eta, GVec3 *h);

/** Rough refraction times |wi.z|: (1 - F(wo.h, eta)) D(h) G2(wi, wo, h) |wi.h| wo.h / (wo.z (wi.h + eta wo.h)^2),
 * h from gmicrofacet_dielectric_half_refract; 0 for a pair that has none. */
GENERIC_API double gmicrofacet_dielectric_refract(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta);

/** The density per unit solid angle of wi as gmicrofacet_dielectric_sample draws it for wo: for wi above the surface
 * F D_wo(h) / (4 wo.h), below it (1 - F) D_wo(h) |wi.h| / (wi.h + eta wo.h)^2 (D_wo: gmicrofacet_pdf_visible); 0 for
 * wo.z <= 0. */
GENERIC_API double gmicrofacet_dielectric_pdf(const GMicrofacet *m, GVec3 wi, GVec3 wo, double eta);

/** Draws wi for wo (wo.z > 0) from u1, u2 in [0, 1): a visible normal h from (u1, u2), then reflection about h with
 * probability F(wo.h, eta) (1 past total internal reflection) or refraction through h, the choice made with the
 * fraction of u1 * 2^24 (fine digits of u1 that move h by less than 2^-24). Returns 1 (reflected) or 2 (refracted)
 * with *wi, or 0 when the direction falls on the wrong side of the surface (nothing drawn: the density counts only
 * directions on their side). For wi: the value over the density is G2(wi, wo, h) / G1(wo, h). */
GENERIC_API int gmicrofacet_dielectric_sample(const GMicrofacet *m, GVec3 wo, double eta, double u1, double u2,
                                              GVec3 *wi);

/** Sizes of GMicrofacetDielectricAlbedo: cos(theta_o) and ln eta. */
#define GMICROFACET_DIELECTRIC_ALBEDO_MU 32
#define GMICROFACET_DIELECTRIC_ALBEDO_ETA 41

/** The single-scattering albedos of a lossless rough dielectric, R(cos theta_o, eta) of its reflection and
 * T(cos theta_o, eta) of its refraction (values over the sphere of wi), over cos theta_o in (0, 1] (cell midpoints)
 * and ln eta evenly over [-ln_eta_max, ln_eta_max]. R + T < 1 is the light the microfacet model loses to the
 * multiple scattering it leaves out; a compensation gives it back. */
typedef struct GMicrofacetDielectricAlbedo {
    double ln_eta_max;
    float r[GMICROFACET_DIELECTRIC_ALBEDO_ETA][GMICROFACET_DIELECTRIC_ALBEDO_MU];
    float t[GMICROFACET_DIELECTRIC_ALBEDO_ETA][GMICROFACET_DIELECTRIC_ALBEDO_MU];
} GMicrofacetDielectricAlbedo;

/** Fills a for the distribution m (anisotropic widths by their isotropic mean sqrt(alpha_x alpha_y)) up to
 * |ln eta| = ln(eta_max) (eta_max >= 1.01), each entry by a 24 x 24 stratified quadrature of the visible normals with
 * the Fresnel choice summed exactly. Deterministic; about 1.5 million evaluations. */
GENERIC_API void gmicrofacet_dielectric_albedo_init(GMicrofacetDielectricAlbedo *a, const GMicrofacet *m,
                                                    double eta_max);

/** R and T at (cos_o, eta) from a, interpolated bilinearly in cos_o and ln eta and clamped at the table's edges;
 * R = 0 and T = 1 for eta = 1 within 1e-5 (an index-matched interface is no interface). */
GENERIC_API void gmicrofacet_dielectric_albedo(const GMicrofacetDielectricAlbedo *a, double cos_o, double eta,
                                               double *r, double *t);

#ifdef __cplusplus
}
#endif
#endif
