/* path.c - unidirectional path tracing on the generic interfaces (`gtrace --integrator path`).
 *
 * Radiance is computed recursively, one path per camera sample. At every surface: the material's emission;
 * next-event estimation (NEE) to every light (one when many) unless every lobe of the material is a delta one; then one
 * direction drawn by gmaterial_sample, the radiance arriving along it traced recursively, divided by the
 * sample's pdf (and the Russian-roulette probability), and passed on through gmaterial_reflection (or
 * gmaterial_refraction for a GSAMPLE_TRANSMIT sample). The sample's weight colour is never multiplied in: the
 * material itself transforms the actual incoming light, so with re-radiation matrices a fluorescent surface
 * re-radiates the light that really arrives, at every bounce. The weight only steers Russian roulette: after
 * PATH_RR_START bounces a path survives with probability min(1, sqrt(t)), t the product of the weights' largest bands
 * (roulette_factor, roulette.h), which bounds every band of the path's throughput. Each band's throughput over the
 * survival probability then stays at most sqrt(t) <= 1: no survivor carries more light in a band than it would
 * without the roulette. By the brightness instead (the red wall of a Cornell box has brightness 0.18 and red
 * 0.63), the survivors off a saturated colour carried red weights above 1, the red speckles of the box's shadows:
 * measured on the box at 64 spp, 0.69 of the variance over the image for 1.09 of the CPU time
 * (bench/cycles_regions.py). The square root keeps more paths alive than t itself.
 *
 * Lights. When the scene's light table (lights/light_pick.h: the lights that send light and the glowing geometry as one
 * entry) holds at most LIGHT_PICK_EVERY_MAX entries, NEE takes one sample of every light source at each vertex
 * (path_direct_light_every; `make bench-lights` measured it ahead of one chosen light in time to equal RMSE up to that
 * count). With more, NEE takes one light source a vertex, chosen by power from the table (an alias table: constant time
 * whatever their number), and divides its estimate by the probability of the choice; the density a light's MIS weight
 * uses, on either side, is its sampling density times that probability (1 when every light is sampled). A delta light,
 * which material sampling never meets, is then chosen again among the delta lights by its unshadowed light at the
 * vertex (delta_choice: among all of them when they are few, else by resampled importance sampling of a few candidates
 * drawn by power): one shadow ray still, the choice weighted by what each light gives there. Point, spot, directional
 * and IES lights, including the directional lights a probe technique (mediancut, adaptive, kmeans, irradiance,
 * variance) makes, are delta lights: NEE only, through lights.c's light_shade (the same shadow rule as the Whitted
 * tracer: transmission through non-opaque surfaces along the straight line). Sphere and rectangle lights and a `light
 * probe` of technique reference (the environment, importance sampled by probe_sample.c's probe_light_nee, the Whitted
 * tracer's reference estimator with one direction, drawn from the vertex's light dimensions and from the probe's
 * compensated distribution, ProbeEnv.nee_dist: only the brightness above the probe's mean, the smooth rest left to
 * material sampling; on bench/scenes/cycles_probe.scene, a sky with a sun, RMSE 0.0031 at 64 spp against a 4096-spp
 * reference where the plain distribution gave 0.0097) can also be reached by material sampling, so both estimates are
 * combined by multiple importance sampling with the power heuristic (a sphere light is sampled uniformly in the solid
 * angle it subtends, a rectangle light uniformly by area; area_light_hit gives the same density. Sampling rectangles by
 * solid angle, as spherical rectangles, was measured on the Cornell box: 35% more time for 2% less RMSE); their shadow
 * rays are blocked by any surface (light through glass reaches them by material sampling, a caustic, so counting the
 * straight transmission too would count it twice). Material sampling sees sphere and rectangle lights (one-sided) when
 * they are nearer than the surface hit; a path after a delta bounce counts them fully. One light sample a vertex: the
 * lights' `samples` apply to the Whitted tracer; a reference probe's `shadows off` does not apply. At a Lambertian
 * material (GMAT_LAMBERTIAN) the samples' light, each with its MIS weight in it, is gathered and reflected once
 * (lights.c's light_gather), as in the Whitted tracer.
 *
 * The environment. Camera rays and rays after a delta bounce see the background (the background colour, or
 * the background probe interpolated bilinearly). After a non-delta bounce the background probe is a light:
 * its pixels (piecewise constant, as its distribution), MIS-weighted against NEE for technique reference;
 * none of it when a technique's directional lights already carry its light (as in the Whitted tracer, where
 * the probe's light reaches surfaces only through them); a basis technique (sh, ...) is not used, the probe
 * itself is reached by material sampling. The ambient light (`light ambient`, Scene.ambient) is a uniform
 * environment of that radiance behind the background: rays leaving the scene on a path that has had a
 * non-delta bounce see it, camera rays and the mirror images they see do not. A convex Lambert surface of
 * albedo a so shows a * ambient, as in the Whitted tracer (material.ambient of Lambert), but occluded and
 * interreflected.
 *
 * Glowing geometry (lights/emissive.h): the emissive primitives are one more entry of the table, with their own alias
 * table by power, MIS-weighted; a material-sampled ray that meets one weighs its emission against the set's
 * density for that direction (path_radiance hands shade_path the weight), other emission counts fully.
 *
 * Dispersion (hero band): when the relative index at a non-opaque surface differs between the wavelength
 * groups (bands.h) and the path does not carry a group yet, one group is chosen uniformly; the material is
 * sampled with that group's index, and a transmitted sample keeps only the group's light (its mask) times
 * the number of groups, and carries the group on (later interfaces refract with its index, as whitted.c).
 *
 * Participating media (media/medium.h): where the stack of media puts the ray in a medium, medium_segment draws a
 * free-flight distance (one band chosen, all bands' densities averaged: MIS over the bands) before what the ray meets;
 * a scattering event there is a medium vertex (medium_vertex: NEE through medium_light.c's medium_direct_light, one
 * direction drawn from the phase function, whose density is the MIS weight's for the lights that ray meets), else
 * the ray goes on to arrive() and the sample's weight (transmittance over probability) multiplies what comes back.
 * In a homogeneous medium that scatters, point, spot and IES lights are also sampled along the ray by equiangular
 * sampling (medium_light.c's medium_equiangular_light, one distance per light; TraceCtx.equiangular), and the light
 * the free-flight vertex gathers from them is weighted against it (the balance heuristic over the two strategies).
 * The shadow rays of every vertex are attenuated by the media they cross (TraceCtx.volumes).
 *
 * Random numbers: with the default sampler (trace/sampler.h, SAMPLER_SOBOL) the numbers that decide most of the
 * variance, each vertex's light sample (the choice of the light, the point on a sphere or rectangle light or on the
 * glowing geometry, whose primitive takes what is left of the choice's number, or the direction drawn from a reference
 * probe), its material sample, its wavelength group and its roulette, are dimensions of the camera sample's point in
 * the pixel's shuffled, Owen-scrambled Sobol sequence (two groups of four a vertex, after the camera's group: see SLOT_
 * in path_lights.h). The probe's direction from the sequence: on bench/scenes/cycles_probe.scene at 64 spp, RMSE 0.0097
 * against a 4096-spp reference where the generator's numbers gave 0.0324. The others (media, the lights after the first
 * when every light is sampled) and, with SAMPLER_INDEPENDENT, all of them come from the thread's PCG32 generator
 * (TraceCtx.rng, which lights.c and probe_sample.c draw from too), re-seeded for each path from the pixel's index and
 * the sample's index and restored afterwards. Either way a number depends on the pixel, the sample and its use only, so
 * the image does not depend on the thread count, crops or tile order. Colours only through gcolor_*, materials only
 * through gmaterial_*; temporaries live on the thread's scratch arena and are released at every level: no allocation
 * per ray. */
