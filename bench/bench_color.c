/* bench_color.c - cost of the generic colour interface: nanoseconds per add, mul and brightness in each
 * model, beside inline loops over float arrays of the same (compile-time) length measured in the same
 * run: the plain loop, and the loop written on 4-float vectors. The ratio is the interface's time over
 * the faster inline form. add and mul chain their result into the next call (o = o + b), so inline code
 * may keep o in registers while the interface goes through memory; brightness reads a value in memory.
 * Prints figures; never fails on time. Targets: rgb within 3x of inline code, the 81-sample spectrum
 * within 1.5x. */
#include "generic/builtins.h"
#include "generic/color.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TARGET_SECONDS 0.2

/* The thread's CPU time: time slices other processes take on a busy machine do not count. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Tells the compiler memory may have changed and been read: results before it are kept, values after it
 * are loaded again. */
#define BARRIER() __asm__ __volatile__("" ::: "memory")

/* Measuring: CALIBRATE finds how many runs of a body take about a slice; ROUND times one slice and keeps
 * the fastest nanoseconds per run seen. The bodies of a comparison are timed in alternating slices
 * (ROUNDS each, TARGET_SECONDS per body in all), so other load on the machine hits them alike, and the
 * minimum filters it out. */
#define ROUNDS 10
#define CALIBRATE(iters, ...)                                                                                \
    do {                                                                                                     \
        iters = 64;                                                                                          \
        for (;;) {                                                                                           \
            double t0_ = now();                                                                              \
            for (long i_ = 0; i_ < iters; i_++) {                                                            \
                __VA_ARGS__;                                                                                 \
            }                                                                                                \
            BARRIER();                                                                                       \
            double t_ = now() - t0_;                                                                         \
            if (t_ > 0.005) {                                                                                \
                iters = (long)(iters * (TARGET_SECONDS / ROUNDS / t_)) + 1;                                  \
                break;                                                                                       \
            }                                                                                                \
            iters *= 4;                                                                                      \
        }                                                                                                    \
    } while (0)
#define ROUND(ns, iters, ...)                                                                                \
    do {                                                                                                     \
        double t0_ = now();                                                                                  \
        for (long i_ = 0; i_ < iters; i_++) {                                                                \
            __VA_ARGS__;                                                                                     \
        }                                                                                                    \
        BARRIER();                                                                                           \
        ns = fmin(ns, (now() - t0_) * 1e9 / iters);                                                          \
    } while (0)

/* Interface, plain and vectorised inline bodies of one comparison, into a Row. */
#define COMPARE(row, IFACE, PLAIN, VEC)                                                                      \
    do {                                                                                                     \
        long n1_, n2_, n3_;                                                                                  \
        CALIBRATE(n1_, IFACE);                                                                               \
        CALIBRATE(n2_, PLAIN);                                                                               \
        CALIBRATE(n3_, VEC);                                                                                 \
        row.iface = row.plain = row.blocked = 1e30;                                                          \
        for (int r_ = 0; r_ < ROUNDS; r_++) {                                                                \
            ROUND(row.iface, n1_, IFACE);                                                                    \
            ROUND(row.plain, n2_, PLAIN);                                                                    \
            ROUND(row.blocked, n3_, VEC);                                                                    \
        }                                                                                                    \
    } while (0)

/* The inline code an application would write for a fixed representation of N floats: the plain loops
 * (which GCC 12 leaves scalar at -O2), and the same loops on 4-float vectors, the form the spectral
 * models' kernels use (include/generic/kit/spectral_kernels.h). */
