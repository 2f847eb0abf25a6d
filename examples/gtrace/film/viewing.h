/* viewing.h - the viewing illuminant (--illuminant): the light the film takes as white. The rendered XYZ is
 * adapted from that light's white to the output colour space's (sRGB, D65) by the Bradford transform before it is
 * encoded, so that a white reflectance lit by it comes out neutral (viewing.c). */
#ifndef GTRACE_VIEWING_H
#define GTRACE_VIEWING_H

#include <generic/color.h>
#include <generic/error.h>

/** Reads a viewing illuminant's name into its spectrum: a CIE illuminant gcie_illuminant_nm knows (A, D50, F11,
 * LED-B1, ...) or `blackbody K` (a temperature in kelvin, 100..100000). G_OK, or G_ERR_NOTFOUND with a message
 * naming the unknown name and listing the known ones, G_ERR_INVALID for a blackbody temperature out of range. */
int viewing_illuminant_nm(const char *name, GSpectrumNM *out, GError *err);

/** The 3x3 matrix (row by row) that takes XYZ seen under the light `white` (an nm spectrum, any scale) to XYZ seen
 * under D65, the white of linear sRGB (gcie_xyz_to_rgb maps it to r = g = b), by the Bradford cone response: the
 * light's white as model m has it (gcolor_from_nm as a light, then gcolor_to_xyz), so that the model's own white
 * becomes exactly neutral; the luminance of the white is kept. G_OK, or the model's error (G_ERR_INVALID for a
 * white whose XYZ is not positive). */
int viewing_adaptation(const GColorModel *m, const GSpectrumNM *white, double out[9], GError *err);

/** out = M xyz (M row by row); out may alias xyz. */
void viewing_apply(const double M[9], const double xyz[3], double out[3]);

#endif
