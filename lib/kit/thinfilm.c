/* thinfilm.c - the Airy sum of a thin film (kit/thinfilm.h). */
#include "generic/kit/thinfilm.h"

#include <complex.h>
#include <math.h>

/* The wavelength-independent part of the sum at one angle: per polarisation (0 s, 1 p) the interfaces' amplitude
 * coefficients and the factor turning |t|^2 into power; the phase 2 pi d n_1 cos(theta_1) (complex with extinction). */
typedef struct Stack {
    double complex r01[2], r12[2], t012[2]; /* t012 = t_01 t_12 */
    double power[2];
    double complex phase;
    int tir; /* total internal reflection at the substrate */
} Stack;

static Stack stack_at(const GThinFilm *f, double cos_ambient)
{
    Stack st;
    double c0 = fmin(1.0, fmax(1e-9, cos_ambient));
    double s = f->ambient * sqrt(fmax(0.0, 1.0 - c0 * c0)); /* n_0 sin(theta_0), kept across the stack */
    double complex n[3] = {f->ambient, f->n + I * f->k, f->substrate}, cs[3];
    cs[0] = c0;
    /* n_1 cos(theta_1) = sqrt(n_1^2 - s^2), the principal root: Im >= 0, the wave decays into the film */
    cs[1] = csqrt(n[1] * n[1] - s * s) / n[1];
    double sub2 = f->substrate * f->substrate - s * s;
    st.tir = sub2 <= 0.0; /* then nothing enters the substrate: an evanescent wave */
    cs[2] = st.tir ? I * sqrt(-sub2) / f->substrate : sqrt(sub2) / f->substrate;
    for (int p = 0; p < 2; p++) {
        /* s: n_i cos_i against n_j cos_j; p: n_j cos_i against n_i cos_j */
        double complex a0 = p ? n[1] * cs[0] : n[0] * cs[0], b0 = p ? n[0] * cs[1] : n[1] * cs[1];
        double complex a1 = p ? n[2] * cs[1] : n[1] * cs[1], b1 = p ? n[1] * cs[2] : n[2] * cs[2];
        st.r01[p] = (a0 - b0) / (a0 + b0);
        st.r12[p] = (a1 - b1) / (a1 + b1);
        st.t012[p] = 2.0 * n[0] * cs[0] / (a0 + b0) * (2.0 * n[1] * cs[1] / (a1 + b1));
        double complex c2 = p ? conj(cs[2]) : cs[2], c0c = p ? conj(cs[0]) : cs[0];
        st.power[p] = creal(n[2] * c2) / creal(n[0] * c0c);
    }
    st.phase = 2.0 * M_PI * f->thickness * n[1] * cs[1];
    return st;
}

/* R and T of the stack at wavelength nm. */
static void stack_eval(const Stack *st, double nm, double *r, double *t)
{
    double complex e1 = cexp(I * st->phase / nm), e2 = e1 * e1;
    double rsum = 0.0, tsum = 0.0;
    for (int p = 0; p < 2; p++) {
        double complex den = 1.0 + st->r01[p] * st->r12[p] * e2;
        double complex rr = (st->r01[p] + st->r12[p] * e2) / den, tt = st->t012[p] * e1 / den;
        rsum += creal(rr * conj(rr));
        tsum += st->power[p] * creal(tt * conj(tt));
    }
    *r = 0.5 * rsum;
    *t = st->tir ? 0.0 : 0.5 * tsum;
}

void gthinfilm_airy(const GThinFilm *f, double nm, double cos_ambient, double *r, double *t)
{
    Stack st = stack_at(f, cos_ambient);
    double rr, tt;
    stack_eval(&st, nm, &rr, &tt);
    if (r)
        *r = rr;
    if (t)
        *t = tt;
}

/* cos and sin of phase / lambda at lambda = GNM_MIN + i, given them at i - 1: exactly every PHASE_SYNC nm and where
 * the step is large, else by rotating through the step d = phase (1 / (lambda - 1) - 1 / lambda), whose cosine and
 * sine are their Taylor series to d^8 and d^9 (each step within 3e-10 for d <= 0.5). */
