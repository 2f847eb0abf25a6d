/* node_kit.c - the node kit (generic/kit/node_kit.h): the methods of blend nodes (interpolate, spline, select), which
 * pick a blend and hand it to lib/kit/node_blend.c's weighted blends, temporaries, one-child and list nodes, and
 * the construction checks of all nodes. */
#include "generic/kit/node_kit.h"
#include "generic/kit/material_kit.h" /* gmaterial_new: nodes are built like the built-in materials */
#include "node_blend.h"

#include <string.h>

/* the keyword of each GNodeMethod: the name of each picked method of GMATERIAL_METHODS (material.h) */
#define METHOD_NAME(name, NAME, type, attr, unless, dispatch, blend, params, args) METHOD_NAME_##blend(name)
#define METHOD_NAME_pick(name) #name,
#define METHOD_NAME_sampled(name)
static const char *const method_names[] = {GMATERIAL_METHODS(METHOD_NAME)};
_Static_assert(sizeof method_names / sizeof method_names[0] == GNODE_METHOD_COUNT, "a keyword for each GNodeMethod");

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
        gnode_inherit_kit_no_ideal(*out, children, n); /* the kit's direction slots: their rays or blends of them */
        gnode_inherit_kit_no_rel_index(*out, children, n); /* the kit's slots only: their index reads, if any */
        gnode_inherit_kit_constant_index(*out, children, n); /* the kit's pass-through index: its child's */
        gnode_inherit_kit_clear(*out, children, n); /* the kit's pass-through absorption: its child's */
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

/* the pass-through methods: the child's gmaterial_<name> for each of GMATERIAL_METHODS */
#define CHILD_METHOD(name, NAME, type, attr, unless, dispatch, blend, params, args)                                \
    type gnode_child_##name GMATERIAL_WITH(const GMaterial *self, params)                                           \
    {                                                                                                              \
        return gmaterial_##name GMATERIAL_WITH(gnode_child_of(self), args);                                        \
    }
GMATERIAL_METHODS(CHILD_METHOD)

/* ---- the methods of blend nodes: the class's pick, then the blend ---- */

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
{
    ((const GNodeBlendClass *)self->cls)->pick(self, sp, m, b);
}

/* the methods whose blend is `pick` (GMATERIAL_METHODS): the pick's blend for GNODE_<NAME>, then gnode_blend_<name>;
 * the sampling methods are written out below */
#define BLENDED_METHOD_pick(name, NAME, type, params, args)                                                        \
    type gnode_blended_##name GMATERIAL_WITH(const GMaterial *self, params)                                         \
    {                                                                                                              \
        GNodeBlend b;                                                                                              \
        pick(self, sp, GNODE_##NAME, &b);                                                                          \
        return gnode_blend_##name GMATERIAL_WITH(&b, args);                                                        \
    }
#define BLENDED_METHOD_sampled(name, NAME, type, params, args)
#define BLENDED_METHOD(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    BLENDED_METHOD_##blend(name, NAME, type, params, args)
GMATERIAL_METHODS(BLENDED_METHOD)

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
