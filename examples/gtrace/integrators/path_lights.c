/* path_lights.c - the path tracer's next-event estimation at a surface vertex (path.c's header describes the
 * strategy): one sample of every light source when the scene's table holds few (path_direct_light_every), else one
 * light source chosen by power, a delta light chosen again among the delta lights by its unshadowed light at the
 * vertex (delta_choice); sphere and rectangle lights, a reference probe and the glowing geometry weighted by the power
 * heuristic against the material's density. */
#include "path_lights.h"
#include "lights/area_light.h"
#include "lights/emissive.h"
#include "lights/light_pick.h"
#include "lights/probe_env.h"
#include "scene/ies.h"

#include <math.h>

/* Candidates a vertex weighs when NEE has chosen a delta light among more (see delta_choice). */
#define NEE_DELTA_CANDIDATES 8

/* The guide to delta light entry k's light at x (facing: the surface's side; opaque: its back gets none) that
 * delta_choice draws by: the brightness of its colour times its intensity towards x over the squared distance (a
 * directional light's irradiance) times the cosine on an opaque surface; no shadows. 0 exactly where light_shade
 * adds nothing for want of light or by the cosine. */
static double delta_guide(const LightPick *lp, int k, GVec3 x, GVec3 facing, int opaque)
{
    const Light *l = lp->lights[k];
    GVec3 in;
    double g = lp->bright[k];
    if (l->kind == LIGHT_DIRECTIONAL) {
        in = gvec3_neg(l->direction);
    } else {
        GVec3 to = gvec3_sub(l->position, x);
        double d2 = gvec3_dot(to, to);
        if (!(d2 > 0.0))
            return 0.0;
        in = gvec3_scale(to, 1.0 / sqrt(d2));
        g /= d2;
        if (l->kind == LIGHT_SPOT)
            g *= light_spot_factor(l, in);
        else if (l->kind == LIGHT_IES)
            g *= ies_candela_dir(l->ies, gvec3_neg(in), l->direction, l->along, l->third);
    }
    if (opaque)
        g *= fmax(0.0, gvec3_dot(in, facing));
    return g > 0.0 && isfinite(g) ? g : 0.0;
}

/* Once the table has chosen a delta light (entry k0, with the delta lights' share lp->delta_prob), the one to shade:
 * with at most NEE_DELTA_CANDIDATES delta lights, one of them all drawn by its delta_guide at x; with more, resampled
 * importance sampling (Talbot, Cline and Egbert 2005): k0 and NEE_DELTA_CANDIDATES - 1 more drawn by power from the
 * delta lights' table (the generator's numbers), one of them kept by guide over power. u makes the last choice. The
 * entry kept, and into *pick the factor its light is divided by (the delta lights' share times the kept one's
 * density, or for the resampled choice its guide times the count over the sum of the candidates' guide over power);
 * -1 when every guide is 0 (no delta light reaches x). */
static int delta_choice(PathCtx *p, const LightPick *lp, int k0, GVec3 x, GVec3 facing, int opaque, double u,
                        double *pick)
{
    int cand[NEE_DELTA_CANDIDATES], m = lp->ndelta <= NEE_DELTA_CANDIDATES ? lp->ndelta : NEE_DELTA_CANDIDATES;
    int every = lp->ndelta <= NEE_DELTA_CANDIDATES;
    double w[NEE_DELTA_CANDIDATES], g[NEE_DELTA_CANDIDATES], sum = 0.0;
    for (int i = 0; i < m; i++) {
        cand[i] = every ? lp->delta[i] : i == 0 ? k0 : light_pick_delta(lp, path_uniform(p));
        g[i] = delta_guide(lp, cand[i], x, facing, opaque);
        w[i] = every ? g[i] : g[i] * lp->delta_prob / lp->prob[cand[i]];
        sum += w[i];
    }
    if (!(sum > 0.0) || !isfinite(sum))
        return -1;
    double t = u * sum;
    int i = 0;
    while (i < m - 1 && (t >= w[i] || !(w[i] > 0.0))) {
        t -= w[i];
        i++;
    }
    if (!(w[i] > 0.0)) /* rounding ran past the last candidate that counts */
        while (i > 0 && !(w[i] > 0.0))
            i--;
    *pick = every ? lp->delta_prob * g[i] / sum : lp->delta_prob * g[i] * m / sum;
    return cand[i];
}

