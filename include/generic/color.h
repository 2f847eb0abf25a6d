/* color.h - the generic colour interface.
 *
 * A colour model (GColorModel) is chosen at run time by name ("rgb", "spectrum9", "spectrum",
 * "bispectral", or one a plug-in registers) and configured once (e.g. the spectrum's step in nm).
 * Its behaviour is a versioned const vtable (GColorModelClass); the instance carries the chosen
 * configuration and the model's private tables.
 *
 * Storage and ownership. A GColor is a small handle: the model, a kind, a pointer to at least
 * `model->capacity` floats, and a record of where those floats live (`storage`, a GColorStorage) and how many
 * there are (`capacity`). Who frees the floats follows from where they live:
 *   - GCOLOR_STORAGE_CALLER (gcolor_wrap): the caller's buffer; the caller keeps owning it;
 *   - GCOLOR_STORAGE_ARENA (gcolor_scratch): a GScratch arena; a mark/release pair (or destroying the arena)
 *     gives it back. This is how the per-ray path works, so colour arithmetic never calls malloc;
 *   - GCOLOR_STORAGE_HEAP (gcolor_alloc): the library's allocator, for long-lived values (a material's
 *     parameters); the handle owns it and gcolor_free frees it.
 * gcolor_free may be called on any handle: it frees only HEAP storage and then clears the handle (a cleared
 * handle, e.g. `GColor c = {0}`, is GCOLOR_STORAGE_NONE and freeing it again is a no-op). Copying a handle by
 * assignment copies the pointer, not the floats: free only one of the copies. A handle built by hand must name
 * its fields (designated initialisers) and set storage and capacity.
 * Every operation writes into an `out` colour that already has storage; `out` may alias an operand.
 *
 * Kinds. In every model a value is a vector of samples (a light spectrum, or a plain reflectance that
 * multiplies sample by sample). The bispectral model also has re-radiation matrices (GCOLOR_MATRIX,
 * out x in) for fluorescent reflectances; colormodels/bispectral.c and docs/reference/colour.md ("Bispectral
 * values") define every operation on them. rgb and spectrum9 hold the reduction of such a matrix onto their own
 * values (3 x 3, 9 x 9) with the same operations (colormodels/rgb.c, colormodels/spectrum9.c).
 *
 * Roles. Converting from or to RGB needs to know whether a value is a reflectance (seen under D65) or a
 * light (its own spectrum); the role argument says which. Sample values themselves are role free.
 *
 * The nm exchange format (GSpectrumNM) samples 380..780 nm at 1 nm; every model converts to and from
 * it, so any model can be converted to any other. */
#ifndef GENERIC_COLOR_H
#define GENERIC_COLOR_H

#include "export.h"
#include <stddef.h>
#include "error.h"
#include "memory.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the colour model vtable; a class with another version is refused. */
#define GCOLOR_ABI_VERSION 3

/** The nm exchange grid: 380..780 nm at 1 nm. */
#define GNM_MIN 380
#define GNM_MAX 780
#define GNM_COUNT (GNM_MAX - GNM_MIN + 1)

/** A spectrum sampled at every nm from GNM_MIN to GNM_MAX. */
typedef struct GSpectrumNM {
    float v[GNM_COUNT];
} GSpectrumNM;

/** What a colour value holds. */
typedef enum GColorKind {
    GCOLOR_VECTOR = 0, /**< samples: a light, or a reflectance applied sample by sample */
    GCOLOR_MATRIX = 1  /**< a re-radiation matrix (bispectral; its reduction to the values of rgb and spectrum9) */
} GColorKind;

/** How to read a value when converting from or to RGB/XYZ. */
typedef enum GColorRole {
    GCOLOR_REFLECTANCE = 0, /**< a reflectance: seen under D65 normalised to Y = 1 */
    GCOLOR_LIGHT = 1,       /**< a light: its spectrum as it is; equal energy E has Y = 1 */
    /** a unitless spectral quantity (a refractive index n, an extinction coefficient k): a curve over wavelength that
     * no light multiplies. From the nm spectrum (gcolor_from_nm) a model whose vectors are samples at wavelengths
     * (plain samples, nsamples == nvalues: spectrum, spectrum9, bispectral) takes the curve's values at its
     * wavelengths (linear between whole nm, the edge value beyond GNM_MIN..GNM_MAX); any other model (rgb) reduces it
     * as a reflectance. Every other conversion reads it as a reflectance. docs/reference/colour.md ("Unitless
     * quantities") gives the measurements behind the rule. */
    GCOLOR_UNITLESS = 2
} GColorRole;

