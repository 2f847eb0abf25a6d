/* lights.c - the light sources' shade routine (the paper's GPointLight::shade, generalised).
 *
 * For each light sample: the direction `in` to the light, the light's colour at the point (intensity / d^2,
 * irradiance, or radiance times the sample's solid angle), the material's reflection of it towards the
 * viewer, then visibility. The reflection is computed first with the unshadowed light so a material that
 * reflects nothing from this direction (mirrors, clear glass) costs no shadow ray.
 *
 * Shadows: a shadow ray that reaches the light unobstructed leaves the reflected light to the absorption
 * of the medium over the distance (as in Fig. 4). When something is in the way, the shadow ray walks the
 * hits in order: an opaque surface blocks the light; at a non-opaque one the light is passed through the
 * material's refraction() (Fresnel transmission, coloured glass filters), media absorb over the lengths
 * travelled inside them, and the ray continues straight: no caustics, the refracting path the light really
 * takes is not searched for. The material then reflects the light that got through. Directional lights are
 * not absorbed by the media (their distance is infinite).
 *
 * The straight path stands for the refracting one, so each interface is read with the straight direction on
 * its optically thinner side: entering a denser medium, the refraction pair of the shadow-ray direction; leaving
 * one, the pair seen from the other side (the light arriving along the straight direction from outside and
 * refracted inwards). A straight path never meets total internal reflection that way. For a sphere and for a
 * slab this is exact: the real path enters and leaves at the same outside angle as the straight chord, so the
 * transmittance is T(theta)^2, T the one-interface Fresnel transmittance at the chord's angle theta.
 *
 * With LightTmp.blocked (the path tracer's sphere, rectangle and probe lights, which its material sampling
 * also reaches) a shadow ray stops at any surface: light through glass arrives there as a caustic.
 *
 * Lambertian materials (GMAT_LAMBERTIAN, material.h; light_gather): the reflection of every sample is diffuse(sp)
 * times its light times its cosine over pi, so the samples' light times cosine is summed over all lights and the
 * material is asked once per shading point (diffuse), where it would be asked once or twice per sample. A sample
 * whose cosine is 0 casts no shadow ray, as a black reflection does otherwise. The walk through glass changes the
 * light before it is reflected, which the sum carries as well; the absorption of the medium the point lies in acts
 * on the reflected light, so a sample at a finite distance in a medium is still reflected on its own. */
#include "lighting.h"
#include "scene/accel.h"
#include "scene/ies.h"
#include "media/medium.h"

#include <generic/kit/material_kit.h>

#include <math.h>

#define SHADOW_MAX_HITS 64
#define AREA_MAX_SAMPLES 256

/* The two indices of hp into nf (n(from)) and nt (n(to)). */
static int both_indices(GSurfPoint *hp, GColor *nf, GColor *nt)
{
    int rc = gmaterial_refraction_index(hp->from, hp, nf);
    return rc < 0 ? rc : gmaterial_refraction_index(hp->to, hp, nt);
}

/* What of `light`, arriving along the straight shadow direction dir (pointing towards the light), the surface
 * at hp lets through, into out: 1 when something went through, 0 when the surface blocks, or a status. The
 * interface is read with dir on its optically thinner side (see the top of this file): when the shadow ray
 * leaves a denser medium, the refraction pair is taken at the surface seen from the other side, where dir is
 * the direction of the light's arrival and the material refracts it inwards. Between two materials with a constant
 * index the pair's relative indices, both ways, are the colours c keeps (trace_cached_index), else computed here
 * into ri and nf (the same bits). */
