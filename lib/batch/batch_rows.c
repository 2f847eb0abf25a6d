/* batch_rows.c - the loop every batch function runs: rows spread over OpenMP threads, each with the thread's own
 * scratch arena, and the lowest failing row reported whatever the threads did. */
#include "batch_rows.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>

int batch_rows(const char *fn, size_t n, int threads, BatchRowFn row, const void *job, GError *err)
{
    size_t bad_row = SIZE_MAX;
    int bad_rc = G_OK;
    const char *bad_what = NULL;
    int nthreads = threads > 0 ? threads : omp_get_max_threads();
    if ((size_t)nthreads > n)
        nthreads = n > 0 ? (int)n : 1;
    #pragma omp parallel for schedule(static) num_threads(nthreads)
    for (size_t i = 0; i < n; i++) {
        GScratch *s = gscratch_thread();
        const char *what = NULL;
        int rc = G_ERR_NOMEM;
        if (s) {
            GScratchMark mark = gscratch_mark(s);
            rc = row(job, i, s, &what);
            gscratch_release(s, mark);
        }
        if (rc < 0) {
            #pragma omp critical(gbatch_failure)
            if (i < bad_row) {
                bad_row = i;
                bad_rc = rc;
                bad_what = what;
            }
        }
    }
    if (bad_rc == G_OK)
        return G_OK;
    if (bad_what)
        return gerror_set(err, bad_rc, "%s: row %zu: %s: %s", fn, bad_row, bad_what, gstatus_string(bad_rc));
    return gerror_set(err, bad_rc, "%s: row %zu: %s", fn, bad_row, gstatus_string(bad_rc));
}

int batch_finite(const double *v, int k)
{
    for (int j = 0; j < k; j++)
        if (!isfinite(v[j]))
            return 0;
    return 1;
}

int batch_write_color(const GColor *c, GBatchOutput output, double *dst)
{
    switch (output) {
    case GBATCH_SAMPLES:
        if (c->kind != GCOLOR_VECTOR)
            return G_ERR_UNSUPPORTED;
        for (int j = 0; j < c->model->nvalues; j++)
            dst[j] = c->v[j];
        return G_OK;
    case GBATCH_XYZ:
        return gcolor_to_xyz(c, GCOLOR_LIGHT, dst);
    case GBATCH_RGB:
        return gcolor_to_rgb(c, GCOLOR_LIGHT, dst);
    }
    return G_ERR_INVALID;
}

int batch_check_output(const char *fn, GBatchOutput output, GError *err)
{
    if (output != GBATCH_SAMPLES && output != GBATCH_XYZ && output != GBATCH_RGB)
        return gerror_set(err, G_ERR_INVALID, "%s: output %d is none of samples (0), xyz (1), rgb (2)", fn,
                          (int)output);
    return G_OK;
}

int batch_require(const char *fn, const void *array, const char *what, GError *err)
{
    return array ? G_OK : gerror_set(err, G_ERR_INVALID, "%s: no %s array given", fn, what);
}

int gbatch_output_width(const GColorModel *m, GBatchOutput output)
{
    switch (output) {
    case GBATCH_SAMPLES: return m ? m->nvalues : 0;
    case GBATCH_XYZ:
    case GBATCH_RGB: return 3;
    }
    return 0;
}
