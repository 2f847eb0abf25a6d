/* optimize.c - irradiance optimisation (Madsen, Sorensen & Vittrup 2003; the paper's sec. 4.4).
 *
 * Model: N lights, each with a direction omega_i (two angles) and an RGB colour L_i >= 0, give at normal n_k
 *     E'_c(n_k) = sum_i L_ic max(0, omega_i . n_k)                          (the paper's Eq. 5)
 * and are fitted to the ground truth E_c(n_k) at M_f Fibonacci normals (2000 by default) by minimising
 *     F = sum_k,c ( w_k s_c (E'_c(n_k) - E_c(n_k)) )^2,
 * with s_c = 1 / (mean of E_c over the normals) and w_k = 1 / max(mean_c s_c E_c(n_k), 1e-3): squared
 * relative errors, the measure the evaluation reports, with a weight that is the same for every channel
 * (after the channel scaling) so that one Gram matrix serves all three channels.
 *
 * Method (variable projection with non-negativity):
 *   - the colours enter linearly, so for given directions the best colours are a non-negative least-squares
 *     problem per channel, solved exactly (Lawson-Hanson on the normal equations, warm-started from the
 *     previous colours); the colours are never a free LM parameter and can never go negative;
 *   - the 2N direction parameters move by Levenberg-Marquardt steps (Marquardt's diagonal scaling, Nielsen's
 *     damping update) with the analytic Jacobian: the derivative of max(0, omega . n) along two tangent
 *     directions of omega. Directions are updated on the sphere by the exponential map (no pole singularity)
 *     and no light turns more than 0.5 rad per step;
 *   - the Gauss-Newton matrix is Kaufman's for the projected problem: J_d^T J_d minus, per channel, the part
 *     the re-solved colours absorb (the Schur complement over the channel's non-zero colours, see schur()).
 *     This turned ~400 slow alternating iterations into ~30-120;
 *   - a step is accepted only when F, with the colours re-solved at the new directions, goes down: F never
 *     increases, so the result is never worse than the start. At optimal colours J^T r is the gradient of the
 *     projected F (Danskin), so a damped step always exists that lowers F until a stationary point. The run
 *     stops when no step up to lambda = 1e12 lowers F, the gradient vanishes, or four accepted steps in a row
 *     gain less than 1e-5 of F ("converged"), else at the iteration limit (400 by default);
 *   - the paper lost convergence above 64 sources, which it blamed on sources finding too little energy to
 *     latch on to. Here a source never has to find energy: its colour is whatever the projection gives, and
 *     the damping only accepts improvements. A source whose colours all reach 0 has a zero Jacobian and
 *     would stay unused (it happens at N = 64..128 on several real probes), so after convergence each such
 *     source is moved to the fit normal where the model falls furthest short of the truth and the fit runs
 *     again (up to three rounds), kept only when F went down (revive()).
 * The fit uses its own M_f normals (2000: 6000 residuals for at most 5 x 128 = 640 parameters); callers
 * evaluate the lights at as many normals as they like (gprobe eval: 20000).
 * Start: adaptive median cut with N lights (its directions and colours). End: IRLS_ROUNDS rounds of
 * iteratively reweighted least squares towards the mean absolute relative error, the best round kept. */
#include "probe_internal.h"
#include "generic/memory.h"

/** Reweighting rounds towards the mean absolute relative error (see the end of gprobe_irradiance_fit). */
#define IRLS_ROUNDS 4

#include <math.h>
#include <string.h>

typedef struct Fit {
    int n, m;
    const GVec3 *nrm;
    const double *E; /* truth, 3 per normal */
    double *w;       /* per normal */
    double *wE;      /* column-major m x 3: w_k E_kc */
    double s[3];     /* per channel */
    double *A;       /* column-major m x n: A[i * m + k] = w_k max(0, omega_i . n_k) (weighted) */
    double *G, *h;   /* Gram n x n; h: 3 x n (per channel) */
    double *hbuf;    /* n x 3 */
    double *nnls_work;
    double *Gt;      /* column-major m x 2n: w_k [visible] (t_ia . n_k) */
    double *JJ, *g, *sys, *delta; /* 2n x 2n, 2n, 2n x 2n, 2n */
    double *res;     /* 3 per normal: s_c w_k (E' - E) */
    double *H;       /* 2n x n: Gt^T A (direction-colour coupling) */
    double *chol, *Y; /* n x n, n x 2n: scratch for the Schur complement */
    int *act;        /* n */
} Fit;

