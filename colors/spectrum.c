/* spectrum.c - the colour literal `spectrum { NM VALUE ... }`: a tabulated spectrum on the 1 nm exchange grid,
 * linear between increasing (nm, value) pairs and constant beyond the first and the last. */
#include "generic/colorspec.h"
#include "generic/plugin.h"
#include "generic/reader.h"

/* Fills the grid from the pairs of the block. */
static int read_pairs(GReader *r, GSpectrumNM *out, GError *err)
{
    int rc = greader_block_begin(r, err);
    double pl = 0.0, pv = 0.0;
    int pairs = 0;
    while (rc == G_OK) {
        int end = greader_block_end(r, err);
        if (end < 0)
            return end;
        if (end)
            return pairs ? G_OK
                         : greader_error(r, err, "spectrum: expected wavelength/value pairs, found an empty block");
        double l = 0.0, v = 0.0; /* set before use; initialised for the link-time optimiser's flow analysis */
        int ll, lc;
        if ((rc = greader_number_in(r, 1.0, 100000.0, &l, err)) != G_OK)
            break;
        greader_position(r, &ll, &lc);
        if (pairs && !(l > pl))
            return greader_error(r, err, "spectrum: wavelength %g does not increase (the previous one is %g)", l, pl);
        end = greader_block_end(r, err);
        if (end != 0)
            return end < 0 ? end
                           : greader_error_at(r, err, G_ERR_PARSE, ll, lc, "spectrum: wavelength %g has no value", l);
        if ((rc = greader_number(r, &v, err)) != G_OK)
            break;
        for (int i = 0; i < GNM_COUNT; i++) {
            double nm = GNM_MIN + i;
            if (!pairs && nm <= l)
                out->v[i] = (float)v;
            else if (pairs && nm > pl && nm <= l)
                out->v[i] = (float)(pv + (v - pv) * (nm - pl) / (l - pl));
            else if (nm > l)
                out->v[i] = (float)v;
        }
        pl = l;
        pv = v;
        pairs++;
    }
    return rc;
}

static int parse_spectrum(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GColorSpec *s = gcolorspec_create();
    if (!s)
        return greader_error(r, err, "out of memory");
    s->form = GCOLORSPEC_NM;
    int rc = read_pairs(r, &s->nm, err);
    if (rc != G_OK) {
        gcolorspec_destroy(s);
        return rc;
    }
    *object = s;
    return G_OK;
}

static const GParamInfo spectrum_params[] = {
    {"PAIRS", GPARAM_POSITIONAL, "block", NULL, "{ NM VALUE ... }, wavelengths in [1, 100000] increasing",
     "the spectrum at those wavelengths, linear in between and held beyond the ends (values per nm for lights)"},
    {NULL},
};

GENERIC_TYPE_NAMED_PARAMS(color_spectrum, GKIND_COLOR, "spectrum", parse_spectrum,
                          "tabulated spectrum: spectrum { NM VALUE ... }", NULL, spectrum_params);
