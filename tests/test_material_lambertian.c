/* test_material_lambertian.c - GMAT_LAMBERTIAN (material.h): reflection(sp, in, illum, out) is diffuse(sp) * illum *
 * gmaterial_cos_in(sp, in, out) / pi everywhere, so a renderer may reflect the sum of its lights at once:
 *  - which materials and nodes get the bit: lambert; the blend nodes whose pick gives one blend for reflection and
 *    diffuse (interpolate, interpolate-one of another method, spline, select) over children that all have it; the
 *    one-child nodes (bump, scale, image, transform: gnode_inherit_lambertian_child) over a child that has it, and
 *    nodes over those; not interpolate-one of reflection or diffuse, not a node (blend or one-child) over a phong,
 *    mirror or dielectric child or over an unflagged node, not a blend class the kit does not know to pick alike
 *    (gnode_new_checked never sets it, gnode_inherit_lambertian refuses another class, a one-child one too);
 *  - the property itself for every flagged material and node, in rgb, spectrum and bispectral (with a re-radiation
 *    matrix as a lambert's reflectance there): random points (generator values, geometric normals, and a shading
 *    normal set on the point, which every child reads as the node does, or else the node's own: a bump's bumped
 *    normal, a transform's child's at the original point), random pairs of directions on both sides and random
 *    lights, the class's reflection against diffuse * light * cos / pi within relative 1e-6; scale factors that
 *    are 0 (both black) and negative, texel colours of a small PPM written into a temporary directory;
 *  - gmaterial_is_delta answers 0 for a flagged material without calling the class or a node's pick, and the
 *    one-child nodes' own is_delta slots agree (their Lambertian child is not delta). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/kit/affine.h>
#include <generic/generators.h>
#include <generic/kit/material_kit.h>
#include <generic/materials.h>
#include <generic/kit/node_kit.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

/* A small colour image (written by main into a temporary directory) for the image nodes. */
static char image_path[256];

static int lamb(const GMaterial *m) { return (m->flags & GMAT_LAMBERTIAN) != 0; }

/* A lambert of reflectance (r, g, b) in model m. */
static GMaterial *lambert_rgb(const GColorModel *m, double r, double g, double b)
{
    GColor c;
    double rgb[3] = {r, g, b};
    GMaterial *out = NULL;
    GError err;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(glambert_create(m, &c, &out, &err), G_OK);
    gcolor_free(&c);
    assert_true(lamb(out));
    return out;
}

/* Deterministic uniform numbers in [0, 1). */
static double uniform(unsigned long long *s) { return tu_uniform(s); }

/* An image node over child reading image_path (texels of every colour, some black). */
static GMaterial *image_over(GMaterial *child)
{
    GMaterial *out = NULL;
    GError err;
    int rc = gnode_image_create(child, image_path, NULL, &out, &err);
    if (rc != G_OK)
        fail_msg("image node: %s", err.message);
    return out;
}

/* Writes an 8 x 8 binary PPM of pseudo-random colours (and one black texel) to path; 0 on success. */
static int write_image(const char *path)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    unsigned long long seed = 7;
    fprintf(f, "P6\n8 8\n255\n");
    for (int i = 0; i < 64 * 3; i++)
        fputc(i < 3 ? 0 : (int)(255.0 * tu_uniform(&seed)), f);
    return fclose(f);
}

static GVec3 random_dir(unsigned long long *s)
{
    double z = 1.0 - 2.0 * uniform(s), p = 2.0 * M_PI * uniform(s), r = sqrt(fmax(0.0, 1.0 - z * z));
    return gvec3(r * cos(p), r * sin(p), z);
}

/* A blend class whose pick answers reflection with child b and every other method with child a: the kit cannot see
 * that from its slots, so it must not flag it. */
typedef struct Pair {
    GMaterial base;
    GMaterial *a, *b;
} Pair;

static void pair_destroy(GMaterial *self)
{
    Pair *p = (Pair *)self;
    gmaterial_unref(p->a);
    gmaterial_unref(p->b);
    gmem_free(p);
}

