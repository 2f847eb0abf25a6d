/* colorspace.h - input colour spaces of RGB colour literals, and sigmoid uplifting: RGB to smooth spectra.
 *
 * Colour spaces. A literal may give linear RGB in sRGB (Rec.709 primaries), Display P3, Rec.2020, ACES2065-1
 * (AP0) or ACEScg (AP1). The library's colorimetry is CIE 1931 2-degree with the D65 white of sRGB, so every
 * space is taken to XYZ with its own primaries and its white brought to D65 (a Bradford adaptation for the ACES
 * spaces, whose white is near D60): RGB 1 1 1 is D65 white (Y = 1) in every space, the perfect white reflector
 * as a reflectance.
 *
 * Uplifting (Jakob and Hanika, "A Low-Dimensional Function Space for Efficient Spectral Upsampling", 2019). A
 * colour becomes the spectrum s(nm) = scale * S(c0 u^2 + c1 u + c2), u = (nm - 380) / 400, S(x) = 1/2 + x /
 * (2 sqrt(1 + x^2)), times the D65 illuminant (Y = 1 as a light) for a light: smooth, and for a reflectance
 * whose components lie in [0, 1] within [0, 1] at every wavelength. The three coefficients come from tables the
 * build computes with the library's CIE tables (scripts/gen_uplift_tables.c): for sRGB, Rec.2020 and ACES2065-1,
 * each the three slices of Jakob and Hanika's table (by the largest component). A colour is looked up in the
 * narrowest of them in which it has no negative component (Display P3 lies inside Rec.2020, ACEScg inside
 * ACES2065-1), so the spectrum depends on the colour, not on the space it was written in. Three forms: a
 * reflectance within [0, 1] is bounded (scale 1); a reflectance with a component above 1 is scaled (the colour
 * divided by twice its largest component, scale twice that); a light takes the scaled form times D65. */
#ifndef GENERIC_COLORSPACE_H
#define GENERIC_COLORSPACE_H

#include "export.h"
#include "color.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The input colour spaces. */
typedef enum GColorSpace {
    GCOLORSPACE_SRGB = 0,   /**< "srgb" (also "rec709"): IEC 61966-2-1 primaries, D65 */
    GCOLORSPACE_DISPLAY_P3, /**< "display-p3": DCI-P3 primaries, D65 */
    GCOLORSPACE_REC2020,    /**< "rec2020": ITU-R BT.2020 primaries, D65 */
    GCOLORSPACE_ACES2065_1, /**< "aces2065-1": ACES AP0 primaries, white adapted to D65 (Bradford) */
    GCOLORSPACE_ACESCG,     /**< "acescg": ACES AP1 primaries, white adapted to D65 (Bradford) */
    GCOLORSPACE_COUNT
} GColorSpace;

/** The space of a name (case-insensitive), or -1 when no space has it. */
GENERIC_API int gcolorspace_find(const char *name);
/** The name of a space ("srgb", ...), or NULL for a number out of range. */
GENERIC_API const char *gcolorspace_name(int space);
/** The names of all spaces, comma separated, for messages. */
GENERIC_API const char *gcolorspace_names(void);
/** XYZ (D65 white with Y = 1) of linear RGB in space; G_ERR_INVALID for a space out of range. */
GENERIC_API GENERIC_NODISCARD int gcolorspace_to_xyz(int space, const double rgb[3], double xyz[3]);
/** Linear sRGB of linear RGB in space (components outside [0, 1] where the colour lies outside sRGB);
 * G_ERR_INVALID for a space out of range. */
GENERIC_API GENERIC_NODISCARD int gcolorspace_to_srgb(int space, const double rgb[3], double srgb[3]);

/** An uplifted colour: the spectrum scale * S(c0 u^2 + c1 u + c2), times D65 when light is 1. */
typedef struct GUplift {
    double c[3];   /**< polynomial coefficients in u = (nm - 380) / 400 */
    double scale;  /**< 1 for a bounded reflectance */
    int light;     /**< 1: times the D65 illuminant of Y = 1 */
    double xyz[3]; /**< the colour S(...) must reproduce, XYZ as a reflectance under D65 (before scale) */
} GUplift;

/** Uplifts linear sRGB in role by table lookup and trilinear interpolation (no allocation): any finite colour;
 * negative components are taken in the narrowest table space where the colour has none, and a colour outside
 * ACES2065-1 (outside the visible gamut) has its negative AP0 components set to 0. G_ERR_INVALID for a
 * non-finite component. */
GENERIC_API GENERIC_NODISCARD int guplift_from_rgb(const double srgb[3], GColorRole role, GUplift *out);
/** The uplifted spectrum at nm (0 outside 380..780 nm for a light, whose D65 is 0 there). */
GENERIC_API double guplift_value(const GUplift *u, double nm);
/** Uplifts linear sRGB onto the nm exchange grid: the table's coefficients refined against the 1 nm CIE tables,
 * so the spectrum's XYZ is the colour's (a reflectance's within [0, 1] stays there). *delta_e (may be NULL) gets
 * the CIELAB distance left: 0 up to rounding for a colour sigmoid spectra reach, more outside their gamut (a
 * reflectance more saturated than a smooth spectrum can be). G_ERR_INVALID for a non-finite component. */
GENERIC_API GENERIC_NODISCARD int guplift_rgb_to_nm(const double srgb[3], GColorRole role, GSpectrumNM *out,
                                                   double *delta_e);

#ifdef __cplusplus
}
#endif
#endif
