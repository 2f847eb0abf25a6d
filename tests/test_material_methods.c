/* test_material_methods.c - the method list GMATERIAL_METHODS (material.h) against what is generated from it: the
 * class's slots in the list's order after destroy, GNodeMethod and its keywords, each dispatch function's call of
 * its slot and its default for a NULL slot, a NULL material and the method's `unless` bit, and the node kit's
 * pass-through (gnode_child_*) and blend (gnode_blended_*) methods, each calling the child once. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/kit/material_kit.h"
#include "generic/kit/node_kit.h"
#include "generic/material.h"
#include "generic/memory.h"
#include "test_util.h"

/* The probe's methods below read none of their parameters: written once for every method of the list. */
#pragma GCC diagnostic ignored "-Wunused-parameter"

/* ---- the list itself ---- */

/* An index for each method of the list, in its order: M_REFLECTION, ... */
#define INDEX(name, NAME, type, attr, unless, dispatch, blend, params, args) M_##NAME,
enum { GMATERIAL_METHODS(INDEX) N_METHODS };

#define NAME_OF(name, NAME, type, attr, unless, dispatch, blend, params, args) #name,
static const char *const list_names[] = {GMATERIAL_METHODS(NAME_OF)};

/* The slots of the interface, in the order modules are built against (the ABI: a method is only appended). */
static const char *const abi_order[] = {"reflection", "refraction", "refraction_index", "reflection_dir",
                                        "refraction_dir", "emission", "ambient", "absorption", "normal", "diffuse",
                                        "opaque", "sample", "pdf", "is_delta"};

#define OFFSET_OF(name, NAME, type, attr, unless, dispatch, blend, params, args) offsetof(GMaterialClass, name),
static const size_t slot_offsets[] = {GMATERIAL_METHODS(OFFSET_OF)};

/* The list has the interface's fourteen methods in the ABI's order, and the class a slot for each, one pointer
 * after another right after destroy, and nothing else after them. */
static void test_list_is_the_class(void **state)
{
    (void)state;
    assert_int_equal(N_METHODS, sizeof abi_order / sizeof *abi_order);
    for (int i = 0; i < N_METHODS; i++) {
        assert_string_equal(list_names[i], abi_order[i]);
        assert_int_equal(slot_offsets[i], offsetof(GMaterialClass, destroy) + (size_t)(i + 1) * sizeof(void (*)(void)));
    }
    size_t end = offsetof(GMaterialClass, destroy) + (N_METHODS + 1) * sizeof(void (*)(void));
    assert_int_equal(sizeof(GMaterialClass), end);
}

/* GNodeMethod: the picked methods in the list's order, the sampling ones (sample, pdf, is_delta) not among them;
 * every value has its keyword and the keywords go back to their values. */
static void test_node_method_names(void **state)
{
    (void)state;
    assert_int_equal(GNODE_METHOD_COUNT, 11);
    assert_int_equal(GNODE_REFLECTION, 0);
    assert_int_equal(GNODE_REFRACTION_INDEX, 2);
    assert_int_equal(GNODE_OPAQUE, 10);
    for (int i = 0; i < GNODE_METHOD_COUNT; i++) {
        const char *name = gnode_method_name((GNodeMethod)i);
        assert_string_equal(name, abi_order[i]); /* the first eleven slots are the picked methods */
        assert_int_equal(gnode_method_from_name(name), i);
    }
    assert_string_equal(gnode_method_name(GNODE_METHOD_COUNT), "?");
    assert_string_equal(gnode_method_name((GNodeMethod)-1), "?");
    assert_int_equal(gnode_method_from_name("sample"), -1);
    assert_int_equal(gnode_method_from_name("pdf"), -1);
    assert_int_equal(gnode_method_from_name("is_delta"), -1);
    assert_int_equal(gnode_method_from_name("Reflection"), -1);
    assert_int_equal(gnode_method_from_name(""), -1);
    assert_int_equal(gnode_method_from_name(NULL), -1);
}