#define INLINE_OPS(N)                                                                                        \
    static inline void add_##N(float *o, const float *b)                                                     \
    {                                                                                                        \
        for (int j = 0; j < N; j++)                                                                          \
            o[j] = o[j] + b[j];                                                                              \
    }                                                                                                        \
    static inline void mul_##N(float *o, const float *b)                                                     \
    {                                                                                                        \
        for (int j = 0; j < N; j++)                                                                          \
            o[j] = o[j] * b[j];                                                                              \
    }                                                                                                        \
    static inline float bright_##N(const float *w, const float *a)                                           \
    {                                                                                                        \
        float s = 0.0f;                                                                                      \
        for (int j = 0; j < N; j++)                                                                          \
            s += w[j] * fabsf(a[j]);                                                                         \
        return s;                                                                                            \
    }                                                                                                        \
    static inline void addb_##N(float *o, const float *b)                                                    \
    {                                                                                                        \
        int i = 0;                                                                                           \
        for (; i + 4 <= N; i += 4) {                                                                         \
            v4 x, y;                                                                                         \
            memcpy(&x, o + i, sizeof x);                                                                     \
            memcpy(&y, b + i, sizeof y);                                                                     \
            x += y;                                                                                          \
            memcpy(o + i, &x, sizeof x);                                                                     \
        }                                                                                                    \
        for (; i < N; i++)                                                                                   \
            o[i] = o[i] + b[i];                                                                              \
    }                                                                                                        \
    static inline void mulb_##N(float *o, const float *b)                                                    \
    {                                                                                                        \
        int i = 0;                                                                                           \
        for (; i + 4 <= N; i += 4) {                                                                         \
            v4 x, y;                                                                                         \
            memcpy(&x, o + i, sizeof x);                                                                     \
            memcpy(&y, b + i, sizeof y);                                                                     \
            x *= y;                                                                                          \
            memcpy(o + i, &x, sizeof x);                                                                     \
        }                                                                                                    \
        for (; i < N; i++)                                                                                   \
            o[i] = o[i] * b[i];                                                                              \
    }                                                                                                        \
    static inline float brightb_##N(const float *w, const float *a)                                          \
    {                                                                                                        \
        v4 acc0 = {0, 0, 0, 0}, acc1 = {0, 0, 0, 0};                                                         \
        v4i mask = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};                                         \
        int i = 0;                                                                                           \
        for (; i + 8 <= N; i += 8) {                                                                         \
            v4 x0, x1, w0, w1;                                                                               \
            memcpy(&x0, a + i, sizeof x0);                                                                   \
            memcpy(&x1, a + i + 4, sizeof x1);                                                               \
            memcpy(&w0, w + i, sizeof w0);                                                                   \
            memcpy(&w1, w + i + 4, sizeof w1);                                                               \
            acc0 += w0 * (v4)((v4i)x0 & mask);                                                               \
            acc1 += w1 * (v4)((v4i)x1 & mask);                                                               \
        }                                                                                                    \
        acc0 += acc1;                                                                                        \
        float s = (acc0[0] + acc0[1]) + (acc0[2] + acc0[3]);                                                 \
        for (; i < N; i++)                                                                                   \
            s += w[i] * fabsf(a[i]);                                                                         \
        return s;                                                                                            \
    }

/* A matrix (N x N, row by row) times a vector, plain and on 4-float vectors. */
#define MATVEC_OPS(N)                                                                                        \
    static inline void matvec_##N(float *o, const float *m, const float *v)                                  \
    {                                                                                                        \
        for (int r = 0; r < N; r++) {                                                                        \
            float s = 0.0f;                                                                                  \
            for (int j = 0; j < N; j++)                                                                      \
                s += m[r * N + j] * v[j];                                                                    \
            o[r] = s;                                                                                        \
        }                                                                                                    \
    }                                                                                                        \
    static inline void matvecb_##N(float *o, const float *m, const float *v)                                 \
    {                                                                                                        \
        for (int r = 0; r < N; r++) {                                                                        \
            v4 acc0 = {0, 0, 0, 0}, acc1 = {0, 0, 0, 0};                                                     \
            const float *row = m + r * N;                                                                    \
            int i = 0;                                                                                       \
            for (; i + 8 <= N; i += 8) {                                                                     \
                v4 x0, x1, y0, y1;                                                                           \
                memcpy(&x0, row + i, sizeof x0);                                                             \
                memcpy(&x1, row + i + 4, sizeof x1);                                                         \
                memcpy(&y0, v + i, sizeof y0);                                                               \
                memcpy(&y1, v + i + 4, sizeof y1);                                                           \
                acc0 += x0 * y0;                                                                             \
                acc1 += x1 * y1;                                                                             \
            }                                                                                                \
            acc0 += acc1;                                                                                    \
            float s = (acc0[0] + acc0[1]) + (acc0[2] + acc0[3]);                                             \
            for (; i < N; i++)                                                                               \
                s += row[i] * v[i];                                                                          \
            o[r] = s;                                                                                        \
        }                                                                                                    \
    }

