/* albedo.c - the albedo property of `gmat check` (check.c describes it): light leaving a material, reflected and
 * transmitted, per unit of light arriving, over a sweep of incidences at every place, measured by quadrature
 * (measure.c) and, where the grid exceeds the tolerance, by the material's own sample(). */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define TOL_ALBEDO 0.01
#define ALBEDO_DRAWS 16384 /* draws of sample() for the albedo where the grid exceeds the tolerance */
#define ALBEDO_SE 4.0      /* standard errors of the sampled albedo allowed above the tolerance */

static const double incidences[] = {0, 20, 40, 60, 75, 85};
#define NINC ((int)(sizeof incidences / sizeof incidences[0]))

typedef struct AlbedoCheck {
    GmatContext *ctx;
    const GmatPlace *places;
    int nplaces;
    int samples; /* albedo grid */
    GColor a, b; /* work colours */
    GmatReportFn report;
    void *checker;
} AlbedoCheck;

/* 1 when the result holds light outside sample s (beyond rounding). */
static int leaves_sample(const GColor *result, int nvalues, int s)
{
    for (int j = 0; j < nvalues; j++)
        if (j != s && fabs(result->v[j]) > 1e-7 * fabs(result->v[s]) + 1e-12)
            return 1;
    return 0;
}

/* Two directions 20 degrees off the bisector of the place's shading and geometric normals: above both, so a material
 * reflects there however far a bump tilts its normal (fixed pairs may all lie behind a steep facet: black). */
static void bisector_pair(GmatContext *ctx, GVec3 pair[2])
{
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, 0);
    GVec3 h = gvec3_normalize(gvec3_add(gsurfpoint_normal(&sp), sp.geometric_normal)), t, b;
    goptics_frame(h, &t, &b);
    double c = cos(20.0 * M_PI / 180.0), s = sin(20.0 * M_PI / 180.0);
    pair[0] = gvec3_add(gvec3_scale(h, c), gvec3_scale(t, s));
    pair[1] = gvec3_add(gvec3_scale(h, c), gvec3_scale(b, -s));
}

/* 1 when light in one sample leaves in another at the place ctx->place (checked at a few direction pairs, one about
 * the shading normal, and along the specular ray, each sample alone). */
static int shifts_samples(AlbedoCheck *k)
{
    GmatContext *ctx = k->ctx;
    const GColorModel *m = ctx->model;
    if (m->nvalues < 2)
        return 0;
    GVec3 pairs[4][2] = {{gmat_direction(10, 0), gmat_direction(30, 180)},
                         {gmat_direction(45, 30), gmat_direction(60, 120)},
                         {gmat_direction(70, 200), gmat_direction(20, 10)}};
    bisector_pair(ctx, pairs[3]);
    int shifted = 0;
    for (int s = 0; s < m->nvalues && !shifted; s++) {
        gcolor_black(&k->a);
        k->a.v[s] = 1.0f;
        ctx->light = &k->a;
        for (int p = 0; p < 4 && !shifted; p++) {
            GVec3 dir;
            if (gmat_reflect(ctx, pairs[p][0], pairs[p][1]) == G_OK)
                shifted = leaves_sample(&ctx->result, m->nvalues, s);
            if (!shifted && gmat_specular(ctx, pairs[p][0], &dir) == 1)
                shifted = leaves_sample(&ctx->result, m->nvalues, s);
        }
    }
    ctx->light = NULL;
    return shifted;
}

/* Adds the ideal rays' light for light from in (the mirror ray, and the refracted one unless opaque) to total. */
static int add_ideal(AlbedoCheck *k, GVec3 in, int opaque, GColor *total)
{
    GVec3 dir;
    int rc = gmat_specular(k->ctx, in, &dir);
    if (rc == 1)
        rc = gcolor_add(total, total, &k->ctx->result);
    if (rc >= 0 && !opaque && (rc = gmat_ideal_refraction(k->ctx, in, &dir)) == 1)
        rc = gcolor_add(total, total, &k->ctx->result);
    return rc < 0 ? rc : G_OK;
}

