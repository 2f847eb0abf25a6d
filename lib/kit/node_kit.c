/* node_kit.c - the node kit (generic/kit/node_kit.h): the methods of blend nodes (interpolate, spline, select), which
 * pick a blend and hand it to lib/kit/node_blend.c's weighted blends, temporaries, one-child and list nodes, and
 * the construction checks of all nodes. */
#include "generic/kit/node_kit.h"
#include "generic/kit/material_kit.h" /* gmaterial_new: nodes are built like the built-in materials */
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

int gnode_temps_color(GNodeTemps *t, GSurfPoint *sp, const GColorModel *m, int index, GColor *c)
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

void gnode_temps_release(GNodeTemps *t)
{
    if (t->scratch)
        gscratch_release(t->scratch, t->mark);
    t->scratch = NULL;
}

int gnode_scales_method(GNodeMethod m)
{
    return m == GNODE_REFLECTION || m == GNODE_REFRACTION || m == GNODE_EMISSION || m == GNODE_AMBIENT ||
           m == GNODE_DIFFUSE;
}

int gnode_check(const char *node, GMaterial *const *children, int n, const GGenerator *gen, int gen_needed,
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

int gnode_measure(const char *node, GMaterial *const *children, int n, int *depth, int *cost, GError *err)
{
    int d = 0;
    int top[GNODE_BLEND_MAX] = {0}; /* the largest costs, in decreasing order */
    for (int i = 0; i < n; i++) {
        d = at_least_1(children[i]->depth) > d ? at_least_1(children[i]->depth) : d;
        int c = at_least_1(children[i]->cost);
        for (int k = 0; k < GNODE_BLEND_MAX; k++)
            if (c > top[k]) {
                int t = top[k];
                top[k] = c;
                c = t;
            }
    }
    long long sum = 1; /* each term is at most GNODE_MAX_COST for kit nodes, INT_MAX for any: no overflow */
    for (int k = 0; k < GNODE_BLEND_MAX; k++)
        sum += top[k];
    if (d + 1 > GNODE_MAX_DEPTH)
        return gerror_set(err, G_ERR_INVALID, "%s: the node would be %d deep, the limit is %d", node, d + 1,
                          GNODE_MAX_DEPTH);
    if (sum > GNODE_MAX_COST)
        return gerror_set(err, G_ERR_INVALID,
                          "%s: one call of the node would make %lld material calls, the limit is %d", node, sum,
                          GNODE_MAX_COST);
    *depth = d + 1;
    *cost = (int)sum;
    return G_OK;
}

int gnode_new_checked(const GMaterialClass *cls, GMaterial *const *children, int n, const GGenerator *gen,
                         int gen_needed, size_t size, GMaterial **out, GError *err)
{
    *out = NULL;
    const GColorModel *model;
    int depth = 0, cost = 0;
    int rc = gnode_check(cls->name, children, n, gen, gen_needed, &model, err);
    if (rc == G_OK)
        rc = gnode_measure(cls->name, children, n, &depth, &cost, err);
    if (rc == G_OK)
        rc = gmaterial_new(cls, model, size, out, err);
    if (rc == G_OK) {
        (*out)->depth = depth;
        (*out)->cost = cost;
        if (cls->emission == gnode_blended_emission || cls->emission == gnode_child_emission) /* sums of children */
            gnode_inherit_no_emission(*out, children, n);
        if (cls->opaque == gnode_blended_opaque || cls->opaque == gnode_child_opaque) /* opaque where they all are */
            gnode_inherit_opaque(*out, children, n);
        gnode_inherit_kit_normal(*out, children, n); /* the kit's normal slots: blends of their normals */
        gnode_inherit_kit_diagonal(*out, children, n); /* the kit's pass-on slots: sums of their pass-ons */
    }
    return rc;
}

int gnode_list_new(const GMaterialClass *cls, GMaterial *const *children, int n, GGenerator *gen, size_t size,
                 GMaterial **out, GError *err)
{
    *out = NULL;
    GMaterial *node;
    int rc = gnode_new_checked(cls, children, n, gen, 1, size, &node, err);
    if (rc != G_OK)
        return rc;
    GNodeList *l = (GNodeList *)node;
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

void gnode_list_destroy(GMaterial *self)
{
    GNodeList *l = (GNodeList *)self;
    for (int i = 0; i < l->n; i++)
        gmaterial_unref(l->children[i]);
    gmem_free(l->children);
    ggenerator_unref(l->gen);
    gmem_free(l);
}

/* ---- nodes with one child ---- */

int gnode_child_new(const GMaterialClass *cls, GMaterial *child, const GGenerator *gen, int gen_needed, size_t size,
                  GMaterial **out, GError *err)
{
    int rc = gnode_new_checked(cls, &child, 1, gen, gen_needed, size, out, err);
    if (rc == G_OK)
        ((GNodeChild *)*out)->child = gmaterial_ref(child);
    return rc;
}

void gnode_child_destroy(GMaterial *self)
{
    gmaterial_unref(gnode_child_of(self));
    gmem_free(self);
}

int gnode_child_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    return gmaterial_reflection(gnode_child_of(self), sp, in, illum, out, result);
}

int gnode_child_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         const GColor *rel_index, GVec3 out, GColor *result)
{
    return gmaterial_refraction(gnode_child_of(self), sp, in, illum, rel_index, out, result);
}