static void dots(const Fit *f, const GVec3 *dir, double *A)
{
    #pragma omp parallel for schedule(static) if (f->n * (long)f->m > 400000)
    for (int i = 0; i < f->n; i++) {
        double *col = A + (size_t)i * f->m;
        const GVec3 d = dir[i];
        for (int k = 0; k < f->m; k++) {
            double v = d.x * f->nrm[k].x + d.y * f->nrm[k].y + d.z * f->nrm[k].z;
            col[k] = v > 0.0 ? f->w[k] * v : 0.0;
        }
    }
}

/* F and the weighted residuals for colours L (3 per light) with the weighted dot products A. F is summed in
 * OBJECTIVE_BLOCKS fixed blocks of normals added in order, so it does not depend on the number of threads
 * or their timing: the fit's accept/reject decisions, and so its result, are the same on every run. */
#define OBJECTIVE_BLOCKS 64
static double objective(const Fit *f, const double *A, const double *L, double *res)
{
    double part[OBJECTIVE_BLOCKS] = {0};
    #pragma omp parallel for schedule(static) if (f->n * (long)f->m > 400000)
    for (int b = 0; b < OBJECTIVE_BLOCKS; b++) {
        const int k0 = (int)((long)f->m * b / OBJECTIVE_BLOCKS), k1 = (int)((long)f->m * (b + 1) / OBJECTIVE_BLOCKS);
        double F = 0.0;
        for (int k = k0; k < k1; k++) {
            double e[3] = {0, 0, 0};
            for (int i = 0; i < f->n; i++) {
                double a = A[(size_t)i * f->m + k];
                if (a > 0.0)
                    for (int c = 0; c < 3; c++)
                        e[c] += a * L[i * 3 + c];
            }
            for (int c = 0; c < 3; c++) {
                double r = f->s[c] * (e[c] - f->wE[(size_t)c * f->m + k]);
                if (res)
                    res[k * 3 + c] = r;
                F += r * r;
            }
        }
        part[b] = F;
    }
    double F = 0.0;
    for (int b = 0; b < OBJECTIVE_BLOCKS; b++)
        F += part[b];
    return F;
}

/* Colours for the directions behind A: the Gram matrix A^T A and right-hand sides A^T (w E_c) (the s_c^2
 * cancel), then non-negative least squares per channel, warm-started from L. */
static void solve_colours(Fit *f, const double *A, double *L)
{
    const int n = f->n;
    probe_gemm_tn(A, n, A, n, f->m, f->G, n, 1);
    probe_gemm_tn(A, n, f->wE, 3, f->m, f->hbuf, 3, 0);
    double *x = f->delta; /* n doubles of scratch (delta has 2n) */
    for (int c = 0; c < 3; c++) {
        for (int i = 0; i < n; i++) {
            f->h[c * n + i] = f->hbuf[i * 3 + c];
            x[i] = L[i * 3 + c];
        }
        probe_nnls(n, f->G, f->h + (size_t)c * n, x, f->nnls_work);
        for (int i = 0; i < n; i++)
            L[i * 3 + c] = x[i];
    }
}

static void tangents(GVec3 d, GVec3 *t1, GVec3 *t2)
{
    GVec3 a = fabs(d.x) < 0.6 ? gvec3(1, 0, 0) : fabs(d.y) < 0.6 ? gvec3(0, 1, 0) : gvec3(0, 0, 1);
    *t1 = gvec3_normalize(gvec3_cross(d, a));
    *t2 = gvec3_cross(d, *t1);
}

