/* cpg_shape.c - CPG trees (constructive planar geometry): squares, circles and closed contours
 * (lib/kit/cpg_path.c) with boolean operations and affine transforms (generic/kit/shapes.h), for the cpg
 * generator (textures/cpg.c). */
#include "cpg_internal.h"
#include "shape_tree.h"

#include <math.h>

enum { SQUARE, CIRCLE, CONTOUR };

struct GCpgShape {
    GShapeNode node; /* operation, operands, depth, moved (inv is not the identity); first */
    int type;        /* of a shape (not an operation) */
    GAffine2 inv;    /* parent coordinates -> the shape's own */
    double cx, cy, size;
    GCpgContour contour;
};

static void free_contour(GShapeNode *node) { gtexcpg_contour_free(&((GCpgShape *)node)->contour); }

static int make(int type, GCpgShape **out, GError *err)
{
    *out = gmem_calloc(1, sizeof **out);
    if (!*out)
        return gerror_set(err, G_ERR_NOMEM, "cpg: out of memory");
    (*out)->type = type;
    (*out)->node.depth = 1;
    (*out)->inv = gaffine2_identity();
    return G_OK;
}

int gcpg_square(double cx, double cy, double side, GCpgShape **out, GError *err)
{
    *out = NULL;
    if (!isfinite(cx) || !isfinite(cy) || !(side > 0.0) || !isfinite(side))
        return gerror_set(err, G_ERR_INVALID, "cpg square: needs a finite centre and a positive side, got %g", side);
    int rc = make(SQUARE, out, err);
    if (rc == G_OK) {
        (*out)->cx = cx;
        (*out)->cy = cy;
        (*out)->size = 0.5 * side;
    }
    return rc;
}

int gcpg_circle(double cx, double cy, double radius, GCpgShape **out, GError *err)
{
    *out = NULL;
    if (!isfinite(cx) || !isfinite(cy) || !(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "cpg circle: needs a finite centre and a positive radius, got %g",
                          radius);
    int rc = make(CIRCLE, out, err);
    if (rc == G_OK) {
        (*out)->cx = cx;
        (*out)->cy = cy;
        (*out)->size = radius;
    }
    return rc;
}

int gcpg_polygon(const double *xy, int n, GCpgShape **out, GError *err)
{
    *out = NULL;
    if (n < 3)
        return gerror_set(err, G_ERR_INVALID, "cpg polygon: needs at least 3 points, got %d", n);
    GCpgPath *p;
    int rc = gcpg_path_create(&p, err);
    if (rc != G_OK)
        return rc;
    rc = gcpg_path_lines(p, xy, n, err);
    if (rc != G_OK) {
        gcpg_path_destroy(p);
        return rc;
    }
    return gcpg_path_close(p, out, err);
}

int gtexcpg_shape_from_contour(GCpgContour *c, GCpgShape **out, GError *err)
{
    int rc = make(CONTOUR, out, err);
    if (rc != G_OK) {
        gtexcpg_contour_free(c);
        return rc;
    }
    (*out)->contour = *c;
    c->segs = NULL;
    c->n = 0;
    return G_OK;
}

int gcpg_combine(GShapeOp op, GCpgShape *a, GCpgShape *b, GCpgShape **out, GError *err)
{
    GShapeNode *s = NULL;
    int rc = gshape_combine("cpg", op, a ? &a->node : NULL, b ? &b->node : NULL, sizeof(GCpgShape), free_contour, &s,
                            err);
    *out = (GCpgShape *)s;
    if (rc == G_OK && s != &a->node)
        (*out)->inv = gaffine2_identity();
    return rc;
}

int gcpg_transform(GCpgShape *s, const GAffine2 *m, GError *err)
{
    GAffine2 inv;
    if (gaffine2_invert(m, &inv, NULL) != G_OK)
        return gerror_set(err, G_ERR_INVALID, "cpg: transform is singular or not finite");
    s->inv = gaffine2_mul(&s->inv, &inv);
    s->node.moved = 1;
    return G_OK;
}

/* Recursion as deep as the tree, at most GSHAPE_MAX_DEPTH (gshape_combine refuses deeper trees). */
int gcpg_inside(const GCpgShape *s, double x, double y)
{
    if (s->node.moved)
        gaffine2_apply(&s->inv, x, y, &x, &y);
    if (s->node.combine) {
        GCpgShape *const *k = (GCpgShape *const *)s->node.kids;
        int n = s->node.n;
        switch (s->node.op) {
        case GSHAPE_UNION:
            for (int i = 0; i < n; i++)
                if (gcpg_inside(k[i], x, y))
                    return 1;
            return 0;
        case GSHAPE_INTERSECTION:
            for (int i = 0; i < n; i++)
                if (!gcpg_inside(k[i], x, y))
                    return 0;
            return 1;
        default:
            if (!gcpg_inside(k[0], x, y))
                return 0;
            for (int i = 1; i < n; i++)
                if (gcpg_inside(k[i], x, y))
                    return 0;
            return 1;
        }
    }
    switch (s->type) {
    case SQUARE: return fabs(x - s->cx) <= s->size && fabs(y - s->cy) <= s->size;
    case CIRCLE: {
        double dx = x - s->cx, dy = y - s->cy;
        return dx * dx + dy * dy <= s->size * s->size;
    }
    default: return gtexcpg_winding(&s->contour, x, y) != 0;
    }
}

void gcpg_destroy(GCpgShape *s) { gshape_destroy(s ? &s->node : NULL, free_contour); }
