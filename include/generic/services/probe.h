/* probe.h - HDR light probes and their approximation by directional lights (lib/probe/).
 *
 * After Madsen & Laursen, "A Comparison of Techniques for Approximating Full Image-Based Lighting"
 * (../shared/papers/). Probe pixels are linear RGB radiance; everything here works per RGB channel.
 *
 * Direction convention (the one used by every function here, by gprobe and by the lights it writes):
 *   right-handed, z is up (the zenith). A direction is a unit vector from the probe's centre towards where
 *   the light comes from:   omega(theta, phi) = (sin theta cos phi, sin theta sin phi, cos theta),
 *   theta in [0, pi] measured from +z, phi measured from +x towards +y (the paper's sec. 3.1).
 * Latitude-longitude images (width = 2 * height): pixel (u, v), row v = 0 at the top, is centred on
 *   theta = pi (v + 0.5) / H   and   phi = pi - 2 pi (u + 0.5) / W.
 *   Row 0 touches the zenith and the middle row is the horizon; the middle column looks along +x, the left
 *   and right edges along -x, a quarter of the way along +y and three quarters along -y. Seen from the
 *   centre, facing the middle of the image with z up, the image's right is the viewer's right (-y): the
 *   environment is not mirrored. This is the mapping of Blender's world textures (Cycles'
 *   direction_to_equirectangular), for which the blender-data probes are made. The paper puts phi = 0 at
 *   the left edge and lets it grow to the right, which in a right-handed frame shows the scene mirrored;
 *   irradiance and every error measure are the same either way.
 * Angular maps (Debevec's "light probe" form, a D x D image): the disc's centre looks along +x (the middle
 *   of the lat-long image), up in the image is +z and right is -y (the viewer's right, as in the lat-long
 *   image), and a point at distance r from the centre (in units of the disc's radius) lies at the angle pi r
 *   from +x, so the rim is -x. Pixels outside the disc are ignored.
 *
 * Irradiance. Pixel (u, v) with radiance P is a small source of weight
 *   Q(u, v) = 2 pi^2 P(u, v) sin(theta_v) / (W H)          (the paper's Eq. 4, at the pixel centre),
 * the irradiance it gives a surface facing it; the ground truth for a normal n is
 *   E(n) = sum over pixels of Q(u, v) max(0, n . omega(u, v)).
 * A directional light (GProbeLight) is described the same way: `rgb` is the irradiance on a surface facing
 * it, so it adds rgb * max(0, n . dir) to E(n) (the paper's Eq. 5 with L_i A = rgb).
 *
 * Thread safety: a GProbe is read-only after creation and may be shared between threads; the functions
 * use OpenMP threads internally where it pays. */
#ifndef GENERIC_PROBE_H
#define GENERIC_PROBE_H

#include "../export.h"
#include "../color.h"
#include "../error.h"
#include "image.h"
#include "../vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A light probe held as a latitude-longitude image of linear RGB radiance (opaque). Besides the pixels it
 * keeps their weights Q and a summed-area table for the median cuts: about 80 bytes per pixel in all. */
typedef struct GProbe GProbe;

/** How an image file maps to directions. */
typedef enum GProbeFormat {
    GPROBE_AUTO = 0,    /**< 2:1 images are lat-long, square ones angular maps; anything else is refused */
    GPROBE_LATLONG = 1, /**< latitude-longitude, width = 2 * height */
    GPROBE_ANGULAR = 2  /**< Debevec's angular map, square */
} GProbeFormat;

/* ---- creation ---- */

/** The largest radiance a probe pixel keeps: larger finite values are clamped to it (far above any real
 * scene, the sun's disc included, and small enough that sums over a probe stay finite in float). */
#define GPROBE_MAX_RADIANCE 1e20f

/** Creates a lat-long probe from `rgb` (width * height * 3 floats, rows from the zenith down; NULL gives a
 * black probe). width must be 2 * height, height >= 2. Negative, NaN and infinite values are set to 0,
 * values above GPROBE_MAX_RADIANCE to that (see gprobe_clamped_count). */
GENERIC_API GENERIC_NODISCARD int gprobe_create(int width, int height, const float *rgb, GProbe **out, GError *err);

/** Loads a probe from any image OpenImageIO reads (EXR, HDR, PFM, TIFF, ...). `format` says how to read it
 * (GPROBE_AUTO decides by the aspect ratio); an angular map is resampled to a lat-long probe of `height`
 * rows (0: half the map's size). Clear errors for unreadable files and for images of the wrong shape. */
