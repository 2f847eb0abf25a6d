/* medium.c - the kind `medium` and its type homogeneous:
 *
 *   medium NAME? homogeneous { sigma_a COLOUR sigma_s COLOUR phase PHASE scale S }
 *
 * Coefficients per scene unit, in the file's colour model, >= 0 in every band; `scale` multiplies both. A ray is
 * in a medium inside an object that names it as its `interior` (the medium belongs to that object's material: every
 * object of that material bounds it) and, outside every object, in the camera's `atmosphere`.
 *
 * Free flight (medium_sample_distance): the bands of the model differ in extinction, so no one exponential is
 * right for all of them. A band j is chosen uniformly and a distance drawn from sigma_t[j] exp(-sigma_t[j] t); the
 * sample is weighted with the mean density of all bands (the balance heuristic over the bands' strategies, "spectral
 * MIS", Wilkie et al. 2014 "Hero wavelength spectral sampling"): the estimate of every band stays unbiased and none
 * has unbounded weight, in an RGB model (3 bands) as in a spectral one (tens). */
#include "medium.h"

#include <generic/memory.h>
#include <generic/reader.h>

#include <math.h>
#include <string.h>

GKind gtrace_kind_medium = GKIND_MAX;

int media_register_kinds(GError *err)
{
    static const GKindInfo phases = {"phase", NULL, 0}, media = {"medium", NULL, 0};
    int rc = gregistry_add_kind(&phases, &gtrace_kind_phase, err);
    return rc == G_OK ? gregistry_add_kind(&media, &gtrace_kind_medium, err) : rc;
}

const Medium *medium_current(const Scene *s, const Media *media)
{
    if (!s->has_media)
        return NULL;
    const GMaterial *top = media_top(media);
    if (!top || (media->n == 1 && top == s->medium))
        return s->atmosphere;
    for (int i = 0; i < s->ninteriors; i++)
        if (s->interiors[i].material == top)
            return s->interiors[i].medium;
    return NULL;
}

int media_bind_scene(Scene *s, const char *name, GError *err)
{
    int n = 0;
    for (int i = 0; i < s->nobjects; i++)
        n += s->objects[i]->interior != NULL;
    s->has_media = s->atmosphere != NULL || n > 0;
    if (n == 0)
        return G_OK;
    s->interiors = gmem_calloc((size_t)n, sizeof *s->interiors);
    if (!s->interiors)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", name);
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (!o->interior)
            continue;
        int k = 0;
        while (k < s->ninteriors && s->interiors[k].material != o->material)
            k++;
        if (k < s->ninteriors && s->interiors[k].medium != o->interior)
            return gerror_set(err, G_ERR_INVALID, "%s: objects of one material ('%s') name different interiors: a "
                              "medium belongs to the material that bounds it, give each its own material", name,
                              gmaterial_name(o->material));
        if (k == s->ninteriors)
            s->interiors[s->ninteriors++] = (MediumBinding){o->material, o->interior};
    }
    return G_OK;
}

int medium_attenuate(const Medium *m, double d, GColor *light, GScratch *scratch)
{
    /* exp(-sigma_t d): a distance capped so that 0 * d stays 0 (a band without extinction passes everything) */
    double dd = isfinite(d) ? d : 1e300;
    GScratchMark mark = gscratch_mark(scratch);
    GColor tr;
    int rc = gcolor_scratch_uncleared(&tr, light->model, scratch); /* the exp writes it in full */
    if (rc == G_OK && (rc = gcolor_exp(&tr, &m->sigma_t, -dd)) == G_OK)
        rc = gcolor_mul(light, light, &tr);
    gscratch_release(scratch, mark);
    return rc;
}

int medium_sample_distance(const Medium *m, double tmax, double u_band, double u_dist, double *t, GColor *weight)
{
    if (!m->scatters) { /* absorption only: the transmittance itself, no sampling (and no noise) */
        *t = tmax;
        return gcolor_exp(weight, &m->sigma_t, isfinite(tmax) ? -tmax : -1e300);
    }
    int n = m->bands, j = (int)(u_band * n);
    j = j < n ? j : n - 1;
    double sj = gcolor_band_value(&m->sigma_t, j);
    double s = sj > 0.0 ? -log1p(-u_dist) / sj : INFINITY;
    int scatter = s < tmax;
    double d = scatter ? s : tmax, dd = isfinite(d) ? d : 1e300;
    int rc = gcolor_exp(weight, &m->sigma_t, -dd);
    if (rc < 0)
        return rc;
    /* the mean over the bands of the density (a scattering event) or of the probability (passing) */
    double p = 0.0;
    for (int i = 0; i < n; i++) {
        double si = gcolor_band_value(&m->sigma_t, i), tr = exp(-si * dd);
        p += scatter ? si * tr : (si > 0.0 ? tr : 1.0);
    }
    p /= n;
    if (!(p > 0.0)) /* every band extinct (passing an infinite medium): nothing arrives */
        return (rc = gcolor_fill(weight, 0.0)) < 0 ? rc : 0;
    if (scatter && (rc = gcolor_mul(weight, weight, &m->sigma_s)) < 0)
        return rc;
    if ((rc = gcolor_scale(weight, weight, 1.0 / p)) < 0)
        return rc;
    *t = d;
    return scatter;
}

/* ---- the type homogeneous ---- */

