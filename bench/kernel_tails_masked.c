/* kernel_tails_masked.c - bench_kernel_tails' kernels with the last samples as one masked 8-lane operation. */
#define GSPECTRAL_TAIL_MODE GSPECTRAL_TAIL_MASKED
#define TAIL_OPS kernel_tails_masked
#include "kernel_tails_ops.h"
