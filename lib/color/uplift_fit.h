/* uplift_fit.h - the fit behind sigmoid uplifting (Jakob and Hanika 2019), private to lib/ and shared with the
 * table generator (scripts/gen_uplift_tables.c): a reflectance s(u) = S(c0 u^2 + c1 u + c2) with
 * S(x) = 1/2 + x / (2 sqrt(1 + x^2)) and u = (nm - GUPLIFT_NM0) / GUPLIFT_NM_SPAN, fitted by Levenberg-Marquardt
 * so that its tristimulus values under a discretisation (sample positions and XYZ weights) meet a target, with
 * the residual measured in CIELAB. Needs libm only. */
#ifndef GENERIC_LIB_UPLIFT_FIT_H
#define GENERIC_LIB_UPLIFT_FIT_H

/** The wavelength at u = 0 and the span of u = 1, in nm: the coefficients are in this normalised variable. */
#define GUPLIFT_NM0 380.0
#define GUPLIFT_NM_SPAN 400.0

/** A discretisation: XYZ = sum_k w[c][k] * s(u[k]). */
typedef struct GUpliftFit {
    int n;
    const double *u;    /**< n normalised wavelengths */
    const double *w[3]; /**< n weights per tristimulus value */
    double white[3];    /**< the CIELAB reference white (XYZ) */
} GUpliftFit;

/** S(x), with S(+inf) = 1 and S(-inf) = 0. */
double guplift_sigmoid(double x);

/** Improves c (start value in, fitted value out) so that the fit's XYZ of S(c) meets xyz, in at most `iterations`
 * Levenberg-Marquardt steps, stopping once the CIELAB distance is within tolerance; returns the remaining distance
 * (within tolerance for a colour sigmoid spectra reach; the distance to the nearest reachable colour outside their
 * gamut). */
double guplift_fit_solve(const GUpliftFit *f, const double xyz[3], double c[3], int iterations, double tolerance);
/** guplift_fit_solve on the scalar body, whatever the processor: the same results bit for bit (for the test that
 * compares the bodies). */
double guplift_fit_solve_scalar(const GUpliftFit *f, const double xyz[3], double c[3], int iterations,
                                double tolerance);
/** 1 when guplift_fit_solve runs the vector (AVX2) body on this processor, 0 when it runs the scalar one. */
int guplift_fit_vectorised(void);

#endif