static int interface_transmit(TraceCtx *c, GSurfPoint *hp, GVec3 dir, const GColor *light, GColor *nf, GColor *nt,
                              GColor *ri, GColor *out)
{
    const GColor *ri_hp, *ri_other;
    int rc, have_both = 0;
    if ((rc = trace_cached_index(c, hp->from, hp->to, hp, &ri_hp)) < 0)
        return rc;
    /* the relative index set on the point the material is asked at (n(from) / n(to) there): its scalar is taken
     * once (or was, for a kept one), and the colour is not changed while the point is used */
    if (!ri_hp) {
        if ((rc = both_indices(hp, nf, nt)) < 0 || (rc = gcolor_div(ri, nf, nt)) < 0)
            return rc;
        have_both = 1;
        ri_hp = ri;
        gsurfpoint_set_relative_index(hp, ri);
    }
    GSurfPoint other;
    GSurfPoint *at = hp;
    GVec3 view = dir, to_light;
    const GColor *ri_at = ri_hp;
    if (gsurfpoint_relative_index(hp) > 1.0) { /* leaving a denser medium: the point seen from the thinner side */
        other = *hp;
        other.geometric_normal = gvec3_neg(hp->geometric_normal);
        other.entering = !hp->entering;
        other.from = hp->to;
        other.to = hp->from;
        gsurfpoint_invalidate(&other);
        if ((rc = trace_cached_index(c, other.from, other.to, &other, &ri_other)) < 0)
            return rc;
        if (!ri_other) { /* n(to) / n(from) of hp, in nf's storage */
            if ((!have_both && (rc = both_indices(hp, nf, nt)) < 0) || (rc = gcolor_div(nf, nt, nf)) < 0)
                return rc;
            ri_other = nf;
            gsurfpoint_set_relative_index(&other, nf);
        }
        ri_at = ri_other;
        at = &other;
        view = gvec3_neg(dir);
    }
    int valid = gmaterial_refraction_dir(at->material, at, view, ri_at, &to_light);
    if (valid <= 0)
        return valid;
    if (at == hp)
        rc = gmaterial_refraction(hp->material, hp, to_light, light, ri_at, gvec3_neg(dir), out);
    else /* reciprocity: the same pair with the light entering from dir */
        rc = gmaterial_refraction(at->material, at, to_light, light, ri_at, dir, out);
    return rc < 0 ? rc : 1;
}

int light_transmit(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 dir, double dist,
                   GColor *light, int *visible)
{
    const Scene *s = c->scene;
    *visible = 0;
    Media walk;
    if (gvec3_dot(dir, facing) >= 0.0)
        media_copy(&walk, media);
    else /* the light is behind the surface: the path starts on the other side */
        media_cross(media, sp->material, sp->entering, &walk);
    Ray seg = {offset_origin(sp->point, facing, dir), dir, 0.0, dist * (1.0 - 1e-7), 0.0, 0.0};
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor tmp, ri, nf, nt;
    int rc = G_OK;
    if ((rc = trace_tmp(c, TRACE_TMP_WALK, &tmp)) < 0 || (rc = trace_tmp(c, TRACE_TMP_WALK_RI, &ri)) < 0 ||
        (rc = trace_tmp(c, TRACE_TMP_WALK_NF, &nf)) < 0 || (rc = trace_tmp(c, TRACE_TMP_WALK_NT, &nt)) < 0)
        goto done;
    double left = dist;
    GVec3 target = isfinite(dist) ? gvec3_madd(sp->point, dir, dist) : sp->point;
    for (int k = 0; k < SHADOW_MAX_HITS; k++) {
        Hit h;
        c->rays++;
        if (!accel_intersect(s, &seg, &h))
            break;
        GSurfPoint hp;
        GVec3 hf;
        surfpoint_fill(c, &seg, &h, &walk, &hp, &hf);
        if (gmaterial_opaque(hp.material, &hp))
            goto done;
        int absorbs = !media_clear(hp.from); /* clear (GMAT_CLEAR, vacuum): the dispatch gives the light back */
        if (absorbs && ((rc = gmaterial_absorption(hp.from, &hp, light, h.t, &tmp)) < 0 ||
                        (rc = gcolor_copy(light, &tmp)) < 0))
            goto done;
        const Medium *vol = c->volumes ? medium_current(s, &walk) : NULL; /* a participating medium (medium.h) */
        if (vol && (rc = medium_transmit(vol, seg.o, dir, h.t, &c->rng, light, c->scratch)) < 0)
            goto done;
        if ((rc = interface_transmit(c, &hp, dir, light, &nf, &nt, &ri, &tmp)) <= 0 ||
            (rc = gcolor_copy(light, &tmp)) < 0)
            goto done;
        if (gcolor_is_black(light))
            goto done;
        Media next;
        media_cross(&walk, hp.material, hp.entering, &next);
        media_copy(&walk, &next);
        seg.o = offset_origin(hp.point, hf, dir);
        if (isfinite(dist)) {
            left = gvec3_dot(gvec3_sub(target, seg.o), dir);
            if (!(left > 0.0))
                break;
            seg.tmax = left * (1.0 - 1e-7);
        }
    }
    const GMaterial *last = media_top(&walk);
    if (!media_clear(last) && isfinite(left) && left > 0.0) {
        if ((rc = gmaterial_absorption(last, sp, light, left, &tmp)) < 0 || (rc = gcolor_copy(light, &tmp)) < 0)
            goto done;
    }
    const Medium *vol = c->volumes ? medium_current(s, &walk) : NULL;
    if (vol && left > 0.0 && (rc = medium_transmit(vol, seg.o, dir, left, &c->rng, light, c->scratch)) < 0)
        goto done;
    *visible = 1;
done:
    gscratch_release(c->scratch, mark);
    return rc;
}

