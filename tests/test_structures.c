/* test_structures.c - structures built from input, generated at run time: long CSG and CPG operand lists
 * (inside tests at known points, destroy), trees at the depth bound and one past it, chains of node references
 * and towers of self-blending nodes at and past their limits (the exact message, the number of calls one
 * evaluation makes), wide nodes, and 200,000 entries loaded and listed in bounded time. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/builtins.h>
#include <generic/kit/node_kit.h>
#include <generic/reader.h>
#include <generic/textures.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "texture_fixtures.h"

/* ---- a growing text ---- */

typedef struct Text {
    char *s;
    size_t n, cap;
} Text;

static void text_add(Text *t, const char *fmt, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int w = vsnprintf(t->s ? t->s + t->n : NULL, t->s ? t->cap - t->n : 0, fmt, ap);
        va_end(ap);
        assert_true(w >= 0);
        if (t->s && t->n + (size_t)w < t->cap) {
            t->n += (size_t)w;
            return;
        }
        t->cap = t->cap ? t->cap * 2 : 1 << 16;
        while (t->cap < t->n + (size_t)w + 1)
            t->cap *= 2;
        t->s = realloc(t->s, t->cap);
        assert_non_null(t->s);
    }
}

static GLibrary *load_ok(const Text *t)
{
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(t->s, "gen", NULL, &lib, &err);
    if (rc != G_OK)
        fail_msg("load: %s", err.message);
    return lib;
}

static void load_fails(const Text *t, const char *want)
{
    GLibrary *lib = NULL;
    GError err;
    assert_int_not_equal(greader_load_string(t->s, "gen", NULL, &lib, &err), G_OK);
    assert_null(lib);
    if (strcmp(err.message, want) != 0)
        fail_msg("message '%s', expected '%s'", err.message, want);
}

static double value_at(const GGenerator *g, double x, double y, double z)
{
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.u = x;
    sp.v = y;
    sp.point = sp.object_point = gvec3(x, y, z);
    return ggenerator_value(g, &sp);
}

/* ---- long operand lists ---- */

enum { MANY = 100000 };

/* A union of MANY spheres of radius 0.25 at x = 0, 1, 2, ... read from text; the inside test at their
 * centres, between them and past the last. */
static void test_csg_long_union(void **state)
{
    (void)state;
    Text t = {0};
    text_add(&t, "generator g csg { shape union {\n");
    for (int i = 0; i < MANY; i++)
        text_add(&t, "transform { translate %d 0 0 } sphere 0.25\n", i);
    text_add(&t, "} }\n");
    double t0 = tu_cpu_seconds();
    GLibrary *lib = load_ok(&t);
    const GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "g");
    assert_non_null(g);
    assert_near(value_at(g, 0, 0, 0), 1.0, 0);
    assert_near(value_at(g, 54321.2, 0, 0), 1.0, 0);
    assert_near(value_at(g, MANY - 1, 0.2, 0), 1.0, 0);
    assert_near(value_at(g, 54321.5, 0, 0), 0.0, 0); /* between two spheres */
    assert_near(value_at(g, MANY - 0.7, 0, 0), 0.0, 0);
    assert_near(value_at(g, 7, 0.26, 0), 0.0, 0);
    glibrary_destroy(lib);
    double took = tu_cpu_seconds() - t0;
    print_message("csg union of %d spheres: read, 6 inside tests and freed in %.2f s of CPU\n", MANY, took);
    assert_true(took < 20.0);
    free(t.s);
}

static void test_cpg_long_union(void **state)
{
    (void)state;
    Text t = {0};
    text_add(&t, "generator g cpg { shape union {\n");
    for (int i = 0; i < MANY; i++)
        text_add(&t, "circle %d 0 0.25\n", i);
    text_add(&t, "} }\n");
    GLibrary *lib = load_ok(&t);
    const GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "g");
    assert_non_null(g);
    assert_near(value_at(g, 0, 0, 0), 1.0, 0);
    assert_near(value_at(g, 77777, 0.24, 0), 1.0, 0);
    assert_near(value_at(g, 77777.5, 0, 0), 0.0, 0);
    assert_near(value_at(g, -0.3, 0, 0), 0.0, 0);
    glibrary_destroy(lib);
    free(t.s);
}

