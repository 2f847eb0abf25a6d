/* material_params.c - material parameters (generic/kit/material_params.h): checking and converting parameter colours,
 * defaults for parameters a file leaves out. */
#include "generic/kit/material_params.h"
#include "generic/kit/texparam.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int value_count(const GColor *c)
{
    return c->kind == GCOLOR_MATRIX ? c->model->capacity : c->model->nvalues;
}

double gmaterial_param_max(const GColor *c, int *at)
{
    if (at)
        *at = 0;
    if (c->kind == GCOLOR_MATRIX)
        return gcolor_brightness(c);
    double mx = -INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        if (c->v[i] > mx) {
            mx = c->v[i];
            if (at)
                *at = i;
        }
    return mx;
}

int gmaterial_param_range(const GColor *c, GColorRole role, double max, double *lo, double *hi)
{
    double rlo, rhi;
    int rc = gcolormodel_rgb_range(c->model, role, &rlo, &rhi);
    if (rc != G_OK)
        return rc;
    double scale = max;
    if (!(max > 0.0)) { /* unbounded: the size of this colour, its largest RGB component */
        double rgb[3] = {0, 0, 0};
        if (c->kind == GCOLOR_VECTOR && (rc = gcolor_to_rgb(c, role, rgb)) != G_OK)
            return rc;
        scale = fmax(0.0, fmax(rgb[0], fmax(rgb[1], rgb[2])));
    }
    /* float rounding of the conversion on top of the model's error */
    double eps = 1e-5 * scale;
    *lo = rlo * scale - eps;
    *hi = max > 0.0 ? fmax(rhi, 1.0) * max + eps : INFINITY;
    return G_OK;
}

double gmaterial_param_energy(const GColor *c, int *at)
{
    const GColorModel *m = c->model;
    if (at)
        *at = 0;
    if (c->kind == GCOLOR_MATRIX) { /* the largest column sum: all that leaves per unit arriving in one sample */
        int n = m->nvalues; /* a matrix is nvalues x nvalues (bispectral's samples, rgb's components) */
        double worst = 0.0;
        for (int i = 0; i < n; i++) {
            double sum = 0.0;
            for (int o = 0; o < n; o++)
                sum += c->v[o * n + i];
            if (sum > worst) {
                worst = sum;
                if (at)
                    *at = i;
            }
        }
        return worst;
    }
    GSpectrumNM s;
    if (gcolor_to_nm(c, GCOLOR_REFLECTANCE, &s) != G_OK)
        return INFINITY;
    double sum = 0.0;
    for (int i = 0; i < GNM_COUNT; i++)
        sum += s.v[i];
    return sum / GNM_COUNT;
}

int gmaterial_param_fold_ok(const GColor *c, double hi)
{
    return c->kind == GCOLOR_VECTOR && !c->model->cls->from_reradiation && gmaterial_param_energy(c, NULL) <= hi;
}

/* " (NNN nm)" for sample k of a spectral model, "" otherwise. */
static void sample_nm(const GColorModel *m, int k, char *buf, size_t size)
{
    if (m->nsamples > 0 && k < m->nsamples)
        snprintf(buf, size, " (%g nm)", m->lambda_min + k * m->lambda_step);
    else
        buf[0] = '\0';
}

/* A re-radiation matrix's energy, its largest column sum (gmaterial_param_energy), against hi: "<material>: <what> is a
 * re-radiation matrix that sends out E of the light arriving at excitation sample K (NM nm) (must be <= max:
 * energy is conserved)", naming param. */
static int check_matrix_energy(const GColor *c, double max, double hi, const char *material, const char *what,
                               const char *param, GError *err)
{
    int col;
    double e = gmaterial_param_energy(c, &col);
    if (!(e > hi))
        return G_OK;
    char where[48];
    sample_nm(c->model, col, where, sizeof where);
    return gerror_set_param(err, G_ERR_INVALID, param,
                            "%s: %s is a re-radiation matrix that sends out %g of the light arriving at excitation "
                            "sample %d%s (must be <= %g: energy is conserved)",
                            material, what, e, col, where, max);
}

/* Checks src against [lo, hi] (vector samples; a matrix's entries >= 0 and its energy per excitation sample
 * <= hi). */
