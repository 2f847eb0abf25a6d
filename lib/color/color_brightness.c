/* color_brightness.c - brightness read in a role (gcolor_brightness_as, color.h): a reflectance's is the model's own
 * brightness; a light's is its Y as a light, taken through the model's conversion with samples by magnitude. */
#include "generic/color.h"
#include "generic/memory.h"

#include <float.h>
#include <math.h>

double gcolor_brightness_as(const GColor *c, GColorRole role)
{
    if (role != GCOLOR_LIGHT || c->kind != GCOLOR_VECTOR)
        return gcolor_brightness(c);
    const GColorModel *m = c->model;
    GScratch *arena = gscratch_thread();
    if (!arena)
        return NAN;
    GScratchMark mark = gscratch_mark(arena);
    GColor mag;
    double xyz[3] = {NAN, NAN, NAN};
    int nonzero = 0;
    if (gcolor_scratch_uncleared(&mag, m, arena) == G_OK) {
        /* samples by magnitude, as gcolor_brightness counts them: a light with negative samples is not darker
         * for them */
        for (int k = 0; k < m->nvalues; k++) {
            mag.v[k] = fabsf(c->v[k]);
            nonzero |= c->v[k] != 0.0f;
        }
        mag.kind = GCOLOR_VECTOR;
        if (gcolor_to_xyz(&mag, GCOLOR_LIGHT, xyz) != G_OK)
            xyz[1] = NAN;
    }
    gscratch_release(arena, mark);
    if (xyz[1] > 0.0)
        return xyz[1];
    if (!nonzero)
        return 0.0;
    return isfinite(xyz[1]) ? DBL_MIN : NAN; /* light the eye does not see is still not black */
}
