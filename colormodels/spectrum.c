/* spectrum.c - the nm-sampled spectrum colour model: n samples from min_nm to max_nm every step_nm
 * (default 380..780 nm at 5 nm, 81 samples; any step from 1 to 100 nm that divides the range, inside
 * 300..830 nm). A value is n floats, a light or a reflectance; every operation works sample by sample.
 *
 * to_nm interpolates linearly between samples (0 outside the grid); from_nm takes the hat-weighted
 * average around each sample (energy conserving, the identity at 1 nm; see include/generic/kit/spectral.h). to_xyz
 * and brightness use weights computed once from the CIE tables through that same interpolation, so
 * they agree with the nm path while costing n multiply-adds. Every operation is the kit's (gspectral_*), as a
 * module written on the kit has them, on any grid. */
#include "generic/plugin.h"
#include "generic/kit/spectral.h"

/* The model's priv struct is a plain GSpectral. */
static int spectrum_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    return gspectral_model_init(self, opt, 5.0, GSPECTRAL_MAX_SAMPLES, 0, err);
}

static const GColorModelClass gcolormodel_spectrum = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "spectrum",
    .description = "spectrum sampled every step_nm (default 380..780 nm at 5 nm)",
    .init = spectrum_init,
    .fini = gspectral_model_fini,
    .black = gspectral_black,
    .add = gspectral_add,
    .mul = gspectral_mul,
    .scale = gspectral_scale,
    .div = gspectral_div,
    .pow = gspectral_pow,
    .brightness = gspectral_brightness,
    .to_nm = gspectral_to_nm,
    .from_nm = gspectral_from_nm,
    .to_xyz = gspectral_to_xyz,
    .from_rgb = gspectral_from_rgb,
    .band_count = gspectral_band_count,
    .band_mask = gspectral_band_mask,
    .band_value = gspectral_band_value,
};

static const GParamInfo spectrum_params[] = {
    {"step", GPARAM_NAMED, "number", "5", "[1, 100], a whole number of steps from min to max",
     "the spacing of the samples, in nm"},
    {"min", GPARAM_NAMED, "number", "380", "[300, 830], below max", "the wavelength of the first sample, in nm"},
    {"max", GPARAM_NAMED, "number", "780", "[300, 830], at most 1023 steps above min",
     "the wavelength of the last sample, in nm"},
    {"uplift", GPARAM_NAMED, "choice", "sigmoid", "sigmoid, basis",
     "how RGB colours become spectra: sigmoid (smooth, a reflectance within [0, 1]) or basis (the exact linear basis)"},
    {NULL},
};

GENERIC_TYPE_PARAMS(spectrum, GKIND_COLORMODEL, &gcolormodel_spectrum, NULL, NULL, spectrum_params);
