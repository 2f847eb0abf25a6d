/* check.c - `gmat check FILE MATERIAL`: conformance checks any material or texture-tree author can run, built-in
 * or plug-in. Each property is measured and printed on one line: its name, the worst figure, the tolerance and
 * PASS or FAIL; the exit status is 1 when one fails.
 *
 * Every property is measured at several places on the surface (u, v, the point and the surface index vary, so
 * texture generators change), with the geometry of measure.c: the xy plane, normal +z, seen from outside
 * (light from vacuum) or, for transmission, from inside.
 *   albedo       reflection integrated over the upper hemisphere plus the ideal reflection ray, plus refraction
 *                over the lower hemisphere plus the ideal refraction ray (measure.c), for light from each
 *                incidence of a sweep, per sample of the colour model: reflected / incident <= 1 + TOL_ALBEDO
 *                (the quadrature's error on a sharp lobe), relative to the irradiance about the shading
 *                normal (the same as the geometric one unless a bump node tilts it: against the geometric
 *                normal a bumped Lambertian surface reflects up to 1.48 times the light at 85 degrees, the
 *                known energy gain of shading normals at grazing incidence); an ideal ray's colour, a reflectance
 *                about the shading normal already, is added as it is. Where the grid exceeds 1 + TOL_ALBEDO, a
 *                narrow lobe (roughness 0.01) between its nodes may be the cause (a midpoint rule on a peak
 *                overestimates it): the albedo is then estimated again by the material's own sample() from the
 *                same direction (reciprocity, its own property, makes it the same albedo), the mean of
 *                ALBEDO_DRAWS weights, unbiased when sample() agrees with pdf() (the chi2, pdf integral and
 *                weight properties), and judged by its mean less ALBEDO_SE standard errors; it replaces the
 *                grid's figures there when that passes, else the grid's figures stand (with white light only:
 *                where light moves between samples, the grid alone). A material that moves light between
 *                samples (fluorescence) is measured with a one-sample light per sample instead: the power
 *                leaving, summed over all samples, per unit of power arriving in that sample. Whether it does is
 *                asked at each place (a texture tree may re-radiate at some places only); the first place where
 *                it does is measured so (on half the grid: it costs a light per sample), the places where light
 *                keeps its sample with white light, and further re-radiating places are left out.
 *   reciprocity  f_r(in, out) = reflection(in, out) / cos(theta_in) against f_r(out, in) over random pairs,
 *                cosines about the shading normal: max difference / max value <= TOL_RECIPROCITY.
 *   finite       every colour method (reflection, refraction, emission, ambient, absorption, diffuse,
 *                refraction index) over a sweep of directions returns G_OK and a value gcolor_is_nonnegative
 *                accepts.
 *   snell        for a material that is not opaque: refraction_dir from outside and from inside follows
 *                n1 sin(theta1) = n2 sin(theta2) in the plane of incidence (n1 / n2 the scalar relative index
 *                it is handed, as a renderer uses it; vacuum outside), returns 0 past the critical angle, angles
 *                taken about the shading normal (the facet a bump tilts refracts as a flat one would);
 *                for an opaque one, refraction_dir returns 0.
 *   defaults     for every method the class leaves NULL, the value material.h documents.
 *   no-emission  for a material with GMAT_NO_EMISSION: its class's own emission slot is black (flags.c).
 *   opaque-flag  for a material with GMAT_OPAQUE: its class's own opaque slot says 1 (flags.c).
 *   geometric-normal  for a material with GMAT_GEOMETRIC_NORMAL: its class's own normal slot gives the geometric
 *                normal (flags.c).
 *   lambertian   for a material with GMAT_LAMBERTIAN: its class's own reflection is its diffuse colour times the
 *                light times gmaterial_cos_in / pi over random pairs and lights, and it is not delta (flags.c).
 *   diagonal     for a material with GMAT_DIAGONAL: its class's own reflection and refraction of a random light
 *                are what they pass on of white times the light, over random and ideal pairs (flags.c).
 *   no-uv        for a material with GMAT_NO_UV: the same colours, normal and opacity with the surface's (u, v)
 *                and tangents as without them (uvflag.c).
 *   no-ideal     for a material with GMAT_NO_IDEAL: its class's own reflection_dir and refraction_dir say 0
 *                (flags.c).
 *   no-rel-index for a material with GMAT_NO_REL_INDEX: its class's own slots give the same results, bit for bit,
 *                with the relative indices 1.5 and 1 / 1.5 (relindex.c).
 *   constant-index  for a material with GMAT_CONSTANT_INDEX: its class's own refraction_index gives the same
 *                colour, bit for bit, at the places and at points drawn around them, both sides, as for sp NULL
 *                (constindex.c).
 *   clear        for a material with GMAT_CLEAR: its class's own absorption gives the light back, bit for bit, for
 *                lengths 0 to 1e3 and lights black to bright, at the places and points drawn around them, both
 *                sides, and for sp NULL (clear.c).
 *   chi2, pdf integral, weight: the sampling slots (sampling.c). */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL_RECIPROCITY 1e-3
