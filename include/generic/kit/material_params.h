/* material_params.h - the parameters of a material: checking a parameter colour and copying it into the
 * material's model, and the default colour a parse routine takes for a parameter the file leaves out.
 *
 * A constructor reports a bad parameter with gerror_set_param (error.h) naming it, as gmaterial_param_color does;
 * when the constructor was called by a parse routine, the reader then places the message at that parameter
 * in the file ("file:line:col: lambert: reflectance has the value ..."). */
#ifndef GENERIC_MATERIAL_PARAMS_H
#define GENERIC_MATERIAL_PARAMS_H

#include "../export.h"
#include "../color.h"
#include "../error.h"
#include "../reader.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Checks a parameter colour and copies it into new heap storage of model m (dst must be freed with gcolor_free, and
 * is left cleared on failure). Every sample must be finite and within the range gmaterial_param_range gives: >= 0 and,
 * with max > 0, <= max, each widened by the conversion error of src's model (gcolormodel_rgb_range), so that every
 * in-gamut colour a file can write is accepted in every model; values within that error are clamped into [0, max].
 * A re-radiation matrix (bispectral, rgb) needs entries >= 0 and its energy per excitation sample, its largest column
 * sum (gmaterial_param_energy), <= max (widened the same way). A colour of another model is converted through the nm
 * spectrum with the given role and clamped the same way. Above max in a band: in a model without matrices (no
 * from_reradiation slot: spectrum9, spectrum) a reflectance that exceeds max in some band is what the fold of
 * a re-radiation matrix looks like (blue light re-radiated as red), and it is
 * accepted, unclamped, when its energy (gmaterial_param_energy) is <= max; in a model with matrices a vector is a plain
 * reflectance and stays <= max in every band, and a matrix needs its energy per excitation sample <= max. The same
 * physical rule in every model: energy is conserved. A complaint reads "<material>: <param> has the value V at
 * sample K (NM nm) (must be ...)" (or names the matrix's entry or energy) and names param (gerror_set_param). */
GENERIC_API GENERIC_NODISCARD int gmaterial_param_color(const GColorModel *m, const GColor *src, GColorRole role,
                                                        double max, const char *material, const char *param,
                                                        GColor *dst, GError *err);
/** The range a parameter colour c of role may take in its own model: [0, max] (max <= 0: no upper bound)
 * widened on both sides by the model's conversion error (gcolormodel_rgb_range) for a colour of size max (for
 * max <= 0, of c's largest RGB component), plus float rounding. *hi is INFINITY without an upper bound. */
GENERIC_API GENERIC_NODISCARD int gmaterial_param_range(const GColor *c, GColorRole role, double max, double *lo,
                                                        double *hi);
/** The energy a reflectance sends out per unit arriving, under equal-energy light: a vector, the mean of its
 * reflectance spectrum (gcolor_to_nm) over GNM_MIN..GNM_MAX; a re-radiation matrix, its largest column sum (all
 * it sends out, over every emission sample, per unit arriving at one excitation sample; that sample in *at,
 * which may be NULL). Energy conservation is this <= 1. */
GENERIC_API double gmaterial_param_energy(const GColor *c, int *at);
/** 1 when a vector reflectance c that exceeds hi in some band may be the fold of re-radiation: c's model has
 * no matrices (no from_reradiation slot) and c's energy (gmaterial_param_energy) is <= hi; else 0. */
GENERIC_API int gmaterial_param_fold_ok(const GColor *c, double hi);
/** Checks a sum of a material's reflectances in its own model (phong's kd + ks + mirror: all that one light
 * leaves as) against energy conservation, the rule gmaterial_param_color applies to one parameter with max 1: a vector
 * at most 1 in every sample within the model's conversion error (gmaterial_param_range), or whose linear sRGB as a
 * reflectance is at most 1 (colours uplifted one by one by the sigmoid uplift, which is not linear, may add up above
 * 1 at some samples where their RGB sum is within 1), or above it only as a fold (gmaterial_param_fold_ok); a
 * re-radiation matrix (a vector added to a matrix is one, on its diagonal) at most 1 in
 * its energy per excitation sample, its largest column sum (gmaterial_param_energy), light re-radiated into other
 * samples included. G_ERR_INVALID otherwise: "<material>: <what> is V at sample K; it must not exceed 1 (energy
 * conservation)" for a vector, with no parameter named (the sum is none); "<material>: <what> is a re-radiation
 * matrix that sends out E of the light arriving at excitation sample K (NM nm) (must be <= 1: energy is
 * conserved)" for a matrix, naming param (the parameter that re-radiates). */
GENERIC_API GENERIC_NODISCARD int gmaterial_param_check_sum(const GColor *sum, const char *material, const char *what,
                                                      const char *param, GError *err);
/** Largest sample of a vector value (its index in *at, may be NULL), the brightness of a matrix. */
GENERIC_API double gmaterial_param_max(const GColor *c, int *at);
/** For a parse routine: unless c already holds a colour (one the file gave), makes c the grey `grey` (an sRGB
 * triple of that value, read in role) in the file's colour model, in new storage (free with gcolor_free). */
GENERIC_API GENERIC_NODISCARD int gmaterial_param_default(GReader *r, double grey, GColorRole role, GColor *c,
                                                          GError *err);

/** A constructor of a material whose one parameter is a colour (e.g. glambert_create, gmirror_create). */
typedef int (*GMaterialOneColorCreate)(const GColorModel *model, const GColor *color, GMaterial **out, GError *err);
/** The whole parse routine of a material written `NAME { KEY COLOR }`: reads the optional block (KEY is its only
 * parameter), gives the colour the grey `grey` in role when the file leaves it out (gmaterial_param_default), and
 * makes the material with create in the file's model into *object. KEY may be textured (kit/texparam.h:
 * `image { ... }` or `mix { ... }`): create then checks each extreme the texture can take, and the material made
 * with the unit colour is scaled by the texture's colour at each point (gtexparam_one_color_material), which is
 * the textured parameter for a material whose results are linear in its colour, as a one-colour material's are. */
GENERIC_API GENERIC_NODISCARD int gmaterial_param_parse_one_color(GReader *r, const char *key, double grey,
                                                                  GColorRole role, GMaterialOneColorCreate create,
                                                                  void **object, GError *err);

#ifdef __cplusplus
}
#endif
#endif
