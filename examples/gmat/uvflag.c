/* uvflag.c - the no-uv check of `gmat check` (material.h's GMAT_NO_UV): a material with the bit says that none of
 * its methods reads the surface's parametrisation (u, v, the tangents, the (u, v) footprint), so a renderer leaves
 * those fields zero. The check evaluates the material (through the dispatch, as a renderer does) at every place of
 * the finite check, above and below the surface, once with the parametrisation set (the place's (u, v), tangents, a
 * footprint ellipse) and once with it zero; reflection, refraction, emission, diffuse, ambient, the normal and the
 * opacity must agree exactly. */
#include "gmat.h"

#include <math.h>
#include <stdio.h>

/* The point of the finite check at the current place with its parametrisation set (a full renderer's) or zero. */
static void point_with(GmatContext *ctx, GSurfPoint *sp, int below, int with_uv)
{
    gmat_surface_point(ctx, sp, below);
    if (with_uv) {
        sp->object_dpdu = gvec3(0.5, 0.0, 0.25);
        sp->object_dpdv = gvec3(0.0, 0.75, 0.0);
        sp->uv_footprint = 0.02;
        sp->uv_axis1[0] = 0.02;
        sp->uv_axis1[1] = 0.01;
        sp->uv_axis2[0] = -0.005;
        sp->uv_axis2[1] = 0.01;
        return;
    }
    sp->u = sp->v = 0.0;
    sp->dpdu = sp->dpdv = sp->object_dpdu = sp->object_dpdv = gvec3(0, 0, 0);
    sp->uv_footprint = 0.0;
    sp->uv_axis1[0] = sp->uv_axis1[1] = sp->uv_axis2[0] = sp->uv_axis2[1] = 0.0;
}

/* The largest difference of two colours' samples relative to max(1, |a|, |b|): 0 for equal NaNs, infinite for a
 * NaN against a number. */
static double colour_gap(const GColor *a, const GColor *b)
{
    int n = a->kind == GCOLOR_MATRIX || b->kind == GCOLOR_MATRIX ? a->model->capacity : a->model->nvalues;
    double worst = a->kind == b->kind ? 0.0 : INFINITY;
    for (int j = 0; j < n && j < a->capacity && j < b->capacity; j++) {
        double x = a->v[j], y = b->v[j];
        if (isnan(x) || isnan(y)) {
            worst = isnan(x) && isnan(y) ? worst : INFINITY;
            continue;
        }
        worst = fmax(worst, fabs(x - y) / fmax(1.0, fmax(fabs(x), fabs(y))));
    }
    return worst;
}

/* One colour method at the two points, by index: 0 reflection, 1 refraction, 2 emission, 3 diffuse, 4 ambient. */
static int colour_method(GmatContext *ctx, int method, GSurfPoint *sp, GVec3 in, GVec3 out, GColor *c)
{
    const GMaterial *m = ctx->material;
    const GColor *white = &ctx->white;
    switch (method) {
    case 0: return gmaterial_reflection(m, sp, in, white, out, c);
    case 1: {
        GColor ri;
        int rc = gcolor_scratch(&ri, ctx->model, ctx->scratch);
        if (rc == G_OK)
            rc = gmat_relative_index(sp, &ri);
        return rc == G_OK ? gmaterial_refraction(m, sp, in, white, &ri, out, c) : rc;
    }
    case 2: return gmaterial_emission(m, sp, out, c);
    case 3: return gmaterial_diffuse(m, sp, c);
    default: return gmaterial_ambient(m, sp, white, c);
    }
}

/* The largest gap between the point with and without its parametrisation over every method and direction pair at
 * the current place and side (a call that fails on one side only: infinite). */
static double gap_at(GmatContext *ctx, int below, int *calls)
{
    double worst = 0.0, sign = below ? -1.0 : 1.0;
    for (int method = 0; method < 5; method++)
        for (int t = 0; t < 90; t += 30)
            for (int ph = 0; ph < 360; ph += 120) {
                GVec3 in = gmat_direction(t, ph), out = gmat_direction(75 - t, ph + 45);
                in.z *= sign;
                out.z *= method == 1 ? -sign : sign; /* refraction passes light to the other side */
                GScratchMark mark = gscratch_mark(ctx->scratch);
                GSurfPoint a, z;
                point_with(ctx, &a, below, 1);
                point_with(ctx, &z, below, 0);
                GColor ca, cz;
                int ra = gcolor_scratch(&ca, ctx->model, ctx->scratch);
                int rz = gcolor_scratch(&cz, ctx->model, ctx->scratch);
                if (ra == G_OK && rz == G_OK) {
                    ra = colour_method(ctx, method, &a, in, out, &ca);
                    rz = colour_method(ctx, method, &z, in, out, &cz);
                }
                worst = fmax(worst, ra != rz ? INFINITY : ra == G_OK ? colour_gap(&ca, &cz) : 0.0);
                *calls += 2;
                gscratch_release(ctx->scratch, mark);
            }
    GSurfPoint a, z;
    point_with(ctx, &a, below, 1);
    point_with(ctx, &z, below, 0);
    GVec3 na = gsurfpoint_normal(&a), nz = gsurfpoint_normal(&z);
    double d = gvec3_length(gvec3_sub(na, nz));
    worst = fmax(worst, isnan(d) ? INFINITY : d);
    worst = fmax(worst, gmaterial_opaque(ctx->material, &a) != gmaterial_opaque(ctx->material, &z) ? INFINITY : 0.0);
    *calls += 4;
    return worst;
}

void gmat_check_no_uv(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker)
{
    if (!(ctx->material->flags & GMAT_NO_UV)) {
        report(checker, "no-uv", 0.0, 0.0, "(GMAT_NO_UV not set: the renderer fills the parametrisation)");
        return;
    }
    double worst = 0.0;
    int calls = 0;
    for (int p = 0; p < nplaces; p++) {
        ctx->place = &places[p];
        for (int below = 0; below < 2; below++)
            worst = fmax(worst, gap_at(ctx, below, &calls));
    }
    ctx->place = NULL;
    char detail[200];
    snprintf(detail, sizeof detail,
             "(GMAT_NO_UV set: largest relative gap between the point with its (u, v) and tangents and without, "
             "%d calls)", calls);
    report(checker, "no-uv", worst, 0.0, detail);
}