int path_direct_light_every(PathCtx *p, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 to_viewer,
                            int opaque, const GColor *ri, int depth, GColor *out, int *unset)
{
    int slots_free = 1;
    TraceCtx *c = p->c;
    const Scene *s = c->scene;
    const GMaterial *m = sp->material;
    GScratchMark mark = gscratch_mark(c->scratch);
    LightTmp lt;
    GColor L;
    int rc = G_OK;
    CHECK(light_temps(c, &lt));
    if (c->emissive) /* the glowing geometry's radiance (an area light's is its colour, read where it is) */
        CHECK(gcolor_scratch(&L, s->model, c->scratch));
    lt.unset = *unset;
    light_gather(sp, &lt); /* a Lambertian material: asked once for all samples, MIS weights in their light */
    for (int i = 0; i < s->nlights; i++) {
        const Light *l = s->lights[i];
        lt.blocked = 0;
        if (l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_DIRECTIONAL || l->kind == LIGHT_IES) {
            CHECK(light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, out));
            continue;
        }
        lt.blocked = 1; /* material sampling reaches these lights: light through glass is a caustic */
        if (l->kind != LIGHT_SPHERE && l->kind != LIGHT_RECT && l->kind != LIGHT_PROBE)
            continue;
        double u[2];
        if (slots_free) {
            u[0] = path_vertex_uniform(p, depth, SLOT_LIGHT_U);
            u[1] = path_vertex_uniform(p, depth, SLOT_LIGHT_V);
            slots_free = 0;
        } else {
            u[0] = path_uniform(p);
            u[1] = path_uniform(p);
        }
        if (l->kind == LIGHT_PROBE) { /* the reference's estimator with one direction (a basis: not used) */
            CHECK(probe_light_nee(c, l, sp, facing, media, to_viewer, opaque, 1, u, l == p->env_light ? ri : NULL,
                                  1.0, &lt, out));
            continue;
        }
        GVec3 in;
        double dist, pdf_l;
        int got; /* the radiance is the light's colour, read where it is */
        CHECK(got = path_light_direction_at(l, sp->point, u[0], u[1], &in, &dist, &pdf_l));
        if (!got || (opaque && gvec3_dot(in, facing) <= 0.0))
            continue;
        double w = mis_power(pdf_l, gmaterial_pdf(m, sp, in, to_viewer, ri));
        if (w > 0.0)
            CHECK(sample_light(c, sp, facing, media, in, dist, &l->color, w / pdf_l, to_viewer, &lt, out));
    }
    if (c->emissive) { /* glowing geometry: one point of one primitive, chosen by power */
        GVec3 in, normal;
        double dist, pdf_l, u0, u1, u2;
        int got;
        if (slots_free) {
            u0 = path_vertex_uniform(p, depth, SLOT_LIGHT_PICK);
            u1 = path_vertex_uniform(p, depth, SLOT_LIGHT_U);
            u2 = path_vertex_uniform(p, depth, SLOT_LIGHT_V);
        } else {
            u0 = path_uniform(p);
            u1 = path_uniform(p);
            u2 = path_uniform(p);
        }
        lt.blocked = 1;
        CHECK(got = emissive_sample(c, c->emissive, sp->point, u0, u1, u2, &in, &dist, &normal, &pdf_l, &L));
        if (got && !(opaque && gvec3_dot(in, facing) <= 0.0)) {
            double w = mis_power(pdf_l, gmaterial_pdf(m, sp, in, to_viewer, ri));
            if (w > 0.0)
                CHECK(sample_light(c, sp, facing, media, in, emissive_shadow_reach(sp->point, facing, in, dist, normal),
                                   &L, w / pdf_l, to_viewer, &lt, out));
        }
    }
    CHECK(light_gather_finish(sp, &lt, out));
    *unset = lt.unset;
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

