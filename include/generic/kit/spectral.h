/* spectral.h - the kit for sampled-spectrum colour models: a uniform wavelength grid, resampling between
 * grids, the colorimetric tables a model builds once (brightness weights, colour matching weights, an RGB
 * basis with the exact round-trip correction), and the operations of a plain sampled spectrum. The built-in
 * spectrum, spectrum9 and bispectral models are written with it, and so can a module.
 *
 * A model keeps a GSpectral at the start of its priv struct. For a plain sampled spectrum the whole model is
 * its init (one call: gspectral_model_init for a configurable grid, gspectral_model_init_fixed for a fixed
 * one) and a class table of the gspectral_* operations:
 *
 *     static int m_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
 *     {
 *         GSpectralGrid grid = {400.0, 25.0, 16};      // 400..775 nm
 *         return gspectral_model_init_fixed(self, opt, grid, err);
 *     }
 *     static const GColorModelClass m_class = {GCOLOR_ABI_VERSION, "m", "16 samples", .init = m_init,
 *         .fini = gspectral_model_fini, .black = gspectral_black, .add = gspectral_add, ...};
 *
 * A model with its own reconstruction (spectrum9's spline) supplies to_nm and calls gspectral_init itself;
 * the colour matching weights and the RGB basis are then derived from that to_nm, so to_xyz and from_rgb
 * agree with the nm path and rgb -> model -> rgb stays exact.
 *
 * Sampling onto a grid at least as coarse as the source (from_nm, and every other change onto a coarser
 * grid) is a hat-weighted average: each destination sample takes the source samples within one destination
 * step, weighted by a triangle and normalised by the weight it covers, so energy is conserved (a 1 nm line
 * between two samples splits between them) and a constant stays the same constant. Going onto a finer grid
 * is linear interpolation. On an equal grid both are the identity. */
#ifndef GENERIC_SPECTRAL_H
#define GENERIC_SPECTRAL_H

#include "../export.h"
#include <stddef.h>
#include "../color.h"
#include "../error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A uniform wavelength grid: n samples at min + k * step nm. */
typedef struct GSpectralGrid {
    double min, step;
    int n;
} GSpectralGrid;

/** A sparse linear map between two grids: dst[k] = sum_j w[off[k] + j] * src[first[k] + j], j < count[k].
 * Onto a grid at least as coarse as the source (unless built with interpolate) it is the hat-weighted average
 * (triangle of half-width dst.step around each destination sample, source samples outside the destination's
 * range dropped); onto a finer grid, linear interpolation (0 outside the source). */
typedef struct GSpectralResample {
    int n;
    int *first, *count, *off;
    float *w;
} GSpectralResample;

/** What every sampled model keeps at the start of its priv struct (gspectral_init fills it). */
typedef struct GSpectral {
    GSpectralGrid grid;
    GSpectralResample from_nm; /**< 1 nm exchange grid -> model grid (hat-weighted average) */
    GSpectralResample to_nm;   /**< model grid -> 1 nm, linear interpolation (empty for models with their own) */
    float *lum;                /**< brightness weights: > 0 everywhere, sum 1 */
    double *xyz[2];            /**< per GColorRole: 3 * n colour matching weights, [c * n + k] (the same
                                    allocation goes on with the float table gspectral_to_xyz reads) */
    float *rgb[2];             /**< per GColorRole: 3 * n RGB basis on the grid, corrected so the round trip
                                    rgb -> model -> rgb is exact */
    int uplift;                /**< a GColorUplift: how from_rgb makes spectra (0: sigmoid) */
    double *fit[2];            /**< per GColorRole: the sigmoid uplift's discretisation, 5 * n + 3: the
                                    normalised wavelengths, the three XYZ weights (a light's times D65), the D65
                                    factor (1 for a reflectance), the sums of the three weights (the white) */
} GSpectral;

/** A sanity limit on a grid's samples (300..830 nm at 1 nm has 531). */
#define GSPECTRAL_MAX_SAMPLES 1024

/* ---- grids and resampling ---- */

/** Reads a configurable grid from the options (zero fields take the defaults: def_step, 380..780 nm) and
 * checks it: step in [1, 100] nm, the range inside 300..830 nm and a whole number of steps, at most max_n
 * samples. G_ERR_INVALID with a message naming the model otherwise. */
