/* node_common.c - the node kit (generic/node_kit.h): weighted blends of children for every material method,
 * the methods of blend nodes (interpolate, spline, select), temporaries, one-child and list nodes, and the
 * construction checks of all nodes. */
#include "generic/node_kit.h"
#include "generic/material_kit.h" /* gmat_new: nodes are built like the built-in materials */

#include <math.h>
#include <string.h>

static const char *const method_names[GNODE_METHOD_COUNT] = {
    "reflection", "refraction", "refraction_index", "reflection_dir", "refraction_dir", "emission",
    "ambient",    "absorption", "normal",           "diffuse",        "opaque",
};

const char *gnode_method_name(GNodeMethod m)
{
    return (unsigned)m < GNODE_METHOD_COUNT ? method_names[m] : "?";
}

int gnode_method_from_name(const char *name)
{
    for (int i = 0; name && i < GNODE_METHOD_COUNT; i++)
        if (strcmp(name, method_names[i]) == 0)
            return i;
    return -1;
}

int gtextemps_color(GTexTemps *t, GSurfPoint *sp, const GColorModel *m, int index, GColor *c)
{
    (void)index;
    GScratch *arena = sp && sp->scratch ? sp->scratch : gscratch_thread();
    if (!arena)
        return G_ERR_NOMEM;
    if (!t->scratch) {
        t->scratch = arena;
        t->mark = gscratch_mark(arena);
    }
    float *v = gscratch_alloc(t->scratch, (size_t)m->capacity * sizeof(float));
    if (!v)
        return G_ERR_NOMEM;
    *c = (GColor){.model = m, .v = v, .kind = GCOLOR_VECTOR, .storage = GCOLOR_STORAGE_ARENA, .capacity = m->capacity};
    return G_OK;
}

void gtextemps_release(GTexTemps *t)
{
    if (t->scratch)
        gscratch_release(t->scratch, t->mark);
    t->scratch = NULL;
}

int gtexnode_scales_method(GNodeMethod m)
{
    return m == GNODE_REFLECTION || m == GNODE_REFRACTION || m == GNODE_EMISSION || m == GNODE_AMBIENT ||
           m == GNODE_DIFFUSE;
}

int gtexnode_check(const char *node, GMaterial *const *children, int n, const GGenerator *gen, int gen_needed,
                   const GColorModel **model, GError *err)
{
    if (!children || n <= 0)
        return gerror_set(err, G_ERR_INVALID, "%s: no children given", node);
    for (int i = 0; i < n; i++)
        if (!children[i])
            return gerror_set(err, G_ERR_INVALID, "%s: child %d is missing", node, i + 1);
    if (gen_needed && !gen)
        return gerror_set(err, G_ERR_INVALID, "%s: no generator given", node);
    const GColorModel *m = children[0]->model;
    for (int i = 1; i < n; i++)
        if (children[i]->model != m)
            return gerror_set(err, G_ERR_MISMATCH, "%s: child %d computes in colour model '%s', child 1 in '%s'",
                              node, i + 1, gcolormodel_name(children[i]->model), gcolormodel_name(m));
    *model = m;
    return G_OK;
}

/* A material made without gmaterial_init may have 0 there: it counts as a material. */
static int at_least_1(int v) { return v > 1 ? v : 1; }

int gtexnode_measure(const char *node, GMaterial *const *children, int n, int *depth, int *cost, GError *err)
{
    int d = 0;
    int top[GTEX_BLEND_MAX] = {0}; /* the largest costs, in decreasing order */
    for (int i = 0; i < n; i++) {
        d = at_least_1(children[i]->depth) > d ? at_least_1(children[i]->depth) : d;
        int c = at_least_1(children[i]->cost);
        for (int k = 0; k < GTEX_BLEND_MAX; k++)
            if (c > top[k]) {
                int t = top[k];
                top[k] = c;
                c = t;
            }
    }
    long long sum = 1; /* each term is at most GTEXNODE_MAX_COST for kit nodes, INT_MAX for any: no overflow */
    for (int k = 0; k < GTEX_BLEND_MAX; k++)
        sum += top[k];
    if (d + 1 > GTEXNODE_MAX_DEPTH)
        return gerror_set(err, G_ERR_INVALID, "%s: the node would be %d deep, the limit is %d", node, d + 1,
                          GTEXNODE_MAX_DEPTH);
    if (sum > GTEXNODE_MAX_COST)
        return gerror_set(err, G_ERR_INVALID,
                          "%s: one call of the node would make %lld material calls, the limit is %d", node, sum,
                          GTEXNODE_MAX_COST);
    *depth = d + 1;
    *cost = (int)sum;
    return G_OK;
}

