/* dispersion.h - refraction indices over wavelength for type writers: the named glasses of published dispersion
 * formulas, the index as a colour of a model, and the reader of an `index` value. The formulas themselves
 * (GDispersion, gdispersion_index, gdispersion_check) are declared in materials.h. */
#ifndef GENERIC_KIT_DISPERSION_H
#define GENERIC_KIT_DISPERSION_H

#include "../export.h"
#include "../color.h"
#include "../error.h"
#include "../materials.h"
#include "../reader.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A named glass (or other clear dielectric): its dispersion formula as published and where it holds. */
typedef struct GGlass {
    const char *name;    /**< the name a file writes (`glass BK7`); matched without regard to case, '_' = ' ' */
    const char *product; /**< what the name stands for (e.g. "SCHOTT N-BK7") */
    const char *source;  /**< where the coefficients come from */
    double nm_lo, nm_hi; /**< the wavelength range the source gives the formula for, in nm */
    GDispersion formula; /**< the formula (outside [nm_lo, nm_hi] it is extrapolated) */
} GGlass;

/** The number of named glasses. */
GENERIC_API int gdispersion_glass_count(void);
/** Named glass i (0 <= i < gdispersion_glass_count()), NULL outside that range. */
GENERIC_API const GGlass *gdispersion_glass_at(int i);
/** The glass called name (without regard to case; '_' and ' ' are the same), NULL when there is none. */
GENERIC_API const GGlass *gdispersion_glass_find(const char *name);
/** Writes the names of the glasses as a file writes them ('_' for ' '), separated by ", ", into buf of size bytes
 * (always NUL-terminated, cut when short); returns buf. */
GENERIC_API const char *gdispersion_glass_names(char *buf, size_t size);

/** The index of d as a colour of out's model: spectral models (nsamples > 0) get the nm spectrum of n(lambda)
 * through gcolor_from_nm, the others the three values n(610 nm), n(550 nm), n(465 nm) through gcolor_from_rgb,
 * which rgb stores as they are (an index is no light: integrating it against an illuminant would mix it). */
GENERIC_API GENERIC_NODISCARD int gdispersion_color(const GDispersion *d, GColor *out);

/** Reads an index value at the reader's position: `N` (a number in [0.01, 100]), `cauchy A B [C]`,
 * `sellmeier B1 B2 B3 C1 C2 C3` or `glass NAME` (NAME an identifier or a quoted string). A number out of range is
 * refused at the number with the bound named, a formula whose index is not finite and positive over
 * GNM_MIN..GNM_MAX at its last coefficient, an unknown glass at its name with the known names listed. */
GENERIC_API GENERIC_NODISCARD int gdispersion_read(GReader *r, GDispersion *d, GError *err);
/** Reads a glass name (an identifier or a quoted string) and stores its formula in d; an unknown name is refused
 * at the name with the known names listed (what `glass NAME` reads in gdispersion_read). */
GENERIC_API GENERIC_NODISCARD int gdispersion_read_glass(GReader *r, GDispersion *d, GError *err);

#ifdef __cplusplus
}
#endif
#endif
