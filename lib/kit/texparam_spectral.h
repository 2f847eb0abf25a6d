/* texparam_spectral.h - the texels of a spectral OpenEXR (the layout of Fichet, Pacanowski and Wilkie 2021,
 * generic/services/image.h) looked up at (s, t) as nm spectra (texparam_spectral.c), for texparam_image.c: the
 * image node and textured colours read such a file through it. */
#ifndef GENERIC_KIT_TEXPARAM_SPECTRAL_H
#define GENERIC_KIT_TEXPARAM_SPECTRAL_H

#include "generic/color.h"
#include "generic/services/texsys.h"

/** The spectra of one layer of a file, at the file's wavelengths (floats), and the weights that resample them to the
 * nm exchange grid. */
typedef struct GTexSpectral GTexSpectral;

/** Opens the spectral channels of path for role: the reflective layer (T.<nm>nm) for GCOLOR_REFLECTANCE, the
 * emissive one (S0.<nm>nm) for GCOLOR_LIGHT, and the other layer when the file has none of that one (values are
 * role free, as an RGB image's serve either role). G_OK with *out NULL when path is not an OpenEXR file (its first
 * four bytes) or has no spectral channel: the caller reads it as an RGB image. G_OK with *out set when it has;
 * G_ERR_IO naming the file when its spectral channels are refused (gimage_read_spectra_layer: names, duplicated
 * wavelengths, too many, a damaged file), when it has more than GTEXSYS_MAX_PIXELS texels, or when a value is NaN,
 * infinite or negative (the texel, the wavelength and the value named); G_ERR_NOMEM when the values do not fit the
 * memory budget, which holds them until gtexparam_spectral_free. */
int gtexparam_spectral_open(const char *path, GColorRole role, GTexSpectral **out, GError *err);

/** Frees the texels and returns their memory to the budget; NULL is a no-op. */
void gtexparam_spectral_free(GTexSpectral *sp);

/** The spectrum at (s, t) (s to the right, t down: t = 0 is the top row), bilinear over the four nearest texel
 * centres (texel (x, y) centred at ((x + 0.5) / width, (y + 0.5) / height)) with the wraps along s and t, resampled
 * to the nm grid: linear between the file's wavelengths, the edge value beyond them. No allocation. */
void gtexparam_spectral_lookup(const GTexSpectral *sp, GTexWrap swrap, GTexWrap twrap, double s, double t,
                               GSpectrumNM *out);

/** The largest value of every wavelength over all texels, on the nm grid: G_OK, or G_ERR_NOMEM (out untouched). */
int gtexparam_spectral_max(const GTexSpectral *sp, GSpectrumNM *out);

/** The largest linear sRGB value of each channel over the texels (each texel's spectrum as a reflectance, or as a
 * light for the emissive layer, through CIE 1931 XYZ), for gtexparam_image_channel_max. */
void gtexparam_spectral_rgb_max(const GTexSpectral *sp, double rgb[3]);

/** The role the texels were read for (the layer: GCOLOR_REFLECTANCE reflective, GCOLOR_LIGHT emissive). */
GColorRole gtexparam_spectral_role(const GTexSpectral *sp);

#endif
