/* whitted.c - the paper's Fig. 4: trace a ray to its closest hit, fill the surface point, and shade it:
 * emission, ambient, every light (light_shade), the ideal reflection traced recursively, the ideal
 * refraction with the relative index of the media on both sides (total internal reflection is the
 * material's refraction_dir saying "not valid"), and the absorption of the medium the ray travelled in.
 *
 * Dispersion: when the relative index differs between the colour model's wavelength groups (bands.h), the
 * refracted ray splits: each group is refracted with its own index, and of what comes back only the group's
 * light (its mask times the light) is kept. A path that carries one group is refracted with that group's index
 * at every later interface and never splits again. The reflected ray does not depend on wavelength and stays
 * whole. Light that a fluorescent surface re-radiates into the group is carried on (the mask applies where the
 * path split, so a group's path sees the scene's full light before that point); an interface crossed by the
 * group's path farther from the viewer still bends it with the group's index, whatever band the light had
 * before it was re-radiated (documented approximation).
 *
 * Adaptive depth (Hall and Greenberg 1983): before a reflected or refracted ray is traced, the material is
 * asked what it would pass on of an illumination of 1 in every sample; the brightness of that, times the
 * weight of the path so far, is the most the ray can contribute to its pixel per unit of radiance, and
 * rays below the cutoff are not traced (the glass sphere's internal reflections die out after a few
 * bounces instead of branching to the depth limit).
 * Participating media (`medium`, an object's `interior`, the camera's `atmosphere`: media/medium.h) are the path
 * tracer's: this tracer keeps only the materials' Beer absorption and renders a scene's media as vacuum.
 * Colours only through gcolor_*, materials only through gmaterial_*; temporaries live on the thread's
 * scratch arena and are released before returning. */
#include "whitted.h"
#include "bands.h"
#include "scene/accel.h"
#include "lights/emissive.h"
#include "lights/lighting.h"
#include "lights/probe_env.h"
#include "check.h"

#include <math.h>

/* What the material passes on towards the viewer of light `in` arriving from dir: its reflection, or its
 * refraction with the relative index ri when ri is given. */
static int pass_on(const GMaterial *m, GSurfPoint *sp, GVec3 dir, const GColor *in, const GColor *ri,
                   GVec3 to_viewer, GColor *out)
{
    return ri ? gmaterial_refraction(m, sp, dir, in, ri, to_viewer, out)
              : gmaterial_reflection(m, sp, dir, in, to_viewer, out);
}

static int trace_ray(TraceCtx *c, const Ray *r, const Media *media, int depth, GColor *buf, const GColor **out);

/* Adds to out the light that arrives along the secondary direction dir (a reflection_dir, or a refraction_dir
 * with ri its relative index; NULL: reflection) through the media `next`, as the material passes it on
 * towards the viewer; with a mask, only the mask's part of it (one wavelength group of a dispersive
 * refraction). Adaptive depth: the branch is not traced when what it can bring to the pixel (the material's
 * pass-on of 1, times the path's weight) is below the cutoff. A material that filters light sample by sample
 * (GMAT_DIAGONAL) is not asked again with the ray's light: its pass-on of 1 times that light is the same.
 * *unset: out holds nothing yet (it stands for black): the light is written to it instead of added, and *unset
 * cleared; out stays unwritten when the branch brings nothing. */
