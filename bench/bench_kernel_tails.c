/* bench_kernel_tails.c - what the last n % 8 samples of the element-wise spectral kernels cost done one sample at
 * a time, in pieces of 4, 2 and 1 floats, and as one masked 8-lane operation (vmaskmovps loads and store), on this
 * processor: nanoseconds per operation of each and the ratios to the first, medians of interleaved rounds with
 * min-max, for every tail length (17 to 23 samples: 2 whole blocks and 1 to 7 more) and the common grids' 41 and
 * 81 (one more sample), then the sum over a chain of all the operations. Each operation works in place on the
 * result of the one before (what a renderer's colour arithmetic does), so the time includes a load waiting for the
 * store before it. Prints figures; never fails on time. spectral_kernels8.h's GSPECTRAL_TAIL_MODE is chosen from
 * them. */
#include "kernel_tails_ops.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "generic/kit/spectral_kernels.h"

enum { ROUNDS = 9, MAX_N = 96 };

static const char *const names[TAIL_NOPS] = {"add", "mul", "scale", "div", "mul_scaled", "axpy (float s)",
                                             "axpy (double s)", "fill", "copy"};
static const int lengths[] = {17, 18, 19, 20, 21, 22, 23, 41, 81};

/* The thread's CPU time: time slices other processes take on a busy machine do not count. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static float x[MAX_N] __attribute__((aligned(32))), y[MAX_N] __attribute__((aligned(32))),
    b[MAX_N] __attribute__((aligned(32)));

/* Runs the operations first to last (first == last: one operation) iters times; returns ns per round. */
static double run(const KernelTailOps *ops, int first, int last, int n, long iters)
{
    double t0 = now();
    for (long i = 0; i < iters; i++)
        for (int k = first; k <= last; k++)
            ops->op[k](x, y, b, n);
    return (now() - t0) * 1e9 / (double)iters;
}

static int by_value(const void *p, const void *q)
{
    double a = *(const double *)p, c = *(const double *)q;
    return (a > c) - (a < c);
}

/* Times operations first to last on n samples with the three tails in alternating slices of about 2 ms (the order
 * turning each round); prints the medians and the ratios to the scalar tail. */
static void compare(const char *what, int first, int last, int n)
{
    const KernelTailOps *ways[3] = {&kernel_tails_scalar, &kernel_tails_pieces, &kernel_tails_masked};
    long iters = 256;
    while (run(ways[0], first, last, n, iters) * (double)iters < 2e6)
        iters *= 2;
    double ns[3][ROUNDS], ratio[3][ROUNDS];
    for (int r = 0; r < ROUNDS; r++) {
        for (int k = 0; k < 3; k++) {
            int w = (k + r) % 3;
            ns[w][r] = run(ways[w], first, last, n, iters);
        }
        for (int w = 1; w < 3; w++)
            ratio[w][r] = ns[w][r] / ns[0][r];
    }
    for (int w = 0; w < 3; w++) {
        qsort(ns[w], ROUNDS, sizeof *ns[w], by_value);
        if (w)
            qsort(ratio[w], ROUNDS, sizeof *ratio[w], by_value);
    }
    printf("  %-15s n %2d (tail %d): scalar %5.2f ns, pieces %5.2f ns, ratio %.2f (%.2f-%.2f), masked %5.2f ns, "
           "ratio %.2f (%.2f-%.2f)\n",
           what, n, n % 8, ns[0][ROUNDS / 2], ns[1][ROUNDS / 2], ratio[1][ROUNDS / 2], ratio[1][0],
           ratio[1][ROUNDS - 1], ns[2][ROUNDS / 2], ratio[2][ROUNDS / 2], ratio[2][0], ratio[2][ROUNDS - 1]);
}

int main(void)
{
#ifdef GSPECTRAL_AVX2
    if (!gspectral_have_avx2()) {
        printf("bench_kernel_tails: no AVX2 on this processor, nothing to compare\n");
        return 0;
    }
    for (int i = 0; i < MAX_N; i++)
        x[i] = y[i] = b[i] = 1.0f;
    printf("bench_kernel_tails: the last n %% 8 samples one by one (scalar), in pieces of 4, 2, 1 and masked, "
           "in place, %d interleaved rounds (medians; ratios to scalar with min-max)\n", ROUNDS);
    for (size_t l = 0; l < sizeof lengths / sizeof *lengths; l++) {
        int n = lengths[l];
        for (int k = 0; k < TAIL_NOPS; k++)
            compare(names[k], k, k, n);
        compare("all in a chain", 0, TAIL_NOPS - 1, n);
    }
#else
    printf("bench_kernel_tails: no 8-float kernels in this build\n");
#endif
    return 0;
}
