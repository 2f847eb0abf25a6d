/* test_node_ideal.c - blends at their ideal ray (materials.h, node_kit.h): at a pair aligned with the blend's ideal
 * ray only the children with an ideal ray of their own answer (a glass's Fresnel reflectance, a mirror's, a
 * phong's `mirror`), and a child without one (lambert, a glossy phong lobe, fluorescent-phong, a translucent test
 * double) adds nothing; away from that pair, or in a blend without a ray, the result is the weighted sum, bit for
 * bit. In rgb, spectrum and bispectral, for reflection and refraction, through interpolate, spline and a GNodeBlend
 * of three children; sampling weighs a non-delta direction on the ray with the children without a ray. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/materials.h>
#include <generic/kit/node_kit.h>
#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

#define DEG (M_PI / 180.0)

static const char *const text =
    "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"
    "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"
    "material glass dielectric { index 1.5 }\n"
    "material fp fluorescent-phong { matrix dayglo ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
    "material ll lambert { reflectance rgb 0.6 0.3 0.2 }\n"
    "material gl phong { diffuse rgb 0.1 0.1 0.1 specular rgb 0.5 0.5 0.5 exponent 200 }\n"
    "material pm phong { diffuse rgb 0.1 0.1 0.1 specular rgb 0.2 0.2 0.2 exponent 200 mirror rgb 0.3 0.2 0.1 }\n"
    "material mr mirror { reflectance rgb 0.9 0.8 0.7 }\n"
    "node glass_fp interpolate { a fp b glass t constant { value 0.3 } }\n"
    "node ll_glass spline { t constant { value 0.6 } basis linear children { ll glass } }\n"
    "node glossy spline { t constant { value 0.4 } basis bspline children { gl fp ll pm } }\n";

typedef struct Fix {
    GColorModel *model;
    GScratch *scratch;
    GLibrary *lib;
    GSurfPoint sp;
    GColor light, ri, got, want, tmp, old;
} Fix;

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    assert_non_null(f);
    assert_int_equal(gcolormodel_create(*state, NULL, &f->model, &err), G_OK);
    f->scratch = gscratch_create(0);
    GReaderOptions ro = {.model = f->model};
    if (greader_load_string(text, "ideal.mat", &ro, &f->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    plane_point(&f->sp, f->model, f->scratch, 0.3, 0.4);
    GColor *c[] = {&f->light, &f->ri, &f->got, &f->want, &f->tmp, &f->old};
    for (int i = 0; i < 6; i++)
        assert_int_equal(gcolor_alloc(c[i], f->model), G_OK);
    assert_int_equal(gcolor_from_rgb(&f->light, (double[3]){0.9, 0.6, 0.3}, GCOLOR_LIGHT), G_OK);
    /* from vacuum into glass: the relative index every child reads, cached on the point */
    assert_int_equal(gcolor_fill(&f->ri, 1.0 / 1.5), G_OK);
    gsurfpoint_set_relative_index(&f->sp, &f->ri);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    GColor *c[] = {&f->light, &f->ri, &f->got, &f->want, &f->tmp, &f->old};
    for (int i = 0; i < 6; i++)
        gcolor_free(c[i]);
    glibrary_destroy(f->lib);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
    free(f);
    return 0;
}

static const GMaterial *mat(Fix *f, const char *name)
{
    const GMaterial *m = glibrary_material(f->lib, name);
    assert_non_null(m);
    return m;
}

/* The weighted sum of the children in `use` (bit i: child i) as the blend forms it: the first into the sum and
 * scaled, the others added with their weights; refraction when transmit. */
static void weighted(Fix *f, const GNodeBlend *b, unsigned use, GVec3 in, GVec3 out, int transmit, GColor *sum)
{
    int first = 1;
    gcolor_black(sum);
    for (int i = 0; i < b->n; i++) {
        if (!(use >> i & 1))
            continue;
        GColor *r = first ? sum : &f->tmp;
        if (transmit)
            assert_int_equal(gmaterial_refraction(b->m[i], &f->sp, in, &f->light, &f->ri, out, r), G_OK);
        else
            assert_int_equal(gmaterial_reflection(b->m[i], &f->sp, in, &f->light, out, r), G_OK);
        if (first)
            assert_int_equal(gcolor_scale(sum, sum, b->w[i]), G_OK);
        else
            assert_int_equal(gcolor_add_scaled(sum, &f->tmp, b->w[i]), G_OK);
        first = 0;
    }
}