static int trace_secondary(TraceCtx *c, const Ray *r, GSurfPoint *sp, GVec3 facing, GVec3 dir, const GColor *ri,
                           const GColor *mask, const Media *next, int depth, GColor *out, int *unset)
{
    const GMaterial *m = sp->material;
    GVec3 to_viewer = gvec3_neg(r->d);
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor tmp, illum;
    const GColor *lit;
    int rc = G_OK, diagonal = gmaterial_diagonal(m);
    if (diagonal) /* the pass-on of 1 is kept across the ray (written in full by the material: not cleared) */
        CHECK(gcolor_scratch_uncleared(&tmp, c->scene->model, c->scratch));
    else
        CHECK(trace_tmp(c, TRACE_TMP_PASS, &tmp)); /* not held across whitted_trace, which uses it too */
    CHECK(pass_on(m, sp, dir, &c->unit, ri, to_viewer, &tmp));
    if (mask)
        CHECK(gcolor_mul(&tmp, mask, &tmp));
    double w = c->weight * gcolor_brightness(&tmp);
    if (!(w > 0.0 && w >= c->cutoff))
        goto done;
    if (c->rays_left <= 0) { /* the sample's ray budget is spent: this branch is not traced */
        c->capped = 1;
        goto done;
    }
    c->rays_left--;
    CHECK(gcolor_scratch_uncleared(&illum, c->scene->model, c->scratch)); /* trace_ray writes it in full */
    double width = r->cone_width + r->cone_spread * sp->t;
    Ray ray = {offset_origin(sp->point, facing, dir), dir, 0.0, INFINITY, width, r->cone_spread};
    double saved = c->weight;
    c->weight = w;
    rc = trace_ray(c, &ray, next, depth + 1, &illum, &lit);
    c->weight = saved;
    CHECK(rc);
    /* the light passed on, into out directly when it holds nothing yet (black plus it is it) */
    GColor *dst = *unset ? out : &tmp;
    if (diagonal) { /* its pass-on of 1 (the mask in it) times the ray's light */
        CHECK(gcolor_mul(dst, &tmp, lit));
    } else {
        CHECK(pass_on(m, sp, dir, lit, ri, to_viewer, dst));
        if (mask)
            CHECK(gcolor_mul(dst, mask, dst));
    }
    if (*unset)
        *unset = 0;
    else
        CHECK(gcolor_add(out, out, &tmp));
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

/* The refracted light at sp: one ray with the relative index ri; a ray per wavelength group when ri is
 * dispersive; the carried group's index on a path that already split. */
static int refract(TraceCtx *c, const Ray *r, GSurfPoint *sp, GVec3 facing, const GColor *ri, const Media *media,
                   int depth, GColor *out, int *unset)
{
    const GMaterial *m = sp->material;
    const Bands *b = c->bands;
    GVec3 dir;
    Media next;
    media_cross(media, m, sp->entering, &next);
    int split = c->band < 0 && b && bands_disperse(b, ri), valid, rc = G_OK;
    GScratchMark mark = gscratch_mark(c->scratch);
    if (!split && (c->band < 0 || !b)) {
        CHECK(valid = gmaterial_refraction_dir(m, sp, r->d, ri, &dir));
        if (valid)
            CHECK(trace_secondary(c, r, sp, facing, dir, ri, NULL, &next, depth, out, unset));
        goto done;
    }
    GColor rg;
    CHECK(gcolor_scratch(&rg, c->scene->model, c->scratch));
    int g0 = split ? 0 : c->band, g1 = split ? b->n : c->band + 1;
    for (int g = g0; g < g1; g++) {
        CHECK(gcolor_fill(&rg, bands_value(b, ri, g)));
        CHECK(valid = gmaterial_refraction_dir(m, sp, r->d, &rg, &dir));
        if (!valid)
            continue; /* this group is totally reflected */
        c->band = g;
        rc = trace_secondary(c, r, sp, facing, dir, &rg, split ? &b->mask[g] : NULL, &next, depth, out, unset);
        c->band = split ? -1 : g;
        CHECK(rc);
    }
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

static int shade(TraceCtx *c, const Ray *r, GSurfPoint *sp, GVec3 facing, const Media *media, int depth, GColor *out)
{
    const Scene *s = c->scene;
    const GMaterial *m = sp->material;
    GScratchMark mark = gscratch_mark(c->scratch);
    GVec3 view = r->d, to_viewer = gvec3_neg(r->d), dir;
    GColor tmp, inside, *res = out;
    int rc = G_OK, valid;
    CHECK(trace_tmp(c, TRACE_TMP_SHADE, &tmp)); /* not held across the secondary rays, which use it too */
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
    /* emission, ambient light and the direct light of every light source */
    if (!unset)
        CHECK(gmaterial_emission(m, sp, to_viewer, res));
    if (s->have_ambient) {
        CHECK(gmaterial_ambient(m, sp, &s->ambient, unset ? res : &tmp));
        if (!unset)
            CHECK(gcolor_add(res, res, &tmp));
        unset = 0;
    }
    int opaque = gmaterial_opaque(m, sp);
    /* a material whose every lobe is ideal reflects no light sample (is_delta, material.h): no light is asked */
    if ((s->nlights > 0 || c->emissive) && !gmaterial_is_delta(m, sp)) {
        LightTmp lt;
        CHECK(light_temps(c, &lt));
        lt.unset = unset;
        light_gather(sp, &lt); /* a Lambertian material: asked once for all lights (lights.c) */
        for (int i = 0; i < s->nlights; i++)
            CHECK(light_shade(c, s->lights[i], sp, facing, media, to_viewer, opaque, &lt, res));
        if (c->emissive) /* glowing geometry, as an area light */
            CHECK(emissive_shade(c, c->emissive, sp, facing, media, to_viewer, opaque, &lt, res));
        CHECK(light_gather_finish(sp, &lt, res));
        unset = lt.unset;
    }
    if (depth < c->max_depth) {
        /* the relative index first: the reflection's Fresnel term reads it too */
        GColor room;
        const GColor *ri = NULL; /* read only: it may be a colour the context keeps (trace.h) */
        if (!opaque)
            CHECK(trace_relative_index(c, sp, &room, &ri));
        /* ideal reflection, in the medium the ray came through */
        CHECK(valid = gmaterial_reflection_dir(m, sp, view, &dir));
        if (valid)
            CHECK(trace_secondary(c, r, sp, facing, dir, NULL, NULL, media, depth, res, &unset));
        /* ideal refraction into the medium on the other side; not valid: total internal reflection */
        if (!opaque)
            CHECK(refract(c, r, sp, facing, ri, media, depth, res, &unset));
    }
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

/* Radiance arriving along r into *out: buf, which the hit's shading writes, or the scene's background colour itself
 * when r leaves the scene and no probe is the background (not copied: the caller reads it where it is). */
static int trace_ray(TraceCtx *c, const Ray *r, const Media *media, int depth, GColor *buf, const GColor **out)
{
    Hit h;
    c->rays++;
    *out = buf;
    int hit = accel_intersect(c->scene, r, &h), seen_rc;
    if (depth == 0 && light_seen(c->scene, r, hit ? h.t : INFINITY, buf, &seen_rc))
        return seen_rc;
    if (!hit) {
        if (c->scene->env)
            return probe_background(c->scene->env, r->d, buf);
        *out = &c->scene->background;
        return G_OK;
    }
    GSurfPoint sp;
    GVec3 facing;
    surfpoint_fill(c, r, &h, media, &sp, &facing);
    return shade(c, r, &sp, facing, media, depth, buf);
}

int whitted_trace(TraceCtx *c, const Ray *r, const Media *media, int depth, GColor *out)
{
    const GColor *lit;
    int rc = trace_ray(c, r, media, depth, out, &lit);
    return rc < 0 || lit == out ? rc : gcolor_copy(out, lit);
}
