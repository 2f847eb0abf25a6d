/* spline.c - the spline node: n children at t = i / (n - 1) blended by a cubic spline over a generator
 * value (Catmull-Rom by default; uniform B-spline and linear on request):
 *
 *   node NAME spline { t GENERATOR  basis catmull-rom|bspline|linear  children { MATERIAL ... } }
 *
 * A blend node (generic/node_kit.h): pick below gives the children and weights of the segment at t. */
#include <generic/node_kit.h>
#include <generic/plugin.h>
#include <generic/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Spline {
    GTexList list; /* gen is t; first: the class's destroy is gtexlist_destroy */
    int basis;     /* a GSplineBasis */
} Spline;

/* Adds weight w of child i (clamped to the ends) to the blend, merging repeats and skipping zeros. */
static void add(GTexBlend *b, const Spline *s, int i, double w)
{
    if (w == 0.0)
        return;
    const GMaterial *m = s->list.children[i < 0 ? 0 : i >= s->list.n ? s->list.n - 1 : i];
    for (int j = 0; j < b->n; j++)
        if (b->m[j] == m) {
            b->w[j] += w;
            return;
        }
    b->m[b->n] = m;
    b->w[b->n++] = w;
}

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GTexBlend *b)
{
    (void)m;
    const Spline *s = (const Spline *)self;
    b->n = 0;
    if (!sp) {
        add(b, s, 0, 1.0);
        return;
    }
    double t = ggenerator_cached_value(s->list.gen, sp);
    t = !(t > 0.0) ? 0.0 : t > 1.0 ? 1.0 : t;
    double x = t * (s->list.n - 1);
    int k = (int)floor(x);
    if (k > s->list.n - 2)
        k = s->list.n - 2;
    double f = x - k, f2 = f * f, f3 = f2 * f;
    switch (s->basis) {
    case GSPLINE_LINEAR:
        add(b, s, k, 1.0 - f);
        add(b, s, k + 1, f);
        break;
    case GSPLINE_BSPLINE:
        add(b, s, k - 1, (1.0 - f) * (1.0 - f) * (1.0 - f) / 6.0);
        add(b, s, k, (3.0 * f3 - 6.0 * f2 + 4.0) / 6.0);
        add(b, s, k + 1, (-3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0) / 6.0);
        add(b, s, k + 2, f3 / 6.0);
        break;
    default: /* Catmull-Rom */
        add(b, s, k - 1, 0.5 * (-f3 + 2.0 * f2 - f));
        add(b, s, k, 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0));
        add(b, s, k + 1, 0.5 * (-3.0 * f3 + 4.0 * f2 + f));
        add(b, s, k + 2, 0.5 * (f3 - f2));
        break;
    }
    /* merged weights may cancel exactly; drop them so the single-child path is taken */
    int j = 0;
    for (int i = 0; i < b->n; i++)
        if (b->w[i] != 0.0) {
            b->m[j] = b->m[i];
            b->w[j++] = b->w[i];
        }
    b->n = j;
    if (b->n == 0)
        add(b, s, k, 1.0);
}

static const GTexBlendClass spline_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "spline",
             .description = "n children blended by a cubic spline over a generator value",
             .destroy = gtexlist_destroy,
             GTEXBLEND_NODE_METHODS},
    .pick = pick,
};

int gnode_spline_create(GMaterial *const *children, int n, GGenerator *t, GSplineBasis basis, GMaterial **out,
                        GError *err)
{
    *out = NULL;
    if (children && n == 1)
        return gerror_set(err, G_ERR_INVALID, "spline: needs at least 2 children, got 1");
    if ((unsigned)basis > GSPLINE_LINEAR)
        return gerror_set(err, G_ERR_INVALID, "spline: unknown basis %d", (int)basis);
    int rc = gtexlist_new(&spline_class.base, children, n, t, sizeof(Spline), out, err);
    if (rc == G_OK)
        ((Spline *)*out)->basis = (int)basis;
    return rc;
}

static int parse_spline(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    static const char *const basis_names[] = {"catmull-rom", "bspline", "linear", NULL};
    GMaterial **kids = NULL;
    int n = 0, basis = GSPLINE_CATMULL_ROM, have_kids = 0;
    GGenerator *g = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "t") == 0)
            rc = gtexparse_generator(r, &g, err);
        else if (strcmp(key, "children") == 0) {
            rc = gtexparse_materials(r, &kids, &n, err);
            have_kids = 1;
        } else if (strcmp(key, "basis") == 0)
            rc = greader_choice(r, basis_names, &basis, err);
        else
            rc = greader_unknown_param(r, "t, basis, children", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !g)
        rc = greader_error(r, err, "spline: needs t");
    else if (rc == 0 && !have_kids)
        rc = greader_error(r, err, "spline: needs children { ... }");
    if (rc == 0) {
        GMaterial *m = NULL;
        rc = gnode_spline_create(kids, n, g, (GSplineBasis)basis, &m, err);
        rc = gtexparse_finish(r, rc, m, object, err);
    }
    gmem_free(kids);
    return rc;
}

GENERIC_TYPE(spline, GKIND_NODE, &spline_class.base, parse_spline, NULL);