static void pair_pick(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
{
    (void)sp;
    const Pair *p = (const Pair *)self;
    gnode_blend_one(b, m == GNODE_REFLECTION ? p->b : p->a);
}

static const GNodeBlendClass pair_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION, .name = "test-pair", .description = "reflection from b",
             .destroy = pair_destroy, GNODE_BLENDED_METHODS},
    .pick = pair_pick,
};

static void test_which_get_the_bit(void **state)
{
    (void)state;
    GColorModel *rgb;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &rgb, &err), G_OK);
    GMaterial *a = lambert_rgb(rgb, 0.2, 0.3, 0.4), *b = lambert_rgb(rgb, 0.8, 0.7, 0.6);
    GMaterial *c = lambert_rgb(rgb, 0.5, 0.5, 0.1);
    GGenerator *t;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(1, 0, 0), 0.0, &t, &err), G_OK);
    enum { NODES = 21, FLAGGED = 15 };
    GMaterial *kids[3] = {a, b, c}, *n[NODES];
    GAffine2 uv = gaffine2_rotate(30.0);
    GAffine3 xyz = gaffine3_rotate(gvec3(0, 0, 1), 20.0);
    assert_int_equal(gnode_interpolate_create(a, b, t, &n[0], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(a, b, t, GNODE_NORMAL, &n[1], &err), G_OK);
    assert_int_equal(gnode_spline_create(kids, 3, t, GSPLINE_CATMULL_ROM, &n[2], &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 3, t, &n[3], &err), G_OK);
    GMaterial *inner[2] = {n[0], n[3]};
    assert_int_equal(gnode_spline_create(inner, 2, t, GSPLINE_LINEAR, &n[4], &err), G_OK);
    /* one-child nodes over a lambert, over an interpolate of lamberts, over one another */
    assert_int_equal(gnode_bump_create(a, t, 1.0, &n[5], &err), G_OK);
    assert_int_equal(gnode_scale_create(b, t, &n[6], &err), G_OK);
    assert_int_equal(gnode_transform_create(c, &uv, NULL, &n[7], &err), G_OK);
    n[8] = image_over(a);
    assert_int_equal(gnode_scale_create(n[0], t, &n[9], &err), G_OK);
    assert_int_equal(gnode_bump_create(n[9], t, 0.5, &n[10], &err), G_OK);
    assert_int_equal(gnode_transform_create(n[10], &uv, &xyz, &n[11], &err), G_OK);
    n[12] = image_over(n[11]);
    /* blends over them */
    GMaterial *over_bump[2] = {n[0], n[5]};
    assert_int_equal(gnode_spline_create(over_bump, 2, t, GSPLINE_LINEAR, &n[13], &err), G_OK);
    GMaterial *over_transform[2] = {n[7], n[3]};
    assert_int_equal(gnode_select_create(over_transform, 2, t, &n[14], &err), G_OK);
    /* without the bit: interpolate-one of reflection or diffuse, and one-child nodes over them */
    assert_int_equal(gnode_interpolate_one_create(a, b, t, GNODE_REFLECTION, &n[15], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(a, b, t, GNODE_DIFFUSE, &n[16], &err), G_OK);
    assert_int_equal(gnode_bump_create(n[15], t, 1.0, &n[17], &err), G_OK);
    assert_int_equal(gnode_scale_create(n[16], t, &n[18], &err), G_OK);
    assert_int_equal(gnode_transform_create(n[15], &uv, &xyz, &n[19], &err), G_OK);
    n[20] = image_over(n[16]);
    for (int i = 0; i < NODES; i++)
        if (lamb(n[i]) != (i < FLAGGED))
            fail_msg("node %d (%s): GMAT_LAMBERTIAN %d", i, gmaterial_name(n[i]), lamb(n[i]));

    /* over a phong, a mirror or a dielectric child: no bit */
    GColor half;
    assert_int_equal(gcolor_alloc(&half, rgb), G_OK);
    assert_int_equal(gcolor_fill(&half, 0.5), G_OK);
    GPhongParams pp = {.kd = &half, .ks = &half, .exponent = 20.0};
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    GMaterial *other[3], *m[3];
    assert_int_equal(gphong_create(rgb, &pp, &other[0], &err), G_OK);
    assert_int_equal(gmirror_create(rgb, &half, &other[1], &err), G_OK);
    assert_int_equal(gdielectric_create(rgb, &gp, &other[2], &err), G_OK);
    GMaterial *with_mirror[3] = {a, other[1], b};
    assert_int_equal(gnode_interpolate_create(a, other[0], t, &m[0], &err), G_OK);
    assert_int_equal(gnode_spline_create(with_mirror, 3, t, GSPLINE_BSPLINE, &m[1], &err), G_OK);
    GMaterial *with_glass[2] = {other[2], a};
    assert_int_equal(gnode_select_create(with_glass, 2, t, &m[2], &err), G_OK);
    for (int i = 0; i < 3; i++) {
        assert_false(lamb(other[i]));
        assert_false(gmaterial_lambertian(m[i]));
    }
    assert_false(gmaterial_lambertian(NULL));
    /* one-child nodes over each of them: no bit */
    GMaterial *one[12];
    for (int i = 0; i < 3; i++) {
        assert_int_equal(gnode_bump_create(other[i], t, 1.0, &one[4 * i], &err), G_OK);
        assert_int_equal(gnode_scale_create(other[i], t, &one[4 * i + 1], &err), G_OK);
        assert_int_equal(gnode_transform_create(other[i], &uv, &xyz, &one[4 * i + 2], &err), G_OK);
        one[4 * i + 3] = image_over(other[i]);
    }
    for (int i = 0; i < 12; i++)
        if (lamb(one[i]))
            fail_msg("%s over %s: GMAT_LAMBERTIAN", gmaterial_name(one[i]), gmaterial_name(other[i / 4]));

    /* a blend class the kit does not know to pick alike: not from construction, and the inherit call refuses a
     * class with other slots than the kit's blend (a one-child node) */
    GMaterial *pair_kids[2] = {a, b}, *p;
    assert_int_equal(gnode_new_checked(&pair_class.base, pair_kids, 2, NULL, 0, sizeof(Pair), &p, &err), G_OK);
    ((Pair *)p)->a = gmaterial_ref(a);
    ((Pair *)p)->b = gmaterial_ref(b);
    assert_false(lamb(p));
    gnode_inherit_lambertian(one[1], pair_kids, 2); /* a scale over a mirror: not a blend class */
    assert_false(lamb(one[1]));
    assert_true(gnode_children_lambertian(pair_kids, 2));
    assert_false(gnode_children_lambertian(other, 3));
    /* the one-child form: nothing for a child without the bit, for NULL, or for the node as its own child */
    gnode_inherit_lambertian_child(one[1], other[1]);
    assert_false(lamb(one[1]));
    gnode_inherit_lambertian_child(one[1], NULL);
    gnode_inherit_lambertian_child(NULL, a);
    assert_false(lamb(one[1]));
    gnode_inherit_lambertian_child(n[15], n[15]);
    assert_false(lamb(n[15]));

    for (int i = 11; i >= 0; i--)
        gmaterial_unref(one[i]);
    gmaterial_unref(p);
    for (int i = 2; i >= 0; i--)
        gmaterial_unref(m[i]);
    for (int i = 0; i < 3; i++)
        gmaterial_unref(other[i]);
    gcolor_free(&half);
    for (int i = NODES - 1; i >= 0; i--)
        gmaterial_unref(n[i]);
    gmaterial_unref(a);
    gmaterial_unref(b);
    gmaterial_unref(c);
    ggenerator_unref(t);
    gcolormodel_destroy(rgb);
}

/* The largest relative difference between m's own reflection and diffuse * light * gmaterial_cos_in / pi over n random
 * points, pairs and lights (per pair: the largest sample difference over the pair's largest |value|); *lit counts
 * the pairs whose reflection is not black. */
static double worst_relative(const GMaterial *m, GScratch *scratch, int n, int *lit)
{
    const GColorModel *model = m->model;
    GColor light, got, want, diffuse;
    assert_int_equal(gcolor_alloc(&light, model), G_OK);
    assert_int_equal(gcolor_alloc(&got, model), G_OK);
    assert_int_equal(gcolor_alloc(&want, model), G_OK);
    assert_int_equal(gcolor_alloc(&diffuse, model), G_OK);
    unsigned long long seed = 42;
    double worst = 0.0;
    *lit = 0;
    for (int i = 0; i < n; i++) {
        GSurfPoint sp;
        plane_point(&sp, model, scratch, uniform(&seed), uniform(&seed));
        sp.point = sp.object_point = gvec3(4 * uniform(&seed) - 2, 4 * uniform(&seed) - 2, uniform(&seed));
        sp.geometric_normal = gvec3_normalize(gvec3(uniform(&seed) - 0.5, uniform(&seed) - 0.5, 1.0));
        if (i % 2) /* a shading normal of the point's own (as a bump at the root gives it): every child reads it */
            gsurfpoint_set_normal(&sp, gvec3_normalize(gvec3_madd(sp.geometric_normal, random_dir(&seed), 0.4)));
        sp.material = m;
        GVec3 in = random_dir(&seed), out = random_dir(&seed), g = sp.geometric_normal, nrm;
        if (i % 5 != 4) { /* mostly both on the incident side, else anywhere */
            in = gvec3_dot(in, g) < 0.0 ? gvec3_neg(in) : in;
            out = gvec3_dot(out, g) < 0.0 ? gvec3_neg(out) : out;
        }
        for (int j = 0; j < model->nvalues; j++)
            light.v[j] = (float)(0.1 + 10.0 * uniform(&seed));
        assert_int_equal(m->cls->reflection(m, &sp, in, &light, out, &got), G_OK);
        assert_int_equal(gmaterial_diffuse(m, &sp, &diffuse), G_OK);
        assert_int_equal(gcolor_mul_scaled(&want, &diffuse, &light, gmaterial_cos_in(&sp, in, out, &nrm) / M_PI), G_OK);
        double d = 0.0, big = 0.0;
        for (int j = 0; j < model->nvalues; j++) {
            d = fmax(d, fabs((double)got.v[j] - want.v[j]));
            big = fmax(big, fmax(fabs(got.v[j]), fabs(want.v[j])));
        }
        *lit += big > 0.0;
        worst = fmax(worst, big > 0.0 ? d / big : d);
    }
    gcolor_free(&light);
    gcolor_free(&got);
    gcolor_free(&want);
    gcolor_free(&diffuse);
    return worst;
}

static void test_reflection_is_diffuse(void **state)
{
    const char *name = *state;
    GColorModel *model;
    GError err;
    assert_int_equal(gcolormodel_create(name, NULL, &model, &err), G_OK);
    GScratch *scratch = gscratch_create(0);
    GMaterial *a = lambert_rgb(model, 0.2, 0.3, 0.4), *b = lambert_rgb(model, 0.8, 0.7, 0.6);
    GMaterial *c = lambert_rgb(model, 0.9, 0.1, 0.05), *d = NULL;
    GColor matrix;
    assert_int_equal(gcolor_alloc(&matrix, model), G_OK);
    if (tu_diagonal_matrix(model, &matrix)) { /* bispectral: a lambert whose reflectance is a matrix */
        assert_int_equal(glambert_create(model, &matrix, &d, &err), G_OK);
        assert_true(lamb(d));
    } else {
        d = gmaterial_ref(c);
    }
    gcolor_free(&matrix);
    GGenerator *t, *w, *h, *cells, *zero;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(1, 0.3, 0), 0.0, &t, &err), G_OK);
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_OBJECT, gvec3(0.2, -0.1, 0), 0.5, &w, &err), G_OK);
    GNoiseParams np = {.space = GGENERATOR_SPACE_OBJECT, .frequency = 2.0, .seed = 5};
    assert_int_equal(ggenerator_perlin_create(&np, &h, &err), G_OK);            /* a bump's height */
    assert_int_equal(ggenerator_checker_create(3, 1.0, &cells, &err), G_OK);    /* a factor 0 on half the points */
    assert_int_equal(ggenerator_constant_create(0.0, &zero, &err), G_OK);
    enum { NODES = 20 };
    GMaterial *kids[4] = {a, b, c, d}, *n[NODES];
    assert_int_equal(gnode_interpolate_create(a, d, t, &n[0], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(b, c, t, GNODE_NORMAL, &n[1], &err), G_OK);
    assert_int_equal(gnode_spline_create(kids, 4, w, GSPLINE_CATMULL_ROM, &n[2], &err), G_OK);
    assert_int_equal(gnode_spline_create(kids, 4, t, GSPLINE_BSPLINE, &n[3], &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 4, w, &n[4], &err), G_OK);
    GMaterial *inner[3] = {n[0], n[2], n[4]};
    assert_int_equal(gnode_spline_create(inner, 3, t, GSPLINE_LINEAR, &n[5], &err), G_OK);
    /* one-child nodes over a lambert (d: the matrix one in bispectral) and over the interpolate n[0] */
    GAffine2 uv_rot = gaffine2_rotate(35.0), uv_scale = gaffine2_scale(0.4, 1.7);
    GAffine2 uv_move = gaffine2_translate(0.25, -0.1), uv_turned = gaffine2_mul(&uv_scale, &uv_rot);
    GAffine2 uv = gaffine2_mul(&uv_move, &uv_turned);
    GAffine3 xyz_rot = gaffine3_rotate(gvec3(1, 1, 0), 40.0), xyz_scale = gaffine3_scale(gvec3(2, 0.5, 1));
    GAffine3 xyz = gaffine3_mul(&xyz_scale, &xyz_rot);
    assert_int_equal(gnode_bump_create(d, h, 0.8, &n[6], &err), G_OK);
    assert_int_equal(gnode_bump_create(n[0], h, 3.0, &n[7], &err), G_OK); /* steep: some normals far off */
    assert_int_equal(gnode_scale_create(d, w, &n[8], &err), G_OK);       /* factors in [-0.1, 1.1] */
    assert_int_equal(gnode_scale_create(n[0], cells, &n[9], &err), G_OK); /* 0 or 1 */
    assert_int_equal(gnode_scale_create(a, zero, &n[10], &err), G_OK);    /* black everywhere */
    n[11] = image_over(d);
    n[12] = image_over(n[0]);
    assert_int_equal(gnode_transform_create(d, &uv, &xyz, &n[13], &err), G_OK);
    assert_int_equal(gnode_transform_create(n[0], &uv, &xyz, &n[14], &err), G_OK);
    assert_int_equal(gnode_transform_create(n[7], &uv, &xyz, &n[15], &err), G_OK); /* a bump's normal, moved */
    /* a chain of all four over a spline, and a blend of one-child nodes */
    assert_int_equal(gnode_scale_create(n[2], w, &n[16], &err), G_OK);
    n[17] = image_over(n[16]);
    assert_int_equal(gnode_bump_create(n[17], h, 1.5, &n[18], &err), G_OK);
    GMaterial *ones[4] = {n[7], n[9], n[12], n[14]};
    assert_int_equal(gnode_spline_create(ones, 4, t, GSPLINE_BSPLINE, &n[19], &err), G_OK);
    GMaterial *chain;
    assert_int_equal(gnode_transform_create(n[18], &uv, &xyz, &chain, &err), G_OK);
    struct {
        const GMaterial *m;
        const char *what;
        int min_lit; /* pairs that must reflect something (of 400) */
    } all[] = {
        {a, "lambert", 200}, {b, "lambert", 200}, {d, "lambert (matrix in bispectral)", 200},
        {n[0], "interpolate", 200}, {n[1], "interpolate-one normal", 200}, {n[2], "spline object", 200},
        {n[3], "spline uv", 200}, {n[4], "select", 200}, {n[5], "spline of nodes", 200},
        {n[6], "bump over lambert", 200}, {n[7], "bump over interpolate", 200},
        {n[8], "scale over lambert", 200}, {n[9], "scale 0 or 1 over interpolate", 100},
        {n[10], "scale 0 over lambert", 0}, {n[11], "image over lambert", 150},
        {n[12], "image over interpolate", 150}, {n[13], "transform over lambert", 200},
        {n[14], "transform over interpolate", 200}, {n[15], "transform over bump", 200},
        {chain, "transform(bump(image(scale(spline))))", 150}, {n[19], "spline of one-child nodes", 150},
    };
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        if (!lamb(all[i].m))
            fail_msg("%s %s: no GMAT_LAMBERTIAN", name, all[i].what);
        int lit;
        double worst = worst_relative(all[i].m, scratch, 400, &lit);
        print_message("%s %s: largest relative difference %.3g over %d lit pairs\n", name, all[i].what, worst, lit);
        if (lit < all[i].min_lit) /* most pairs reflect something */
            fail_msg("%s %s: %d lit pairs, fewer than %d", name, all[i].what, lit, all[i].min_lit);
        if (all[i].min_lit == 0)
            assert_int_equal(lit, 0); /* the black scale: both sides black everywhere */
        assert_true(worst <= 1e-6);
    }
    gmaterial_unref(chain);
    for (int i = NODES - 1; i >= 0; i--)
        gmaterial_unref(n[i]);
    ggenerator_unref(h);
    ggenerator_unref(cells);
    ggenerator_unref(zero);
    gmaterial_unref(a);
    gmaterial_unref(b);
    gmaterial_unref(c);
    gmaterial_unref(d);
    ggenerator_unref(t);
    ggenerator_unref(w);
    gscratch_destroy(scratch);
    gcolormodel_destroy(model);
}