/* 1,000,000 spheres combined pair by pair through the API: one flat union (freed without recursion). */
static void test_csg_api_pairwise(void **state)
{
    (void)state;
    GError err;
    GCsgShape *acc = NULL;
    for (int i = 0; i < 10 * MANY; i++) {
        GCsgShape *s;
        assert_int_equal(gcsg_sphere(0.25, &s, &err), G_OK);
        GAffine3 m = gaffine3_translate(gvec3(i, 0, 0));
        assert_int_equal(gcsg_transform(s, &m, &err), G_OK);
        if (acc)
            assert_int_equal(gcsg_combine(GSHAPE_UNION, acc, s, &acc, &err), G_OK);
        else
            acc = s;
    }
    assert_true(gcsg_inside(acc, gvec3(999999, 0, 0)));
    assert_false(gcsg_inside(acc, gvec3(999999.5, 0, 0)));
    gcsg_destroy(acc);
}

/* Differences of long lists: a minus b minus c ..., and nested differences read the same. */
static void test_difference_lists(void **state)
{
    (void)state;
    Text t = {0};
    /* a box [0, 100] x [-1, 1] x [-1, 1] with 100 spheres cut away, every other one nested a level deeper */
    text_add(&t, "generator g csg { shape difference { difference { box 0 -1 -1 100 1 1\n");
    for (int i = 0; i < 100; i += 2)
        text_add(&t, "transform { translate %d 0 0 } sphere 0.3\n", i);
    text_add(&t, "}\n");
    for (int i = 1; i < 100; i += 2)
        text_add(&t, "transform { translate %d 0 0 } sphere 0.3\n", i);
    text_add(&t, "} }\n");
    text_add(&t, "generator h cpg { shape difference { square 0 0 10 union { circle 1 1 0.5 circle 2 2 0.5 } "
                 "circle -1 -1 0.5 } }\n");
    GLibrary *lib = load_ok(&t);
    const GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "g");
    for (int i = 0; i < 100; i++) {
        assert_near(value_at(g, i, 0, 0), 0.0, 0);        /* cut away */
        assert_near(value_at(g, i + 0.5, 0, 0), 1.0, 0);  /* between the holes */
        assert_near(value_at(g, i + 0.5, 0, 1.1), 0.0, 0); /* above the box */
    }
    const GGenerator *h = glibrary_find(lib, GKIND_GENERATOR, "h");
    assert_near(value_at(h, 0, 0, 0), 1.0, 0);
    assert_near(value_at(h, 1, 1, 0), 0.0, 0);
    assert_near(value_at(h, 2, 2, 0), 0.0, 0);
    assert_near(value_at(h, -1, -1, 0), 0.0, 0);
    assert_near(value_at(h, -2, 2, 0), 1.0, 0);
    glibrary_destroy(lib);
    free(t.s);
}

/* Operations that cannot be merged (each has a transform of its own) nest: accepted up to GSHAPE_MAX_DEPTH,
 * refused one past it with the message, and everything freed. */
