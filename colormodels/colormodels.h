/* colormodels.h - the built-in colour model classes (one .c file each in colormodels/). */
#ifndef GENERIC_COLORMODELS_H
#define GENERIC_COLORMODELS_H

#include "generic/color.h"

/** Linear sRGB. */
extern const GColorModelClass gcolormodel_rgb;
/** Nine samples 380..780 nm every 50 nm, natural cubic spline to nm. */
extern const GColorModelClass gcolormodel_spectrum9;
/** nm-sampled spectrum, step set at run time (default 5 nm). */
extern const GColorModelClass gcolormodel_spectrum;
/** Spectra and re-radiation matrices (default 380..780 nm at 10 nm). */
extern const GColorModelClass gcolormodel_bispectral;

#endif
