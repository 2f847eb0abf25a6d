/* parsers.c - the text format of the fluorescent types (README.md, "Fluorescent types"):
 *
 *   color NAME reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97
 *                            emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 step 5 }
 *   material NAME fluorescent-phong { matrix COLOR  ks 0.04  exponents 30 120 480  weights 0.2 0.3 0.5 }
 *   material NAME fluorescent-varnish { matrix COLOR  ior 1.5  slope 17 | exponent M }
 *
 * `reradiation` is a colour literal holding the parametric matrix (gfluor_matrix_create) on the file's
 * spectral grid (or 380..780 nm at `step` nm, default 5, in non-spectral models). `matrix` takes any colour
 * value: a re-radiation matrix (`bfc "FILE"`, `reradiation {...}`, or the name of one, optionally `scale`d)
 * or a plain reflectance (rgb, spectrum), which makes a non-fluorescent matrix holding it on the diagonal.
 * Without `matrix` the default `reradiation` (a day-glo orange) is used. */
#include "fluor_internal.h"
#include "fluorescent_builtin.h"
#include "generic/plugin.h"
#include "generic/reader.h"

#include <stddef.h>
#include <string.h>

/* ---- the parametric matrix as a colour literal ---- */

static int parse_reradiation(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorBands b;
    gfluor_bands_default(&b);
    double step = 0.0;
    static const char *const names[] = {"absorb_peak", "absorb_width", "absorb_shape", "absorb_max", "emit_width",
                                        "stokes_shift", "quantum_yield", "reflectance", NULL};
    double *fields[] = {&b.absorb_peak, &b.absorb_width, &b.absorb_shape, &b.absorb_max, &b.emit_width,
                        &b.stokes_shift, &b.quantum_yield, &b.reflectance};
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        int k = 0;
        while (names[k] && strcmp(key, names[k]) != 0)
            k++;
        if (names[k])
            rc = greader_number(r, fields[k], err);
        else if (strcmp(key, "step") == 0)
            rc = greader_number_in(r, 1.0, 50.0, &step, err);
        else
            rc = greader_unknown_param(r, "absorb_peak, absorb_width, absorb_shape, absorb_max, emit_width, "
                                          "stokes_shift, quantum_yield, reflectance, step", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    const GColorModel *m = greader_colormodel(r);
    double lo = GNM_MIN, st = step > 0.0 ? step : 5.0;
    int n = (int)((GNM_MAX - GNM_MIN) / st) + 1;
    if (step == 0.0 && m && m->nsamples > 0) {
        lo = m->lambda_min;
        st = m->lambda_step;
        n = m->nsamples;
    }
    GReradiation mat;
    rc = gfluor_matrix_create(&b, lo, st, n, &mat, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    GColorSpec *s = gcolorspec_create();
    if (!s) {
        gfluor_matrix_free(&mat);
        return greader_error(r, err, "out of memory");
    }
    s->form = GCOLORSPEC_RERADIATION;
    s->rerad = mat;
    s->owned_data = (float *)mat.data;
    *object = s;
    return G_OK;
}

/* ---- the materials ---- */

/* The matrix a `matrix` value stands for, in new storage (free with gfluor_matrix_free). */
static int spec_matrix(GReader *r, const GColorSpec *s, GReradiation *out, GError *err)
{
    memset(out, 0, sizeof *out);
    if (s->form == GCOLORSPEC_LINE)
        return greader_error(r, err, "matrix: a spectral line is a light, not a reflectance");
    if (s->form == GCOLORSPEC_RERADIATION) {
        int rc = fluor_matrix_check(&s->rerad, "matrix", err);
        if (rc != G_OK)
            return greader_locate(r, err);
        size_t n = (size_t)s->rerad.n_in * s->rerad.n_out;
        float *d = gmem_alloc(n * sizeof *d);
        if (!d)
            return greader_error(r, err, "out of memory");
        for (size_t k = 0; k < n; k++)
            d[k] = (float)(s->rerad.data[k] * s->scale);
        *out = s->rerad;
        out->data = d;
        return G_OK;
    }
    GSpectrumNM nm;
    if (s->form == GCOLORSPEC_RGB)
        gcie_rgb_to_nm(s->rgb, GCOLOR_REFLECTANCE, &nm);
    else
        nm = s->nm;
    const int n = (GNM_MAX - GNM_MIN) / 5 + 1;
    float *d = gmem_calloc((size_t)n * n, sizeof *d);
    if (!d)
        return greader_error(r, err, "out of memory");
    for (int k = 0; k < n; k++)
        d[k * n + k] = (float)(nm.v[5 * k] * s->scale);
    *out = (GReradiation){GNM_MIN, 5.0, n, GNM_MIN, 5.0, n, d};
    return G_OK;
}

static int read_matrix(GReader *r, GReradiation *out, GError *err)
{
    gfluor_matrix_free(out);
    GColorSpec *s = NULL;
    int rc = greader_color_spec(r, &s, err);
    if (rc == G_OK)
        rc = spec_matrix(r, s, out, err);
    gcolorspec_destroy(s);
    return rc;
}

static int default_matrix(GReader *r, GReradiation *out, GError *err)
{
    if (out->data)
        return G_OK;
    GFluorBands b;
    gfluor_bands_default(&b);
    const GColorModel *m = greader_colormodel(r);
    int rc = m && m->nsamples > 0 ? gfluor_matrix_create(&b, m->lambda_min, m->lambda_step, m->nsamples, out, err)
                                  : gfluor_matrix_create(&b, GNM_MIN, 5.0, (GNM_MAX - GNM_MIN) / 5 + 1, out, err);
    return rc ? greader_locate(r, err) : G_OK;
}

static int read_numbers(GReader *r, double lo, double hi, double *v, int n, GError *err)
{
    int rc = G_OK;
    for (int k = 0; k < n && rc == G_OK; k++)
        rc = greader_number_in(r, lo, hi, &v[k], err);
    return rc;
}

/* A numeric parameter of a fluorescent material: `count` numbers in [lo, hi] at `offset` in its parameter
 * struct. */
typedef struct FluorParam {
    const char *key;
    double lo, hi;
    size_t offset;
    int count;
} FluorParam;

static const FluorParam phong_params[] = {
    {"ks", 0.0, 0.999, offsetof(GFluorPhongParams, ks), 1},
    {"exponents", 1.0, 1e6, offsetof(GFluorPhongParams, exponent), 3},
    {"weights", 0.0, 1.0, offsetof(GFluorPhongParams, weight), 3},
    {NULL, 0.0, 0.0, 0, 0},
};

static const FluorParam varnish_params[] = {
    {"ior", 1.0, 4.0, offsetof(GFluorVarnishParams, ior), 1},
    {"slope", 0.01, 44.99, offsetof(GFluorVarnishParams, slope_deg), 1},
    {"exponent", 0.0, 1e6, offsetof(GFluorVarnishParams, exponent), 1},
    {NULL, 0.0, 0.0, 0, 0},
};

/* Reads a fluorescent material's parameter block into params: `matrix` into *mat (the default matrix when
 * it is not given), the numbers of the table; `keys` lists them all for the unknown-key message. *mat is
 * freed by the caller, also on failure. */
static int read_material(GReader *r, const FluorParam *table, const char *keys, void *params, GReradiation *mat,
                         GError *err)
{
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        const FluorParam *p = table;
        while (p->key && strcmp(key, p->key) != 0)
            p++;
        if (strcmp(key, "matrix") == 0)
            rc = read_matrix(r, mat, err);
        else if (p->key)
            rc = read_numbers(r, p->lo, p->hi, (double *)((char *)params + p->offset), p->count, err);
        else
            rc = greader_unknown_param(r, keys, err);
        if (rc < 0)
            break;
    }
    return rc == G_OK ? default_matrix(r, mat, err) : rc;
}

/* The end of a parse: frees the matrix and hands over the material when rc is G_OK. */
static int finish(int rc, GReradiation *mat, GMaterial *m, void **object)
{
    gfluor_matrix_free(mat);
    if (rc == G_OK)
        *object = m;
    return rc;
}

static int parse_fluorescent_phong(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorPhongParams p;
    gfluor_phong_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = read_material(r, phong_params, "matrix, ks, exponents, weights", &p, &mat, err);
    if (rc == G_OK && (rc = gfluor_phong_create(greader_colormodel(r), &mat, &p, &m, err)) != G_OK)
        greader_locate(r, err);
    return finish(rc, &mat, m, object);
}

static int parse_fluorescent_varnish(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = read_material(r, varnish_params, "matrix, ior, slope, exponent", &p, &mat, err);
    if (rc == G_OK && (rc = gfluor_varnish_create(greader_colormodel(r), &mat, &p, &m, err)) != G_OK)
        greader_locate(r, err);
    return finish(rc, &mat, m, object);
}

GENERIC_TYPE_NAMED(reradiation, GKIND_COLOR, "reradiation", parse_reradiation,
                   "parametric fluorescent re-radiation matrix: reradiation { absorb_peak NM ... quantum_yield Q }",
                   NULL);
GENERIC_TYPE(fluorescent_phong, GKIND_MATERIAL, &gmaterial_fluorescent_phong, parse_fluorescent_phong, NULL);
GENERIC_TYPE(fluorescent_varnish, GKIND_MATERIAL, &gmaterial_fluorescent_varnish, parse_fluorescent_varnish, NULL);
