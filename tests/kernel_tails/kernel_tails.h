/* kernel_tails.h - the 8-float spectral kernels compiled with each way of doing the last n % 8 samples
 * (spectral_kernels8.h's GSPECTRAL_TAIL_MODE), for test_spectrum_fast: the library uses one, the others stay
 * selectable and must give the same results. Included by one file per way, which defines GSPECTRAL_TAIL_MODE and
 * TAIL_KERNELS (the table's name) first; included without them, it declares the tables. */
#ifndef TESTS_KERNEL_TAILS_H
#define TESTS_KERNEL_TAILS_H

/** One element-wise operation (test_spectrum_fast's ADD .. MUL_SCALED) on n samples, o = a op b. */
typedef void (*TailElemFn)(int op, float *o, const float *a, const float *b, double s, int n);

/** The sums whose last samples the way changes: brightness (weights b of |a|) and colour matching (table t). */
typedef void (*TailSumsFn)(const float *a, const float *b, const float *t, int n, double *bright, double xyz[3]);

/** One way's kernels; elem is NULL where there are no 8-float kernels or the processor lacks AVX2. */
typedef struct TailKernels {
    const char *name;
    TailElemFn elem;
    TailSumsFn sums;
} TailKernels;

/** The kernels with the last samples one by one, and as one masked 8-lane operation. */
TailKernels tail_kernels_scalar(void), tail_kernels_masked(void);
#endif

#ifdef TAIL_KERNELS
#include <stddef.h>

#include "generic/kit/spectral_kernels.h"

#ifdef GSPECTRAL_AVX2
static GSPECTRAL_TARGET_AVX2 void elem(int op, float *o, const float *a, const float *b, double s, int n)
{
    switch (op) {
    case 0: gspectral_kmap8(GSPECTRAL_ADD, o, a, b, n); break;
    case 1: gspectral_kmap8(GSPECTRAL_MUL, o, a, b, n); break;
    case 2: gspectral_kscale8(o, a, (float)s, n); break;
    case 3: gspectral_kdiv8(o, a, b, n); break;
    case 4: gspectral_kfill8(o, (float)s, n); break;
    case 6: gspectral_kcopy8(o, a, n); break;
    case 7: gspectral_kmul_scaled8(o, a, b, (float)s, n); break;
    default: gspectral_kaxpyd8(o, s, a, b, n); break;
    }
}

static GSPECTRAL_TARGET_AVX2 void sums(const float *a, const float *b, const float *t, int n, double *bright,
                                       double xyz[3])
{
    *bright = gspectral_kbright8(b, a, n);
    gspectral_kxyz8(t, a, n, xyz);
}
#endif

TailKernels TAIL_KERNELS(void)
{
    TailKernels k = {GSPECTRAL_TAIL_MODE == GSPECTRAL_TAIL_MASKED ? "masked tails" : "scalar tails", NULL, NULL};
#ifdef GSPECTRAL_AVX2
    if (gspectral_have_avx2()) {
        k.elem = elem;
        k.sums = sums;
    }
#endif
    return k;
}
#endif