/* Variable projection (Kaufman): the colours are re-solved after every step, so the directions see the
 * Schur complement J_d^T J_d - sum_c J_d^T J_c (J_c^T J_c)^-1 J_c^T J_d over each channel's active colours
 * instead of J_d^T J_d; the gradient is unchanged because J_c^T r = 0 at the non-negative optimum.
 * With J_d[(k,c),(i,a)] = s_c L_ic Gt[k,(i,a)] and J_c[(k,c),j] = s_c A_kj: J_d^T J_c = s_c^2 L_ic H and
 * J_c^T J_c = s_c^2 G. */
static void schur(Fit *f, const double *A, const double *L)
{
    const int n = f->n, p = 2 * n;
    probe_gemm_tn(f->Gt, p, A, n, f->m, f->H, n, 0);
    for (int c = 0; c < 3; c++) {
        int q = 0;
        for (int j = 0; j < n; j++)
            if (L[j * 3 + c] > 0.0)
                f->act[q++] = j;
        if (q == 0)
            continue;
        double dmax = 0.0;
        for (int a = 0; a < q; a++)
            dmax = fmax(dmax, f->G[f->act[a] * n + f->act[a]]);
        for (int a = 0; a < q; a++) {
            for (int b = 0; b <= a; b++)
                f->chol[a * q + b] = f->G[f->act[a] * n + f->act[b]];
            f->chol[a * q + a] += 1e-12 * dmax;
        }
        if (probe_cholesky(f->chol, q) != 0)
            continue; /* degenerate: keep the plain Gauss-Newton matrix for this channel */
        /* with G_PP = C C^T: J_d^T J_c G_PP^-1 J_c^T J_d / s_c^2 = Z^T Z, Z = C^-1 (L_ic H_P)^T (q x 2n) */
        double *Z = f->Y;
        #pragma omp parallel for schedule(static) if (p * (long)q * q > 4000000)
        for (int x = 0; x < p; x++) {
            double *z = Z + (size_t)x * q;
            const double lx = L[(x / 2) * 3 + c];
            for (int a = 0; a < q; a++) {
                double v = lx * f->H[(size_t)x * n + f->act[a]];
                const double *row = f->chol + (size_t)a * q;
                for (int b = 0; b < a; b++)
                    v -= row[b] * z[b];
                z[a] = v / row[a];
            }
        }
        probe_gemm_tn(Z, p, Z, p, q, f->sys, p, 1);
        const double s2 = f->s[c] * f->s[c];
        for (int x = 0; x < p * p; x++)
            f->JJ[x] -= s2 * f->sys[x];
    }
}

/* The reduced Gauss-Newton matrix (in JJ) and gradient J^T r (in g) for the 2n direction parameters. */
static void jacobian(Fit *f, const GVec3 *dir, const double *A, const double *L)
{
    const int n = f->n, m = f->m, p = 2 * n;
    #pragma omp parallel for schedule(static) if (n * (long)m > 400000)
    for (int i = 0; i < n; i++) {
        GVec3 t1, t2;
        tangents(dir[i], &t1, &t2);
        double *c1 = f->Gt + (size_t)(2 * i) * m, *c2 = c1 + m;
        const double *a = A + (size_t)i * m;
        double g1 = 0.0, g2 = 0.0;
        const double w[3] = {f->s[0] * L[i * 3], f->s[1] * L[i * 3 + 1], f->s[2] * L[i * 3 + 2]};
        for (int k = 0; k < m; k++) {
            if (a[k] > 0.0) {
                c1[k] = f->w[k] * gvec3_dot(t1, f->nrm[k]);
                c2[k] = f->w[k] * gvec3_dot(t2, f->nrm[k]);
                double r = w[0] * f->res[k * 3] + w[1] * f->res[k * 3 + 1] + w[2] * f->res[k * 3 + 2];
                g1 += c1[k] * r;
                g2 += c2[k] * r;
            } else {
                c1[k] = c2[k] = 0.0;
            }
        }
        f->g[2 * i] = g1;
        f->g[2 * i + 1] = g2;
    }
    /* J_d^T J_d = (sum_c s_c^2 L_ic L_jc) (Gt^T Gt) */
    probe_gemm_tn(f->Gt, p, f->Gt, p, m, f->JJ, p, 1);
    for (int x = 0; x < p; x++)
        for (int y = 0; y <= x; y++) {
            const int i = x / 2, j = y / 2;
            double ll = 0.0;
            for (int c = 0; c < 3; c++)
                ll += f->s[c] * f->s[c] * L[i * 3 + c] * L[j * 3 + c];
            f->JJ[x * p + y] *= ll;
            if (y != x)
                f->JJ[y * p + x] *= ll;
        }
    schur(f, A, L);
}