#define PHASE_SYNC 16
static void next_phase(double phase, int i, double *c, double *s)
{
    double lambda = GNM_MIN + i, d = i > 0 ? phase / ((lambda - 1.0) * lambda) : 0.0;
    if (i % PHASE_SYNC == 0 || !(d <= 0.5)) {
        *c = cos(phase / lambda);
        *s = sin(phase / lambda);
        return;
    }
    /* the series' coefficients as products, not divisions: a division per term was most of a film's cost (the
     * divider's throughput, nine divisions a nanometre) */
    double d2 = d * d;
    double cd = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0) * (1.0 - d2 * (1.0 / 30.0) * (1.0 - d2 * (1.0 / 56.0))));
    double sd = d * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0) * (1.0 - d2 * (1.0 / 42.0) *
                                                                            (1.0 - d2 * (1.0 / 72.0)))));
    /* phase / lambda = phase / (lambda - 1) - d: rotate back by d */
    double c1 = *c * cd + *s * sd, s1 = *s * cd - *c * sd;
    *c = c1, *s = s1;
}

/* The film's spectra at cos_ambient into r and t. Without extinction and total internal reflection the Fresnel
 * coefficients are real and the same at every wavelength: R = (a + 2 b cos phi) / (c + 2 b cos phi) per
 * polarisation with phi = 4 pi d n_1 cos(theta_1) / lambda, and T = 1 - R; one cosine per nm. Otherwise the complex
 * sum of gthinfilm_airy at every nm. */
static void film_spectra(const GThinFilm *f, double cos_ambient, GSpectrumNM *rs, GSpectrumNM *ts)
{
    double c0 = fmin(1.0, fmax(1e-9, cos_ambient));
    double s2 = f->ambient * f->ambient * (1.0 - c0 * c0);
    double n0 = f->ambient, n1 = f->n, n2 = f->substrate;
    if (f->k != 0.0 || s2 >= n1 * n1 || s2 >= n2 * n2) {
        Stack st = stack_at(f, cos_ambient);
        for (int i = 0; i < GNM_COUNT; i++) {
            double r, t;
            stack_eval(&st, GNM_MIN + i, &r, &t);
            rs->v[i] = (float)r;
            ts->v[i] = (float)t;
        }
        return;
    }
    double nc0 = n0 * c0, nc1 = sqrt(n1 * n1 - s2), nc2 = sqrt(n2 * n2 - s2);
    double c1 = nc1 / n1, c2 = nc2 / n2;
    double r01[2] = {(nc0 - nc1) / (nc0 + nc1), (n1 * c0 - n0 * c1) / (n1 * c0 + n0 * c1)};
    double r12[2] = {(nc1 - nc2) / (nc1 + nc2), (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2)};
    double phase = 4.0 * M_PI * f->thickness * nc1, cp = 0.0, sp = 0.0;
    double cosines[GNM_COUNT]; /* cos phi at every nm first (a recurrence), then R of each (independent) */
    for (int i = 0; i < GNM_COUNT; i++) {
        next_phase(phase, i, &cp, &sp);
        cosines[i] = cp;
    }
    for (int i = 0; i < GNM_COUNT; i++) {
        cp = cosines[i];
        /* the mean of the two polarisations' (a + 2 b cos phi) / (1 + b^2 + 2 b cos phi), over one division */
        double num[2], den[2];
        for (int p = 0; p < 2; p++) {
            double a = r01[p] * r01[p] + r12[p] * r12[p], b = r01[p] * r12[p];
            num[p] = a + 2.0 * b * cp;
            den[p] = 1.0 + b * b + 2.0 * b * cp;
        }
        double r = 0.5 * (num[0] * den[1] + num[1] * den[0]) / (den[0] * den[1]);
        rs->v[i] = (float)r;
        ts->v[i] = (float)(1.0 - r);
    }
}

int gthinfilm_color(const GThinFilm *f, double cos_ambient, GColor *reflectance, GColor *transmittance)
{
    GSpectrumNM rs, ts;
    film_spectra(f, cos_ambient, &rs, &ts);
    int rc = G_OK;
    if (reflectance)
        rc = gcolor_from_nm(reflectance, &rs, GCOLOR_REFLECTANCE);
    if (rc == G_OK && transmittance)
        rc = gcolor_from_nm(transmittance, &ts, GCOLOR_REFLECTANCE);
    return rc;
}
