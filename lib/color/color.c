/* color.c - colour model creation, value storage, and dispatch of the generic colour operations (the defaults of
 * fill and axpy, copy and the finiteness tests: color_vector_ops.c). */
#include "generic/color.h"
#include "generic/kit/spectral.h"

#include <limits.h>
#include <float.h>
#include <math.h>
#include <pthread.h>

/* What the library keeps with a model past its public struct (a model is only made here, so every GColorModel is
 * the first member of one): gcolormodel_rgb_range's results per class role, measured once. A mutex guards them:
 * models are shared by threads, and the measurement (seven uplifts, a fit each) runs once per role. */
typedef struct ModelRecord {
    GColorModel model;
    pthread_mutex_t lock;
    int ready;            /* set once init has succeeded: a range measured before that is not kept */
    int bands;            /* gcolormodel_band_count, asked of the class once init has succeeded */
    int have_range[2];    /* per class role (reflectance, light) */
    double range[2][2];   /* lo, hi */
} ModelRecord;

static ModelRecord *record_of(const GColorModel *m) { return (ModelRecord *)(void *)m; }

int gcolormodel_create_class(const GColorModelClass *cls, const GColorModelOptions *opt, GColorModel **out,
                             GError *err)
{
    *out = NULL;
    if (!cls)
        return gerror_set(err, G_ERR_INVALID, "no colour model class given");
    if (cls->abi_version != GCOLOR_ABI_VERSION)
        return gerror_set(err, G_ERR_VERSION, "colour model '%s' has interface version %d, the library has %d",
                          cls->name ? cls->name : "?", cls->abi_version, GCOLOR_ABI_VERSION);
    if (!cls->init || !cls->black || !cls->add || !cls->mul || !cls->scale || !cls->div || !cls->pow ||
        !cls->to_nm || !cls->from_nm)
        return gerror_set(err, G_ERR_INVALID, "colour model '%s' lacks a required operation", cls->name);
    GColorModelOptions none = {0, 0, 0, 0};
    if (!opt)
        opt = &none;
    if (!isfinite(opt->step_nm) || !isfinite(opt->min_nm) || !isfinite(opt->max_nm) || opt->step_nm < 0)
        return gerror_set(err, G_ERR_INVALID, "colour model '%s': options must be finite and non-negative", cls->name);
    ModelRecord *rec = gmem_calloc(1, sizeof *rec);
    if (!rec)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating colour model '%s'", cls->name);
    if (pthread_mutex_init(&rec->lock, NULL) != 0) {
        gmem_free(rec);
        return gerror_set(err, G_ERR_NOMEM, "out of resources creating colour model '%s'", cls->name);
    }
    GColorModel *m = &rec->model;
    m->cls = cls;
    int rc = cls->init(m, opt, err);
    if (rc == G_OK && (m->nvalues <= 0 || m->capacity < m->nvalues))
        rc = gerror_set(err, G_ERR_INVALID, "colour model '%s' reported invalid sizes", cls->name);
    if (rc != G_OK) {
        if (cls->fini)
            cls->fini(m);
        pthread_mutex_destroy(&rec->lock);
        gmem_free(rec);
        return rc;
    }
    rec->bands = cls->band_count ? cls->band_count(m) : 1;
    if (rec->bands < 1)
        rec->bands = 1;
    rec->ready = 1;
    *out = m;
    return G_OK;
}

void gcolormodel_destroy(GColorModel *m)
{
    if (!m)
        return;
    if (m->cls->fini)
        m->cls->fini(m);
    ModelRecord *rec = record_of(m);
    pthread_mutex_destroy(&rec->lock);
    gmem_free(rec);
}

const char *gcolormodel_name(const GColorModel *m) { return m ? m->cls->name : "(none)"; }

/* ---- storage ---- */

static void clear(GColor *c)
{
    *c = (GColor){.model = NULL, .v = NULL, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_NONE, .capacity = 0};
}

/* Points c at v (at least m->capacity floats), its values as they are. */
static void attach_uncleared(GColor *c, const GColorModel *m, float *v, GColorStorage storage, int capacity)
{
    *c = (GColor){.model = m, .v = v, .kind = GCOLOR_VECTOR, .storage = storage, .capacity = capacity};
}

