/* test_material_clear_dispatch.c - gmaterial_absorption for a material with GMAT_CLEAR (material.h): the light
 * itself, its kind and samples bit for bit (nothing copied when the result is the light), for a point and for none
 * and at any length, without a call to the class, whether the bit was set on the material directly or by the node
 * kit (gnode_inherit_clear, as the transform node and a node of one's own get it over a clear child); a material
 * without the bit still has its class's absorption called, which here answers half the light. In rgb and spectrum. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/kit/affine.h"
#include "generic/kit/material_kit.h"
#include "generic/kit/node_kit.h"
#include "generic/material.h"
#include "generic/nodes.h"
#include "test_util.h"

/* Calls of the absorption slots below. */
static int calls;

/* Half the light at any length, counted: not the light, so a call the dispatch should not make shows. */
static int counted_half(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    (void)self, (void)sp, (void)length;
    calls++;
    return gcolor_scale(result, illum, 0.5);
}

static void plain_destroy(GMaterial *self) { gmem_free(self); }

static const GMaterialClass half_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "half", .description = "absorbs half the light (tests)",
    .destroy = plain_destroy, .absorption = counted_half,
};

/* A one-child node whose absorption is its own: half of what the child's gives, counted. */
static int counted_half_child(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                              GColor *result)
{
    calls++;
    int rc = gmaterial_absorption(gnode_child_of(self), sp, illum, length, result);
    return rc ? rc : gcolor_scale(result, result, 0.5);
}

static const GMaterialClass half_node_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "half-node", .description = "half the child's absorption (tests)",
    .destroy = gnode_child_destroy, .absorption = counted_half_child,
};

typedef struct Fix {
    GColorModel *model;
    GScratch *scratch;
    GSurfPoint sp;
    GColor light, out, half;
} Fix;

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    if (!f || gcolormodel_create(*state, NULL, &f->model, &err) != G_OK)
        return -1;
    f->scratch = gscratch_create(0);
    if (!f->scratch || gcolor_alloc(&f->light, f->model) != G_OK || gcolor_alloc(&f->out, f->model) != G_OK ||
        gcolor_alloc(&f->half, f->model) != G_OK)
        return -1;
    gsurfpoint_init(&f->sp, f->model, f->scratch);
    f->sp.u = 0.3;
    f->sp.v = 0.6;
    f->sp.point = f->sp.object_point = gvec3(0.3, 0.6, 0.0);
    f->sp.geometric_normal = gvec3(0, 0, 1);
    f->sp.dpdu = gvec3(1, 0, 0);
    f->sp.dpdv = gvec3(0, 1, 0);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    gcolor_free(&f->light);
    gcolor_free(&f->out);
    gcolor_free(&f->half);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
    free(f);
    return 0;
}

/* 1 when x and y hold the same kind and values, bit for bit. */
static int same_bits(const GColor *x, const GColor *y)
{
    return x->kind == y->kind && memcmp(x->v, y->v, (size_t)x->model->nvalues * sizeof(float)) == 0;
}

/* Fills c with NaN bits (no light has them), so that a result nobody wrote shows. */
static void poison(GColor *c) { memset(c->v, 0xff, (size_t)c->model->nvalues * sizeof(float)); }

/* Light number k: black, white, then lights of rgb values drawn in [0, 10) from *s, every third scaled by 1e30. */
static void make_light(Fix *f, int k, unsigned long long *s)
{
    double rgb[3] = {1.0, 1.0, 1.0};
    if (k == 0) {
        gcolor_black(&f->light);
        return;
    }
    if (k > 1)
        for (int j = 0; j < 3; j++)
            rgb[j] = 10.0 * tu_uniform(s);
    assert_int_equal(gcolor_from_rgb(&f->light, rgb, GCOLOR_LIGHT), G_OK);
    if (k > 1 && k % 3 == 0)
        assert_int_equal(gcolor_scale(&f->light, &f->light, 1e30), G_OK);
}

#define NLIGHTS 8
static const double lengths[] = {0.0, 1e-3, 1.0, 1e3, -1.0}; /* a clear material answers for any length */
#define NLENGTHS (sizeof lengths / sizeof lengths[0])

/* gmaterial_absorption of the clear m gives each light back at each length, at the point and for none, into
 * another colour and in place, with no call of an absorption slot. */
static void gives_light_back_uncalled(Fix *f, const GMaterial *m)
{
    assert_true(m->flags & GMAT_CLEAR);
    GColor in_place;
    assert_int_equal(gcolor_alloc(&in_place, f->model), G_OK);
    unsigned long long s = 5;
    calls = 0;
    for (int k = 0; k < NLIGHTS; k++) {
        make_light(f, k, &s);
        for (size_t i = 0; i < NLENGTHS; i++)
            for (int at = 0; at < 2; at++) {
                GSurfPoint *sp = at ? &f->sp : NULL;
                poison(&f->out);
                assert_int_equal(gmaterial_absorption(m, sp, &f->light, lengths[i], &f->out), G_OK);
                assert_true(same_bits(&f->out, &f->light));
                assert_int_equal(gcolor_copy(&in_place, &f->light), G_OK);
                assert_int_equal(gmaterial_absorption(m, sp, &in_place, lengths[i], &in_place), G_OK);
                assert_true(same_bits(&in_place, &f->light));
            }
    }
    assert_int_equal(calls, 0);
    gcolor_free(&in_place);
}

