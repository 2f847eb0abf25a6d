/* bands.h - wavelength bands for dispersion (bands.c): the colour model's bands, grouped into at most a cap,
 * with one mask per group. A refraction whose relative index differs between the groups splits the ray: each
 * group is refracted with its own index and carries only its own light (whitted.c). */
#ifndef GTRACE_BANDS_H
#define GTRACE_BANDS_H

#include <generic/color.h>
#include <generic/error.h>

/** Default cap on the groups a refracted ray splits into (the model's bands are grouped evenly when it has
 * more: 81 bands in 16 groups of 5 or 6). */
#define BANDS_DEFAULT_CAP 16
/** Largest cap accepted (--bands). */
#define BANDS_LIMIT 1024
/** Most bytes the groups' masks may take together: a model with large values (a model of fine re-radiation matrices)
 * gets fewer groups than asked for rather than an allocation the size of the cap times its matrices. */
#define BANDS_MASK_BUDGET (64u << 20)
/** Relative indices whose groups differ by no more than this are not split (constant-index glass). */
#define BANDS_INDEX_TOLERANCE 1e-4

/** The groups of a model's bands: group g covers the model's bands first[g] .. first[g] + count[g] - 1. */
typedef struct Bands {
    int n;        /**< groups (1: no dispersion) */
    int *first;   /**< n + 1 entries: group g is [first[g], first[g + 1]) */
    GColor *mask; /**< n masks (heap), the sum of the group's band masks */
} Bands;

/** Groups the bands of model m into min(cap, band count) groups (cap 0: BANDS_DEFAULT_CAP), fewer when their
 * masks would exceed BANDS_MASK_BUDGET. */
int bands_init(Bands *b, const GColorModel *m, int cap, GError *err);
/** Frees the masks; a zeroed Bands is a no-op. */
void bands_free(Bands *b);
/** The index of group g of the relative index ri: the mean of its bands' values. */
double bands_value(const Bands *b, const GColor *ri, int g);
/** 1 when ri differs by more than BANDS_INDEX_TOLERANCE between its first, middle and last band (the
 * refraction must split). */
int bands_disperse(const Bands *b, const GColor *ri);

#endif
