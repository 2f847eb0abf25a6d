/* test_material_clear_dispatch.c - gmaterial_absorption for a material with GMAT_CLEAR (material.h): the light
 * itself, its kind and samples bit for bit (nothing copied when the result is the light), at a point and for none
 * and at any length, without a call to the class, whether the bit was set on the material directly or by the node
 * kit (gnode_inherit_clear: the transform node and a node of one's own over a clear child). A material without the
 * bit still has its class's absorption called and its answer handed on. The leaf is texture_fixtures.h's counting
 * material, whose absorption at a point multiplies the light by its colour: another answer than the light's. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/kit/affine.h>
#include <generic/kit/node_kit.h>
#include <generic/nodes.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include "node_fixture.h"

/* Calls of the node's absorption below. */
static int node_calls;

/* A one-child node whose absorption is its child's (the kit's pass-through), counted. */
static int counted_child_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                                    GColor *result)
{
    node_calls++;
    return gnode_child_absorption(self, sp, illum, length, result);
}

static const GMaterialClass counted_node_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "counted-node", .description = "the child's absorption (tests)",
    .destroy = gnode_child_destroy, .absorption = counted_child_absorption,
};

/* 1 when x and y hold the same kind and values, bit for bit. */
static int same_bits(const GColor *x, const GColor *y)
{
    return x->kind == y->kind && memcmp(x->v, y->v, (size_t)x->model->nvalues * sizeof(float)) == 0;
}

/* Fills c with NaN bits (no light has them), so that a result nobody wrote shows. */
static void poison(GColor *c) { memset(c->v, 0xff, (size_t)c->model->nvalues * sizeof(float)); }

/* Light number k into f->illum: black, white, then lights of rgb values drawn in [0, 10) from *s, every third
 * scaled by 1e30. */
static void make_light(Fix *f, int k, unsigned long long *s)
{
    double rgb[3] = {1.0, 1.0, 1.0};
    if (k == 0) {
        gcolor_black(&f->illum);
        return;
    }
    if (k > 1)
        for (int j = 0; j < 3; j++)
            rgb[j] = 10.0 * tu_uniform(s);
    assert_int_equal(gcolor_from_rgb(&f->illum, rgb, GCOLOR_LIGHT), G_OK);
    if (k > 1 && k % 3 == 0)
        assert_int_equal(gcolor_scale(&f->illum, &f->illum, 1e30), G_OK);
}

#define NLIGHTS 8
static const double lengths[] = {0.0, 1e-3, 1.0, 1e3, -1.0}; /* a clear material answers for any length */
#define NLENGTHS (sizeof lengths / sizeof lengths[0])

/* gmaterial_absorption of the clear m gives each light back at each length, at the point and for none, into
 * another colour (f->c) and in place, with no call of leaf's absorption or the counted node's. */
static void gives_light_back_uncalled(Fix *f, const GMaterial *m, CountMat *leaf)
{
    assert_true(gmaterial_clear(m));
    GColor in_place;
    assert_int_equal(gcolor_alloc(&in_place, f->rgb), G_OK);
    unsigned long long s = 5;
    leaf->calls[GNODE_ABSORPTION] = node_calls = 0;
    for (int k = 0; k < NLIGHTS; k++) {
        make_light(f, k, &s);
        for (size_t i = 0; i < NLENGTHS; i++)
            for (int at = 0; at < 2; at++) {
                GSurfPoint *sp = at ? &f->sp : NULL;
                poison(&f->c);
                assert_int_equal(gmaterial_absorption(m, sp, &f->illum, lengths[i], &f->c), G_OK);
                assert_true(same_bits(&f->c, &f->illum));
                assert_int_equal(gcolor_copy(&in_place, &f->illum), G_OK);
                assert_int_equal(gmaterial_absorption(m, sp, &in_place, lengths[i], &in_place), G_OK);
                assert_true(same_bits(&in_place, &f->illum));
            }
    }
    assert_int_equal(leaf->calls[GNODE_ABSORPTION], 0);
    assert_int_equal(node_calls, 0);
    gcolor_free(&in_place);
}

/* gmaterial_absorption of m, which has no GMAT_CLEAR and whose absorption reaches leaf's at the point, hands on its
 * class's answer (asked directly), which is not the light, into another colour and in place; leaf's slot is
 * called for each. */