int gnode_child_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(gnode_child_of(self), sp, result);
}

int gnode_child_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    return gmaterial_reflection_dir(gnode_child_of(self), sp, view, dir);
}

int gnode_child_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                             GVec3 *dir)
{
    return gmaterial_refraction_dir(gnode_child_of(self), sp, view, rel_index, dir);
}

int gnode_child_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    return gmaterial_emission(gnode_child_of(self), sp, out, result);
}

int gnode_child_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    return gmaterial_ambient(gnode_child_of(self), sp, illum, result);
}

int gnode_child_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                         GColor *result)
{
    return gmaterial_absorption(gnode_child_of(self), sp, illum, length, result);
}

int gnode_child_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    return gmaterial_normal(gnode_child_of(self), sp, n);
}

int gnode_child_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_diffuse(gnode_child_of(self), sp, result);
}

int gnode_child_opaque(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_opaque(gnode_child_of(self), sp);
}

int gnode_child_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                     double u2, GMaterialSample *s, GColor *weight)
{
    return gmaterial_sample(gnode_child_of(self), sp, out, rel_index, u1, u2, s, weight);
}

double gnode_child_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    return gmaterial_pdf(gnode_child_of(self), sp, in, out, rel_index);
}

int gnode_child_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_is_delta(gnode_child_of(self), sp);
}

/* ---- the methods of blend nodes: the class's pick, then the blend ---- */

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
{
    ((const GNodeBlendClass *)self->cls)->pick(self, sp, m, b);
}

int gnode_blended_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_REFLECTION, &b);
    return gnode_blend_reflection(&b, sp, in, illum, out, result);
}

int gnode_blended_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                             const GColor *rel_index, GVec3 out, GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_REFRACTION, &b);
    return gnode_blend_refraction(&b, sp, in, illum, rel_index, out, result);
}

int gnode_blended_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_REFRACTION_INDEX, &b);
    return gnode_blend_refraction_index(&b, sp, result);
}

int gnode_blended_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GNodeBlend b;
    pick(self, sp, GNODE_REFLECTION_DIR, &b);
    return gnode_blend_reflection_dir(&b, sp, view, dir);
}

int gnode_blended_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                 GVec3 *dir)
{
    GNodeBlend b;
    pick(self, sp, GNODE_REFRACTION_DIR, &b);
    return gnode_blend_refraction_dir(&b, sp, view, rel_index, dir);
}

int gnode_blended_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_EMISSION, &b);
    return gnode_blend_emission(&b, sp, out, result);
}

int gnode_blended_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_AMBIENT, &b);
    return gnode_blend_ambient(&b, sp, illum, result);
}

int gnode_blended_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                             GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_ABSORPTION, &b);
    return gnode_blend_absorption(&b, sp, illum, length, result);
}

int gnode_blended_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    GNodeBlend b;
    pick(self, sp, GNODE_NORMAL, &b);
    return gnode_blend_normal(&b, sp, n);
}

int gnode_blended_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GNodeBlend b;
    pick(self, sp, GNODE_DIFFUSE, &b);
    return gnode_blend_diffuse(&b, sp, result);
}

int gnode_blended_opaque(const GMaterial *self, GSurfPoint *sp)
{
    GNodeBlend b;
    pick(self, sp, GNODE_OPAQUE, &b);
    return gnode_blend_opaque(&b, sp);
}

int gnode_blended_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                         double u2, GMaterialSample *s, GColor *weight)
{
    GNodeBlend r, t;
    pick(self, sp, GNODE_REFLECTION, &r);
    pick(self, sp, GNODE_REFRACTION, &t);
    return gnode_blend_sample_split(&r, &t, sp, out, rel_index, u1, u2, s, weight);
}

/* The blend sampling draws from (gnode_blend_sampled): the reflection's, or the union with the refraction's. */
static void sampled(const GMaterial *self, GSurfPoint *sp, GNodeBlend *sel)
{
    GNodeBlend r, t;
    pick(self, sp, GNODE_REFLECTION, &r);
    pick(self, sp, GNODE_REFRACTION, &t);
    (void)gnode_blend_sampled(&r, &t, sel);
}

double gnode_blended_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    GNodeBlend b;
    sampled(self, sp, &b);
    return gnode_blend_pdf(&b, sp, in, out, rel_index);
}

int gnode_blended_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    GNodeBlend b;
    sampled(self, sp, &b);
    return gnode_blend_is_delta(&b, sp);
}
