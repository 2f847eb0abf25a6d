/* csg_shape.c - CSG trees of solids (sphere, box, cylinder, cone, half-space) with boolean operations and
 * affine transforms (generic/kit/shapes.h), for the csg generator (textures/csg.c). */
#include "generic/memory.h"
#include "generic/kit/shapes.h"
#include "shape_tree.h"

#include <math.h>

enum { SPHERE, BOX, CYLINDER, CONE, HALFSPACE };

struct GCsgShape {
    GShapeNode node; /* operation, operands, depth, moved (inv is not the identity); first */
    int type;        /* of a shape (not an operation) */
    GAffine3 inv;    /* parent coordinates -> the shape's own */
    double r0, r1, z0, z1, offset;
    GVec3 lo, hi, normal;
};

static int finite3(GVec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

static int make(int type, GCsgShape **out, GError *err)
{
    *out = gmem_calloc(1, sizeof **out);
    if (!*out)
        return gerror_set(err, G_ERR_NOMEM, "csg: out of memory");
    (*out)->type = type;
    (*out)->node.depth = 1;
    (*out)->inv = gaffine3_identity();
    return G_OK;
}

int gcsg_sphere(double radius, GCsgShape **out, GError *err)
{
    *out = NULL;
    if (!(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "csg sphere: radius must be positive and finite, got %g", radius);
    int rc = make(SPHERE, out, err);
    if (rc == G_OK)
        (*out)->r0 = radius;
    return rc;
}

int gcsg_box(GVec3 lo, GVec3 hi, GCsgShape **out, GError *err)
{
    *out = NULL;
    if (!finite3(lo) || !finite3(hi) || !(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        return gerror_set(err, G_ERR_INVALID, "csg box: needs finite corners with lo < hi on every axis");
    int rc = make(BOX, out, err);
    if (rc == G_OK) {
        (*out)->lo = lo;
        (*out)->hi = hi;
    }
    return rc;
}

int gcsg_cylinder(double radius, double z0, double z1, GCsgShape **out, GError *err)
{
    *out = NULL;
    if (!(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "csg cylinder: radius must be positive and finite, got %g", radius);
    if (!isfinite(z0) || !isfinite(z1) || !(z0 < z1))
        return gerror_set(err, G_ERR_INVALID, "csg cylinder: needs z0 < z1, got %g and %g", z0, z1);
    int rc = make(CYLINDER, out, err);
    if (rc == G_OK) {
        (*out)->r0 = radius;
        (*out)->z0 = z0;
        (*out)->z1 = z1;
    }
    return rc;
}

int gcsg_cone(double r0, double z0, double r1, double z1, GCsgShape **out, GError *err)
{
    *out = NULL;
    if (!isfinite(r0) || !isfinite(r1) || r0 < 0.0 || r1 < 0.0 || (r0 == 0.0 && r1 == 0.0))
        return gerror_set(err, G_ERR_INVALID, "csg cone: radii must be >= 0 and not both 0, got %g and %g", r0, r1);
    if (!isfinite(z0) || !isfinite(z1) || !(z0 < z1))
        return gerror_set(err, G_ERR_INVALID, "csg cone: needs z0 < z1, got %g and %g", z0, z1);
    int rc = make(CONE, out, err);
    if (rc == G_OK) {
        (*out)->r0 = r0;
        (*out)->r1 = r1;
        (*out)->z0 = z0;
        (*out)->z1 = z1;
    }
    return rc;
}

int gcsg_halfspace(GVec3 normal, double offset, GCsgShape **out, GError *err)
{
    *out = NULL;
    if (!finite3(normal) || gvec3_length(normal) == 0.0 || !isfinite(offset))
        return gerror_set(err, G_ERR_INVALID, "csg half-space: needs a finite non-zero normal and a finite offset");
    int rc = make(HALFSPACE, out, err);
    if (rc == G_OK) {
        (*out)->normal = normal;
        (*out)->offset = offset;
    }
    return rc;
}

int gcsg_combine(GShapeOp op, GCsgShape *a, GCsgShape *b, GCsgShape **out, GError *err)
{
    GShapeNode *s = NULL;
    int rc = gshape_combine("csg", op, a ? &a->node : NULL, b ? &b->node : NULL, sizeof(GCsgShape), NULL, &s, err);
    *out = (GCsgShape *)s;
    if (rc == G_OK && s != &a->node)
        (*out)->inv = gaffine3_identity();
    return rc;
}

int gcsg_transform(GCsgShape *s, const GAffine3 *m, GError *err)
{
    GAffine3 inv;
    if (gaffine3_invert(m, &inv, NULL) != G_OK)
        return gerror_set(err, G_ERR_INVALID, "csg: transform is singular or not finite");
    s->inv = gaffine3_mul(&s->inv, &inv);
    s->node.moved = 1;
    return G_OK;
}

/* Recursion as deep as the tree, at most GSHAPE_MAX_DEPTH (gshape_combine refuses deeper trees). */
int gcsg_inside(const GCsgShape *s, GVec3 p)
{
    if (s->node.moved)
        p = gaffine3_apply(&s->inv, p);
    if (s->node.combine) {
        GCsgShape *const *k = (GCsgShape *const *)s->node.kids;
        int n = s->node.n;
        switch (s->node.op) {
        case GSHAPE_UNION:
            for (int i = 0; i < n; i++)
                if (gcsg_inside(k[i], p))
                    return 1;
            return 0;
        case GSHAPE_INTERSECTION:
            for (int i = 0; i < n; i++)
                if (!gcsg_inside(k[i], p))
                    return 0;
            return 1;
        default:
            if (!gcsg_inside(k[0], p))
                return 0;
            for (int i = 1; i < n; i++)
                if (gcsg_inside(k[i], p))
                    return 0;
            return 1;
        }
    }
    switch (s->type) {
    case SPHERE: return gvec3_dot(p, p) <= s->r0 * s->r0;
    case BOX:
        return p.x >= s->lo.x && p.x <= s->hi.x && p.y >= s->lo.y && p.y <= s->hi.y && p.z >= s->lo.z &&
               p.z <= s->hi.z;
    case CYLINDER: return p.z >= s->z0 && p.z <= s->z1 && p.x * p.x + p.y * p.y <= s->r0 * s->r0;
    case CONE: {
        if (p.z < s->z0 || p.z > s->z1)
            return 0;
        double r = s->r0 + (s->r1 - s->r0) * (p.z - s->z0) / (s->z1 - s->z0);
        return p.x * p.x + p.y * p.y <= r * r;
    }
    default: return gvec3_dot(s->normal, p) <= s->offset;
    }
}

void gcsg_destroy(GCsgShape *s) { gshape_destroy(s ? &s->node : NULL, NULL); }
