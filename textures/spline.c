/* spline.c - the spline node: n children at t = i / (n - 1), or at the keys of a ramp, blended by a cubic
 * spline over a generator value (Catmull-Rom by default; uniform B-spline and linear on request):
 *
 *   node NAME spline { t GENERATOR  basis catmull-rom|bspline|linear  children { MATERIAL ... } }
 *   node NAME spline { t GENERATOR  basis ...  ramp { KEY MATERIAL  KEY MATERIAL ... } }
 *   node NAME spline { t GENERATOR  basis ...  colors [of BASE PARAMETER] { KEY COLOR  KEY COLOR ... } }
 *
 * A colour ramp's children are `BASE { PARAMETER COLOR }` (BASE a material type) or `like BASE { PARAMETER
 * COLOR }` (BASE a material defined before), made by the reader (greader_material_with); the default is
 * `of lambert reflectance`.
 *
 * A blend node (generic/kit/node_kit.h): pick below gives the children and weights of the segment at t. */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Spline {
    GNodeList list; /* gen is t; first: the class's destroy is gnode_list_destroy */
    int basis;     /* a GSplineBasis */
    double *keys;  /* a ramp: list.n keys; NULL: uniform, child i at i / (n - 1) */
} Spline;

static void spline_destroy(GMaterial *self)
{
    gmem_free(((Spline *)self)->keys);
    gnode_list_destroy(self);
}

/* The position on the uniform spline's axis (child i at x = i) of t on the ramp. */
static double ramp_x(const Spline *s, double t)
{
    const double *k = s->keys;
    int n = s->list.n;
    if (t <= k[0])
        return 0.0;
    if (t >= k[n - 1])
        return n - 1;
    int lo = 0, hi = n - 1; /* k[lo] <= t < k[hi] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (k[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo + (t - k[lo]) / (k[hi] - k[lo]); /* k[hi] > t >= k[lo]: a segment of positive width */
}

/* Adds weight w of child i (clamped to the ends) to the blend, merging repeats and skipping zeros. */
static void add(GNodeBlend *b, const Spline *s, int i, double w)
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

static void pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
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
    double x = s->keys ? ramp_x(s, t) : t * (s->list.n - 1);
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

static const GNodeBlendClass spline_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "spline",
             .description = "n children blended by a cubic spline over a generator value",
             .destroy = spline_destroy,
             GNODE_BLENDED_METHODS},
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
    int rc = gnode_list_new(&spline_class.base, children, n, t, sizeof(Spline), out, err);
    if (rc == G_OK) {
        ((Spline *)*out)->basis = (int)basis;
        gnode_inherit_lambertian(*out, children, n); /* pick ignores the method: one blend for all */
        gnode_inherit_no_uv(*out, children, n, t); /* reads the point only through t */
    }
    return rc;
}

int gnode_spline_create_keyed(GMaterial *const *children, const double *keys, int n, GGenerator *t,
                              GSplineBasis basis, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!keys || n < 2 || n > GSPLINE_MAX_KEYS)
        return gerror_set(err, G_ERR_INVALID, "spline: a ramp needs 2 to %d keys, got %d", GSPLINE_MAX_KEYS, n);
    for (int i = 0; i < n; i++) {
        if (!(keys[i] >= 0.0 && keys[i] <= 1.0))
            return gerror_set(err, G_ERR_INVALID, "spline: ramp key %g is outside [0, 1]", keys[i]);
        if (i > 0 && keys[i] < keys[i - 1])
            return gerror_set(err, G_ERR_INVALID, "spline: ramp key %g comes after %g (keys must not decrease)",
                              keys[i], keys[i - 1]);
    }
    double *copy = gmem_alloc((size_t)n * sizeof *copy);
    if (!copy)
        return gerror_set(err, G_ERR_NOMEM, "spline: out of memory");
    memcpy(copy, keys, (size_t)n * sizeof *copy);
    int rc = gnode_spline_create(children, n, t, basis, out, err);
    if (rc != G_OK) {
        gmem_free(copy);
        return rc;
    }
    ((Spline *)*out)->keys = copy;
    return G_OK;
}

/* `ramp { KEY MATERIAL ... }`: keys in [0, 1], none smaller than the one before, 2 to GSPLINE_MAX_KEYS of them;
 * each problem is reported at its key. */
