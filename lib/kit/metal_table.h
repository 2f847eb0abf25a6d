/* metal_table.h - the measured optical constants behind generic/kit/metals.h: a table written by
 * scripts/gen_metals.py (lib/kit/metal_table.c). */
#ifndef GENERIC_LIB_KIT_METAL_TABLE_H
#define GENERIC_LIB_KIT_METAL_TABLE_H

/** The table's wavelength grid: GMETAL_GRID_N values from GMETAL_GRID_MIN nm every GMETAL_GRID_STEP nm. */
enum { GMETAL_GRID_MIN = 360, GMETAL_GRID_STEP = 5, GMETAL_GRID_N = 95 };

/** One material: its name, what it is, where the data come from, the measured range and n, k on the grid. */
typedef struct GMetalData {
    const char *name;
    const char *description;
    const char *source;
    double min_nm, max_nm;
    float eta[GMETAL_GRID_N];
    float k[GMETAL_GRID_N];
} GMetalData;

extern const GMetalData gmetal_data[];
extern const int gmetal_data_count;

#endif
