/* params.h - parameter checks, construction and shading helpers shared by the built-in materials and the
 * texture nodes (not public). */
#ifndef GENERIC_MATERIALS_PARAMS_H
#define GENERIC_MATERIALS_PARAMS_H

#include "generic/material.h"

/** Checks a parameter colour and copies it into new heap storage of model m (dst must be freed with
 * gcolor_free). Every sample must be finite and >= 0, and with max > 0 also <= max (for matrices the
 * brightness is compared with max). A colour of another model is converted through the nm spectrum
 * with the given role and clamped to [0, max] afterwards. Messages read "<material>: <param> ...". */
int gmatparam_color(const GColorModel *m, const GColor *src, GColorRole role, double max, const char *material,
                    const char *param, GColor *dst, GError *err);
/** Largest sample of a vector value (its index in *at, may be NULL), the brightness of a matrix. */
double gmatparam_max(const GColor *c, int *at);
/** Allocates a zeroed material of `size` bytes (a struct that begins with its GMaterial) of class cls in
 * model into *out: G_ERR_NOMEM "<class>: out of memory". Until it is complete, the material is freed with its
 * class's destroy (or gmem_free). */
int gmat_new(const GMaterialClass *cls, const GColorModel *model, size_t size, GMaterial **out, GError *err);

/** The state of a material whose one parameter is a colour (lambert, mirror; emitter adds a flag after it). */
typedef struct GMatOneColor {
    GMaterial base;
    GColor c;
} GMatOneColor;
/** The destroy method of the materials whose struct begins with a GMatOneColor. */
void gmat_one_color_destroy(GMaterial *self);
/** Creates a material of class cls whose struct (`size` bytes) begins with a GMatOneColor, its colour being
 * src checked and converted by gmatparam_color (role, max; messages "<class>: <param> ..."). G_ERR_INVALID
 * "<class>: no colour model given" without a model. */
int gmat_one_color_create(const GMaterialClass *cls, const GColorModel *model, size_t size, const GColor *src,
                          GColorRole role, double max, const char *param, GMaterial **out, GError *err);
/** Cosine of a direction with the shading normal when in and out are both on the incident side of the
 * geometric normal, else 0; *n receives the shading normal. */
double gmat_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n);

#endif
