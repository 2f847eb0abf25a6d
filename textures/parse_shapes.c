/* parse_shapes.c - text format parse routines of the csg and cpg generators and their shape trees:
 *
 *   generator NAME csg { space object|world  shape SOLID }
 *   SOLID := sphere R | box X0 Y0 Z0 X1 Y1 Z1 | cylinder R Z0 Z1 | cone R0 Z0 R1 Z1 | halfspace NX NY NZ D
 *          | union { SOLID ... } | intersection { SOLID ... } | difference { SOLID SOLID ... }
 *          | transform { translate X Y Z  rotate AXIS DEG  scale S ... } SOLID
 *
 *   generator NAME cpg { shape SHAPE }
 *   SHAPE := square CX CY SIDE | circle CX CY R | polygon { X Y X Y ... } | path { EDGE ... }
 *          | union { SHAPE ... } | intersection { SHAPE ... } | difference { SHAPE SHAPE ... }
 *          | transform { translate U V  rotate DEG  scale S [S2] ... } SHAPE
 *   EDGE  := lines { X Y ... } | bezier { X Y ... }   (degree = points - 1)
 *          | bspline { degree N  periodic BOOL  points { X Y ... } }
 *          | nurbs { degree N  points { X Y ... }  weights { W ... }  knots { U ... } }
 * (vectors may also be written <x, y, z>). Several shapes in an operation combine from the left:
 * difference { a b c } is a minus b minus c. */
#include "generic/reader.h"
#include "generic/textures.h"
#include "parse_common.h"
#include "textures_builtin.h"

#include <string.h>

enum { MAX_SHAPE_DEPTH = 64 };

static const char *const op_names[] = {"union", "intersection", "difference", NULL};

/* Places a constructor's message at the last token read. */
static int located(GReader *r, int rc, GError *err) { return rc == G_OK ? G_OK : greader_locate(r, err); }

/* ---- CSG ---- */

static int solid(GReader *r, int depth, GCsgShape **out, GError *err);

static int solid_list(GReader *r, int depth, GShapeOp op, GCsgShape **out, GError *err)
{
    int rc = greader_block_begin(r, err);
    GCsgShape *acc = NULL;
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        GCsgShape *s;
        rc = solid(r, depth + 1, &s, err);
        if (rc == G_OK && acc)
            rc = located(r, gcsg_combine(op, acc, s, &acc, err), err);
        else if (rc == G_OK)
            acc = s;
    }
    if (rc < 0) {
        gcsg_destroy(acc);
        return rc;
    }
    if (!acc)
        return greader_error(r, err, "csg %s: no shapes given", op_names[op]);
    *out = acc;
    return G_OK;
}

static int solid(GReader *r, int depth, GCsgShape **out, GError *err)
{
    static const char *const kinds[] = {"sphere",    "box",   "cylinder",     "cone",       "halfspace",
                                        "transform", "union", "intersection", "difference", NULL};
    *out = NULL;
    if (depth > MAX_SHAPE_DEPTH)
        return greader_error(r, err, "csg: shapes nested more than %d deep", MAX_SHAPE_DEPTH);
    int k, rc = greader_choice(r, kinds, &k, err);
    if (rc != G_OK)
        return rc;
    double a[4] = {0, 0, 0, 0};
    GVec3 p, q;
    switch (k) {
    case 0:
        rc = greader_number(r, &a[0], err);
        return rc ? rc : located(r, gcsg_sphere(a[0], out, err), err);
    case 1:
        rc = greader_vec3(r, &p, err);
        if (rc == G_OK)
            rc = greader_vec3(r, &q, err);
        return rc ? rc : located(r, gcsg_box(p, q, out, err), err);
    case 2:
    case 3:
        for (int i = 0; i < (k == 2 ? 3 : 4) && rc == G_OK; i++)
            rc = greader_number(r, &a[i], err);
        if (rc != G_OK)
            return rc;
        return located(r, k == 2 ? gcsg_cylinder(a[0], a[1], a[2], out, err) : gcsg_cone(a[0], a[1], a[2], a[3], out, err),
                       err);
    case 4:
        rc = greader_vec3(r, &p, err);
        if (rc == G_OK)
            rc = greader_number(r, &a[0], err);
        return rc ? rc : located(r, gcsg_halfspace(p, a[0], out, err), err);
    case 5: {
        GAffine3 m;
        rc = gtexparse_xyz_steps(r, &m, err);
        if (rc == G_OK)
            rc = solid(r, depth + 1, out, err);
        if (rc == G_OK && (rc = located(r, gcsg_transform(*out, &m, err), err)) != G_OK) {
            gcsg_destroy(*out);
            *out = NULL;
        }
        return rc;
    }
    default: return solid_list(r, depth, (GShapeOp)(k - 6), out, err);
    }
}

