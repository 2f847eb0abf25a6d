/* methods.c - every approximation gprobe compares, lights and bases alike, behind one interface: names,
 * the sizes eval and report try, making one, and its irradiance and radiance. */
#include "gprobe.h"

#include <generic/memory.h>

#include <string.h>

#define STR_(x) #x
#define STR(x) STR_(x)

/* The list's order fixes each method's colour in the plots (plot.c), whatever methods a run uses. */
static const Method methods[] = {
    {"mediancut", GPROBE_MEDIANCUT, -1, "lights"},
    {"adaptive", GPROBE_ADAPTIVE, -1, "lights"},
    {"kmeans", GPROBE_KMEANS, -1, "lights"},
    {"irradiance", GPROBE_IRRADIANCE, -1, "lights"},
    {"variance", GPROBE_VARIANCE, -1, "lights"},
    {"sh", -1, GPROBE_BASIS_SH, "coefficients"},
    {"sh-hanning", -1, GPROBE_BASIS_SH_HANNING, "coefficients"},
    {"ambientcube", -1, GPROBE_BASIS_AMBIENT_CUBE, "coefficients"},
    {"sg-naive", -1, GPROBE_BASIS_SG_NAIVE, "lobes"},
    {"sg-ls", -1, GPROBE_BASIS_SG_LS, "lobes"},
    {"sg-nnls", -1, GPROBE_BASIS_SG_NNLS, "lobes"},
    {"sg-ambient", -1, GPROBE_BASIS_SG_AMBIENT, "lobes"},
    {"sh9", -1, GPROBE_BASIS_SH, "coefficients"}, /* the 9-coefficient reference line of the first plots */
};

const char methods_names[] = "mediancut, adaptive, kmeans, irradiance, variance, sh, sh-hanning, ambientcube, "
                             "sg-naive, sg-ls, sg-nnls, sg-ambient, sh9";

int method_count(void) { return (int)(sizeof methods / sizeof methods[0]); }

const Method *method_get(int i) { return i >= 0 && i < method_count() ? &methods[i] : NULL; }

int method_find(const char *name)
{
    for (int i = 0; i < method_count(); i++)
        if (strcmp(methods[i].name, name) == 0)
            return i;
    return -1;
}

int method_is_sh9(int i) { return i == method_count() - 1; }

int method_sizes(int i, const int *counts, int ncounts, int fit_normals, int *out, int quiet)
{
    const Method *m = &methods[i];
    int n = 0;
    if (method_is_sh9(i)) {
        out[0] = 9;
        return 1;
    }
    if (m->basis == GPROBE_BASIS_SH || m->basis == GPROBE_BASIS_SH_HANNING) {
        for (int l = 1; l <= GPROBE_SH_MAX_ORDER; l++)
            out[n++] = GPROBE_SH_COEFFS(l);
        return n;
    }
    if (m->basis == GPROBE_BASIS_AMBIENT_CUBE) {
        out[0] = 6;
        return 1;
    }
    for (int c = 0; c < ncounts; c++) {
        int k = counts[c];
        const char *why = NULL;
        if (m->light == GPROBE_MEDIANCUT && (k & (k - 1)) != 0)
            why = "median cut makes powers of two";
        else if (m->light == GPROBE_IRRADIANCE && 2 * k > (fit_normals > 0 ? fit_normals : 2000))
            why = "needs twice as many fit normals: --fit-normals";
        else if (m->light == GPROBE_IRRADIANCE && k > GPROBE_FIT_MAX_LIGHTS)
            why = "the fit's limit is " STR(GPROBE_FIT_MAX_LIGHTS) " lights";
        else if (m->basis >= 0 && k > GPROBE_SG_MAX_LOBES)
            why = "at most " STR(GPROBE_SG_MAX_LOBES) " lobes";
        if (why) {
            if (!quiet)
                fprintf(stderr, "  %-12s N=%-4d skipped (%s)\n", m->name, k, why);
            continue;
        }
        out[n++] = k;
    }
    return n;
}

int approx_make(const GProbe *p, int method, int n, const GProbeOptions *opt, Approx *a, GProbeFitReport *rep,
                GError *err)
{
    memset(a, 0, sizeof *a);
    a->method = method;
    a->n = n;
    const Method *m = &methods[method];
    if (m->basis >= 0)
        return gprobe_basis_fit(p, (GProbeBasisKind)m->basis, n, &a->basis, err);
    if (!(a->lights = gmem_calloc((size_t)n, sizeof *a->lights)))
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d lights", n);
    int rc = m->light == GPROBE_IRRADIANCE ? gprobe_irradiance_fit(p, n, opt, a->lights, rep, err)
                                           : gprobe_approximate(p, (GProbeTechnique)m->light, n, opt, a->lights, err);
    if (rc != G_OK)
        approx_free(a);
    return rc;
}

void approx_irradiance(const Approx *a, const GVec3 *normals, int m, double *E)
{
    if (a->lights)
        gprobe_lights_irradiance(a->lights, a->n, normals, m, E);
    else
        gprobe_basis_irradiance(&a->basis, normals, m, E);
}

void approx_free(Approx *a)
{
    gmem_free(a->lights);
    a->lights = NULL;
    gprobe_basis_free(&a->basis);
}
