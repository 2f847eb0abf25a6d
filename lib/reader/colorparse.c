/* colorparse.c - colour literals: rgb, spectrum, blackbody, illuminant, line, bfc, scale, and names.
 * A literal is parsed into a model-free GColorSpec; each use converts it into the file's colour model in the
 * role of that use (reflectance or light). */
#include "reader_internal.h"
#include "generic/plugin.h"
#include "generic/services/bfc.h"
#include "generic/memory.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- GColorSpec ---- */

GColorSpec *gcolorspec_create(void)
{
    GColorSpec *s = gmem_calloc(1, sizeof *s);
    if (s)
        s->scale = 1.0;
    return s;
}

void gcolorspec_destroy(GColorSpec *s)
{
    if (!s)
        return;
    gmem_free(s->owned_data);
    gmem_free(s);
}

int gcolorspec_copy(const GColorSpec *src, GColorSpec **out, GError *err)
{
    *out = NULL;
    GColorSpec *s = gmem_alloc(sizeof *s);
    if (!s)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    *s = *src;
    s->owned_data = NULL;
    if (src->form == GCOLORSPEC_RERADIATION && src->rerad.data) {
        size_t n = (size_t)src->rerad.n_in * (size_t)src->rerad.n_out;
        s->owned_data = gmem_calloc(n, sizeof(float));
        if (!s->owned_data) {
            gmem_free(s);
            return gerror_set(err, G_ERR_NOMEM, "out of memory");
        }
        memcpy(s->owned_data, src->rerad.data, n * sizeof(float));
        s->rerad.data = s->owned_data;
    }
    *out = s;
    return G_OK;
}

/* A line of `power` at nm: a triangle of half-width h (the model's sample step, at least 1 nm) on the 1 nm grid,
 * normalised so the samples sum to power: energy and centre survive any resampling to the model's grid. */
static void line_nm(double nm, double power, double h, GSpectrumNM *out)
{
    double sum = 0.0;
    for (int i = 0; i < GNM_COUNT; i++) {
        double w = 1.0 - fabs(GNM_MIN + i - nm) / h;
        out->v[i] = w > 0.0 ? (float)w : 0.0f;
        sum += out->v[i];
    }
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = sum > 0.0 ? (float)(out->v[i] * power / sum) : 0.0f;
}

int gcolorspec_to_color(const GColorSpec *s, GColorRole role, GColor *out, GError *err)
{
    if (!s || !out || !out->model || !out->v)
        return gerror_set(err, G_ERR_INVALID, "no colour to convert into");
    GSpectrumNM nm;
    int rc;
    switch (s->form) {
    case GCOLORSPEC_RGB: {
        double v[3] = {s->rgb[0] * s->scale, s->rgb[1] * s->scale, s->rgb[2] * s->scale};
        rc = gcolor_from_rgb(out, v, role);
        break;
    }
    case GCOLORSPEC_NM:
        for (int i = 0; i < GNM_COUNT; i++)
            nm.v[i] = (float)(s->nm.v[i] * s->scale);
        rc = gcolor_from_nm(out, &nm, role);
        break;
    case GCOLORSPEC_LINE: {
        const GColorModel *m = out->model;
        double h = m->nsamples > 0 && m->lambda_step > 1.0 ? m->lambda_step : 1.0;
        line_nm(s->line_nm, s->line_power * s->scale, h, &nm);
        rc = gcolor_from_nm(out, &nm, role);
        break;
    }
    case GCOLORSPEC_RERADIATION:
        if (role == GCOLOR_LIGHT)
            return gerror_set(err, G_ERR_INVALID, "a re-radiation matrix is a reflectance and cannot be a light");
        rc = gcolor_from_reradiation(out, &s->rerad, err);
        if (rc == G_OK && s->scale != 1.0)
            rc = gcolor_scale(out, out, s->scale);
        if (rc != G_OK)
            return rc;
        break;
    default:
        return gerror_set(err, G_ERR_INVALID, "unknown colour form %d", s->form);
    }
    if (rc != G_OK)
        return gerror_set(err, rc, "the colour cannot be converted into model '%s' (%s)", gcolormodel_name(out->model),
                          gstatus_string(rc));
    if (!gcolor_is_finite(out)) { /* finite factors whose product overflows a float: nothing infinite gets out */
        gcolor_black(out);
        return gerror_set(err, G_ERR_INVALID, "the colour is too large: a value overflows in model '%s'",
                          gcolormodel_name(out->model));
    }
    return G_OK;
}

