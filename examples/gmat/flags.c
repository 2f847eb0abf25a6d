/* flags.c - the checks of `gmat check` on the instance flags (material.h). A flag lets the dispatch answer without
 * calling the class, so a bit set wrongly (by a plug-in) changes pictures without an error; each check calls the
 * class's own slot directly, at the places of the finite check, above and below the surface:
 *   no-emission  with GMAT_NO_EMISSION: the largest |value| of any sample the emission slot returns over the
 *                finite check's directions (a failed call counts as infinite); must be black;
 *   opaque-flag  with GMAT_OPAQUE: how many calls of the opaque slot did not say 1; must be none;
 *   geometric-normal  with GMAT_GEOMETRIC_NORMAL: the largest distance of the normal slot's vector from the
 *                geometric normal (a failed call counts as infinite); at most 1e-9 (rounding only);
 *   lambertian   with GMAT_LAMBERTIAN: over random pairs of directions (both on the side of the geometric normal
 *                mostly, one or both behind it else) and lights (white, and gmat_random_light), the class's
 *                own reflection against its diffuse colour times the light times gmaterial_cos_in / pi: the largest
 *                difference over the largest value at a place (a failed call, or an is_delta slot that does not
 *                say 0, counts as infinite); at most 1e-5 (rounding: a blend sums its children's products);
 *   diagonal     with GMAT_DIAGONAL: over random directions out (on the side of the geometric normal mostly) and
 *                random lights (gmat_random_light: values in [0.25, 1], each sample on its own, or a random spectrum
 *                through a plug-in model's own conversion), the class's own reflection of the light from random
 *                directions (one or both behind the normal sometimes) and from the ideal reflection of out, and its
 *                refraction with the relative indices 1 and 1.5 (gcolor_fill) from across the surface, from the
 *                ideal refraction and sometimes from out's side, each against what the slot passes on of white (1
 *                in every sample) times the light (gcolor_mul): the largest difference over the largest value of
 *                each of the three at a place (a failed call counts as infinite); at most 1e-5 (rounding).
 *   no-ideal     with GMAT_NO_IDEAL: how many calls of the reflection_dir and refraction_dir slots (the relative
 *                indices 1.5 and 1 / 1.5) over the finite check's directions did not say 0 (not valid); must be none.
 * Nothing to check without the bit, or without the slot (the default is then what the bit says). */
#include "gmat.h"

#include <generic/kit/material_kit.h>

#include <math.h>
#include <stdio.h>

/* The largest |sample| of c, every entry of a matrix (infinite for NaN). */
static double largest(const GColor *c)
{
    double big = 0.0;
    int n = c->kind == GCOLOR_MATRIX ? c->model->capacity : c->model->nvalues;
    for (int j = 0; j < n && j < c->capacity; j++) {
        double x = fabs((double)c->v[j]);
        big = isnan(x) ? INFINITY : fmax(big, x);
    }
    return big;
}

/* What one check measures at a surface point (below: the point is seen from under the surface); *calls counts the
 * class's calls. */
typedef double (*PointMeasure)(GmatContext *ctx, GSurfPoint *sp, int below, int *calls);

/* The measure at every place of the finite check, above and below the surface: the largest value, or with `sum`
 * the total. */
static double over_places(GmatContext *ctx, const GmatPlace *places, int nplaces, PointMeasure measure, int sum,
                          int *calls)
{
    double acc = 0.0;
    *calls = 0;
    for (int p = 0; p < nplaces; p++) {
        ctx->place = &places[p];
        for (int below = 0; below < 2; below++) {
            GSurfPoint sp;
            gmat_surface_point(ctx, &sp, below);
            double v = measure(ctx, &sp, below, calls);
            acc = sum ? acc + v : fmax(acc, v);
        }
    }
    ctx->place = NULL;
    return acc;
}

/* Measures `measure` at every place (over_places, with `sum`) and reports the result as `property` against tol, with
 * the detail `format` given the number of the class's calls (its one conversion, %d). */
