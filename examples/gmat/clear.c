/* clear.c - the clear check of `gmat check` (material.h's GMAT_CLEAR): a material with the bit says that as a
 * medium it absorbs nothing, its absorption writing the light itself for every length >= 0, so a renderer may skip
 * the call. The check calls the class's own absorption slot, not the dispatch (gmaterial_absorption gives the light
 * back for the bit without asking the class: it would pass any material), for sp NULL, at each place of the
 * finite check on both sides, and at points drawn around each place (other positions, normals, tangents, (u, v),
 * surface indices, footprints and distances), with the lengths 0, 1e-3, 1 and 1e3 and four lights: black, white, a
 * random light and a random light scaled by a drawn factor up to 1e3. Every call must succeed and write the light's
 * kind and samples bit for bit, into a result filled with other bits first. Nothing to check without the bit, nor
 * for a class without the slot (the default gives the light back). */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DRAWN_POINTS 8 /* points drawn around each place and side */
#define NLIGHTS 4

static const double lengths[] = {0.0, 1e-3, 1.0, 1e3};

/* Light number k of a call: black, white, a random light, a random light scaled by up to 1e3. */
static int make_light(GmatContext *ctx, int k, unsigned long long *seed, GColor *light)
{
    switch (k) {
    case 0: gcolor_black(light); return G_OK;
    case 1: return gcolor_copy(light, &ctx->white);
    default: {
        int rc = gmat_random_light(ctx->model, seed, light);
        return rc == G_OK && k == 3 ? gcolor_scale(light, light, 1e3 * gmat_uniform(seed)) : rc;
    }
    }
}

/* 0 when the class's absorption at sp (NULL: none) gives each light back for each length, else the number of calls
 * that did not; *calls counts them. */
static int absorb_all(GmatContext *ctx, GSurfPoint *sp, unsigned long long *seed, GColor *light, GColor *at,
                      int *calls)
{
    const GMaterial *m = ctx->material;
    int differ = 0;
    for (int k = 0; k < NLIGHTS; k++) {
        if (make_light(ctx, k, seed, light) != G_OK) {
            differ++;
            continue;
        }
        for (size_t i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
            memset(at->v, 0xff, (size_t)ctx->model->nvalues * sizeof(float)); /* NaN bits: no light has them */
            at->kind = GCOLOR_VECTOR;
            GScratchMark inner = gscratch_mark(ctx->scratch);
            int r = m->cls->absorption(m, sp, light, lengths[i], at);
            gscratch_release(ctx->scratch, inner);
            (*calls)++;
            differ += !(r == G_OK && gmat_same_colour(at, light));
        }
    }
    return differ;
}

/* absorb_all's state for the points gmat_each_point_around visits. */
typedef struct AbsorbVisit {
    unsigned long long *seed;
    GColor light, at;
    int calls;
} AbsorbVisit;

static int absorb_at(GmatContext *ctx, GSurfPoint *sp, void *user)
{
    AbsorbVisit *v = user;
    return absorb_all(ctx, sp, v->seed, &v->light, &v->at, &v->calls);
}

void gmat_check_clear(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker)
{
    const GMaterial *m = ctx->material;
    if (!(m->flags & GMAT_CLEAR)) {
        report(checker, "clear", 0.0, 0.0, "(GMAT_CLEAR not set: renderers ask the medium's absorption)");
        return;
    }
    if (!m->cls->absorption) {
        report(checker, "clear", 0.0, 0.0, "(GMAT_CLEAR set, no absorption slot: the light itself)");
        return;
    }
    unsigned long long seed = 37;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    AbsorbVisit v = {.seed = &seed, .calls = 0};
    int differ = 0, rc = gcolor_scratch(&v.light, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&v.at, ctx->model, ctx->scratch);
    if (rc == G_OK) {
        differ += absorb_all(ctx, NULL, &seed, &v.light, &v.at, &v.calls); /* a homogeneous medium: no point */
        differ += gmat_each_point_around(ctx, places, nplaces, DRAWN_POINTS, &seed, absorb_at, &v);
    }
    gscratch_release(ctx->scratch, mark);
    char detail[200];
    snprintf(detail, sizeof detail,
             "(GMAT_CLEAR set: calls of the class's own absorption that failed or did not give the light back, of %d)",
             v.calls);
    report(checker, "clear", rc == G_OK ? differ : INFINITY, 0.0, detail);
}