/* ---- reading ---- */

int greader_color_spec(GReader *r, GColorSpec **out, GError *err)
{
    *out = NULL;
    void *obj = NULL;
    const GTypeInfo *type = NULL;
    int owned = 0;
    int rc = greader_value(r, GKIND_COLOR, 0, &obj, &type, &owned, err);
    if (rc != G_OK)
        return rc;
    (void)type;
    if (owned) { /* a new literal: every colour type makes its spec with gcolorspec_create */
        *out = obj;
        return G_OK;
    }
    rc = gcolorspec_copy(obj, out, err);
    return rc ? greader_locate(r, err) : G_OK;
}

int greader_color(GReader *r, GColorRole role, GColor *out, GError *err)
{
    const GColorModel *m = greader_colormodel(r);
    if (!m)
        return greader_error(r, err, "out of memory creating the colour model");
    if (out->v && out->model != m)
        gcolor_free(out);
    if (!out->v && gcolor_alloc(out, m) != G_OK)
        return greader_error(r, err, "out of memory");
    GColorSpec *s = NULL;
    GToken first;
    int rc = greader_peek(r, &first, err);
    if (rc == G_OK)
        rc = greader_color_spec(r, &s, err);
    if (rc != G_OK)
        return rc;
    rc = gcolorspec_to_color(s, role, out, err);
    gcolorspec_destroy(s);
    if (rc != G_OK) { /* a conversion error is the whole literal's: point at its start */
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err ? err->message : "");
        gcolor_black(out);
        return greader_error_at(r, err, rc, first.line, first.col, "%s", msg);
    }
    return G_OK;
}

/* ---- the literal types ---- */

static int new_spec(GReader *r, int form, GColorSpec **s, GError *err)
{
    *s = gcolorspec_create();
    if (!*s)
        return greader_error(r, err, "out of memory");
    (*s)->form = form;
    return G_OK;
}

static int finish(GColorSpec *s, int rc, void **object)
{
    if (rc != G_OK) {
        gcolorspec_destroy(s);
        return rc;
    }
    *object = s;
    return G_OK;
}

static int parse_rgb(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s;
    int rc = new_spec(r, GCOLORSPEC_RGB, &s, err);
    if (rc != G_OK)
        return rc;
    GVec3 v;
    rc = greader_vec3(r, &v, err);
    if (rc == G_OK) {
        s->rgb[0] = v.x;
        s->rgb[1] = v.y;
        s->rgb[2] = v.z;
    }
    return finish(s, rc, object);
}