#include "path.h"
#include "path_lights.h"
#include "bands.h"
#include "scene/accel.h"
#include "lights/emissive.h"
#include "lights/light_pick.h"
#include "lights/lighting.h"
#include "lights/probe_env.h"
#include "medium_light.h"
#include "roulette.h"
#include "media/medium.h"
#include "trace/sampler.h"
#include "camera/rng.h"

#include <math.h>

static int path_radiance(PathCtx *p, const Ray *r, const Media *media, int depth, double beta, int prev_delta,
                    double prev_pdf, GColor *out, const GColor **res);
static int arrive(PathCtx *p, const Ray *r, const Media *media, int depth, double beta, int first, double prev_pdf,
                  int from_medium, const Hit *hp, const Light *lh, double t_l, double pdf_l, GColor *out,
                  const GColor **res);

/* The light leaving sp towards the viewer of r: emission (times emit_weight, its MIS weight against the emissive
 * set's NEE), NEE, and one sampled bounce. */
static int shade_path(PathCtx *p, const Ray *r, GSurfPoint *sp, GVec3 facing, const Media *media, int depth,
                      double beta, double emit_weight, GColor *out)
{
    TraceCtx *c = p->c;
    const Scene *s = c->scene;
    const GMaterial *m = sp->material;
    GVec3 to_viewer = gvec3_neg(r->d);
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor room, rg, tmp, weight, illum, inside, *res = out;
    const GColor *ri = NULL; /* read only: it may be a colour the context keeps (trace.h) */
    int rc = G_OK, opaque, delta, valid;
    CHECK(trace_relative_index(c, sp, &room, &ri));
    /* in a medium that absorbs the light is gathered apart (written in full: not cleared), and its absorption written
     * to out; a clear medium (GMAT_CLEAR, vacuum), whose gmaterial_absorption writes the light itself without calling
     * the class, is skipped: the light is gathered into out */
    if (!media_clear(sp->from)) {
        CHECK(gcolor_scratch_uncleared(&inside, s->model, c->scratch));
        res = &inside;
    }
    /* res stands for black while `unset` (a material that emits nothing): the first light is written to it, not added
     * to a black written first, and black is written at the end only when no light came */
    int unset = !gmaterial_emits(m);
    if (!unset) {
        CHECK(gmaterial_emission(m, sp, to_viewer, res));
        if (emit_weight != 1.0)
            CHECK(gcolor_scale(res, res, emit_weight));
    }
    opaque = gmaterial_opaque(m, sp);
    CHECK(delta = gmaterial_is_delta(m, sp));

    /* dispersion: the wavelength group this vertex refracts with (hero band) */
    const Bands *b = c->bands;
    const GColor *ri_use = ri;
    int band = c->band, pick = -1;
    if (!opaque && b && b->n > 1) {
        if (band < 0 && bands_disperse(b, ri)) {
            pick = (int)(path_vertex_uniform(p, depth, SLOT_BAND) * b->n);
            band = pick < b->n ? pick : b->n - 1;
            pick = band;
        }
        if (band >= 0) { /* written in full by the fill: not cleared */
            CHECK(gcolor_scratch_uncleared(&rg, s->model, c->scratch));
            CHECK(gcolor_fill(&rg, bands_value(b, ri, band)));
            ri_use = &rg;
        }
    }

    if (!delta && light_pick_nee_every(c->pick) && (s->nlights > 0 || c->emissive))
        CHECK(path_direct_light_every(p, sp, facing, media, to_viewer, opaque, ri_use, depth, res, &unset));
    else if (!delta && c->pick && c->pick->n > 0)
        CHECK(path_direct_light(p, sp, facing, media, to_viewer, opaque, ri_use, depth, res, &unset));

    if (depth < c->max_depth) {
        /* written in full before they are read (the weight by a sample drawn, the bounce's light by path_radiance, the
         * light passed on as an operation's out): not cleared */
        CHECK(gcolor_scratch_uncleared(&weight, s->model, c->scratch));
        CHECK(gcolor_scratch_uncleared(&illum, s->model, c->scratch));
        GMaterialSample smp;
        double u1 = path_vertex_uniform(p, depth, SLOT_BSDF_U), u2 = path_vertex_uniform(p, depth, SLOT_BSDF_V);
        CHECK(valid = gmaterial_sample(m, sp, to_viewer, ri_use, u1, u2, &smp, &weight));
        if (!valid || !(smp.pdf > 0.0)) /* no sample: the weight is not read */
            goto absorb;
        double nb = beta * roulette_factor(&weight), q = 1.0;
        if (!(nb > 0.0) || !isfinite(nb))
            goto absorb;
        if (depth >= PATH_RR_START) { /* Russian roulette on the path's throughput */
            q = roulette_survival(nb);
            if (path_vertex_uniform(p, depth, SLOT_ROULETTE) >= q)
                goto absorb;
            nb /= q;
        }
        int transmit = (smp.flags & GSAMPLE_TRANSMIT) != 0;
        Media next;
        if (transmit)
            media_cross(media, m, sp->entering, &next);
        else
            media_copy(&next, media);
        double width = r->cone_width + r->cone_spread * sp->t;
        Ray ray = {offset_origin(sp->point, facing, smp.in), smp.in, 0.0, INFINITY, width, r->cone_spread};
        int saved = c->band, scattered = p->scattered, is_delta = (smp.flags & GSAMPLE_DELTA) != 0;
        if (transmit && pick >= 0)
            c->band = pick;
        p->scattered |= !is_delta;
        const GColor *lit; /* the bounce's light: illum, or the background where it is */
        rc = path_radiance(p, &ray, &next, depth + 1, nb, is_delta, smp.pdf, &illum, &lit);
        c->band = saved;
        p->scattered = scattered;
        CHECK(rc);
        /* the light passed on, into res directly when it holds nothing yet (black plus it is it) */
        GColor *dst = &tmp;
        if (unset && !(transmit && pick >= 0))
            dst = res;
        else
            CHECK(gcolor_scratch_uncleared(&tmp, s->model, c->scratch));
        if (gmaterial_diagonal(m)) {
            /* what it passes on of white light over the density (the sample's weight), times the light: no second
             * evaluation, and each ideal lobe counts with its own probability where a blend's children share an
             * ideal ray (there, reflection() gives their sum, which one child's probability would overweigh) */
            CHECK(gcolor_mul_scaled(dst, &weight, lit, 1.0 / q));
        } else { /* re-radiation: the light itself through the material */
            CHECK(gcolor_scale(&illum, lit, 1.0 / (smp.pdf * q)));
            if (transmit)
                CHECK(gmaterial_refraction(m, sp, smp.in, &illum, ri_use, to_viewer, dst));
            else
                CHECK(gmaterial_reflection(m, sp, smp.in, &illum, to_viewer, dst));
        }
        if (transmit && pick >= 0) { /* one group of n chosen: its light, n times */
            CHECK(gcolor_mul(&tmp, &b->mask[pick], &tmp));
            CHECK(gcolor_scale(&tmp, &tmp, (double)b->n));
        }
        if (dst == res)
            unset = 0;
        else if (unset) {
            unset = 0;
            gcolor_black(res);
            CHECK(gcolor_add(res, res, &tmp));
        } else
            CHECK(gcolor_add(res, res, &tmp));
    }
absorb:
    if (unset)
        gcolor_black(res);
    /* absorption until the light reaches the viewer */
    if (res != out)
        CHECK(gmaterial_absorption(sp->from, sp, res, sp->t, out));
done:
    gscratch_release(c->scratch, mark);
    if (rc < 0 && c->status == G_OK) {
        c->status = rc;
        c->culprit = gmaterial_name(m);
    }
    return rc;
}