/* Points c at v (at least m->capacity floats) and sets it to black. */
static void attach(GColor *c, const GColorModel *m, float *v, GColorStorage storage, int capacity)
{
    attach_uncleared(c, m, v, storage, capacity);
    m->cls->black(m, c);
}

int gcolor_wrap(GColor *c, const GColorModel *m, float *storage, size_t nfloats)
{
    if (!storage || nfloats < (size_t)m->capacity) {
        clear(c);
        return G_ERR_INVALID;
    }
    attach(c, m, storage, GCOLOR_STORAGE_CALLER, nfloats > INT_MAX ? INT_MAX : (int)nfloats);
    return G_OK;
}

int gcolor_scratch_uncleared(GColor *c, const GColorModel *m, GScratch *s)
{
    float *v = gscratch_alloc(s, (size_t)m->capacity * sizeof(float));
    if (!v) {
        clear(c);
        return G_ERR_NOMEM;
    }
    attach_uncleared(c, m, v, GCOLOR_STORAGE_ARENA, m->capacity);
#ifdef __SANITIZE_ADDRESS__
    /* sanitizer builds: a NaN in every value, so that a caller that reads before writing makes non-finite results
     * (which renders count and tests see) instead of quietly reusing old values, which no sanitizer reports */
    for (int i = 0; i < m->capacity; i++)
        v[i] = NAN;
#endif
    return G_OK;
}

int gcolor_scratch(GColor *c, const GColorModel *m, GScratch *s)
{
    int rc = gcolor_scratch_uncleared(c, m, s);
    if (rc == G_OK)
        m->cls->black(m, c);
    return rc;
}

int gcolor_alloc(GColor *c, const GColorModel *m)
{
    float *v = gmem_calloc((size_t)m->capacity, sizeof(float));
    if (!v) {
        clear(c);
        return G_ERR_NOMEM;
    }
    attach(c, m, v, GCOLOR_STORAGE_HEAP, m->capacity);
    return G_OK;
}

void gcolor_free(GColor *c)
{
    if (!c)
        return;
    if (c->storage == GCOLOR_STORAGE_HEAP)
        gmem_free(c->v);
    clear(c);
}

/* ---- operations ---- */

void gcolor_black(GColor *c) { c->model->cls->black(c->model, c); }

int gcolor_add(GColor *out, const GColor *a, const GColor *b)
{
    if (a->model != b->model || out->model != a->model)
        return G_ERR_MISMATCH;
    return a->model->cls->add(a->model, out, a, b);
}

int gcolor_mul(GColor *out, const GColor *a, const GColor *b)
{
    if (a->model != b->model || out->model != a->model)
        return G_ERR_MISMATCH;
    return a->model->cls->mul(a->model, out, a, b);
}

int gcolor_scale(GColor *out, const GColor *a, double s)
{
    if (out->model != a->model)
        return G_ERR_MISMATCH;
    return a->model->cls->scale(a->model, out, a, s);
}

int gcolor_div(GColor *out, const GColor *a, const GColor *b)
{
    if (a->model != b->model || out->model != a->model)
        return G_ERR_MISMATCH;
    return a->model->cls->div(a->model, out, a, b);
}

int gcolor_pow(GColor *out, const GColor *a, double e)
{
    if (out->model != a->model)
        return G_ERR_MISMATCH;
    return a->model->cls->pow(a->model, out, a, e);
}

/* The default brightness, for a model without the slot: Y of the value as a reflectance under D65, through the
 * model's own conversion; a value whose Y is not > 0 (a spectrum outside the eye's range, or one whose negative
 * samples cancel its positive ones) and is not black gets the smallest normal double, so that 0 still means black
 * alone. Out of line, as to_xyz_through_nm: the dispatch needs no stack frame. */
__attribute__((noinline)) static double default_brightness(const GColor *c)
{
    double xyz[3];
    if (gcolor_to_xyz(c, GCOLOR_REFLECTANCE, xyz) == G_OK && xyz[1] > 0.0)
        return xyz[1];
    for (int k = 0; k < c->model->nvalues; k++)
        if (c->v[k] != 0.0f)
            return isfinite(xyz[1]) ? DBL_MIN : NAN;
    return 0.0;
}