GENERIC_API GENERIC_NODISCARD int gprobe_load(const char *path, GProbeFormat format, int height, GProbe **out,
                                              GError *err);

/** Makes a lat-long probe of `height` rows (0: half the map's size) from an angular map (RGB or RGBA). */
GENERIC_API GENERIC_NODISCARD int gprobe_from_angular(const GImage *map, int height, GProbe **out, GError *err);

/** Frees a probe; NULL is a no-op. */
GENERIC_API void gprobe_destroy(GProbe *p);

/* ---- access ---- */

/** Width of the lat-long image (2 * height). */
GENERIC_API GENERIC_NODISCARD int gprobe_width(const GProbe *p);
/** Height of the lat-long image. */
GENERIC_API GENERIC_NODISCARD int gprobe_height(const GProbe *p);
/** The radiance P, 3 floats per pixel, rows from the zenith down. */
GENERIC_API const float *gprobe_pixels(const GProbe *p);
/** The pixel weights Q (see the top of this file), 3 floats per pixel. */
GENERIC_API const float *gprobe_weights(const GProbe *p);
/** Number of pixels that had a negative, NaN, infinite or too large value clamped when the probe was made. */
GENERIC_API long gprobe_clamped_count(const GProbe *p);

/** Direction of a point of the lat-long image in pixel units (u + 0.5, v + 0.5 is the centre of pixel u, v). */
GENERIC_API GVec3 gprobe_direction(const GProbe *p, double x, double y);
/** Position of a direction in the lat-long image in pixel units (the inverse of gprobe_direction);
 * dir need not be normalised. */
GENERIC_API void gprobe_position(const GProbe *p, GVec3 dir, double *x, double *y);
/** Radiance arriving from a direction, bilinear between pixel centres (dir need not be normalised). */
GENERIC_API void gprobe_radiance(const GProbe *p, GVec3 dir, float rgb[3]);
/** Integrated power: the sum of P times each pixel's exact solid angle (per channel). */
GENERIC_API void gprobe_power(const GProbe *p, double rgb[3]);

/* ---- conversion and rotation ---- */

/** Renders the probe as a D x D angular map (RGB; black outside the disc), supersampled per pixel. */
GENERIC_API GENERIC_NODISCARD int gprobe_to_angular(const GProbe *p, int size, GImage *out, GError *err);
/** The probe as a lat-long RGB image (a copy of the pixels). */
GENERIC_API GENERIC_NODISCARD int gprobe_to_image(const GProbe *p, GImage *out, GError *err);
/** Writes the probe to a file in the given form (GPROBE_AUTO: lat-long); angular maps are H x H. */
GENERIC_API GENERIC_NODISCARD int gprobe_save(const GProbe *p, const char *path, GProbeFormat format, GError *err);
/** A new probe showing the environment turned by the rotation matrix R (row-major, 3x3): radiance that came
 * from direction d now comes from R d. Resampled bilinearly, except for turns about z by whole pixels, which
 * are exact column shifts. G_ERR_INVALID when R is not a rotation. */
GENERIC_API GENERIC_NODISCARD int gprobe_rotate(const GProbe *p, const double R[9], GProbe **out, GError *err);
/** Fills R with the rotation by the given angles in degrees about x, then y, then z (R = Rz Ry Rx). */
GENERIC_API void gprobe_rotation_xyz(double x_deg, double y_deg, double z_deg, double R[9]);

/* ---- irradiance ---- */

/** Fills normals[0..m-1] with unit vectors spread evenly over the sphere (a Fibonacci lattice). */
GENERIC_API void gprobe_fibonacci(int m, GVec3 *normals);

/** Ground-truth irradiance E (3 doubles per normal) at m unit normals: the full sum over pixels (Eq. 4), exact
 * up to rounding. Each row of the probe is a circle of directions; the visible arc for a normal is found in
 * closed form and summed with per-row prefix sums, so the cost is O(W H + m H) instead of O(m W H). */
GENERIC_API GENERIC_NODISCARD int gprobe_irradiance(const GProbe *p, const GVec3 *normals, int m, double *E,
                                                    GError *err);