static void assert_same(const GColor *got, const GColor *want, const char *what)
{
    for (int i = 0; i < got->model->nvalues; i++)
        if (!(got->v[i] == want->v[i]))
            fail_msg("%s, sample %d: %.9g, expected %.9g", what, i, got->v[i], want->v[i]);
}

static double brightness(const GColor *c) { return gcolor_brightness(c); }

/* The node `name` against the weighted sum of its children `b` (the same weights): on its ray (and within the
 * 1e-6 cosine of it) only those in `ideal`, all of them when `ideal` is 0 (no child has a ray), and all of them
 * elsewhere. */
static void check_node(Fix *f, const char *name, const GNodeBlend *b, unsigned ideal, GVec3 out)
{
    const GMaterial *n = mat(f, name);
    unsigned all = (1u << b->n) - 1u;
    GVec3 mirror = gvec3(-out.x, -out.y, out.z);
    assert_true(gmaterial_is_mirror_pair(mirror, gvec3(0, 0, 1), out));
    char what[96];
    /* the ideal pair, and 0.05 degrees off it (inside the 1e-6 cosine): the children with a ray alone */
    GVec3 t, u;
    goptics_frame(mirror, &t, &u);
    GVec3 near = gvec3_normalize(gvec3_madd(mirror, t, tan(0.05 * DEG)));
    GVec3 off = gvec3_normalize(gvec3_madd(mirror, t, tan(0.2 * DEG))); /* cos 1 - 6.1e-6: outside */
    GVec3 ins[3] = {mirror, near, off};
    for (int k = 0; k < 3; k++) {
        assert_int_equal(gmaterial_reflection(n, &f->sp, ins[k], &f->light, out, &f->got), G_OK);
        weighted(f, b, k < 2 ? (ideal ? ideal : all) : all, ins[k], out, 0, &f->want);
        snprintf(what, sizeof what, "%s %s", name, k == 0 ? "on its ray" : k == 1 ? "0.05 deg off" : "0.2 deg off");
        assert_same(&f->got, &f->want, what);
    }
    if (ideal) { /* what summing every child gave */
        weighted(f, b, all, mirror, out, 0, &f->old);
        assert_int_equal(gmaterial_reflection(n, &f->sp, mirror, &f->light, out, &f->got), G_OK);
        print_message("%s on its ray: %.6g (the sum of every child: %.6g)\n", name, brightness(&f->got),
                      brightness(&f->old));
    }
    /* elsewhere: every child, whatever the light */
    GVec3 in = gvec3_normalize(gvec3(0.3, -0.2, 0.8));
    assert_int_equal(gmaterial_reflection(n, &f->sp, in, &f->light, out, &f->got), G_OK);
    weighted(f, b, all, in, out, 0, &f->want);
    snprintf(what, sizeof what, "%s away from its ray", name);
    assert_same(&f->got, &f->want, what);
}

/* interpolate and spline over glass and a child without a ray: on the ray w_glass * the glass's reflectance. */
static void test_blend_nodes(void **state)
{
    Fix *f = *state;
    GVec3 out = gvec3(sin(40 * DEG) * cos(0.3), sin(40 * DEG) * sin(0.3), cos(40 * DEG));
    GNodeBlend b = {2, {mat(f, "fp"), mat(f, "glass")}, {1.0 - 0.3, 0.3}};
    check_node(f, "glass_fp", &b, 2u, out);
    /* the node's reflection on its ray is exactly 0.3 times the glass's own, which is not black */
    GVec3 mirror = gvec3(-out.x, -out.y, out.z);
    assert_int_equal(gmaterial_reflection(mat(f, "glass"), &f->sp, mirror, &f->light, out, &f->want), G_OK);
    assert_true(brightness(&f->want) > 0.01); /* F(40 deg) 0.042 of the light */
    assert_int_equal(gcolor_scale(&f->want, &f->want, 0.3), G_OK);
    assert_int_equal(gmaterial_reflection(mat(f, "glass_fp"), &f->sp, mirror, &f->light, out, &f->got), G_OK);
    assert_same(&f->got, &f->want, "glass_fp: 0.3 glass");
    GNodeBlend s = {2, {mat(f, "ll"), mat(f, "glass")}, {1.0 - 0.6, 0.6}};
    check_node(f, "ll_glass", &s, 2u, out);
    /* a B-spline segment of four (t = 0.4: x = 1.2, the spline's own arithmetic), one with a mirror term: on its
     * ray pm's mirror alone, the glossy lobes, the lambert and fluorescent-phong dropping out */
    double x = 0.4 * 3, fr = x - 1, f2 = fr * fr, f3 = f2 * fr;
    GNodeBlend g = {4,
                   {mat(f, "gl"), mat(f, "fp"), mat(f, "ll"), mat(f, "pm")},
                   {(1.0 - fr) * (1.0 - fr) * (1.0 - fr) / 6.0, (3.0 * f3 - 6.0 * f2 + 4.0) / 6.0,
                    (-3.0 * f3 + 3.0 * f2 + 3.0 * fr + 1.0) / 6.0, f3 / 6.0}};
    check_node(f, "glossy", &g, 8u, out);
}