static void medium_free(Medium *m)
{
    if (!m)
        return;
    gcolor_free(&m->sigma_a);
    gcolor_free(&m->sigma_s);
    gcolor_free(&m->sigma_t);
    gmem_free(m);
}

static void destroy_medium(void *p) { medium_free(p); }

/* Reads a coefficient: a colour of the file's model, a vector >= 0 and finite in every band; refused at its
 * position otherwise. */
static int read_sigma(GReader *r, const char *key, GColor *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    gcolor_free(out);
    if (rc == G_OK)
        rc = greader_color(r, GCOLOR_REFLECTANCE, out, err);
    if (rc == G_OK && out->kind != GCOLOR_VECTOR)
        rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col, "homogeneous: %s must be a plain colour, "
                              "not a matrix", key);
    if (rc == G_OK && !gcolor_is_nonnegative(out))
        rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col, "homogeneous: %s must be finite and >= 0 in "
                              "every band (a coefficient per scene unit)", key);
    return rc;
}

static int parse_homogeneous(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Medium *m = gmem_calloc(1, sizeof *m);
    if (!m)
        return greader_error(r, err, "out of memory");
    m->phase = phase_isotropic();
    const GColorModel *model = greader_colormodel(r);
    double scale = 1.0;
    int rc = G_OK;
    const char *key;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "sigma_a") == 0)
            rc = read_sigma(r, key, &m->sigma_a, err);
        else if (strcmp(key, "sigma_s") == 0)
            rc = read_sigma(r, key, &m->sigma_s, err);
        else if (strcmp(key, "scale") == 0)
            rc = greader_number_in(r, 0.0, MEDIUM_MAX_SIGMA, &scale, err);
        else if (strcmp(key, "phase") == 0) {
            void *ph = NULL;
            const GTypeInfo *type = NULL;
            if ((rc = greader_object(r, gtrace_kind_phase, &ph, &type, err)) == G_OK)
                m->phase = ph;
        } else
            rc = greader_unknown_param(r, "sigma_a, sigma_s, phase, scale", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !m->sigma_a.v && (rc = gcolor_alloc(&m->sigma_a, model)) < 0)
        rc = greader_error(r, err, "out of memory");
    if (rc == G_OK && !m->sigma_s.v && (rc = gcolor_alloc(&m->sigma_s, model)) < 0)
        rc = greader_error(r, err, "out of memory");
    if (rc == G_OK && ((rc = gcolor_scale(&m->sigma_a, &m->sigma_a, scale)) < 0 ||
                       (rc = gcolor_scale(&m->sigma_s, &m->sigma_s, scale)) < 0 ||
                       (rc = gcolor_alloc(&m->sigma_t, model)) < 0 ||
                       (rc = gcolor_add(&m->sigma_t, &m->sigma_a, &m->sigma_s)) < 0))
        rc = greader_error(r, err, "homogeneous: cannot combine the coefficients in colour model '%s'",
                           gcolormodel_name(model));
    if (rc == G_OK) {
        m->bands = gcolormodel_band_count(model);
        for (int i = 0; i < m->bands && rc == G_OK; i++) {
            double st = gcolor_band_value(&m->sigma_t, i);
            if (!(st >= 0.0 && st <= MEDIUM_MAX_SIGMA))
                rc = greader_error(r, err, "homogeneous: sigma_a + sigma_s times scale must lie in [0, %g] in every "
                                   "band (band %d: %g)", MEDIUM_MAX_SIGMA, i, st);
        }
        m->scatters = !gcolor_is_black(&m->sigma_s);
    }
    if (rc == G_OK && m->bands < 1)
        rc = greader_error(r, err, "homogeneous: colour model '%s' has no bands", gcolormodel_name(model));
    if (rc < 0) {
        medium_free(m);
        return rc;
    }
    *object = m;
    return G_OK;
}

static const GParamInfo homogeneous_params[] = {
    {"sigma_a", GPARAM_NAMED, "colour", "0", ">= 0 per band",
     "the absorption coefficient per scene unit (a transmittance exp(-sigma_a d) without scattering)"},
    {"sigma_s", GPARAM_NAMED, "colour", "0", ">= 0 per band",
     "the scattering coefficient per scene unit (albedo sigma_s / (sigma_a + sigma_s))"},
    {"phase", GPARAM_NAMED, "phase", "isotropic", "a phase entry: isotropic, hg { g G }",
     "the distribution of scattered directions"},
    {"scale", GPARAM_NAMED, "number", "1", "[0, 1e9]", "multiplies both coefficients (the density)"},
    {NULL},
};

int media_register_types(GError *err)
{
    int rc = media_register_kinds(err);
    if (rc == G_OK)
        rc = phase_register_types(gtrace_kind_phase, err);
    if (rc == G_OK && !gregistry_find(gtrace_kind_medium, "homogeneous")) {
        static const int homogeneous_tag = 0;
        GTypeInfo t = {.kind = gtrace_kind_medium, .name = "homogeneous", .vtable = &homogeneous_tag,
                       .parse = parse_homogeneous,
                       .summary = "homogeneous participating medium: absorption, scattering, a phase function",
                       .destroy = destroy_medium, .params = homogeneous_params};
        rc = gregistry_add(&t, err);
    }
    return rc < 0 ? rc : G_OK;
}