static void report_over_places(GmatContext *ctx, const GmatPlace *places, int nplaces, PointMeasure measure, int sum,
                               GmatReportFn report, void *checker, const char *property, double tol,
                               const char *format)
{
    int calls;
    double value = over_places(ctx, places, nplaces, measure, sum, &calls);
    char detail[240];
    snprintf(detail, sizeof detail, format, calls);
    report(checker, property, value, tol, detail);
}

/* The largest |value| of the class's own emission over the finite check's directions (a failed call: infinite). */
static double emission_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    const GMaterial *m = ctx->material;
    double worst = 0.0, sign = below ? -1.0 : 1.0;
    for (int t = 0; t < 90; t += 15)
        for (int ph = 0; ph < 360; ph += 90) {
            GVec3 out = gmat_direction(t, ph);
            out.z *= sign;
            GScratchMark mark = gscratch_mark(ctx->scratch);
            GColor c;
            int rc = gcolor_scratch(&c, ctx->model, ctx->scratch);
            if (rc == G_OK)
                rc = m->cls->emission(m, sp, out, &c);
            worst = fmax(worst, rc == G_OK ? largest(&c) : INFINITY);
            (*calls)++;
            gscratch_release(ctx->scratch, mark);
        }
    return worst;
}

void gmat_check_no_emission(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                            void *checker)
{
    const GMaterial *m = ctx->material;
    if (gmaterial_emits(m) || !m->cls->emission) {
        report(checker, "no-emission", 0.0, 0.0,
               gmaterial_emits(m) ? "(GMAT_NO_EMISSION not set: the emission slot is called)"
                                  : "(GMAT_NO_EMISSION set, no emission slot: black, the default)");
        return;
    }
    report_over_places(ctx, places, nplaces, emission_at, 0, report, checker, "no-emission", 0.0,
                       "(GMAT_NO_EMISSION set: largest |value| of the class's own emission, %d calls; must be black)");
}

/* 1 when the class's own opaque slot does not say 1 at sp. */
static double not_opaque_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    (void)below;
    (*calls)++;
    return ctx->material->cls->opaque(ctx->material, sp) != 1;
}

void gmat_check_opaque_flag(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                            void *checker)
{
    const GMaterial *m = ctx->material;
    if (!gmaterial_opaque_everywhere(m) || !m->cls->opaque) {
        report(checker, "opaque-flag", 0.0, 0.0,
               !gmaterial_opaque_everywhere(m) ? "(GMAT_OPAQUE not set: the opaque slot is called)"
                                               : "(GMAT_OPAQUE set, no opaque slot: opaque, the default)");
        return;
    }
    report_over_places(ctx, places, nplaces, not_opaque_at, 1, report, checker, "opaque-flag", 0.0,
                       "(GMAT_OPAQUE set: calls of the class's own opaque slot that did not say 1, of %d)");
}

/* The distance of the class's own normal at sp from the geometric normal (a failed call: infinite). */
static double normal_off_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    (void)below;
    const GMaterial *m = ctx->material;
    GVec3 n = sp->geometric_normal;
    int rc = m->cls->normal(m, sp, &n);
    double d = gvec3_length(gvec3_sub(n, sp->geometric_normal));
    (*calls)++;
    return rc == G_OK && !isnan(d) ? d : INFINITY;
}

void gmat_check_geometric_normal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                                 void *checker)
{
    const GMaterial *m = ctx->material;
    const double tol = 1e-9;
    if (!(m->flags & GMAT_GEOMETRIC_NORMAL) || !m->cls->normal) {
        report(checker, "geometric-normal", 0.0, tol,
               !(m->flags & GMAT_GEOMETRIC_NORMAL)
                   ? "(GMAT_GEOMETRIC_NORMAL not set: the normal slot is called)"
                   : "(GMAT_GEOMETRIC_NORMAL set, no normal slot: the geometric normal, the default)");
        return;
    }
    report_over_places(ctx, places, nplaces, normal_off_at, 0, report, checker, "geometric-normal", tol,
                       "(GMAT_GEOMETRIC_NORMAL set: largest distance of the class's own normal from the geometric one, "
                       "%d calls)");
}

/* ---- lambertian: reflection against diffuse * light * cos / pi ---- */

#define LAMBERT_PAIRS 64
#define TOL_LAMBERTIAN 1e-5

