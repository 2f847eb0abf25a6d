/* fluorescent_kit.h - the kit of fluorescent material writers: checks of re-radiation matrices, their entries,
 * the incident and outgoing cosines of a reflection, the two-part sum a fluorescent reflection returns, and the
 * parameter block shared by the fluorescent materials (matrix plus numbers). Used by
 * the fluorescent materials of materials/fluorescent/; a module may use it the same way. */
#ifndef GENERIC_FLUORESCENT_KIT_H
#define GENERIC_FLUORESCENT_KIT_H

#include "../export.h"
#include "../fluorescent.h"
#include "../material.h"
#include "material_kit.h"
#include "../reader.h"

#include <stddef.h>

/** Checks a GReradiation's grid and values (finite); G_ERR_INVALID naming `what` otherwise. */
GENERIC_API GENERIC_NODISCARD int gfluor_matrix_check(const GReradiation *r, const char *what, GError *err);
/** The excitation column of r whose wavelength is nm (within a millionth of a step), or -1. */
GENERIC_API GENERIC_NODISCARD int gfluor_column_of(const GReradiation *r, double nm);
/** Entry (o, i) of r with negative noise clamped to 0. */
static inline double gfluor_entry(const GReradiation *r, int o, int i)
{
    float v = r->data[(long)o * r->n_in + i];
    return v > 0.0f ? (double)v : 0.0;
}

/** The cosines of a reflection from in to out with the shading normal *n: *ci (gmaterial_cos_in) and *co. 1 when
 * light reflects, else 0 with result made black (either cosine <= 0). */
static inline int gfluor_cosines(GSurfPoint *sp, GVec3 in, GVec3 out, GColor *result, GVec3 *n, double *ci,
                                double *co)
{
    *ci = gmaterial_cos_in(sp, in, out, n);
    *co = gvec3_dot(out, *n);
    if (*ci <= 0.0 || *co <= 0.0) {
        gcolor_black(result);
        return 0;
    }
    return 1;
}

/** result = wa * (a ? a * illum : illum) + wb * (b * illum): the light a fluorescent material returns as
 * the sum of two parts, b * illum held in a temporary on sp's arena and computed first (result may alias
 * illum). The operations run in the order written, so each material gets the same numbers as it would
 * spelling the sum out. */
static inline int gfluor_two_parts(GSurfPoint *sp, const GColorModel *model, const GColor *illum, const GColor *a,
                                  double wa, const GColor *b, double wb, GColor *result)
{
    GScratchMark mark = gscratch_mark(sp->scratch);
    GColor t;
    int rc = gcolor_scratch(&t, model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_mul(&t, b, illum);
    if (rc == G_OK && a) {
        rc = gcolor_mul(result, a, illum);
        if (rc == G_OK)
            rc = gcolor_scale(result, result, wa);
    } else if (rc == G_OK)
        rc = gcolor_scale(result, illum, wa);
    if (rc == G_OK)
        rc = gcolor_add_scaled(result, &t, wb);
    gscratch_release(sp->scratch, mark);
    return rc;
}

/** A numeric parameter of a fluorescent material: `count` numbers in [lo, hi] at `offset` in its parameter
 * struct. */
typedef struct GFluorParam {
    const char *key;
    double lo, hi;
    size_t offset;
    int count;
} GFluorParam;

/** Reads a fluorescent material's parameter block (lib/kit/fluorescent_params.c): `matrix` into *mat
 * (the default matrix when it is not given) and the numbers of `table` into params; `keys` lists every name for
 * the unknown-key message. *mat is freed by the caller (gfluor_finish), also on failure. */
GENERIC_API GENERIC_NODISCARD int gfluor_read_params(GReader *r, const GFluorParam *table, const char *keys,
                                                     void *params, GReradiation *mat, GError *err);
/** The end of a fluorescent material's parse: frees *mat and hands over m when rc is G_OK; returns rc. */
GENERIC_API GENERIC_NODISCARD int gfluor_finish(int rc, GReradiation *mat, GMaterial *m, void **object);

#endif