typedef struct GColorModel GColorModel;
typedef struct GColorModelClass GColorModelClass;

/** Where the floats of a colour value live (see "Storage and ownership" above). */
typedef enum GColorStorage {
    GCOLOR_STORAGE_NONE = 0,   /**< a cleared handle, or one built by hand that owns nothing */
    GCOLOR_STORAGE_CALLER = 1, /**< the caller's buffer (gcolor_wrap) */
    GCOLOR_STORAGE_ARENA = 2,  /**< a GScratch arena (gcolor_scratch) */
    GCOLOR_STORAGE_HEAP = 3    /**< the library's allocator (gcolor_alloc); freed by gcolor_free */
} GColorStorage;

/** A colour value: a handle to at least `model->capacity` floats in caller, arena or heap storage. */
typedef struct GColor {
    const GColorModel *model;
    float *v;
    int kind;     /**< a GColorKind */
    int storage;  /**< a GColorStorage: who owns v */
    int capacity; /**< floats at v (>= model->capacity for a usable handle; 0 when cleared) */
} GColor;

/** How a spectral model turns an RGB colour into a spectrum (GColorModelOptions.uplift). */
typedef enum GColorUplift {
    GCOLOR_UPLIFT_DEFAULT = 0, /**< the model's default: sigmoid in the built-in spectral models */
    GCOLOR_UPLIFT_SIGMOID = 1, /**< Jakob and Hanika's sigmoid spectra (colorspace.h): smooth, a reflectance of the
                                    sRGB cube within [0, 1] */
    GCOLOR_UPLIFT_BASIS = 2    /**< the spectral primary basis, corrected so that the round trip is exact (linear
                                    in RGB; saturated reflectances leave [0, 1] on coarse grids) */
} GColorUplift;

/** Options for creating a model; zero fields take the model's defaults. */
typedef struct GColorModelOptions {
    double step_nm; /**< sample spacing (spectrum: 5 by default; bispectral: 10) */
    double min_nm;  /**< first sample (default 380) */
    double max_nm;  /**< last sample (default 780) */
    int uplift;     /**< a GColorUplift (models without wavelength samples ignore it) */
} GColorModelOptions;

/** A re-radiation matrix on its own grid, used to bring measured data into any model.
 * data[o * n_in + i] is the share of light at excitation in_min + i*in_step re-radiated at
 * emission out_min + o*out_step (per excitation bin); the diagonal is the plain reflectance. */
typedef struct GReradiation {
    double in_min, in_step;
    int n_in;
    double out_min, out_step;
    int n_out;
    const float *data;
} GReradiation;

/** A colour model instance: its class, its configuration and its sizes. Made only by gcolormodel_create and
 * gcolormodel_create_class (the library keeps more with it, past this struct) and freed by gcolormodel_destroy. */
struct GColorModel {
    const GColorModelClass *cls;
    int nvalues;        /**< floats in a vector value */
    int capacity;       /**< floats any value of this model may need */
    int nsamples;       /**< spectral samples (0 for non-spectral models) */
    double lambda_min;  /**< wavelength of sample 0 in nm (spectral models) */
    double lambda_step; /**< spacing of samples in nm (spectral models) */
    void *priv;         /**< the model's own tables */
};

/** The vtable of a colour model. Required: init, black, add, mul, scale, div, pow, to_nm, from_nm. Optional (NULL
 * = go through the nm spectrum): fini, to_xyz, from_rgb, from_reradiation. Optional (NULL = Y of to_xyz as a
 * reflectance, the definition below): brightness.
 * Optional (NULL = the defaults of lib/color/color_vector_ops.c and color.c, which read a vector as nvalues independent
 * samples, as add and scale treat it): fill, axpy, exp_scaled. A model whose vectors are not plain samples, or that
 * has matrices, gives its own. Optional (NULL = one band, no dispersion): band_count, band_mask, band_value.
 * Operations get valid operands of this model (the dispatch checks models); `out` may alias them. */