static GVec3 rotate_dir(GVec3 d, double a, double b)
{
    GVec3 t1, t2;
    tangents(d, &t1, &t2);
    GVec3 v = gvec3_add(gvec3_scale(t1, a), gvec3_scale(t2, b));
    double th = gvec3_length(v);
    if (th < 1e-300)
        return d;
    return gvec3_normalize(gvec3_add(gvec3_scale(d, cos(th)), gvec3_scale(v, sin(th) / th)));
}

/* Levenberg-Marquardt on the directions with the colours projected out. dir, L, A and *F are updated.
 * Returns 1 when it stopped by its convergence test, 0 at the iteration limit. */
static int levenberg_marquardt(Fit *f, GVec3 *dir, double *L, double *F, int max_it, GVec3 *tdir, double *tL,
                               double *tA, const GProbeOptions *opt, GProbeFitReport *rep)
{
    const int n = f->n, p = 2 * n;
    double lambda = 1e-3, nu = 2.0;
    int small = 0, it, converged = 0;
    *F = objective(f, f->A, L, f->res);
    for (it = 0; it < max_it; it++) {
        if (!(*F > 0.0)) {
            converged = 1;
            break;
        }
        if (rep)
            rep->iterations++;
        jacobian(f, dir, f->A, L);
        double dmax = 0.0, gmax = 0.0;
        for (int x = 0; x < p; x++) {
            dmax = fmax(dmax, f->JJ[x * p + x]);
            gmax = fmax(gmax, fabs(f->g[x]));
        }
        if (!(dmax > 0.0) || gmax <= 1e-15 * *F) {
            converged = 1;
            break;
        }
        int accepted = 0;
        while (!accepted && lambda < 1e12) {
            for (int x = 0; x < p * p; x++)
                f->sys[x] = f->JJ[x];
            for (int x = 0; x < p; x++)
                f->sys[x * p + x] += lambda * fmax(f->JJ[x * p + x], 1e-9 * dmax);
            if (probe_cholesky(f->sys, p) != 0) {
                lambda *= nu;
                nu *= 2.0;
                continue;
            }
            for (int x = 0; x < p; x++)
                f->delta[x] = -f->g[x];
            probe_cholesky_solve(f->sys, p, f->delta);
            /* no light turns by more than 0.5 radians in one step */
            double big = 0.0;
            for (int i = 0; i < n; i++)
                big = fmax(big, hypot(f->delta[2 * i], f->delta[2 * i + 1]));
            double scale = big > 0.5 ? 0.5 / big : 1.0;
            double pred = 0.0;
            for (int x = 0; x < p; x++) {
                double d = f->delta[x] * scale;
                pred += -f->g[x] * d * (2.0 - scale) + lambda * fmax(f->JJ[x * p + x], 1e-9 * dmax) * d * d;
            }
            for (int i = 0; i < n; i++)
                tdir[i] = rotate_dir(dir[i], scale * f->delta[2 * i], scale * f->delta[2 * i + 1]);
            memcpy(tL, L, sizeof(double) * 3 * n);
            dots(f, tdir, tA);
            solve_colours(f, tA, tL);
            double Fn = objective(f, tA, tL, NULL);
            if (Fn < *F) {
                double rho = pred > 0.0 ? (*F - Fn) / pred : 1.0;
                double t = 2.0 * rho - 1.0;
                lambda *= fmax(1.0 / 3.0, 1.0 - t * t * t);
                nu = 2.0;
                small = (*F - Fn) < 1e-5 * *F ? small + 1 : 0;
                memcpy(dir, tdir, sizeof(GVec3) * n);
                memcpy(L, tL, sizeof(double) * 3 * n);
                memcpy(f->A, tA, sizeof(double) * (size_t)n * f->m);
                *F = objective(f, f->A, L, f->res);
                accepted = 1;
                if (rep)
                    rep->accepted++;
            } else {
                lambda *= nu;
                nu *= 2.0;
            }
        }
        probe_progress(opt, "irradiance", (it + 1.0) / max_it);
        if (!accepted || small >= 4) { /* no step lowers F any more, or it has stopped moving */
            converged = 1;
            break;
        }
    }
    return converged;
}