static void test_shape_depth_bound(void **state)
{
    (void)state;
    GError err;
    GCsgShape *acc;
    GCpgShape *cacc;
    assert_int_equal(gcsg_sphere(1.0, &acc, &err), G_OK);
    assert_int_equal(gcpg_circle(0, 0, 1.0, &cacc, &err), G_OK);
    GAffine3 m = gaffine3_translate(gvec3(0.5, 0, 0));
    GAffine2 m2 = gaffine2_translate(0.5, 0);
    for (int depth = 2; depth <= GSHAPE_MAX_DEPTH; depth++) { /* depth: of acc after this step */
        GCsgShape *s;
        GCpgShape *c;
        assert_int_equal(gcsg_sphere(1.0, &s, &err), G_OK);
        assert_int_equal(gcsg_combine(GSHAPE_UNION, acc, s, &acc, &err), G_OK);
        assert_int_equal(gcsg_transform(acc, &m, &err), G_OK);
        assert_int_equal(gcpg_circle(0, 0, 1.0, &c, &err), G_OK);
        assert_int_equal(gcpg_combine(GSHAPE_UNION, cacc, c, &cacc, &err), G_OK);
        assert_int_equal(gcpg_transform(cacc, &m2, &err), G_OK);
    }
    /* unit spheres (circles) at x = 0.5, 1, ..., 128: the innermost one moved 255 times, the last added once */
    assert_true(gcsg_inside(acc, gvec3(128, 0, 0)));
    assert_true(gcsg_inside(acc, gvec3(64.25, 0.9, 0)));
    assert_true(gcsg_inside(acc, gvec3(0.5, 0, 0.99)));
    assert_false(gcsg_inside(acc, gvec3(-0.51, 0, 0)));
    assert_false(gcsg_inside(acc, gvec3(129.01, 0, 0)));
    assert_true(gcpg_inside(cacc, 128.0, 0.0));
    assert_true(gcpg_inside(cacc, 0.5, 0.99));
    assert_false(gcpg_inside(cacc, -0.51, 0.0));
    assert_false(gcpg_inside(cacc, 64.25, 1.01));
    GCsgShape *s, *out = NULL;
    assert_int_equal(gcsg_sphere(1.0, &s, &err), G_OK);
    assert_int_equal(gcsg_combine(GSHAPE_DIFFERENCE, acc, s, &out, &err), G_ERR_INVALID);
    assert_null(out);
    assert_string_equal(err.message, "csg: shapes nested more than 256 deep");
    GCpgShape *c, *cout = NULL;
    assert_int_equal(gcpg_circle(0, 0, 1.0, &c, &err), G_OK);
    assert_int_equal(gcpg_combine(GSHAPE_DIFFERENCE, cacc, c, &cout, &err), G_ERR_INVALID);
    assert_null(cout);
    assert_string_equal(err.message, "cpg: shapes nested more than 256 deep");
}

/* ---- node references ---- */

/* node n1 .. nN, each a scale of the one before (factor 0.5 every second step, else 1). */
static void chain(Text *t, int n)
{
    text_add(t, "material n0 lambert { reflectance rgb 0.8 0.8 0.8 }\n");
    for (int i = 1; i <= n; i++)
        text_add(t, "node n%d scale { child n%d factor constant { value %s } }\n", i, i - 1, i % 2 ? "1" : "0.5");
}

static double diffuse_r(const GMaterial *m)
{
    GSurfPoint sp;
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    plane_point(&sp, m->model, s, 0.3, 0.3);
    GColor c;
    assert_int_equal(gcolor_alloc(&c, m->model), G_OK);
    assert_int_equal(gmaterial_diffuse(m, &sp, &c), G_OK);
    double r = color_r(&c);
    gcolor_free(&c);
    gscratch_destroy(s);
    return r;
}

static void test_reference_chain(void **state)
{
    (void)state;
    /* at the limit: n255 is 256 deep; 0.8 times 0.5^127 */
    Text t = {0};
    chain(&t, GNODE_MAX_DEPTH - 1);
    GLibrary *lib = load_ok(&t);
    GMaterial *top = glibrary_material(lib, "n255");
    assert_non_null(top);
    assert_int_equal(top->depth, GNODE_MAX_DEPTH);
    assert_int_equal(top->cost, GNODE_MAX_DEPTH);
    assert_near(diffuse_r(top) / (0.8 * pow(0.5, 127)), 1.0, 1e-5);
    glibrary_destroy(lib);
    free(t.s);
    /* 100,000 references: refused at the first node past the limit */
    t = (Text){0};
    chain(&t, MANY);
    double t0 = tu_cpu_seconds();
    load_fails(&t, "gen:257:60: scale: the node would be 257 deep, the limit is 256");
    assert_true(tu_cpu_seconds() - t0 < 10.0);
    free(t.s);
}

/* node n1 .. nN, each blending the one before with itself. */
static void tower(Text *t, int n)
{
    text_add(t, "material n0 lambert { reflectance rgb 0.6 0.6 0.6 }\n");
    for (int i = 1; i <= n; i++)
        text_add(t, "node n%d interpolate { a n%d b n%d t constant { value 0.5 } }\n", i, i - 1, i - 1);
}

