/* kernel_tails_ops.h - the element-wise kernels of spectral_kernels8.h as bench_kernel_tails times them, one
 * function each as the library's operations are (taking the common grids' lengths as constants, called through a
 * pointer), under the name TAIL_OPS (a KernelTailOps table). Included by one file per way of doing the last n % 8
 * samples, which defines GSPECTRAL_TAIL_MODE first (spectral_kernels8.h). */
#ifndef BENCH_KERNEL_TAILS_OPS_H
#define BENCH_KERNEL_TAILS_OPS_H

/** The operations timed, each in place on x (o = x): x = x + b, x * b, x * s, x / b, (x * b) * s, x + b * s (s a
 * float and a double), x = s, and y = x (copy, y apart). */
enum { TAIL_ADD, TAIL_MUL, TAIL_SCALE, TAIL_DIV, TAIL_MUL_SCALED, TAIL_AXPY, TAIL_AXPYD, TAIL_FILL, TAIL_COPY,
       TAIL_NOPS };

/** One operation on n samples: x its operand and result, b the other operand, y the copy's destination. */
typedef void (*KernelTailOp)(float *x, float *y, const float *b, int n);

/** The operations of one policy, by the enum above. */
typedef struct KernelTailOps {
    const char *policy;
    KernelTailOp op[TAIL_NOPS];
} KernelTailOps;

extern const KernelTailOps kernel_tails_scalar, kernel_tails_pieces, kernel_tails_masked;
#endif

#ifdef TAIL_OPS
#include "generic/kit/spectral_kernels.h"

#ifdef GSPECTRAL_AVX2
/* scales that keep every result what it was (no overflow, no denormal over any number of rounds); the double is
 * not a float, so that axpyd takes its double products */
#define TAIL_S 1.0f
#define TAIL_SD 0.0000000001

#define TAIL_FN(name, CALL)                                                                                    \
    __attribute__((noinline)) static GSPECTRAL_TARGET_AVX2 void name(float *x, float *y, const float *b, int n) \
    {                                                                                                          \
        (void)x, (void)y, (void)b;                                                                             \
        GSPECTRAL_ON_COMMON_LENGTH(n, CALL);                                                                   \
    }
#define ADD(len) gspectral_kmap8(GSPECTRAL_ADD, x, x, b, len)
#define MUL(len) gspectral_kmap8(GSPECTRAL_MUL, x, x, b, len)
#define SCALE(len) gspectral_kscale8(x, x, TAIL_S, len)
#define DIV(len) gspectral_kdiv8(x, x, b, len)
#define MUL_SCALED(len) gspectral_kmul_scaled8(x, x, b, TAIL_S, len)
#define AXPY(len) gspectral_kaxpyd8(x, 0.0, b, x, len)
#define AXPYD(len) gspectral_kaxpyd8(x, TAIL_SD, b, x, len)
#define FILL(len) gspectral_kfill8(x, 1.0f, len)
#define COPY(len) gspectral_kcopy8(y, x, len)
TAIL_FN(op_add, ADD)
TAIL_FN(op_mul, MUL)
TAIL_FN(op_scale, SCALE)
TAIL_FN(op_div, DIV)
TAIL_FN(op_mul_scaled, MUL_SCALED)
TAIL_FN(op_axpy, AXPY)
TAIL_FN(op_axpyd, AXPYD)
TAIL_FN(op_fill, FILL)
TAIL_FN(op_copy, COPY)

const KernelTailOps TAIL_OPS = {GSPECTRAL_TAIL_MODE == GSPECTRAL_TAIL_MASKED   ? "masked"
                                : GSPECTRAL_TAIL_MODE == GSPECTRAL_TAIL_PIECES ? "pieces"
                                                                               : "scalar",
                                {op_add, op_mul, op_scale, op_div, op_mul_scaled, op_axpy, op_axpyd, op_fill,
                                 op_copy}};
#else
const KernelTailOps TAIL_OPS = {"none", {0}};
#endif
#endif
