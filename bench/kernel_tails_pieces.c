/* kernel_tails_pieces.c - bench_kernel_tails' kernels with the last samples in pieces of 4, 2 and 1 floats. */
#define GSPECTRAL_TAIL_MODE GSPECTRAL_TAIL_PIECES
#define TAIL_OPS kernel_tails_pieces
#include "kernel_tails_ops.h"