double gcolor_brightness(const GColor *c)
{
    const GColorModelClass *cls = c->model->cls;
    return cls->brightness ? cls->brightness(c->model, c) : default_brightness(c);
}

int gcolor_exp(GColor *out, const GColor *a, double s)
{
    if (out->model != a->model)
        return G_ERR_MISMATCH;
    const GColorModel *m = a->model;
    if (m->cls->exp_scaled)
        return m->cls->exp_scaled(m, out, a, s);
    if (a->kind != GCOLOR_VECTOR)
        return G_ERR_UNSUPPORTED;
    for (int i = 0; i < m->nvalues; i++)
        out->v[i] = (float)exp(s * a->v[i]);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

/* ---- conversions ---- */

/* The role a model's class is handed: a unitless quantity is read as a reflectance (color.h). */
static GColorRole class_role(GColorRole role) { return role == GCOLOR_UNITLESS ? GCOLOR_REFLECTANCE : role; }

int gcolor_to_nm(const GColor *c, GColorRole role, GSpectrumNM *out)
{
    return c->model->cls->to_nm(c->model, c, class_role(role), out);
}

/* A unitless curve in a model whose vectors are samples at wavelengths: its value at each sample's wavelength,
 * linear between whole nm and the edge value beyond the exchange grid. */
static void unitless_at_wavelengths(GColor *c, const GSpectrumNM *in)
{
    const GColorModel *m = c->model;
    for (int k = 0; k < m->nsamples; k++) {
        double x = m->lambda_min + k * m->lambda_step - GNM_MIN;
        x = x < 0.0 ? 0.0 : x > GNM_COUNT - 1 ? GNM_COUNT - 1 : x;
        int i = (int)x;
        if (i > GNM_COUNT - 2)
            i = GNM_COUNT - 2;
        double t = x - i;
        c->v[k] = (float)((1.0 - t) * in->v[i] + t * in->v[i + 1]);
    }
    c->kind = GCOLOR_VECTOR;
}

int gcolor_from_nm(GColor *c, const GSpectrumNM *in, GColorRole role)
{
    for (int i = 0; i < GNM_COUNT; i++)
        if (!isfinite(in->v[i]))
            return G_ERR_INVALID;
    const GColorModel *m = c->model;
    if (role == GCOLOR_UNITLESS && !m->cls->fill && m->nsamples > 0 && m->nsamples == m->nvalues &&
        m->lambda_step > 0.0 && isfinite(m->lambda_min)) {
        unitless_at_wavelengths(c, in);
        return G_OK;
    }
    return m->cls->from_nm(m, in, class_role(role), c);
}

int gcolormodel_xyz_shows_nonfinite(const GColorModel *m)
{
    return m && (m->cls->to_xyz == gspectral_to_xyz || m->cls->to_xyz == gspectral_to_xyz_folded);
}

/* gcolor_to_xyz for a model without to_xyz: through the nm spectrum. Out of line, so that the dispatch to the class
 * keeps no room for the spectrum on its stack. */
__attribute__((noinline)) static int to_xyz_through_nm(const GColor *c, GColorRole role, double xyz[3])
{
    GSpectrumNM s;
    int rc = gcolor_to_nm(c, role, &s);
    if (rc == G_OK)
        gcie_nm_to_xyz(&s, role, xyz);
    return rc;
}

int gcolor_to_xyz(const GColor *c, GColorRole role, double xyz[3])
{
    role = class_role(role);
    if (c->model->cls->to_xyz)
        return c->model->cls->to_xyz(c->model, c, role, xyz);
    return to_xyz_through_nm(c, role, xyz);
}

int gcolor_to_rgb(const GColor *c, GColorRole role, double rgb[3])
{
    double xyz[3];
    int rc = gcolor_to_xyz(c, role, xyz);
    if (rc == G_OK)
        gcie_xyz_to_rgb(xyz, rgb);
    return rc;
}

int gcolor_from_rgb(GColor *c, const double rgb[3], GColorRole role)
{
    if (!isfinite(rgb[0]) || !isfinite(rgb[1]) || !isfinite(rgb[2]))
        return G_ERR_INVALID;
    role = class_role(role);
    if (c->model->cls->from_rgb)
        return c->model->cls->from_rgb(c->model, rgb, role, c);
    GSpectrumNM s;
    gcie_rgb_to_nm(rgb, role, &s);
    return c->model->cls->from_nm(c->model, &s, role, c);
}

/* A matrix whose emission or excitation wavelengths all lie outside the model's range (a spectral model's
 * samples, else the exchange grid GNM_MIN..GNM_MAX) would convert to black: refused, naming both ranges. */
static int reradiation_overlaps(const GColorModel *m, const GReradiation *r, GError *err)
{
    double lo = GNM_MIN, hi = GNM_MAX;
    if (m->nsamples > 0 && isfinite(m->lambda_min) && m->lambda_step > 0) {
        lo = m->lambda_min;
        hi = m->lambda_min + (m->nsamples - 1) * m->lambda_step;
    }
    double tol = 1e-6 * (fabs(lo) + fabs(hi));
    double out_hi = r->out_min + (r->n_out - 1) * r->out_step, in_hi = r->in_min + (r->n_in - 1) * r->in_step;
    const char *which = NULL;
    double a = 0.0, b = 0.0;
    if (!(out_hi >= lo - tol && r->out_min <= hi + tol))
        which = "emission", a = r->out_min, b = out_hi;
    else if (!(in_hi >= lo - tol && r->in_min <= hi + tol))
        which = "excitation", a = r->in_min, b = in_hi;
    if (!which)
        return G_OK;
    return gerror_set(err, G_ERR_INVALID,
                      "re-radiation matrix: its %s wavelengths %g..%g nm lie outside the range of the colour "
                      "model '%s' (%g..%g nm), so it would be black",
                      which, a, b, gcolormodel_name(m), lo, hi);
}

int gcolor_from_reradiation(GColor *c, const GReradiation *r, GError *err)
{
    if (!r || !r->data || r->n_in <= 0 || r->n_out <= 0 || !(r->in_step > 0) || !(r->out_step > 0) ||
        !isfinite(r->in_min) || !isfinite(r->in_step) || !isfinite(r->out_min) || !isfinite(r->out_step))
        return gerror_set(err, G_ERR_INVALID, "re-radiation matrix has an empty or invalid grid");
    for (long i = 0; i < (long)r->n_in * r->n_out; i++)
        if (!isfinite(r->data[i]))
            return gerror_set(err, G_ERR_INVALID, "re-radiation matrix holds a non-finite value");
    int rc = reradiation_overlaps(c->model, r, err);
    if (rc != G_OK)
        return rc;
    if (c->model->cls->from_reradiation)
        return c->model->cls->from_reradiation(c->model, r, c, err);
    /* Fold: the response to an equal-energy light over the exchange range, read as a reflectance. */
    GSpectrumNM s;
    for (int i = 0; i < GNM_COUNT; i++) {
        double nm = GNM_MIN + i;
        double f = (nm - r->out_min) / r->out_step;
        if (!(f > -1.0 && f < r->n_out)) { /* no emission row within one step (also a grid far away) */
            s.v[i] = 0.0f;
            continue;
        }
        int o = (int)floor(f);
        double t = f - o, v = 0.0;
        for (int k = 0; k < 2; k++) {
            int row = o + k;
            double w = k ? t : 1.0 - t;
            if (row < 0 || row >= r->n_out || w == 0.0)
                continue;
            double sum = 0.0;
            for (int j = 0; j < r->n_in; j++) {
                double in_nm = r->in_min + j * r->in_step;
                if (in_nm >= GNM_MIN - 1e-9 && in_nm <= GNM_MAX + 1e-9)
                    sum += r->data[(long)row * r->n_in + j];
            }
            v += w * sum;
        }
        s.v[i] = (float)v;
    }
    rc = c->model->cls->from_nm(c->model, &s, GCOLOR_REFLECTANCE, c);
    /* A fluorescent pigment's fold is often outside the rgb gamut (day-glo orange has a negative blue): a
     * negative reflectance would subtract light, so such components become 0 and the luminance is kept
     * (gcolor_clip_to_gamut, the mapping out-of-gamut lights get too; the spectral models sample the
     * non-negative fold and are not affected). */
    return rc == G_OK ? gcolor_clip_to_gamut(c, GCOLOR_REFLECTANCE, NULL) : rc;
}

int gcolor_convert(GColor *dst, const GColor *src, GColorRole role)
{
    if (dst->model == src->model)
        return gcolor_copy(dst, src);
    if (src->model->nsamples == 0 && src->kind == GCOLOR_VECTOR) {
        /* a tristimulus model: its exact colour, then the target's own (exact) from_rgb */
        double rgb[3];
        int rc = gcolor_to_rgb(src, role, rgb);
        return rc ? rc : gcolor_from_rgb(dst, rgb, role);
    }
    GSpectrumNM s;
    int rc = gcolor_to_nm(src, role, &s);
    return rc ? rc : gcolor_from_nm(dst, &s, role);
}

/* ---- wavelength bands (dispersion) ---- */

size_t gcolormodel_value_bytes(const GColorModel *m) { return (size_t)m->capacity * sizeof(float); }

int gcolormodel_band_count(const GColorModel *m) { return record_of(m)->bands; }

int gcolor_band_mask(GColor *out, int band)
{
    const GColorModel *m = out->model;
    if (band < 0 || band >= gcolormodel_band_count(m))
        return G_ERR_INVALID;
    if (m->cls->band_mask)
        return m->cls->band_mask(m, band, out);
    return gcolor_fill(out, 1.0);
}

/* The default band value: brightness(mask * c) / brightness(mask), through temporaries of the thread's arena. Out of
 * line: gcolor_band_value's other paths need no stack frame. */
__attribute__((noinline)) static double band_value_by_mask(const GColorModel *m, const GColor *c, int band)
{
    GScratch *arena = gscratch_thread();
    if (!arena)
        return NAN;
    GScratchMark mark = gscratch_mark(arena);
    GColor mask, part;
    double v = NAN;
    if (gcolor_scratch(&mask, m, arena) == G_OK && gcolor_scratch(&part, m, arena) == G_OK &&
        gcolor_band_mask(&mask, band) == G_OK && gcolor_mul(&part, &mask, c) == G_OK) {
        double w = gcolor_brightness(&mask);
        v = w > 0.0 ? gcolor_brightness(&part) / w : NAN;
    }
    gscratch_release(arena, mark);
    return v;
}

double gcolor_band_value(const GColor *c, int band)
{
    const GColorModel *m = c->model;
    if (c->kind != GCOLOR_VECTOR || band < 0 || band >= record_of(m)->bands)
        return NAN;
    if (m->cls->band_value == gspectral_band_value) /* the kit's: the sample itself, without the call (a path
                                                      * tracer's roulette reads a dozen bands a bounce) */
        return c->v[band];
    if (m->cls->band_value)
        return m->cls->band_value(m, c, band);
    if (!m->cls->band_count)
        return gcolor_brightness(c); /* the one band is everything */
    return band_value_by_mask(m, c, band);
}

double gcolor_band_peak(const GColor *c, int first, int step)
{
    int n = record_of(c->model)->bands;
    double peak = 0.0;
    if (first < 0 || step < 1)
        return NAN;
    if (c->kind == GCOLOR_VECTOR && c->model->cls->band_value == gspectral_band_value) { /* the samples themselves */
        for (long i = first; i < n; i += step) {
            double v = c->v[i];
            if (isnan(v))
                return NAN;
            peak = v > peak ? v : peak;
        }
        return peak;
    }
    for (long i = first; i < n; i += step) {
        double v = gcolor_band_value(c, (int)i);
        if (isnan(v))
            return NAN;
        peak = v > peak ? v : peak;
    }
    return peak;
}

/* ---- range after conversion ---- */

/* gcolormodel_rgb_range's measurement. */
static int measure_rgb_range(const GColorModel *m, GColorRole role, double *lo, double *hi)
{
    *lo = 0.0;
    *hi = 0.0;
    GScratch *arena = gscratch_thread();
    if (!arena)
        return G_ERR_NOMEM;
    GScratchMark mark = gscratch_mark(arena);
    GColor p;
    int rc = gcolor_scratch(&p, m, arena);
    /* per sample, the extremes over the cube's seven corners other than black: exact for a linear from_rgb (the
     * extremes of a linear function on a cube lie at its corners: the sums of the primaries' negative or positive
     * parts), and the corners' own values for a smooth one (the sigmoid uplift) */
    for (int corner = 1; corner < 8 && rc == G_OK; corner++) {
        double e[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
        rc = gcolor_from_rgb(&p, e, role);
        for (int k = 0; rc == G_OK && k < m->nvalues; k++) {
            *lo = fmin(*lo, p.v[k]);
            *hi = fmax(*hi, p.v[k]);
        }
    }
    gscratch_release(arena, mark);
    return rc;
}

int gcolormodel_rgb_range(const GColorModel *m, GColorRole role, double *lo, double *hi)
{
    ModelRecord *rec = record_of(m);
    int r = class_role(role) == GCOLOR_LIGHT;
    pthread_mutex_lock(&rec->lock);
    int rc = G_OK;
    if (!rec->have_range[r]) {
        rc = measure_rgb_range(m, class_role(role), &rec->range[r][0], &rec->range[r][1]);
        rec->have_range[r] = rc == G_OK && rec->ready;
    }
    *lo = rc == G_OK ? rec->range[r][0] : 0.0;
    *hi = rc == G_OK ? rec->range[r][1] : 0.0;
    pthread_mutex_unlock(&rec->lock);
    return rc;
}

/* Negative samples to 0 (gcolor_clip_to_gamut, gcolor_clip_light_to_gamut); the luminance kept when keep_luminance
 * or when the value was within the model's conversion error. */
static int clip_negative(GColor *c, GColorRole role, int keep_luminance, int *mapped)
{
    if (mapped)
        *mapped = 0;
    if (c->kind != GCOLOR_VECTOR)
        return G_OK;
    const GColorModel *m = c->model;
    double most = -INFINITY;
    for (int k = 0; k < m->nvalues; k++) {
        if (!isfinite(c->v[k]))
            return G_ERR_INVALID;
        most = fmax(most, c->v[k]);
    }
    double lowest = INFINITY;
    for (int k = 0; k < m->nvalues; k++)
        lowest = fmin(lowest, c->v[k]);
    if (lowest >= 0.0)
        return G_OK;
    double xyz[3], rgb[3], lo, hi;
    int rc = gcolor_to_xyz(c, role, xyz);
    if (rc == G_OK)
        rc = gcolormodel_rgb_range(m, role, &lo, &hi);
    if (rc != G_OK)
        return rc;
    gcie_xyz_to_rgb(xyz, rgb);
    double s = fmax(0.0, fmax(rgb[0], fmax(rgb[1], rgb[2]))), y0 = xyz[1];
    /* out of gamut: an RGB component below 0 (beyond rounding), or a sample below what conversion gives */
    double eps = 1e-5 * fmax(s, most > 0.0 ? most : 0.0);
    int out = fmin(rgb[0], fmin(rgb[1], rgb[2])) < -eps || lowest < lo * s - eps;
    for (int k = 0; k < m->nvalues; k++)
        if (c->v[k] < 0.0f)
            c->v[k] = 0.0f;
    keep_luminance |= !out;
    double y1 = 0.0;
    if (keep_luminance && (rc = gcolor_to_xyz(c, role, xyz)) != G_OK)
        return rc;
    y1 = xyz[1];
    if (keep_luminance && y0 > 0.0 && y1 > 0.0 && isfinite(y0 / y1))
        rc = gcolor_scale(c, c, y0 / y1);
    if (mapped)
        *mapped = out;
    return rc;
}

int gcolor_clip_to_gamut(GColor *c, GColorRole role, int *mapped) { return clip_negative(c, role, 1, mapped); }

int gcolor_clip_light_to_gamut(GColor *c, int *mapped) { return clip_negative(c, GCOLOR_LIGHT, 0, mapped); }
