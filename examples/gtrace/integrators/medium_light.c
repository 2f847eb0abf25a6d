/* medium_light.c - next-event estimation at a scattering event in a medium (the path tracer's medium vertices): each
 * light's sample is weighted by the phase function instead of a material's reflection and carried to the point
 * by light_transmit (lights.c), which applies the media and the absorbing materials along the shadow ray. Sphere and
 * rectangle lights and glowing geometry, which the phase-sampled ray also reaches, follow the path tracer's rule:
 * any surface blocks their shadow ray, and the sample is weighted by the power heuristic against the phase
 * function's density (path.c weighs the light that phase sampling meets against theirs). */
#include "medium_light.h"
#include "path.h"
#include "lights/emissive.h"
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

int medium_direct_light(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, const MediumWay *way,
                        GColor *out)
{
    const Scene *s = c->scene;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor L;
    int rc = gcolor_scratch_uncleared(&L, s->model, c->scratch); /* written by each sample drawn */
    for (int i = 0; i < s->nlights && rc == G_OK; i++) {
        const Light *l = s->lights[i];
        GVec3 in;
        double dist, pdf, f = 1.0;
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
                rc = add_sample(c, vol, media, x, d, in, dist, &l->color, f / (dist * dist), 0, out);
            break;
        }
        case LIGHT_DIRECTIONAL:
            rc = add_sample(c, vol, media, x, d, gvec3_neg(l->direction), INFINITY, &l->color, 1.0, 0, out);
            break;
        case LIGHT_SPHERE:
        case LIGHT_RECT: {
            int got = path_light_sample(c, l, x, &in, &dist, &pdf, &L);
            if (got < 0)
                rc = got;
            else if (got && pdf > 0.0)
                rc = add_sample(c, vol, media, x, d, in, dist, &L,
                                mis_power(pdf, phase_eval(vol->phase, d, in)) / pdf, 1, out);
            break;
        }
        default: /* a probe: phase sampling reaches it (path.c counts it fully after a medium vertex) */
            break;
        }
    }
    if (rc == G_OK && c->emissive) {
        GVec3 in;
        double dist, pdf, u0 = rng_next(&c->rng), u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
        int got = emissive_sample(c, c->emissive, x, u0, u1, u2, &in, &dist, &pdf, &L);
        if (got < 0)
            rc = got;
        else if (got && pdf > 0.0)
            rc = add_sample(c, vol, media, x, d, in, dist * EMISSIVE_SHADOW_SHORTEN, &L,
                            mis_power(pdf, phase_eval(vol->phase, d, in)) / pdf, 1, out);
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