int gtexparse_csg(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    static const char *const space_names[] = {"object", "world", NULL};
    GCsgShape *root = NULL;
    int space = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "shape") == 0 && !root)
            rc = solid(r, 0, &root, err);
        else if (strcmp(key, "space") == 0)
            rc = greader_choice(r, space_names, &space, err);
        else
            rc = greader_unknown_param(r, "space, shape", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !root)
        rc = greader_error(r, err, "csg: needs a shape");
    if (rc < 0) {
        gcsg_destroy(root);
        return rc;
    }
    GGenerator *g = NULL;
    rc = ggen_csg_create(root, space ? GGENERATOR_SPACE_WORLD : GGENERATOR_SPACE_OBJECT, &g, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = g;
    return G_OK;
}

/* ---- CPG ---- */

/* Named parameters of a bspline or nurbs edge inside its block. */
static int curve_edge(GReader *r, GCpgPath *path, int nurbs, GError *err)
{
    static const char *const bkeys[] = {"degree", "periodic", "points", NULL};
    static const char *const nkeys[] = {"degree", "points", "weights", "knots", NULL};
    double *pts = NULL, *w = NULL, *knots = NULL;
    int npts = 0, nw = 0, nknots = 0, periodic = 0, line = 0, col = 0;
    long degree = nurbs ? 2 : 3;
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int k;
        rc = greader_choice(r, nurbs ? nkeys : bkeys, &k, err);
        if (rc != G_OK)
            break;
        const char *key = (nurbs ? nkeys : bkeys)[k];
        if (strcmp(key, "degree") == 0)
            rc = greader_int(r, 1, GCPG_MAX_DEGREE, &degree, err);
        else if (strcmp(key, "periodic") == 0)
            rc = greader_bool(r, &periodic, err);
        else if (strcmp(key, "points") == 0) {
            greader_position(r, &line, &col);
            rc = gtexparse_numbers(r, &pts, &npts, err);
        } else if (strcmp(key, "weights") == 0)
            rc = gtexparse_numbers(r, &w, &nw, err);
        else
            rc = gtexparse_numbers(r, &knots, &nknots, err);
    }
    if (rc >= 0) {
        const char *what = nurbs ? "nurbs" : "bspline";
        int n = npts / 2;
        rc = G_OK;
        if (npts % 2)
            rc = greader_error(r, err, "cpg %s: points need pairs of numbers, got %d numbers", what, npts);
        else if (w && nw != n)
            rc = greader_error(r, err, "cpg nurbs: %d weights for %d points", nw, n);
        else if (knots && nknots != n + (int)degree + 1)
            rc = greader_error(r, err, "cpg nurbs: %d knots, degree %ld with %d points needs %d", nknots, degree, n,
                               n + (int)degree + 1);
        else {
            rc = nurbs ? gcpg_path_nurbs(path, (int)degree, pts, w, n, knots, err)
                       : gcpg_path_bspline(path, (int)degree, pts, n, periodic, err);
            if (rc != G_OK && line) {
                char msg[sizeof err->message];
                strcpy(msg, err->message);
                rc = greader_error_at(r, err, rc, line, col, "%s", msg);
            }
        }
    }
    gmem_free(pts);
    gmem_free(w);
    gmem_free(knots);
    return rc;
}

