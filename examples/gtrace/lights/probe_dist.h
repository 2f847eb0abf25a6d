/* probe_dist.h - a light probe as a distribution of directions for importance sampling (probe_sample.c). */
#ifndef GTRACE_PROBE_DIST_H
#define GTRACE_PROBE_DIST_H

#include <generic/color.h>
#include <generic/error.h>
#include <generic/services/probe.h>
#include <generic/vec.h>

/** The probe as a piecewise-constant distribution over its pixels, proportional to each pixel's brightness
 * in the scene's colour model times its solid angle. */
typedef struct ProbeDist {
    int w, h;
    double *row_cdf; /**< h + 1 running sums of the rows' weights */
    double *col_cdf; /**< h rows of w + 1 running sums of the pixels' weights */
} ProbeDist;

/** Builds the distribution of probe p with brightness measured in model. */
int probe_dist_build(ProbeDist *d, const GProbe *p, const GColorModel *model, GError *err);
/** probe_dist_build with each pixel's brightness less the probe's mean brightness (over the sphere), 0 where that is
 * negative: the distribution for next-event estimation combined by MIS with a strategy that reaches every direction
 * (MIS compensation: Karlik, Sik, Vevoda, Skrivan and Krivanek 2019), which leaves the smooth part of the probe to
 * the material's sampling; a probe of one brightness keeps the plain distribution. */
int probe_dist_build_compensated(ProbeDist *d, const GProbe *p, const GColorModel *model, GError *err);
/** Frees the tables (a zeroed ProbeDist is fine). */
void probe_dist_free(ProbeDist *d);
/** Maps (u1, u2) in [0,1)^2 to a direction in probe space inside pixel (*u, *v), uniform in solid angle within
 * the pixel; returns the density of the direction in solid angle (0: the probe is black). */
double probe_dist_sample(const ProbeDist *d, const GProbe *p, double u1, double u2, int *u, int *v,
                         GVec3 *dir);
/** Density in solid angle of a direction in probe space. */
double probe_dist_pdf(const ProbeDist *d, const GProbe *p, GVec3 dir);

#endif
