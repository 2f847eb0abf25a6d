/* reradiation_param.c - the `reradiation` colour type: the parametric re-radiation matrix (absorption band,
 * emission band, quantum yield, Stokes shift) read from text; the matrix itself is made by the library
 * (gfluor_matrix_create, lib/kit/reradiation.c). */
#include "generic/kit/fluorescent_kit.h"
#include "generic/plugin.h"

#include <math.h>
#include <stdio.h>
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
    char what[96];
    snprintf(what, sizeof what, "a %dx%d re-radiation matrix", n, n);
    if (gcolorspec_own_matrix(s, &mat, (float *)mat.data, what, err) != G_OK) {
        gcolorspec_destroy(s);
        return greader_locate(r, err);
    }
    *object = s;
    return G_OK;
}

static const GParamInfo reradiation_params[] = {
    {"absorb_peak", GPARAM_NAMED, "number", "470", "[100, 2000]", "the centre of the absorption band, in nm"},
    {"absorb_width", GPARAM_NAMED, "number", "115", "(0, 1000]",
     "the band's half width in nm: absorption falls to absorb_max e^(-1/2) this far from the peak"},
    {"absorb_shape", GPARAM_NAMED, "number", "8", "[1, 64]", "the band's edge exponent: 2 a Gaussian, larger flatter"},
    {"absorb_max", GPARAM_NAMED, "number", "0.97", "[0, 1]", "the share of the light absorbed at the peak"},
    {"emit_width", GPARAM_NAMED, "number", "20", "(0, 1000]", "the standard deviation of the emission band, in nm"},
    {"stokes_shift", GPARAM_NAMED, "number", "135", "[0, 1000]", "the emission peak minus the absorption peak, in nm"},
    {"quantum_yield", GPARAM_NAMED, "number", "0.65", "[0, 1]", "photons emitted per photon absorbed"},
    {"reflectance", GPARAM_NAMED, "number", "0.92", "[0, 1]", "the reflectance of the light that is not absorbed"},
    {"step", GPARAM_NAMED, "number", "the model's grid, else 5", "[1, 50]",
     "the matrix's grid spacing in nm, over 380..780 nm (default: the spectral model's own grid)"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(reradiation, GKIND_COLOR, "reradiation", parse_reradiation,
                          "parametric fluorescent re-radiation matrix: reradiation { absorb_peak NM ... "
                          "quantum_yield Q }",
                          NULL, reradiation_params);