/* ---- the fixture: a model, an arena, a point and colours named as the list's parameters ---- */

typedef struct Fix {
    GColorModel *model;
    GScratch *scratch;
    GSurfPoint *sp;
    GColor illum, rel_index, result, weight;
} Fix;

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    if (!f || gcolormodel_create(*state ? *state : "rgb", NULL, &f->model, &err) != G_OK)
        return -1;
    f->scratch = gscratch_create(0);
    f->sp = gsurfpoint_new(f->model, f->scratch, gvec3(0.5, 0.25, 0), gvec3(0, 0, 1), gvec3(1, 0, 0),
                           gvec3(0, 1, 0), 0.5, 0.25, 0, &err);
    if (!f->sp || gcolor_alloc(&f->illum, f->model) != G_OK || gcolor_alloc(&f->rel_index, f->model) != G_OK ||
        gcolor_alloc(&f->result, f->model) != G_OK || gcolor_alloc(&f->weight, f->model) != G_OK)
        return -1;
    double light[3] = {1.0, 0.5, 0.25};
    if (gcolor_from_rgb(&f->illum, light, GCOLOR_LIGHT) != G_OK || gcolor_fill(&f->rel_index, 1.0 / 1.5) != G_OK)
        return -1;
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    gcolor_free(&f->illum);
    gcolor_free(&f->rel_index);
    gcolor_free(&f->result);
    gcolor_free(&f->weight);
    gsurfpoint_free(f->sp);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
    free(f);
    return 0;
}

/* The arguments of every method, named as the list names them, so that `gmaterial_<name> GMATERIAL_WITH(m, args)`
 * calls any of them. */
#define ARGUMENTS(f)                                                                                               \
    GSurfPoint *sp = (f)->sp;                                                                                      \
    GVec3 in = gvec3(0, 0.6, 0.8), out = gvec3(0, -0.6, 0.8), view = gvec3(0, 0.6, -0.8);                         \
    GVec3 dir_v = gvec3(9, 9, 9), n_v = dir_v, *dir = &dir_v, *n = &n_v;                                          \
    const GColor *illum = &(f)->illum, *rel_index = &(f)->rel_index;                                               \
    GColor *result = &(f)->result, *weight = &(f)->weight;                                                         \
    double length = 2.0, u1 = 0.25, u2 = 0.75;                                                                     \
    GMaterialSample sample_s, *s = &sample_s;                                                                      \
    (void)sp, (void)in, (void)out, (void)view, (void)illum, (void)rel_index, (void)result, (void)weight;          \
    (void)length, (void)u1, (void)u2, (void)s, (void)dir, (void)n

/* ---- a material whose every slot counts its calls and answers 7 ---- */

static int calls[N_METHODS];

#define PROBE(name, NAME, type, attr, unless, dispatch, blend, params, args)                                       \
    static type probe_##name GMATERIAL_WITH(const GMaterial *self, params)                                         \
    {                                                                                                              \
        calls[M_##NAME]++;                                                                                         \
        return (type)7;                                                                                            \
    }
GMATERIAL_METHODS(PROBE)

static void plain_destroy(GMaterial *self) { gmem_free(self); }

#define PROBE_SLOT(name, NAME, type, attr, unless, dispatch, blend, params, args) .name = probe_##name,
static const GMaterialClass probe_class = {.abi_version = GMATERIAL_ABI_VERSION,
                                           .name = "probe",
                                           .description = "answers 7 from every method and counts the calls",
                                           .destroy = plain_destroy,
                                           GMATERIAL_METHODS(PROBE_SLOT)};

/* No slot but destroy: every method takes its default. */
static const GMaterialClass bare_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "bare", .description = "no methods", .destroy = plain_destroy};

static int half_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gcolor_fill(result, 0.5);
}