GENERIC_API GENERIC_NODISCARD int gspectral_grid_from_options(const char *model, const GColorModelOptions *opt,
                                                              double def_step, int max_n, GSpectralGrid *grid,
                                                              GError *err);
/** For a model with a fixed grid: G_OK when every non-zero option equals the grid's own value, G_ERR_INVALID
 * ("colour model '<model>' has a fixed grid ...") otherwise, or when the grid itself is not one (n outside
 * 1..GSPECTRAL_MAX_SAMPLES, a start that is not finite, a step that is not finite and > 0). */
GENERIC_API GENERIC_NODISCARD int gspectral_grid_check_fixed(const char *model, const GColorModelOptions *opt,
                                                             GSpectralGrid grid, GError *err);
/** The wavelength of sample k of a grid, in nm. */
static inline double gspectral_grid_nm(GSpectralGrid grid, int k) { return grid.min + k * grid.step; }

/** Builds a map from src to dst: G_ERR_NOMEM when out of memory, G_ERR_INVALID when dst's step is more than
 * 1000 source steps. With interpolate the map is linear interpolation whatever the steps (for reflectances,
 * which carry no energy to preserve). */
GENERIC_API GENERIC_NODISCARD int gspectral_resample_build(GSpectralResample *r, GSpectralGrid src, GSpectralGrid dst,
                                                           int interpolate);
/** Applies a map: dst[k * dst_stride] from src[j * src_stride] (strides in floats). */
GENERIC_API void gspectral_resample_apply(const GSpectralResample *r, const float *src, int src_stride, float *dst,
                              int dst_stride);
/** Frees a map; a zeroed map is a no-op. */
GENERIC_API void gspectral_resample_free(GSpectralResample *r);

/* ---- the model's tables ---- */

/** Fills s for model m on grid: sets m's nsamples, nvalues (n), capacity (at least n) and grid fields, the
 * resampling maps (the linear to_nm map only with linear_to_nm), the brightness weights and the colorimetric
 * tables. m->priv must already point at the struct holding s and whatever m->cls->to_nm needs must be ready:
 * the colour matching weights and the RGB basis correction are computed through it. G_ERR_NOMEM, or
 * G_ERR_INVALID when the grid cannot represent RGB colours. */
GENERIC_API GENERIC_NODISCARD int gspectral_init(GColorModel *m, GSpectral *s, GSpectralGrid grid, int linear_to_nm,
                                                 GError *err);
/** Sets how s's model makes spectra from RGB (GColorModelOptions.uplift; opt may be NULL: the default, sigmoid).
 * G_ERR_INVALID, naming the model, for a value that is not a GColorUplift. */
GENERIC_API GENERIC_NODISCARD int gspectral_set_uplift(const GColorModel *m, GSpectral *s,
                                                       const GColorModelOptions *opt, GError *err);
/** Frees what gspectral_init allocated; NULL is a no-op. */
GENERIC_API void gspectral_fini(GSpectral *s);

/* ---- a model's init and fini ---- */

/** Allocates the model's zeroed priv struct of `size` bytes (one that begins with its GSpectral) into m->priv
 * and sets m->capacity; G_ERR_NOMEM "out of memory creating colour model '<name>'". */
GENERIC_API GENERIC_NODISCARD int gspectral_model_alloc(GColorModel *m, size_t size, int capacity, GError *err);
/** The whole init of a plain sampled model on a configurable grid (priv is a GSpectral): the grid from the
 * options (gspectral_grid_from_options with def_step and max_n), capacity for n values per colour (n * n with
 * matrices), linear to_nm. */
GENERIC_API GENERIC_NODISCARD int gspectral_model_init(GColorModel *m, const GColorModelOptions *opt, double def_step,
                                                       int max_n, int matrices, GError *err);
/** The whole init of a plain sampled model on a fixed grid (priv is a GSpectral, linear to_nm): refuses other
 * grid options (gspectral_grid_check_fixed). */
GENERIC_API GENERIC_NODISCARD int gspectral_model_init_fixed(GColorModel *m, const GColorModelOptions *opt,
                                                             GSpectralGrid grid, GError *err);
/** The fini of every sampled model: gspectral_fini on the priv struct, which is then freed. */
GENERIC_API void gspectral_model_fini(GColorModel *m);

/* ---- operations of a plain sampled spectrum (vectors of m->nvalues floats), for class tables ---- */