/* Radiance arriving along r, which leaves the scene, into *res: out, or the background colour itself where it is all
 * (no probe, no ambient light seen); first: a camera ray or one after a delta bounce, else drawn by material sampling
 * with density prev_pdf. See the top of the file: the environment. */
static int escaped(PathCtx *p, const Ray *r, int first, double prev_pdf, int from_medium, GColor *out,
                   const GColor **res)
{
    const Scene *s = p->c->scene;
    const ProbeEnv *env = s->env;
    int rc = G_OK;
    int ambient = p->scattered && s->have_ambient;
    *res = out;
    if (!env && !ambient) {
        *res = &s->background;
        return G_OK;
    }
    if (!env) /* the background and the ambient light behind it, added where they are */
        return gcolor_add(out, &s->background, &s->ambient);
    if (first)
        CHECK(probe_background(env, r->d, out));
    else if (p->env_in_lights)
        CHECK(gcolor_fill(out, 0.0));
    else {
        CHECK(probe_pixel_radiance(env, r->d, out));
        if (p->env_light && !from_medium) {
            double pdf_nee = p->env_pick * probe_dist_pdf(&env->nee_dist, env->probe, probe_from_world(env, r->d));
            CHECK(gcolor_scale(out, out, mis_power(prev_pdf, pdf_nee)));
        }
    }
    if (ambient)
        CHECK(gcolor_add(out, out, &s->ambient));
done:
    return rc;
}

