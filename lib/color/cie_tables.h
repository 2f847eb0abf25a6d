/* cie_tables.h - CIE tables at 1 nm over 380..780 nm and the spectral primary basis at 5 nm
 * (lib/color/cie_tables.c, generated from colord-data by scripts/gen_cie_tables.py). Private to lib/. */
#ifndef GENERIC_LIB_CIE_TABLES_H
#define GENERIC_LIB_CIE_TABLES_H

/** Samples of the 1 nm tables. */
#define GCIE_N1 401
/** Samples of the 5 nm basis. */
#define GCIE_N5 81

extern const float gcie_xbar[GCIE_N1], gcie_ybar[GCIE_N1], gcie_zbar[GCIE_N1];
extern const float gcie_d65[GCIE_N1], gcie_a[GCIE_N1];
extern const float gcie_basis_r[GCIE_N5], gcie_basis_g[GCIE_N5], gcie_basis_b[GCIE_N5];

#endif
