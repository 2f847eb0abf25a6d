/* masked.c - the 8-float spectral kernels with the last n % 8 samples as one masked operation (kernel_tails.h). */
#define GSPECTRAL_TAIL_MODE GSPECTRAL_TAIL_MASKED
#define TAIL_KERNELS tail_kernels_masked
#include "kernel_tails.h"
