/* uplift.h - sigmoid uplifting's pieces for the spectral kit (lib/color/spectral.c), private to lib/. */
#ifndef GENERIC_LIB_UPLIFT_H
#define GENERIC_LIB_UPLIFT_H

#include "generic/colorspace.h"

/** scale * S(poly(x)) at the normalised wavelength x = (nm - 380) / 400 (without D65 for a light). */
double guplift_sigmoid_at(const GUplift *u, double x);
/** Refines u's coefficients so that sum_k w[c][k] * S(poly(x[k])) meets u->xyz: the uplift made exact in a
 * model's own discretisation (for a light, w includes the D65 factor). *delta_e (may be NULL) gets the CIELAB
 * distance left. */
int guplift_refine(GUplift *u, int n, const double *x, const double *const w[3], double *delta_e);

#endif
