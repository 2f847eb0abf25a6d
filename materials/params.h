/* params.h - parameter checks and shading helpers shared by the built-in materials (not public). */
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
/** Cosine of a direction with the shading normal when in and out are both on the incident side of the
 * geometric normal, else 0; *n receives the shading normal. */
double gmat_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n);

#endif