int gtexnode_new_checked(const GMaterialClass *cls, GMaterial *const *children, int n, const GGenerator *gen,
                         int gen_needed, size_t size, GMaterial **out, GError *err)
{
    *out = NULL;
    const GColorModel *model;
    int depth = 0, cost = 0;
    int rc = gtexnode_check(cls->name, children, n, gen, gen_needed, &model, err);
    if (rc == G_OK)
        rc = gtexnode_measure(cls->name, children, n, &depth, &cost, err);
    if (rc == G_OK)
        rc = gmat_new(cls, model, size, out, err);
    if (rc == G_OK) {
        (*out)->depth = depth;
        (*out)->cost = cost;
        if (cls->emission == gtexblendnode_emission || cls->emission == gtexchild_emission) /* sums of children */
            gtexnode_inherit_no_emission(*out, children, n);
        if (cls->opaque == gtexblendnode_opaque || cls->opaque == gtexchild_opaque) /* opaque where they all are */
            gtexnode_inherit_opaque(*out, children, n);
        gtexnode_inherit_kit_normal(*out, children, n); /* the kit's normal slots: blends of their normals */
        gtexnode_inherit_kit_diagonal(*out, children, n); /* the kit's pass-on slots: sums of their pass-ons */
    }
    return rc;
}

int gtexlist_new(const GMaterialClass *cls, GMaterial *const *children, int n, GGenerator *gen, size_t size,
                 GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *node;
    int rc = gtexnode_new_checked(cls, children, n, gen, 1, size, &node, err);
    if (rc != G_OK)
        return rc;
    GTexList *l = (GTexList *)node;
    l->children = gmem_calloc((size_t)n, sizeof *l->children);
    if (!l->children) {
        gmem_free(l);
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", cls->name);
    }
    for (int i = 0; i < n; i++)
        l->children[i] = gmaterial_ref(children[i]);
    l->n = n;
    l->gen = ggenerator_ref(gen);
    *out = node;
    return G_OK;
}

void gtexlist_destroy(GMaterial *self)
{
    GTexList *l = (GTexList *)self;
    for (int i = 0; i < l->n; i++)
        gmaterial_unref(l->children[i]);
    gmem_free(l->children);
    ggenerator_unref(l->gen);
    gmem_free(l);
}

/* ---- nodes with one child ---- */

int gtexchild_new(const GMaterialClass *cls, GMaterial *child, const GGenerator *gen, int gen_needed, size_t size,
                  GMaterial **out, GError *err)
{
    int rc = gtexnode_new_checked(cls, &child, 1, gen, gen_needed, size, out, err);
    if (rc == G_OK)
        ((GTexChild *)*out)->child = gmaterial_ref(child);
    return rc;
}

void gtexchild_destroy(GMaterial *self)
{
    gmaterial_unref(gtexchild_of(self));
    gmem_free(self);
}

int gtexchild_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    return gmaterial_reflection(gtexchild_of(self), sp, in, illum, out, result);
}

int gtexchild_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         const GColor *rel_index, GVec3 out, GColor *result)
{
    return gmaterial_refraction(gtexchild_of(self), sp, in, illum, rel_index, out, result);
}

int gtexchild_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(gtexchild_of(self), sp, result);
}

int gtexchild_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    return gmaterial_reflection_dir(gtexchild_of(self), sp, view, dir);
}

int gtexchild_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                             GVec3 *dir)
{
    return gmaterial_refraction_dir(gtexchild_of(self), sp, view, rel_index, dir);
}

int gtexchild_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    return gmaterial_emission(gtexchild_of(self), sp, out, result);
}

int gtexchild_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    return gmaterial_ambient(gtexchild_of(self), sp, illum, result);
}

int gtexchild_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                         GColor *result)
{
    return gmaterial_absorption(gtexchild_of(self), sp, illum, length, result);
}

int gtexchild_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    return gmaterial_normal(gtexchild_of(self), sp, n);
}

int gtexchild_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_diffuse(gtexchild_of(self), sp, result);
}

int gtexchild_opaque(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_opaque(gtexchild_of(self), sp);
}

int gtexchild_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                     double u2, GMaterialSample *s, GColor *weight)
{
    return gmaterial_sample(gtexchild_of(self), sp, out, rel_index, u1, u2, s, weight);
}

double gtexchild_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    return gmaterial_pdf(gtexchild_of(self), sp, in, out, rel_index);
}

int gtexchild_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_is_delta(gtexchild_of(self), sp);
}

void gtexblend_pair(GTexBlend *b, const GMaterial *a, const GMaterial *c, double t)
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