/* The comparison can fail: a phong's reflection (diffuse plus a glossy lobe) is far from its diffuse colour times
 * the light's cosine. */
static void test_comparison_sees_a_glossy_lobe(void **state)
{
    (void)state;
    GColorModel *rgb;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &rgb, &err), G_OK);
    GScratch *scratch = gscratch_create(0);
    GColor kd, ks;
    assert_int_equal(gcolor_alloc(&kd, rgb), G_OK);
    assert_int_equal(gcolor_alloc(&ks, rgb), G_OK);
    assert_int_equal(gcolor_fill(&kd, 0.5), G_OK);
    assert_int_equal(gcolor_fill(&ks, 0.05), G_OK);
    GPhongParams pp = {.kd = &kd, .ks = &ks, .exponent = 2.0};
    GMaterial *m;
    assert_int_equal(gphong_create(rgb, &pp, &m, &err), G_OK);
    int lit;
    double worst = worst_relative(m, scratch, 400, &lit);
    print_message("phong: largest relative difference %.3g\n", worst);
    assert_true(worst > 1e-2);
    gmaterial_unref(m);
    gcolor_free(&kd);
    gcolor_free(&ks);
    gscratch_destroy(scratch);
    gcolormodel_destroy(rgb);
}

static int delta_calls;