/** The same sum pixel by pixel (O(m W H)); a reference for tests and benchmarks. */
GENERIC_API GENERIC_NODISCARD int gprobe_irradiance_direct(const GProbe *p, const GVec3 *normals, int m, double *E,
                                                           GError *err);

/** A directional light: direction towards it (unit) and the irradiance it gives a surface facing it. */
typedef struct GProbeLight {
    GVec3 dir;
    double rgb[3];
} GProbeLight;

/** Irradiance E (3 doubles per normal) that n lights give at m normals. */
GENERIC_API void gprobe_lights_irradiance(const GProbeLight *lights, int n, const GVec3 *normals, int m, double *E);

/** Approximation errors against the ground truth, in percent. For each channel the mean and the maximum
 * over the normals are taken, then averaged over R, G, B (the paper's Fig. 6 measure). */
typedef struct GProbeErrors {
    double mean_rel;  /**< |E' - E| / E per normal and channel (the paper's measure) */
    double max_rel;
    double mean_norm; /**< |E' - E| / max over normals of E (normalised by the largest irradiance) */
    double max_norm;
    double smape;     /**< symmetric mean absolute percentage error, 100 mean of 2 |E' - E| / (|E'| + |E|) over
                           normals and channels (0..200; Probulator's reports use the same form) */
} GProbeErrors;

/** Compares approximate irradiances with the ground truth at m normals (3 doubles each). Normals whose
 * true irradiance is below 1e-6 of the channel's maximum are left out of the relative measure. */
GENERIC_API void gprobe_compare(const double *truth, const double *approx, int m, GProbeErrors *out);

/* ---- approximation techniques ---- */

/** The techniques, one file each in lib/probe/. */
typedef enum GProbeTechnique {
    GPROBE_MEDIANCUT = 0, /**< Debevec's median cut: 2^k lights */
    GPROBE_ADAPTIVE,      /**< adaptive median cut: any count */
    GPROBE_KMEANS,        /**< LightGen-style energy-weighted k-means */
    GPROBE_IRRADIANCE,    /**< irradiance optimisation (Madsen et al. 2003) */
    GPROBE_VARIANCE,      /**< variance-minimising median cut (Viriyothai & Debevec 2009): any count */
    GPROBE_TECHNIQUE_COUNT
} GProbeTechnique;

/** Keyword of a technique: "mediancut", "adaptive", "kmeans", "irradiance", "variance". */
GENERIC_API const char *gprobe_technique_name(GProbeTechnique t);
/** Technique for a keyword; G_ERR_NOTFOUND (message lists the names) for unknown ones. */
GENERIC_API GENERIC_NODISCARD int gprobe_technique_parse(const char *name, GProbeTechnique *t, GError *err);

/** Progress report: stage name and completed fraction 0..1; called from the calling thread. */
typedef void (*GProbeProgress)(void *user, const char *stage, double fraction);

/** Largest light count of the irradiance optimisation: each of its iterations solves a system of 2 x count
 * unknowns, so its time grows with the cube of the count (128 lights on 2000 normals: about 15 s). */
#define GPROBE_FIT_MAX_LIGHTS 128
/** Largest lights x fit normals of the irradiance optimisation (each iteration is linear in the product). */
#define GPROBE_FIT_MAX_PAIRS 524288

/** Options for the techniques; a zeroed struct (or NULL) takes every default. */
typedef struct GProbeOptions {
    int fit_normals; /**< irradiance: normals the fit uses (0: 2000); lights x normals at most GPROBE_FIT_MAX_PAIRS */
    int max_iterations;  /**< irradiance: Levenberg-Marquardt iterations (0: 400); kmeans: Lloyd rounds (0: 60) */
    GProbeProgress progress;
    void *user;
} GProbeOptions;

/** What the irradiance optimisation did (optional output of gprobe_irradiance_fit). The objective is the
 * sum over fit normals and channels of ((E' - E) / E)^2. */
typedef struct GProbeFitReport {
    double initial;     /**< objective of the initial lights (adaptive median cut, colours as cut) */
    double projected;   /**< after the first non-negative least-squares fit of the colours */
    double final;       /**< at the end */
    int iterations;     /**< Levenberg-Marquardt iterations run */
    int accepted;       /**< steps that lowered the objective */
    int active;         /**< lights with non-zero colour at the end */
    int converged;      /**< 1 when the iteration stopped by its convergence test, 0 at the iteration limit */
    int revived;        /**< lights that lost all colour and were moved and fitted again (kept results only) */
    int reweighted;     /**< reweighting rounds towards the mean absolute error that were kept (0: none) */
} GProbeFitReport;