struct GColorModelClass {
    int abi_version;         /**< GCOLOR_ABI_VERSION */
    const char *name;        /**< type keyword, e.g. "spectrum" */
    const char *description; /**< one line for listings */
    /** Fills nvalues, capacity, the grid and priv from the options; reports bad options. */
    int (*init)(GColorModel *self, const GColorModelOptions *opt, GError *err);
    /** Frees priv. */
    void (*fini)(GColorModel *self);
    void (*black)(const GColorModel *m, GColor *out);
    int (*add)(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
    /** Reflection: a applied to b (a reflectance or matrix, b a light or reflectance). */
    int (*mul)(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
    int (*scale)(const GColorModel *m, GColor *out, const GColor *a, double s);
    /** Relative refraction index a / b, sample by sample. */
    int (*div)(const GColorModel *m, GColor *out, const GColor *a, const GColor *b);
    /** a to the power e, sample by sample (absorption: transmittance^distance). */
    int (*pow)(const GColorModel *m, GColor *out, const GColor *a, double e);
    /** Brightness (gcolor_brightness's definition): 0 exactly for black, constant c gives c. */
    double (*brightness)(const GColorModel *m, const GColor *a);
    int (*to_nm)(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out);
    int (*from_nm)(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out);
    int (*to_xyz)(const GColorModel *m, const GColor *a, GColorRole role, double xyz[3]);
    int (*from_rgb)(const GColorModel *m, const double rgb[3], GColorRole role, GColor *out);
    int (*from_reradiation)(const GColorModel *m, const GReradiation *r, GColor *out, GError *err);
    /** The constant `value` (a vector; in a model with matrices it stands for value times the identity).
     * Default: value in each of the nvalues samples. */
    int (*fill)(const GColorModel *m, GColor *out, double value);
    /** exp(s * a) sample by sample (Beer-Lambert: a transmittance from an absorption coefficient; not named
     * exp, which <tgmath.h> defines as a macro). Default: vectors sample by sample; a matrix is refused
     * (G_ERR_UNSUPPORTED): the library cannot read it. */
    int (*exp_scaled)(const GColorModel *m, GColor *out, const GColor *a, double s);
    /** out = s * a + b. Default: two vectors sample by sample; otherwise the class's scale then add, through
     * a temporary of the model's capacity from a per-thread arena of the library. */
    int (*axpy)(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b);
    /* Wavelength bands, for dispersion: a renderer that refracts light with an index that varies across the
     * model's samples splits the ray into bands, each refracted with the band's own index and carrying only
     * the band's light. The bands partition the model's samples: their masks sum to white. */
    /** Number of bands (>= 1). Default 1: the model says nothing about wavelengths, and light is refracted
     * whole with the brightness of the index (no dispersion). The library asks once, when the model is created
     * (a model's bands are part of its configuration), and answers gcolormodel_band_count from that. */
    int (*band_count)(const GColorModel *m);
    /** out = the mask of band `band` (0 <= band < band_count): a vector that multiplied with a light keeps the
     * light of the band and nothing else. Default: white (the one band is everything). */
    int (*band_mask)(const GColorModel *m, int band, GColor *out);
    /** The value of the vector a in band `band` (e.g. the refraction index of the band's light). Default: the
     * luminance-weighted mean, brightness(mask * a) / brightness(mask). */
    double (*band_value)(const GColorModel *m, const GColor *a, int band);
};

/* ---- models ---- */

/** Creates a model by registered name with options (NULL = defaults). */
GENERIC_API GENERIC_NODISCARD int gcolormodel_create(const char *name, const GColorModelOptions *opt, GColorModel **out,
                                                     GError *err);
/** Creates a model from a class directly (used by plug-ins and tests). */
GENERIC_API GENERIC_NODISCARD int gcolormodel_create_class(const GColorModelClass *cls, const GColorModelOptions *opt,
                                                           GColorModel **out, GError *err);
/** Frees a model; NULL is a no-op. Colours of the model must not be used afterwards. */
GENERIC_API void gcolormodel_destroy(GColorModel *m);
/** The model's type keyword. */
GENERIC_API const char *gcolormodel_name(const GColorModel *m);

/* ---- storage ---- */

/** Points c at the caller's buffer of nfloats floats (GCOLOR_STORAGE_CALLER) and sets it to black.
 * G_ERR_INVALID, with c cleared, when storage is NULL or nfloats < m->capacity. */
GENERIC_API GENERIC_NODISCARD int gcolor_wrap(GColor *c, const GColorModel *m, float *storage, size_t nfloats);
/** Gives c storage from the arena (GCOLOR_STORAGE_ARENA) and sets it to black; G_ERR_NOMEM, with c cleared,
 * when the arena cannot grow. The arena's mark/release gives the storage back. */
GENERIC_API GENERIC_NODISCARD int gcolor_scratch(GColor *c, const GColorModel *m, GScratch *s);
/** gcolor_scratch without setting the colour to black: its values are whatever the arena held (a vector of
 * unspecified samples), for a colour that the caller's next operation writes in full (a material method's
 * result, the out of an operation): a renderer's per-ray temporaries save the black's stores. In a build with
 * AddressSanitizer the values are NaN, so that a read before the write shows as non-finite results. */
GENERIC_API GENERIC_NODISCARD int gcolor_scratch_uncleared(GColor *c, const GColorModel *m, GScratch *s);
/** Gives c heap storage (GCOLOR_STORAGE_HEAP, for long-lived values) and sets it to black; G_ERR_NOMEM, with
 * c cleared, when out of memory. */
GENERIC_API GENERIC_NODISCARD int gcolor_alloc(GColor *c, const GColorModel *m);
/** Frees c's storage if it is HEAP (caller and arena storage are left alone) and clears the handle; NULL and
 * a cleared handle are no-ops. */
GENERIC_API void gcolor_free(GColor *c);
/** Copies the value of src into dst (same model). */
GENERIC_API GENERIC_NODISCARD int gcolor_copy(GColor *dst, const GColor *src);

/* ---- the generic operations (status: G_OK, or G_ERR_MISMATCH for colours of different models) ---- */

/** Sets c to black (a zero vector). */
GENERIC_API void gcolor_black(GColor *c);
/** out = a + b */
GENERIC_API GENERIC_NODISCARD int gcolor_add(GColor *out, const GColor *a, const GColor *b);
/** out = a * b: reflection of b by a. */
GENERIC_API GENERIC_NODISCARD int gcolor_mul(GColor *out, const GColor *a, const GColor *b);
/** out = (a * b) * s: the reflection of b by a, scaled (a material's reflectance times light times cos / pi). The
 * same value as gcolor_mul then gcolor_scale, in one pass over the samples for vectors of a model the library
 * reads as plain samples (no fill of its own: each product rounded to float, then times (float)s, as the built-in
 * models' mul and scale do); otherwise exactly that composition. */
GENERIC_API GENERIC_NODISCARD int gcolor_mul_scaled(GColor *out, const GColor *a, const GColor *b, double s);
/** out = a * s */
GENERIC_API GENERIC_NODISCARD int gcolor_scale(GColor *out, const GColor *a, double s);
/** out = a / b: relative refraction index (zero divisors give zero). */
GENERIC_API GENERIC_NODISCARD int gcolor_div(GColor *out, const GColor *a, const GColor *b);
/** out = a ^ e, sample by sample (absorption). */
GENERIC_API GENERIC_NODISCARD int gcolor_pow(GColor *out, const GColor *a, double e);
/** Brightness, one definition in every model: Y (CIE 1931) of the value read as a reflectance under D65, the perfect
 * white reflector 1 (the value 1 everywhere). So the same reflectance has the same brightness in every model (the
 * Y its to_xyz gives in the reflectance role), and Russian roulette, light selection and energy checks see one
 * number for one colour. Samples count by magnitude (a value with negative samples is not darker for them), and
 * each sample's weight has a floor of 1e-6 of the largest, so brightness is 0 if and only if c is black; a constant
 * value c gives c. The brightness has no role, and a light read so is its Y weighted by D65 once more: in the
 * spectral models the D65 white light's is 1.007, and a saturated light's of the sRGB cube within 11% of its Y as a
 * light (rgb: equal, as rgb's lights are relative to D65). The brightness of a light: gcolor_brightness_as. A model
 * without a brightness slot gets Y of its own to_xyz in the reflectance role. */
GENERIC_API double gcolor_brightness(const GColor *c);
/** Brightness of c read in role. GCOLOR_REFLECTANCE: gcolor_brightness(c). GCOLOR_LIGHT (a vector): Y (CIE 1931) of
 * the value as a light, equal-energy white 1 (so rgb's white light (1, 1, 1), D65, is 1), through the model's own
 * to_xyz with every sample taken by magnitude; so the same light has the same brightness in every model (within
 * 1e-3 over the sRGB cube, tests/test_brightness.c), where gcolor_brightness, which has no role, weighs a spectral
 * light's samples by D65 once more than its Y does (up to 11% off). 0 only for black (a light outside the eye's
 * range gets the smallest normal double). A matrix is read as gcolor_brightness reads it. For light selection,
 * photon powers and emitted light; a path's throughput is a reflectance. */
GENERIC_API double gcolor_brightness_as(const GColor *c, GColorRole role);
/** 1 when c is black, 0 otherwise: what gcolor_brightness(c) == 0.0 asks (brightness is 0 only for black), for
 * callers that need no more than that answer. A value that any NaN makes NaN is not black; -0.0 is zero. A vector
 * of a model whose vectors the library reads as plain samples (no fill of its own) is black when every sample is
 * zero, which the test finds out at the first non-zero one; otherwise (matrices, and vectors of models that give
 * their own fill) it is brightness == 0. */
GENERIC_API int gcolor_is_black(const GColor *c);
/** out = s * a + b (out may alias a or b); any kinds the model's add and scale accept. */
GENERIC_API GENERIC_NODISCARD int gcolor_axpy(GColor *out, double s, const GColor *a, const GColor *b);
/** out += a * s, that is gcolor_axpy(out, s, a, out). */
GENERIC_API GENERIC_NODISCARD int gcolor_add_scaled(GColor *out, const GColor *a, double s);
/** out = the constant value (a vector: 1 is white, and the relative index of vacuum); G_ERR_INVALID for a
 * non-finite value. */
GENERIC_API GENERIC_NODISCARD int gcolor_fill(GColor *out, double value);
/** out = exp(s * a) sample by sample (a transmittance from an absorption coefficient: s = -distance). A
 * matrix operand: the model's definition (bispectral: its diagonal, as pow), G_ERR_UNSUPPORTED in a plug-in
 * model that gives no exp of its own. */
GENERIC_API GENERIC_NODISCARD int gcolor_exp(GColor *out, const GColor *a, double s);
/** Bytes of storage one value of the model takes (what gcolor_alloc allocates): for budgets of renderers
 * that keep many values. */
GENERIC_API size_t gcolormodel_value_bytes(const GColorModel *m);
/** Number of wavelength bands of the model (>= 1; see GColorModelClass.band_count). */
GENERIC_API int gcolormodel_band_count(const GColorModel *m);
/** out = the mask of band `band` of out's model: mul(mask, light) keeps the band's light; the masks of all
 * bands sum to white. G_ERR_INVALID for a band out of range. */
GENERIC_API GENERIC_NODISCARD int gcolor_band_mask(GColor *out, int band);
/** The value of the vector c in band `band` (the band's refraction index when c is an index); NAN for a
 * band out of range or a matrix. */
GENERIC_API double gcolor_band_value(const GColor *c, int band);
/** The largest of 0 and gcolor_band_value(c, b) over the bands b = first, first + step, first + 2 step, ... below
 * gcolormodel_band_count (a path tracer's Russian roulette reads a spread of bands this way, in one call): 0 when
 * no band is read (first at or past the count), NAN when one of them is NAN (a matrix, or c a vector of a model
 * whose band_value gives one) or when first < 0 or step < 1. */
GENERIC_API double gcolor_band_peak(const GColor *c, int first, int step);

/** 1 when every sample is finite, 0 otherwise. */
GENERIC_API GENERIC_NODISCARD int gcolor_is_finite(const GColor *c);
/** 1 when every sample is finite and >= 0 (a physical light or reflectance), 0 otherwise. */
GENERIC_API GENERIC_NODISCARD int gcolor_is_nonnegative(const GColor *c);
/** 1 when the model's conversion to XYZ shows every non-finite value: gcolor_to_xyz of a colour of m with a NaN or
 * infinite value anywhere gives non-finite coordinates, so that finite coordinates prove the colour finite and a
 * renderer may test the three numbers it converts instead of every sample (gcolor_is_finite). It holds for the
 * models whose to_xyz is the spectral kit's (gspectral_to_xyz: each coordinate is a sum over every sample of the
 * sample times a weight, and NaN or infinity times any weight, zero included, stays non-finite through the sum; and
 * gspectral_to_xyz_folded, which reads a matrix by its row sums, each non-finite where one of its entries is); 0
 * for any other, whose conversion the library cannot read (it may clamp, or skip samples). */
GENERIC_API int gcolormodel_xyz_shows_nonfinite(const GColorModel *m);

/* ---- conversions ---- */

/** To the nm exchange spectrum. */
GENERIC_API GENERIC_NODISCARD int gcolor_to_nm(const GColor *c, GColorRole role, GSpectrumNM *out);
/** From the nm exchange spectrum (checks for NaN). */
GENERIC_API GENERIC_NODISCARD int gcolor_from_nm(GColor *c, const GSpectrumNM *in, GColorRole role);
/** The wavelengths (nm, increasing) at which the model keeps its values, for writing them out (e.g. the
 * spectral channels of an OpenEXR): its own sample grid (GColorModel.nsamples from lambda_min in steps of
 * lambda_step) where it lies within the nm exchange range GNM_MIN..GNM_MAX. Returns how many there are (0 for a
 * model without wavelength samples, such as rgb) and writes the first min(that, max) of them to nm (which may be
 * NULL when max is 0). */
GENERIC_API int gcolormodel_wavelengths(const GColorModel *m, double *nm, int max);
/** The values of c at the model's wavelengths (gcolormodel_wavelengths), read in role (a light: its spectral
 * radiance, so that integrating them against the CIE 1931 observer gives gcolor_to_xyz): out[k] for the k-th
 * wavelength, n of them (n must equal the count). Goes through the nm exchange spectrum (gcolor_to_nm, on the
 * stack: no allocation). G_ERR_INVALID when n is not the model's count or the model has none. */
GENERIC_API GENERIC_NODISCARD int gcolor_at_wavelengths(const GColor *c, GColorRole role, float *out, int n);
/** To CIE 1931 XYZ. */
GENERIC_API GENERIC_NODISCARD int gcolor_to_xyz(const GColor *c, GColorRole role, double xyz[3]);
/** To linear sRGB (Rec.709 primaries, D65 white). */
GENERIC_API GENERIC_NODISCARD int gcolor_to_rgb(const GColor *c, GColorRole role, double rgb[3]);
/** From linear sRGB; G_ERR_INVALID for NaN or infinite input. */
GENERIC_API GENERIC_NODISCARD int gcolor_from_rgb(GColor *c, const double rgb[3], GColorRole role);
/** From a re-radiation matrix: a matrix in the bispectral model (the matrix resampled), in rgb and in spectrum9 (its
 * reduction, gcolormodel_reduce_reradiation); in a model without the slot the response to an equal-energy light (the
 * matrix's effect folded into a plain reflectance), with components a narrow gamut makes negative set to 0.
 * G_ERR_INVALID for an empty grid, a step that is not finite and > 0, a non-finite start or value, or grids that
 * share no wavelength (no diagonal). */
GENERIC_API GENERIC_NODISCARD int gcolor_from_reradiation(GColor *c, const GReradiation *r, GError *err);
/** The non-orthogonal reduction of a re-radiation matrix onto the n = nvalues values of m (after Fichet, Belcour and
 * Barla 2024, "Non-orthogonal reduction for rendering fluorescent materials in non-spectral engines"), for a model's
 * from_reradiation slot: out becomes the n x n GCOLOR_MATRIX R (R[o * n + j], color.h's matrix convention) whose
 * column j is the light r sends back when the model's unit light j falls on it: the unit value j read as a light
 * (to_nm), the matrix applied per nm (its diagonal, linear between its samples, times the light at every nm; each
 * re-radiating entry times the light at its excitation wavelength within GNM_MIN..GNM_MAX, linear between the
 * emission samples), converted back as a light (from_nm). Reconstruction (the model's light basis) and projection
 * (the colour matching functions) differ: the reduction is exact for the lights the model's basis holds, in rgb
 * white (1, 1, 1), D65. Then two steps make R a matrix a material may hold, each keeping the row sums (the response
 * to white) where it can: a negative entry (a re-radiated colour outside the model's gamut) is set to 0 and taken
 * from the entries of its row, nearest value first; when all entries sum above n (white sent back above white) they
 * are scaled by n / sum, and a column above 1 (energy as material_params.h counts it, all that leaves per unit
 * arriving in one value) gives its excess to the columns of the same rows with room. So the entries are >= 0 and
 * every column sums to at most 1. Measured (tests/test_fluorescent_rgb.c, the parametric day-glo orange and
 * the four measured matrices of the test data): mean CIEDE2000 of the patch colour to the bispectral model's under
 * D65 / A / F2 2.4 / 9.9 / 6.8 against 3.7 / 13.3 / 9.4 for the equal-energy fold; 0.02 and 0.05 under D65 for the
 * two whose colour is inside the gamut. A plain reflectance (a diagonal matrix) reduces to a matrix whose response
 * to white is its reflectance. G_ERR_UNSUPPORTED when the model holds no n x n matrix (capacity < n^2, or n > 16)
 * or cannot convert a unit light; G_ERR_INVALID for more than 1024 emission samples. */
GENERIC_API GENERIC_NODISCARD int gcolormodel_reduce_reradiation(const GColorModel *m, const GReradiation *r,
                                                                 GColor *out, GError *err);
/** A linear projection of an nm spectrum onto a model's values in a role (the signature of a class's from_nm). */
typedef int (*GColorProjectNM)(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out);
/** gcolormodel_reduce_reradiation with the sent light of each column converted back by project (NULL: the model's
 * from_nm), for a model whose from_nm is not linear for every light: spectrum9 sets a narrow line's negative samples
 * to 0, where a column of the operator keeps them until the reduction's own non-negative step. Measured in spectrum9
 * (the patch colours of gcolormodel_reduce_reradiation): mean CIEDE2000 under D65 / A / F2 1.95 / 1.89 / 2.32
 * against 3.26 / 7.78 / 8.75 for the equal-energy fold. */
GENERIC_API GENERIC_NODISCARD int gcolormodel_reduce_reradiation_by(const GColorModel *m, const GReradiation *r,
                                                                    GColorProjectNM project, GColor *out,
                                                                    GError *err);
/** Converts a value of one model into another (through a direct formula or the nm spectrum). */
GENERIC_API GENERIC_NODISCARD int gcolor_convert(GColor *dst, const GColor *src, GColorRole role);

/* ---- range after conversion ---- */

/** The model's own conversion error: *lo and *hi get the smallest and the largest sample that the corners of
 * the sRGB cube [0, 1]^3 take after gcolor_from_rgb in role (*lo at most 0). For a linear from_rgb (rgb, and the
 * spectral models with uplift basis) that is every colour of the cube's extremes, and an in-gamut colour whose
 * largest RGB component is s has every sample within [*lo * s, *hi * s]. rgb: exactly 0 and 1 for a reflectance.
 * Measured (reflectance, uplift basis): spectrum at 5 nm -0.00005..1.00013, bispectral at 10 nm -0.0030..1.0030,
 * spectrum9 -0.129..1.129 at its samples (its spline reaches -0.21..1.21 between them); with the sigmoid uplift
 * (the default) a reflectance of the cube lies within [0, 1] in spectrum and bispectral. A vector is read as
 * nvalues samples. G_ERR_NOMEM when no temporary can be had. */
GENERIC_API GENERIC_NODISCARD int gcolormodel_rgb_range(const GColorModel *m, GColorRole role, double *lo, double *hi);
/** Maps a vector into the model's range: negative samples become 0, and the value is then scaled so that its
 * luminance (Y of gcolor_to_xyz in role) is what it was (kept as it is when either luminance is not > 0).
 * *mapped (may be NULL) gets 1 when a sample lay further below 0 than the model's conversion error allows for
 * a colour of this size (gcolormodel_rgb_range, times the value's largest RGB component): the value was out of
 * the model's gamut, which a caller may want to report; 0 when nothing or only conversion error was clipped.
 * Matrices are left alone. G_ERR_INVALID for a non-finite sample. */
GENERIC_API GENERIC_NODISCARD int gcolor_clip_to_gamut(GColor *c, GColorRole role, int *mapped);
/** Maps a light into the model's range: within the model's conversion error as gcolor_clip_to_gamut (negative samples
 * to 0, luminance kept); out of the gamut (*mapped 1) its negative samples become 0 and the rest stay as they are,
 * which keeps the chromaticity nearest the light's that the gamut holds where restoring the luminance would darken
 * the components that remain. Measured (tests/test_gtrace_fluorescent_rgb.c): the Cornell box with white walls lit
 * by a 450 nm line renders in rgb within image-mean CIEDE2000 0.19 of bispectral this way, 8.86 with the luminance
 * kept. Matrices are left alone; G_ERR_INVALID for a non-finite sample. */
GENERIC_API GENERIC_NODISCARD int gcolor_clip_light_to_gamut(GColor *c, int *mapped);

/* ---- colorimetry helpers (lib/color/cie.c) ---- */

/** Linear sRGB -> XYZ (D65). */
GENERIC_API void gcie_rgb_to_xyz(const double rgb[3], double xyz[3]);
/** XYZ -> linear sRGB (D65). */
GENERIC_API void gcie_xyz_to_rgb(const double xyz[3], double rgb[3]);
/** XYZ of an nm spectrum read as a role (light: E has Y = 1; reflectance: under D65 with Y = 1). */
GENERIC_API void gcie_nm_to_xyz(const GSpectrumNM *s, GColorRole role, double xyz[3]);
/** Spectrum for a linear sRGB colour: a smooth reflectance from the spectral primary basis
 * (times D65 normalised to Y = 1 for lights), so that gcie_nm_to_xyz gives back the colour. */
GENERIC_API void gcie_rgb_to_nm(const double rgb[3], GColorRole role, GSpectrumNM *out);
/** CIE 1931 2-degree colour matching functions at a wavelength in nm (linear between table values, 0 outside). */
GENERIC_API void gcie_cmf(double nm, double xyz[3]);
/** Relative spectral power of a named CIE illuminant (gcie_illuminant_name lists them: A, B, C, D50, D55, D65,
 * D75, E, F1..F12, LED-B1..B5, LED-BH1, LED-RGB1, LED-V1, LED-V2) at nm, from the CIE's 5 nm tables interpolated
 * to 1 nm (Sprague) and linearly between, normalised so the illuminant has Y = 1 as a light; 0 outside
 * GNM_MIN..GNM_MAX. The interpolation dips slightly below 0 beside the mercury lines of F4, F10, F11 and F12.
 * -1 when the name is unknown (gcie_illuminant_nm tells names apart). */
GENERIC_API double gcie_illuminant(const char *name, double nm);
/** The i-th name gcie_illuminant knows (0, 1, ...; CIE order: A, B, C, the D series, E, F, LED), NULL past the
 * last: for listing them. */
GENERIC_API const char *gcie_illuminant_name(int i);
/** Fills an nm spectrum with a named illuminant (Y = 1); G_ERR_NOTFOUND for unknown names. */
GENERIC_API GENERIC_NODISCARD int gcie_illuminant_nm(const char *name, GSpectrumNM *out);
/** Planck blackbody at temperature K, normalised to Y = 1. */
GENERIC_API void gcie_blackbody_nm(double kelvin, GSpectrumNM *out);
/** Fills c (allocated in its model) with a named light as a light (GCOLOR_LIGHT, Y = 1): a CIE illuminant
 * gcie_illuminant_name lists, or `blackbody K` (a temperature in kelvin, 100..100000). c NULL: only checks the name.
 * G_OK, G_ERR_NOTFOUND with a message naming the name and listing the known ones, G_ERR_INVALID for a bad
 * temperature, or the model's error. */
GENERIC_API GENERIC_NODISCARD int gcolor_named_light(GColor *c, const char *name, GError *err);
/** Luminance weight of an nm sample: ybar / sum(ybar), so the weights sum to 1. */
GENERIC_API double gcie_luminance_weight(int nm_index);

#ifdef __cplusplus
}
#endif
#endif
