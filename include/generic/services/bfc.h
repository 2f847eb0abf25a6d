/* bfc.h - reader for measured re-radiation (Donaldson) matrices in the Labsphere BFC-450 text format.
 *
 * Layout: 10 header lines (line 4 is a description such as ";Ciba plastic white # 12"); a grid line
 * `out_min out_max out_step n_in in_min in_step` (emission range and step in nm, number of excitation columns,
 * first excitation and its step); a row of column labels (`r:c:` followed by the excitation wavelengths); one
 * row per emission wavelength: the wavelength, then n_in values; a final `EOD` line. Lines may end in CRLF.
 * Values are kept as measured, small negative noise included. */
#ifndef GENERIC_BFC_H
#define GENERIC_BFC_H

#include "../export.h"
#include <stddef.h>
#include "../color.h"
#include "../error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A matrix read from a BFC file. rerad.data points at values (n_out rows of n_in excitation columns). */
typedef struct GBfcData {
    GReradiation rerad; /**< grid and data, ready for gcolor_from_reradiation */
    float *values;      /**< owned storage, gmem_alloc */
    char description[128]; /**< the header's description line without its ';' (may be empty) */
} GBfcData;

/** Reads a BFC file; on failure out is cleared and err says "file:line:col: message". */
GENERIC_API GENERIC_NODISCARD int gbfc_read(const char *path, GBfcData *out, GError *err);
/** Parses BFC text of len bytes; name is used in messages. */
GENERIC_API GENERIC_NODISCARD int gbfc_parse(const char *text, size_t len, const char *name, GBfcData *out,
                                             GError *err);
/** Frees the values and clears out; a cleared or zeroed struct is a no-op. */
GENERIC_API void gbfc_free(GBfcData *d);

#ifdef __cplusplus
}
#endif
#endif
