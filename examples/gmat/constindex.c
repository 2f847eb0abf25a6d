/* constindex.c - the constant-index check of `gmat check` (material.h's GMAT_CONSTANT_INDEX): a material with the bit
 * says that its refraction_index gives the same colour, bit for bit, at every point and for sp NULL, so a renderer
 * may compute the relative index of a pair of such materials once. The check calls the class's own refraction_index
 * slot (not the dispatch) with sp NULL for the reference, then at each place of the finite check on both sides, and
 * at points drawn around each place: other positions, tilted normals and tangents, other (u, v), surface indices,
 * footprints and distances. Every status and colour (kind and samples) must be the reference's bit for bit. Nothing
 * to check without the bit, nor for a class without the slot (the default, 1 everywhere). */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DRAWN_POINTS 24 /* points drawn around each place and side */

int gmat_same_colour(const GColor *a, const GColor *b)
{
    if (a->kind != b->kind)
        return 0;
    int n = a->kind == GCOLOR_MATRIX ? a->model->capacity : a->model->nvalues;
    return memcmp(a->v, b->v, (size_t)n * sizeof(float)) == 0;
}

/* A unit vector drawn uniformly on the sphere. */
static GVec3 random_unit(unsigned long long *seed)
{
    double z = 2.0 * gmat_uniform(seed) - 1.0, a = 2.0 * M_PI * gmat_uniform(seed);
    double r = sqrt(fmax(0.0, 1.0 - z * z));
    return gvec3(r * cos(a), r * sin(a), z);
}

void gmat_draw_point(GSurfPoint *sp, unsigned long long *seed)
{
    GVec3 n = random_unit(seed);
    if (gvec3_dot(n, sp->geometric_normal) < 0.0)
        n = gvec3_neg(n);
    GVec3 t = gvec3_normalize(gvec3_cross(n, fabs(n.x) < 0.9 ? gvec3(1, 0, 0) : gvec3(0, 1, 0)));
    sp->geometric_normal = n;
    sp->dpdu = gvec3_scale(t, 0.5 + 2.0 * gmat_uniform(seed));
    sp->dpdv = gvec3_scale(gvec3_cross(n, t), 0.5 + 2.0 * gmat_uniform(seed));
    sp->point = sp->object_point = gvec3_scale(random_unit(seed), 10.0 * gmat_uniform(seed));
    sp->u = 4.0 * gmat_uniform(seed) - 1.5;
    sp->v = 4.0 * gmat_uniform(seed) - 1.5;
    sp->surface = (int)(6.0 * gmat_uniform(seed));
    sp->footprint = 0.1 * gmat_uniform(seed);
    sp->uv_footprint = 0.1 * gmat_uniform(seed);
    sp->t = 5.0 * gmat_uniform(seed);
    gsurfpoint_invalidate(sp);
}

int gmat_each_point_around(GmatContext *ctx, const GmatPlace *places, int nplaces, int drawn, unsigned long long *seed,
                           GmatPointVisit visit, void *user)
{
    int sum = 0;
    for (int q = 0; q < nplaces; q++) {
        ctx->place = &places[q];
        for (int below = 0; below < 2; below++)
            for (int k = 0; k <= drawn; k++) { /* the place's own point, then points drawn around it */
                GSurfPoint sp;
                gmat_surface_point(ctx, &sp, below);
                if (k > 0)
                    gmat_draw_point(&sp, seed);
                sum += visit(ctx, &sp, user);
            }
    }
    ctx->place = NULL;
    return sum;
}

/* What the constant-index visit compares against: the class's colour for sp NULL and its status. */
typedef struct IndexVisit {
    GColor ref, at;
    int ref_rc, calls;
} IndexVisit;

/* 1 when the class's own refraction_index at sp differs from its index for sp NULL (status or bits). */
static int index_differs(GmatContext *ctx, GSurfPoint *sp, void *user)
{
    IndexVisit *v = user;
    const GMaterial *m = ctx->material;
    GScratchMark inner = gscratch_mark(ctx->scratch);
    int r = m->cls->refraction_index(m, sp, &v->at);
    gscratch_release(ctx->scratch, inner);
    v->calls++;
    return !(r == v->ref_rc && (r != G_OK || gmat_same_colour(&v->at, &v->ref)));
}

void gmat_check_constant_index(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                               void *checker)
{
    const GMaterial *m = ctx->material;
    if (!(m->flags & GMAT_CONSTANT_INDEX)) {
        report(checker, "constant-index", 0.0, 0.0,
               "(GMAT_CONSTANT_INDEX not set: renderers compute the index per point)");
        return;
    }
    if (!m->cls->refraction_index) {
        report(checker, "constant-index", 0.0, 0.0,
               "(GMAT_CONSTANT_INDEX set, no refraction_index slot: 1 everywhere)");
        return;
    }
    unsigned long long seed = 31;
    int differ = 0;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    IndexVisit v = {.calls = 0};
    int rc = gcolor_scratch(&v.ref, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&v.at, ctx->model, ctx->scratch);
    v.ref_rc = rc == G_OK ? m->cls->refraction_index(m, NULL, &v.ref) : rc;
    if (rc == G_OK)
        differ = gmat_each_point_around(ctx, places, nplaces, DRAWN_POINTS, &seed, index_differs, &v);
    gscratch_release(ctx->scratch, mark);
    char detail[200];
    snprintf(detail, sizeof detail,
             "(GMAT_CONSTANT_INDEX set: calls of the class's own refraction_index whose status or colour differed from "
             "its colour for sp NULL, of %d)", v.calls);
    report(checker, "constant-index", rc == G_OK ? differ : INFINITY, 0.0, detail);
}
