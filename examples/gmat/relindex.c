/* relindex.c - the no-rel-index check of `gmat check` (material.h's GMAT_NO_REL_INDEX): a material with the bit says
 * that none of its methods reads the relative index, neither the rel_index argument nor the point's
 * (gsurfpoint_relative_index, gsurfpoint_index_of), so a renderer may skip computing it. The check makes two copies
 * of each point of the finite check (above and below the surface), one with the relative index 1.5 and one with
 * 1 / 1.5 (set on the point with gsurfpoint_set_relative_index and handed as the argument), and calls every slot
 * of the class (not the dispatch, which a bit may answer) on both with the same arguments: directions out over the
 * finite check's grid, directions in drawn at random on both sides, the mirror direction, the ideal refractions for
 * both indices and the straight line through, white and a random light, the same numbers for sample. Every result
 * (status, colour samples, directions, densities, flags) must be the same bit for bit. Nothing to check without the
 * bit. */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define INDEX_HIGH 1.5 /* the two relative indices: entering glass, and leaving it */

/* One place and side: the two points (index 1.5 and 1 / 1.5), their relative indices, a light, and the tally. */
typedef struct Pair {
    GmatContext *ctx;
    GSurfPoint sp[2];
    GColor ri[2];
    const GColor *light;
    int calls, differ;
} Pair;

static int same_bits(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }

/* 1 when the two colours hold the same kind and the same samples, bit for bit. */
static int same_colour(const GColor *a, const GColor *b)
{
    if (a->kind != b->kind)
        return 0;
    int n = a->kind == GCOLOR_MATRIX ? a->model->capacity : a->model->nvalues;
    return same_bits(a->v, b->v, (size_t)n * sizeof(float));
}

static void tally(Pair *p, int same)
{
    p->calls++;
    p->differ += !same;
}

/* The colour slots at the pair for one (in, out): a method number picks the slot (0 reflection, 1 refraction,
 * 2 emission, 3 ambient, 4 absorption, 5 diffuse, 6 refraction_index); the statuses and colours must agree. */
static void colour_slot(Pair *p, int method, GVec3 in, GVec3 out)
{
    const GMaterial *m = p->ctx->material;
    const GMaterialClass *cls = m->cls;
    GScratch *scratch = p->ctx->scratch;
    GScratchMark mark = gscratch_mark(scratch);
    GColor c[2];
    int rc[2];
    for (int k = 0; k < 2; k++) {
        GSurfPoint *sp = &p->sp[k];
        rc[k] = gcolor_scratch(&c[k], p->ctx->model, scratch);
        if (rc[k] != G_OK)
            continue;
        switch (method) {
        case 0: rc[k] = cls->reflection(m, sp, in, p->light, out, &c[k]); break;
        case 1: rc[k] = cls->refraction(m, sp, in, p->light, &p->ri[k], out, &c[k]); break;
        case 2: rc[k] = cls->emission(m, sp, out, &c[k]); break;
        case 3: rc[k] = cls->ambient(m, sp, p->light, &c[k]); break;
        case 4: rc[k] = cls->absorption(m, sp, p->light, 0.7, &c[k]); break;
        case 5: rc[k] = cls->diffuse(m, sp, &c[k]); break;
        default: rc[k] = cls->refraction_index(m, sp, &c[k]); break;
        }
    }
    tally(p, rc[0] == rc[1] && (rc[0] != G_OK || same_colour(&c[0], &c[1])));
    gscratch_release(scratch, mark);
}

/* The slots of one point alone: the colours without directions, the normal, opaque and is_delta. */
static void point_slots(Pair *p)
{
    const GMaterial *m = p->ctx->material;
    const GMaterialClass *cls = m->cls;
    GVec3 none = gvec3(0, 0, 0);
    if (cls->ambient)
        colour_slot(p, 3, none, none);
    if (cls->absorption)
        colour_slot(p, 4, none, none);
    if (cls->diffuse)
        colour_slot(p, 5, none, none);
    if (cls->refraction_index)
        colour_slot(p, 6, none, none);
    if (cls->normal) {
        GVec3 n[2] = {gvec3(7, 7, 7), gvec3(7, 7, 7)};
        int rc0 = cls->normal(m, &p->sp[0], &n[0]), rc1 = cls->normal(m, &p->sp[1], &n[1]);
        tally(p, rc0 == rc1 && same_bits(&n[0], &n[1], sizeof n[0]));
    }
    if (cls->opaque)
        tally(p, cls->opaque(m, &p->sp[0]) == cls->opaque(m, &p->sp[1]));
    if (cls->is_delta)
        tally(p, cls->is_delta(m, &p->sp[0]) == cls->is_delta(m, &p->sp[1]));
}

/* The slots that take a direction out (and a direction in): emission, the ideal directions for the view -out,
 * reflection, refraction and pdf from every in given, and sample with the numbers u. */
