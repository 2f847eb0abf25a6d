/* spline.c - the spline node: n children at t = i / (n - 1) blended by a cubic spline over a generator
 * value (Catmull-Rom by default; uniform B-spline and linear on request). */
#include "generic/plugin.h"
#include "node_common.h"
#include "textures_builtin.h"

#include <math.h>

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

static void pick(const GMaterial *self, GSurfPoint *sp, GTexBlend *b)
{
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

static int spline_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_reflection(&b, sp, in, illum, out, result);
}

static int spline_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                             const GColor *rel_index, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_refraction(&b, sp, in, illum, rel_index, out, result);
}

static int spline_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_refraction_index(&b, sp, result);
}

static int spline_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_reflection_dir(&b, sp, view, dir);
}

static int spline_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                 GVec3 *dir)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_refraction_dir(&b, sp, view, rel_index, dir);
}

static int spline_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_emission(&b, sp, out, result);
}

static int spline_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_ambient(&b, sp, illum, result);
}

static int spline_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                             GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_absorption(&b, sp, illum, length, result);
}

static int spline_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_normal(&b, sp, n);
}

static int spline_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_diffuse(&b, sp, result);
}

static int spline_opaque(const GMaterial *self, GSurfPoint *sp)
{
    GTexBlend b;
    pick(self, sp, &b);
    return gtexblend_opaque(&b, sp);
}

const GMaterialClass gnode_spline_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "spline",
    .description = "n children blended by a cubic spline over a generator value",
    .destroy = gtexlist_destroy,
    .reflection = spline_reflection,
    .refraction = spline_refraction,
    .refraction_index = spline_refraction_index,
    .reflection_dir = spline_reflection_dir,
    .refraction_dir = spline_refraction_dir,
    .emission = spline_emission,
    .ambient = spline_ambient,
    .absorption = spline_absorption,
    .normal = spline_normal,
    .diffuse = spline_diffuse,
    .opaque = spline_opaque,
};

int gnode_spline_create(GMaterial *const *children, int n, GGenerator *t, GSplineBasis basis, GMaterial **out,
                        GError *err)
{
    *out = NULL;
    if (children && n == 1)
        return gerror_set(err, G_ERR_INVALID, "spline: needs at least 2 children, got 1");
    if ((unsigned)basis > GSPLINE_LINEAR)
        return gerror_set(err, G_ERR_INVALID, "spline: unknown basis %d", (int)basis);
    int rc = gtexlist_new(&gnode_spline_class, children, n, t, sizeof(Spline), out, err);
    if (rc == G_OK)
        ((Spline *)*out)->basis = (int)basis;
    return rc;
}

GENERIC_TYPE(spline, GKIND_NODE, &gnode_spline_class, gtexparse_spline, NULL);