static int parse_ramp(GReader *r, const char *base, const char *param, GMaterial ***kids, double **keys, int *n,
                      GError *err)
{
    int cap = 0, line = 0, col = 0;
    int rc = greader_block_begin(r, err);
    if (rc == G_OK)
        greader_position(r, &line, &col);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        double k;
        if ((rc = greader_number_in(r, 0.0, 1.0, &k, err)) != G_OK)
            break;
        if (*n > 0 && k < (*keys)[*n - 1]) {
            rc = greader_error(r, err, "spline: ramp key %g comes after %g (keys must not decrease)", k,
                               (*keys)[*n - 1]);
            break;
        }
        if (*n == GSPLINE_MAX_KEYS) {
            rc = greader_error(r, err, "spline: a ramp has at most %d keys", GSPLINE_MAX_KEYS);
            break;
        }
        GMaterial *m;
        rc = base ? greader_material_with(r, base, param, &m, err) : greader_material(r, &m, err);
        if (rc != G_OK)
            break;
        if (*n == cap) {
            cap = cap ? 2 * cap : 8;
            GMaterial **gk = gmem_realloc(*kids, (size_t)cap * sizeof *gk);
            if (gk)
                *kids = gk;
            double *gv = gk ? gmem_realloc(*keys, (size_t)cap * sizeof *gv) : NULL;
            if (gv)
                *keys = gv;
            if (!gk || !gv) {
                rc = greader_error(r, err, "out of memory");
                break;
            }
        }
        (*kids)[*n] = m;
        (*keys)[(*n)++] = k;
    }
    if (rc == 1 && *n < 2)
        return greader_error(r, err, "spline: a ramp needs at least 2 keys, got %d (the block opened at %d:%d)", *n,
                             line, col);
    return rc < 0 ? rc : G_OK;
}

/* `colors [of BASE PARAMETER] { KEY COLOR ... }` */
static int parse_colors(GReader *r, GMaterial ***kids, double **keys, int *n, GError *err)
{
    char base[256] = "lambert", param[256] = "reflectance";
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK && t.type == GTOK_IDENT && strcmp(t.text, "of") == 0) {
        rc = greader_next(r, NULL, err);
        if (rc == G_OK)
            rc = greader_ident(r, base, sizeof base, err);
        if (rc == G_OK && !greader_lookup(r, GKIND_MATERIAL, base) && !gregistry_find(GKIND_MATERIAL, base) &&
            !gregistry_find(GKIND_NODE, base))
            rc = greader_error(r, err, "spline: colors of '%s': neither a material defined before nor a material type",
                               base);
        if (rc == G_OK)
            rc = greader_ident(r, param, sizeof param, err);
    }
    return rc == G_OK ? parse_ramp(r, base, param, kids, keys, n, err) : rc;
}

static int parse_spline(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    static const char *const basis_names[] = {"catmull-rom", "bspline", "linear", NULL};
    GMaterial **kids = NULL;
    double *keys = NULL;
    int n = 0, basis = GSPLINE_CATMULL_ROM, have_kids = 0;
    GGenerator *g = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "t") == 0)
            rc = gtexparse_generator(r, &g, err);
        else if (strcmp(key, "children") == 0 || strcmp(key, "ramp") == 0 || strcmp(key, "colors") == 0) {
            if (have_kids) {
                rc = greader_error(r, err, "spline: children, ramp and colors exclude each other");
                break;
            }
            if (strcmp(key, "children") == 0)
                rc = gtexparse_materials(r, &kids, &n, err);
            else if (strcmp(key, "ramp") == 0)
                rc = parse_ramp(r, NULL, NULL, &kids, &keys, &n, err);
            else
                rc = parse_colors(r, &kids, &keys, &n, err);
            have_kids = 1;
        } else if (strcmp(key, "basis") == 0)
            rc = greader_choice(r, basis_names, &basis, err);
        else
            rc = greader_unknown_param(r, "t, basis, children, ramp, colors", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !g)
        rc = greader_error(r, err, "spline: needs t");
    else if (rc == 0 && !have_kids)
        rc = greader_error(r, err, "spline: needs children { ... }, ramp { ... } or colors { ... }");
    if (rc == 0) {
        GMaterial *m = NULL;
        if (keys)
            rc = gnode_spline_create_keyed(kids, keys, n, g, (GSplineBasis)basis, &m, err);
        else
            rc = gnode_spline_create(kids, n, g, (GSplineBasis)basis, &m, err);
        rc = gtexparse_finish(r, rc, m, object, err);
    }
    gmem_free(kids);
    gmem_free(keys);
    return rc;
}

static const GParamInfo spline_params[] = {
    {"t", GPARAM_NAMED, "generator", NULL, NULL, "where along the children: 0 the first, 1 the last"},
    {"basis", GPARAM_NAMED, "choice", "catmull-rom", "catmull-rom, bspline, linear",
     "the spline: Catmull-Rom passes through every child, the uniform B-spline smooths, linear interpolates"},
    {"children", GPARAM_NAMED, "block", "one of children, ramp, colors", "{ MATERIAL ... }, at least 2",
     "the children at t = i / (n - 1)"},
    {"ramp", GPARAM_NAMED, "block", "one of children, ramp, colors", "{ KEY MATERIAL ... }, 2 to 1024 keys",
     "the children at their keys in [0, 1], none below the one before (equal keys make a step)"},
    {"colors", GPARAM_NAMED, "block", "one of children, ramp, colors",
     "[of BASE PARAMETER] { KEY COLOR ... }, 2 to 1024 keys",
     "a ramp of children BASE { PARAMETER COLOR } (BASE a material type) or like BASE { PARAMETER COLOR } (a "
     "material defined before); default of lambert reflectance"},
    {NULL},
};

GENERIC_TYPE_PARAMS(spline, GKIND_NODE, &spline_class.base, parse_spline, NULL, spline_params);