static int always_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    delta_calls++;
    return 1;
}

static void plain_destroy(GMaterial *self) { gmem_free(self); }

static const GMaterialClass delta_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "test-delta", .description = "is_delta says 1",
    .destroy = plain_destroy, .is_delta = always_delta,
};

/* With the bit, gmaterial_is_delta answers 0 without calling the class (set by hand here only to see the call
 * skipped), and for a node over lamberts without running its pick. */
static void test_is_delta_skips_the_class(void **state)
{
    (void)state;
    GColorModel *rgb;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &rgb, &err), G_OK);
    GScratch *scratch = gscratch_create(0);
    GSurfPoint sp;
    plane_point(&sp, rgb, scratch, 0.3, 0.4);
    GMaterial *m = gmem_calloc(1, sizeof *m);
    assert_int_equal(gmaterial_init(m, &delta_class, rgb, &err), G_OK);
    assert_false(lamb(m)); /* gmaterial_init never sets it */
    delta_calls = 0;
    assert_int_equal(gmaterial_is_delta(m, &sp), 1);
    assert_int_equal(delta_calls, 1);
    m->flags |= GMAT_LAMBERTIAN;
    assert_int_equal(gmaterial_is_delta(m, &sp), 0);
    assert_int_equal(delta_calls, 1);
    gmaterial_unref(m);

    GMaterial *a = lambert_rgb(rgb, 0.2, 0.2, 0.2), *b = lambert_rgb(rgb, 0.8, 0.8, 0.8), *node;
    CountGen *g = countgen_new(0.5);
    assert_int_equal(gnode_interpolate_create(a, b, &g->base, &node, &err), G_OK);
    sp.material = node;
    assert_int_equal(gmaterial_is_delta(node, &sp), 0);
    assert_int_equal(g->calls, 0); /* no pick, no generator */
    assert_int_equal(gnode_blended_is_delta(node, &sp), 0); /* the class's own answer agrees */
    assert_int_equal(g->calls, 1);

    /* the one-child nodes over a lambert and over that interpolate: is_delta 0 without a call, and their own slots
     * (the child's answer, at the point or a moved copy) agree */
    GGenerator *t;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(1, 0, 0), 0.0, &t, &err), G_OK);
    GAffine2 uv = gaffine2_rotate(30.0);
    GMaterial *one[8];
    for (int i = 0; i < 2; i++) {
        GMaterial *child = i ? node : a;
        assert_int_equal(gnode_bump_create(child, t, 1.0, &one[4 * i], &err), G_OK);
        assert_int_equal(gnode_scale_create(child, t, &one[4 * i + 1], &err), G_OK);
        assert_int_equal(gnode_transform_create(child, &uv, NULL, &one[4 * i + 2], &err), G_OK);
        one[4 * i + 3] = image_over(child);
    }
    for (int i = 0; i < 8; i++) {
        GSurfPoint q;
        plane_point(&q, rgb, scratch, 0.3, 0.4);
        q.material = one[i];
        assert_true(lamb(one[i]));
        assert_int_equal(gmaterial_is_delta(one[i], &q), 0);
        assert_int_equal(one[i]->cls->is_delta(one[i], &q), 0);
    }
    for (int i = 7; i >= 0; i--)
        gmaterial_unref(one[i]);
    ggenerator_unref(t);
    gmaterial_unref(node);
    gmaterial_unref(a);
    gmaterial_unref(b);
    ggenerator_unref(&g->base);
    gscratch_destroy(scratch);
    gcolormodel_destroy(rgb);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    char dir[128];
    if (tu_tempdir(dir, sizeof dir, "lambertian") != 0 ||
        write_image(tu_in_dir(dir, "colours.ppm", image_path, sizeof image_path)) != 0)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_which_get_the_bit),
        {"test_reflection_is_diffuse (rgb)", test_reflection_is_diffuse, NULL, NULL, (void *)"rgb"},
        {"test_reflection_is_diffuse (spectrum)", test_reflection_is_diffuse, NULL, NULL, (void *)"spectrum"},
        {"test_reflection_is_diffuse (bispectral)", test_reflection_is_diffuse, NULL, NULL, (void *)"bispectral"},
        cmocka_unit_test(test_comparison_sees_a_glossy_lobe),
        cmocka_unit_test(test_is_delta_skips_the_class),
    };
    int failed = cmocka_run_group_tests(tests, NULL, NULL);
    tu_rmtree(dir);
    return failed;
}
