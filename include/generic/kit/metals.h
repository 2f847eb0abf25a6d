/* metals.h - measured optical constants (refractive index n, extinction k) of metals and compounds, by name: the
 * table behind `conductor { metal NAME }`. The data are published measurements from the refractiveindex.info database
 * (public domain), every 5 nm from 360 to 830 nm, held constant beyond each material's measured range;
 * docs/reference/metals.md lists each name with its source and range. Built into the library: no file is read. */
#ifndef GENERIC_KIT_METALS_H
#define GENERIC_KIT_METALS_H

#include "../export.h"
#include <stddef.h>
#include "../color.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What the table says of one material. */
typedef struct GMetalInfo {
    const char *name;        /**< the name a file writes: a symbol or formula ("Au", "CuZn", "TiN"), or "steel" */
    const char *description; /**< what it is ("gold", "brass, 70% Cu 30% Zn") */
    const char *source;      /**< the measurement: database entry, first author, year */
    double min_nm, max_nm;   /**< the measured range; the table holds the edge values beyond it */
} GMetalInfo;

/** The number of materials in the table. */
GENERIC_API int gmetal_count(void);

/** The material at index i (0 <= i < gmetal_count(), in alphabetical order of names as C's strcmp orders them):
 * G_OK, or G_ERR_INVALID for an index out of range (out is then cleared). */
GENERIC_API GENERIC_NODISCARD int gmetal_info(int i, GMetalInfo *out);

/** The index of the material called name (ASCII case ignored), or -1. */
GENERIC_API int gmetal_find(const char *name);

/** The names of all materials, separated by ", ", into buf (NUL-terminated, cut at size - 1 characters): for
 * messages that list the known names. Returns the length the whole list needs (as snprintf). */
GENERIC_API size_t gmetal_names(char *buf, size_t size);

/** n and k of material i at wavelength nm: linear between the table's values, the edge values beyond it; NAN for an
 * index out of range. */
GENERIC_API double gmetal_eta_at(int i, double nm);
/** See gmetal_eta_at. */
GENERIC_API double gmetal_k_at(int i, double nm);

/** n and k of material i as colours of eta's model (k of the same model), reduced from the measured curves by
 * gmaterial_complex_index_from_nm (fresnel.h): the rule for unitless quantities (GCOLOR_UNITLESS, color.h), with k
 * matched to the normal-incidence reflectance in a model without wavelength samples.
 * G_ERR_INVALID for an index out of range, G_ERR_MISMATCH for colours of two models. */
GENERIC_API GENERIC_NODISCARD int gmetal_colors(int i, GColor *eta, GColor *k);

#ifdef __cplusplus
}
#endif
#endif
