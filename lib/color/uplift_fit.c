/* uplift_fit.c - Levenberg-Marquardt fit of a sigmoid-polynomial reflectance to a colour (uplift_fit.h). The
 * residual is the CIELAB difference (as in Jakob and Hanika's optimiser: dark and light colours weigh alike),
 * its Jacobian analytic: one pass over the samples gives XYZ and its derivatives by the three coefficients. */
#include "uplift_fit.h"

#include <math.h>
#include <string.h>

double guplift_sigmoid(double x)
{
    if (isinf(x))
        return x > 0.0 ? 1.0 : 0.0;
    return 0.5 + 0.5 * x / sqrt(1.0 + x * x);
}

/* XYZ of S(c) and, when d is not NULL, d[j][a] = dXYZ_j / dc_a. */
static void eval_xyz(const GUpliftFit *f, const double c[3], double xyz[3], double d[3][3])
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

/* Residual r = Lab(target) - Lab(fit of c) and, when jac is not NULL, dr / dc. Returns |r|^2. */
static double residual(const GUpliftFit *f, const double target_lab[3], const double c[3], double r[3],
                       double jac[3][3])
{
    double xyz[3], d[3][3], l[3], dl[3][3];
    eval_xyz(f, c, xyz, jac ? d : NULL);
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

double guplift_fit_solve(const GUpliftFit *f, const double xyz[3], double c[3], int iterations, double tolerance)
{
    double target[3], r[3], jac[3][3];
    lab(xyz, f->white, target, NULL);
    double cost = residual(f, target, c, r, jac), damping = 1e-3;
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
            double tc = residual(f, target, trial, tr, tj);
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