/** Approximates the probe by n directional lights with a technique (median cut needs n a power of 2).
 * lights must hold n entries; lights without energy get rgb = 0 and still fill a slot. */
GENERIC_API GENERIC_NODISCARD int gprobe_approximate(const GProbe *p, GProbeTechnique t, int n,
                                                     const GProbeOptions *opt, GProbeLight *lights, GError *err);

/** Median cut (Debevec 2005): n = 2^k regions split along their longest side (width weighted by
 * sin theta) where the energy (luminance of Q) halves; a light at each region's energy centroid with the
 * region's summed Q. */
GENERIC_API GENERIC_NODISCARD int gprobe_median_cut(const GProbe *p, int n, GProbeLight *lights, GError *err);
/** Adaptive median cut: the same splits, one region at a time, always the one with the largest
 * energy-weighted angular spread, until there are n regions. */
GENERIC_API GENERIC_NODISCARD int gprobe_adaptive_median_cut(const GProbe *p, int n, GProbeLight *lights, GError *err);
/** LightGen-style clustering: spherical k-means of the pixel directions weighted by energy, seeded
 * deterministically (k-means++ from a fixed seed); each light carries its cluster's summed Q. */
GENERIC_API GENERIC_NODISCARD int gprobe_kmeans(const GProbe *p, int n, const GProbeOptions *opt, GProbeLight *lights,
                                                GError *err);
/** Irradiance optimisation: n lights fitted to the ground-truth irradiance at fit normals (see
 * lib/probe/optimize.c for the method); report may be NULL. */
GENERIC_API GENERIC_NODISCARD int gprobe_irradiance_fit(const GProbe *p, int n, const GProbeOptions *opt,
                                                        GProbeLight *lights, GProbeFitReport *report, GError *err);

/** Variance-minimising median cut (Viriyothai & Debevec 2009): regions of the lat-long image are split one
 * at a time, always the split (either axis, any position) that lowers the summed within-region variance
 * most (see gprobe_region_variance); a light at each region's energy centroid with its summed Q. */
GENERIC_API GENERIC_NODISCARD int gprobe_variance_cut(const GProbe *p, int n, GProbeLight *lights, GError *err);

/** A rectangle of the lat-long image: pixels [u0, u1) x [v0, v1). */
typedef struct GProbeRect {
    int u0, v0, u1, v1;
} GProbeRect;

/** The n regions a cutting technique (GPROBE_MEDIANCUT, GPROBE_ADAPTIVE or GPROBE_VARIANCE) makes, in the
 * order of its lights. G_ERR_INVALID for other techniques or counts they cannot make. */
GENERIC_API GENERIC_NODISCARD int gprobe_cut_regions(const GProbe *p, GProbeTechnique t, int n, GProbeRect *rects,
                                                     GError *err);

/** Energy-weighted variance of the pixel positions of a region: sum of e |x - mean x|^2 over its pixels,
 * e the luminance of Q, x = ((u + 0.5 - W / 2) sin theta_v, v + 0.5) in pixels (the sinusoidal projection,
 * where distances are angles and areas solid angles). The measure the variance cut minimises. */
GENERIC_API double gprobe_region_variance(const GProbe *p, const GProbeRect *r);

/* ---- spherical harmonics reference ---- */

/** Nine spherical-harmonic coefficients of the radiance per channel (Ramamoorthi & Hanrahan 2001), in the
 * order (l, m) = (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2). */
typedef struct GProbeSH9 {
    double c[9][3];
} GProbeSH9;

/** Projects the probe's radiance onto the nine harmonics (sums of Q times the basis). */
GENERIC_API void gprobe_sh9_project(const GProbe *p, GProbeSH9 *sh);
/** Irradiance the nine coefficients give at m normals (3 doubles each). */
GENERIC_API void gprobe_sh9_irradiance(const GProbeSH9 *sh, const GVec3 *normals, int m, double *E);

/* ---- basis-function approximations (lib/probe/basis.c and one file per basis) ---- */

/** Highest spherical-harmonic order (band) of GProbeSH. */
#define GPROBE_SH_MAX_ORDER 4
/** Coefficients of an order-L expansion: (L + 1)^2. */
#define GPROBE_SH_COEFFS(L) (((L) + 1) * ((L) + 1))
/** Most lobes of a spherical-Gaussian fit. */
#define GPROBE_SG_MAX_LOBES 128