#define TOL_SNELL 1e-4
#define SNELL_MIN_COS 0.01 /* a view closer to a tilted facet's plane, or behind it, is not refracted there */
#define TOL_DEFAULT 1e-5
#define NPLACES 4
#define NPAIRS 200

typedef struct Checker {
    GmatContext *ctx;
    GmatPlace places[NPLACES];
    int samples; /* albedo grid */
    int failures;
    GColor a, b, c; /* work colours */
} Checker;

static void report(Checker *k, const char *property, double worst, double tol, const char *detail)
{
    int pass = worst <= tol; /* NaN fails */
    if (!pass)
        k->failures++;
    printf("%-12s worst %-11.4g tolerance %-8.4g %s  %s\n", property, worst, tol, pass ? "PASS" : "FAIL", detail);
}

static void report_fn(void *k, const char *property, double worst, double tol, const char *detail)
{
    report(k, property, worst, tol, detail);
}

/* A direction in the upper hemisphere at most 85 degrees from the normal. */
static GVec3 random_direction(unsigned long long *s)
{
    double ct = cos(85.0 * M_PI / 180.0) + (1.0 - cos(85.0 * M_PI / 180.0)) * gmat_uniform(s);
    double p = 2.0 * M_PI * gmat_uniform(s);
    double st = sqrt(fmax(0.0, 1.0 - ct * ct));
    return gvec3(st * cos(p), st * sin(p), ct);
}

/* ---- reciprocity ---- */

static int f_r(Checker *k, GVec3 in, GVec3 out, GColor *f, double *cos_in)
{
    GmatContext *ctx = k->ctx;
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, 0);
    *cos_in = gvec3_dot(gsurfpoint_normal(&sp), in);
    int rc = gmat_reflect(ctx, in, out);
    if (rc == G_OK && *cos_in > 0.05)
        rc = gcolor_scale(f, &ctx->result, 1.0 / *cos_in);
    return rc;
}

static void check_reciprocity(Checker *k)
{
    unsigned long long seed = 12345;
    double worst = 0.0, wi = 0, wo = 0;
    int pairs = 0, failed = 0;
    for (int p = 0; p < NPLACES && !failed; p++) {
        k->ctx->place = &k->places[p];
        for (int i = 0; i < NPAIRS / NPLACES && !failed; i++) {
            GVec3 in = random_direction(&seed), out = random_direction(&seed);
            double ci, co;
            if (f_r(k, in, out, &k->a, &ci) != G_OK || f_r(k, out, in, &k->b, &co) != G_OK) {
                failed = 1;
                break;
            }
            if (ci <= 0.05 || co <= 0.05) /* grazing about a bumped shading normal: f_r is not defined */
                continue;
            double big = 0.0, d = 0.0;
            for (int j = 0; j < k->ctx->model->nvalues; j++) {
                big = fmax(big, fmax(fabs(k->a.v[j]), fabs(k->b.v[j])));
                d = fmax(d, fabs((double)k->a.v[j] - k->b.v[j]));
            }
            double e = big > 0.0 ? d / big : d;
            if (!isfinite(e))
                e = INFINITY;
            if (e > worst)
                worst = e, wi = acos(fmin(1.0, in.z)) * 180 / M_PI, wo = acos(fmin(1.0, out.z)) * 180 / M_PI;
            pairs++;
        }
    }
    k->ctx->place = NULL;
    char detail[160];
    snprintf(detail, sizeof detail, "(|f(in,out) - f(out,in)| / max, %d random pairs; worst at theta %.1f / %.1f)",
             pairs, wi, wo);
    report(k, "reciprocity", failed ? INFINITY : worst, TOL_RECIPROCITY, failed ? "(the material failed)" : detail);
}