static int path_shape(GReader *r, GCpgShape **out, GError *err)
{
    static const char *const edges[] = {"lines", "bezier", "bspline", "nurbs", NULL};
    GCpgPath *path;
    int rc = gcpg_path_create(&path, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int k;
        rc = greader_choice(r, edges, &k, err);
        if (rc != G_OK)
            break;
        if (k >= 2) {
            rc = curve_edge(r, path, k == 3, err);
            continue;
        }
        double *v = NULL;
        int n = 0;
        rc = gtexparse_numbers(r, &v, &n, err);
        if (rc == G_OK && n % 2)
            rc = greader_error(r, err, "cpg %s: points need pairs of numbers, got %d numbers", edges[k], n);
        else if (rc == G_OK)
            rc = located(r, k == 0 ? gcpg_path_lines(path, v, n / 2, err) : gcpg_path_bezier(path, n / 2 - 1, v, err),
                         err);
        gmem_free(v);
    }
    if (rc < 0) {
        gcpg_path_destroy(path);
        return rc;
    }
    return located(r, gcpg_path_close(path, out, err), err);
}

static int shape(GReader *r, int depth, GCpgShape **out, GError *err);

static int shape_list(GReader *r, int depth, GShapeOp op, GCpgShape **out, GError *err)
{
    int rc = greader_block_begin(r, err);
    GCpgShape *acc = NULL;
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        GCpgShape *s;
        rc = shape(r, depth + 1, &s, err);
        if (rc == G_OK && acc)
            rc = located(r, gcpg_combine(op, acc, s, &acc, err), err);
        else if (rc == G_OK)
            acc = s;
    }
    if (rc < 0) {
        gcpg_destroy(acc);
        return rc;
    }
    if (!acc)
        return greader_error(r, err, "cpg %s: no shapes given", op_names[op]);
    *out = acc;
    return G_OK;
}

static int shape(GReader *r, int depth, GCpgShape **out, GError *err)
{
    static const char *const kinds[] = {"square", "circle", "polygon",      "path",       "transform",
                                        "union",  "intersection", "difference", NULL};
    *out = NULL;
    if (depth > MAX_SHAPE_DEPTH)
        return greader_error(r, err, "cpg: shapes nested more than %d deep", MAX_SHAPE_DEPTH);
    int k, rc = greader_choice(r, kinds, &k, err);
    if (rc != G_OK)
        return rc;
    double a[3];
    switch (k) {
    case 0:
    case 1:
        for (int i = 0; i < 3 && rc == G_OK; i++)
            rc = greader_number(r, &a[i], err);
        if (rc != G_OK)
            return rc;
        return located(r, k == 0 ? gcpg_square(a[0], a[1], a[2], out, err) : gcpg_circle(a[0], a[1], a[2], out, err),
                       err);
    case 2: {
        double *v = NULL;
        int n = 0;
        rc = gtexparse_numbers(r, &v, &n, err);
        if (rc == G_OK && n % 2)
            rc = greader_error(r, err, "cpg polygon: points need pairs of numbers, got %d numbers", n);
        else if (rc == G_OK)
            rc = located(r, gcpg_polygon(v, n / 2, out, err), err);
        gmem_free(v);
        return rc;
    }
    case 3: return path_shape(r, out, err);
    case 4: {
        GAffine2 m;
        rc = gtexparse_uv_steps(r, &m, err);
        if (rc == G_OK)
            rc = shape(r, depth + 1, out, err);
        if (rc == G_OK && (rc = located(r, gcpg_transform(*out, &m, err), err)) != G_OK) {
            gcpg_destroy(*out);
            *out = NULL;
        }
        return rc;
    }
    default: return shape_list(r, depth, (GShapeOp)(k - 5), out, err);
    }
}

int gtexparse_cpg(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GCpgShape *root = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "shape") == 0 && !root)
            rc = shape(r, 0, &root, err);
        else
            rc = greader_unknown_param(r, "shape", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !root)
        rc = greader_error(r, err, "cpg: needs a shape");
    if (rc < 0) {
        gcpg_destroy(root);
        return rc;
    }
    GGenerator *g = NULL;
    rc = ggen_cpg_create(root, &g, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = g;
    return G_OK;
}
