/* fluorescent_params.c - what the parse routines of the fluorescent materials share (fluorescent_kit.h): the
 * `matrix` parameter and the numeric parameters of a table (docs/reference/format.md, "Fluorescent types"):
 *
 *   material NAME fluorescent-phong { matrix COLOR  ks 0.04  exponents 30 120 480  weights 0.2 0.3 0.5 }
 *   material NAME fluorescent-varnish { matrix COLOR  ior 1.5  slope 17 | exponent M }
 *
 * `matrix` takes any colour value: a re-radiation matrix (`bfc "FILE"`, `reradiation {...}`, or the name of one,
 * optionally `scale`d) or a plain reflectance (rgb, spectrum), which makes a non-fluorescent matrix holding it on
 * the diagonal. Without `matrix` the default `reradiation` (a day-glo orange) is used. */
#include "generic/kit/fluorescent_kit.h"

#include <string.h>

/* The matrix a `matrix` value stands for, in new storage (free with gfluor_matrix_free). */
static int spec_matrix(GReader *r, const GColorSpec *s, GReradiation *out, GError *err)
{
    memset(out, 0, sizeof *out);
    if (s->form == GCOLORSPEC_LINE)
        return greader_error(r, err, "matrix: a spectral line is a light, not a reflectance");
    if (s->form == GCOLORSPEC_RERADIATION) {
        int rc = gfluor_matrix_check(&s->rerad, "matrix", err);
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

/* Reads a fluorescent material's parameter block into params: `matrix` into *mat (the default matrix when
 * it is not given), the numbers of the table; `keys` lists them all for the unknown-key message. *mat is
 * freed by the caller, also on failure. */
int gfluor_read_params(GReader *r, const GFluorParam *table, const char *keys, void *params, GReradiation *mat,
                         GError *err)
{
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        const GFluorParam *p = table;
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
int gfluor_finish(int rc, GReradiation *mat, GMaterial *m, void **object)
{
    gfluor_matrix_free(mat);
    if (rc == G_OK)
        *object = m;
    return rc;
}
