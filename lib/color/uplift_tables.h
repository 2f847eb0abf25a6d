/* uplift_tables.h - the layout of the sigmoid uplifting tables that the build generates (build/gen/
 * uplift_tables.c, by scripts/gen_uplift_tables.c). Private to lib/. */
#ifndef GENERIC_LIB_UPLIFT_TABLES_H
#define GENERIC_LIB_UPLIFT_TABLES_H

#include <stddef.h>

/** Tables: sRGB, Rec.2020, ACES2065-1, in that order. */
enum { GUPLIFT_TABLE_SRGB = 0, GUPLIFT_TABLE_REC2020 = 1, GUPLIFT_TABLE_ACES = 2, GUPLIFT_TABLES = 3 };

/** The grid's resolution per axis. */
extern const int guplift_res;
/** The grid's values of the largest component, increasing from 0 to 1 (guplift_res of them). */
extern const float guplift_z[];
/** Three coefficients per node, at guplift_table_index. */
extern const float guplift_coeffs[];

/** The floats of all tables at resolution res. */
static inline size_t guplift_table_floats(int res) { return (size_t)GUPLIFT_TABLES * 3 * res * res * res * 3; }

/** Where the coefficients of node (k: largest component's value z_k, j: the third component's ratio, i: the
 * second's) of slice l (the largest component's index) of table t begin. */
static inline size_t guplift_table_index(int res, int t, int l, int k, int j, int i)
{
    return ((((size_t)t * 3 + l) * res + k) * res + j) * (size_t)res * 3 + (size_t)i * 3;
}

#endif