/* Adds the light of one sample: color * scale is the light's colour at the point (before shadows). With t->gather
 * (a Lambertian material, light_gather) the material is not asked: the light that arrives, times cos_in, is added
 * to t->gathered, which is what the material's reflection of it would be but for the factor diffuse(sp) / pi that
 * light_gather_finish applies to the sum; only where the medium absorbs the reflected light is the sample
 * reflected on its own, as without gathering. */
int sample_light(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 in, double dist,
                 const GColor *color, double scale, GVec3 out_dir, LightTmp *t, GColor *result)
{
    const Scene *s = c->scene;
    /* a result that holds nothing yet (t->unset) takes the reflected light itself: light_add then has nothing to copy,
     * and a sample that adds nothing leaves it unset, whatever it holds */
    GColor *illum = &t->illum, *refl = t->unset ? result : &t->refl, *tmp = &t->tmp;
    double cos_in = 0.0;
    int rc;
    if (t->gather) { /* illum is made below where it is needed: the clear path adds color * (scale * cos) */
        GVec3 n;
        cos_in = gmaterial_cos_in(sp, in, out_dir, &n); /* the cosine the material's reflection would use */
        if (!(cos_in > 0.0))
            return G_OK; /* its reflection would be black: no shadow ray */
    } else {
        if ((rc = gcolor_scale(illum, color, scale)) < 0 ||
            (rc = gmaterial_reflection(sp->material, sp, in, illum, out_dir, refl)) < 0)
            return rc;
        if (gcolor_is_black(refl))
            return G_OK; /* nothing reflected from here: no shadow ray */
    }
    Ray sr = {offset_origin(sp->point, facing, in), in, 0.0, dist * (1.0 - 1e-7), 0.0, 0.0};
    c->rays++;
    int occluded = accel_occluded(s, &sr);
    const GMaterial *medium = NULL;
    if (occluded == OCCLUDED_CLEAR && !c->volumes) { /* participating media: the walk below attenuates */
        medium = gvec3_dot(in, facing) >= 0.0 ? sp->from : sp->to;
        if (!medium || !isfinite(dist)) { /* the light arrives as it left */
            if (!t->gather)
                return light_add(t, result, refl);
            /* gathered with the factor rounded to float, as gcolor_scale rounds its own: the axpy then multiplies in
             * float, and the first sample's product is the axpy's onto black, so it is written by gcolor_scale */
            if (!t->gathered_any) {
                t->gathered_any = 1;
                return gcolor_scale(&t->gathered, color, (float)(scale * cos_in));
            }
            return gcolor_add_scaled(&t->gathered, color, (float)(scale * cos_in));
        }
    } else if (occluded != OCCLUDED_CLEAR && (t->blocked || occluded == OCCLUDED_OPAQUE)) {
        return G_OK; /* the walk below would end at that surface */
    }
    if (t->gather && (rc = gcolor_scale(illum, color, scale)) < 0) /* the light itself, which gathering skipped */
        return rc;
    if (occluded == OCCLUDED_CLEAR && !c->volumes) { /* the medium absorbs the reflected light: this sample alone */
        if ((t->gather && (rc = gmaterial_reflection(sp->material, sp, in, illum, out_dir, refl)) < 0) ||
            (!media_clear(medium) &&
             ((rc = gmaterial_absorption(medium, sp, refl, dist, tmp)) < 0 || (rc = gcolor_copy(refl, tmp)) < 0)))
            return rc;
        return light_add(t, result, refl);
    }
    int visible;
    if ((rc = light_transmit(c, sp, facing, media, in, dist, illum, &visible)) < 0 || !visible)
        return rc;
    if (t->gather) { /* the light that got through, as the material would reflect it */
        if (!t->gathered_any)
            gcolor_black(&t->gathered);
        t->gathered_any = 1;
        return gcolor_add_scaled(&t->gathered, illum, cos_in);
    }
    if ((rc = gmaterial_reflection(sp->material, sp, in, illum, out_dir, refl)) < 0)
        return rc;
    return light_add(t, result, refl);
}

