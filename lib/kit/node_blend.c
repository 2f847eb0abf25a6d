/* node_blend.c - the node kit's weighted blends of children (generic/kit/node_kit.h): every material method of a
 * GNodeBlend, the colours summed with the children's weights, the directions and normals summed and normalised,
 * and sampling as a mixture of the children. The blend nodes' methods (lib/kit/node_kit.c) pick a blend and
 * call these. */
#include "generic/kit/node_kit.h"
#include "generic/kit/material_kit.h" /* gmaterial_pick_lobe */
#include "node_blend.h"

#include <math.h>

void gnode_blend_pair(GNodeBlend *b, const GMaterial *a, const GMaterial *c, double t)
{
    if (!(t > 0.0)) { /* also NaN */
        b->n = 1;
        b->m[0] = a;
        b->w[0] = 1.0;
    } else if (t >= 1.0) {
        b->n = 1;
        b->m[0] = c;
        b->w[0] = 1.0;
    } else {
        b->n = 2;
        b->m[0] = a;
        b->w[0] = 1.0 - t;
        b->m[1] = c;
        b->w[1] = t;
    }
}

void gnode_blend_one(GNodeBlend *b, const GMaterial *m)
{
    b->n = 1;
    b->m[0] = m;
    b->w[0] = 1.0;
}

/* The direction methods of one child (reflection_dir, refraction_dir, normal). */
typedef struct DirCall {
    int method; /* GNODE_REFLECTION_DIR, GNODE_REFRACTION_DIR or GNODE_NORMAL */
    GVec3 view;
    const GColor *rel_index;
} DirCall;

static int call_dir(const GMaterial *m, GSurfPoint *sp, const DirCall *c, GVec3 *d)
{
    switch (c->method) {
    case GNODE_REFLECTION_DIR: return gmaterial_reflection_dir(m, sp, c->view, d);
    case GNODE_REFRACTION_DIR: return gmaterial_refraction_dir(m, sp, c->view, c->rel_index, d);
    default: {
        int rc = gmaterial_normal(m, sp, d);
        return rc < 0 ? rc : 1;
    }
    }
}

/* ---- colour methods: the children's results summed with their weights into the result (through an
 * accumulator when the result is also an input colour) ---- */

typedef struct ColorCall {
    int method;   /* a GNodeMethod */
    int nondelta; /* reflection, refraction: the value of the lobes that are not ideal (sampling's weight) */
    GVec3 in, out;
    const GColor *illum, *rel_index;
    double length;
} ColorCall;

static int call_color(const GMaterial *m, GSurfPoint *sp, const ColorCall *c, GColor *r)
{
    switch (c->method) {
    case GNODE_REFLECTION: return gmaterial_reflection(m, sp, c->in, c->illum, c->out, r);
    case GNODE_REFRACTION: return gmaterial_refraction(m, sp, c->in, c->illum, c->rel_index, c->out, r);
    case GNODE_REFRACTION_INDEX: return gmaterial_refraction_index(m, sp, r);
    case GNODE_EMISSION: return gmaterial_emission(m, sp, c->out, r);
    case GNODE_AMBIENT: return gmaterial_ambient(m, sp, c->illum, r);
    case GNODE_ABSORPTION: return gmaterial_absorption(m, sp, c->illum, c->length, r);
    default: return gmaterial_diffuse(m, sp, r);
    }
}

/* ---- the ideal ray (material.h, materials.h): at a pair aligned with the blend's own ideal ray the result is the
 * ideal part, the sum of the children that have an ideal ray of their own there; the others' BRDF has no delta
 * part and adds nothing. The blend's ray is its children's rays blended (gnode_blend_reflection_dir); the pair is
 * taken as aligned with it when `in` is the mirror direction of `out` (for refraction: the ideal refraction of
 * -out) about the point's shading normal, the cached normal every child reads, so that the test is exact when the
 * children reflect and refract about it, as every built-in material and node does, and costs no call and no
 * square root. Children whose rays go elsewhere (a plug-in with a normal of its own) make the blended ray an
 * approximation, which a renderer traces once; the test stays the point's own ideal pair. ---- */

/* 1 when some child of non-zero weight has the direction slot of the method (reflection_dir for reflection,
 * refraction_dir for refraction) and not GMAT_NO_IDEAL: only then may the blend have an ideal ray. No call. */
