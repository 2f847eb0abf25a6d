/* medium_parse.c - the kinds `medium` and `phase` and the medium type homogeneous:
 *
 *   medium NAME? homogeneous { sigma_a COLOUR sigma_s COLOUR phase PHASE scale S }
 *
 * Coefficients per scene unit, in the file's colour model, >= 0 and finite in every band; `scale` multiplies both;
 * every value is checked and refused at its position in the file. */
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

/* ---- the type homogeneous ---- */

void medium_free(Medium *m)
{
    if (!m)
        return;
    if (m->grid) {
        Grid *g = (Grid *)m->grid;
        grid_release(g);
        gmem_free(g);
    }
    gcolor_free(&m->sigma_a);
    gcolor_free(&m->sigma_s);
    gcolor_free(&m->sigma_t);
    gmem_free(m);
}

static void destroy_medium(void *p) { medium_free(p); }

/* Reads a coefficient: a colour of the file's model, a vector >= 0 and finite in every band; refused at its
 * position otherwise. */
static int read_sigma(GReader *r, const char *type, const char *key, GColor *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    gcolor_free(out);
    if (rc == G_OK)
        rc = greader_color(r, GCOLOR_REFLECTANCE, out, err);
    if (rc == G_OK && out->kind != GCOLOR_VECTOR)
        rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col, "%s: %s must be a plain colour, "
                              "not a matrix", type, key);
    if (rc == G_OK && !gcolor_is_nonnegative(out))
        rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col, "%s: %s must be finite and >= 0 in "
                              "every band (a coefficient per scene unit)", type, key);
    return rc;
}

int medium_read_param(GReader *r, const char *type, const char *key, Medium *m, double *scale, GError *err)
{
    int rc = 0;
    if (strcmp(key, "sigma_a") == 0)
        rc = read_sigma(r, type, key, &m->sigma_a, err);
    else if (strcmp(key, "sigma_s") == 0)
        rc = read_sigma(r, type, key, &m->sigma_s, err);
    else if (strcmp(key, "scale") == 0)
        rc = greader_number_in(r, 0.0, MEDIUM_MAX_SIGMA, scale, err);
    else if (strcmp(key, "phase") == 0) {
        void *ph = NULL;
        const GTypeInfo *type_info = NULL;
        if ((rc = greader_object(r, gtrace_kind_phase, &ph, &type_info, err)) == G_OK)
            m->phase = ph;
    } else
        return 0;
    return rc < 0 ? rc : 1;
}

int medium_complete(GReader *r, const char *type, Medium *m, double scale, GError *err)
{
    const GColorModel *model = greader_colormodel(r);
    int rc = G_OK;
    if (!m->sigma_a.v && (rc = gcolor_alloc(&m->sigma_a, model)) < 0)
        return greader_error(r, err, "out of memory");
    if (!m->sigma_s.v && (rc = gcolor_alloc(&m->sigma_s, model)) < 0)
        return greader_error(r, err, "out of memory");
    if ((rc = gcolor_scale(&m->sigma_a, &m->sigma_a, scale)) < 0 ||
        (rc = gcolor_scale(&m->sigma_s, &m->sigma_s, scale)) < 0 || (rc = gcolor_alloc(&m->sigma_t, model)) < 0 ||
        (rc = gcolor_add(&m->sigma_t, &m->sigma_a, &m->sigma_s)) < 0)
        return greader_error(r, err, "%s: cannot combine the coefficients in colour model '%s'", type,
                             gcolormodel_name(model));
    m->bands = gcolormodel_band_count(model);
    for (int i = 0; i < m->bands; i++) {
        double st = gcolor_band_value(&m->sigma_t, i);
        if (!(st >= 0.0 && st <= MEDIUM_MAX_SIGMA))
            return greader_error(r, err, "%s: sigma_a + sigma_s times scale must lie in [0, %g] in every band (band "
                                 "%d: %g)", type, MEDIUM_MAX_SIGMA, i, st);
    }
    m->scatters = !gcolor_is_black(&m->sigma_s);
    if (m->bands < 1)
        return greader_error(r, err, "%s: colour model '%s' has no bands", type, gcolormodel_name(model));
    return G_OK;
}

static int parse_homogeneous(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Medium *m = gmem_calloc(1, sizeof *m);
    if (!m)
        return greader_error(r, err, "out of memory");
    m->phase = phase_isotropic();
    double scale = 1.0;
    int rc = G_OK;
    const char *key;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = medium_read_param(r, "homogeneous", key, m, &scale, err);
        if (rc == 0)
            rc = greader_unknown_param(r, "sigma_a, sigma_s, phase, scale", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK)
        rc = medium_complete(r, "homogeneous", m, scale, err);
    if (rc < 0) {
        medium_free(m);
        return rc;
    }
    *object = m;
    return G_OK;
}

static const GParamInfo homogeneous_params[] = {
    {"sigma_a", GPARAM_NAMED, "color", "0", ">= 0 per band",
     "the absorption coefficient per scene unit (a transmittance exp(-sigma_a d) without scattering)"},
    {"sigma_s", GPARAM_NAMED, "color", "0", ">= 0 per band",
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
    if (rc == G_OK)
        rc = media_register_grid(gtrace_kind_medium, err);
    return rc < 0 ? rc : G_OK;
}
