/* csg.c - the csg generator: 1 inside a CSG solid (generic/kit/shapes.h), 0 outside, at the point in object or
 * world space:
 *
 *   generator NAME csg { space object|world  shape SOLID }
 *   SOLID := sphere R | box X0 Y0 Z0 X1 Y1 Z1 | cylinder R Z0 Z1 | cone R0 Z0 R1 Z1 | halfspace NX NY NZ D
 *          | union { SOLID ... } | intersection { SOLID ... } | difference { SOLID SOLID ... }
 *          | transform { translate X Y Z  rotate AXIS DEG  scale S ... } SOLID
 * (vectors may also be written <x, y, z>). Several solids in an operation combine from the left:
 * difference { a b c } is a minus b minus c. */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/shapes.h>
#include <generic/kit/texture_parse.h>

#include <string.h>

typedef struct Csg {
    GGenerator base;
    GCsgShape *root;
} Csg;

static void csg_destroy(GGenerator *self)
{
    gcsg_destroy(((Csg *)self)->root);
    gmem_free(self);
}

static double csg_value(const GGenerator *self, GSurfPoint *sp)
{
    GVec3 p = self->space == GGENERATOR_SPACE_WORLD ? sp->point : sp->object_point;
    return gcsg_inside(((const Csg *)self)->root, p) ? 1.0 : 0.0;
}

static const GGeneratorClass csg_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "csg",
    .description = "1 inside a CSG solid, 0 outside",
    .destroy = csg_destroy,
    .value = csg_value,
};

int ggenerator_csg_create(GCsgShape *root, GGeneratorSpace space, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!root)
        return gerror_set(err, G_ERR_INVALID, "csg: no shape given");
    if (space != GGENERATOR_SPACE_NONE && space != GGENERATOR_SPACE_OBJECT && space != GGENERATOR_SPACE_WORLD) {
        gcsg_destroy(root);
        return gerror_set(err, G_ERR_INVALID, "csg: space must be object or world");
    }
    GGenerator *gen;
    if (space != GGENERATOR_SPACE_WORLD)
        space = GGENERATOR_SPACE_OBJECT;
    int rc = ggenerator_new(&csg_class, space, sizeof(Csg), &gen, err);
    if (rc != G_OK) {
        gcsg_destroy(root);
        return rc;
    }
    Csg *c = (Csg *)gen;
    c->root = root;
    *out = &c->base;
    return G_OK;
}

/* ---- text ---- */

enum { MAX_SHAPE_DEPTH = 64 };

static const char *const op_names[] = {"union", "intersection", "difference", NULL};

/* Places a constructor's message at the last token read. */
static int located(GReader *r, int rc, GError *err) { return rc == G_OK ? G_OK : greader_locate(r, err); }

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
        return located(
            r, k == 2 ? gcsg_cylinder(a[0], a[1], a[2], out, err) : gcsg_cone(a[0], a[1], a[2], a[3], out, err), err);
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

static int parse_csg(GReader *r, const void *vtable, void **object, GError *err)
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
    rc = ggenerator_csg_create(root, space ? GGENERATOR_SPACE_WORLD : GGENERATOR_SPACE_OBJECT, &g, err);
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = g;
    return G_OK;
}

static const GParamInfo csg_params[] = {
    {"space", GPARAM_NAMED, "choice", "object", "object, world", "the space the solid is placed in"},
    {"shape", GPARAM_NAMED, "shape", NULL,
     "SOLID := sphere R | box X0 Y0 Z0 X1 Y1 Z1 | cylinder R Z0 Z1 | cone R0 Z0 R1 Z1 | halfspace NX NY NZ D | "
     "union { SOLID ... } | intersection { SOLID ... } | difference { SOLID SOLID ... } | "
     "transform { translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... } SOLID",
     "the solid: the value is 1 inside, 0 outside; several solids of an operation combine from the left"},
    {NULL},
};

GENERIC_TYPE_PARAMS(csg, GKIND_GENERATOR, &csg_class, parse_csg, ggenerator_release, csg_params);
