/* dispersion.c - refraction indices over wavelength: the formulas (constant, Cauchy, Sellmeier), their check, the
 * index as a colour of a model, and the reader of an `index` value (materials.h, kit/dispersion.h). */
#include "generic/kit/dispersion.h"

#include <math.h>
#include <string.h>

GDispersion gdispersion_constant(double n)
{
    GDispersion d = {GDISPERSION_CONSTANT, {n, 0, 0, 0, 0, 0}};
    return d;
}

GDispersion gdispersion_cauchy(double a, double b, double c)
{
    GDispersion d = {GDISPERSION_CAUCHY, {a, b, c, 0, 0, 0}};
    return d;
}

GDispersion gdispersion_sellmeier(const double b[3], const double c[3])
{
    GDispersion d = {GDISPERSION_SELLMEIER, {b[0], b[1], b[2], c[0], c[1], c[2]}};
    return d;
}

double gdispersion_index(const GDispersion *d, double nm)
{
    double l = nm * 1e-3, l2 = l * l;
    switch (d->kind) {
    case GDISPERSION_CONSTANT:
        return d->c[0];
    case GDISPERSION_CAUCHY:
        return d->c[0] + d->c[1] / l2 + d->c[2] / (l2 * l2);
    case GDISPERSION_SELLMEIER: {
        double n2 = 1.0;
        for (int i = 0; i < 3; i++)
            n2 += d->c[i] * l2 / (l2 - d->c[3 + i]);
        return n2 > 0.0 ? sqrt(n2) : NAN;
    }
    }
    return NAN;
}

int gdispersion_check(const GDispersion *d, GError *err)
{
    static const char *const names[3][6] = {
        {"n", "", "", "", "", ""},
        {"A", "B", "C", "", "", ""},
        {"B1", "B2", "B3", "C1", "C2", "C3"},
    };
    static const int counts[3] = {1, 3, 6};
    static const char *const kinds[3] = {"constant", "Cauchy", "Sellmeier"};
    if (!d || (unsigned)d->kind > GDISPERSION_SELLMEIER)
        return gerror_set(err, G_ERR_INVALID, "dielectric: unknown dispersion formula %d", d ? (int)d->kind : -1);
    for (int i = 0; i < counts[d->kind]; i++)
        if (!isfinite(d->c[i]))
            return gerror_set(err, G_ERR_INVALID, "dielectric: %s coefficient %s is %g (must be finite)",
                              kinds[d->kind], names[d->kind][i], d->c[i]);
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm++) {
        double n = gdispersion_index(d, nm);
        if (!isfinite(n) || n <= 0.0)
            return gerror_set(err, G_ERR_INVALID,
                              "dielectric: the %s formula gives the index %g at %d nm (must be finite and > 0)",
                              kinds[d->kind], n, nm);
    }
    return G_OK;
}

int gdispersion_color(const GDispersion *d, GColor *out)
{
    if (out->model->nsamples > 0) {
        GSpectrumNM s;
        for (int i = 0; i < GNM_COUNT; i++)
            s.v[i] = (float)gdispersion_index(d, GNM_MIN + i);
        return gcolor_from_nm(out, &s, GCOLOR_REFLECTANCE);
    }
    double rgb[3] = {gdispersion_index(d, 610.0), gdispersion_index(d, 550.0), gdispersion_index(d, 465.0)};
    return gcolor_from_rgb(out, rgb, GCOLOR_REFLECTANCE);
}

int gdispersion_read_glass(GReader *r, GDispersion *d, GError *err)
{
    GToken tok;
    int rc = greader_next(r, &tok, err);
    if (rc < 0)
        return rc;
    if (tok.type != GTOK_IDENT && tok.type != GTOK_STRING)
        return greader_error_at(r, err, G_ERR_PARSE, tok.line, tok.col, "expected a glass name, found '%s'",
                                tok.text);
    const GGlass *g = gdispersion_glass_find(tok.text);
    if (!g) {
        char names[512];
        return greader_error_at(r, err, G_ERR_NOTFOUND, tok.line, tok.col, "unknown glass '%s' (known: %s)",
                                tok.text, gdispersion_glass_names(names, sizeof names));
    }
    *d = g->formula;
    return G_OK;
}

int gdispersion_read(GReader *r, GDispersion *d, GError *err)
{
    int rc = greader_at_number(r, err); /* a number or a constant */
    if (rc < 0)
        return rc;
    if (rc == 1) {
        double n;
        rc = greader_number_in(r, 0.01, 100.0, &n, err);
        if (rc == G_OK)
            *d = gdispersion_constant(n);
        return rc;
    }
    static const char *const forms[] = {"cauchy", "sellmeier", "glass", NULL};
    int which = 0;
    if ((rc = greader_choice(r, forms, &which, err)) != G_OK)
        return rc;
    if (which == 2)
        return gdispersion_read_glass(r, d, err);
    double c[6] = {0, 0, 0, 0, 0, 0};
    int n = which == 0 ? 2 : 6;
    for (int i = 0; i < n && rc == G_OK; i++)
        rc = greader_number(r, &c[i], err);
    if (rc == G_OK && which == 0 && (rc = greader_at_number(r, err)) == 1)
        rc = greader_number(r, &c[2], err);
    if (rc != G_OK)
        return rc;
    *d = which == 0 ? gdispersion_cauchy(c[0], c[1], c[2]) : gdispersion_sellmeier(c, c + 3);
    GError check; /* a bad formula is reported at its last coefficient */
    if (gdispersion_check(d, &check) != G_OK)
        return greader_error(r, err, "%s", check.message);
    return G_OK;
}