int path_direct_light(PathCtx *p, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 to_viewer, int opaque,
                      const GColor *ri, int depth, GColor *out, int *unset)
{
    TraceCtx *c = p->c;
    const LightPick *lp = c->pick;
    const Scene *s = c->scene;
    const GMaterial *m = sp->material;
    double pick, u_rest = 0.5;
    double u = lp->n == 1 && lp->lights[0] ? 0.5 : path_vertex_uniform(p, depth, SLOT_LIGHT_PICK);
    int k = light_pick_sample(lp, u, &pick, &u_rest);
    if (k >= 0 && lp->ndelta > 1 && light_pick_is_delta(lp, k)) /* which delta light, by its light here */
        k = delta_choice(p, lp, k, sp->point, facing, opaque, path_vertex_uniform(p, depth, SLOT_DELTA_PICK),
                         &pick);
    if (k < 0 || !(pick > 0.0))
        return G_OK;
    const Light *l = lp->lights[k];
    GScratchMark mark = gscratch_mark(c->scratch);
    LightTmp lt;
    GColor L, acc, *sum = out; /* the chosen light's estimate, before the division by pick (out itself when 1) */
    int rc = G_OK;
    CHECK(light_temps(c, &lt));
    if (!l) /* the glowing geometry's radiance (an area light's is its colour, read where it is) */
        CHECK(gcolor_scratch(&L, s->model, c->scratch));
    if (pick != 1.0) {
        CHECK(gcolor_scratch(&acc, s->model, c->scratch));
        sum = &acc;
        if (*unset) { /* out is added to below */
            gcolor_black(out);
            *unset = 0;
        }
    }
    lt.unset = *unset;
    light_gather(sp, &lt); /* a Lambertian material: asked once, the MIS weight in the light */
    if (l && (l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_DIRECTIONAL ||
              l->kind == LIGHT_IES)) {
        CHECK(light_shade(c, l, sp, facing, media, to_viewer, opaque, &lt, sum));
    } else if (l && l->kind == LIGHT_PROBE) { /* the reference's estimator with one direction */
        lt.blocked = 1; /* material sampling reaches it: light through glass is a caustic */
        double u[2] = {path_vertex_uniform(p, depth, SLOT_LIGHT_U), path_vertex_uniform(p, depth, SLOT_LIGHT_V)};
        CHECK(probe_light_nee(c, l, sp, facing, media, to_viewer, opaque, 1, u, l == p->env_light ? ri : NULL, pick,
                              &lt, sum));
    } else { /* a sphere or rectangle light, or one point of one glowing primitive */
        GVec3 in, normal;
        double dist, pdf_l, u1 = path_vertex_uniform(p, depth, SLOT_LIGHT_U);
        double u2 = path_vertex_uniform(p, depth, SLOT_LIGHT_V);
        int got;
        lt.blocked = 1;
        if (l) /* the radiance is the light's colour, read where it is */
            CHECK(got = path_light_direction_at(l, sp->point, u1, u2, &in, &dist, &pdf_l));
        else
            CHECK(got = emissive_sample(c, lp->emissive, sp->point, u_rest, u1, u2, &in, &dist, &normal, &pdf_l, &L));
        if (got && !(opaque && gvec3_dot(in, facing) <= 0.0)) {
            double w = mis_power(pdf_l * pick, gmaterial_pdf(m, sp, in, to_viewer, ri));
            if (!l) /* the shadow ray ends before the glowing surface (a sphere or rectangle light is no surface) */
                dist = emissive_shadow_reach(sp->point, facing, in, dist, normal);
            if (w > 0.0)
                CHECK(sample_light(c, sp, facing, media, in, dist, l ? &l->color : &L, w / pdf_l, to_viewer, &lt,
                                   sum));
        }
    }
    CHECK(light_gather_finish(sp, &lt, sum));
    if (sum == out)
        *unset = lt.unset;
    if (sum != out)
        CHECK(gcolor_add_scaled(out, sum, 1.0 / pick));
done:
    gscratch_release(c->scratch, mark);
    return rc;
}
#undef CHECK