/* ---- finite and non-negative ---- */

static void check_finite(Checker *k)
{
    GmatContext *ctx = k->ctx;
    const GMaterial *m = ctx->material;
    int bad = 0, total = 0;
    const char *first = NULL;
#define COUNT(call, what)                                                                                     \
    do {                                                                                                      \
        total++;                                                                                              \
        int rc_ = (call);                                                                                     \
        if (rc_ != G_OK || !gcolor_is_nonnegative(&k->c)) {                                                   \
            bad++;                                                                                            \
            if (!first)                                                                                       \
                first = what;                                                                                 \
        }                                                                                                     \
    } while (0)
    for (int p = 0; p < NPLACES; p++) {
        ctx->place = &k->places[p];
        for (int below = 0; below < 2; below++) {
            GSurfPoint sp;
            gmat_surface_point(ctx, &sp, below);
            GScratchMark mark = gscratch_mark(ctx->scratch);
            COUNT(gmaterial_refraction_index(m, &sp, &k->c), "refraction_index");
            COUNT(gmaterial_diffuse(m, &sp, &k->c), "diffuse");
            COUNT(gmaterial_ambient(m, &sp, &ctx->white, &k->c), "ambient");
            COUNT(gmaterial_absorption(m, &sp, &ctx->white, 1.0, &k->c), "absorption");
            double sign = below ? -1.0 : 1.0;
            for (int t = 0; t < 90; t += 15)
                for (int ph = 0; ph < 360; ph += 90) {
                    GVec3 a = gmat_direction(t, ph), b = gmat_direction(90 - t * 0.9, ph + 135);
                    a.z *= sign;
                    b.z *= sign;
                    COUNT(gmaterial_emission(m, &sp, a, &k->c), "emission");
                    COUNT(gmaterial_reflection(m, &sp, a, &ctx->white, b, &k->c), "reflection");
                    GVec3 th = gvec3(-b.x, -b.y, -b.z); /* from the other side */
                    COUNT(gmaterial_refraction(m, &sp, th, &ctx->white, NULL, a, &k->c), "refraction");
                }
            gscratch_release(ctx->scratch, mark);
        }
    }
#undef COUNT
    ctx->place = NULL;
    char detail[160];
    snprintf(detail, sizeof detail, "(%d of %d evaluations failed, NaN, infinite or negative%s%s)", bad, total,
             first ? "; first: " : "", first ? first : "");
    report(k, "finite", bad, 0, detail);
}

/* ---- Snell's law and total internal reflection ---- */

static double index_of(Checker *k, GSurfPoint *sp, const GMaterial *m)
{
    GScratchMark mark = gscratch_mark(k->ctx->scratch);
    GColor c;
    double n = NAN;
    if (gcolor_scratch(&c, k->ctx->model, k->ctx->scratch) == G_OK && gmaterial_refraction_index(m, sp, &c) == G_OK)
        n = gcolor_brightness(&c);
    gscratch_release(k->ctx->scratch, mark);
    return n;
}

/* What the snell property saw. */
typedef struct SnellTally {
    double worst;  /* largest tangential error */
    int wrong;     /* wrong validity: TIR where there is none, none where there is, or an error */
    int tir;       /* TIR cases seen */
    int tested;    /* directions refracted and measured */
    int skipped;   /* directions at the back of the facet (a tilted shading normal) */
} SnellTally;

/* The refraction direction the material gives for view at sp, with the relative index n(from) / n(to) there:
 * 1 valid, 0 TIR, negative on error. */
static int refracted(GmatContext *ctx, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GScratchMark mark = gscratch_mark(ctx->scratch);
    GColor ri;
    int valid = gcolor_scratch(&ri, ctx->model, ctx->scratch);
    if (valid == G_OK)
        valid = gmat_relative_index(sp, &ri);
    if (valid == G_OK)
        valid = gmaterial_refraction_dir(ctx->material, sp, view, &ri, dir);
    gscratch_release(ctx->scratch, mark);
    return valid;
}

