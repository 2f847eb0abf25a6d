/* batch_rows.h - what the batch functions share (batch_rows.c): the loop over rows with OpenMP and the lowest
 * failing row, the checks of a row's numbers, and writing a colour result. */
#ifndef GENERIC_BATCH_ROWS_H
#define GENERIC_BATCH_ROWS_H

#include "generic/batch.h"

/** One row of a batch: its index and the calling thread's arena (a mark is taken before and released after).
 * Returns G_OK or a status; *what may name the argument a failure is about (a static string). */
typedef int (*BatchRowFn)(const void *job, size_t row, GScratch *scratch, const char **what);

/** Runs row(job, i, ...) for i in [0, n) on `threads` threads (0: OpenMP's default). On a failure returns the
 * status of the lowest failing row, with err set to "FN: row I: WHAT: STATUS" (WHAT when the row named one). */
int batch_rows(const char *fn, size_t n, int threads, BatchRowFn row, const void *job, GError *err);

/** 1 when the k doubles at v are all finite. */
int batch_finite(const double *v, int k);

/** Writes the vector colour c as output says into dst (gbatch_output_width doubles); G_ERR_UNSUPPORTED for a
 * matrix asked for as samples. */
int batch_write_color(const GColor *c, GBatchOutput output, double *dst);

/** G_ERR_INVALID with a message naming fn and the argument when output is not one of GBatchOutput, or when an
 * array that must be given is NULL (what: its name). */
int batch_check_output(const char *fn, GBatchOutput output, GError *err);
int batch_require(const char *fn, const void *array, const char *what, GError *err);

#endif
