/* thinfilm.h - the optics of a thin film for type writers: the Airy sum of the light a film of thickness d and
 * complex index n + ik reflects and transmits between an ambient medium and a substrate, both non-absorbing
 * (Born and Wolf, section 1.6), unpolarised (the mean of s and p), per wavelength; and as colours of any model.
 *
 * With delta = 2 pi d (n + ik) cos(theta_1) / lambda the phase across the film and r_ij, t_ij the Fresnel
 * amplitude coefficients of its two interfaces (s and p polarisation),
 *   r = (r_01 + r_12 e^{2 i delta}) / (1 + r_01 r_12 e^{2 i delta}),   R = |r|^2,
 *   t = t_01 t_12 e^{i delta} / (1 + r_01 r_12 e^{2 i delta}),         T = Re(n_2 cos theta_2) / (n_0 cos theta_0)
 *                                                                           |t|^2 (s; p with the conjugate cosines),
 * the sum of every multiple reflection inside the film in closed form. Without extinction R + T = 1. */
#ifndef GENERIC_KIT_THINFILM_H
#define GENERIC_KIT_THINFILM_H

#include "../color.h"
#include "../export.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest film thickness in nm a type should accept: beyond it the reflectance oscillates faster over the
 * wavelength than the 1 nm exchange grid (GSpectrumNM) resolves, at film indices up to GTHINFILM_MAX_INDEX. */
#define GTHINFILM_MAX_THICKNESS 5000.0
/** Largest film index (real part) and extinction a type should accept. */
#define GTHINFILM_MAX_INDEX 10.0

/** A film: thickness in nm (>= 0), its index n (> 0) and extinction k (>= 0), the ambient medium's index (light
 * arrives from it) and the substrate's (real, > 0). */
typedef struct GThinFilm {
    double thickness;
    double n, k;
    double ambient, substrate;
} GThinFilm;

/** Unpolarised reflectance *r and transmittance *t (into the substrate; either may be NULL) of the film f at
 * wavelength nm, for light arriving in the ambient medium at cos_ambient in (0, 1] from the normal. Total internal
 * reflection at the substrate gives t = 0. */
GENERIC_API void gthinfilm_airy(const GThinFilm *f, double nm, double cos_ambient, double *r, double *t);

/** The film's reflectance and transmittance (either may be NULL) at cos_ambient as colours of their model
 * (GCOLOR_REFLECTANCE): the Airy sum at every nm of GSpectrumNM, handed to the model's conversion from nm, so a
 * sampled-spectrum model gets the sum at its samples (averaged over each sample's hat, as every spectrum it reads)
 * and rgb and spectrum9 its integral over the spectrum against their bands (rgb: the CIE observer under D65). */
GENERIC_API GENERIC_NODISCARD int gthinfilm_color(const GThinFilm *f, double cos_ambient, GColor *reflectance,
                                                  GColor *transmittance);

/* ---- a film tabulated over the angle ---- */

/** Nodes a table gets per period of the film's phase over the ambient cosine (GThinFilmTable). */
#define GTHINFILM_TABLE_NODES_PER_CYCLE 128
/** Below this ambient cosine (0.6 degrees from grazing) a table's colours are the exact sum: there a film's
 * reflectance climbs to 1 within a cosine of 1e-3, and even the nodes dense towards grazing keep only within 5e-5. */
#define GTHINFILM_TABLE_COS_MIN 0.01
/** The most nodes a table has; a film that would need more is not tabulated. */
#define GTHINFILM_TABLE_MAX_NODES 4097

/** A film's reflectance and transmittance colours (gthinfilm_color) tabulated over the ambient cosine at creation,
 * for a material whose film is the same at every point: a lookup is a cubic (Catmull-Rom) interpolation of four
 * nodes per sample instead of the Airy sum at every nm and the model's conversion. The nodes are uniform in
 * sqrt(cos), dense towards grazing where the colours change fastest, 2 GTHINFILM_TABLE_NODES_PER_CYCLE per period of
 * the phase 4 pi d n_1 cos(theta_1) / lambda at 380 nm (and 33 more), a row beyond an end extrapolated from the three
 * nearest: within 2e-6 of the exact colours from GTHINFILM_TABLE_COS_MIN to normal incidence (measured on a fine
 * grid of cosines in spectrum; tests/test_thinfilm.c: 1.2e-6 against the closed form in spectrum at 1 nm, films of 0
 * to 1000 nm, 0 to 80 degrees, as the exact sum's float colours), the exact sum below it; exact at the nodes, normal
 * incidence among them. */
typedef struct GThinFilmTable GThinFilmTable;

/** Tabulates the film f for colours of model into *out. G_ERR_UNSUPPORTED (nothing made) where a table would not be
 * exact enough: a film index n below the ambient's or a substrate index below it (total internal reflection inside
 * the range of angles bends the curves), more than GTHINFILM_TABLE_MAX_NODES nodes, or a model whose values are not
 * plain samples; G_ERR_NOMEM, or the memory budget's status when it refuses the table's bytes (memory.h: the
 * thickness sizes it), until gthinfilm_table_destroy. */
GENERIC_API GENERIC_NODISCARD int gthinfilm_table_create(const GThinFilm *f, const GColorModel *model,
                                                         GThinFilmTable **out);

/** Frees a table; NULL is a no-op. */
GENERIC_API void gthinfilm_table_destroy(GThinFilmTable *t);

/** 1 when t was made for exactly the film f (every field equal), so that its colours are f's. */
GENERIC_API int gthinfilm_table_matches(const GThinFilmTable *t, const GThinFilm *f);

/** The tabulated reflectance and transmittance (either may be NULL) at cos_ambient, clamped to [0, 1], into colours
 * of the table's model. G_ERR_MISMATCH for a colour of another model. */
GENERIC_API GENERIC_NODISCARD int gthinfilm_table_color(const GThinFilmTable *t, double cos_ambient,
                                                        GColor *reflectance, GColor *transmittance);

#ifdef __cplusplus
}
#endif
#endif