static int may_have_ray(const GNodeBlend *b, int reflect)
{
    for (int i = 0; i < b->n; i++) {
        const GMaterialClass *cls = b->m[i]->cls;
        if (b->w[i] != 0.0 && !(b->m[i]->flags & GMAT_NO_IDEAL) &&
            (reflect ? cls->reflection_dir != NULL : cls->refraction_dir != NULL))
            return 1;
    }
    return 0;
}

/* The children a reflection or refraction call leaves out, one bit each (child i: 1 << i): at an aligned pair
 * where some child of non-zero weight has an ideal ray for the view -out, those without one (with c->nondelta,
 * those with one: their value there is the ideal part). 0 elsewhere; or a negative status. */
_Static_assert(GNODE_BLEND_MAX <= 31, "ideal_skip's children are the bits of an int");

static int ideal_skip(const GNodeBlend *b, GSurfPoint *sp, const ColorCall *c)
{
    int reflect = c->method == GNODE_REFLECTION;
    if (!may_have_ray(b, reflect))
        return 0;
    GVec3 n = gsurfpoint_normal(sp), view = gvec3_neg(c->out);
    if (reflect ? !gmaterial_is_mirror_pair(c->in, n, c->out)
                : !goptics_is_refraction_pair(view, n, c->rel_index ? gsurfpoint_index_of(sp, c->rel_index)
                                                                     : gsurfpoint_relative_index(sp), c->in))
        return 0;
    DirCall d = {.method = reflect ? GNODE_REFLECTION_DIR : GNODE_REFRACTION_DIR, .view = view,
                 .rel_index = c->rel_index};
    int with = 0, without = 0;
    for (int i = 0; i < b->n; i++) {
        if (b->w[i] == 0.0)
            continue;
        GVec3 dir;
        int rc = call_dir(b->m[i], sp, &d, &dir);
        if (rc < 0)
            return rc;
        if (rc > 0)
            with |= 1 << i;
        else
            without |= 1 << i;
    }
    return !with ? 0 : c->nondelta ? with : without;
}

static int blend_color(const GNodeBlend *b, GSurfPoint *sp, const ColorCall *c, GColor *result)
{
    if (b->n == 1)
        return call_color(b->m[0], sp, c, result);
    int skip = 0; /* the children left out at the ideal ray */
    if (c->method == GNODE_REFLECTION || c->method == GNODE_REFRACTION)
        if ((skip = ideal_skip(b, sp, c)) < 0)
            return skip;
    /* the first child goes straight into the result unless the result is also an input */
    int alias = (c->illum && c->illum->v == result->v) || (c->rel_index && c->rel_index->v == result->v);
    GNodeTemps t;
    gnode_temps_init(&t);
    GColor acc, tmp;
    int rc = G_OK;
    if (alias)
        rc = gnode_temps_color(&t, sp, result->model, 0, &acc);
    else
        acc = *result;
    if (rc == G_OK)
        rc = gnode_temps_color(&t, sp, result->model, 1, &tmp);
    int first = 1;
    for (int i = 0; i < b->n && rc == G_OK; i++) {
        if (b->w[i] == 0.0 || (skip >> i & 1))
            continue;
        if (first) {
            rc = call_color(b->m[i], sp, c, &acc);
            if (rc == G_OK && b->w[i] != 1.0)
                rc = gcolor_scale(&acc, &acc, b->w[i]);
            first = 0;
        } else {
            rc = call_color(b->m[i], sp, c, &tmp);
            if (rc == G_OK)
                rc = gcolor_add_scaled(&acc, &tmp, b->w[i]);
        }
    }
    if (rc == G_OK && first) /* no child answered */
        gcolor_black(&acc);
    if (rc == G_OK && alias)
        rc = gcolor_copy(result, &acc);
    else if (rc == G_OK)
        result->kind = acc.kind;
    gnode_temps_release(&t);
    return rc;
}