/* Moves every light without colour to the fit normal where the model falls furthest short of the truth
 * (the largest weighted under-estimate in f->res), damping the shortfall around it so that the next one
 * goes elsewhere. f->res is overwritten. Returns the number of lights moved. */
static int revive(Fit *f, GVec3 *dir, const double *L)
{
    int moved = 0;
    for (int i = 0; i < f->n; i++) {
        if (L[i * 3] > 0.0 || L[i * 3 + 1] > 0.0 || L[i * 3 + 2] > 0.0)
            continue;
        int best = -1;
        double bv = 0.0;
        for (int k = 0; k < f->m; k++) {
            double r = -(f->res[k * 3] + f->res[k * 3 + 1] + f->res[k * 3 + 2]); /* > 0: the model is too dark */
            if (r > bv) {
                bv = r;
                best = k;
            }
        }
        if (best < 0)
            break;
        dir[i] = f->nrm[best];
        moved++;
        for (int k = 0; k < f->m; k++) {
            double d = gvec3_dot(f->nrm[k], f->nrm[best]);
            if (d > 0.0)
                for (int c = 0; c < 3; c++)
                    f->res[k * 3 + c] *= 1.0 - d * d;
        }
    }
    return moved;
}

/* The paper's measure at the fit normals, as gprobe_compare reports it (percent), for directions dir and colours
 * L; `tmp` holds n lights and `approx` 3 m doubles. */
static double mean_rel_error(const Fit *f, const GVec3 *dir, const double *L, GProbeLight *tmp, double *approx)
{
    for (int i = 0; i < f->n; i++) {
        tmp[i].dir = dir[i];
        for (int c = 0; c < 3; c++)
            tmp[i].rgb[c] = L[i * 3 + c];
    }
    gprobe_lights_irradiance(tmp, f->n, f->nrm, f->m, approx);
    GProbeErrors e;
    gprobe_compare(f->E, approx, f->m, &e);
    return e.mean_rel;
}

/* Sets the per-normal weights w_k = base_k * mult_k and the weighted truth wE. */
static void set_weights(Fit *f, const double *base, const double *mult)
{
    for (int k = 0; k < f->m; k++) {
        f->w[k] = base[k] * (mult ? mult[k] : 1.0);
        for (int c = 0; c < 3; c++)
            f->wE[(size_t)c * f->m + k] = f->w[k] * f->E[k * 3 + c];
    }
}

