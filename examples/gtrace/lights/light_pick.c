/* light_pick.c - the scene's light sources in one alias table by power (light_pick.h). The power of each is emit.c's
 * emit_power (the brightness of its colour in the light role times the factor that turns it into the power it sends
 * into the scene: 4 pi for a point light, pi R^2 of the scene's bounds for a directional light or a probe, pi times
 * the area for an area light) and the glowing geometry's is emissive_power (pi times the sum of its primitives' area
 * times their emission's brightness): the same measure, so a rectangle light and an emitter quad of the same radiance
 * and size weigh the same. The power is a guide: any choice of positive probabilities is unbiased, a poor guide only
 * adds noise. Lights that send nothing by this measure (a probe's basis, ambient light, black lights) are left out. */
#include "light_pick.h"
#include "alias_table.h"

#include <generic/memory.h>

#include <math.h>

/* 1 for the kinds of light material sampling never meets. */
static int light_pick_kind_delta(const Light *l)
{
    return l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_DIRECTIONAL || l->kind == LIGHT_IES;
}

void light_pick_free(LightPick *lp)
{
    gmem_free(lp->lights);
    gmem_free(lp->prob);
    gmem_free(lp->q);
    gmem_free(lp->alias);
    gmem_free(lp->scene_prob);
    gmem_free(lp->area);
    gmem_free(lp->bright);
    gmem_free(lp->delta);
    gmem_free(lp->delta_q);
    gmem_free(lp->delta_alias);
    *lp = (LightPick){0};
}

int light_pick_build(LightPick *lp, const Scene *s, const EmissiveSet *e, GError *err)
{
    *lp = (LightPick){0};
    emit_bounds(s, &lp->bounds);
    size_t cap = (size_t)s->nlights + 1;
    lp->lights = gmem_calloc(cap, sizeof *lp->lights);
    lp->prob = gmem_calloc(cap, sizeof *lp->prob);
    lp->q = gmem_calloc(cap, sizeof *lp->q);
    lp->alias = gmem_calloc(cap, sizeof *lp->alias);
    lp->scene_prob = gmem_calloc(cap, sizeof *lp->scene_prob);
    lp->area = gmem_calloc(cap, sizeof *lp->area);
    lp->bright = gmem_calloc(cap, sizeof *lp->bright);
    lp->delta = gmem_calloc(cap, sizeof *lp->delta);
    lp->delta_q = gmem_calloc(cap, sizeof *lp->delta_q);
    lp->delta_alias = gmem_calloc(cap, sizeof *lp->delta_alias);
    int *entry = gmem_calloc(cap, sizeof *entry); /* the entry of each scene light (-1: none) */
    if (!lp->lights || !lp->prob || !lp->q || !lp->alias || !lp->scene_prob || !lp->area || !lp->bright ||
        !lp->delta || !lp->delta_q || !lp->delta_alias || !entry) {
        gmem_free(entry);
        light_pick_free(lp);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the table of %d lights", s->nlights);
    }
    double total = 0.0;
    for (int i = 0; i < s->nlights; i++) {
        const Light *l = s->lights[i];
        entry[i] = -1;
        if (l->kind == LIGHT_SPHERE || l->kind == LIGHT_RECT)
            lp->area[lp->narea++] = i;
        double w = emit_supported(l) ? emit_power(l, &lp->bounds) : 0.0;
        if (!(w > 0.0) || !isfinite(w) || !isfinite(total + w))
            continue;
        entry[i] = lp->n;
        if (light_pick_kind_delta(l))
            lp->delta[lp->ndelta++] = lp->n;
        lp->bright[lp->n] = gcolor_brightness_as(&l->color, GCOLOR_LIGHT);
        lp->lights[lp->n] = l;
        lp->prob[lp->n++] = w;
        total += w;
    }
    double we = emissive_power(e);
    int emissive_entry = -1;
    if (we > 0.0 && isfinite(we) && isfinite(total + we)) { /* the glowing geometry, after the lights */
        lp->emissive = e;
        emissive_entry = lp->n;
        lp->lights[lp->n] = NULL;
        lp->prob[lp->n++] = we;
        total += we;
    }
    int rc = G_OK;
    if (lp->n > 0) {
        for (int k = 0; k < lp->n; k++)
            lp->prob[k] /= total;
        rc = alias_table_build(lp->prob, lp->n, lp->q, lp->alias);
        for (int d = 0; d < lp->ndelta; d++)
            lp->delta_prob += lp->prob[lp->delta[d]];
        double *dp = lp->ndelta > 0 && rc == G_OK ? gmem_alloc(sizeof *dp * (size_t)lp->ndelta) : NULL;
        if (lp->ndelta > 0 && rc == G_OK && !dp)
            rc = G_ERR_NOMEM;
        for (int d = 0; dp && d < lp->ndelta; d++)
            dp[d] = lp->prob[lp->delta[d]] / lp->delta_prob;
        if (dp)
            rc = alias_table_build(dp, lp->ndelta, lp->delta_q, lp->delta_alias);
        gmem_free(dp);
        for (int i = 0; i < s->nlights; i++)
            lp->scene_prob[i] = entry[i] >= 0 ? lp->prob[entry[i]] : 0.0;
        lp->emissive_prob = emissive_entry >= 0 ? lp->prob[emissive_entry] : 0.0;
    }
    lp->every = lp->n <= LIGHT_PICK_EVERY_MAX;
    gmem_free(entry);
    if (rc != G_OK) {
        light_pick_free(lp);
        return gerror_set(err, rc, "out of memory for the table of %d lights", s->nlights);
    }
    return G_OK;
}

int light_pick_sample(const LightPick *lp, double u, double *prob, double *u_rest)
{
    if (!lp || lp->n <= 0) {
        *prob = 0.0;
        return -1;
    }
    int k = alias_table_pick(lp->q, lp->alias, lp->n, u, u_rest);
    *prob = lp->prob[k];
    return k;
}

double light_pick_pmf(const LightPick *lp, int i) { return lp && lp->scene_prob ? lp->scene_prob[i] : 0.0; }

int light_pick_delta(const LightPick *lp, double u)
{
    return lp->delta[alias_table_pick(lp->delta_q, lp->delta_alias, lp->ndelta, u, NULL)];
}

int light_pick_is_delta(const LightPick *lp, int k) { return lp->lights[k] && light_pick_kind_delta(lp->lights[k]); }

int light_pick_nee_every(const LightPick *lp) { return lp && lp->every; }

double light_pick_nee_pmf(const LightPick *lp, int i) { return light_pick_nee_every(lp) ? 1.0 : light_pick_pmf(lp, i); }

double light_pick_nee_emissive_pmf(const LightPick *lp) { return light_pick_nee_every(lp) ? 1.0 : lp->emissive_prob; }
