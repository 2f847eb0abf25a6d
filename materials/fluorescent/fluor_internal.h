/* fluor_internal.h - helpers shared by the fluorescent materials (not public). */
#ifndef GENERIC_FLUOR_INTERNAL_H
#define GENERIC_FLUOR_INTERNAL_H

#include "generic/fluorescent.h"

/** Checks a GReradiation's grid and values (finite); G_ERR_INVALID naming `what` otherwise. */
int fluor_matrix_check(const GReradiation *r, const char *what, GError *err);
/** The excitation column of r whose wavelength is nm (within a millionth of a step), or -1. */
int fluor_column_of(const GReradiation *r, double nm);
/** Entry (o, i) of r with negative noise clamped to 0. */
static inline double fluor_entry(const GReradiation *r, int o, int i)
{
    float v = r->data[(long)o * r->n_in + i];
    return v > 0.0f ? (double)v : 0.0;
}

#endif