/* A uniformly distributed direction on the sphere, turned to the side of n unless `behind`. */
static GVec3 sphere_direction(unsigned long long *s, GVec3 n, int behind)
{
    double z = 1.0 - 2.0 * gmat_uniform(s), p = 2.0 * M_PI * gmat_uniform(s), r = sqrt(fmax(0.0, 1.0 - z * z));
    GVec3 d = gvec3(r * cos(p), r * sin(p), z);
    return (gvec3_dot(d, n) < 0.0) != behind ? gvec3_neg(d) : d;
}

/* The largest difference between the class's own reflection and diffuse * light * gmaterial_cos_in / pi over
 * LAMBERT_PAIRS random pairs at sp, over the largest value (a failed call, or is_delta not 0: infinite). */
static double lambertian_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    const GMaterial *m = ctx->material;
    /* other pairs at each place and side, the same on every run */
    unsigned long long seed = 0x5eedULL + (below ? 977ULL : 0ULL) + (unsigned long long)(ctx->place->u * 1000003.0);
    if (m->cls->is_delta && m->cls->is_delta(m, sp) != 0)
        return INFINITY;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    GColor diffuse, light, got, want;
    int rc = gcolor_scratch(&diffuse, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&light, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&got, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&want, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gmaterial_diffuse(m, sp, &diffuse);
    double diff = 0.0, big = 0.0;
    for (int i = 0; i < LAMBERT_PAIRS && rc == G_OK; i++) {
        GVec3 g = sp->geometric_normal, n;
        GVec3 in = sphere_direction(&seed, g, i % 8 == 5 || i % 8 == 7), out = sphere_direction(&seed, g, i % 8 >= 6);
        if (i % 2) { /* a light of random values in [0.25, 1] */
            rc = gmat_random_light(ctx->model, &seed, &light);
        } else {
            rc = gcolor_copy(&light, &ctx->white);
        }
        double c = gmaterial_cos_in(sp, in, out, &n);
        gcolor_black(&got); /* no reflection slot: black, the default */
        if (rc == G_OK && m->cls->reflection)
            rc = m->cls->reflection(m, sp, in, &light, out, &got);
        if (rc == G_OK)
            rc = gcolor_mul_scaled(&want, &diffuse, &light, c / M_PI);
        (*calls)++;
        for (int j = 0; rc == G_OK && j < ctx->model->nvalues; j++) {
            double a = got.v[j], b = want.v[j];
            diff = fmax(diff, isnan(a - b) ? INFINITY : fabs(a - b));
            big = fmax(big, fmax(fabs(a), fabs(b)));
        }
    }
    gscratch_release(ctx->scratch, mark);
    if (rc != G_OK || !isfinite(diff))
        return INFINITY;
    return big > 0.0 ? diff / big : diff;
}

void gmat_check_lambertian(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                           void *checker)
{
    if (!gmaterial_lambertian(ctx->material)) {
        report(checker, "lambertian", 0.0, TOL_LAMBERTIAN, "(GMAT_LAMBERTIAN not set: reflection is asked per light)");
        return;
    }
    report_over_places(ctx, places, nplaces, lambertian_at, 0, report, checker, "lambertian", TOL_LAMBERTIAN,
                       "(GMAT_LAMBERTIAN set: |reflection - diffuse * light * cos / pi| / max, %d random pairs and "
                       "lights)");
}

/* ---- diagonal: the pass-on of a light against the pass-on of white times that light ---- */

#define DIAGONAL_PAIRS 48
#define TOL_DIAGONAL 1e-5

/* One comparison of the diagonal check: reflection, refraction with the relative index 1 or with 1.5. */
enum { DIAG_REFLECTION, DIAG_REFRACTION_1, DIAG_REFRACTION_15, DIAG_KINDS };

/* What the diagonal check holds at one place: white (1 in every sample: the bit's white, not ctx->white, which is
 * D65 in a spectral model), the indices 1 (white itself) and 1.5, the light, the two answers, and per comparison
 * the largest |difference| and the largest |value| (kept apart: a dielectric's small reflection is not measured
 * against its large refraction). */