int gprobe_irradiance_fit(const GProbe *p, int n, const GProbeOptions *opt, GProbeLight *lights,
                          GProbeFitReport *report, GError *err)
{
    if (n < 1 || !lights)
        return gerror_set(err, G_ERR_INVALID, "irradiance optimisation needs at least one light, not %d", n);
    const int m = opt && opt->fit_normals > 0 ? opt->fit_normals : 2000;
    const int max_it = opt && opt->max_iterations > 0 ? opt->max_iterations : 400;
    if (n > GPROBE_FIT_MAX_LIGHTS)
        return gerror_set(err, G_ERR_INVALID, "irradiance optimisation of %d lights: the limit is %d lights (its time "
                          "grows with the cube of the count); mediancut, adaptive and kmeans make more", n,
                          GPROBE_FIT_MAX_LIGHTS);
    if (m < 2 * n)
        return gerror_set(err, G_ERR_INVALID,
                          "irradiance optimisation of %d lights needs at least %d fit normals, not %d", n, 2 * n, m);
    if ((long)n * m > GPROBE_FIT_MAX_PAIRS)
        return gerror_set(err, G_ERR_INVALID, "irradiance optimisation of %d lights on %d fit normals: %ld pairs, more "
                          "than the limit of %d", n, m, (long)n * m, GPROBE_FIT_MAX_PAIRS);
    GProbeFitReport rep;
    memset(&rep, 0, sizeof rep);
    Fit f;
    memset(&f, 0, sizeof f);
    f.n = n;
    f.m = m;
    const size_t P = 2 * (size_t)n;
    size_t doubles = 3 * (size_t)m + m + 2 * (size_t)n * m + (size_t)n * n + 3 * (size_t)n + probe_nnls_work_size(n) +
                     P * m + P * P * 2 + 2 * P + 3 * (size_t)m + 6 * (size_t)n + P * n + (size_t)n * n +
                     (size_t)n * P + n + 3 * (size_t)m + 3 * (size_t)n + 3 * (size_t)n;
    double *mem = gmem_calloc(doubles, sizeof(double));
    GVec3 *vecs = gmem_calloc((size_t)m + 3 * (size_t)n, sizeof(GVec3));
    if (!mem || !vecs) {
        gmem_free(mem);
        gmem_free(vecs);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the irradiance optimisation of %d lights", n);
    }
    double *E = mem, *cur = E + 3 * (size_t)m;
    f.w = cur; cur += m;
    f.wE = cur; cur += 3 * (size_t)m;
    f.hbuf = cur; cur += 3 * (size_t)n;
    f.A = cur; cur += (size_t)n * m;
    double *tA = cur; cur += (size_t)n * m;
    f.G = cur; cur += (size_t)n * n;
    f.h = cur; cur += 3 * (size_t)n;
    f.nnls_work = cur; cur += probe_nnls_work_size(n);
    f.Gt = cur; cur += P * m;
    f.JJ = cur; cur += P * P;
    f.sys = cur; cur += P * P;
    f.g = cur; cur += P;
    f.delta = cur; cur += P;
    f.res = cur; cur += 3 * (size_t)m;
    double *L = cur, *tL = cur + 3 * (size_t)n;
    cur += 6 * (size_t)n;
    f.H = cur; cur += P * n;
    f.chol = cur; cur += (size_t)n * n;
    f.Y = cur; cur += (size_t)n * P;
    double *sL = cur;
    cur += 3 * (size_t)n;
    f.act = (int *)cur; /* n ints in the last n doubles */
    GVec3 *nrm = vecs, *dir = vecs + m, *tdir = dir + n, *sdir = tdir + n;
    f.nrm = nrm;
    f.E = E;

    gprobe_fibonacci(m, nrm);
    int rc = gprobe_irradiance(p, nrm, m, E, err);
    if (rc == G_OK)
        rc = gprobe_adaptive_median_cut(p, n, lights, err);
    if (rc != G_OK) {
        gmem_free(mem);
        gmem_free(vecs);
        return rc;
    }
    for (int c = 0; c < 3; c++) {
        double mean = 0.0;
        for (int k = 0; k < m; k++)
            mean += E[k * 3 + c];
        mean /= m;
        f.s[c] = mean > 0.0 ? 1.0 / mean : 0.0;
    }
    for (int k = 0; k < m; k++) {
        double e = (f.s[0] * E[k * 3] + f.s[1] * E[k * 3 + 1] + f.s[2] * E[k * 3 + 2]) / 3.0;
        f.w[k] = 1.0 / fmax(e, 1e-3);
    }
    set_weights(&f, f.w, NULL);
    for (int i = 0; i < n; i++) {
        dir[i] = lights[i].dir;
        for (int c = 0; c < 3; c++)
            L[i * 3 + c] = lights[i].rgb[c];
    }
    dots(&f, dir, f.A);
    rep.initial = objective(&f, f.A, L, NULL);
    solve_colours(&f, f.A, L);
    double F = objective(&f, f.A, L, NULL);
    rep.projected = F;
    probe_progress(opt, "irradiance", 0.0);

    rep.converged = levenberg_marquardt(&f, dir, L, &F, max_it, tdir, tL, tA, opt, &rep);

    /* lights that lost all colour: move them where the model is too dark and fit again while that pays */
    for (int round = 0; round < 3 && F > 0.0; round++) {
        memcpy(sdir, dir, sizeof(GVec3) * n);
        memcpy(sL, L, sizeof(double) * 3 * n);
        const double sF = F;
        int moved = revive(&f, dir, L);
        if (moved == 0)
            break;
        dots(&f, dir, f.A);
        solve_colours(&f, f.A, L);
        int conv = levenberg_marquardt(&f, dir, L, &F, max_it / 4, tdir, tL, tA, opt, &rep);
        if (!(F < sF)) { /* no better: keep what we had */
            memcpy(dir, sdir, sizeof(GVec3) * n);
            memcpy(L, sL, sizeof(double) * 3 * n);
            F = sF;
            break;
        }
        rep.converged = conv;
        rep.revived += moved;
    }

    /* The fit minimises squared relative errors; the measure reported (and the paper's) is their mean absolute
     * value. A few rounds of iteratively reweighted least squares (weights divided by the square root of each
     * normal's residual, so the squares approximate absolute values) move the fit towards that measure; the
     * round with the lowest mean absolute error at the fit normals is kept, so it never gets worse. */
    {
        double *base = gmem_alloc(sizeof(double) * 5 * (size_t)m);
        GVec3 *bdir = gmem_alloc(sizeof(GVec3) * (size_t)n);
        double *bL = gmem_alloc(sizeof(double) * 3 * (size_t)n);
        GProbeLight *tmp = gmem_alloc(sizeof(GProbeLight) * (size_t)n);
        if (base && bdir && bL && tmp) {
            double *mult = base + m, *approx = base + 2 * (size_t)m;
            memcpy(base, f.w, sizeof(double) * m);
            memcpy(bdir, dir, sizeof(GVec3) * n);
            memcpy(bL, L, sizeof(double) * 3 * n);
            double best = mean_rel_error(&f, dir, L, tmp, approx);
            for (int round = 0; round < IRLS_ROUNDS; round++) {
                /* residual of each normal at the current lights, in the base weighting */
                set_weights(&f, base, NULL);
                dots(&f, dir, f.A);
                objective(&f, f.A, L, f.res);
                double rmax = 0.0;
                for (int k = 0; k < m; k++) {
                    const double *r = f.res + 3 * (size_t)k;
                    mult[k] = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
                    rmax = fmax(rmax, mult[k]);
                }
                const double floor_r = 1e-3 * rmax + 1e-12;
                for (int k = 0; k < m; k++)
                    mult[k] = 1.0 / sqrt(fmax(mult[k], floor_r));
                set_weights(&f, base, mult);
                dots(&f, dir, f.A);
                solve_colours(&f, f.A, L);
                double G = objective(&f, f.A, L, NULL);
                levenberg_marquardt(&f, dir, L, &G, max_it / 4, tdir, tL, tA, opt, &rep);
                double e = mean_rel_error(&f, dir, L, tmp, approx);
                if (e < best) {
                    best = e;
                    memcpy(bdir, dir, sizeof(GVec3) * n);
                    memcpy(bL, L, sizeof(double) * 3 * n);
                    rep.reweighted = round + 1;
                }
            }
            memcpy(dir, bdir, sizeof(GVec3) * n);
            memcpy(L, bL, sizeof(double) * 3 * n);
            set_weights(&f, base, NULL);
            dots(&f, dir, f.A);
            F = objective(&f, f.A, L, NULL);
        }
        gmem_free(base);
        gmem_free(bdir);
        gmem_free(bL);
        gmem_free(tmp);
    }

    probe_progress(opt, "irradiance", 1.0);

    rep.final = F;
    rep.active = 0;
    for (int i = 0; i < n; i++) {
        lights[i].dir = dir[i];
        for (int c = 0; c < 3; c++)
            lights[i].rgb[c] = L[i * 3 + c];
        rep.active += L[i * 3] > 0.0 || L[i * 3 + 1] > 0.0 || L[i * 3 + 2] > 0.0;
    }
    if (report)
        *report = rep;
    gmem_free(mem);
    gmem_free(vecs);
    return G_OK;
}