int light_add(LightTmp *t, GColor *result, const GColor *x)
{
    if (!t->unset)
        return gcolor_add(result, result, x);
    t->unset = 0;
    return x == result ? G_OK : gcolor_copy(result, x);
}

void light_gather(GSurfPoint *sp, LightTmp *t)
{
    t->gather = gmaterial_lambertian(sp->material);
    t->gathered_any = 0; /* t->gathered is written by the first sample */
}

int light_gather_finish(GSurfPoint *sp, LightTmp *t, GColor *result)
{
    if (!t->gather)
        return G_OK;
    t->gather = 0;
    if (!t->gathered_any)
        return G_OK; /* no light sample arrived (all shadowed or turned away): the material is not asked */
    int rc = gmaterial_diffuse(sp->material, sp, &t->tmp);
    if (rc == G_OK && t->unset) { /* black plus the reflected light is that light: written to result directly */
        t->unset = 0;
        return gcolor_mul_scaled(result, &t->tmp, &t->gathered, 1.0 / M_PI);
    }
    if (rc == G_OK)
        rc = gcolor_mul_scaled(&t->tmp, &t->tmp, &t->gathered, 1.0 / M_PI);
    return rc == G_OK ? gcolor_add(result, result, &t->tmp) : rc;
}

static double smoothstep(double a, double b, double x)
{
    if (b <= a)
        return x >= b ? 1.0 : 0.0;
    double t = gfmin(1.0, gfmax(0.0, (x - a) / (b - a)));
    return t * t * (3.0 - 2.0 * t);
}

double light_spot_factor(const Light *l, GVec3 in)
{
    return smoothstep(l->cos_outer, l->cos_inner, -gvec3_dot(in, l->direction));
}

double mis_power(double a, double b)
{
    a *= a;
    b *= b;
    return a + b > 0.0 && isfinite(a + b) ? a / (a + b) : (isinf(a) ? 1.0 : 0.0);
}

int light_temps(TraceCtx *c, LightTmp *t)
{
    int rc;
    t->blocked = 0;
    t->gather = 0;
    t->gathered_any = 0;
    t->unset = 0;
    if ((rc = trace_tmp(c, TRACE_TMP_ILLUM, &t->illum)) < 0 || (rc = trace_tmp(c, TRACE_TMP_REFL, &t->refl)) < 0 ||
        (rc = trace_tmp(c, TRACE_TMP_LIGHT, &t->tmp)) < 0 || (rc = trace_tmp(c, TRACE_TMP_GATHER, &t->gathered)) < 0)
        return rc;
    return G_OK;
}

