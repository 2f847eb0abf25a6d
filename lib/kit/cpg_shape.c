/* cpg_shape.c - CPG trees (constructive planar geometry): squares, circles and closed contours
 * (lib/kit/cpg_path.c) with boolean operations and affine transforms (generic/shapes.h), for the cpg
 * generator (textures/cpg.c). */
#include "cpg_internal.h"

#include <math.h>

enum { SQUARE, CIRCLE, CONTOUR, COMBINE };

struct GCpgShape {
    int type;
    int op;       /* GShapeOp of COMBINE */
    int moved;
    GAffine2 inv; /* parent coordinates -> the shape's own */
    double cx, cy, size;
    GCpgContour contour;
    GCpgShape *a, *b;
};

static int make(int type, GCpgShape **out, GError *err)
{
    *out = gmem_calloc(1, sizeof **out);
    if (!*out)
        return gerror_set(err, G_ERR_NOMEM, "cpg: out of memory");
    (*out)->type = type;
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
    *out = NULL;
    int rc;
    if ((unsigned)op > GSHAPE_DIFFERENCE)
        rc = gerror_set(err, G_ERR_INVALID, "cpg: unknown operation %d", (int)op);
    else if (!a || !b)
        rc = gerror_set(err, G_ERR_INVALID, "cpg: an operation needs two shapes");
    else
        rc = make(COMBINE, out, err);
    if (rc != G_OK) {
        gcpg_destroy(a);
        gcpg_destroy(b);
        return rc;
    }
    (*out)->op = (int)op;
    (*out)->a = a;
    (*out)->b = b;
    return G_OK;
}

int gcpg_transform(GCpgShape *s, const GAffine2 *m, GError *err)
{
    GAffine2 inv;
    if (gaffine2_invert(m, &inv, NULL) != G_OK)
        return gerror_set(err, G_ERR_INVALID, "cpg: transform is singular or not finite");
    s->inv = gaffine2_mul(&s->inv, &inv);
    s->moved = 1;
    return G_OK;
}

int gcpg_inside(const GCpgShape *s, double x, double y)
{
    if (s->moved)
        gaffine2_apply(&s->inv, x, y, &x, &y);
    switch (s->type) {
    case SQUARE: return fabs(x - s->cx) <= s->size && fabs(y - s->cy) <= s->size;
    case CIRCLE: {
        double dx = x - s->cx, dy = y - s->cy;
        return dx * dx + dy * dy <= s->size * s->size;
    }
    case CONTOUR: return gtexcpg_winding(&s->contour, x, y) != 0;
    default:
        switch (s->op) {
        case GSHAPE_UNION: return gcpg_inside(s->a, x, y) || gcpg_inside(s->b, x, y);
        case GSHAPE_INTERSECTION: return gcpg_inside(s->a, x, y) && gcpg_inside(s->b, x, y);
        default: return gcpg_inside(s->a, x, y) && !gcpg_inside(s->b, x, y);
        }
    }
}

void gcpg_destroy(GCpgShape *s)
{
    if (!s)
        return;
    gcpg_destroy(s->a);
    gcpg_destroy(s->b);
    gtexcpg_contour_free(&s->contour);
    gmem_free(s);
}