static int check_range(const GColor *src, GColorRole role, double max, const char *material, const char *param,
                       GError *err)
{
    const GColorModel *m = src->model;
    const char *name = gcolormodel_name(m);
    if (src->kind == GCOLOR_MATRIX) {
        int n = m->nvalues;
        for (int i = 0; i < value_count(src); i++)
            if (!isfinite(src->v[i]) || src->v[i] < 0.0f)
                return gerror_set_param(err, G_ERR_INVALID, param,
                                        "%s: %s is a re-radiation matrix with the entry %g at emission sample %d, "
                                        "excitation sample %d (must be finite and >= 0)",
                                        material, param, (double)src->v[i], i / n, i % n);
    } else {
        for (int i = 0; i < m->nvalues; i++)
            if (!isfinite(src->v[i]))
                return gerror_set_param(err, G_ERR_INVALID, param,
                                        "%s: %s has the value %g at sample %d (must be finite and >= 0)", material,
                                        param, (double)src->v[i], i);
    }
    double lo, hi, rlo, rhi;
    int rc = gmaterial_param_range(src, role, max, &lo, &hi);
    if (rc == G_OK)
        rc = gcolormodel_rgb_range(m, role, &rlo, &rhi);
    if (rc != G_OK)
        return gerror_set_param(err, rc, param, "%s: cannot measure the range of %s in model '%s'", material, param,
                                name);
    if (src->kind == GCOLOR_MATRIX)
        return max > 0.0 ? check_matrix_energy(src, max, hi, material, param, param, err) : G_OK;
    char where[48];
    /* above max in a band: in a model without matrices only a fold of re-radiation can be (see the header) */
    double fold_energy = -1.0;
    if (max > 0.0 && role == GCOLOR_REFLECTANCE && !m->cls->from_reradiation)
        fold_energy = gmaterial_param_energy(src, NULL);
    for (int i = 0; i < m->nvalues; i++) {
        double x = src->v[i];
        sample_nm(m, i, where, sizeof where);
        if (x < 0.0 && x < lo) {
            if (rlo == 0.0) /* the model has no conversion error below 0 */
                return gerror_set_param(err, G_ERR_INVALID, param,
                                        "%s: %s has the value %g at sample %d%s (must be finite and >= 0)",
                                        material, param, x, i, where);
            return gerror_set_param(err, G_ERR_INVALID, param,
                                    "%s: %s has the value %g at sample %d%s (must be finite and >= 0, or >= %.3g "
                                    "within the conversion error of model '%s')",
                                    material, param, x, i, where, lo, name);
        }
        if (x > hi && fold_energy >= 0.0 && fold_energy <= hi)
            continue;
        if (x > hi) {
            char bound[160] = "", fold[160] = "";
            if (rhi > 1.0)
                snprintf(bound, sizeof bound, ", or <= %.6g within the conversion error of model '%s'", hi, name);
            if (fold_energy >= 0.0)
                snprintf(fold, sizeof fold, "; above that only as the fold of re-radiation, whose energy under "
                         "equal-energy light, here %g, is <= %.6g", fold_energy, hi);
            return gerror_set_param(err, G_ERR_INVALID, param,
                                    "%s: %s has the value %g at sample %d%s (must be <= %g%s%s)", material, param, x, i,
                                    where, max, bound, fold);
        }
    }
    return G_OK;
}