/* One side: from outside (below = 0, eta = n(vacuum) / n) or inside (below = 1, eta = n / n(vacuum)), eta as the
 * material reads it from the relative index it is handed (gmat_relative_eta). Snell's law holds at the facet
 * the material refracts at: angles and tangential parts are taken about the point's shading normal (the geometric
 * one unless a bump node tilts it; against the geometric normal a bumped glass "broke" the law and its TIR).
 * Views from the geometric side that reach the back of a tilted facet (cosine below SNELL_MIN_COS) have no
 * refraction to check and are skipped; the critical angle's neighbourhood too. */
static void snell_side(Checker *k, int below, SnellTally *t)
{
    GmatContext *ctx = k->ctx;
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, below);
    GVec3 ns = gsurfpoint_normal(&sp); /* faces the incident side */
    double eta = gmat_relative_eta(&sp);
    if (!(eta > 0.0) || !isfinite(eta)) {
        t->wrong++;
        return;
    }
    double ncrit = eta > 1.0 ? asin(1.0 / eta) * 180.0 / M_PI : 90.0;
    for (double theta = 0.0; theta < 89.5; theta += 2.5) {
        GVec3 d = gmat_direction(theta, 40.0);
        GVec3 view = below ? gvec3(-d.x, -d.y, d.z) : gvec3_neg(d); /* travels towards the surface */
        double cos_i = -gvec3_dot(view, ns);
        if (cos_i < SNELL_MIN_COS) {
            t->skipped++;
            continue;
        }
        double s_in = sqrt(fmax(0.0, 1.0 - cos_i * cos_i));
        if (fabs(asin(fmin(1.0, s_in)) * 180.0 / M_PI - ncrit) < 0.5)
            continue;
        GVec3 dir;
        int valid = refracted(ctx, &sp, view, &dir);
        if (valid < 0 || valid != (eta * s_in < 1.0)) {
            t->wrong++;
            continue;
        }
        if (!valid) {
            t->tir++;
            continue;
        }
        t->tested++;
        GVec3 u = gvec3_normalize(dir);
        /* past the facet, in the plane of incidence, with the tangential part eta times the view's */
        GVec3 ut = gvec3_sub(u, gvec3_scale(ns, gvec3_dot(u, ns)));
        GVec3 vt = gvec3_sub(view, gvec3_scale(ns, -cos_i));
        double e = gvec3_length(gvec3_sub(ut, gvec3_scale(vt, eta)));
        if (!(gvec3_dot(u, ns) < 0.0) || !isfinite(e))
            e = INFINITY;
        t->worst = fmax(t->worst, e);
    }
}

static void check_snell(Checker *k)
{
    GmatContext *ctx = k->ctx;
    SnellTally t = {0};
    int clear = 0, opaque_with_dir = 0, rough = 0;
    double n_seen = 0.0;
    for (int p = 0; p < NPLACES; p++) {
        ctx->place = &k->places[p];
        GSurfPoint sp;
        gmat_surface_point(ctx, &sp, 0);
        if (gmaterial_opaque(ctx->material, &sp)) {
            GVec3 dir;
            if (gmaterial_refraction_dir(ctx->material, &sp, gvec3(0.3, 0, -1), NULL, &dir) != 0)
                opaque_with_dir++;
            continue;
        }
        /* a rough interface (not delta) may have no ideal refraction at all: nothing to check there */
        GVec3 probe;
        if (!gmaterial_is_delta(ctx->material, &sp) &&
            gmaterial_refraction_dir(ctx->material, &sp, gvec3(0.3, 0, -1), NULL, &probe) == 0 &&
            gmaterial_refraction_dir(ctx->material, &sp, gvec3(0, 0, -1), NULL, &probe) == 0) {
            rough++;
            continue;
        }
        clear++;
        double n = index_of(k, &sp, ctx->material);
        n_seen = n;
        if (!(n > 0.0) || !isfinite(n)) {
            t.wrong++;
            continue;
        }
        snell_side(k, 0, &t);
        snell_side(k, 1, &t);
    }
    ctx->place = NULL;
    char detail[320];
    if (!clear && rough)
        snprintf(detail, sizeof detail, "(no ideal refraction at %d places: a rough interface; %d opaque places with a "
                 "direction)", rough, opaque_with_dir);
    else if (!clear)
        snprintf(detail, sizeof detail, "(opaque at every place: refraction_dir must return 0; it did not at %d)",
                 opaque_with_dir);
    else
        snprintf(detail, sizeof detail, "(tangential error of the refracted direction about the shading normal; "
                 "n = %.4f; %d directions, %d wrong validity (TIR), %d TIR cases seen, %d at the back of a tilted "
                 "facet; %d opaque places with a direction)", n_seen, t.tested, t.wrong, t.tir, t.skipped,
                 opaque_with_dir);
    /* a clear material with no direction refracted has not shown Snell's law */
    int bad = t.wrong || opaque_with_dir || (clear && !t.tested);
    report(k, "snell", bad ? INFINITY : t.worst, TOL_SNELL, detail);
}

