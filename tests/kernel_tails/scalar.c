/* scalar.c - the 8-float spectral kernels with the last n % 8 samples one by one (kernel_tails.h). */
#define GSPECTRAL_TAIL_MODE GSPECTRAL_TAIL_SCALAR
#define TAIL_KERNELS tail_kernels_scalar
#include "kernel_tails.h"
