/* reradiation_param.c - the `reradiation` colour type: the parametric re-radiation matrix (absorption band,
 * emission band, quantum yield, Stokes shift) read from text; the matrix itself is made by the library
 * (gfluor_matrix_create, lib/kit/reradiation.c). */
#include "generic/kit/fluorescent_kit.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

/* ---- the parametric matrix as a colour literal ----
 *
 *   color NAME reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97
 *                            emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 step 5 }
 *
 * holds the parametric matrix (gfluor_matrix_create) on the file's spectral grid (or 380..780 nm at `step` nm,
 * default 5, in non-spectral models). */

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

GENERIC_TYPE_NAMED(reradiation, GKIND_COLOR, "reradiation", parse_reradiation,
                   "parametric fluorescent re-radiation matrix: reradiation { absorb_peak NM ... quantum_yield Q }",
                   NULL);
