/* medium_light.c - next-event estimation at a scattering event in a medium (the path tracer's medium vertices): a
 * sample of every light when the scene has few, else of one chosen by power (light_pick.h) divided by the choice's
 * probability, is weighted by the phase function instead of a material's reflection and carried to the point by
 * light_transmit (lights.c), which applies the media and the absorbing materials along the shadow ray. Sphere and
 * rectangle lights and glowing geometry, which the phase-sampled ray also reaches, follow the path tracer's rule: any
 * surface blocks their shadow ray, and the sample is weighted by the power heuristic against the phase function's
 * density (path.c weighs the light that phase sampling meets against theirs). Point, spot and IES lights in a
 * homogeneous medium are also sampled by equiangular sampling along the ray (medium_equiangular_light), the two
 * weighted by the balance heuristic. */
#include "medium_light.h"
#include "path.h"
#include "lights/emissive.h"
#include "lights/light_pick.h"
#include "lights/lighting.h"
#include "scene/accel.h"
#include "scene/ies.h"
#include "media/equiangular.h"

#include <math.h>

/* Adds L * scale * the phase density (times the transmittance to x over dist) to out; blocked: any surface on the way
 * stops it. */
static int add_sample(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, GVec3 in, double dist,
                      const GColor *L, double scale, int blocked, GColor *out)
{
    double f = phase_eval(vol->phase, d, in) * scale;
    if (!(f > 0.0))
        return G_OK;
    if (blocked) {
        Ray sr = {x, in, 0.0, dist * (1.0 - 1e-7), 0.0, 0.0};
        c->rays++;
        if (accel_occluded(c->scene, &sr) != OCCLUDED_CLEAR)
            return G_OK;
    }
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor light;
    GSurfPoint at;
    int rc = gcolor_scratch_uncleared(&light, c->scene->model, c->scratch), visible = 0; /* the scale writes it */
    if (rc == G_OK && (rc = gcolor_scale(&light, L, f)) == G_OK) {
        gsurfpoint_init(&at, c->scene->model, c->scratch);
        at.point = x;
        at.from = media_top(media);
        /* facing = in: the walk starts in this point's media, the shadow ray leaves from x itself */
        rc = light_transmit(c, &at, in, media, in, dist, &light, &visible);
    }
    if (rc == G_OK && visible)
        rc = gcolor_add(out, out, &light);
    gscratch_release(c->scratch, mark);
    return rc;
}

/* 1 for the lights equiangular sampling serves: a point of light in the medium. */
static int point_like(const Light *l)
{
    return l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_IES;
}

/* The balance heuristic's weight of free flight's event at way->t against equiangular sampling towards position. */
static double free_flight_weight(const Medium *vol, const MediumWay *way, GVec3 position)
{
    Equiangular e;
    if (!way || !equiangular_setup(&e, way->o, way->d, way->tmax, position))
        return 1.0;
    double pd = medium_distance_pdf(vol, way->t), pe = equiangular_pdf(&e, way->t);
    return pd + pe > 0.0 ? pd / (pd + pe) : 1.0;
}

/* Adds to out the sample of light l (not the glowing geometry) at x, divided by pick, the probability of its choice;
 * a point-like light's weighted against its equiangular sample on way (NULL: counted fully). */
static int light_sample(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, const MediumWay *way,
                        const Light *l, double pick, GColor *L, GColor *out)
{
    GVec3 in;
    double dist, pdf, f = 1.0;
    int rc = G_OK;
    switch (l->kind) {
    case LIGHT_POINT:
    case LIGHT_SPOT:
    case LIGHT_IES: {
        GVec3 to = gvec3_sub(l->position, x);
        dist = gvec3_length(to);
        if (!(dist > 0.0))
            break;
        in = gvec3_scale(to, 1.0 / dist);
        if (l->kind == LIGHT_SPOT)
            f = light_spot_factor(l, in);
        else if (l->kind == LIGHT_IES)
            f = ies_candela_dir(l->ies, gvec3_neg(in), l->direction, l->along, l->third);
        if (f > 0.0)
            f *= free_flight_weight(vol, way, l->position);
        if (f > 0.0)
            rc = add_sample(c, vol, media, x, d, in, dist, &l->color, f / (dist * dist * pick), 0, out);
        break;
    }
    case LIGHT_DIRECTIONAL:
        rc = add_sample(c, vol, media, x, d, gvec3_neg(l->direction), INFINITY, &l->color, 1.0 / pick, 0, out);
        break;
    case LIGHT_SPHERE:
    case LIGHT_RECT: {
        int got = path_light_sample(c, l, x, &in, &dist, &pdf, L);
        if (got < 0)
            rc = got;
        else if (got && pdf > 0.0)
            rc = add_sample(c, vol, media, x, d, in, dist, L,
                            mis_power(pdf * pick, phase_eval(vol->phase, d, in)) / (pdf * pick), 1, out);
        break;
    }
    default: /* a probe: phase sampling reaches it (path.c counts it fully after a medium vertex) */
        break;
    }
    return rc;
}

