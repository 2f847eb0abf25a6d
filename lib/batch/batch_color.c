/* batch_color.c - colour conversions and generator values over arrays (generic/batch.h). */
#include "batch_rows.h"

#include <math.h>
#include <string.h>

typedef struct ColorJob {
    const GColorModel *m;
    const float *samples_in;
    const double *rgb;
    GColorRole role;
    GBatchOutput output;
    int width;
    double *result;
    float *samples_out;
} ColorJob;

static int color_to_row(const void *job, size_t i, GScratch *s, const char **what)
{
    const ColorJob *j = job;
    const float *src = j->samples_in + (size_t)j->m->nvalues * i;
    for (int k = 0; k < j->m->nvalues; k++)
        if (!isfinite(src[k]))
            return *what = "samples are not finite", G_ERR_INVALID;
    GColor c;
    int rc = gcolor_scratch(&c, j->m, s);
    if (rc != G_OK)
        return rc;
    memcpy(c.v, src, (size_t)j->m->nvalues * sizeof(float));
    rc = j->output == GBATCH_SAMPLES ? batch_write_color(&c, GBATCH_SAMPLES, j->result + (size_t)j->width * i)
         : j->output == GBATCH_XYZ   ? gcolor_to_xyz(&c, j->role, j->result + (size_t)j->width * i)
                                     : gcolor_to_rgb(&c, j->role, j->result + (size_t)j->width * i);
    return rc;
}

static int color_from_row(const void *job, size_t i, GScratch *s, const char **what)
{
    const ColorJob *j = job;
    if (!batch_finite(j->rgb + 3 * i, 3))
        return *what = "rgb is not finite", G_ERR_INVALID;
    GColor c;
    int rc = gcolor_scratch(&c, j->m, s);
    if (rc == G_OK)
        rc = gcolor_from_rgb(&c, j->rgb + 3 * i, j->role);
    if (rc == G_OK && c.kind != GCOLOR_VECTOR)
        rc = G_ERR_UNSUPPORTED;
    if (rc == G_OK)
        memcpy(j->samples_out + (size_t)j->m->nvalues * i, c.v, (size_t)j->m->nvalues * sizeof(float));
    return rc;
}

static int check_color(const char *fn, const GColorModel *m, GColorRole role, GError *err)
{
    if (!m)
        return gerror_set(err, G_ERR_INVALID, "%s: no colour model given", fn);
    if (role != GCOLOR_REFLECTANCE && role != GCOLOR_LIGHT)
        return gerror_set(err, G_ERR_INVALID, "%s: role %d is neither reflectance (0) nor light (1)", fn, (int)role);
    return G_OK;
}

int gbatch_color_to(const GColorModel *m, size_t n, const float *samples, GColorRole role, GBatchOutput output,
                    double *result, int threads, GError *err)
{
    static const char fn[] = "gbatch_color_to";
    int rc = check_color(fn, m, role, err);
    if (rc == G_OK)
        rc = batch_check_output(fn, output, err);
    if (rc == G_OK)
        rc = batch_require(fn, samples, "samples", err);
    if (rc == G_OK)
        rc = batch_require(fn, result, "result", err);
    if (rc != G_OK)
        return rc;
    ColorJob j = {.m = m, .samples_in = samples, .role = role, .output = output,
                  .width = gbatch_output_width(m, output), .result = result};
    return batch_rows(fn, n, threads, color_to_row, &j, err);
}

int gbatch_color_from_rgb(const GColorModel *m, size_t n, const double *rgb, GColorRole role, float *samples,
                          int threads, GError *err)
{
    static const char fn[] = "gbatch_color_from_rgb";
    int rc = check_color(fn, m, role, err);
    if (rc == G_OK)
        rc = batch_require(fn, rgb, "rgb", err);
    if (rc == G_OK)
        rc = batch_require(fn, samples, "samples", err);
    if (rc != G_OK)
        return rc;
    ColorJob j = {.m = m, .rgb = rgb, .role = role, .samples_out = samples};
    return batch_rows(fn, n, threads, color_from_row, &j, err);
}

typedef struct GeneratorJob {
    const GGenerator *g;
    const GColorModel *model;
    const GBatchPoints *pts;
    double *value;
} GeneratorJob;

static int generator_row(const void *job, size_t i, GScratch *s, const char **what)
{
    const GeneratorJob *j = job;
    GSurfPoint sp;
    GError err;
    if (gbatch_surface_point(j->pts, i, NULL, j->model, s, &sp, &err) != G_OK)
        return *what = "a number is not finite or the normal is zero", G_ERR_INVALID;
    j->value[i] = ggenerator_value(j->g, &sp);
    return G_OK;
}

int gbatch_generator_value(const GGenerator *g, const GColorModel *model, const GBatchPoints *pts, double *value,
                           GError *err)
{
    static const char fn[] = "gbatch_generator_value";
    if (!g || !model || !pts)
        return gerror_set(err, G_ERR_INVALID, "%s: no %s given", fn, !g ? "generator" : !model ? "model" : "points");
    int rc = batch_require(fn, pts->normal, "normal", err);
    if (rc == G_OK)
        rc = batch_require(fn, value, "value", err);
    if (rc != G_OK)
        return rc;
    GeneratorJob j = {.g = g, .model = model, .pts = pts, .value = value};
    return batch_rows(fn, pts->n, pts->threads, generator_row, &j, err);
}
