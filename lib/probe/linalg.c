/* linalg.c - dense kernels for the irradiance fit: column products, Cholesky, non-negative least squares. */
#include "probe_internal.h"

#include <math.h>
#include <string.h>

/* C[x][y] = sum_k X[x m + k] Y[y m + k] for a block of 2 x 4 columns; the compiler vectorises over k. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define PROBE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PROBE_CLONES
#endif

PROBE_CLONES
static void block24(const double *x0, const double *x1, const double *y0, const double *y1, const double *y2,
                    const double *y3, int m, double out[8])
{
    double s00 = 0, s01 = 0, s02 = 0, s03 = 0, s10 = 0, s11 = 0, s12 = 0, s13 = 0;
    #pragma omp simd reduction(+ : s00, s01, s02, s03, s10, s11, s12, s13)
    for (int k = 0; k < m; k++) {
        const double a = x0[k], b = x1[k];
        s00 += a * y0[k];
        s01 += a * y1[k];
        s02 += a * y2[k];
        s03 += a * y3[k];
        s10 += b * y0[k];
        s11 += b * y1[k];
        s12 += b * y2[k];
        s13 += b * y3[k];
    }
    out[0] = s00; out[1] = s01; out[2] = s02; out[3] = s03;
    out[4] = s10; out[5] = s11; out[6] = s12; out[7] = s13;
}

void probe_gemm_tn(const double *X, int p, const double *Y, int q, int m, double *C, int ldc, int symmetric)
{
    const int xb = (p + 1) / 2;
    #pragma omp parallel for schedule(dynamic, 1) if ((double)p * q * m > 2e7)
    for (int bx = 0; bx < xb; bx++) {
        const int x = 2 * bx, x1 = x + 1 < p ? x + 1 : x;
        const int yend = symmetric ? x1 + 1 : q;
        for (int y = 0; y < yend; y += 4) {
            int yy[4];
            for (int t = 0; t < 4; t++)
                yy[t] = y + t < yend ? y + t : yend - 1;
            double out[8];
            block24(X + (size_t)x * m, X + (size_t)x1 * m, Y + (size_t)yy[0] * m, Y + (size_t)yy[1] * m,
                    Y + (size_t)yy[2] * m, Y + (size_t)yy[3] * m, m, out);
            for (int t = 0; t < 4 && y + t < yend; t++) {
                C[(size_t)x * ldc + y + t] = out[t];
                if (x1 != x)
                    C[(size_t)x1 * ldc + y + t] = out[4 + t];
            }
        }
    }
    if (symmetric)
        for (int x = 0; x < p; x++)
            for (int y = x + 1; y < p; y++)
                C[(size_t)x * ldc + y] = C[(size_t)y * ldc + x];
}

int probe_cholesky(double *a, int n)
{
    for (int j = 0; j < n; j++) {
        double d = a[j * n + j];
        for (int k = 0; k < j; k++)
            d -= a[j * n + k] * a[j * n + k];
        if (!(d > 0.0))
            return -1;
        d = sqrt(d);
        a[j * n + j] = d;
        for (int i = j + 1; i < n; i++) {
            double s = a[i * n + j];
            const double *ri = a + (size_t)i * n, *rj = a + (size_t)j * n;
            for (int k = 0; k < j; k++)
                s -= ri[k] * rj[k];
            a[i * n + j] = s / d;
        }
    }
    return 0;
}

void probe_cholesky_solve(const double *l, int n, double *b)
{
    for (int i = 0; i < n; i++) {
        double s = b[i];
        for (int k = 0; k < i; k++)
            s -= l[i * n + k] * b[k];
        b[i] = s / l[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = b[i];
        for (int k = i + 1; k < n; k++)
            s -= l[k * n + i] * b[k];
        b[i] = s / l[i * n + i];
    }
}

/* z = argmin on the passive set (G_PP z_P = h_P, z = 0 elsewhere); returns 0, or -1 when singular. */
static int solve_passive(int n, const double *G, const double *h, const int *idx, int p, double *z, double *chol,
                         double *rhs)
{
    double dmax = 0.0;
    for (int a = 0; a < p; a++)
        dmax = fmax(dmax, G[idx[a] * n + idx[a]]);
    for (double ridge = 1e-13; ridge < 1e-3; ridge *= 100.0) {
        for (int a = 0; a < p; a++) {
            for (int b = 0; b <= a; b++)
                chol[a * p + b] = G[idx[a] * n + idx[b]];
            chol[a * p + a] += ridge * dmax;
            rhs[a] = h[idx[a]];
        }
        if (probe_cholesky(chol, p) == 0) {
            probe_cholesky_solve(chol, p, rhs);
            memset(z, 0, sizeof(double) * n);
            for (int a = 0; a < p; a++)
                z[idx[a]] = rhs[a];
            return 0;
        }
    }
    return -1;
}

void probe_nnls(int n, const double *G, const double *h, double *x, double *work)
{
    double *chol = work, *z = chol + (size_t)n * n, *rhs = z + n, *wv = rhs + n;
    int *idx = (int *)(wv + n); /* n ints fit in n doubles */
    double hmax = 0.0;
    for (int i = 0; i < n; i++)
        hmax = fmax(hmax, fabs(h[i]));
    if (!(hmax > 0.0)) {
        memset(x, 0, sizeof(double) * n);
        return;
    }
    const double tol = 1e-12 * hmax;
    int p = 0;
    for (int i = 0; i < n; i++) {
        if (!(x[i] > 0.0))
            x[i] = 0.0;
        else
            idx[p++] = i;
    }
    int added = -1;
    for (int outer = 0; outer < 3 * n + 10; outer++) {
        /* inner loop: the unconstrained optimum on the passive set, stepping back to stay feasible */
        for (int inner = 0; inner < n + 1 && p > 0; inner++) {
            if (solve_passive(n, G, h, idx, p, z, chol, rhs) != 0)
                return;
            if (added >= 0 && !(z[added] > 0.0)) { /* the new index cannot enter: keep x as it is */
                for (int a = 0; a < p; a++)
                    if (idx[a] == added)
                        idx[a] = idx[--p];
                return;
            }
            added = -1;
            double alpha = 1.0;
            int block = -1;
            for (int a = 0; a < p; a++) {
                int i = idx[a];
                if (!(z[i] > 0.0)) {
                    double t = x[i] / (x[i] - z[i]);
                    if (t < alpha) {
                        alpha = t;
                        block = i;
                    }
                }
            }
            for (int a = 0; a < p; a++) {
                int i = idx[a];
                x[i] += alpha * (z[i] - x[i]);
            }
            if (block < 0)
                break;
            x[block] = 0.0;
            for (int a = 0; a < p;) { /* drop what reached zero */
                int i = idx[a];
                if (!(x[i] > 0.0)) {
                    x[i] = 0.0;
                    idx[a] = idx[--p];
                } else {
                    a++;
                }
            }
        }
        /* optimality: the gradient h - G x must be <= 0 off the passive set */
        int best = -1;
        double bw = tol;
        for (int i = 0; i < n; i++) {
            if (x[i] > 0.0)
                continue;
            double g = h[i];
            const double *gi = G + (size_t)i * n;
            for (int j = 0; j < n; j++)
                g -= gi[j] * x[j];
            wv[i] = g;
            if (g > bw) {
                bw = g;
                best = i;
            }
        }
        if (best < 0 || p == n)
            return;
        idx[p++] = best;
        added = best;
    }
}
