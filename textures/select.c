/* select.c - the select node: an integer generator (e.g. the surface index) picks one of n children.
 *
 *   node NAME select { index GENERATOR  children { MATERIAL ... } }
 *
 * A blend node (generic/kit/node_kit.h) whose blend is always one child; its state is a GNodeList (gen is the
 * index). */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
{
    (void)m;
    const GNodeList *s = (const GNodeList *)self;
    int i = 0;
    if (sp) {
        double v = floor(ggenerator_cached_value(s->gen, sp));
        i = !(v > 0.0) ? 0 : v >= s->n - 1 ? s->n - 1 : (int)v; /* NaN picks the first */
    }
    gnode_blend_one(b, s->children[i]);
}

static const GNodeBlendClass select_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "select",
             .description = "one of n children picked by an integer generator (e.g. the surface index)",
             .destroy = gnode_list_destroy,
             GNODE_BLENDED_METHODS},
    .pick = pick,
};

int gnode_select_create(GMaterial *const *children, int n, GGenerator *index, GMaterial **out, GError *err)
{
    int rc = gnode_list_new(&select_class.base, children, n, index, sizeof(GNodeList), out, err);
    if (rc == G_OK) {
        gnode_inherit_lambertian(*out, children, n); /* pick ignores the method: one child for all */
        gnode_inherit_no_uv(*out, children, n, index); /* reads the point only through the index */
        gnode_inherit_clear(*out, children, n); /* its absorption is one child's, unchanged */
    }
    return rc;
}

static int parse_select(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial **kids = NULL;
    int n = 0, have_kids = 0;
    GGenerator *g = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "index") == 0)
            rc = gtexparse_generator(r, &g, err);
        else if (strcmp(key, "children") == 0) {
            rc = gtexparse_materials(r, &kids, &n, err);
            have_kids = 1;
        } else
            rc = greader_unknown_param(r, "index, children", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !g)
        rc = greader_error(r, err, "select: needs index");
    else if (rc == 0 && !have_kids)
        rc = greader_error(r, err, "select: needs children { ... }");
    if (rc == 0) {
        GMaterial *m = NULL;
        rc = gnode_select_create(kids, n, g, &m, err);
        rc = gtexparse_finish(r, rc, m, object, err);
    }
    gmem_free(kids);
    return rc;
}

static const GParamInfo select_params[] = {
    {"index", GPARAM_NAMED, "generator", NULL, NULL,
     "picks the child: its value rounded down, clamped to 0 .. n - 1 (e.g. surface: a material per face)"},
    {"children", GPARAM_NAMED, "block", NULL, "{ MATERIAL ... }", "the children, numbered from 0"},
    {NULL},
};

GENERIC_TYPE_PARAMS(select, GKIND_NODE, &select_class.base, parse_select, NULL, select_params);