/* ---- documented defaults of NULL slots ---- */

static double diff_colors(const GColor *a, const GColor *b)
{
    double big = 0.0, d = 0.0;
    for (int j = 0; j < a->model->nvalues; j++) {
        big = fmax(big, fmax(fabs(a->v[j]), fabs(b->v[j])));
        d = fmax(d, fabs((double)a->v[j] - b->v[j]));
    }
    return isfinite(d) ? (big > 0.0 ? d / big : d) : INFINITY;
}

/* The NULL slots checked, named once (at the first place). */
typedef struct Slots {
    int checked;
    char which[160];
} Slots;

static void note(Slots *s, int first, const char *name)
{
    if (!first)
        return;
    s->checked++;
    size_t l = strlen(s->which);
    snprintf(s->which + l, sizeof s->which - l, "%s%s", l ? ", " : "", name);
}

/* The colour slots left out at sp against their defaults (ambient = diffuse * illum, black, illum unchanged):
 * the worst difference. */
static double defaults_colours(Checker *k, GSurfPoint *sp, int first, Slots *slots)
{
    GmatContext *ctx = k->ctx;
    const GMaterial *m = ctx->material;
    const GMaterialClass *cls = m->cls;
    GVec3 in = gmat_direction(30, 10), out = gmat_direction(50, 200);
    double worst = 0.0;
    if (!cls->ambient) {
        note(slots, first, "ambient");
        if (gmaterial_diffuse(m, sp, &k->a) || gcolor_mul(&k->a, &k->a, &ctx->white) ||
            gmaterial_ambient(m, sp, &ctx->white, &k->b))
            worst = INFINITY;
        else
            worst = fmax(worst, diff_colors(&k->a, &k->b));
    }
    gcolor_black(&k->a);
    if (!cls->reflection) {
        note(slots, first, "reflection");
        worst = fmax(worst, gmaterial_reflection(m, sp, in, &ctx->white, out, &k->b) ? INFINITY
                                                                                   : diff_colors(&k->a, &k->b));
    }
    if (!cls->refraction) {
        note(slots, first, "refraction");
        worst = fmax(worst, gmaterial_refraction(m, sp, gvec3_neg(in), &ctx->white, NULL, out, &k->b)
                                ? INFINITY
                                : diff_colors(&k->a, &k->b));
    }
    if (!cls->emission) {
        note(slots, first, "emission");
        worst = fmax(worst, gmaterial_emission(m, sp, out, &k->b) ? INFINITY : diff_colors(&k->a, &k->b));
    }
    if (!cls->diffuse) {
        note(slots, first, "diffuse");
        worst = fmax(worst, gmaterial_diffuse(m, sp, &k->b) ? INFINITY : diff_colors(&k->a, &k->b));
    }
    if (!cls->absorption) {
        note(slots, first, "absorption");
        worst = fmax(worst, gmaterial_absorption(m, sp, &ctx->white, 2.0, &k->b) ? INFINITY
                                                                                : diff_colors(&ctx->white, &k->b));
    }
    return worst;
}

/* The other slots left out at sp against their defaults (index 1, no ideal directions, the geometric normal,
 * opaque, not delta): the worst difference. */