/* Light leaving (reflected and transmitted) for the light ctx->light from in, into total, per unit of the light
 * the shading normal receives. The integrals are divided by in's geometric cosine (measure.c): they are scaled
 * to the shading one. An ideal ray is not: the material returns its reflectance times the light, the radiance
 * along the ray per radiance arriving (material.h), which is already the share of the light the shading normal
 * receives (about a tilted facet a mirrored beam keeps its cross-section); scaled, a bumped mirror of
 * reflectance 0.9 reflected 0.9 cos_g / cos_s, up to 5.5 times the light. */
static int leaving(AlbedoCheck *k, GVec3 in, GColor *total)
{
    GSurfPoint sp;
    gmat_surface_point(k->ctx, &sp, 0);
    int opaque = gmaterial_opaque(k->ctx->material, &sp); /* then refraction is black: skip its integral */
    double cos_s = gvec3_dot(gsurfpoint_normal(&sp), in);
    gcolor_black(total);
    int rc = gmat_integrate(k->ctx, in, k->samples, 0, total);
    if (rc == G_OK && !opaque)
        rc = gmat_integrate(k->ctx, in, k->samples, 1, total);
    if (rc == G_OK)
        rc = gcolor_scale(total, total, cos_s > 0.01 ? in.z / cos_s : 0.0);
    return rc == G_OK ? add_ideal(k, in, opaque, total) : rc;
}

/* Energy of light c over the energy of the white light: sums of their nm spectra (read as lights). */
static double energy_ratio(AlbedoCheck *k, const GColor *c)
{
    GSpectrumNM a, w;
    if (gcolor_to_nm(c, GCOLOR_LIGHT, &a) != G_OK || gcolor_to_nm(&k->ctx->white, GCOLOR_LIGHT, &w) != G_OK)
        return INFINITY;
    double sa = 0.0, sw = 0.0;
    for (int i = 0; i < GNM_COUNT; i++)
        sa += a.v[i], sw += w.v[i];
    return sw > 0.0 ? sa / sw : INFINITY;
}

/* The albedo from in by sample() (gmat_albedo_sampled), each sample's mean less ALBEDO_SE standard errors, into
 * ratio[0 .. nr) when every one is within 1 + TOL_ALBEDO: 1 then, else 0 (ratio unchanged). */
static int sampled_ratios(AlbedoCheck *k, GVec3 in, int nr, double ratio[1024])
{
    double mean[1024], se[1024], bound[1024];
    if (nr > 1024 || k->ctx->model->nvalues != nr || gmat_albedo_sampled(k->ctx, in, ALBEDO_DRAWS, mean, se) != G_OK)
        return 0;
    for (int j = 0; j < nr; j++) {
        bound[j] = mean[j] - ALBEDO_SE * se[j];
        if (!(bound[j] <= 1.0 + TOL_ALBEDO))
            return 0;
    }
    memcpy(ratio, bound, (size_t)nr * sizeof *ratio);
    return 1;
}

/* The ratios of light leaving to light arriving from in: with shift, the power leaving in every sample per unit
 * arriving in sample s (one ratio); else white light's, sample by sample, or, above 1 in a band of a model without
 * matrices, a fold of re-radiation held to energy conservation over all bands (material_params.h; *folded set).
 * Their number, or -1 when the material failed. */
static int albedo_ratios(AlbedoCheck *k, GVec3 in, int shift, int s, double ratio[1024], int *folded, int *sampled)
{
    GmatContext *ctx = k->ctx;
    const GColorModel *m = ctx->model;
    int nr = 0;
    if (shift) {
        gcolor_black(&k->a);
        k->a.v[s] = 1.0f;
        ctx->light = &k->a;
        if (leaving(k, in, &k->b) != G_OK)
            return -1;
        double sum = 0.0;
        for (int j = 0; j < m->nvalues; j++)
            sum += k->b.v[j];
        ratio[nr++] = sum;
        return nr;
    }
    ctx->light = NULL; /* white light, not the one-sample light a re-radiating place before left */
    if (leaving(k, in, &k->b) != G_OK)
        return -1;
    double most = 0.0;
    for (int j = 0; j < m->nvalues && j < 1024; j++) {
        ratio[nr++] = ctx->white.v[j] > 0.0f ? k->b.v[j] / ctx->white.v[j] : 0.0;
        most = fmax(most, ratio[nr - 1]);
    }
    if (most > 1.0 + TOL_ALBEDO && sampled_ratios(k, in, nr, ratio)) {
        (*sampled)++;
        return nr;
    }
    if (most > 1.0 + TOL_ALBEDO && !m->cls->from_reradiation) {
        ratio[0] = energy_ratio(k, &k->b);
        nr = 1;
        *folded = 1;
    }
    return nr;
}