typedef struct DiagonalWork {
    GColor white, index15, light, got, want;
    double diff[DIAG_KINDS], big[DIAG_KINDS];
} DiagonalWork;


/* Compares w->got with w->want sample by sample into comparison `kind` (a NaN difference: infinite); the values
 * are read as nvalues floats, as the lambertian check reads them. */
static void diagonal_compare(GmatContext *ctx, DiagonalWork *w, int kind)
{
    for (int j = 0; j < ctx->model->nvalues; j++) {
        double a = w->got.v[j], b = w->want.v[j];
        w->diff[kind] = fmax(w->diff[kind], isnan(a - b) ? INFINITY : fabs(a - b));
        w->big[kind] = fmax(w->big[kind], fmax(fabs(a), fabs(b)));
    }
}

/* The class's own reflection (rel_index NULL) or refraction of w->light from in towards out against its pass-on
 * of white times the light (gcolor_mul), into comparison `kind`; a missing slot is black (the default), which
 * passes black on of any light: nothing to compare. */
static int diagonal_pair(GmatContext *ctx, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index,
                         DiagonalWork *w, int kind, int *calls)
{
    const GMaterial *m = ctx->material;
    if (rel_index ? !m->cls->refraction : !m->cls->reflection)
        return G_OK;
    int rc = rel_index ? m->cls->refraction(m, sp, in, &w->light, rel_index, out, &w->got)
                       : m->cls->reflection(m, sp, in, &w->light, out, &w->got);
    if (rc == G_OK) /* want: first what it passes on of white, then times the light */
        rc = rel_index ? m->cls->refraction(m, sp, in, &w->white, rel_index, out, &w->want)
                       : m->cls->reflection(m, sp, in, &w->white, out, &w->want);
    if (rc == G_OK)
        rc = gcolor_mul(&w->want, &w->want, &w->light);
    *calls += 2;
    if (rc == G_OK)
        diagonal_compare(ctx, w, kind);
    return rc;
}

/* The direction light comes from along the ideal ray of out (reflection_dir, or refraction_dir with rel_index):
 * a delta lobe (a mirror, glass) passes light on there alone, which random pairs never hit. Else a random
 * direction on the side of g unless `behind`. */
static GVec3 pair_in(GmatContext *ctx, GSurfPoint *sp, unsigned long long *seed, GVec3 out, const GColor *rel_index,
                     int ideal, int behind)
{
    GVec3 g = sp->geometric_normal, in = sphere_direction(seed, g, behind);
    GVec3 dir;
    if (!ideal)
        return in;
    int valid = rel_index ? gmaterial_refraction_dir(ctx->material, sp, gvec3_neg(out), rel_index, &dir)
                          : gmaterial_reflection_dir(ctx->material, sp, gvec3_neg(out), &dir);
    return valid == 1 && gvec3_length(dir) > 0.0 ? gvec3_normalize(dir) : in;
}

/* Over DIAGONAL_PAIRS random directions out (on the side of the geometric normal mostly, behind it else) and a
 * random light each: the reflection of light from a direction on out's side (one pair in four the ideal
 * reflection of out), and the refraction with the relative indices 1 and 1.5 of light from across the surface
 * (one pair in four the ideal refraction, one in eight from out's side), each against the pass-on of white times
 * the light. The largest of the three comparisons' largest difference over largest value (a failed call:
 * infinite). */
