/* shape_tree.h - what the CSG and CPG trees (lib/kit/csg_shape.c, lib/kit/cpg_shape.c) share: n-ary
 * operation nodes, so that a long operand list is one flat node and not a deep chain of pairs, the depth
 * bound (GSHAPE_MAX_DEPTH) checked as a tree is built, and a destroy that does not recurse. Internal. */
#ifndef GENERIC_KIT_SHAPE_TREE_H
#define GENERIC_KIT_SHAPE_TREE_H

#include "generic/export.h"
#include "generic/kit/shapes.h"

#include <stddef.h>

/** The start of every CSG and CPG node. */
typedef struct GShapeNode {
    int combine;              /* 1 for an operation node, 0 for a shape */
    int op;                   /* GShapeOp of an operation */
    int moved;                /* the node has a transform of its own */
    int depth;                /* 1 for a shape, 1 + the deepest operand's for an operation */
    int n, cap;               /* operands of an operation */
    struct GShapeNode **kids; /* union: any; intersection: all; difference: the first and none of the rest */
    struct GShapeNode *next;  /* gshape_destroy's work list */
} GShapeNode;

/** Frees what a shape node owns besides the node (NULL: nothing). */
typedef void (*GShapeFreeFn)(GShapeNode *node);

/** gcsg_combine / gcpg_combine for nodes of `size` bytes (what names the tree in messages): a operand list
 * grows in place when a is an operation of the same kind without a transform of its own (b's operands are
 * taken over when b is a like union or intersection), else a new node of two operands; G_ERR_INVALID when
 * the result would be deeper than GSHAPE_MAX_DEPTH. Takes ownership of a and b, also when it fails. */
GENERIC_NODISCARD int gshape_combine(const char *what, GShapeOp op, GShapeNode *a, GShapeNode *b, size_t size,
                                     GShapeFreeFn free_fn, GShapeNode **out, GError *err);
/** Frees a tree without recursion; NULL is a no-op. */
void gshape_destroy(GShapeNode *s, GShapeFreeFn free_fn);

#endif