int light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                int opaque, LightTmp *t, GColor *result)
{
    GVec3 p = sp->point;
    switch (l->kind) {
    case LIGHT_POINT:
    case LIGHT_SPOT: {
        GVec3 L = gvec3_sub(l->position, p);
        double d = gvec3_length(L);
        if (d <= 0.0)
            return G_OK;
        GVec3 in = gvec3_scale(L, 1.0 / d);
        if (opaque && gvec3_dot(in, facing) <= 0.0)
            return G_OK;
        double f = 1.0;
        if (l->kind == LIGHT_SPOT)
            f = smoothstep(l->cos_outer, l->cos_inner, -gvec3_dot(in, l->direction));
        if (f <= 0.0)
            return G_OK;
        return sample_light(c, sp, facing, media, in, d, &l->color, f / (d * d), out_dir, t, result);
    }
    case LIGHT_DIRECTIONAL: {
        GVec3 in = gvec3_neg(l->direction);
        if (opaque && gvec3_dot(in, facing) <= 0.0)
            return G_OK;
        return sample_light(c, sp, facing, media, in, INFINITY, &l->color, 1.0, out_dir, t, result);
    }
    case LIGHT_SPHERE: {
        GVec3 axis = gvec3_sub(l->position, p);
        double dc = gvec3_length(axis);
        if (dc <= l->radius)
            return G_OK;
        axis = gvec3_scale(axis, 1.0 / dc);
        double sin_max = l->radius / dc, cos_max = sqrt(gfmax(0.0, 1.0 - sin_max * sin_max));
        if (opaque && gvec3_dot(axis, facing) < -sin_max)
            return G_OK; /* the whole cap is below the surface */
        double omega = 2.0 * M_PI * (1.0 - cos_max);
        int n = l->samples < 1 ? 1 : l->samples > AREA_MAX_SAMPLES ? AREA_MAX_SAMPLES : l->samples;
        int perm[AREA_MAX_SAMPLES], grid = strata_grid(n);
        if (!grid && n > 1)
            strata_shuffle(&c->rng, n, perm);
        GVec3 t1, t2;
        frame_from_normal(axis, &t1, &t2);
        for (int i = 0; i < n; i++) {
            double u1, u2;
            pixel_sample(&c->rng, i, n, grid, perm, &u1, &u2);
            if (n == 1)
                u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
            double ct = 1.0 - u1 * (1.0 - cos_max), st = sqrt(gfmax(0.0, 1.0 - ct * ct)), ph = 2.0 * M_PI * u2;
            GVec3 in = gvec3_add(gvec3_scale(axis, ct),
                                 gvec3_add(gvec3_scale(t1, st * cos(ph)), gvec3_scale(t2, st * sin(ph))));
            if (opaque && gvec3_dot(in, facing) <= 0.0)
                continue;
            /* distance to the near side of the sphere along in */
            double b = dc * ct, disc = b * b - (dc * dc - l->radius * l->radius);
            double d = b - sqrt(gfmax(0.0, disc));
            int rc = sample_light(c, sp, facing, media, in, d, &l->color, omega / n, out_dir, t, result);
            if (rc < 0)
                return rc;
        }
        return G_OK;
    }
    case LIGHT_RECT: {
        GVec3 nl = gvec3_cross(l->edge1, l->edge2);
        double area = gvec3_length(nl);
        if (area <= 0.0)
            return G_OK;
        nl = gvec3_scale(nl, 1.0 / area);
        int n = l->samples < 1 ? 1 : l->samples > AREA_MAX_SAMPLES ? AREA_MAX_SAMPLES : l->samples;
        int perm[AREA_MAX_SAMPLES], grid = strata_grid(n);
        if (!grid && n > 1)
            strata_shuffle(&c->rng, n, perm);
        for (int i = 0; i < n; i++) {
            double u1, u2;
            pixel_sample(&c->rng, i, n, grid, perm, &u1, &u2);
            if (n == 1)
                u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
            GVec3 y = gvec3_add(l->position, gvec3_add(gvec3_scale(l->edge1, u1), gvec3_scale(l->edge2, u2)));
            GVec3 w = gvec3_sub(y, p);
            double d = gvec3_length(w);
            if (d <= 0.0)
                continue;
            GVec3 in = gvec3_scale(w, 1.0 / d);
            double cos_l = -gvec3_dot(in, nl);
            if (cos_l <= 0.0 || (opaque && gvec3_dot(in, facing) <= 0.0))
                continue;
            int rc =
                sample_light(c, sp, facing, media, in, d, &l->color, area * cos_l / (d * d * n), out_dir, t, result);
            if (rc < 0)
                return rc;
        }
        return G_OK;
    }
    case LIGHT_IES: { /* a point light of the table's intensity towards the point */
        GVec3 L = gvec3_sub(l->position, p);
        double d = gvec3_length(L);
        if (d <= 0.0)
            return G_OK;
        GVec3 in = gvec3_scale(L, 1.0 / d);
        if (opaque && gvec3_dot(in, facing) <= 0.0)
            return G_OK;
        double cd = ies_candela_dir(l->ies, gvec3_neg(in), l->direction, l->along, l->third);
        if (!(cd > 0.0))
            return G_OK;
        return sample_light(c, sp, facing, media, in, d, &l->color, cd / (d * d), out_dir, t, result);
    }
    case LIGHT_PROBE:
        return probe_light_shade(c, l, sp, facing, media, out_dir, opaque, t, result);
    case LIGHT_AMBIENT:
    case LIGHT_BACKGROUND:
        break;
    }
    return G_OK;
}