/* Adds to out the sample of the glowing geometry e at x from the numbers u0 (the primitive), u1, u2 (the point),
 * divided by pick, the probability of its choice. */
static int emissive_light_sample(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d,
                                 const EmissiveSet *e, double u0, double u1, double u2, double pick, GColor *L,
                                 GColor *out)
{
    GVec3 in, normal;
    double dist, pdf;
    int got = emissive_sample(c, e, x, u0, u1, u2, &in, &dist, &normal, &pdf, L);
    if (got < 0)
        return got;
    if (!got || !(pdf > 0.0))
        return G_OK;
    return add_sample(c, vol, media, x, d, in, emissive_shadow_reach(x, in, in, dist, normal), L,
                      mis_power(pdf * pick, phase_eval(vol->phase, d, in)) / (pdf * pick), 1, out);
}

int medium_direct_light(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, const MediumWay *way,
                        GColor *out)
{
    const Scene *s = c->scene;
    const LightPick *lp = c->pick;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor L;
    int rc = gcolor_scratch_uncleared(&L, s->model, c->scratch); /* written by each sample drawn */
    if (light_pick_nee_every(lp)) { /* few lights: one sample of each, then of the glowing geometry */
        for (int i = 0; i < s->nlights && rc == G_OK; i++)
            rc = light_sample(c, vol, media, x, d, way, s->lights[i], 1.0, &L, out);
        if (rc == G_OK && c->emissive) {
            double u0 = rng_next(&c->rng), u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
            rc = emissive_light_sample(c, vol, media, x, d, c->emissive, u0, u1, u2, 1.0, &L, out);
        }
    } else if (rc == G_OK) { /* one light chosen by power */
        double pick, u_rest = 0.5;
        int k = lp->n == 1 && lp->lights[0] ? light_pick_sample(lp, 0.5, &pick, NULL) /* no number for one light */
                                            : light_pick_sample(lp, rng_next(&c->rng), &pick, &u_rest);
        if (k >= 0 && pick > 0.0 && !lp->lights[k]) {
            double u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
            rc = emissive_light_sample(c, vol, media, x, d, lp->emissive, u_rest, u1, u2, pick, &L, out);
        } else if (k >= 0 && pick > 0.0) {
            rc = light_sample(c, vol, media, x, d, way, lp->lights[k], pick, &L, out);
        }
    }
    gscratch_release(c->scratch, mark);
    return rc;
}

int medium_equiangular_light(TraceCtx *c, const Medium *vol, const Media *media, const MediumWay *way, GColor *out)
{
    const Scene *s = c->scene;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor light = {0}, weight = {0};
    int rc = G_OK;
    for (int i = 0; i < s->nlights && rc == G_OK; i++) {
        const Light *l = s->lights[i];
        Equiangular e;
        if (!point_like(l) || !equiangular_setup(&e, way->o, way->d, way->tmax, l->position))
            continue;
        double pe, t = equiangular_sample(&e, rng_next(&c->rng), &pe);
        if (!(t > 0.0 && t < way->tmax && pe > 0.0))
            continue;
        GVec3 x = gvec3_madd(way->o, way->d, t), to = gvec3_sub(l->position, x);
        double dist = gvec3_length(to), f = 1.0;
        if (!(dist > 0.0))
            continue;
        GVec3 in = gvec3_scale(to, 1.0 / dist);
        if (l->kind == LIGHT_SPOT)
            f = light_spot_factor(l, in);
        else if (l->kind == LIGHT_IES)
            f = ies_candela_dir(l->ies, gvec3_neg(in), l->direction, l->along, l->third);
        if (!(f > 0.0))
            continue;
        if (!light.v) { /* the first sample: its temporaries */
            if ((rc = gcolor_scratch(&light, s->model, c->scratch)) < 0 ||
                (rc = gcolor_scratch_uncleared(&weight, s->model, c->scratch)) < 0)
                break;
        } else
            gcolor_black(&light);
        /* the light's sample at x, then times exp(-sigma_t t) sigma_s / (pe + pd) */
        if ((rc = add_sample(c, vol, media, x, way->d, in, dist, &l->color, f / (dist * dist), 0, &light)) < 0 ||
            (rc = gcolor_exp(&weight, &vol->sigma_t, -t)) < 0 ||
            (rc = gcolor_mul(&weight, &weight, &vol->sigma_s)) < 0 ||
            (rc = gcolor_mul(&light, &light, &weight)) < 0)
            break;
        rc = gcolor_add_scaled(out, &light, 1.0 / (pe + medium_distance_pdf(vol, t)));
    }
    gscratch_release(c->scratch, mark);
    return rc;
}