static double diagonal_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    /* other pairs at each place and side, the same on every run */
    unsigned long long seed = 0xd1a6ULL + (below ? 977ULL : 0ULL) + (unsigned long long)(ctx->place->u * 1000003.0);
    GScratchMark mark = gscratch_mark(ctx->scratch);
    DiagonalWork w = {.diff = {0}, .big = {0}};
    int rc = gcolor_scratch(&w.white, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&w.index15, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&w.light, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&w.got, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&w.want, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_fill(&w.white, 1.0);
    if (rc == G_OK)
        rc = gcolor_fill(&w.index15, 1.5);
    const GColor *index[2] = {&w.white, &w.index15}; /* white is the relative index 1 too */
    GVec3 g = sp->geometric_normal;
    for (int i = 0; i < DIAGONAL_PAIRS && rc == G_OK; i++) {
        int out_behind = i % 8 >= 6; /* as the lambertian check: one or both behind the normal in 3 of 8 */
        GVec3 out = sphere_direction(&seed, g, out_behind);
        rc = gmat_random_light(ctx->model, &seed, &w.light); /* coloured: what moves light between samples shows */
        GVec3 in = pair_in(ctx, sp, &seed, out, NULL, i % 4 == 0, i % 8 == 5 || i % 8 == 7);
        if (rc == G_OK)
            rc = diagonal_pair(ctx, sp, in, out, NULL, &w, DIAG_REFLECTION, calls);
        for (int r = 0; r < 2 && rc == G_OK; r++) { /* across the surface, from out's side one pair in eight */
            in = pair_in(ctx, sp, &seed, out, index[r], i % 4 == 0, i % 8 == 3 ? out_behind : !out_behind);
            rc = diagonal_pair(ctx, sp, in, out, index[r], &w, DIAG_REFRACTION_1 + r, calls);
        }
    }
    gscratch_release(ctx->scratch, mark);
    double worst = 0.0;
    for (int k = 0; k < DIAG_KINDS; k++)
        worst = fmax(worst, w.big[k] > 0.0 ? w.diff[k] / w.big[k] : w.diff[k]);
    return rc != G_OK || !isfinite(worst) ? INFINITY : worst;
}

void gmat_check_diagonal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker)
{
    if (!gmaterial_diagonal(ctx->material)) {
        report(checker, "diagonal", 0.0, TOL_DIAGONAL,
               "(GMAT_DIAGONAL not set: reflection and refraction are asked with each light)");
        return;
    }
    report_over_places(ctx, places, nplaces, diagonal_at, 0, report, checker, "diagonal", TOL_DIAGONAL,
                       "(GMAT_DIAGONAL set: |pass-on of a light - pass-on of white * light| / max, reflection and "
                       "refraction at indices 1 and 1.5, %d calls)");
}

/* How many calls of the class's own reflection_dir and refraction_dir slots at sp did not say 0, over the finite
 * check's views (from above and from below the surface) and the relative indices 1.5 and 1 / 1.5. */
static double ideal_rays_at(GmatContext *ctx, GSurfPoint *sp, int below, int *calls)
{
    const GMaterial *m = ctx->material;
    double valid = 0.0, sign = below ? 1.0 : -1.0; /* the view travels towards the surface */
    for (int t = 0; t < 90; t += 15)
        for (int ph = 0; ph < 360; ph += 90) {
            GVec3 view = gmat_direction(t, ph), dir;
            view.z *= sign;
            if (m->cls->reflection_dir) {
                valid += m->cls->reflection_dir(m, sp, view, &dir) != 0;
                (*calls)++;
            }
            for (int k = 0; k < 2 && m->cls->refraction_dir; k++) {
                GScratchMark mark = gscratch_mark(ctx->scratch);
                GColor ri;
                int rc = gcolor_scratch(&ri, ctx->model, ctx->scratch);
                if (rc == G_OK)
                    rc = gcolor_fill(&ri, k ? 1.0 / 1.5 : 1.5);
                valid += rc != G_OK || m->cls->refraction_dir(m, sp, view, &ri, &dir) != 0;
                (*calls)++;
                gscratch_release(ctx->scratch, mark);
            }
        }
    return valid;
}

void gmat_check_no_ideal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker)
{
    const GMaterial *m = ctx->material;
    int flagged = (m->flags & GMAT_NO_IDEAL) != 0;
    if (!flagged || (!m->cls->reflection_dir && !m->cls->refraction_dir)) {
        report(checker, "no-ideal", 0.0, 0.0,
               !flagged ? "(GMAT_NO_IDEAL not set: the direction slots are called)"
                        : "(GMAT_NO_IDEAL set, no direction slots: not valid, the default)");
        return;
    }
    report_over_places(ctx, places, nplaces, ideal_rays_at, 1, report, checker, "no-ideal", 0.0,
                       "(GMAT_NO_IDEAL set: calls of the class's own reflection_dir and refraction_dir that did not "
                       "say 0, of %d)");
}
