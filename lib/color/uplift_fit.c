/* uplift_fit.c - Levenberg-Marquardt fit of a sigmoid-polynomial reflectance to a colour (uplift_fit.h). The
 * residual is the CIELAB difference (as in Jakob and Hanika's optimiser: dark and light colours weigh alike),
 * its Jacobian analytic: one pass over the samples gives XYZ and its derivatives by the three coefficients. That
 * pass has two bodies, scalar and (on x86-64) AVX2, with the same results bit for bit, bound when the library is
 * loaded as the spectral kernels are (generic/kit/spectral_kernels.h). */
#include "uplift_fit.h"
#include "generic/kit/spectral_kernels.h"

#include <math.h>
#include <string.h>

double guplift_sigmoid(double x)
{
    if (isinf(x))
        return x > 0.0 ? 1.0 : 0.0;
    return 0.5 + 0.5 * x / sqrt(1.0 + x * x);
}

/* XYZ of S(c) and, when d is not NULL, d[j][a] = dXYZ_j / dc_a. Every sum runs over the samples in order, one
 * double addition a sample: the vector body below keeps that order, so the two give the same bits. */
static void eval_xyz_scalar(const GUpliftFit *f, const double c[3], double xyz[3], double d[3][3])
{
    double out[3] = {0, 0, 0}, dd[3][3] = {{0}};
    for (int k = 0; k < f->n; k++) {
        double u = f->u[k], x = (c[0] * u + c[1]) * u + c[2];
        double q = 1.0 / sqrt(1.0 + x * x);
        double s = 0.5 * x * q + 0.5, ds = 0.5 * q * q * q;
        for (int j = 0; j < 3; j++) {
            double w = f->w[j][k];
            out[j] += w * s;
            if (d) {
                double wd = w * ds;
                dd[j][0] += wd * u * u;
                dd[j][1] += wd * u;
                dd[j][2] += wd;
            }
        }
    }
    memcpy(xyz, out, sizeof out);
    if (d)
        memcpy(d, dd, sizeof dd);
}

#ifdef GSPECTRAL_AVX2
/* 4 doubles in one AVX register. */
typedef double fit_v4d __attribute__((vector_size(32)));

static inline GSPECTRAL_TARGET_AVX2 fit_v4d fit_splat(double x) { return (fit_v4d){x, x, x, x}; }

/* The 4 doubles from p, the lanes from `count` on 0 (count 1..4). */
static inline __attribute__((always_inline)) GSPECTRAL_TARGET_AVX2 fit_v4d fit_load(const double *p, int count)
{
    fit_v4d v;
    if (count == 4) {
        memcpy(&v, p, sizeof v);
        return v;
    }
    double t[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; i++)
        t[i] = p[i];
    memcpy(&v, t, sizeof v);
    return v;
}

/* Lane l of v in every lane. */
#define FIT_LANE(v, l) __builtin_shufflevector(v, v, l, l, l, l)

/* One sample's contributions to the sums of fit_block (the derivatives' when deriv is set): w its weights (w0, w1,
 * w2, 0), u, s and ds its position, sigmoid and derivative in every lane. */
#define FIT_ADD_SAMPLE(w, u, s, ds)                                                                            \
    do {                                                                                                       \
        fit_v4d wd_ = (w) * (ds), wu_ = wd_ * (u);                                                             \
        out += (w) * (s);                                                                                      \
        if (deriv) {                                                                                           \
            d0 += wu_ * (u);                                                                                   \
            d1 += wu_;                                                                                         \
            d2 += wd_;                                                                                         \
        }                                                                                                      \
    } while (0)

/* The accumulators of eval_xyz_avx2: lanes 0-2 the three tristimulus values. */
typedef struct FitSums {
    fit_v4d out, d0, d1, d2;
} FitSums;