/* Only a diffuse colour: ambient's default is diffuse times the light. */
static const GMaterialClass diffuse_class = {.abi_version = GMATERIAL_ABI_VERSION,
                                             .name = "diffuse-only",
                                             .description = "a diffuse colour of 0.5",
                                             .destroy = plain_destroy,
                                             .diffuse = half_diffuse};

static GMaterial *new_material(const GMaterialClass *cls, const GColorModel *model)
{
    GMaterial *m;
    GError err;
    assert_int_equal(gmaterial_new(cls, model, sizeof *m, &m, &err), G_OK);
    return m;
}

/* Every dispatch function calls its slot once and hands its answer on. */
static void test_dispatch_calls_the_slot(void **state)
{
    Fix *f = *state;
    GMaterial *m = new_material(&probe_class, f->model);
    assert_int_equal(m->flags, 0u); /* every slot there: no bit from gmaterial_init */
    ARGUMENTS(f);
    memset(calls, 0, sizeof calls);
#define CALL_EXPECT_7(name, NAME, type, attr, unless, dispatch, blend, params, args)                               \
    assert_true(gmaterial_##name GMATERIAL_WITH(m, args) == (type)7);                                              \
    assert_int_equal(calls[M_##NAME], 1);
    GMATERIAL_METHODS(CALL_EXPECT_7)
    gmaterial_unref(m);
}

/* A method's `unless` bit makes its dispatch answer the default without a call: what it answers for vacuum. */
static void test_unless_bits(void **state)
{
    Fix *f = *state;
    GMaterial *m = new_material(&probe_class, f->model);
    ARGUMENTS(f);
    int with_bit = 0;
#define CALL_UNLESS(name, NAME, type, attr, unless, dispatch, blend, params, args)                                 \
    if ((unless) != 0) {                                                                                           \
        with_bit++;                                                                                                \
        m->flags = (unless);                                                                                       \
        memset(calls, 0, sizeof calls);                                                                            \
        type got = gmaterial_##name GMATERIAL_WITH(m, args);                                                       \
        assert_int_equal(calls[M_##NAME], 0);                                                                      \
        assert_true(got == gmaterial_##name GMATERIAL_WITH(NULL, args));                                           \
        m->flags = 0;                                                                                              \
        assert_true(gmaterial_##name GMATERIAL_WITH(m, args) == (type)7);                                          \
        assert_int_equal(calls[M_##NAME], 1);                                                                      \
    }
    GMATERIAL_METHODS(CALL_UNLESS)
    assert_int_equal(with_bit, 7); /* reflection_dir, refraction_dir, emission, absorption, normal, opaque, is_delta */
    gmaterial_unref(m);
}

/* 1 when every sample of c is v. */
static int all_samples(const GColor *c, float v)
{
    for (int i = 0; i < c->model->nsamples; i++)
        if (c->v[i] != v)
            return 0;
    return 1;
}

/* The defaults, for a NULL slot (flags cleared, so each dispatch reaches the slot test) and for vacuum. */
static void defaults_of(Fix *f, const GMaterial *m)
{
    ARGUMENTS(f);
    assert_int_equal(gcolor_fill(result, 3.0), G_OK);
    assert_int_equal(gmaterial_reflection(m, sp, in, illum, out, result), G_OK);
    assert_true(gcolor_is_black(result));
    assert_int_equal(gcolor_fill(result, 3.0), G_OK);
    assert_int_equal(gmaterial_refraction(m, sp, in, illum, rel_index, out, result), G_OK);
    assert_true(gcolor_is_black(result));
    assert_int_equal(gmaterial_refraction_index(m, sp, result), G_OK);
    assert_true(all_samples(result, 1.0f)); /* a flat 1 in every model */
    assert_int_equal(gmaterial_reflection_dir(m, sp, view, dir), 0);
    assert_int_equal(gmaterial_refraction_dir(m, sp, view, rel_index, dir), 0);
    assert_int_equal(gcolor_fill(result, 3.0), G_OK);
    assert_int_equal(gmaterial_emission(m, sp, out, result), G_OK);
    assert_true(gcolor_is_black(result));
    assert_int_equal(gcolor_fill(result, 3.0), G_OK);
    assert_int_equal(gmaterial_ambient(m, sp, illum, result), G_OK); /* diffuse (black) times illum */
    assert_true(gcolor_is_black(result));
    assert_int_equal(gmaterial_absorption(m, sp, illum, length, result), G_OK);
    for (int i = 0; i < f->model->nsamples; i++)
        assert_true(result->v[i] == illum->v[i]);
    assert_int_equal(gmaterial_normal(m, sp, n), G_OK);
    assert_true(n->x == 0.0 && n->y == 0.0 && n->z == 1.0);
    assert_int_equal(gcolor_fill(result, 3.0), G_OK);
    assert_int_equal(gmaterial_diffuse(m, sp, result), G_OK);
    assert_true(gcolor_is_black(result));
    assert_int_equal(gmaterial_opaque(m, sp), 1);
    assert_int_equal(gmaterial_is_delta(m, sp), 0);
}

static void test_defaults(void **state)
{
    Fix *f = *state;
    defaults_of(f, NULL);
    GMaterial *m = new_material(&bare_class, f->model);
    assert_int_equal(m->flags, (unsigned)(GMAT_NO_EMISSION | GMAT_OPAQUE | GMAT_GEOMETRIC_NORMAL | GMAT_NO_IDEAL |
                                          GMAT_CONSTANT_INDEX | GMAT_CLEAR));
    defaults_of(f, m);
    m->flags = 0; /* the NULL slots themselves */
    defaults_of(f, m);
    ARGUMENTS(f);
    /* sampling: nothing known, so a uniform hemisphere lobe of density 1 / (2 pi) whose value, reflection(), is
     * black; vacuum draws nothing and has density 0 */
    assert_int_equal(gmaterial_sample(m, sp, out, rel_index, u1, u2, s, weight), 1);
    assert_near(s->pdf, 1.0 / (2.0 * M_PI), 1e-15);
    assert_int_equal(s->flags, GSAMPLE_REFLECT);
    assert_true(s->in.z > 0.0);
    assert_true(gcolor_is_black(weight));
    assert_near(gmaterial_pdf(m, sp, in, out, rel_index), 1.0 / (2.0 * M_PI), 1e-15);
    assert_near(gmaterial_pdf(m, sp, gvec3(0, 0, -1), out, rel_index), 0.0, 0.0);
    assert_int_equal(gmaterial_sample(NULL, sp, out, rel_index, u1, u2, s, weight), 0);
    assert_true(gcolor_is_black(weight) && s->pdf == 0.0);
    assert_near(gmaterial_pdf(NULL, sp, in, out, rel_index), 0.0, 0.0);
    gmaterial_unref(m);

    /* ambient's default reflects the diffuse colour: 0.5 of the light */
    m = new_material(&diffuse_class, f->model);
    assert_int_equal(gmaterial_ambient(m, sp, illum, result), G_OK);
    for (int i = 0; i < f->model->nsamples; i++)
        assert_true(result->v[i] == 0.5f * illum->v[i]);
    gmaterial_unref(m);
}

/* ---- the node kit's generated methods ---- */

#define CHILD_SLOT(name, NAME, type, attr, unless, dispatch, blend, params, args) .name = gnode_child_##name,
static const GMaterialClass child_class = {.abi_version = GMATERIAL_ABI_VERSION,
                                           .name = "pass-through",
                                           .description = "every method the child's",
                                           .destroy = gnode_child_destroy,
                                           GMATERIAL_METHODS(CHILD_SLOT)};

/* Every pass-through method calls the child's once and hands its answer on. */
static void test_child_methods(void **state)
{
    Fix *f = *state;
    GMaterial *probe = new_material(&probe_class, f->model), *m; /* m: the node, as CALL_EXPECT_7 names it */
    GError err;
    assert_int_equal(gnode_child_new(&child_class, probe, NULL, 0, sizeof(GNodeChild), &m, &err), G_OK);
    assert_ptr_equal(gnode_child_of(m), probe);
    ARGUMENTS(f);
    memset(calls, 0, sizeof calls);
    GMATERIAL_METHODS(CALL_EXPECT_7)
    gmaterial_unref(m);
    gmaterial_unref(probe);
}

/* A blend node over one child whose pick records the methods it is asked for. */
static int picked[GNODE_METHOD_COUNT];

static void pick_one(const GMaterial *self, GSurfPoint *sp, GNodeMethod m, GNodeBlend *b)
{
    assert_true((unsigned)m < GNODE_METHOD_COUNT);
    picked[m]++;
    gnode_blend_one(b, gnode_child_of(self));
}

static const GNodeBlendClass blend_class = {
    .base = {.abi_version = GMATERIAL_ABI_VERSION,
             .name = "one-blend",
             .description = "a blend of one child",
             .destroy = gnode_child_destroy,
             GNODE_BLENDED_METHODS},
    .pick = pick_one,
};

/* Each picked method asks the pick for its own GNodeMethod once and calls the child once; the sampling methods ask
 * for the blends of reflection and refraction and call the child's own sampling method once. */
static void test_blended_methods(void **state)
{
    Fix *f = *state;
    GMaterial *probe = new_material(&probe_class, f->model), *node;
    GError err;
    assert_int_equal(gnode_child_new(&blend_class.base, probe, NULL, 0, sizeof(GNodeChild), &node, &err), G_OK);
    ARGUMENTS(f);
    int n_picked = 0, n_sampled = 0;
#define CALL_BLENDED(name, NAME, type, attr, unless, dispatch, blend, params, args)                                \
    memset(calls, 0, sizeof calls);                                                                                \
    memset(picked, 0, sizeof picked);                                                                              \
    {                                                                                                              \
        type got = gmaterial_##name GMATERIAL_WITH(node, args);                                                    \
        (void)got; /* what a one-child blend makes of the probe's 7 depends on the method */                       \
    }                                                                                                              \
    assert_int_equal(calls[M_##NAME], 1);                                                                          \
    for (int i = 0; i < N_METHODS; i++)                                                                            \
        if (i != M_##NAME)                                                                                         \
            assert_int_equal(calls[i], 0);                                                                         \
    if (strcmp(#blend, "pick") == 0) {                                                                             \
        n_picked++;                                                                                                \
        for (int i = 0; i < GNODE_METHOD_COUNT; i++)                                                               \
            assert_int_equal(picked[i], i == M_##NAME);                                                            \
    } else {                                                                                                       \
        n_sampled++;                                                                                               \
        assert_int_equal(picked[GNODE_REFLECTION], 1);                                                             \
        assert_int_equal(picked[GNODE_REFRACTION], 1);                                                             \
    }
    GMATERIAL_METHODS(CALL_BLENDED)
    assert_int_equal(n_picked, GNODE_METHOD_COUNT);
    assert_int_equal(n_sampled, N_METHODS - GNODE_METHOD_COUNT);
    gmaterial_unref(node);
    gmaterial_unref(probe);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_list_is_the_class),
        cmocka_unit_test(test_node_method_names),
        cmocka_unit_test_setup_teardown(test_dispatch_calls_the_slot, setup, teardown),
        cmocka_unit_test_setup_teardown(test_unless_bits, setup, teardown),
        {"test_defaults (rgb)", test_defaults, setup, teardown, (void *)"rgb"},
        {"test_defaults (spectrum)", test_defaults, setup, teardown, (void *)"spectrum"},
        cmocka_unit_test_setup_teardown(test_child_methods, setup, teardown),
        cmocka_unit_test_setup_teardown(test_blended_methods, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
