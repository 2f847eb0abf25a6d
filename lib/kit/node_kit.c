/* node_kit.c - the node kit (generic/kit/node_kit.h): the methods of blend nodes (interpolate, spline, select), which
 * pick a blend and hand it to lib/kit/node_blend.c's weighted blends, temporaries, one-child and list nodes, and
 * the construction checks of all nodes. */
#include "generic/kit/node_kit.h"
#include "generic/kit/material_kit.h" /* gmat_new: nodes are built like the built-in materials */
#include "node_blend.h"

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
    GTexBlend r, t;
    pick(self, sp, GNODE_REFLECTION, &r);
    pick(self, sp, GNODE_REFRACTION, &t);
    return gtexblend_sample_split(&r, &t, sp, out, rel_index, u1, u2, s, weight);
}

/* The blend sampling draws from (gtexblend_sampled): the reflection's, or the union with the refraction's. */
static void sampled(const GMaterial *self, GSurfPoint *sp, GTexBlend *sel)
{
    GTexBlend r, t;
    pick(self, sp, GNODE_REFLECTION, &r);
    pick(self, sp, GNODE_REFRACTION, &t);
    (void)gtexblend_sampled(&r, &t, sel);
}

double gtexblendnode_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    GTexBlend b;
    sampled(self, sp, &b);
    return gtexblend_pdf(&b, sp, in, out, rel_index);
}

int gtexblendnode_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    GTexBlend b;
    sampled(self, sp, &b);
    return gtexblend_is_delta(&b, sp);
}