int gnode_blend_reflection(const GNodeBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    ColorCall c = {.method = GNODE_REFLECTION, .in = in, .out = out, .illum = illum};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_refraction(const GNodeBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *rel_index,
                         GVec3 out, GColor *result)
{
    ColorCall c = {.method = GNODE_REFRACTION, .in = in, .out = out, .illum = illum, .rel_index = rel_index};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_refraction_index(const GNodeBlend *b, GSurfPoint *sp, GColor *result)
{
    ColorCall c = {.method = GNODE_REFRACTION_INDEX};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_emission(const GNodeBlend *b, GSurfPoint *sp, GVec3 out, GColor *result)
{
    ColorCall c = {.method = GNODE_EMISSION, .out = out};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_ambient(const GNodeBlend *b, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    ColorCall c = {.method = GNODE_AMBIENT, .illum = illum};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_absorption(const GNodeBlend *b, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    ColorCall c = {.method = GNODE_ABSORPTION, .illum = illum, .length = length};
    return blend_color(b, sp, &c, result);
}

int gnode_blend_diffuse(const GNodeBlend *b, GSurfPoint *sp, GColor *result)
{
    ColorCall c = {.method = GNODE_DIFFUSE};
    return blend_color(b, sp, &c, result);
}

/* ---- vectors: the weighted sum of the valid children's vectors, normalised; with one valid child its own
 * vector; when the sum vanishes (opposite vectors) the valid child of largest weight ---- */

static int blend_dir(const GNodeBlend *b, GSurfPoint *sp, const DirCall *c, GVec3 *dir)
{
    if (b->n == 1)
        return call_dir(b->m[0], sp, c, dir);
    GVec3 sum = gvec3(0, 0, 0), best = sum;
    double best_w = -INFINITY;
    int valid = 0;
    for (int i = 0; i < b->n; i++) {
        if (b->w[i] == 0.0)
            continue;
        GVec3 d;
        int rc = call_dir(b->m[i], sp, c, &d);
        if (rc < 0)
            return rc;
        if (rc == 0)
            continue;
        valid++;
        sum = gvec3_madd(sum, d, b->w[i]);
        if (b->w[i] > best_w) {
            best_w = b->w[i];
            best = d;
        }
    }
    if (valid == 0)
        return 0;
    if (valid == 1) {
        *dir = best;
        return 1;
    }
    double len = gvec3_length(sum);
    *dir = len > 1e-12 ? gvec3_scale(sum, 1.0 / len) : best;
    return 1;
}

int gnode_blend_reflection_dir(const GNodeBlend *b, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    DirCall c = {.method = GNODE_REFLECTION_DIR, .view = view};
    return blend_dir(b, sp, &c, dir);
}

int gnode_blend_refraction_dir(const GNodeBlend *b, GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir)
{
    DirCall c = {.method = GNODE_REFRACTION_DIR, .view = view, .rel_index = rel_index};
    return blend_dir(b, sp, &c, dir);
}

int gnode_blend_normal(const GNodeBlend *b, GSurfPoint *sp, GVec3 *n)
{
    DirCall c = {.method = GNODE_NORMAL};
    int rc = blend_dir(b, sp, &c, n);
    return rc < 0 ? rc : G_OK;
}

int gnode_blend_opaque(const GNodeBlend *b, GSurfPoint *sp)
{
    for (int i = 0; i < b->n; i++)
        if (b->w[i] != 0.0 && !gmaterial_opaque(b->m[i], sp))
            return 0;
    return 1;
}

/* ---- sampling: a mixture of the children ---- */

/* The selection probability of each child: |w_i| / sum |w_j|. */
static double blend_probs(const GNodeBlend *b, double q[GNODE_BLEND_MAX])
{
    double total = 0.0;
    for (int i = 0; i < b->n; i++)
        total += fabs(b->w[i]);
    for (int i = 0; i < b->n; i++)
        q[i] = total > 0.0 ? fabs(b->w[i]) / total : 0.0;
    return total;
}

double gnode_blend_pdf(const GNodeBlend *b, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    if (b->n == 1)
        return gmaterial_pdf(b->m[0], sp, in, out, rel_index);
    double q[GNODE_BLEND_MAX], pdf = 0.0;
    blend_probs(b, q);
    for (int i = 0; i < b->n; i++)
        if (q[i] > 0.0)
            pdf += q[i] * gmaterial_pdf(b->m[i], sp, in, out, rel_index);
    return pdf;
}

/* The weight child m has in b: the sum over its entries (a spline may list one child twice). */
static double weight_of(const GNodeBlend *b, const GMaterial *m)
{
    double w = 0.0;
    for (int i = 0; i < b->n; i++)
        if (b->m[i] == m)
            w += b->w[i];
    return w;
}

/* The mixture over sel's children; a sample's value is that of refl, or of refr for a transmitted one (sel is both
 * when the two are one blend; see gnode_blend_sample_split). */
static int mixture_sample(const GNodeBlend *sel, const GNodeBlend *refl, const GNodeBlend *refr, GSurfPoint *sp,
                          GVec3 out, const GColor *rel_index, double u1, double u2, GMaterialSample *s, GColor *weight)
{
    double q[GNODE_BLEND_MAX], p;
    if (!(blend_probs(sel, q) > 0.0))
        return 0;
    int i = gmaterial_pick_lobe(q, sel->n, &u1, &p);
    int rc = gmaterial_sample(sel->m[i], sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        return rc;
    int transmit = (s->flags & GSAMPLE_TRANSMIT) != 0;
    const GNodeBlend *value = transmit ? refr : refl;
    if (s->flags & GSAMPLE_DELTA) { /* the child's ideal lobe, weighted as in the blend */
        s->pdf *= q[i];
        rc = gcolor_scale(weight, weight, (value == sel ? sel->w[i] : weight_of(value, sel->m[i])) / q[i]);
        return rc ? rc : 1;
    }
    s->pdf = gnode_blend_pdf(sel, sp, s->in, out, rel_index);
    if (!(s->pdf > 0.0)) {
        gcolor_black(weight);
        return 0;
    }
    /* the blend's own value of white light along the direction, over the mixture's density */
    GNodeTemps t;
    gnode_temps_init(&t);
    GColor white;
    rc = gnode_temps_color(&t, sp, weight->model, 0, &white);
    if (rc == G_OK)
        rc = gcolor_fill(&white, 1.0);
    if (rc == G_OK) { /* at the ideal ray, the value of the lobes that are not ideal: the children without a ray */
        ColorCall c = {.method = transmit ? GNODE_REFRACTION : GNODE_REFLECTION, .nondelta = 1, .in = s->in,
                       .out = out, .illum = &white, .rel_index = transmit ? rel_index : NULL};
        rc = blend_color(value, sp, &c, weight);
    }
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / s->pdf);
    gnode_temps_release(&t);
    return rc ? rc : 1;
}

int gnode_blend_sample(const GNodeBlend *b, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1, double u2,
                     GMaterialSample *s, GColor *weight)
{
    if (b->n == 1)
        return gmaterial_sample(b->m[0], sp, out, rel_index, u1, u2, s, weight);
    return mixture_sample(b, b, b, sp, out, rel_index, u1, u2, s, weight);
}

int gnode_blend_sampled(const GNodeBlend *refl, const GNodeBlend *refr, GNodeBlend *sel)
{
    int same = refl->n == refr->n;
    for (int i = 0; i < refl->n && same; i++)
        same = refl->m[i] == refr->m[i] && refl->w[i] == refr->w[i];
    *sel = *refl;
    if (same)
        return 0;
    sel->n = 0;
    const GNodeBlend *both[2] = {refl, refr};
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < both[k]->n; i++) {
            int j = 0;
            while (j < sel->n && sel->m[j] != both[k]->m[i])
                j++;
            if (j == GNODE_BLEND_MAX) { /* more children than a blend holds: the reflection's alone */
                *sel = *refl;
                return 0;
            }
            if (j == sel->n) {
                sel->m[sel->n] = both[k]->m[i];
                sel->w[sel->n++] = 0.0;
            }
            sel->w[j] += fabs(both[k]->w[i]);
        }
    return 1;
}

int gnode_blend_sample_split(const GNodeBlend *refl, const GNodeBlend *refr, GSurfPoint *sp, GVec3 out,
                           const GColor *rel_index, double u1, double u2, GMaterialSample *s, GColor *weight)
{
    GNodeBlend sel;
    if (!gnode_blend_sampled(refl, refr, &sel))
        return gnode_blend_sample(refl, sp, out, rel_index, u1, u2, s, weight);
    return mixture_sample(&sel, refl, refr, sp, out, rel_index, u1, u2, s, weight);
}

int gnode_blend_is_delta(const GNodeBlend *b, GSurfPoint *sp)
{
    for (int i = 0; i < b->n; i++)
        if (b->w[i] != 0.0 && !gmaterial_is_delta(b->m[i], sp))
            return 0;
    return 1;
}