/** Real spherical harmonics of the radiance up to order `order`, index l (l + 1) + m (the order of
 * GProbeSH9 for l <= 2; no Condon-Shortley phase), per RGB channel. */
typedef struct GProbeSH {
    int order;
    double c[GPROBE_SH_COEFFS(GPROBE_SH_MAX_ORDER)][3];
} GProbeSH;

/** Projects the radiance onto the harmonics of order <= order (1..GPROBE_SH_MAX_ORDER). */
GENERIC_API GENERIC_NODISCARD int gprobe_sh_project(const GProbe *p, int order, GProbeSH *sh, GError *err);
/** Multiplies band l by the Hanning window (1 + cos(pi l / (2 order + 1))) / 2 (Sloan, "Stupid Spherical
 * Harmonics Tricks", 2008): less ringing, a blurrier result. The width 2 L + 1 is the one that lowers the
 * negative irradiance a point light gives order 2 most (to -0.076 of the mean from -0.159; width L + 1,
 * which damps band 1 more, rings more: -0.19). */
GENERIC_API void gprobe_sh_window_hanning(GProbeSH *sh);
/** The real harmonics of order <= order at a unit direction (GPROBE_SH_COEFFS(order) values). */
GENERIC_API void gprobe_sh_basis(int order, GVec3 d, double *y);
/** Irradiance at m normals: sum over l, m of A_l c_lm Y_lm(n), A_l the clamped cosine's bands
 * (pi, 2 pi / 3, pi / 4, 0, -pi / 24). */
GENERIC_API void gprobe_sh_irradiance(const GProbeSH *sh, const GVec3 *normals, int m, double *E);
/** Radiance the expansion gives along a unit direction. */
GENERIC_API void gprobe_sh_radiance(const GProbeSH *sh, GVec3 d, double rgb[3]);

/** Ambient cube (McTaggart, Half-Life 2, 2004): six colours on the axes, E(n) = sum over axes of
 * n_i^2 C[axis i, side of sign(n_i)], order +x -x +y -y +z -z. */
typedef struct GProbeAmbientCube {
    double c[6][3];
} GProbeAmbientCube;
/** Fits the six colours to the ground-truth irradiance at fit_normals normals (0: 2000) by least squares. */
GENERIC_API GENERIC_NODISCARD int gprobe_ambient_cube_fit(const GProbe *p, int fit_normals, GProbeAmbientCube *cube,
                                                          GError *err);
/** The cube's value along a unit direction: the irradiance on a surface with that normal. */
GENERIC_API void gprobe_ambient_cube_eval(const GProbeAmbientCube *cube, GVec3 d, double rgb[3]);

/** A spherical Gaussian lobe: radiance amp exp(sharpness (axis . d - 1)). */
typedef struct GProbeSGLobe {
    GVec3 axis;
    double sharpness;
    double amp[3];
} GProbeSGLobe;

/** How the lobes' amplitudes are found (the lobes themselves: see lib/probe/sg_fit.c). */
typedef enum GProbeSGFit {
    GPROBE_SG_NAIVE = 0, /**< clustered lobes, each taking its cluster's power */
    GPROBE_SG_LS,        /**< least squares on the radiance holding the irradiance's bands (order <= 4) */
    GPROBE_SG_NNLS,      /**< the same, non-negative */
    GPROBE_SG_LS_AMBIENT /**< the same as GPROBE_SG_NNLS with a constant ambient term >= 0 beside the lobes:
                              its irradiance is never negative */
} GProbeSGFit;

/** Fits n lobes (1..GPROBE_SG_MAX_LOBES); ambient (3 values, may be NULL unless GPROBE_SG_LS_AMBIENT) gets
 * the constant term (0 for the other fits). */
GENERIC_API GENERIC_NODISCARD int gprobe_sg_fit(const GProbe *p, int n, GProbeSGFit fit, GProbeSGLobe *lobes,
                                                double ambient[3], GError *err);
/** Irradiance of a lobe of amplitude 1 on a surface whose normal makes cosine mu with the axis (numerical
 * quadrature of the exact integral, accurate to about 1e-6 relative). */
GENERIC_API double gprobe_sg_lobe_irradiance(double sharpness, double mu);

