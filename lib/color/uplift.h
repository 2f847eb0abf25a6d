/* uplift.h - sigmoid uplifting's pieces for the spectral kit (lib/color/spectral.c), private to lib/. */
#ifndef GENERIC_LIB_UPLIFT_H
#define GENERIC_LIB_UPLIFT_H

#include "generic/colorspace.h"

/** scale * S(poly(x)) at the normalised wavelength x = (nm - 380) / 400 (without D65 for a light). */
double guplift_sigmoid_at(const GUplift *u, double x);
/** Refines u's coefficients so that sum_k w[c][k] * S(poly(x[k])) meets u->xyz: the uplift made exact in a
 * model's own discretisation (for a light, w includes the D65 factor). white (may be NULL: summed here) is the
 * discretisation's white, sum_k w[c][k] added up in k's order. *delta_e (may be NULL) gets the CIELAB distance
 * left. */
int guplift_refine(GUplift *u, int n, const double *x, const double *const w[3], const double white[3],
                   double *delta_e);
/** out[k] = (float)(guplift_sigmoid_at(u, x[k]) * f[k]) for k < n: a model's samples of an uplifted colour (f the
 * D65 factor of a light, 1 for a reflectance). On x86-64 with AVX2, 4 samples a vector, with the same results bit
 * for bit as guplift_sigmoid_samples_scalar. */
void guplift_sigmoid_samples(const GUplift *u, int n, const double *x, const double *f, float *out);
/** guplift_sigmoid_samples one sample at a time, whatever the processor (for the test that compares the two). */
void guplift_sigmoid_samples_scalar(const GUplift *u, int n, const double *x, const double *f, float *out);

#endif
