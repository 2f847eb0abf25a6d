/* bfc.c - the colour literal `bfc "FILE.BFC"`: a measured re-radiation matrix (a Labsphere BFC file), a
 * reflectance only. */
#include "generic/colorspec.h"
#include "generic/memory.h"
#include "generic/plugin.h"
#include "generic/reader.h"
#include "generic/services/bfc.h"

#include <stdio.h>

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
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_RERADIATION;
    char *path = NULL;
    int rc = greader_path(r, &path, err);
    GBfcData d;
    if (rc == G_OK && (rc = gbfc_read(path, &d, err)) == G_OK) {
        char what[96];
        snprintf(what, sizeof what, "a %dx%d re-radiation matrix", d.rerad.n_out, d.rerad.n_in);
        if ((rc = gcolorspec_own_matrix(s, &d.rerad, d.values, what, err)) == G_OK)
            clean_matrix(&s->rerad, s->owned_data);
        else
            rc = greader_locate(r, err);
    }
    gmem_free(path);
    if (rc != G_OK) {
        gcolorspec_destroy(s);
        return rc;
    }
    *object = s;
    return G_OK;
}

static const GParamInfo bfc_params[] = {
    {"FILE", GPARAM_POSITIONAL, "path", NULL, "a Labsphere BFC-450 text file",
     "a measured re-radiation (Donaldson) matrix, for reflectances only"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_bfc, GKIND_COLOR, "bfc", parse_bfc,
                          "measured re-radiation matrix: bfc \"FILE.BFC\"", NULL, bfc_params);