static void direction_slots(Pair *p, GVec3 out, const GVec3 *ins, int nin, const double *u, int nu)
{
    const GMaterial *m = p->ctx->material;
    const GMaterialClass *cls = m->cls;
    GVec3 view = gvec3_neg(out);
    if (cls->emission)
        colour_slot(p, 2, out, out);
    if (cls->reflection_dir) {
        GVec3 d[2] = {gvec3(7, 7, 7), gvec3(7, 7, 7)};
        int rc0 = cls->reflection_dir(m, &p->sp[0], view, &d[0]), rc1 = cls->reflection_dir(m, &p->sp[1], view, &d[1]);
        tally(p, rc0 == rc1 && same_bits(&d[0], &d[1], sizeof d[0]));
    }
    if (cls->refraction_dir) {
        GVec3 d[2] = {gvec3(7, 7, 7), gvec3(7, 7, 7)};
        int rc0 = cls->refraction_dir(m, &p->sp[0], view, &p->ri[0], &d[0]);
        int rc1 = cls->refraction_dir(m, &p->sp[1], view, &p->ri[1], &d[1]);
        tally(p, rc0 == rc1 && same_bits(&d[0], &d[1], sizeof d[0]));
    }
    for (int i = 0; i < nin; i++) {
        if (cls->reflection)
            colour_slot(p, 0, ins[i], out);
        if (cls->refraction)
            colour_slot(p, 1, ins[i], out);
        if (cls->pdf) {
            double a = cls->pdf(m, &p->sp[0], ins[i], out, &p->ri[0]);
            double b = cls->pdf(m, &p->sp[1], ins[i], out, &p->ri[1]);
            tally(p, same_bits(&a, &b, sizeof a));
        }
    }
    for (int j = 0; cls->sample && j + 1 < nu; j += 2) {
        GScratchMark mark = gscratch_mark(p->ctx->scratch);
        GMaterialSample s[2];
        GColor w[2];
        int rc[2];
        for (int k = 0; k < 2; k++) {
            memset(&s[k], 0, sizeof s[k]);
            rc[k] = gcolor_scratch(&w[k], p->ctx->model, p->ctx->scratch);
            if (rc[k] == G_OK)
                rc[k] = cls->sample(m, &p->sp[k], out, &p->ri[k], u[j], u[j + 1], &s[k], &w[k]);
        }
        tally(p, rc[0] == rc[1] && same_bits(&s[0].in, &s[1].in, sizeof s[0].in) &&
                     same_bits(&s[0].pdf, &s[1].pdf, sizeof s[0].pdf) && s[0].flags == s[1].flags &&
                     (rc[0] <= 0 || same_colour(&w[0], &w[1])));
        gscratch_release(p->ctx->scratch, mark);
    }
}

/* Every slot at the place's two points of one side, over the directions and lights. */
static void check_side(Pair *p, int below, unsigned long long *seed)
{
    GmatContext *ctx = p->ctx;
    for (int k = 0; k < 2; k++) { /* the same point, the index set on it and handed as the argument */
        gmat_surface_point(ctx, &p->sp[k], below);
        gsurfpoint_set_relative_index(&p->sp[k], &p->ri[k]);
    }
    double up = below ? -1.0 : 1.0; /* the side of the geometric normal */
    point_slots(p);
    for (int t = 0; t < 90; t += 15)
        for (int ph = 0; ph < 360; ph += 90) {
            GVec3 out = gmat_direction(t, ph + 7.5 * t / 15.0), n = gvec3(0, 0, up), ins[8];
            out.z *= up;
            int nin = 0;
            ins[nin++] = gvec3_sub(gvec3_scale(n, 2.0 * gvec3_dot(out, n)), out); /* the mirror direction */
            ins[nin++] = gvec3_neg(out);                                           /* straight through */
            for (int e = 0; e < 2; e++) { /* the ideal refractions of the view -out for both indices */
                GVec3 d;
                if (goptics_refract(gvec3_neg(out), n, e ? 1.0 / INDEX_HIGH : INDEX_HIGH, &d))
                    ins[nin++] = gvec3_neg(d);
            }
            while (nin < 8) { /* random, on both sides */
                double z = 2.0 * gmat_uniform(seed) - 1.0, a = 2.0 * M_PI * gmat_uniform(seed);
                double r = sqrt(fmax(0.0, 1.0 - z * z));
                ins[nin++] = gvec3(r * cos(a), r * sin(a), z);
            }
            double u[6];
            for (int j = 0; j < 6; j++)
                u[j] = gmat_uniform(seed);
            direction_slots(p, out, ins, nin, u, 6);
        }
}

void gmat_check_no_rel_index(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                             void *checker)
{
    const GMaterial *m = ctx->material;
    if (!(m->flags & GMAT_NO_REL_INDEX)) {
        report(checker, "no-rel-index", 0.0, 0.0, "(GMAT_NO_REL_INDEX not set: renderers hand the relative index)");
        return;
    }
    Pair p = {.ctx = ctx};
    unsigned long long seed = 29;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    GColor random_light;
    int rc = gcolor_scratch(&p.ri[0], ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&p.ri[1], ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&random_light, ctx->model, ctx->scratch);
    if (rc == G_OK)
        rc = gcolor_fill(&p.ri[0], INDEX_HIGH);
    if (rc == G_OK)
        rc = gcolor_fill(&p.ri[1], 1.0 / INDEX_HIGH);
    if (rc == G_OK)
        rc = gmat_random_light(ctx->model, &seed, &random_light);
    for (int q = 0; q < nplaces && rc == G_OK; q++) {
        ctx->place = &places[q];
        p.light = q % 2 ? &random_light : &ctx->white;
        for (int below = 0; below < 2; below++)
            check_side(&p, below, &seed);
    }
    ctx->place = NULL;
    gscratch_release(ctx->scratch, mark);
    char detail[200];
    snprintf(detail, sizeof detail,
             "(GMAT_NO_REL_INDEX set: calls of the class's own slots whose results differed between the relative "
             "indices %g and 1 / %g, of %d)", INDEX_HIGH, INDEX_HIGH, p.calls);
    report(checker, "no-rel-index", rc == G_OK ? p.differ : INFINITY, 0.0, detail);
}