/** A zero vector. */
GENERIC_API void gspectral_black(const GColorModel *m, GColor *out);
/** Sample by sample a + b. */
GENERIC_API GENERIC_NODISCARD int gspectral_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
/** Sample by sample a * b. */
GENERIC_API GENERIC_NODISCARD int gspectral_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
/** Every sample times s. */
GENERIC_API GENERIC_NODISCARD int gspectral_scale(const GColorModel *m, GColor *out, const GColor *a, double s);
/** Sample by sample a / b, 0 where b is 0. */
GENERIC_API GENERIC_NODISCARD int gspectral_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
/** Sample by sample a ^ e; samples <= 0 give 0 (1 for e = 0). */
GENERIC_API GENERIC_NODISCARD int gspectral_pow(const GColorModel *m, GColor *out, const GColor *a, double e);
/** The brightness weights applied to |a| (color.h's brightness: Y of the value as a reflectance under D65, from
 * the model's own colour matching weights, with a floor so that every sample counts): 0 only for black, a
 * constant c gives c. */
GENERIC_API double gspectral_brightness(const GColorModel *m, const GColor *a);
/** Band slots of a sampled model: every sample is one wavelength band (band_count = nvalues, the mask of band k
 * is 1 at sample k, the value of a in band k is its sample k). */
GENERIC_API int gspectral_band_count(const GColorModel *m);
/** The mask of band k: 1 at sample k, 0 elsewhere. */
GENERIC_API GENERIC_NODISCARD int gspectral_band_mask(const GColorModel *m, int band, GColor *out);
/** Sample k of a. */
GENERIC_API double gspectral_band_value(const GColorModel *m, const GColor *a, int band);
/** to_nm by linear interpolation between samples (0 outside the grid); needs the linear to_nm map. */
GENERIC_API GENERIC_NODISCARD int gspectral_to_nm(const GColorModel *m, const GColor *a, GColorRole role,
                                                  GSpectrumNM *out);
/** from_nm by the hat-weighted average. */
GENERIC_API GENERIC_NODISCARD int gspectral_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role,
                                                    GColor *out);
/** XYZ from the precomputed colour matching weights (equal to the class's to_nm path up to float rounding: the
 * weights are rounded to float and the sums made in float on 8 lanes, gspectral_kxyz of spectral_kernels.h). */
GENERIC_API GENERIC_NODISCARD int gspectral_to_xyz(const GColorModel *m, const GColor *a, GColorRole role,
                                                   double xyz[3]);
/** to_xyz for a model with re-radiation matrices of nvalues x nvalues floats (GCOLOR_MATRIX, A[o * nvalues + i], as
 * the built-in bispectral and spectrum9 hold): a vector as gspectral_to_xyz, a matrix as its response to
 * equal-energy light, the vector of its row sums (each summed in double in order, then rounded to float). A NaN or
 * infinite entry makes its row sum non-finite, so gcolormodel_xyz_shows_nonfinite holds for a model on this
 * conversion as for one on gspectral_to_xyz. nvalues <= GSPECTRAL_MAX_SAMPLES. */
GENERIC_API GENERIC_NODISCARD int gspectral_to_xyz_folded(const GColorModel *m, const GColor *a, GColorRole role,
                                                          double xyz[3]);
/** The float colour matching table gspectral_to_xyz reads for role (gspectral_xyz_table's layout, n = the grid's
 * samples), for a model's own to_xyz kernel over the same sums. */
GENERIC_API const float *gspectral_xyz_floats(const GSpectral *s, GColorRole role);
/** A vector from linear sRGB: by default the sigmoid uplift (generic/colorspace.h) evaluated at the grid's
 * wavelengths, its coefficients refined against the model's own colour matching weights (so the round trip with
 * to_xyz is exact wherever sigmoid spectra reach the colour, and a reflectance of the sRGB cube stays within
 * [0, 1]); with the uplift GCOLOR_UPLIFT_BASIS, through the corrected RGB basis (exact round trip, linear). Each
 * thread keeps the sigmoid spectra it last made, keyed by the exact model, role and colour (a texture's repeated
 * texels cost a copy); gspectral_fini forgets them, so a kit model is freed through it. */
GENERIC_API GENERIC_NODISCARD int gspectral_from_rgb(const GColorModel *m, const double rgb[3], GColorRole role,
                                                     GColor *out);

#ifdef __cplusplus
}
#endif
#endif
