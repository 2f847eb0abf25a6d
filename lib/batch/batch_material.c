/* batch_material.c - the material methods over arrays (generic/batch.h): the surface point of a row, the white
 * light and relative index every row shares the definition of, and one row function per method. */
#include "batch_rows.h"

#include "generic/vec.h"

#include <string.h>

static GVec3 vec_at(const double *a, size_t i) { return gvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

static void put_vec(double *a, size_t i, GVec3 v)
{
    a[3 * i] = v.x;
    a[3 * i + 1] = v.y;
    a[3 * i + 2] = v.z;
}

/* The row's numbers checked: NULL, or the name of the argument that is not finite (or a zero normal). */
static const char *bad_point_input(const GBatchPoints *pts, size_t i)
{
    const double *n = pts->normal + 3 * i;
    if (!batch_finite(n, 3) || (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0))
        return "normal is zero or not finite";
    if (pts->point && !batch_finite(pts->point + 3 * i, 3))
        return "point is not finite";
    if (pts->uv && !batch_finite(pts->uv + 2 * i, 2))
        return "uv is not finite";
    if (pts->dpdu && !batch_finite(pts->dpdu + 3 * i, 3))
        return "dpdu is not finite";
    if (pts->dpdv && !batch_finite(pts->dpdv + 3 * i, 3))
        return "dpdv is not finite";
    return NULL;
}

/* gbatch_surface_point without the checks (the row functions checked already). */
static void fill_point(const GBatchPoints *pts, size_t i, const GMaterial *m, const GColorModel *model,
                       GScratch *scratch, GSurfPoint *sp)
{
    gsurfpoint_init(sp, model, scratch);
    sp->geometric_normal = gvec3_normalize(vec_at(pts->normal, i));
    if (pts->point)
        sp->point = sp->object_point = vec_at(pts->point, i);
    if (pts->uv) {
        sp->u = pts->uv[2 * i];
        sp->v = pts->uv[2 * i + 1];
    }
    if (pts->dpdu)
        sp->dpdu = vec_at(pts->dpdu, i);
    if (pts->dpdv)
        sp->dpdv = vec_at(pts->dpdv, i);
    sp->material = sp->to = m;
}

int gbatch_surface_point(const GBatchPoints *pts, size_t i, const GMaterial *m, const GColorModel *model,
                         GScratch *scratch, GSurfPoint *sp, GError *err)
{
    if (!pts || !pts->normal || i >= pts->n || !model || !scratch || !sp)
        return gerror_set(err, G_ERR_INVALID, "gbatch_surface_point: no points, normals, model or arena, or row "
                          "%zu out of range", i);
    const char *bad = bad_point_input(pts, i);
    if (bad)
        return gerror_set(err, G_ERR_INVALID, "gbatch_surface_point: row %zu: %s", i, bad);
    fill_point(pts, i, m, model, scratch, sp);
    return G_OK;
}

int gbatch_white_light(const GColorModel *m, GColor *out)
{
    (void)m;
    const double one[3] = {1.0, 1.0, 1.0};
    return gcolor_from_rgb(out, one, GCOLOR_LIGHT);
}

int gbatch_relative_index(GSurfPoint *sp, GColor *out)
{
    GColor to;
    int rc = gcolor_scratch(&to, sp->model, sp->scratch);
    if (rc == G_OK)
        rc = gmaterial_refraction_index(sp->from, sp, out);
    if (rc == G_OK)
        rc = gmaterial_refraction_index(sp->to, sp, &to);
    return rc == G_OK ? gcolor_div(out, out, &to) : rc;
}

/* What every material row needs: the method's arrays, the shared white light. */
typedef struct MaterialJob {
    const GMaterial *m;
    const GBatchPoints *pts;
    const double *in, *out, *u;
    GBatchOutput output;
    int width;          /* doubles per colour result */
    const GColor *white;
    double *result, *pdf; /* result: colours (reflection, refraction, emission, the sample's weight) */
    double *dirs;       /* sample: the drawn directions */
    int *flags;
    int method;         /* one of the enum below */
} MaterialJob;

enum { REFLECTION, REFRACTION, EMISSION, PDF, SAMPLE };

/* The row's point and the checks of its directions; G_OK or G_ERR_INVALID with *what set. */
static int begin_row(const MaterialJob *j, size_t i, GScratch *s, GSurfPoint *sp, const char **what)
{
    if ((*what = bad_point_input(j->pts, i)))
        return G_ERR_INVALID;
    if (j->in && !batch_finite(j->in + 3 * i, 3))
        return *what = "in is not finite", G_ERR_INVALID;
    if (j->out && !batch_finite(j->out + 3 * i, 3))
        return *what = "out is not finite", G_ERR_INVALID;
    if (j->u) {
        const double *u = j->u + 2 * i;
        if (!(u[0] >= 0.0 && u[0] < 1.0 && u[1] >= 0.0 && u[1] < 1.0))
            return *what = "u is outside [0, 1)", G_ERR_INVALID;
    }
    fill_point(j->pts, i, j->m, j->m->model, s, sp);
    return G_OK;
}

static int material_row(const void *job, size_t i, GScratch *s, const char **what)
{
    const MaterialJob *j = job;
    GSurfPoint sp;
    int rc = begin_row(j, i, s, &sp, what);
    if (rc != G_OK)
        return rc;
    const GColorModel *model = j->m->model;
    GColor c, ri;
    if ((rc = gcolor_scratch_uncleared(&c, model, s)) != G_OK)
        return rc;
    if (j->method != REFLECTION && j->method != EMISSION &&
        ((rc = gcolor_scratch(&ri, model, s)) != G_OK || (rc = gbatch_relative_index(&sp, &ri)) != G_OK))
        return rc;
    double *res = j->result ? j->result + (size_t)j->width * i : NULL;
    GVec3 out = vec_at(j->out, i);
    switch (j->method) {
    case REFLECTION:
        rc = gmaterial_reflection(j->m, &sp, vec_at(j->in, i), j->white, out, &c);
        break;
    case REFRACTION:
        rc = gmaterial_refraction(j->m, &sp, vec_at(j->in, i), j->white, &ri, out, &c);
        break;
    case EMISSION:
        rc = gmaterial_emission(j->m, &sp, out, &c);
        break;
    case PDF:
        j->pdf[i] = gmaterial_pdf(j->m, &sp, vec_at(j->in, i), out, &ri);
        return G_OK;
    default: {
        GMaterialSample smp = {{0.0, 0.0, 0.0}, 0.0, 0};
        rc = gmaterial_sample(j->m, &sp, out, &ri, j->u[2 * i], j->u[2 * i + 1], &smp, &c);
        if (rc == 0) { /* nothing drawn */
            smp = (GMaterialSample){{0.0, 0.0, 0.0}, 0.0, 0};
            gcolor_black(&c);
        }
        if (rc >= 0) {
            put_vec(j->dirs, i, smp.in);
            j->pdf[i] = smp.pdf;
            j->flags[i] = smp.flags;
            rc = G_OK;
        }
        break;
    }
    }
    return rc == G_OK ? batch_write_color(&c, j->output, res) : rc;
}

/* Checks the common arguments, makes the white light when the method shines it, and runs the rows. */
static int run_material(const char *fn, MaterialJob *j, GError *err)
{
    if (!j->m || !j->pts)
        return gerror_set(err, G_ERR_INVALID, "%s: no %s given", fn, j->m ? "points" : "material");
    int rc = batch_check_output(fn, j->output, err);
    if (rc == G_OK)
        rc = batch_require(fn, j->pts->normal, "normal", err);
    if (rc == G_OK && (j->method == REFLECTION || j->method == REFRACTION || j->method == PDF))
        rc = batch_require(fn, j->in, "in", err);
    if (rc == G_OK)
        rc = batch_require(fn, j->out, "out", err);
    if (rc == G_OK && j->method != PDF)
        rc = batch_require(fn, j->result, j->method == SAMPLE ? "weight" : "result", err);
    if (rc == G_OK && (j->method == PDF || j->method == SAMPLE))
        rc = batch_require(fn, j->pdf, "pdf", err);
    if (rc == G_OK && j->method == SAMPLE) {
        rc = batch_require(fn, j->u, "u", err);
        if (rc == G_OK)
            rc = batch_require(fn, j->dirs, "in", err);
        if (rc == G_OK)
            rc = batch_require(fn, j->flags, "flags", err);
    }
    if (rc != G_OK)
        return rc;
    j->width = gbatch_output_width(j->m->model, j->output);
    GColor white = {0};
    if (j->method == REFLECTION || j->method == REFRACTION) {
        rc = gcolor_alloc(&white, j->m->model);
        if (rc == G_OK)
            rc = gbatch_white_light(j->m->model, &white);
        if (rc != G_OK) {
            gcolor_free(&white);
            return gerror_set(err, rc, "%s: the white light: %s", fn, gstatus_string(rc));
        }
        j->white = &white;
    }
    rc = batch_rows(fn, j->pts->n, j->pts->threads, material_row, j, err);
    gcolor_free(&white);
    return rc;
}

int gbatch_reflection(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out,
                      GBatchOutput output, double *result, GError *err)
{
    MaterialJob j = {.m = m, .pts = pts, .in = in, .out = out, .output = output, .result = result,
                     .method = REFLECTION};
    return run_material("gbatch_reflection", &j, err);
}

int gbatch_refraction(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out,
                      GBatchOutput output, double *result, GError *err)
{
    MaterialJob j = {.m = m, .pts = pts, .in = in, .out = out, .output = output, .result = result,
                     .method = REFRACTION};
    return run_material("gbatch_refraction", &j, err);
}

int gbatch_emission(const GMaterial *m, const GBatchPoints *pts, const double *out, GBatchOutput output,
                    double *result, GError *err)
{
    MaterialJob j = {.m = m, .pts = pts, .out = out, .output = output, .result = result, .method = EMISSION};
    return run_material("gbatch_emission", &j, err);
}

int gbatch_pdf(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out, double *pdf,
               GError *err)
{
    MaterialJob j = {.m = m, .pts = pts, .in = in, .out = out, .pdf = pdf, .method = PDF};
    return run_material("gbatch_pdf", &j, err);
}

int gbatch_sample(const GMaterial *m, const GBatchPoints *pts, const double *out, const double *u,
                  GBatchOutput output, double *in, double *pdf, int *flags, double *weight, GError *err)
{
    MaterialJob j = {.m = m, .pts = pts, .out = out, .u = u, .output = output, .result = weight, .pdf = pdf,
                     .dirs = in, .flags = flags, .method = SAMPLE};
    return run_material("gbatch_sample", &j, err);
}
