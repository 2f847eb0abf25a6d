/* viewing.h - the viewing illuminant (--illuminant): the light the film takes as white. The rendered XYZ is
 * adapted from that light's white to the output colour space's (sRGB, D65) by the Bradford transform before it is
 * encoded, so that a white reflectance lit by it comes out neutral (viewing.c). */
#ifndef GTRACE_VIEWING_H
#define GTRACE_VIEWING_H

#include <generic/color.h>
#include <generic/error.h>

/** The 3x3 matrix (row by row) that takes XYZ seen under the light `name` (a CIE illuminant or `blackbody K`:
 * gcolor_named_light) to XYZ seen under D65, the white of linear sRGB (gcie_xyz_to_rgb maps it to equal
 * components), by the Bradford cone response: the light's white as model m has it (gcolor_named_light, then
 * gcolor_to_xyz), so that the model's own white becomes exactly neutral; the luminance of the white is kept. G_OK,
 * gcolor_named_light's error for an unknown name, or the model's (G_ERR_INVALID for a white whose XYZ is not
 * positive). */
int viewing_adaptation(const GColorModel *m, const char *name, double out[9], GError *err);

/** out = M xyz (M row by row); out may alias xyz. */
void viewing_apply(const double M[9], const double xyz[3], double out[3]);

#endif