/* gmaterial_absorption of m (without the bit) calls an absorption slot and gives half the light, into another
 * colour and in place. */
static void calls_the_class(Fix *f, const GMaterial *m)
{
    assert_false(m->flags & GMAT_CLEAR);
    unsigned long long s = 7;
    calls = 0;
    int expected = 0;
    for (int k = 1; k < NLIGHTS; k++) {
        make_light(f, k, &s);
        assert_int_equal(gcolor_scale(&f->half, &f->light, 0.5), G_OK);
        for (size_t i = 0; i < NLENGTHS - 1; i++) {
            poison(&f->out);
            assert_int_equal(gmaterial_absorption(m, &f->sp, &f->light, lengths[i], &f->out), G_OK);
            assert_true(same_bits(&f->out, &f->half));
            assert_int_equal(gmaterial_absorption(m, NULL, &f->light, lengths[i], &f->light), G_OK); /* in place */
            assert_true(same_bits(&f->light, &f->half));
            assert_int_equal(gcolor_scale(&f->light, &f->light, 2.0), G_OK); /* back, exactly */
            expected += 2;
        }
    }
    assert_true(calls >= expected); /* a node over an unflagged leaf calls two slots */
}

/* A class with an absorption slot of its own: gmaterial_init does not set the bit, and the slot is called; set on
 * the material directly, the bit makes the dispatch give the light back without the slot. */
static void test_flagged_directly(void **state)
{
    Fix *f = *state;
    GMaterial *m;
    GError err;
    assert_int_equal(gmaterial_new(&half_class, f->model, sizeof *m, &m, &err), G_OK);
    assert_false(gmaterial_clear(m));
    calls_the_class(f, m);
    m->flags |= GMAT_CLEAR;
    gives_light_back_uncalled(f, m);
    m->flags &= ~GMAT_CLEAR; /* and back: the slot again */
    calls_the_class(f, m);
    gmaterial_unref(m);
}

/* Nodes flagged by the kit: the transform node over a leaf with the bit, and a node of one's own whose absorption
 * halves its child's, given the bit by gnode_inherit_clear over a clear child; neither node's slot nor the leaf's
 * is called. Over the leaf without the bit the nodes get no bit and their slots are called. */
static void test_flagged_through_a_node(void **state)
{
    Fix *f = *state;
    GMaterial *leaf, *clear_leaf, *node[4];
    GError err;
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gmaterial_new(&half_class, f->model, sizeof *leaf, &leaf, &err), G_OK);
    assert_int_equal(gmaterial_new(&half_class, f->model, sizeof *clear_leaf, &clear_leaf, &err), G_OK);
    clear_leaf->flags |= GMAT_CLEAR;
    GMaterial *kids[4] = {clear_leaf, clear_leaf, leaf, leaf};
    for (int i = 0; i < 4; i++) {
        if (i % 2 == 0) {
            assert_int_equal(gnode_transform_create(kids[i], &uv, NULL, &node[i], &err), G_OK);
            continue;
        }
        assert_int_equal(gnode_child_new(&half_node_class, kids[i], NULL, 0, sizeof(GNodeChild), &node[i], &err),
                         G_OK);
        gnode_inherit_clear(node[i], &kids[i], 1);
    }
    for (int i = 0; i < 2; i++)
        gives_light_back_uncalled(f, node[i]);
    calls_the_class(f, node[2]); /* the transform passes the leaf's half on */
    calls = 0;
    assert_int_equal(gmaterial_absorption(node[3], &f->sp, &f->light, 1.0, &f->out), G_OK);
    assert_int_equal(calls, 2); /* the node's slot and the leaf's */
    for (int i = 3; i >= 0; i--)
        gmaterial_unref(node[i]);
    gmaterial_unref(leaf);
    gmaterial_unref(clear_leaf);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    static const char *const models[] = {"rgb", "spectrum"};
    int failed = 0;
    for (int i = 0; i < 2; i++) {
        const struct CMUnitTest tests[] = {
            cmocka_unit_test_prestate_setup_teardown(test_flagged_directly, setup, teardown, (void *)models[i]),
            cmocka_unit_test_prestate_setup_teardown(test_flagged_through_a_node, setup, teardown, (void *)models[i]),
        };
        failed += cmocka_run_group_tests_name(models[i], tests, NULL, NULL);
    }
    return failed;
}