typedef float v4 __attribute__((vector_size(16)));
typedef int v4i __attribute__((vector_size(16)));

INLINE_OPS(3)
INLINE_OPS(9)
INLINE_OPS(81)
INLINE_OPS(41)
MATVEC_OPS(41)

static double sink;

typedef struct Row {
    double iface, plain, blocked;
} Row;

/* Interface time over the faster of the two inline forms. */
static double ratio(Row r) { return r.iface / fmin(r.plain, r.blocked); }

static void print_row(const char *model, const char *op, Row r)
{
    printf("%-22s %-14s %9.2f ns %9.2f ns %9.2f ns %7.2fx\n", model, op, r.iface, r.plain, r.blocked, ratio(r));
}

/* Interface and inline figures for one vector model of N samples. */
#define BENCH_VECTOR(N, NAME, OPTS, LABEL, OUT)                                                              \
    do {                                                                                                     \
        GColorModel *m;                                                                                      \
        GError err;                                                                                          \
        if (gcolormodel_create(NAME, OPTS, &m, &err) != G_OK || m->nvalues != N) {                           \
            fprintf(stderr, "%s: %s\n", NAME, err.message);                                                  \
            exit(1);                                                                                         \
        }                                                                                                    \
        static float ov[128 * 128], bv[128 * 128], io[N], ib[N], iw[N];                                      \
        GColor o, b;                                                                                         \
        if (gcolor_wrap(&o, m, ov, sizeof ov / sizeof ov[0]) != G_OK ||                                      \
            gcolor_wrap(&b, m, bv, sizeof bv / sizeof bv[0]) != G_OK)                                        \
            exit(1);                                                                                         \
        double lrgb[3] = {0.5, 0.6, 0.7};                                                                    \
        gcolor_from_rgb(&o, lrgb, GCOLOR_LIGHT);                                                             \
        for (int j = 0; j < N; j++) {                                                                        \
            bv[j] = 1.0f; /* mul by 1 and add of small values keep the numbers normal */                     \
            io[j] = ov[j];                                                                                   \
            ib[j] = 1.0f;                                                                                    \
            iw[j] = 1.0f / N;                                                                                \
        }                                                                                                    \
        COMPARE(OUT[0], gcolor_mul(&o, &o, &b), mul_##N(io, ib), mulb_##N(io, ib));                          \
        for (int j = 0; j < N; j++)                                                                          \
            bv[j] = ib[j] = 1e-7f;                                                                           \
        COMPARE(OUT[1], gcolor_add(&o, &o, &b), add_##N(io, ib), addb_##N(io, ib));                          \
        COMPARE(OUT[2], sink += gcolor_brightness(&o), sink += bright_##N(iw, io); BARRIER(),                \
                sink += brightb_##N(iw, io); BARRIER());                                                     \
        print_row(LABEL, "add", OUT[1]);                                                                     \
        print_row(LABEL, "mul", OUT[0]);                                                                     \
        print_row(LABEL, "brightness", OUT[2]);                                                              \
        gcolormodel_destroy(m);                                                                              \
    } while (0)

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    Row rgb[3], s9[3], s81[3], b41[3], mv;
    GColorModelOptions five = {5, 0, 0, 0}, ten = {10, 0, 0, 0};
    printf("%-22s %-14s %12s %12s %12s %8s\n", "model", "operation", "interface", "plain loop", "vectorised", "ratio");
    BENCH_VECTOR(3, "rgb", NULL, "rgb", rgb);
    {
        /* for scale: rgb as an application holding three floats in locals (registers), not in an array */
        static volatile float init[3] = {1e-7f, 2e-7f, 3e-7f};
        float r0 = 0.5f, r1 = 0.6f, r2 = 0.7f, b0 = init[0], b1 = init[1], b2 = init[2];
        long n_;
        double reg = 1e30;
        CALIBRATE(n_, r0 += b0, r1 += b1, r2 += b2);
        for (int r_ = 0; r_ < ROUNDS; r_++)
            ROUND(reg, n_, r0 += b0, r1 += b1, r2 += b2);
        sink += r0 + r1 + r2;
        printf("%-22s %-14s %12s %9.2f ns %12s %7.2fx  (not part of the target)\n", "rgb", "add, 3 locals", "",
               reg, "", rgb[1].iface / reg);
    }
    BENCH_VECTOR(9, "spectrum9", NULL, "spectrum9", s9);
    BENCH_VECTOR(81, "spectrum", &five, "spectrum 5 nm (81)", s81);
    BENCH_VECTOR(41, "bispectral", &ten, "bispectral vector (41)", b41);

    /* bispectral: a re-radiation matrix applied to a light */
    {
        GColorModel *m;
        GError err;
        if (gcolormodel_create("bispectral", &ten, &m, &err) != G_OK)
            return 1;
        int n = m->nsamples;
        static float data[41 * 41], mv_[41 * 41], lv[41 * 41], ov[41 * 41], im[41 * 41], il[41], io[41];
        for (int r = 0; r < n; r++)
            for (int i = 0; i < n; i++)
                data[r * n + i] = r == i ? 0.8f : (r > i ? 0.01f : 0.0f);
        GReradiation rr = {m->lambda_min, m->lambda_step, n, m->lambda_min, m->lambda_step, n, data};
        GColor mat, light, out;
        if (gcolor_wrap(&mat, m, mv_, sizeof mv_ / sizeof mv_[0]) != G_OK ||
            gcolor_wrap(&light, m, lv, sizeof lv / sizeof lv[0]) != G_OK ||
            gcolor_wrap(&out, m, ov, sizeof ov / sizeof ov[0]) != G_OK)
            return 1;
        gcolor_from_reradiation(&mat, &rr, &err);
        double lrgb[3] = {0.5, 0.6, 0.7};
        gcolor_from_rgb(&light, lrgb, GCOLOR_LIGHT);
        memcpy(im, mv_, sizeof im);
        memcpy(il, lv, sizeof il);
        COMPARE(mv, gcolor_mul(&out, &mat, &light), matvec_41(io, im, il); BARRIER(),
                matvecb_41(io, im, il); BARRIER());
        sink += ov[3] + io[3];
        print_row("bispectral 41x41", "matrix*vector", mv);
        gcolormodel_destroy(m);
    }
    double worst_rgb = fmax(ratio(rgb[0]), fmax(ratio(rgb[1]), ratio(rgb[2])));
    double worst_s81 = fmax(ratio(s81[0]), fmax(ratio(s81[1]), ratio(s81[2])));
    printf("rgb: worst ratio %.2fx (target 3x: %s); spectrum 81: worst ratio %.2fx (target 1.5x: %s)\n", worst_rgb,
           worst_rgb <= 3.0 ? "met" : "missed", worst_s81, worst_s81 <= 1.5 ? "met" : "missed");
    printf("(checksum %g)\n", sink);
    return 0;
}
