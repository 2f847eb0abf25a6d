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
#include "generic/reader.h"

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

/* Reads one parameter of a fluorescent material other than `matrix` into its parameter struct, or reports
 * an unknown key. */
typedef int (*FluorParamFn)(GReader *r, const char *key, void *params, GError *err);

/* Reads a fluorescent material's parameter block: `matrix` here, every other key through param; then the
 * default matrix when none was given. *mat is freed by the caller, also on failure. */
static int read_material(GReader *r, FluorParamFn param, void *params, GReradiation *mat, GError *err)
{
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "matrix") == 0)
            rc = read_matrix(r, mat, err);
        else
            rc = param(r, key, params, err);
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

static int phong_param(GReader *r, const char *key, void *params, GError *err)
{
    GFluorPhongParams *p = params;
    if (strcmp(key, "ks") == 0)
        return greader_number_in(r, 0.0, 0.999, &p->ks, err);
    if (strcmp(key, "exponents") == 0)
        return read_numbers(r, 1.0, 1e6, p->exponent, 3, err);
    if (strcmp(key, "weights") == 0)
        return read_numbers(r, 0.0, 1.0, p->weight, 3, err);
    return greader_unknown_param(r, "matrix, ks, exponents, weights", err);
}

static int parse_fluorescent_phong(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorPhongParams p;
    gfluor_phong_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = read_material(r, phong_param, &p, &mat, err);
    if (rc == G_OK && (rc = gfluor_phong_create(greader_colormodel(r), &mat, &p, &m, err)) != G_OK)
        greader_locate(r, err);
    return finish(rc, &mat, m, object);
}

static int varnish_param(GReader *r, const char *key, void *params, GError *err)
{
    GFluorVarnishParams *p = params;
    if (strcmp(key, "ior") == 0)
        return greader_number_in(r, 1.0, 4.0, &p->ior, err);
    if (strcmp(key, "slope") == 0)
        return greader_number_in(r, 0.01, 44.99, &p->slope_deg, err);
    if (strcmp(key, "exponent") == 0)
        return greader_number_in(r, 0.0, 1e6, &p->exponent, err);
    return greader_unknown_param(r, "matrix, ior, slope, exponent", err);
}

static int parse_fluorescent_varnish(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = read_material(r, varnish_param, &p, &mat, err);
    if (rc == G_OK && (rc = gfluor_varnish_create(greader_colormodel(r), &mat, &p, &m, err)) != G_OK)
        greader_locate(r, err);
    return finish(rc, &mat, m, object);
}

const GTypeInfo gfluor_type_reradiation = {
    .kind = GKIND_COLOR, .name = "reradiation", .parse = parse_reradiation,
    .summary = "parametric fluorescent re-radiation matrix: reradiation { absorb_peak NM ... quantum_yield Q }"};
const GTypeInfo gfluor_type_phong = {
    .kind = GKIND_MATERIAL, .name = "fluorescent-phong", .vtable = &gmaterial_fluorescent_phong,
    .parse = parse_fluorescent_phong,
    .summary = "three Phong lobes (matrix diagonal) over a fluorescent Lambertian (Wilkie et al. 5.1)"};
const GTypeInfo gfluor_type_varnish = {
    .kind = GKIND_MATERIAL, .name = "fluorescent-varnish", .vtable = &gmaterial_fluorescent_varnish,
    .parse = parse_fluorescent_varnish,
    .summary = "rough Fresnel varnish over a fluorescent Lambertian base (Wilkie et al. 5.2)"};
