/* kernel_tails_scalar.c - bench_kernel_tails' kernels with the last samples done one at a time. */
#define GSPECTRAL_TAIL_MODE GSPECTRAL_TAIL_SCALAR
#define TAIL_OPS kernel_tails_scalar
#include "kernel_tails_ops.h"
