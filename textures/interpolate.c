/* interpolate.c - the interpolate node (two children blended by a generator) and, sharing its state and
 * methods, the interpolate-one node (one method blended, the rest from the first child):
 *
 *   node NAME interpolate     { a MATERIAL  b MATERIAL  t GENERATOR }
 *   node NAME interpolate-one { a MATERIAL  b MATERIAL  t GENERATOR  method refraction_index }
 *
 * Both are blend nodes (generic/kit/node_kit.h): their class tables take every material method from the kit, and
 * pick below says which children answer a call. */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <stdio.h>
#include <string.h>

typedef struct Interp {
    GMaterial base;
    GMaterial *a, *b;
    GGenerator *t;
    int only; /* -1: every method is blended; else the one GNodeMethod that is */
} Interp;

static void interp_destroy(GMaterial *self)
{
    Interp *n = (Interp *)self;
    gmaterial_unref(n->a);
    gmaterial_unref(n->b);
    ggenerator_unref(n->t);
    gmem_free(n);
}

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *blend)
{
    const Interp *n = (const Interp *)self;
    if (!sp || (n->only >= 0 && n->only != (int)m))
        gnode_blend_one(blend, n->a);
    else
        gnode_blend_pair(blend, n->a, n->b, ggenerator_cached_value(n->t, sp));
}

static const GNodeBlendClass interpolate_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "interpolate",
             .description = "two children blended by a generator value in [0, 1]",
             .destroy = interp_destroy,
             GNODE_BLENDED_METHODS},
    .pick = pick,
};

static const GNodeBlendClass interpolate_one_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "interpolate-one",
             .description = "one method blended by a generator, the others from the first child",
             .destroy = interp_destroy,
             GNODE_BLENDED_METHODS},
    .pick = pick,
};

static int make(const GNodeBlendClass *cls, GMaterial *a, GMaterial *b, GGenerator *t, int only, GMaterial **out,
                GError *err)
{
    *out = NULL;
    GMaterial *children[2] = {a, b};
    GMaterial *node;
    int rc = gnode_new_checked(&cls->base, children, 2, t, 1, sizeof(Interp), &node, err);
    if (rc != G_OK)
        return rc;
    Interp *n = (Interp *)node;
    n->a = gmaterial_ref(a);
    n->b = gmaterial_ref(b);
    n->t = ggenerator_ref(t);
    n->only = only;
    if (only != GNODE_REFLECTION && only != GNODE_DIFFUSE) /* pick blends both alike, or gives a for both */
        gnode_inherit_lambertian(node, children, 2);
    gnode_inherit_no_uv(node, children, 2, t); /* reads the point only through t */
    if (only >= 0 && only != GNODE_ABSORPTION) /* pick gives a alone for absorption: a's, unchanged */
        gnode_inherit_clear(node, children, 1);
    *out = &n->base;
    return G_OK;
}

int gnode_interpolate_create(GMaterial *a, GMaterial *b, GGenerator *t, GMaterial **out, GError *err)
{
    return make(&interpolate_class, a, b, t, -1, out, err);
}

int gnode_interpolate_one_create(GMaterial *a, GMaterial *b, GGenerator *t, GNodeMethod method, GMaterial **out,
                                 GError *err)
{
    *out = NULL;
    if ((unsigned)method >= GNODE_METHOD_COUNT)
        return gerror_set(err, G_ERR_INVALID, "interpolate-one: unknown method %d", (int)method);
    return make(&interpolate_one_class, a, b, t, (int)method, out, err);
}

/* The parameters of both; `one` reads the method too. */
static int parse(GReader *r, int one, void **object, GError *err)
{
    GMaterial *a = NULL, *b = NULL;
    GGenerator *t = NULL;
    int method = -1;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "a") == 0)
            rc = greader_material(r, &a, err);
        else if (strcmp(key, "b") == 0)
            rc = greader_material(r, &b, err);
        else if (strcmp(key, "t") == 0)
            rc = gtexparse_generator(r, &t, err);
        else if (one && strcmp(key, "method") == 0) {
            char name[32];
            rc = greader_ident(r, name, sizeof name, err);
            if (rc == G_OK && (method = gnode_method_from_name(name)) < 0) {
                char known[256] = ""; /* the keywords of GNodeMethod, ", " between them */
                for (int i = 0; i < GNODE_METHOD_COUNT; i++)
                    snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", i ? ", " : "",
                             gnode_method_name((GNodeMethod)i));
                rc = greader_error(r, err, "unknown method '%s' (%s)", name, known);
            }
        } else
            rc = greader_unknown_param(r, one ? "a, b, t, method" : "a, b, t", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    const char *name = one ? "interpolate-one" : "interpolate";
    if (!a || !b || !t)
        return greader_error(r, err, "%s: needs a, b and t", name);
    if (one && method < 0)
        return greader_error(r, err, "interpolate-one: needs a method");
    GMaterial *m = NULL;
    rc = one ? gnode_interpolate_one_create(a, b, t, (GNodeMethod)method, &m, err)
             : gnode_interpolate_create(a, b, t, &m, err);
    return gtexparse_finish(r, rc, m, object, err);
}

static int parse_interpolate(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return parse(r, 0, object, err);
}

static int parse_interpolate_one(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return parse(r, 1, object, err);
}

#define INTERPOLATE_PARAMS                                                                                       \
    {"a", GPARAM_NAMED, "material", NULL, NULL, "the child at t <= 0"},                                           \
    {"b", GPARAM_NAMED, "material", NULL, NULL, "the child at t >= 1"},                                           \
    {"t", GPARAM_NAMED, "generator", NULL, NULL, "the weight of b: (1 - t) a + t b; at 0 or 1 one child is called"}

static const GParamInfo interpolate_params[] = {
    INTERPOLATE_PARAMS,
    {NULL},
};

static const GParamInfo interpolate_one_params[] = {
    INTERPOLATE_PARAMS,
    {"method", GPARAM_NAMED, "choice", NULL,
     "reflection, refraction, refraction_index, reflection_dir, refraction_dir, emission, ambient, absorption, "
     "normal, diffuse, opaque",
     "the one material method that is blended; every other is a's"},
    {NULL},
};

GENERIC_TYPE_PARAMS(interpolate, GKIND_NODE, &interpolate_class.base, parse_interpolate, NULL, interpolate_params);
GENERIC_TYPE_PARAMS(interpolate_one, GKIND_NODE, &interpolate_one_class.base, parse_interpolate_one, NULL,
                    interpolate_one_params);