void gtexblend_one(GTexBlend *b, const GMaterial *m)
{
    b->n = 1;
    b->m[0] = m;
    b->w[0] = 1.0;
}

/* ---- colour methods: the children's results summed with their weights into the result (through an
 * accumulator when the result is also an input colour) ---- */

typedef struct ColorCall {
    int method; /* a GNodeMethod */
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

static int blend_color(const GTexBlend *b, GSurfPoint *sp, const ColorCall *c, GColor *result)
{
    if (b->n == 1)
        return call_color(b->m[0], sp, c, result);
    /* the first child goes straight into the result unless the result is also an input */
    int alias = (c->illum && c->illum->v == result->v) || (c->rel_index && c->rel_index->v == result->v);
    GTexTemps t;
    gtextemps_init(&t);
    GColor acc, tmp;
    int rc = G_OK;
    if (alias)
        rc = gtextemps_color(&t, sp, result->model, 0, &acc);
    else
        acc = *result;
    if (rc == G_OK)
        rc = gtextemps_color(&t, sp, result->model, 1, &tmp);
    int first = 1;
    for (int i = 0; i < b->n && rc == G_OK; i++) {
        if (b->w[i] == 0.0)
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
    if (rc == G_OK && alias)
        rc = gcolor_copy(result, &acc);
    else if (rc == G_OK)
        result->kind = acc.kind;
    gtextemps_release(&t);
    return rc;
}

int gtexblend_reflection(const GTexBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    ColorCall c = {.method = GNODE_REFLECTION, .in = in, .out = out, .illum = illum};
    return blend_color(b, sp, &c, result);
}

int gtexblend_refraction(const GTexBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *rel_index,
                         GVec3 out, GColor *result)
{
    ColorCall c = {.method = GNODE_REFRACTION, .in = in, .out = out, .illum = illum, .rel_index = rel_index};
    return blend_color(b, sp, &c, result);
}

int gtexblend_refraction_index(const GTexBlend *b, GSurfPoint *sp, GColor *result)
{
    ColorCall c = {.method = GNODE_REFRACTION_INDEX};
    return blend_color(b, sp, &c, result);
}

int gtexblend_emission(const GTexBlend *b, GSurfPoint *sp, GVec3 out, GColor *result)
{
    ColorCall c = {.method = GNODE_EMISSION, .out = out};
    return blend_color(b, sp, &c, result);
}

int gtexblend_ambient(const GTexBlend *b, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    ColorCall c = {.method = GNODE_AMBIENT, .illum = illum};
    return blend_color(b, sp, &c, result);
}

int gtexblend_absorption(const GTexBlend *b, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    ColorCall c = {.method = GNODE_ABSORPTION, .illum = illum, .length = length};
    return blend_color(b, sp, &c, result);
}

int gtexblend_diffuse(const GTexBlend *b, GSurfPoint *sp, GColor *result)
{
    ColorCall c = {.method = GNODE_DIFFUSE};
    return blend_color(b, sp, &c, result);
}

/* ---- vectors: the weighted sum of the valid children's vectors, normalised; with one valid child its own
 * vector; when the sum vanishes (opposite vectors) the valid child of largest weight ---- */

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

static int blend_dir(const GTexBlend *b, GSurfPoint *sp, const DirCall *c, GVec3 *dir)
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

int gtexblend_reflection_dir(const GTexBlend *b, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    DirCall c = {.method = GNODE_REFLECTION_DIR, .view = view};
    return blend_dir(b, sp, &c, dir);
}

int gtexblend_refraction_dir(const GTexBlend *b, GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir)
{
    DirCall c = {.method = GNODE_REFRACTION_DIR, .view = view, .rel_index = rel_index};
    return blend_dir(b, sp, &c, dir);
}

int gtexblend_normal(const GTexBlend *b, GSurfPoint *sp, GVec3 *n)
{
    DirCall c = {.method = GNODE_NORMAL};
    int rc = blend_dir(b, sp, &c, n);
    return rc < 0 ? rc : G_OK;
}

int gtexblend_opaque(const GTexBlend *b, GSurfPoint *sp)
{
    for (int i = 0; i < b->n; i++)
        if (b->w[i] != 0.0 && !gmaterial_opaque(b->m[i], sp))
            return 0;
    return 1;
}

/* ---- sampling: a mixture of the children ---- */

/* The selection probability of each child: |w_i| / sum |w_j|. */
static double blend_probs(const GTexBlend *b, double q[GTEX_BLEND_MAX])
{
    double total = 0.0;
    for (int i = 0; i < b->n; i++)
        total += fabs(b->w[i]);
    for (int i = 0; i < b->n; i++)
        q[i] = total > 0.0 ? fabs(b->w[i]) / total : 0.0;
    return total;
}

double gtexblend_pdf(const GTexBlend *b, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    if (b->n == 1)
        return gmaterial_pdf(b->m[0], sp, in, out, rel_index);
    double q[GTEX_BLEND_MAX], pdf = 0.0;
    blend_probs(b, q);
    for (int i = 0; i < b->n; i++)
        if (q[i] > 0.0)
            pdf += q[i] * gmaterial_pdf(b->m[i], sp, in, out, rel_index);
    return pdf;
}

int gtexblend_sample(const GTexBlend *b, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1, double u2,
                     GMaterialSample *s, GColor *weight)
{
    if (b->n == 1)
        return gmaterial_sample(b->m[0], sp, out, rel_index, u1, u2, s, weight);
    double q[GTEX_BLEND_MAX], p;
    if (!(blend_probs(b, q) > 0.0))
        return 0;
    int i = gmat_pick_lobe(q, b->n, &u1, &p);
    int rc = gmaterial_sample(b->m[i], sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        return rc;
    if (s->flags & GSAMPLE_DELTA) { /* the child's ideal lobe, weighted as in the blend */
        s->pdf *= q[i];
        rc = gcolor_scale(weight, weight, b->w[i] / q[i]);
        return rc ? rc : 1;
    }
    s->pdf = gtexblend_pdf(b, sp, s->in, out, rel_index);
    if (!(s->pdf > 0.0)) {
        gcolor_black(weight);
        return 0;
    }
    /* the blend's own value of white light along the direction, over the mixture's density */
    GTexTemps t;
    gtextemps_init(&t);
    GColor white;
    rc = gtextemps_color(&t, sp, weight->model, 0, &white);
    if (rc == G_OK)
        rc = gcolor_fill(&white, 1.0);
    if (rc == G_OK)
        rc = s->flags & GSAMPLE_TRANSMIT ? gtexblend_refraction(b, sp, s->in, &white, rel_index, out, weight)
                                          : gtexblend_reflection(b, sp, s->in, &white, out, weight);
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / s->pdf);
    gtextemps_release(&t);
    return rc ? rc : 1;
}

int gtexblend_is_delta(const GTexBlend *b, GSurfPoint *sp)
{
    for (int i = 0; i < b->n; i++)
        if (b->w[i] != 0.0 && !gmaterial_is_delta(b->m[i], sp))
            return 0;
    return 1;
}

/* ---- the methods of blend nodes: the class's pick, then the blend ---- */

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GTexBlend *b)
{
    ((const GTexBlendClass *)self->cls)->pick(self, sp, m, b);
}

int gtexblendnode_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gtexblend_reflection(&b, sp, in, illum, out, result);
}

