/* batch.h - the material, generator and colour interfaces evaluated over arrays (lib/core/batch.c).
 *
 * For bindings (numpy), measurements and anything else that asks the same question at many places at once: one
 * call evaluates a method for n rows of inputs held in plain row-major arrays of doubles (3 per direction or point,
 * 2 per (u, v) or pair of random numbers) and writes n rows of results, spread over the threads with OpenMP.
 * Each row is computed exactly as one call of the method through the dispatch would compute it (material.h,
 * texture.h), on a surface point filled as gbatch_surface_point documents, with its temporaries on the calling
 * thread's scratch arena (gscratch_thread): nothing is allocated per row, and the results are the same bit for bit
 * whatever the number of threads.
 *
 * Colour results are written as GBatchOutput says: the colour model's own samples (nvalues per row, the floats of
 * a vector value widened to double, which is exact), CIE XYZ or linear sRGB (3 per row; gcolor_to_xyz and
 * gcolor_to_rgb with the role GCOLOR_LIGHT, what a material passes on being light).
 *
 * Errors: G_ERR_INVALID for a NULL array that is required, a non-finite or zero normal or a non-finite number in
 * a row, G_ERR_NOMEM when a thread's arena cannot grow, or the status of a method that fails; err names the
 * function, the argument and the row (the lowest failing row, so the message does not depend on the threads).
 * Rows after a failure may be left unwritten. */
#ifndef GENERIC_BATCH_H
#define GENERIC_BATCH_H

#include "export.h"
#include "color.h"
#include "error.h"
#include "material.h"
#include "surfpoint.h"
#include "texture.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** What a colour result holds per row. */
typedef enum GBatchOutput {
    GBATCH_SAMPLES = 0, /**< the model's nvalues samples of a vector value */
    GBATCH_XYZ = 1,     /**< CIE XYZ (3 per row) */
    GBATCH_RGB = 2      /**< linear sRGB (3 per row) */
} GBatchOutput;

/** The places of a batch: n surface points. Only normal is required; each NULL array takes its default. */
typedef struct GBatchPoints {
    size_t n;              /**< rows */
    const double *normal;  /**< n x 3: the geometric normal (normalised by the batch), facing the viewer */
    const double *point;   /**< n x 3: the point, in world and object space alike (NULL: the origin) */
    const double *uv;      /**< n x 2: the surface parameters (NULL: (0, 0)) */
    const double *dpdu;    /**< n x 3: the tangent along u (NULL: zero, unknown) */
    const double *dpdv;    /**< n x 3: the tangent along v (NULL: zero, unknown) */
    int threads;           /**< threads to use (0: OpenMP's default; 1: the calling thread only) */
} GBatchPoints;

/** The floats per row of a colour result in model m: m->nvalues for GBATCH_SAMPLES, 3 for XYZ and RGB; 0 for an
 * unknown output. */
GENERIC_API int gbatch_output_width(const GColorModel *m, GBatchOutput output);

/** Fills sp for row i of pts as every gbatch_ material function does: gsurfpoint_init with model and scratch, the
 * geometric normal normalised, point and object point, (u, v) and tangents from their arrays (or the defaults of
 * GBatchPoints), surface 0, entering 1; material m, from NULL (vacuum) and to m: the point lies on m's outside. A
 * per-row reference for the batch: a caller evaluating one row through the dispatch on this point gets the
 * batch's numbers. G_ERR_INVALID (naming the row) for a normal that is zero or not finite or another number that
 * is not finite. */
GENERIC_API GENERIC_NODISCARD int gbatch_surface_point(const GBatchPoints *pts, size_t i, const GMaterial *m,
                                                       const GColorModel *model, GScratch *scratch, GSurfPoint *sp,
                                                       GError *err);

/** The light of gbatch_reflection and gbatch_refraction: unit white light, rgb (1, 1, 1) as a light in m's model
 * (what `gmat eval` shines), into out (storage of m's model). */
GENERIC_API GENERIC_NODISCARD int gbatch_white_light(const GColorModel *m, GColor *out);

/** The relative index n(from) / n(to) at sp (the two materials' refraction_index divided), as a renderer hands
 * it to refraction, sample and pdf; out has storage of sp's model. */
GENERIC_API GENERIC_NODISCARD int gbatch_relative_index(GSurfPoint *sp, GColor *out);

/** reflection(sp, in, white, out) for each row: in and out are n x 3 (towards the light, towards the viewer),
 * result n x gbatch_output_width. */
GENERIC_API GENERIC_NODISCARD int gbatch_reflection(const GMaterial *m, const GBatchPoints *pts, const double *in,
                                                    const double *out, GBatchOutput output, double *result,
                                                    GError *err);
/** refraction(sp, in, white, rel_index, out) for each row, rel_index from gbatch_relative_index; as
 * gbatch_reflection. */
GENERIC_API GENERIC_NODISCARD int gbatch_refraction(const GMaterial *m, const GBatchPoints *pts, const double *in,
                                                    const double *out, GBatchOutput output, double *result,
                                                    GError *err);
/** emission(sp, out) for each row: out n x 3, result n x gbatch_output_width. */
GENERIC_API GENERIC_NODISCARD int gbatch_emission(const GMaterial *m, const GBatchPoints *pts, const double *out,
                                                  GBatchOutput output, double *result, GError *err);
/** pdf(sp, in, out, rel_index) for each row into pdf (n). */
GENERIC_API GENERIC_NODISCARD int gbatch_pdf(const GMaterial *m, const GBatchPoints *pts, const double *in,
                                             const double *out, double *pdf, GError *err);
/** sample(sp, out, rel_index, u[0], u[1]) for each row: u is n x 2 in [0, 1). Writes the drawn direction into in
 * (n x 3), its pdf (n), its GSAMPLE_ flags (n; 0 when nothing was drawn, then in and pdf are 0) and the weight
 * (n x gbatch_output_width; black when nothing was drawn). */
GENERIC_API GENERIC_NODISCARD int gbatch_sample(const GMaterial *m, const GBatchPoints *pts, const double *out,
                                                const double *u, GBatchOutput output, double *in, double *pdf,
                                                int *flags, double *weight, GError *err);

/** ggenerator_value(g, sp) for each row into value (n), on points of model (which a generator may read for its
 * temporaries; any model will do for one that reads none). */
GENERIC_API GENERIC_NODISCARD int gbatch_generator_value(const GGenerator *g, const GColorModel *model,
                                                         const GBatchPoints *pts, double *value, GError *err);

/** Converts n vector values of model m (samples: n x m->nvalues floats) with role into output (n x
 * gbatch_output_width doubles; GBATCH_SAMPLES copies them widened). threads as in GBatchPoints. */
GENERIC_API GENERIC_NODISCARD int gbatch_color_to(const GColorModel *m, size_t n, const float *samples,
                                                  GColorRole role, GBatchOutput output, double *result, int threads,
                                                  GError *err);
/** Converts n linear sRGB triples (n x 3) with role into values of model m (samples: n x m->nvalues floats):
 * gcolor_from_rgb for each row. threads as in GBatchPoints. */
GENERIC_API GENERIC_NODISCARD int gbatch_color_from_rgb(const GColorModel *m, size_t n, const double *rgb,
                                                        GColorRole role, float *samples, int threads, GError *err);

#ifdef __cplusplus
}
#endif
#endif