/** The basis techniques gprobe compares beside the lights. */
typedef enum GProbeBasisKind {
    GPROBE_BASIS_SH = 0,       /**< "sh": order L, n = (L + 1)^2 coefficients, L = 1..4 */
    GPROBE_BASIS_SH_HANNING,   /**< "sh-hanning": the same, Hanning-windowed */
    GPROBE_BASIS_AMBIENT_CUBE, /**< "ambientcube": n = 6 */
    GPROBE_BASIS_SG_NAIVE,     /**< "sg-naive": n lobes */
    GPROBE_BASIS_SG_LS,        /**< "sg-ls" */
    GPROBE_BASIS_SG_NNLS,      /**< "sg-nnls" */
    GPROBE_BASIS_SG_AMBIENT,   /**< "sg-ambient": n lobes and an ambient term */
    GPROBE_BASIS_COUNT
} GProbeBasisKind;

/** A fitted basis approximation; release with gprobe_basis_free. SG irradiance is tabulated per lobe so
 * that evaluating it allocates nothing. */
typedef struct GProbeBasis {
    GProbeBasisKind kind;
    int size;               /**< coefficients (sh, ambient cube) or lobes */
    GProbeSH sh;
    GProbeAmbientCube cube;
    GProbeSGLobe *lobes;    /**< size lobes (SG kinds) */
    double ambient[3];
    double *table;          /**< SG: irradiance per unit amplitude, GPROBE_SG_TABLE values per lobe */
} GProbeBasis;
/** Entries of an SG lobe's irradiance table (cosines -1..1). */
#define GPROBE_SG_TABLE 257

/** Keyword of a basis kind (see GProbeBasisKind). */
GENERIC_API const char *gprobe_basis_name(GProbeBasisKind k);
/** What n counts for a kind: "coefficients" or "lobes". */
GENERIC_API const char *gprobe_basis_unit(GProbeBasisKind k);
/** Kind for a keyword; G_ERR_NOTFOUND (message lists the names) for unknown ones. */
GENERIC_API GENERIC_NODISCARD int gprobe_basis_parse(const char *name, GProbeBasisKind *k, GError *err);
/** 1 when a kind can have n coefficients or lobes (sh: 4, 9, 16, 25; ambient cube: 6; SG: 1..128). */
GENERIC_API int gprobe_basis_size_ok(GProbeBasisKind k, int n);
/** Fits a basis of size n to the probe; out is zeroed first and owns its lobes. */
GENERIC_API GENERIC_NODISCARD int gprobe_basis_fit(const GProbe *p, GProbeBasisKind k, int n, GProbeBasis *out,
                                                   GError *err);
/** Frees what a basis holds; a zeroed basis is a no-op. */
GENERIC_API void gprobe_basis_free(GProbeBasis *b);
/** Irradiance at m unit normals (3 doubles each). */
GENERIC_API void gprobe_basis_irradiance(const GProbeBasis *b, const GVec3 *normals, int m, double *E);
/** Radiance along a unit direction (the ambient cube, which holds irradiance, shows E / pi). */
GENERIC_API void gprobe_basis_radiance(const GProbeBasis *b, GVec3 d, double rgb[3]);

/* ---- probes in a colour model (for renderers written against the generic colour interface) ---- */

/** Radiance arriving from a direction (bilinear, as gprobe_radiance) as a light (GCOLOR_LIGHT) in the
 * colour model of `out`, which must have storage. dir need not be normalised. */
GENERIC_API GENERIC_NODISCARD int gprobe_radiance_color(const GProbe *p, GVec3 dir, GColor *out);
/** Radiance of pixel (u, v) as a light in the colour model of `out`; u wraps around, v is clamped. */
GENERIC_API GENERIC_NODISCARD int gprobe_pixel_color(const GProbe *p, int u, int v, GColor *out);
/** The colour of a directional light (its irradiance on a surface facing it) as a light in the colour
 * model of `out`. */
GENERIC_API GENERIC_NODISCARD int gprobe_light_color(const GProbeLight *l, GColor *out);
/** A basis's irradiance for a unit normal as a light (GCOLOR_LIGHT) in the colour model of `out`; negative
 * values (SH's ringing) become 0. */
GENERIC_API GENERIC_NODISCARD int gprobe_basis_irradiance_color(const GProbeBasis *b, GVec3 normal, GColor *out);

#ifdef __cplusplus
}
#endif
#endif
