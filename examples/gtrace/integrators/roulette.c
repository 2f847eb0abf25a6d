/* roulette.c - Russian roulette's throughput factor (roulette.h). */
#include "roulette.h"

/* Bands roulette_factor reads at most: neighbouring bands of a model with many are close, every k-th one will do. */
#define ROULETTE_PEAK_BANDS 16

double roulette_factor(const GColor *w)
{
    int n = gcolormodel_band_count(w->model), step = (n + ROULETTE_PEAK_BANDS - 1) / ROULETTE_PEAK_BANDS;
    double peak = gcolor_band_peak(w, step / 2, step);
    return peak > 0.0 ? peak : gcolor_brightness(w); /* a NaN band, or light only in bands not read: not lost */
}
