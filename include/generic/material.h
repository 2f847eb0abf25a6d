/* material.h - the generic material interface (the paper's Fig. 3 in C).
 *
 * Directions: `in` and `out` point away from the surface (towards the light, towards the viewer);
 * `view` in reflection_dir/refraction_dir is the incident ray's direction (towards the surface) and the
 * returned direction points away from it. Normals come from the surface point and face the incident ray.
 *
 * reflection(in, illum, out) is the light leaving towards `out` when light `illum` arrives from `in`:
 *   - for directions that are not the material's ideal reflection: f_r(in, out) * cos(theta_in) * illum,
 *     so a point light of intensity I at distance d passes illum = I / d^2;
 *   - when out is the ideal mirror direction of in (checked by the material, as the paper asks), the
 *     perfect specular part: the specular reflectance times illum (the radiance traced along that ray).
 * refraction(in, illum, rel_index, out) is the same for light arriving through the surface from `in`.
 *
 * Missing methods (NULL slots) take these defaults: reflection, refraction, emission, diffuse: black;
 * refraction_index: 1; reflection_dir, refraction_dir: not valid; ambient: diffuse * illum;
 * absorption: illum unchanged; normal: the geometric normal; opaque: yes. */
#ifndef GENERIC_MATERIAL_H
#define GENERIC_MATERIAL_H

#include "export.h"
#include "vec.h"
#include "color.h"
#include "surfpoint.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the material vtable and header (2: the header has depth and cost). */
#define GMATERIAL_ABI_VERSION 2

typedef struct GMaterialClass GMaterialClass;

/** A material instance begins with this header; implementations embed it as their first member. */
struct GMaterial {
    const GMaterialClass *cls;
    const GColorModel *model; /**< the model its colours are in */
    int refcount;             /**< owners; see gmaterial_ref/gmaterial_unref */
    int depth;                /**< 1 (gmaterial_init); a texture node: 1 + its deepest child's (node_kit.h) */
    int cost;                 /**< most material calls one call can make, itself included: 1 (gmaterial_init);
                                   a texture node: see GTEXNODE_MAX_COST (node_kit.h) */
};

/** The material vtable. Colour methods return a status; direction methods return 1 (valid), 0 (not valid)
 * or a negative status. */
struct GMaterialClass {
    int abi_version;         /**< GMATERIAL_ABI_VERSION */
    const char *name;        /**< type keyword */
    const char *description; /**< one line for listings */
    /** Frees the instance (called when the last reference goes). */
    void (*destroy)(GMaterial *self);
    int (*reflection)(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                      GColor *result);
    int (*refraction)(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                      const GColor *rel_index, GVec3 out, GColor *result);
    /** Wavelength-dependent refraction index (sp may be NULL for a homogeneous material). */
    int (*refraction_index)(const GMaterial *self, GSurfPoint *sp, GColor *result);
    int (*reflection_dir)(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir);
    int (*refraction_dir)(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                          GVec3 *dir);
    int (*emission)(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result);
    int (*ambient)(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result);
    /** What is left of illum after `length` through the material as a medium (sp may be NULL). */
    int (*absorption)(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result);
    int (*normal)(const GMaterial *self, GSurfPoint *sp, GVec3 *n);
    int (*diffuse)(const GMaterial *self, GSurfPoint *sp, GColor *result);
    /** 1 when opaque, 0 when light passes through. */
    int (*opaque)(const GMaterial *self, GSurfPoint *sp);
};

/** Fills the header of a new instance (refcount 1); G_ERR_VERSION when the class is of another version. */
GENERIC_API GENERIC_NODISCARD int gmaterial_init(GMaterial *m, const GMaterialClass *cls, const GColorModel *model, GError *err);
/** Adds an owner; returns m. */
GENERIC_API GMaterial *gmaterial_ref(GMaterial *m);
/** Drops an owner and destroys the material with the last; NULL is a no-op. */
GENERIC_API void gmaterial_unref(GMaterial *m);
/** The material's type keyword. */
GENERIC_API const char *gmaterial_name(const GMaterial *m);

/** Light reflected towards out (see the top of this file). */
GENERIC_API GENERIC_NODISCARD int gmaterial_reflection(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result);
/** Light refracted towards out. */
GENERIC_API GENERIC_NODISCARD int gmaterial_refraction(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         const GColor *rel_index, GVec3 out, GColor *result);
/** Refraction index (vacuum = 1 for m == NULL). */
GENERIC_API GENERIC_NODISCARD int gmaterial_refraction_index(const GMaterial *m, GSurfPoint *sp, GColor *result);
/** Ideal reflection direction for the incident direction view; 1 when valid. */
GENERIC_API GENERIC_NODISCARD int gmaterial_reflection_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, GVec3 *dir);
/** Ideal refraction direction; 0 for total internal reflection or opaque materials. */
GENERIC_API GENERIC_NODISCARD int gmaterial_refraction_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                             GVec3 *dir);
/** Emitted light towards out. */
GENERIC_API GENERIC_NODISCARD int gmaterial_emission(const GMaterial *m, GSurfPoint *sp, GVec3 out, GColor *result);
/** Reflected ambient light. */
GENERIC_API GENERIC_NODISCARD int gmaterial_ambient(const GMaterial *m, GSurfPoint *sp, const GColor *illum, GColor *result);
/** Light left after `length` in the material as a medium (m == NULL: vacuum, nothing absorbed). */
GENERIC_API GENERIC_NODISCARD int gmaterial_absorption(const GMaterial *m, GSurfPoint *sp, const GColor *illum, double length, GColor *result);
/** Shading normal (uncached; renderers call gsurfpoint_normal, which caches this). */
GENERIC_API GENERIC_NODISCARD int gmaterial_normal(const GMaterial *m, GSurfPoint *sp, GVec3 *n);
/** Lambertian diffuse colour (for previews). */
GENERIC_API GENERIC_NODISCARD int gmaterial_diffuse(const GMaterial *m, GSurfPoint *sp, GColor *result);
/** 1 when opaque. */
GENERIC_API GENERIC_NODISCARD int gmaterial_opaque(const GMaterial *m, GSurfPoint *sp);

/* ---- helpers for material implementations (lib/optics.c) ---- */

/** 1 when out is the ideal mirror direction of in about n (within 1e-6 in cosine). */
GENERIC_API GENERIC_NODISCARD int gmaterial_is_mirror_pair(GVec3 in, GVec3 n, GVec3 out);
/** Ideal refraction of the incident direction view through normal n (facing the incident side) with
 * relative index eta = n_from / n_to; 0 on total internal reflection. */
GENERIC_API GENERIC_NODISCARD int goptics_refract(GVec3 view, GVec3 n, double eta, GVec3 *dir);
/** Unpolarised Fresnel reflectance for cos_i on the incident side and eta = n_from / n_to (1 past TIR). */
GENERIC_API double goptics_fresnel(double cos_i, double eta);

#ifdef __cplusplus
}
#endif
#endif