static void test_self_blending_tower(void **state)
{
    (void)state;
    /* 15 levels: 2^16 - 1 = 65,535 calls; 16 levels would be 131,071 */
    Text t = {0};
    tower(&t, 15);
    GLibrary *lib = load_ok(&t);
    GMaterial *top = glibrary_material(lib, "n15");
    assert_int_equal(top->cost, 65535);
    assert_int_equal(top->depth, 16);
    assert_near(diffuse_r(top), 0.6, 1e-5);
    glibrary_destroy(lib);
    free(t.s);
    t = (Text){0};
    tower(&t, 40); /* 40 levels would be 2^41 calls: refused at level 16, at once */
    double t0 = tu_cpu_seconds();
    load_fails(&t, "gen:17:61: interpolate: one call of the node would make 131071 material calls, the limit is "
                   "100000");
    assert_true(tu_cpu_seconds() - t0 < 5.0);
    free(t.s);
}

/* The cost is a bound on the calls one evaluation makes: a tower over a counting material, with the blend
 * weight strictly between 0 and 1 so that both children are evaluated at every level. */
static void test_cost_bounds_calls(void **state)
{
    (void)state;
    GColorModel *model;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &model, &err), G_OK);
    CountMat *leaf = countmat_new(model, 0.5, 0.5, 0.5);
    CountGen *g = countgen_new(0.5);
    GMaterial *m = &leaf->base; /* its reference passes to the first node */
    for (int level = 1; level <= 12; level++) {
        GMaterial *n;
        assert_int_equal(gnode_interpolate_create(m, m, &g->base, &n, &err), G_OK);
        gmaterial_unref(m);
        m = n;
    }
    assert_int_equal(m->cost, 8191);
    assert_near(diffuse_r(m), 0.5, 1e-6);
    assert_int_equal(leaf->calls[GNODE_DIFFUSE], 4096); /* 2^12 leaves; with the 4095 nodes, 8191 calls */
    /* a wide select over 1000 towers: it evaluates one at a time, the cost counts GNODE_BLEND_MAX of them */
    GMaterial *kids[1000];
    for (int i = 0; i < 1000; i++)
        kids[i] = m;
    GMaterial *sel;
    assert_int_equal(gnode_select_create(kids, 1000, &g->base, &sel, &err), G_OK);
    assert_int_equal(sel->cost, 1 + GNODE_BLEND_MAX * 8191);
    assert_int_equal(sel->depth, 14);
    gmaterial_unref(sel);
    gmaterial_unref(m);
    ggenerator_unref(&g->base);
    gcolormodel_destroy(model);
}

/* ---- many entries ---- */

static void test_many_entries(void **state)
{
    (void)state;
    enum { N = 200000 };
    Text t = {0};
    text_add(&t, "material m lambert { reflectance rgb 0.5 0.5 0.5 }\n");
    for (int i = 0; i < N; i++)
        text_add(&t, "node n%d scale { child m factor constant { value 0.5 } }\n", i);
    double t0 = tu_cpu_seconds();
    GLibrary *lib = load_ok(&t);
    double loaded = tu_cpu_seconds() - t0;
    assert_int_equal(glibrary_count(lib, GKIND_NODE), N);
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 1);
    long found = 0;
    for (int i = 0; i < glibrary_count(lib, GKIND_NODE); i++) {
        const char *name;
        char want[16];
        snprintf(want, sizeof want, "n%d", i);
        assert_non_null(glibrary_entry(lib, GKIND_NODE, i, &name, NULL));
        found +=
            strcmp(name, want) == 0 && glibrary_material(lib, want) == glibrary_entry(lib, GKIND_NODE, i, NULL, NULL);
    }
    assert_int_equal(found, N);
    assert_null(glibrary_entry(lib, GKIND_NODE, N, NULL, NULL));
    glibrary_destroy(lib);
    double total = tu_cpu_seconds() - t0;
    print_message("%d nodes: loaded in %.2f s, listed, looked up and freed in %.2f s of CPU\n", N, loaded, total);
    assert_true(total < 10.0); /* about 0.5 s; quadratic listing took minutes */
    free(t.s);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_csg_long_union),     cmocka_unit_test(test_cpg_long_union),
        cmocka_unit_test(test_csg_api_pairwise),   cmocka_unit_test(test_difference_lists),
        cmocka_unit_test(test_shape_depth_bound),  cmocka_unit_test(test_reference_chain),
        cmocka_unit_test(test_self_blending_tower), cmocka_unit_test(test_cost_bounds_calls),
        cmocka_unit_test(test_many_entries),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