static void check_albedo(AlbedoCheck *k)
{
    GmatContext *ctx = k->ctx;
    const GColorModel *m = ctx->model;
    /* where light moves between samples (a texture tree may re-radiate at some places only): one light per sample
     * costs nvalues times more, so only the first such place is measured so, on half the grid; the places where
     * light stays in its sample are measured with white light */
    int shift_at = -1, shifts[GMAT_MAX_PLACES], nshift = 0;
    for (int p = 0; p < k->nplaces; p++) {
        ctx->place = &k->places[p];
        shifts[p] = shifts_samples(k);
        nshift += shifts[p];
        if (shifts[p] && shift_at < 0)
            shift_at = p;
    }
    double worst = 0.0, at_theta = 0.0;
    int at_sample = 0, at_place = 0, failed = 0, folded = 0, sampled = 0, measured = 0;
    int samples = k->samples, half = samples / 2 > 8 ? samples / 2 : 8;
    for (int p = 0; p < k->nplaces && !failed; p++) {
        if (shifts[p] && p != shift_at)
            continue;
        int shift = shifts[p];
        k->samples = shift ? half : samples;
        ctx->place = &k->places[p];
        for (int t = 0; t < NINC && !failed; t++) {
            GVec3 in = gmat_direction(incidences[t], 30.0);
            for (int s = 0; s < (shift ? m->nvalues : 1) && !failed; s++) {
                double ratio[1024];
                int nr = albedo_ratios(k, in, shift, s, ratio, &folded, &sampled);
                failed = nr < 0;
                measured++;
                for (int j = 0; j < nr; j++)
                    if (!(ratio[j] <= worst)) {
                        worst = isfinite(ratio[j]) ? ratio[j] : INFINITY;
                        at_theta = incidences[t], at_sample = shift ? s : j, at_place = p;
                    }
            }
        }
    }
    ctx->light = NULL;
    ctx->place = NULL;
    k->samples = samples;
    int used = shifts[at_place] ? half : samples;
    char detail[640], moves[120] = "", by_sample[200] = ""; /* room for every part at its longest */
    if (shift_at >= 0)
        snprintf(moves, sizeof moves, ", light moves between samples%s: one light per sample at place %d",
                 nshift < k->nplaces ? " at some places" : "", shift_at);
    if (sampled)
        snprintf(by_sample, sizeof by_sample, ", %d of %d measurements above the grid's tolerance by sample(): "
                 "%d draws, mean - %g standard errors", sampled, measured, ALBEDO_DRAWS, ALBEDO_SE);
    if (failed)
        snprintf(detail, sizeof detail, "(the material failed to evaluate)");
    else
        snprintf(detail, sizeof detail, "(largest reflected+transmitted/incident, at theta_in %g, sample %d, place %d;"
                 " %d x %d grid%s%s%s)", at_theta, at_sample, at_place, used, 2 * used, by_sample, moves,
                 folded ? ", above 1 in a band: a fold of re-radiation, energy over all samples" : "");
    k->report(k->checker, "albedo", failed ? INFINITY : worst, 1.0 + TOL_ALBEDO, detail);
}

void gmat_check_albedo(GmatContext *ctx, const GmatPlace *places, int nplaces, int samples, GmatReportFn report,
                       void *checker)
{
    AlbedoCheck k = {.ctx = ctx, .places = places, .nplaces = nplaces < GMAT_MAX_PLACES ? nplaces : GMAT_MAX_PLACES,
                     .samples = samples, .report = report, .checker = checker};
    if (gcolor_alloc(&k.a, ctx->model) || gcolor_alloc(&k.b, ctx->model)) {
        report(checker, "albedo", INFINITY, 1.0 + TOL_ALBEDO, "(out of memory)");
        gcolor_free(&k.a);
        return;
    }
    check_albedo(&k);
    gcolor_free(&k.a);
    gcolor_free(&k.b);
}