/* The light scattered towards -r->d at x in medium vol: NEE (medium_light.c) and one direction drawn from
 * the phase function, traced on (its density is prev_pdf there, for the MIS weight of a light it reaches). */
static int medium_vertex(PathCtx *p, const Ray *r, const Media *media, const Medium *vol, GVec3 x, int depth,
                         double beta, const MediumWay *way, GColor *out)
{
    TraceCtx *c = p->c;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor illum;
    int rc = G_OK;
    CHECK(gcolor_fill(out, 0.0));
    if (light_pick_nee_every(c->pick) ? c->scene->nlights > 0 || c->emissive : c->pick && c->pick->n > 0)
        CHECK(medium_direct_light(c, vol, media, x, r->d, way, out));
    if (depth >= c->max_depth)
        goto done;
    double q = 1.0;
    if (depth >= PATH_RR_START) {
        q = roulette_survival(beta);
        if (!(q > 0.0) || path_uniform(p) >= q)
            goto done;
    }
    GVec3 in;
    double u1 = path_uniform(p), u2 = path_uniform(p), pdf = phase_sample(vol->phase, r->d, u1, u2, &in);
    if (!(pdf > 0.0))
        goto done;
    CHECK(gcolor_scratch_uncleared(&illum, c->scene->model, c->scratch)); /* path_radiance writes it */
    Ray ray = {x, in, 0.0, INFINITY, r->cone_width, r->cone_spread};
    int scattered = p->scattered;
    p->scattered = 1;
    p->from_medium = 1;
    const GColor *lit;
    rc = path_radiance(p, &ray, media, depth + 1, beta / q, 0, pdf, &illum, &lit);
    p->scattered = scattered;
    p->from_medium = 0;
    CHECK(rc);
    CHECK(gcolor_add_scaled(out, lit, phase_eval(vol->phase, r->d, in) / (pdf * q)));
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

/* Radiance along r through the medium vol up to t_l (what it then meets: see arrive): free-flight sampling
 * (medium_sample_distance) either scatters in the medium or passes on to arrive, times the sample's weight. */
static int medium_segment(PathCtx *p, const Ray *r, const Media *media, const Medium *vol, int depth, double beta,
                          int first, double prev_pdf, int from_medium, const Hit *hp, const Light *lh, double t_l,
                          double pdf_l, GColor *out)
{
    TraceCtx *c = p->c;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor w;
    double t = t_l;
    int rc = G_OK, ev = 0;
    CHECK(gcolor_scratch_uncleared(&w, c->scene->model, c->scratch)); /* written in full by the sampling */
    if (vol->grid) /* delta tracking through the grid (media/medium_grid.c) */
        CHECK(ev = medium_grid_flight(vol, r->o, r->d, t_l, &c->rng, &t, &w, c->scratch));
    else
        CHECK(ev = medium_sample_distance(vol, t_l, path_uniform(p), path_uniform(p), &t, &w));
    double nb = beta * roulette_factor(&w);
    /* point, spot and IES lights: equiangular samples too, MIS-weighted against free flight's (homogeneous media) */
    MediumWay way = {r->o, r->d, t_l, t};
    int equiangular = c->equiangular && !vol->grid && vol->scatters && p->point_lights;
    const GColor *lit = out;
    if (ev)
        CHECK(medium_vertex(p, r, media, vol, gvec3_madd(r->o, r->d, t), depth, nb, equiangular ? &way : NULL, out));
    else if (!gcolor_is_black(&w))
        CHECK(arrive(p, r, media, depth, nb, first, prev_pdf, from_medium, hp, lh, t_l, pdf_l, out, &lit));
    else
        CHECK(gcolor_fill(out, 0.0));
    CHECK(gcolor_mul(out, lit, &w));
    if (equiangular)
        CHECK(medium_equiangular_light(c, vol, media, &way, out));
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

/* Radiance arriving at r's origin along r into *res: out, or the background colour where it is (escaped);
 * prev_delta and prev_pdf describe how r was drawn (for the MIS weight of a light it reaches). */
static int path_radiance(PathCtx *p, const Ray *r, const Media *media, int depth, double beta, int prev_delta,
                    double prev_pdf, GColor *out, const GColor **res)
{
    *res = out;
    TraceCtx *c = p->c;
    const Scene *s = c->scene;
    Hit h;
    c->rays++;
    int hit = accel_intersect(s, r, &h);
    /* the nearest area light in front of the surface, and the density with which NEE draws the direction to it */
    const LightPick *lp = c->pick;
    const Light *lh = NULL;
    double t_l = hit ? h.t : INFINITY, pdf_l = 0.0;
    int nl = lp ? lp->narea : s->nlights;
    for (int k = 0; k < nl; k++) {
        int i = lp ? lp->area[k] : k;
        double pl = 0.0, t = area_light_hit(s->lights[i], r, t_l, &pl);
        if (t < t_l) {
            t_l = t;
            pdf_l = pl * light_pick_nee_pmf(lp, i);
            lh = s->lights[i];
        }
    }
    int first = depth == 0 || prev_delta, from_medium = p->from_medium;
    p->from_medium = 0;
    const Medium *vol = medium_current(s, media);
    if (vol) /* a participating medium along the ray: a scattering event before t_l, or the rest attenuated */
        return medium_segment(p, r, media, vol, depth, beta, first, prev_pdf, from_medium, hit ? &h : NULL, lh, t_l,
                              pdf_l, out);
    return arrive(p, r, media, depth, beta, first, prev_pdf, from_medium, hit ? &h : NULL, lh, t_l, pdf_l, out, res);
}

/* The light arriving along r from what it meets at t_l, into *res (out, or what escaped gives): the area light lh
 * (density pdf_l for NEE), else the surface of h, else the environment. */
static int arrive(PathCtx *p, const Ray *r, const Media *media, int depth, double beta, int first, double prev_pdf,
                  int from_medium, const Hit *hp, const Light *lh, double t_l, double pdf_l, GColor *out,
                  const GColor **res)
{
    *res = out;
    TraceCtx *c = p->c;
    const Scene *s = c->scene;
    int hit = hp != NULL, rc = G_OK;
    Hit h;
    if (hit)
        h = *hp;
    if (lh) {
        CHECK(gcolor_scale(out, &lh->color, first ? 1.0 : mis_power(prev_pdf, pdf_l)));
        const GMaterial *medium = media_top(media);
        if (!media_clear(medium)) { /* clear (GMAT_CLEAR, vacuum): the dispatch gives the light back */
            GScratchMark mark = gscratch_mark(c->scratch);
            GColor tmp;
            if ((rc = gcolor_scratch_uncleared(&tmp, s->model, c->scratch)) == G_OK && /* absorption's out */
                (rc = gmaterial_absorption(medium, NULL, out, t_l, &tmp)) == G_OK)
                rc = gcolor_copy(out, &tmp);
            gscratch_release(c->scratch, mark);
        }
        return rc;
    }
    if (!hit)
        return escaped(p, r, first, prev_pdf, from_medium, out, res);
    /* glowing geometry that NEE also reaches: its emission weighed against that strategy */
    double emit_weight = 1.0;
    const EmissiveSet *nee_set = light_pick_nee_every(c->pick) ? c->emissive : c->pick ? c->pick->emissive : NULL;
    if (nee_set && !first && h.material && !(h.material->flags & GMAT_NO_EMISSION)) {
        double pdf_e = light_pick_nee_emissive_pmf(c->pick) * emissive_pdf(nee_set, &h, r->o, r->d, h.t);
        if (pdf_e > 0.0)
            emit_weight = mis_power(prev_pdf, pdf_e);
    }
    GSurfPoint sp;
    GVec3 facing;
    surfpoint_fill(c, r, &h, media, &sp, &facing);
    return shade_path(p, r, &sp, facing, media, depth, beta, emit_weight, out);
done:
    return rc;
}

int path_trace(TraceCtx *c, const Ray *r, const Media *media, uint64_t pixel, int sample, int sampler, GColor *out)
{
    PathCtx p = {.c = c, .sobol = sampler == SAMPLER_SOBOL, .point = sample_point(pixel, (uint32_t)sample)};
    Rng camera_rng = c->rng; /* the pixel's own sequence (its sample positions) goes on after this path */
    rng_seed(&c->rng, rng_mix64(pixel ^ rng_mix64((uint64_t)sample)), 0x5851f42d4c957f2dULL);
    const Scene *s = c->scene;
    const ProbeEnv *env = s->env;
    for (int i = 0; env && i < s->nlights; i++) {
        const Light *l = s->lights[i];
        if (l->kind == LIGHT_PROBE && l->env == env && env->dist.row_cdf) {
            p.env_light = l;
            p.env_pick = light_pick_nee_pmf(c->pick, i);
        }
    }
    p.env_in_lights = env && env->nlights > 0 && env->lights[0]->kind == LIGHT_DIRECTIONAL;
    for (int i = 0; s->has_media && i < s->nlights; i++) {
        LightKind k = s->lights[i]->kind;
        p.point_lights |= k == LIGHT_POINT || k == LIGHT_SPOT || k == LIGHT_IES;
    }
    int saved = c->band, volumes = c->volumes;
    c->band = -1;
    c->volumes = s->has_media;
    const GColor *lit;
    int rc = path_radiance(&p, r, media, 0, 1.0, 0, 0.0, out, &lit);
    if (rc >= 0 && lit != out)
        rc = gcolor_copy(out, lit);
    c->band = saved;
    c->volumes = volumes;
    c->rng = camera_rng;
    return rc;
}
#undef CHECK
