/* colorspec.h - colour literals apart from any colour model (GColorSpec): the objects of kind `color`.
 *
 * A literal describes a colour the way a file writes it (an sRGB triple, a spectrum on the 1 nm exchange grid, a
 * monochromatic line, a re-radiation matrix) and is converted into a colour model only where it is used, in the
 * role of that use: a colour named once can serve as a reflectance and as a light, in any model. The literal types
 * (colors/, and a module's colour types) make their spec with gcolorspec_create; reading them is reader.h's
 * (greader_color, greader_color_spec). */
#ifndef GENERIC_COLORSPEC_H
#define GENERIC_COLORSPEC_H

#include "export.h"
#include "color.h"
#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What a colour literal describes, kept apart from any colour model: an entry `color NAME ...` stores one, and
 * each use converts it into the model in the role of that use. Objects of kind GKIND_COLOR are GColorSpecs. */
typedef enum GColorSpecForm {
    GCOLORSPEC_RGB = 0,     /**< linear sRGB triple (reflectance, or a light of D65 chromaticity) */
    GCOLORSPEC_NM,          /**< samples on the 1 nm exchange grid (role free) */
    GCOLORSPEC_LINE,        /**< a monochromatic line: line_nm, line_power (energy, W-like units) */
    GCOLORSPEC_RERADIATION  /**< a re-radiation matrix (a reflectance only) */
} GColorSpecForm;

/** A colour literal. Create with gcolorspec_create, release with gcolorspec_destroy. */
typedef struct GColorSpec {
    int form;          /**< a GColorSpecForm */
    double scale;      /**< multiplies the value (1 for a plain literal) */
    double rgb[3];     /**< GCOLORSPEC_RGB */
    GSpectrumNM nm;    /**< GCOLORSPEC_NM */
    double line_nm;    /**< GCOLORSPEC_LINE: wavelength in nm */
    double line_power; /**< GCOLORSPEC_LINE: radiant power of the line */
    GReradiation rerad; /**< GCOLORSPEC_RERADIATION; rerad.data points at owned_data */
    float *owned_data;  /**< matrix storage owned by the spec (gmem_alloc) */
} GColorSpec;

/** A new spec (form RGB, black, scale 1); NULL when out of memory. */
GENERIC_API GColorSpec *gcolorspec_create(void);
/** Frees a spec and its matrix (returning the matrix's bytes to the memory budget); NULL is a no-op. */
GENERIC_API void gcolorspec_destroy(GColorSpec *s);
/** Makes s a re-radiation matrix m whose storage data (m->n_in x m->n_out floats from gmem_alloc) s then owns,
 * reserving its bytes against the memory budget (generic/memory.h) until gcolorspec_destroy. G_OK, or G_ERR_NOMEM
 * naming `what` and the budget's figures, with data freed and s unchanged. Every owned_data is attached this way. */
GENERIC_API GENERIC_NODISCARD int gcolorspec_own_matrix(GColorSpec *s, const GReradiation *m, float *data,
                                                        const char *what, GError *err);
/** Deep copy of src into a new spec. */
GENERIC_API GENERIC_NODISCARD int gcolorspec_copy(const GColorSpec *src, GColorSpec **out, GError *err);
/** Converts a spec in a role into out (which has storage of the target model). A line is spread over a
 * triangle one sample step wide on each side in spectral models (1 nm on the exchange grid, at most 10 nm), so its
 * energy and centre survive any sampling (spectrum9 keeps its XYZ instead); a re-radiation matrix used as a light
 * is G_ERR_INVALID. */
GENERIC_API GENERIC_NODISCARD int gcolorspec_to_color(const GColorSpec *s, GColorRole role, GColor *out, GError *err);
#ifdef __cplusplus
}
#endif
#endif