/* Adds the samples k..k+m-1 (m 1..4; inlined with m constant for the whole blocks). */
static inline __attribute__((always_inline)) GSPECTRAL_TARGET_AVX2 void fit_block(const GUpliftFit *f, int k, int m,
                                                                                const double c[3], int deriv,
                                                                                FitSums *sum)
{
    const fit_v4d one = fit_splat(1.0), half = fit_splat(0.5), zero = fit_splat(0.0);
    fit_v4d out = sum->out, d0 = sum->d0, d1 = sum->d1, d2 = sum->d2;
    fit_v4d u = fit_load(f->u + k, m);
    fit_v4d x = (fit_splat(c[0]) * u + fit_splat(c[1])) * u + fit_splat(c[2]);
    fit_v4d q = one / (fit_v4d)_mm256_sqrt_pd((__m256d)(one + x * x));
    fit_v4d s = half * x * q + half, ds = half * q * q * q;
    /* the weights of the 4 samples, one vector per sample: (w0, w1, w2, 0) */
    fit_v4d a = fit_load(f->w[0] + k, m), b = fit_load(f->w[1] + k, m), e = fit_load(f->w[2] + k, m);
    fit_v4d ab02 = __builtin_shufflevector(a, b, 0, 4, 2, 6), ab13 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
    fit_v4d e02 = __builtin_shufflevector(e, zero, 0, 4, 2, 6), e13 = __builtin_shufflevector(e, zero, 1, 5, 3, 7);
    FIT_ADD_SAMPLE(__builtin_shufflevector(ab02, e02, 0, 1, 4, 5), FIT_LANE(u, 0), FIT_LANE(s, 0), FIT_LANE(ds, 0));
    if (m > 1)
        FIT_ADD_SAMPLE(__builtin_shufflevector(ab13, e13, 0, 1, 4, 5), FIT_LANE(u, 1), FIT_LANE(s, 1),
                       FIT_LANE(ds, 1));
    if (m > 2)
        FIT_ADD_SAMPLE(__builtin_shufflevector(ab02, e02, 2, 3, 6, 7), FIT_LANE(u, 2), FIT_LANE(s, 2),
                       FIT_LANE(ds, 2));
    if (m > 3)
        FIT_ADD_SAMPLE(__builtin_shufflevector(ab13, e13, 2, 3, 6, 7), FIT_LANE(u, 3), FIT_LANE(s, 3),
                       FIT_LANE(ds, 3));
    *sum = (FitSums){out, d0, d1, d2};
}

/* eval_xyz_scalar on AVX2: the per-sample terms (sigmoid, derivative) of 4 samples in 4 lanes, then each sample's
 * contributions added to accumulators whose lanes are the three tristimulus values (lane 3 unused), sample after
 * sample: the same operations in the same order as the scalar body, on every lane, so the same bits. */
static GSPECTRAL_TARGET_AVX2 void eval_xyz_avx2(const GUpliftFit *f, const double c[3], double xyz[3],
                                                double d[3][3])
{
    FitSums sum = {fit_splat(0.0), fit_splat(0.0), fit_splat(0.0), fit_splat(0.0)};
    int k = 0;
    if (d)
        for (; k + 4 <= f->n; k += 4)
            fit_block(f, k, 4, c, 1, &sum);
    else
        for (; k + 4 <= f->n; k += 4)
            fit_block(f, k, 4, c, 0, &sum);
    if (k < f->n)
        fit_block(f, k, f->n - k, c, d != NULL, &sum);
    for (int j = 0; j < 3; j++) {
        xyz[j] = sum.out[j];
        if (d) {
            d[j][0] = sum.d0[j];
            d[j][1] = sum.d1[j];
            d[j][2] = sum.d2[j];
        }
    }
}
#undef FIT_ADD_SAMPLE
#undef FIT_LANE
#endif

static double lab_f(double t, double *dt)
{
    const double delta = 6.0 / 29.0;
    if (t > delta * delta * delta) {
        double r = cbrt(t);
        *dt = 1.0 / (3.0 * r * r);
        return r;
    }
    *dt = 1.0 / (3.0 * delta * delta);
    return t / (3.0 * delta * delta) + 4.0 / 29.0;
}

/* CIELAB of xyz against white; jac (may be NULL) gets dLab / dXYZ. */
static void lab(const double xyz[3], const double white[3], double out[3], double jac[3][3])
{
    double fv[3], g[3];
    for (int k = 0; k < 3; k++) {
        fv[k] = lab_f(xyz[k] / white[k], &g[k]);
        g[k] /= white[k];
    }
    out[0] = 116.0 * fv[1] - 16.0;
    out[1] = 500.0 * (fv[0] - fv[1]);
    out[2] = 200.0 * (fv[1] - fv[2]);
    if (jac) {
        double j[3][3] = {{0, 116.0 * g[1], 0}, {500.0 * g[0], -500.0 * g[1], 0}, {0, 200.0 * g[1], -200.0 * g[2]}};
        memcpy(jac, j, sizeof j);
    }
}

/* One of the bodies of eval_xyz. */
typedef void FitEval(const GUpliftFit *f, const double c[3], double xyz[3], double d[3][3]);