/* Fills the 1 nm grid from increasing (nm, value) pairs, linear between them, constant beyond the ends. */
static int parse_spectrum(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s;
    int rc = new_spec(r, GCOLORSPEC_NM, &s, err);
    if (rc == G_OK)
        rc = greader_block_begin(r, err);
    double pl = 0.0, pv = 0.0;
    int pairs = 0;
    while (rc == G_OK) {
        int end = greader_block_end(r, err);
        if (end < 0) {
            rc = end;
            break;
        }
        if (end) {
            if (!pairs)
                rc = greader_error(r, err, "spectrum: expected wavelength/value pairs, found an empty block");
            break;
        }
        double l = 0.0, v = 0.0; /* set before use; initialised for the link-time optimiser's flow analysis */
        int ll, lc;
        if ((rc = greader_number_in(r, 1.0, 100000.0, &l, err)) != G_OK)
            break;
        greader_position(r, &ll, &lc);
        if (pairs && !(l > pl)) {
            rc = greader_error(r, err, "spectrum: wavelength %g does not increase (the previous one is %g)", l, pl);
            break;
        }
        end = greader_block_end(r, err);
        if (end != 0) {
            rc = end < 0 ? end
                         : greader_error_at(r, err, G_ERR_PARSE, ll, lc, "spectrum: wavelength %g has no value", l);
            break;
        }
        if ((rc = greader_number(r, &v, err)) != G_OK)
            break;
        for (int i = 0; i < GNM_COUNT; i++) {
            double nm = GNM_MIN + i;
            if (!pairs && nm <= l)
                s->nm.v[i] = (float)v;
            else if (pairs && nm > pl && nm <= l)
                s->nm.v[i] = (float)(pv + (v - pv) * (nm - pl) / (l - pl));
            else if (nm > l)
                s->nm.v[i] = (float)v;
        }
        pl = l;
        pv = v;
        pairs++;
    }
    return finish(s, rc, object);
}

static int parse_blackbody(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s;
    int rc = new_spec(r, GCOLORSPEC_NM, &s, err);
    double t = 0.0;
    if (rc == G_OK)
        rc = greader_number_in(r, 100.0, 1e6, &t, err);
    if (rc == G_OK)
        gcie_blackbody_nm(t, &s->nm);
    return finish(s, rc, object);
}

static int parse_illuminant(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    static const char *const names[] = {"D65", "A", "E", NULL};
    GColorSpec *s;
    int rc = new_spec(r, GCOLORSPEC_NM, &s, err), which = 0;
    if (rc == G_OK)
        rc = greader_choice(r, names, &which, err);
    if (rc == G_OK && gcie_illuminant_nm(names[which], &s->nm) != G_OK)
        rc = greader_error(r, err, "illuminant %s is not available", names[which]);
    return finish(s, rc, object);
}

static int parse_line(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s;
    int rc = new_spec(r, GCOLORSPEC_LINE, &s, err);
    if (rc != G_OK)
        return rc;
    s->line_power = 1.0;
    rc = greader_number_in(r, GNM_MIN, GNM_MAX, &s->line_nm, err);
    if (rc == G_OK && (rc = greader_at_number(r, err)) == 1)
        rc = greader_number_in(r, 0.0, 1e30, &s->line_power, err);
    return finish(s, rc, object);
}

/* Emission shorter than excitation cannot happen: those entries are measurement noise and are zeroed, and
 * negative noise elsewhere is clipped. */
static void clean_matrix(GReradiation *m, float *data)
{
    for (int o = 0; o < m->n_out; o++)
        for (int i = 0; i < m->n_in; i++) {
            double out_nm = m->out_min + o * m->out_step, in_nm = m->in_min + i * m->in_step;
            float *v = &data[(size_t)o * m->n_in + i];
            if (out_nm < in_nm - 1e-6 || *v < 0.0f)
                *v = 0.0f;
        }
}

static int parse_bfc(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s;
    char *path = NULL;
    int rc = new_spec(r, GCOLORSPEC_RERADIATION, &s, err);
    if (rc == G_OK)
        rc = greader_path(r, &path, err);
    GBfcData d;
    if (rc == G_OK && (rc = gbfc_read(path, &d, err)) == G_OK) {
        s->owned_data = d.values;
        s->rerad = d.rerad;
        clean_matrix(&s->rerad, s->owned_data);
    }
    gmem_free(path);
    return finish(s, rc, object);
}

static int parse_scale(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    double f = 0.0;
    int rc = greader_number_in(r, 0.0, 1e30, &f, err);
    GColorSpec *s = NULL;
    if (rc == G_OK)
        rc = greader_color_spec(r, &s, err);
    if (rc != G_OK)
        return rc;
    s->scale *= f;
    *object = s;
    return G_OK;
}