int gmaterial_param_color(const GColorModel *m, const GColor *src, GColorRole role, double max, const char *material,
                    const char *param, GColor *dst, GError *err)
{
    *dst = (GColor){.model = NULL, .v = NULL, .storage = GCOLOR_STORAGE_NONE};
    if (!src || !src->model || !src->v)
        return gerror_set_param(err, G_ERR_INVALID, param, "%s: %s is missing", material, param);
    int rc = check_range(src, role, max, material, param, err);
    if (rc != G_OK)
        return rc;
    if (gcolor_alloc(dst, m) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for %s", material, param);
    rc = gcolor_convert(dst, src, role);
    if (rc != G_OK) {
        gcolor_free(dst);
        return gerror_set_param(err, rc, param, "%s: cannot convert %s from model '%s' to '%s'", material, param,
                                gcolormodel_name(src->model), gcolormodel_name(m));
    }
    /* within the model's conversion error: clamped into [0, max]; a fold above max stays as it is */
    double lo, hi;
    int fold = 0;
    if (max > 0.0 && dst->kind == GCOLOR_VECTOR && gmaterial_param_range(dst, role, max, &lo, &hi) == G_OK)
        for (int i = 0; i < m->nvalues; i++)
            fold |= dst->v[i] > hi;
    if (dst->kind == GCOLOR_VECTOR)
        for (int i = 0; i < m->nvalues; i++) {
            if (!(dst->v[i] >= 0.0f))
                dst->v[i] = 0.0f;
            if (max > 0.0 && !fold && dst->v[i] > max)
                dst->v[i] = (float)max;
        }
    return G_OK;
}

int gmaterial_param_check_sum(const GColor *sum, const char *material, const char *what, const char *param, GError *err)
{
    double lo, hi;
    int rc = gmaterial_param_range(sum, GCOLOR_REFLECTANCE, 1.0, &lo, &hi);
    if (rc != G_OK)
        return gerror_set(err, rc, "%s: cannot measure %s (%s)", material, what, gstatus_string(rc));
    if (sum->kind == GCOLOR_MATRIX) /* re-radiated light counts: all that leaves per unit arriving in a sample */
        return check_matrix_energy(sum, 1.0, hi, material, what, param, err);
    int at;
    double mx = gmaterial_param_max(sum, &at);
    /* within the model's conversion error, as each parameter: rgb 0 0.5 0 + 0 0.5 0 is 1.03 in spectrum9 */
    double rgb[3] = {0, 0, 0};
    /* colours uplifted one by one (the sigmoid uplift is not linear) may sum above 1 at a sample where their RGB
     * sum is within 1: the sum is measured by its colour then (rgb 0.5 0 0 + 0 0.5 0.5 reaches 1.17 at 550 nm) */
    int rgb_ok =
        gcolor_to_rgb(sum, GCOLOR_REFLECTANCE, rgb) == G_OK && fmax(rgb[0], fmax(rgb[1], rgb[2])) <= 1.0 + 1e-4;
    if (mx > hi && !rgb_ok && !gmaterial_param_fold_ok(sum, hi)) /* above 1 in a band only as a fold */
        return gerror_set(err, G_ERR_INVALID,
                          "%s: %s is %g at sample %d; it must not exceed 1 (energy conservation)%s", material, what,
                          mx, at, hi > 1.0 + 2e-5 ? ", or the conversion error of the colour model" : "");
    return G_OK;
}

int gmaterial_param_default(GReader *r, double grey, GColorRole role, GColor *c, GError *err)
{
    if (c->v)
        return G_OK;
    const GColorModel *m = greader_colormodel(r);
    double rgb[3] = {grey, grey, grey};
    if (!m || gcolor_alloc(c, m) != G_OK)
        return greader_error(r, err, "out of memory");
    return gcolor_from_rgb(c, rgb, role) == G_OK ? G_OK : greader_error(r, err, "invalid default colour");
}

/* gmaterial_param_parse_one_color's constructor as a GTexParamCreate. */
static int create_one(const GColorModel *m, const GColor *c, void *ctx, GMaterial **out, GError *err)
{
    return (*(GMaterialOneColorCreate *)ctx)(m, c, out, err);
}

int gmaterial_param_parse_one_color(GReader *r, const char *key, double grey, GColorRole role,
                                    GMaterialOneColorCreate create, void **object, GError *err)
{
    GTexColor c = {0};
    const char *k;
    int rc;
    while ((rc = greader_param(r, &k, err)) > 0) {
        if (strcmp(k, key) == 0)
            rc = gtexparam_read_color(r, role, &c, err);
        else
            rc = greader_unknown_param(r, key, err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && c.kind == GTEXCOLOR_CONSTANT)
        rc = gmaterial_param_default(r, grey, role, &c.a, err);
    GMaterial *m = NULL;
    if (rc == G_OK && c.kind != GTEXCOLOR_CONSTANT) {
        if ((rc = gtexparam_one_color_material(greader_colormodel(r), &c, create_one, &create, &m, err)) == G_OK)
            *object = m;
    } else if (rc == G_OK && (rc = create(greader_colormodel(r), &c.a, &m, err)) == G_OK)
        *object = m;
    gtexparam_color_release(&c);
    return rc;
}
