/* node_common.h - code shared by the texture nodes (textures/node_common.c): weighted blends of
 * children for every material method, temporaries, and constructor checks. Internal to the library. */
#ifndef GENERIC_TEXTURES_NODE_COMMON_H
#define GENERIC_TEXTURES_NODE_COMMON_H

#include "generic/material.h"
#include "generic/textures.h"
#include "generic/material_kit.h" /* gmat_new: nodes are built like the built-in materials */

/** Most children a blend evaluates at once (a cubic spline segment). */
#define GTEX_BLEND_MAX 4

/** A weighted sum of children: sum_i w[i] * child_i for every method. Children with weight 0 are not
 * called; n == 1 calls the child for the result directly. */
typedef struct GTexBlend {
    int n;
    const GMaterial *m[GTEX_BLEND_MAX];
    double w[GTEX_BLEND_MAX];
} GTexBlend;

/** The blend of a with weight 1 - t and b with weight t (t in [0, 1]; one child at 0 or 1). */
void gtexblend_pair(GTexBlend *b, const GMaterial *a, const GMaterial *c, double t);

int gtexblend_reflection(const GTexBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result);
int gtexblend_refraction(const GTexBlend *b, GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *rel_index,
                         GVec3 out, GColor *result);
int gtexblend_refraction_index(const GTexBlend *b, GSurfPoint *sp, GColor *result);
int gtexblend_reflection_dir(const GTexBlend *b, GSurfPoint *sp, GVec3 view, GVec3 *dir);
int gtexblend_refraction_dir(const GTexBlend *b, GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir);
int gtexblend_emission(const GTexBlend *b, GSurfPoint *sp, GVec3 out, GColor *result);
int gtexblend_ambient(const GTexBlend *b, GSurfPoint *sp, const GColor *illum, GColor *result);
int gtexblend_absorption(const GTexBlend *b, GSurfPoint *sp, const GColor *illum, double length, GColor *result);
int gtexblend_normal(const GTexBlend *b, GSurfPoint *sp, GVec3 *n);
int gtexblend_diffuse(const GTexBlend *b, GSurfPoint *sp, GColor *result);
int gtexblend_opaque(const GTexBlend *b, GSurfPoint *sp);

/** Storage for up to two temporary colours: on sp->scratch when there is one, else in a small buffer
 * on the caller's stack (enough for models of up to GTEX_STACK_FLOATS floats). */
#define GTEX_STACK_FLOATS 64
typedef struct GTexTemps {
    GScratch *scratch; /**< the arena a mark was taken on (NULL before the first colour) */
    GScratchMark mark;
    float stack[2][GTEX_STACK_FLOATS];
} GTexTemps;

/** Starts an empty set of temporaries (the stack buffers are left uninitialised). */
static inline void gtextemps_init(GTexTemps *t) { t->scratch = NULL; }
/** Gives c temporary storage of model m (index 0 or 1 selects the stack buffer); G_ERR_NOMEM when the
 * arena cannot grow or there is no arena and the model is too big for the stack buffer. */
int gtextemps_color(GTexTemps *t, GSurfPoint *sp, const GColorModel *m, int index, GColor *c);
/** Returns the arena to where it was before the first gtextemps_color. */
void gtextemps_release(GTexTemps *t);

/** Multiplies a colour result by a scalar generator value or a texel colour: the methods of the scale and
 * image nodes share this list. 1 for the methods whose colour carries light (reflection, refraction,
 * emission, ambient, diffuse). */
int gtexnode_scales_method(GNodeMethod m);

/** Checks a node's children (non-NULL, one colour model) and its generator (non-NULL when gen_needed);
 * *model gets the common model. Messages name the node. */
int gtexnode_check(const char *node, GMaterial *const *children, int n, const GGenerator *gen, int gen_needed,
                   const GColorModel **model, GError *err);

/** gtexnode_check (messages naming the class), then gmat_new in the children's model: a zeroed node of
 * `size` bytes into *out, freed with gmem_free until it is complete. */
int gtexnode_new_checked(const GMaterialClass *cls, GMaterial *const *children, int n, const GGenerator *gen,
                         int gen_needed, size_t size, GMaterial **out, GError *err);

/** The start of a node with one child (bump, scale, image): the node's struct begins with it. */
typedef struct GTexChild {
    GMaterial base;
    GMaterial *child;
} GTexChild;
/** The child of such a node. */
static inline GMaterial *gtexchild_of(const GMaterial *self) { return ((const GTexChild *)self)->child; }
/** Methods of such nodes that pass the call on to the child unchanged, for their class tables. */
int gtexchild_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result);
int gtexchild_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         const GColor *rel_index, GVec3 out, GColor *result);
int gtexchild_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result);
int gtexchild_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir);
int gtexchild_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                             GVec3 *dir);
int gtexchild_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result);
int gtexchild_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result);
int gtexchild_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                         GColor *result);
int gtexchild_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n);
int gtexchild_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result);
int gtexchild_opaque(const GMaterial *self, GSurfPoint *sp);

/** The state of a node that picks among n children by a generator's value (select, spline); the node's
 * struct begins with it. */
typedef struct GTexList {
    GMaterial base;
    GGenerator *gen;
    int n;
    GMaterial **children;
} GTexList;
/** Creates a node of class cls whose struct (`size` bytes) begins with a GTexList holding a reference to
 * each of the n children and to gen (all checked with gtexnode_check). */
int gtexlist_new(const GMaterialClass *cls, GMaterial *const *children, int n, GGenerator *gen, size_t size,
                 GMaterial **out, GError *err);
/** The destroy method of the nodes whose struct begins with a GTexList. */
void gtexlist_destroy(GMaterial *self);

#endif
