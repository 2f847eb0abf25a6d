/* colorspace_matrix.h - the colour spaces' matrices (lib/color/colorspace.c), private to lib/ and the table
 * generator. */
#ifndef GENERIC_LIB_COLORSPACE_MATRIX_H
#define GENERIC_LIB_COLORSPACE_MATRIX_H

/** m = the RGB to XYZ matrix of space (D65 white, Y = 1); space must be in range. */
void gcolorspace_matrix(int space, double m[3][3]);
/** out = m^-1; -1 when m is singular. */
int gcolorspace_invert3(const double m[3][3], double out[3][3]);

#endif
