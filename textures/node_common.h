/* node_common.h - code shared by the texture nodes (textures/node_common.c): weighted blends of
 * children for every material method, temporaries, and constructor checks. Internal to the library. */
#ifndef GENERIC_TEXTURES_NODE_COMMON_H
#define GENERIC_TEXTURES_NODE_COMMON_H

#include "generic/material.h"
#include "generic/textures.h"

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

#endif
