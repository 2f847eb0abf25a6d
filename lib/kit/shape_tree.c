/* shape_tree.c - n-ary operation nodes, the depth bound and a destroy without recursion for the CSG and CPG
 * trees (lib/kit/shape_tree.h). */
#include "shape_tree.h"
#include "generic/memory.h"

/* Makes room for `more` operands. */
static int reserve(GShapeNode *s, int more)
{
    if (s->n + more <= s->cap)
        return G_OK;
    if (more > (1 << 30) - s->n)
        return G_ERR_NOMEM;
    int cap = s->cap ? s->cap : 4;
    while (cap < s->n + more)
        cap = cap > (1 << 29) ? s->n + more : cap * 2;
    GShapeNode **k = gmem_realloc(s->kids, (size_t)cap * sizeof *k);
    if (!k)
        return G_ERR_NOMEM;
    s->kids = k;
    s->cap = cap;
    return G_OK;
}

/* An operation of this kind whose operand list may grow. */
static int extendable(const GShapeNode *s, GShapeOp op) { return s->combine && !s->moved && s->op == (int)op; }

static int max_int(int a, int b) { return a > b ? a : b; }

int gshape_combine(const char *what, GShapeOp op, GShapeNode *a, GShapeNode *b, size_t size, GShapeFreeFn free_fn,
                   GShapeNode **out, GError *err)
{
    *out = NULL;
    int rc = G_OK;
    if ((unsigned)op > GSHAPE_DIFFERENCE)
        rc = gerror_set(err, G_ERR_INVALID, "%s: unknown operation %d", what, (int)op);
    else if (!a || !b)
        rc = gerror_set(err, G_ERR_INVALID, "%s: an operation needs two shapes", what);
    /* a - (b0 - b1) is not a - b0 - b1: only unions and intersections take over b's operands */
    int grow = rc == G_OK && extendable(a, op);
    int splice = rc == G_OK && op != GSHAPE_DIFFERENCE && extendable(b, op);
    if (rc == G_OK) {
        int depth = grow ? max_int(a->depth, splice ? b->depth : b->depth + 1)
                         : 1 + max_int(a->depth, splice ? b->depth - 1 : b->depth);
        if (depth > GSHAPE_MAX_DEPTH)
            rc = gerror_set(err, G_ERR_INVALID, "%s: shapes nested more than %d deep", what, GSHAPE_MAX_DEPTH);
    }
    GShapeNode *s = NULL;
    if (rc == G_OK && grow) {
        s = a;
    } else if (rc == G_OK) {
        s = gmem_calloc(1, size);
        if (!s || reserve(s, 2) != G_OK) {
            gmem_free(s);
            s = NULL;
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", what);
        } else {
            s->combine = 1;
            s->op = (int)op;
            s->kids[s->n++] = a;
            s->depth = 1 + a->depth;
        }
    }
    if (rc == G_OK && reserve(s, splice ? b->n : 1) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", what);
    if (rc != G_OK) {
        if (s && s != a) { /* the new node holds a */
            s->n = 0;
            gshape_destroy(s, free_fn);
        }
        gshape_destroy(a, free_fn);
        gshape_destroy(b, free_fn);
        return rc;
    }
    if (splice) {
        for (int i = 0; i < b->n; i++)
            s->kids[s->n++] = b->kids[i];
        s->depth = max_int(s->depth, b->depth);
        b->n = 0;
        gshape_destroy(b, free_fn);
    } else {
        s->kids[s->n++] = b;
        s->depth = max_int(s->depth, 1 + b->depth);
    }
    *out = s;
    return G_OK;
}

void gshape_destroy(GShapeNode *s, GShapeFreeFn free_fn)
{
    if (s)
        s->next = NULL;
    while (s) {
        GShapeNode *t = s;
        s = t->next;
        for (int i = 0; i < t->n; i++) {
            t->kids[i]->next = s;
            s = t->kids[i];
        }
        gmem_free(t->kids);
        if (free_fn)
            free_fn(t);
        gmem_free(t);
    }
}