static void calls_the_class(Fix *f, const GMaterial *m, CountMat *leaf)
{
    assert_false(gmaterial_clear(m));
    GColor own, in_place;
    assert_int_equal(gcolor_alloc(&own, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&in_place, f->rgb), G_OK);
    unsigned long long s = 7;
    int n = 0;
    leaf->calls[GNODE_ABSORPTION] = 0;
    for (int k = 1; k < NLIGHTS; k++) {
        make_light(f, k, &s);
        for (size_t i = 0; i + 1 < NLENGTHS; i++, n++) {
            assert_int_equal(m->cls->absorption(m, &f->sp, &f->illum, lengths[i], &own), G_OK);
            assert_false(same_bits(&own, &f->illum)); /* the class absorbs: a call would show */
            poison(&f->c);
            assert_int_equal(gmaterial_absorption(m, &f->sp, &f->illum, lengths[i], &f->c), G_OK);
            assert_true(same_bits(&f->c, &own));
            assert_int_equal(gcolor_copy(&in_place, &f->illum), G_OK);
            assert_int_equal(gmaterial_absorption(m, &f->sp, &in_place, lengths[i], &in_place), G_OK);
            assert_true(same_bits(&in_place, &own));
        }
    }
    assert_int_equal(leaf->calls[GNODE_ABSORPTION], 3 * n);
    gcolor_free(&own);
    gcolor_free(&in_place);
}

/* The counting material has an absorption slot: gmaterial_init does not set the bit, and the slot is called; set on
 * the material directly, the bit makes the dispatch give the light back without the slot; cleared, the slot again. */
static void test_flagged_directly(void **state)
{
    Fix *f = *state;
    CountMat *leaf = countmat_new(f->rgb, 0.5, 0.25, 2.0);
    assert_non_null(leaf);
    calls_the_class(f, &leaf->base, leaf);
    leaf->base.flags |= GMAT_CLEAR;
    gives_light_back_uncalled(f, &leaf->base, leaf);
    leaf->base.flags &= ~GMAT_CLEAR;
    calls_the_class(f, &leaf->base, leaf);
    gmaterial_unref(&leaf->base);
}

/* Nodes flagged by the kit over a counting material with the bit: the transform node and the counted node (given
 * the bit by gnode_inherit_clear); neither node's slot nor the leaf's is called. Over the leaf without the bit the
 * nodes get no bit, and the dispatch calls their slots: the counted node's hands the leaf's answer on, the
 * transform's asks the leaf for no point. */
static void test_flagged_through_a_node(void **state)
{
    Fix *f = *state;
    GError err;
    GAffine2 uv = gaffine2_rotate(30.0);
    CountMat *leaves[2] = {countmat_new(f->rgb, 0.5, 0.25, 2.0), countmat_new(f->rgb, 0.5, 0.25, 2.0)};
    assert_true(leaves[0] && leaves[1]);
    leaves[0]->base.flags |= GMAT_CLEAR;
    GMaterial *transform[2], *counted[2];
    for (int i = 0; i < 2; i++) {
        GMaterial *leaf = &leaves[i]->base;
        assert_int_equal(gnode_transform_create(leaf, &uv, NULL, &transform[i], &err), G_OK);
        assert_int_equal(gnode_child_new(&counted_node_class, leaf, NULL, 0, sizeof(GNodeChild), &counted[i], &err),
                         G_OK);
        gnode_inherit_clear(counted[i], &leaf, 1);
    }
    gives_light_back_uncalled(f, transform[0], leaves[0]);
    gives_light_back_uncalled(f, counted[0], leaves[0]);

    node_calls = 0;
    calls_the_class(f, counted[1], leaves[1]);
    assert_int_equal(node_calls, leaves[1]->calls[GNODE_ABSORPTION]); /* each call through the node */
    assert_false(gmaterial_clear(transform[1]));
    leaves[1]->calls[GNODE_ABSORPTION] = 0;
    assert_int_equal(gmaterial_absorption(transform[1], &f->sp, &f->illum, 1.0, &f->c), G_OK);
    assert_int_equal(leaves[1]->calls[GNODE_ABSORPTION], 1);
    for (int i = 1; i >= 0; i--) {
        gmaterial_unref(counted[i]);
        gmaterial_unref(transform[i]);
        gmaterial_unref(&leaves[i]->base);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_flagged_directly, setup, teardown),
        cmocka_unit_test_setup_teardown(test_flagged_through_a_node, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
