/* probe_internal.h - the probe's private layout and helpers shared by the files of lib/probe/. */
#ifndef GENERIC_PROBE_INTERNAL_H
#define GENERIC_PROBE_INTERNAL_H

#include <math.h>
#include <stddef.h>

#include "generic/export.h"
#include "generic/services/probe.h"

/** Rec. 709 luminance weights: the "energy" of a pixel for the radiance-space techniques. */
#define GPROBE_LUM_R 0.2126
#define GPROBE_LUM_G 0.7152
#define GPROBE_LUM_B 0.0722

struct GProbe {
    int w, h;
    float *rgb;         /* radiance P, 3 per pixel */
    float *q;           /* weights Q, 3 per pixel */
    double *sat;        /* summed-area table, (h + 1) x (w + 1) entries of PROBE_SAT: luminance of Q, its
                           products with the pixel direction's x, y, z, and Q's R, G, B */
    double *cos_phi, *sin_phi;     /* per column, at pixel centres */
    double *cos_theta, *sin_theta; /* per row, at pixel centres */
    long clamped;
    size_t charged; /* bytes reserved against the memory budget (generic/memory.h) until gprobe_destroy */
};

/** Direction of the point (x, y), in pixel units, of a w x h lat-long image (the convention of probe.h). */
static inline GVec3 probe_latlong_dir(double x, double y, int w, int h)
{
    double theta = M_PI * y / h, phi = M_PI - 2.0 * M_PI * x / w;
    double s = sin(theta);
    return gvec3(s * cos(phi), s * sin(phi), cos(theta));
}

/** Energy (luminance) of a weight triple. */
static inline double probe_lum(const float *q)
{
    return GPROBE_LUM_R * q[0] + GPROBE_LUM_G * q[1] + GPROBE_LUM_B * q[2];
}

/** Direction of the centre of pixel (u, v), exactly as the irradiance sums use it. */
static inline GVec3 probe_pixel_dir(const GProbe *p, int u, int v)
{
    double s = p->sin_theta[v];
    return gvec3(s * p->cos_phi[u], s * p->sin_phi[u], p->cos_theta[v]);
}

/** Values per summed-area table entry. */
#define PROBE_SAT 7

/** Sums of the SAT over the pixel rectangle [u0, u1) x [v0, v1): out[0] energy, out[1..3] energy * dir,
 * out[4..6] the weights Q per channel. */
void probe_sat_sum(const GProbe *p, int u0, int v0, int u1, int v1, double out[PROBE_SAT]);

/* G_ERR_NOMEM when a width x height probe's tables would not fit in what the memory budget has left (generic/memory.h);
 * reserves nothing. */
GENERIC_NODISCARD int probe_check_budget(int width, int height, GError *err);
/** The bytes a width x height probe's tables take: its pixels and weights and its summed-area table. */
double probe_bytes(int width, int height);

/** A rectangle of the lat-long image and its energy statistics (median cut and its adaptive form). */
typedef struct ProbeRegion {
    int u0, v0, u1, v1;   /* [u0, u1) x [v0, v1) */
    double sum[PROBE_SAT]; /* energy, energy-weighted direction and colour sums (see probe_sat_sum) */
} ProbeRegion;

/** Fills r's sums from the SAT. */
void probe_region_init(const GProbe *p, ProbeRegion *r, int u0, int v0, int u1, int v1);
/** Splits r in two along its longest side (width weighted by sin theta) where its energy halves;
 * returns 0 when r is a single pixel (then a is r and b is empty). */
int probe_region_split(const GProbe *p, const ProbeRegion *r, ProbeRegion *a, ProbeRegion *b);
/** Energy-weighted angular spread: sum of E (1 - |mean direction|), the priority of adaptive median cut. */
double probe_region_spread(const ProbeRegion *r);
/** Lights for n regions: direction at the energy centroid, colour the region's summed Q. */
void probe_regions_to_lights(const GProbe *p, const ProbeRegion *regions, int n, GProbeLight *lights);

/** The n regions of median cut (n a power of two) and of adaptive median cut (any n >= 1). */
GENERIC_NODISCARD int probe_median_cut_regions(const GProbe *p, int n, ProbeRegion *out, GError *err);
GENERIC_NODISCARD int probe_adaptive_regions(const GProbe *p, int n, ProbeRegion *out, GError *err);

/** Reports progress when a callback is set. */
static inline void probe_progress(const GProbeOptions *opt, const char *stage, double f)
{
    if (opt && opt->progress)
        opt->progress(opt->user, stage, f);
}

#endif

/* ---- dense linear algebra for the irradiance fit (linalg.c) ---- */

/** C = X^T Y for column-major X (m x p) and Y (m x q), C row-major with row stride ldc (C[x * ldc + y]).
 * With symmetric != 0, Y must be X and q = p; the full symmetric C is filled. Threads for large sizes. */
void probe_gemm_tn(const double *X, int p, const double *Y, int q, int m, double *C, int ldc, int symmetric);

/** Cholesky factorisation in place of the n x n symmetric positive definite row-major matrix a (lower
 * triangle used); returns 0 on success, -1 when a is not positive definite. */
GENERIC_NODISCARD int probe_cholesky(double *a, int n);
/** Solves L L^T x = b in place for a factor from probe_cholesky. */
void probe_cholesky_solve(const double *l, int n, double *b);
/** Non-negative least squares from the normal equations: minimises x^T G x - 2 h^T x over x >= 0 (Lawson &
 * Hanson's active-set method), warm-started from the feasible x it is given. G is n x n row-major.
 * work holds n * n + 3 n doubles and n ints (as doubles' worth of space: pass probe_nnls_work_size(n)). */
void probe_nnls(int n, const double *G, const double *h, double *x, double *work);
/** Doubles of scratch probe_nnls needs. */
static inline size_t probe_nnls_work_size(int n) { return (size_t)n * n + 4 * (size_t)n; }

/* ---- spherical Gaussian lobes (sg_lobe.c) ---- */

/** Integral over the sphere of exp(lambda (axis . d - 1)): 2 pi (1 - exp(-2 lambda)) / lambda. */
double probe_sg_integral(double lambda);
/** The sharpness in [lo, hi] whose lobe has mean direction of the given length (the von Mises-Fisher
 * moment estimate, inverting coth lambda - 1 / lambda). */
double probe_sg_sharpness(double mean_length, double lo, double hi);

/* ---- choosing between lobe sets (sg_select.c) ---- */

/** Mean relative irradiance error (mean of |E' - E| / E over validation normals and channels) of n lobes and
 * a constant ambient radiance (NULL: none) against the probe p, into *error. */
GENERIC_NODISCARD int probe_sg_validation_error(const GProbe *p, int n, const GProbeSGLobe *lobes,
                                                const double ambient[3], double *error, GError *err);