/* Three children straight through the kit, two of them with a ray: both answer on it, the glossy lobe does not;
 * without the ray-carrying children the same pair is an ordinary one. */
static void test_blend_three(void **state)
{
    Fix *f = *state;
    GVec3 out = gvec3(sin(25 * DEG), 0.0, cos(25 * DEG)), mirror = gvec3(-out.x, 0.0, out.z);
    const GMaterial *kids[][3] = {{mat(f, "gl"), mat(f, "glass"), mat(f, "mr")},
                                  {mat(f, "ll"), mat(f, "pm"), mat(f, "fp")},
                                  {mat(f, "ll"), mat(f, "gl"), mat(f, "fp")}};
    unsigned ideal[] = {6u, 2u, 7u};
    for (int c = 0; c < 3; c++) {
        GNodeBlend b = {3, {kids[c][0], kids[c][1], kids[c][2]}, {0.5, 0.3, 0.2}};
        assert_int_equal(gnode_blend_reflection(&b, &f->sp, mirror, &f->light, out, &f->got), G_OK);
        weighted(f, &b, ideal[c], mirror, out, 0, &f->want);
        assert_same(&f->got, &f->want, "three children on the ray");
        /* the result may alias the light */
        assert_int_equal(gcolor_copy(&f->tmp, &f->light), G_OK);
        assert_int_equal(gnode_blend_reflection(&b, &f->sp, mirror, &f->tmp, out, &f->tmp), G_OK);
        assert_same(&f->tmp, &f->want, "three children on the ray, in place");
    }
}

/* Refraction: a translucent child without a refraction ray (the counting double: its colour times the light for
 * any pair) adds nothing along the glass's ideal refraction, and its share elsewhere. */
static void test_blend_refraction(void **state)
{
    Fix *f = *state;
    CountMat *tr = countmat_new(f->model, 0.4, 0.3, 0.2);
    assert_non_null(tr);
    GNodeBlend b = {2, {&tr->base, mat(f, "glass")}, {0.4, 0.6}};
    GVec3 out = gvec3(sin(35 * DEG), 0.0, cos(35 * DEG)), in;
    assert_int_equal(goptics_refract(gvec3_neg(out), gvec3(0, 0, 1), 1.0 / 1.5, &in), 1);
    assert_int_equal(gnode_blend_refraction(&b, &f->sp, in, &f->light, &f->ri, out, &f->got), G_OK);
    weighted(f, &b, 2u, in, out, 1, &f->want);
    assert_true(brightness(&f->want) > 0.3); /* 0.6 (1 - F) */
    assert_same(&f->got, &f->want, "refraction on the glass's ray");
    assert_int_equal(tr->calls[GNODE_REFRACTION], 0); /* not even asked */
    GVec3 other = gvec3_normalize(gvec3(-0.1, 0.2, -0.9));
    assert_int_equal(gnode_blend_refraction(&b, &f->sp, other, &f->light, &f->ri, out, &f->got), G_OK);
    weighted(f, &b, 3u, other, out, 1, &f->want);
    assert_same(&f->got, &f->want, "refraction away from the ray");
    gmaterial_unref(&tr->base);
}

