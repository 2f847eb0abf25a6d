/* spectral_uplift.h - what the spectral kit's two files share (spectral.c: grids, tables, operations;
 * spectral_uplift.c: gspectral_from_rgb, the sigmoid uplift onto a model's grid). Private to lib/color. */
#ifndef GENERIC_SPECTRAL_UPLIFT_H
#define GENERIC_SPECTRAL_UPLIFT_H

#include "generic/kit/spectral.h"

/* XYZ of the samples v from the model's double weights, summed in double: the tables' own arithmetic. */
void spectral_xyz_exact(const GSpectral *s, GColorRole role, const float *v, double xyz[3]);

#endif
