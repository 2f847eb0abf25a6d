/* cpg.c - the cpg generator: 1 inside a CPG shape (generic/kit/shapes.h), 0 outside, at (u, v):
 *
 *   generator NAME cpg { shape SHAPE }
 *   SHAPE := square CX CY SIDE | circle CX CY R | polygon { X Y X Y ... } | path { EDGE ... }
 *          | union { SHAPE ... } | intersection { SHAPE ... } | difference { SHAPE SHAPE ... }
 *          | transform { translate U V  rotate DEG  scale S [S2] ... } SHAPE
 *   EDGE  := lines { X Y ... } | bezier { X Y ... }   (degree = points - 1)
 *          | bspline { degree N  periodic BOOL  points { X Y ... } }
 *          | nurbs { degree N  points { X Y ... }  weights { W ... }  knots { U ... } }
 * Several shapes in an operation combine from the left: difference { a b c } is a minus b minus c. */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/shapes.h>
#include <generic/kit/texture_parse.h>

#include <string.h>

typedef struct Cpg {
    GGenerator base;
    GCpgShape *root;
} Cpg;

static void cpg_destroy(GGenerator *self)
{
    gcpg_destroy(((Cpg *)self)->root);
    gmem_free(self);
}

static double cpg_value(const GGenerator *self, GSurfPoint *sp)
{
    return gcpg_inside(((const Cpg *)self)->root, sp->u, sp->v) ? 1.0 : 0.0;
}

static const GGeneratorClass cpg_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "cpg",
    .description = "1 inside a 2D shape tree at (u, v), 0 outside",
    .destroy = cpg_destroy,
    .value = cpg_value,
};

int ggenerator_cpg_create(GCpgShape *root, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!root)
        return gerror_set(err, G_ERR_INVALID, "cpg: no shape given");
    GGenerator *gen;
    int rc = ggenerator_new(&cpg_class, GGENERATOR_SPACE_UV, sizeof(Cpg), &gen, err);
    if (rc != G_OK) {
        gcpg_destroy(root);
        return rc;
    }
    Cpg *c = (Cpg *)gen;
    c->root = root;
    *out = &c->base;
    return G_OK;
}

/* ---- text ---- */

enum { MAX_SHAPE_DEPTH = 64 };

static const char *const op_names[] = {"union", "intersection", "difference", NULL};

/* Places a constructor's message at the last token read. */
static int located(GReader *r, int rc, GError *err) { return rc == G_OK ? G_OK : greader_locate(r, err); }

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

static int parse_cpg(GReader *r, const void *vtable, void **object, GError *err)
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
    rc = ggenerator_cpg_create(root, &g, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = g;
    return G_OK;
}

static const GParamInfo cpg_params[] = {
    {"shape", GPARAM_NAMED, "shape", NULL,
     "SHAPE := square CX CY SIDE | circle CX CY R | polygon { X Y ... } | path { EDGE ... } | "
     "union { SHAPE ... } | intersection { SHAPE ... } | difference { SHAPE SHAPE ... } | "
     "transform { translate U V  rotate DEG  scale S [S2] ... } SHAPE; EDGE := lines { X Y ... } | "
     "bezier { X Y ... } | bspline { degree N  periodic BOOL  points { X Y ... } } | "
     "nurbs { degree N  points { X Y ... }  weights { W ... }  knots { U ... } }",
     "the shape in (u, v): the value is 1 inside, 0 outside; several shapes of an operation combine from the left"},
    {NULL},
};

GENERIC_TYPE_PARAMS(cpg, GKIND_GENERATOR, &cpg_class, parse_cpg, ggenerator_release, cpg_params);