/* Off the ideal pair a blend asks no child for its direction; on it, each child of non-zero weight once. */
static void test_no_calls_off_the_ray(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->model, 0.2, 0.2, 0.2), *c = countmat_new(f->model, 0.5, 0.5, 0.5);
    GNodeBlend b = {2, {&a->base, &c->base}, {0.25, 0.75}};
    GVec3 out = gvec3(0.0, 0.6, 0.8), mirror = gvec3(0.0, -0.6, 0.8);
    assert_int_equal(gnode_blend_reflection(&b, &f->sp, gvec3(0.6, 0.0, 0.8), &f->light, out, &f->got), G_OK);
    assert_int_equal(a->calls[GNODE_REFLECTION_DIR] + c->calls[GNODE_REFLECTION_DIR], 0);
    assert_int_equal(gnode_blend_reflection(&b, &f->sp, mirror, &f->light, out, &f->got), G_OK);
    assert_int_equal(a->calls[GNODE_REFLECTION_DIR], 1);
    assert_int_equal(c->calls[GNODE_REFLECTION_DIR], 1);
    weighted(f, &b, 3u, mirror, out, 0, &f->want); /* neither has a ray: both answer */
    assert_same(&f->got, &f->want, "no ray");
    gmaterial_unref(&a->base);
    gmaterial_unref(&c->base);
}

/* ---- a child whose sampling draws the mirror direction as a non-delta one (a very sharp lobe) ---- */

static int spike_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *r)
{
    (void)self, (void)sp, (void)in, (void)out;
    return gcolor_scale(r, illum, 2.0); /* f_r cos: a density, on the mirror pair too */
}
static int spike_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *ri, double u1, double u2,
                        GMaterialSample *s, GColor *w)
{
    (void)self, (void)sp, (void)ri, (void)u1, (void)u2, (void)w;
    s->in = gvec3(-out.x, -out.y, out.z);
    s->pdf = 50.0;
    s->flags = GSAMPLE_REFLECT;
    return 1;
}
static double spike_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *ri)
{
    (void)self, (void)sp, (void)ri;
    return gmaterial_is_mirror_pair(in, gvec3(0, 0, 1), out) ? 50.0 : 0.0;
}
static const GMaterialClass spike_class = {.abi_version = GMATERIAL_ABI_VERSION, .name = "spike",
                                           .description = "draws the mirror direction", .destroy = cm_destroy,
                                           .reflection = spike_reflection, .sample = spike_sample,
                                           .pdf = spike_pdf};

/* The weight of a non-delta direction on the blend's ray is the spike's value over the mixture's density, not the
 * glass's reflectance over it. */
static void test_sample_on_the_ray(void **state)
{
    Fix *f = *state;
    GMaterial *spike = calloc(1, sizeof *spike);
    assert_non_null(spike);
    assert_int_equal(gmaterial_init(spike, &spike_class, f->model, NULL), G_OK);
    GNodeBlend b = {2, {spike, mat(f, "glass")}, {0.4, 0.6}};
    GVec3 out = gvec3(0.0, sin(30 * DEG), cos(30 * DEG));
    GMaterialSample s;
    assert_int_equal(gnode_blend_sample(&b, &f->sp, out, &f->ri, 0.1, 0.5, &s, &f->got), 1); /* u1 < 0.4: spike */
    assert_int_equal(s.flags, GSAMPLE_REFLECT);
    assert_true(fabs(s.pdf - 0.4 * 50.0) < 1e-12);
    GColor white = f->tmp;
    assert_int_equal(gcolor_fill(&white, 1.0), G_OK);
    assert_int_equal(gcolor_scale(&f->want, &white, 0.4 * 2.0 / (0.4 * 50.0)), G_OK);
    for (int i = 0; i < f->model->nvalues; i++)
        assert_true(fabs(f->got.v[i] - f->want.v[i]) <= 1e-6 * f->want.v[i]);
    gmaterial_unref(spike);
}

#define MODELS(fn)                                                                                              \
    cmocka_unit_test_prestate_setup_teardown(fn, setup, teardown, (void *)"rgb"),                               \
        cmocka_unit_test_prestate_setup_teardown(fn, setup, teardown, (void *)"spectrum"),                      \
        cmocka_unit_test_prestate_setup_teardown(fn, setup, teardown, (void *)"bispectral")

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        MODELS(test_blend_nodes),    MODELS(test_blend_three),       MODELS(test_blend_refraction),
        MODELS(test_no_calls_off_the_ray), MODELS(test_sample_on_the_ray),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