int gtexblendnode_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                             const GColor *rel_index, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION, &b);
    return gtexblend_refraction(&b, sp, in, illum, rel_index, out, result);
}

int gtexblendnode_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION_INDEX, &b);
    return gtexblend_refraction_index(&b, sp, result);
}

int gtexblendnode_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION_DIR, &b);
    return gtexblend_reflection_dir(&b, sp, view, dir);
}

int gtexblendnode_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                 GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFRACTION_DIR, &b);
    return gtexblend_refraction_dir(&b, sp, view, rel_index, dir);
}

int gtexblendnode_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_EMISSION, &b);
    return gtexblend_emission(&b, sp, out, result);
}

int gtexblendnode_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_AMBIENT, &b);
    return gtexblend_ambient(&b, sp, illum, result);
}

int gtexblendnode_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_ABSORPTION, &b);
    return gtexblend_absorption(&b, sp, illum, length, result);
}

int gtexblendnode_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    GTexBlend b;
    pick(self, sp, GNODE_NORMAL, &b);
    return gtexblend_normal(&b, sp, n);
}

int gtexblendnode_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, GNODE_DIFFUSE, &b);
    return gtexblend_diffuse(&b, sp, result);
}

int gtexblendnode_opaque(const GMaterial *self, GSurfPoint *sp)
{
    GTexBlend b;
    pick(self, sp, GNODE_OPAQUE, &b);
    return gtexblend_opaque(&b, sp);
}

int gtexblendnode_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                         double u2, GMaterialSample *s, GColor *weight)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gtexblend_sample(&b, sp, out, rel_index, u1, u2, s, weight);
}

double gtexblendnode_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gtexblend_pdf(&b, sp, in, out, rel_index);
}

int gtexblendnode_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    GTexBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gtexblend_is_delta(&b, sp);
}
