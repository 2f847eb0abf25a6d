/* spectrum.c - the nm-sampled spectrum colour model: n samples from min_nm to max_nm every step_nm
 * (default 380..780 nm at 5 nm, 81 samples; any step from 1 to 100 nm that divides the range, inside
 * 300..830 nm). A value is n floats, a light or a reflectance; every operation works sample by sample.
 *
 * to_nm interpolates linearly between samples (0 outside the grid); from_nm takes the hat-weighted
 * average around each sample (energy conserving, the identity at 1 nm; see spectral_common.c). to_xyz
 * and brightness use weights computed once from the CIE tables through that same interpolation, so
 * they agree with the nm path while costing n multiply-adds. */
#include "generic/color.h"
#include "colormodels.h"
#include "spectral_common.h"

typedef struct Spectrum {
    GSpectral s;
} Spectrum;

static void spectrum_fini(GColorModel *self)
{
    Spectrum *p = self->priv;
    if (p)
        gspectral_fini(&p->s);
    gmem_free(p);
    self->priv = NULL;
}

static int spectrum_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    GSpectralGrid grid;
    int rc = gspectral_grid_from_options("spectrum", opt, 5.0, GSPECTRAL_MAX_SAMPLES, &grid, err);
    if (rc != G_OK)
        return rc;
    Spectrum *p = gmem_calloc(1, sizeof *p);
    if (!p)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating colour model 'spectrum'");
    self->priv = p;
    self->capacity = grid.n;
    return gspectral_init(self, &p->s, grid, 1, err);
}

const GColorModelClass gcolormodel_spectrum = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "spectrum",
    .description = "spectrum sampled every step_nm (default 380..780 nm at 5 nm)",
    .init = spectrum_init,
    .fini = spectrum_fini,
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
};