static double defaults_geometry(Checker *k, GSurfPoint *sp, int first, Slots *slots)
{
    const GMaterial *m = k->ctx->material;
    const GMaterialClass *cls = m->cls;
    GVec3 in = gmat_direction(30, 10), dir;
    double worst = 0.0;
    if (!cls->refraction_index) {
        note(slots, first, "refraction_index");
        double n = index_of(k, sp, m);
        worst = fmax(worst, isfinite(n) ? fabs(n - 1.0) : INFINITY);
    }
    if (!cls->reflection_dir) {
        note(slots, first, "reflection_dir");
        worst = fmax(worst, gmaterial_reflection_dir(m, sp, gvec3_neg(in), &dir) == 0 ? 0.0 : INFINITY);
    }
    if (!cls->refraction_dir) {
        note(slots, first, "refraction_dir");
        worst = fmax(worst, gmaterial_refraction_dir(m, sp, gvec3_neg(in), NULL, &dir) == 0 ? 0.0 : INFINITY);
    }
    if (!cls->normal) {
        note(slots, first, "normal");
        GVec3 n;
        worst = fmax(worst, gmaterial_normal(m, sp, &n) ? INFINITY : gvec3_length(gvec3_sub(n, sp->geometric_normal)));
    }
    if (!cls->opaque) {
        note(slots, first, "opaque");
        worst = fmax(worst, gmaterial_opaque(m, sp) == 1 ? 0.0 : INFINITY);
    }
    if (!cls->is_delta) {
        note(slots, first, "is_delta");
        worst = fmax(worst, gmaterial_is_delta(m, sp) == 0 ? 0.0 : INFINITY);
    }
    return worst;
}

/* Every slot a class leaves NULL must behave as material.h documents, at every place. */
static void check_defaults(Checker *k)
{
    GmatContext *ctx = k->ctx;
    Slots slots = {0, ""};
    double worst = 0.0;
    for (int p = 0; p < NPLACES; p++) {
        ctx->place = &k->places[p];
        GSurfPoint sp;
        gmat_surface_point(ctx, &sp, 0);
        worst = fmax(worst, defaults_colours(k, &sp, p == 0, &slots));
        worst = fmax(worst, defaults_geometry(k, &sp, p == 0, &slots));
    }
    ctx->place = NULL;
    char detail[240];
    snprintf(detail, sizeof detail, "(NULL slots compared with material.h's defaults: %s)",
             slots.checked ? slots.which : "none");
    report(k, "defaults", worst, TOL_DEFAULT, detail);
}

int gmat_check(GmatContext *ctx, int samples)
{
    Checker k = {.ctx = ctx, .samples = samples > 0 ? samples : 64};
    /* places: different u, v, points and surfaces, so generators take different values */
    for (int p = 0; p < NPLACES; p++) {
        double f = (p + 0.37) / NPLACES;
        k.places[p] = (GmatPlace){f, 1.0 - 0.8 * f, gvec3(2.3 * f - 0.7, 1.1 - 1.7 * f, 0.45 * p - 0.3), p};
    }
    if (gcolor_alloc(&k.a, ctx->model) || gcolor_alloc(&k.b, ctx->model) || gcolor_alloc(&k.c, ctx->model)) {
        fprintf(stderr, "gmat check: out of memory\n");
        gcolor_free(&k.a);
        gcolor_free(&k.b);
        return 1;
    }
    printf("material %s (%s), colour model %s\n", ctx->material_name, gmaterial_name(ctx->material),
           gcolormodel_name(ctx->model));
    gmat_check_albedo(ctx, k.places, NPLACES, k.samples, report_fn, &k);
    check_reciprocity(&k);
    check_finite(&k);
    check_snell(&k);
    check_defaults(&k);
    gmat_check_no_emission(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_opaque_flag(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_geometric_normal(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_lambertian(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_diagonal(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_no_uv(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_no_ideal(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_no_rel_index(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_constant_index(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_clear(ctx, k.places, NPLACES, report_fn, &k);
    gmat_check_sampling(ctx, k.places, NPLACES, 0, report_fn, &k);
    printf("%s: %s\n", ctx->material_name, k.failures ? "FAIL" : "PASS");
    gcolor_free(&k.a);
    gcolor_free(&k.b);
    gcolor_free(&k.c);
    return k.failures ? 1 : 0;
}