/* Residual r = Lab(target) - Lab(fit of c) and, when jac is not NULL, dr / dc. Returns |r|^2. */
static inline __attribute__((always_inline)) double residual(FitEval *eval, const GUpliftFit *f,
                                                             const double target_lab[3], const double c[3],
                                                             double r[3], double jac[3][3])
{
    double xyz[3], d[3][3], l[3], dl[3][3];
    eval(f, c, xyz, jac ? d : NULL);
    lab(xyz, f->white, l, jac ? dl : NULL);
    for (int j = 0; j < 3; j++)
        r[j] = target_lab[j] - l[j];
    if (jac)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                jac[a][b] = -(dl[a][0] * d[0][b] + dl[a][1] * d[1][b] + dl[a][2] * d[2][b]);
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

/* Solves m x = v by Cramer's rule; -1 when m is singular. */
static int solve3(const double m[3][3], const double v[3], double x[3])
{
    double c0 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c1 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
           c2 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    double det = m[0][0] * c0 + m[0][1] * c1 + m[0][2] * c2;
    if (!(fabs(det) > 1e-300) || !isfinite(det))
        return -1;
    double inv[3][3] = {
        {c0, m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][1] * m[1][2] - m[0][2] * m[1][1]},
        {c1, m[0][0] * m[2][2] - m[0][2] * m[2][0], m[0][2] * m[1][0] - m[0][0] * m[1][2]},
        {c2, m[0][1] * m[2][0] - m[0][0] * m[2][1], m[0][0] * m[1][1] - m[0][1] * m[1][0]},
    };
    for (int a = 0; a < 3; a++)
        x[a] = (inv[a][0] * v[0] + inv[a][1] * v[1] + inv[a][2] * v[2]) / det;
    return 0;
}

/* guplift_fit_solve with the XYZ evaluation eval (inlined into each body). */
static inline __attribute__((always_inline)) double fit_solve(FitEval *eval, const GUpliftFit *f,
                                                              const double xyz[3], double c[3], int iterations,
                                                              double tolerance)
{
    double target[3], r[3], jac[3][3];
    lab(xyz, f->white, target, NULL);
    double cost = residual(eval, f, target, c, r, jac), damping = 1e-3;
    for (int it = 0; it < iterations && cost > tolerance * tolerance; it++) {
        double a[3][3], g[3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++)
                a[i][j] = jac[0][i] * jac[0][j] + jac[1][i] * jac[1][j] + jac[2][i] * jac[2][j];
            g[i] = jac[0][i] * r[0] + jac[1][i] * r[1] + jac[2][i] * r[2];
        }
        int accepted = 0;
        for (int t = 0; t < 12 && !accepted; t++) {
            double m[3][3], step[3];
            memcpy(m, a, sizeof m);
            for (int i = 0; i < 3; i++)
                m[i][i] += damping;
            if (solve3(m, g, step) != 0) {
                damping *= 10.0;
                continue;
            }
            /* the trial's residual and Jacobian in one pass: an accepted step needs no second */
            double trial[3] = {c[0] - step[0], c[1] - step[1], c[2] - step[2]}, tr[3], tj[3][3];
            double tc = residual(eval, f, target, trial, tr, tj);
            if (tc < cost) {
                memcpy(c, trial, sizeof trial);
                memcpy(r, tr, sizeof tr);
                memcpy(jac, tj, sizeof tj);
                cost = tc;
                damping = fmax(damping * 0.5, 1e-12);
                accepted = 1;
            } else if ((damping *= 10.0) > 1e12) {
                break;
            }
        }
        if (!accepted)
            break;
    }
    return sqrt(cost);
}

static double guplift_fit_solve_v4(const GUpliftFit *f, const double xyz[3], double c[3], int iterations,
                                   double tolerance)
{
    return fit_solve(eval_xyz_scalar, f, xyz, c, iterations, tolerance);
}

double guplift_fit_solve_scalar(const GUpliftFit *f, const double xyz[3], double c[3], int iterations,
                                double tolerance)
{
    return guplift_fit_solve_v4(f, xyz, c, iterations, tolerance);
}

#ifdef GSPECTRAL_AVX2
static GSPECTRAL_TARGET_AVX2 double guplift_fit_solve_v8(const GUpliftFit *f, const double xyz[3], double c[3],
                                                         int iterations, double tolerance)
{
    return fit_solve(eval_xyz_avx2, f, xyz, c, iterations, tolerance);
}

GSPECTRAL_PICK(guplift_fit_solve);

int guplift_fit_vectorised(void) { return gspectral_have_avx2(); }
#else
double guplift_fit_solve(const GUpliftFit *f, const double xyz[3], double c[3], int iterations, double tolerance)
{
    return guplift_fit_solve_v4(f, xyz, c, iterations, tolerance);
}

int guplift_fit_vectorised(void) { return 0; }
#endif
