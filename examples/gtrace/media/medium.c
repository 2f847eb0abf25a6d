/* medium.c - participating media at render time: which medium a ray is in, transmittance and free-flight
 * sampling (the entries are read by medium_parse.c).
 *
 * A ray is in a medium inside an object that names it as its `interior` (the medium belongs to that object's material:
 * every object of that material bounds it) and, outside every object, in the camera's `atmosphere`.
 *
 * Free flight (medium_sample_distance): the bands of the model differ in extinction, so no one exponential is
 * right for all of them. A band j is chosen uniformly and a distance drawn from sigma_t[j] exp(-sigma_t[j] t); the
 * sample is weighted with the mean density of all bands (the balance heuristic over the bands' strategies: multiple
 * importance sampling over the wavelengths, Wilkie et al. 2014 "Hero wavelength sampling"): the estimate of every band
 * stays unbiased and none has unbounded weight, in a model of 3 bands as in one of tens. */
#include "medium.h"
#include "trace/trace.h"

#include <generic/memory.h>

#include <math.h>

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


double medium_distance_pdf(const Medium *m, double t)
{
    double p = 0.0;
    for (int i = 0; i < m->bands; i++) {
        double si = gcolor_band_value(&m->sigma_t, i);
        p += si * exp(-si * t);
    }
    return p / m->bands;
}
