/* sg_lobe.c - one spherical Gaussian lobe G(d) = exp(lambda (axis . d - 1)): its integral, the sharpness
 * whose mean direction has a given length, and its irradiance.
 *
 * Irradiance: E(mu) = integral over the sphere of G(d) max(0, n . d), mu = n . axis. With t = axis . d and
 * the azimuth phi about the axis, n . d = a + b cos phi with a = mu t, b = sqrt(1 - mu^2) sqrt(1 - t^2), and
 * the integral over phi of max(0, a + b cos phi) is closed-form (2 pi a or 0 when b <= |a|, else
 * 2 (a acos(-a / b) + sqrt(b^2 - a^2))). What is left, the integral over t of exp(lambda (t - 1)) H(t), is
 * taken in s = exp(lambda (t - 1)), where the weight is flat (ds = lambda s dt), by the midpoint rule: the
 * same accuracy for a sun-sized lobe and for one that covers the sphere. */
#include "probe_internal.h"

/* Quadrature points of the integral over s. */
#define SG_QUADRATURE 512

/* The integral over the azimuth of max(0, a + b cos phi), b >= 0. */
static double azimuth_integral(double a, double b)
{
    if (b <= fabs(a))
        return a > 0.0 ? 2.0 * M_PI * a : 0.0;
    return 2.0 * (a * acos(-a / b) + sqrt(b * b - a * a));
}

double gprobe_sg_lobe_irradiance(double sharpness, double mu)
{
    double lambda = sharpness > 1e-6 ? sharpness : 1e-6;
    mu = mu > 1.0 ? 1.0 : mu < -1.0 ? -1.0 : mu;
    double s0 = exp(-2.0 * lambda), ds = (1.0 - s0) / SG_QUADRATURE, sin_mu = sqrt(1.0 - mu * mu), sum = 0.0;
    for (int i = 0; i < SG_QUADRATURE; i++) {
        double s = s0 + (i + 0.5) * ds, t = 1.0 + log(s) / lambda;
        t = t < -1.0 ? -1.0 : t;
        sum += azimuth_integral(mu * t, sin_mu * sqrt(fmax(0.0, 1.0 - t * t)));
    }
    return sum * ds / lambda;
}

double probe_sg_integral(double lambda)
{
    return 2.0 * M_PI * -expm1(-2.0 * lambda) / lambda;
}

/* Mean cosine to the axis of the lobe (the length of its mean direction): coth lambda - 1 / lambda. */
static double mean_cosine(double lambda)
{
    if (lambda < 1e-2)
        return lambda / 3.0 - lambda * lambda * lambda / 45.0;
    return 1.0 / tanh(lambda) - 1.0 / lambda;
}

double probe_sg_sharpness(double mean_length, double lo, double hi)
{
    if (!(mean_length > mean_cosine(lo)))
        return lo;
    if (mean_length >= mean_cosine(hi))
        return hi;
    double a = log(lo), b = log(hi);
    for (int i = 0; i < 100; i++) {
        double mid = 0.5 * (a + b);
        if (mean_cosine(exp(mid)) < mean_length)
            a = mid;
        else
            b = mid;
    }
    return exp(0.5 * (a + b));
}