static void destroy_spec(void *p) { gcolorspec_destroy(p); }

/* The parameter tables of the colour literal types: every one reads positional values. */
static const GParamInfo rgb_params[] = {
    {"R", GPARAM_POSITIONAL, "number", NULL, NULL, "red, linear sRGB (Rec.709 primaries); also written <R, G, B>"},
    {"G", GPARAM_POSITIONAL, "number", NULL, NULL, "green"},
    {"B", GPARAM_POSITIONAL, "number", NULL, NULL, "blue; as a light, rgb 1 1 1 is D65 of luminance Y = 1"},
    {NULL},
};
static const GParamInfo spectrum_params[] = {
    {"PAIRS", GPARAM_POSITIONAL, "block", NULL, "{ NM VALUE ... }, wavelengths in [1, 100000] increasing",
     "the spectrum at those wavelengths, linear in between and held beyond the ends (values per nm for lights)"},
    {NULL},
};
static const GParamInfo blackbody_params[] = {
    {"KELVIN", GPARAM_POSITIONAL, "number", NULL, "[100, 1e6]", "the temperature of a Planck radiator of Y = 1"},
    {NULL},
};
static const GParamInfo illuminant_params[] = {
    {"NAME", GPARAM_POSITIONAL, "choice", NULL, "D65, A, E", "the CIE illuminant, of Y = 1"},
    {NULL},
};
static const GParamInfo line_params[] = {
    {"NM", GPARAM_POSITIONAL, "number", NULL, "[380, 780]", "the wavelength of a monochromatic line"},
    {"POWER", GPARAM_POSITIONAL, "number", "1", "[0, 1e30]", "its radiant power (optional)"},
    {NULL},
};
static const GParamInfo bfc_params[] = {
    {"FILE", GPARAM_POSITIONAL, "path", NULL, "a Labsphere BFC-450 text file",
     "a measured re-radiation (Donaldson) matrix, for reflectances only"},
    {NULL},
};
static const GParamInfo scale_params[] = {
    {"FACTOR", GPARAM_POSITIONAL, "number", NULL, "[0, 1e30]", "multiplies the colour"},
    {"COLOR", GPARAM_POSITIONAL, "color", NULL, NULL, "any colour value: a literal or a name"},
    {NULL},
};

/* The colour literal types; the build lists them with the other built-ins (builtins.h). */
GENERIC_TYPE_NAMED_PARAMS(color_rgb, GKIND_COLOR, "rgb", parse_rgb, "linear sRGB: rgb R G B", destroy_spec,
                          rgb_params);
GENERIC_TYPE_NAMED_PARAMS(color_spectrum, GKIND_COLOR, "spectrum", parse_spectrum,
                          "tabulated spectrum: spectrum { NM VALUE ... }", destroy_spec, spectrum_params);
GENERIC_TYPE_NAMED_PARAMS(color_blackbody, GKIND_COLOR, "blackbody", parse_blackbody,
                          "Planck radiator, Y = 1: blackbody KELVIN", destroy_spec, blackbody_params);
GENERIC_TYPE_NAMED_PARAMS(color_illuminant, GKIND_COLOR, "illuminant", parse_illuminant,
                          "CIE illuminant, Y = 1: illuminant D65|A|E", destroy_spec, illuminant_params);
GENERIC_TYPE_NAMED_PARAMS(color_line, GKIND_COLOR, "line", parse_line, "monochromatic line: line NM [POWER]",
                          destroy_spec, line_params);
GENERIC_TYPE_NAMED_PARAMS(color_bfc, GKIND_COLOR, "bfc", parse_bfc, "measured re-radiation matrix: bfc \"FILE.BFC\"",
                          destroy_spec, bfc_params);
GENERIC_TYPE_NAMED_PARAMS(color_scale, GKIND_COLOR, "scale", parse_scale, "scaled colour: scale FACTOR COLOR",
                          destroy_spec, scale_params);
