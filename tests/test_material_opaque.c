/* test_material_opaque.c - GMAT_OPAQUE (material.h): which materials and nodes get the bit (every built-in
 * material without an opaque slot, not the dielectric; a node whose opacity is its children's when each of them
 * has it, not one over glass, whose opacity stays the children's at each point), and that the bit makes
 * gmaterial_opaque answer 1 without calling the class. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/affine.h>
#include <generic/materials.h>
#include <generic/node_kit.h>
#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

#include "node_fixture.h"

static int flagged(const GMaterial *m) { return (m->flags & GMAT_OPAQUE) != 0; }

static GMaterial *grey_lambert(Fix *f, double r)
{
    GColor c;
    double rgb[3] = {r, r, r};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gcolor_alloc(&c, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(glambert_create(f->rgb, &c, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

/* Every built-in material type: the bit exactly when the class has no opaque slot (all but the dielectric). */
static void test_leaf_materials(void **state)
{
    (void)state;
    static const char *const text =
        "colormodel bispectral\n"
        "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"
        "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"
        "material l lambert { reflectance rgb 0.5 0.5 0.5 }\n"
        "material p phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.5 0.5 0.5 exponent 50 }\n"
        "material m mirror\n"
        "material fv fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
        "material fp fluorescent-phong { matrix dayglo ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
        "material e emitter { radiance rgb 1 0.5 0.25 }\n"
        "material d dielectric\n";
    GLibrary *lib = NULL;
    GError err;
    if (greader_load_string(text, "opaque.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    static const char *const opaque_names[] = {"l", "p", "m", "fv", "fp", "e"};
    for (size_t i = 0; i < sizeof opaque_names / sizeof opaque_names[0]; i++) {
        GMaterial *m = glibrary_material(lib, opaque_names[i]);
        assert_non_null(m);
        assert_null(m->cls->opaque);
        assert_true(flagged(m));
        assert_int_equal(gmaterial_opaque_everywhere(m), 1);
    }
    GMaterial *d = glibrary_material(lib, "d");
    assert_non_null(d->cls->opaque);
    assert_false(flagged(d));
    assert_int_equal(gmaterial_opaque_everywhere(d), 0);
    assert_int_equal(gmaterial_opaque_everywhere(NULL), 0); /* vacuum lets light through */
    glibrary_destroy(lib);
}

/* Nodes over opaque children have the bit, and their class's own slot agrees (1); a node with a glass child has
 * none, and is transparent where the generator blends the glass in and opaque where it does not. */
static void test_nodes(void **state)
{
    Fix *f = *state;
    GMaterial *a = grey_lambert(f, 0.2), *b = grey_lambert(f, 0.8), *c = grey_lambert(f, 0.5), *glass = NULL;
    GError err;
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    CountGen *g = countgen_new(0.4);
    GMaterial *kids[3] = {a, b, c}, *n[8];
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gnode_interpolate_create(a, b, &g->base, &n[0], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(a, b, &g->base, GNODE_DIFFUSE, &n[1], &err), G_OK);
    assert_int_equal(gnode_spline_create(kids, 3, &g->base, GSPLINE_CATMULL_ROM, &n[2], &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 3, &g->base, &n[3], &err), G_OK);
    assert_int_equal(gnode_bump_create(a, &g->base, 1.0, &n[4], &err), G_OK);
    assert_int_equal(gnode_scale_create(b, &g->base, &n[5], &err), G_OK);
    assert_int_equal(gnode_transform_create(c, &uv, NULL, &n[6], &err), G_OK);
    GMaterial *inner[2] = {n[0], n[6]}; /* a node of nodes */
    assert_int_equal(gnode_spline_create(inner, 2, &g->base, GSPLINE_LINEAR, &n[7], &err), G_OK);
    for (int i = 0; i < 8; i++) {
        assert_non_null(n[i]->cls->opaque); /* the bit comes from the children, not a missing slot */
        if (!flagged(n[i]))
            fail_msg("node %d (%s) has no GMAT_OPAQUE", i, gmaterial_name(n[i]));
        assert_int_equal(n[i]->cls->opaque(n[i], &f->sp), 1);
        call_all(f, n[i]); /* every method still answers */
    }
    /* over glass: no bit anywhere up the tree */
    GMaterial *m[4];
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &m[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, NULL, &m[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &m[2], &err), G_OK);
    GMaterial *mixed[2] = {n[0], m[0]};
    assert_int_equal(gnode_spline_create(mixed, 2, &g->base, GSPLINE_LINEAR, &m[3], &err), G_OK);
    for (int i = 0; i < 4; i++) {
        if (flagged(m[i]))
            fail_msg("node %d (%s) over glass has GMAT_OPAQUE", i, gmaterial_name(m[i]));
        assert_int_equal(gmaterial_opaque_everywhere(m[i]), 0);
    }
    /* point by point: t = 0.4 blends the glass in (transparent), t = 0 shows the lambert alone (opaque) */
    assert_int_equal(gmaterial_opaque(m[0], &f->sp), 0);
    g->value = 0.0;
    GSurfPoint fresh;
    plane_point(&fresh, f->rgb, f->scratch, 0.3, 0.4); /* no cached generator value */
    assert_int_equal(gmaterial_opaque(m[0], &fresh), 1);
    for (int i = 3; i >= 0; i--)
        gmaterial_unref(m[i]);
    for (int i = 7; i >= 0; i--)
        gmaterial_unref(n[i]);
    gmaterial_unref(a);
    gmaterial_unref(b);
    gmaterial_unref(c);
    gmaterial_unref(glass);
    ggenerator_unref(&g->base);
}

/* A class whose opaque slot says 0 and counts its calls. */
static int see_through_calls;
static void see_through_destroy(GMaterial *self) { gmem_free(self); }
static int see_through_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    see_through_calls++;
    return 0;
}
static const GMaterialClass see_through_class = {.abi_version = GMATERIAL_ABI_VERSION,
                                                 .name = "see_through",
                                                 .description = "transparent everywhere (tests)",
                                                 .destroy = see_through_destroy,
                                                 .opaque = see_through_opaque};

/* Without the bit the slot decides (0); with it set by hand gmaterial_opaque answers 1 and never calls the
 * class, also through a node; clearing it restores the slot's answer. */
static void test_bit_skips_the_class(void **state)
{
    Fix *f = *state;
    GMaterial *m = gmem_calloc(1, sizeof *m);
    GError err;
    assert_int_equal(gmaterial_init(m, &see_through_class, f->rgb, &err), G_OK);
    assert_false(flagged(m));
    assert_int_equal(gmaterial_opaque(m, &f->sp), 0);
    assert_int_equal(see_through_calls, 1);
    m->flags |= GMAT_OPAQUE;
    GMaterial *node = NULL;
    GAffine2 uv = gaffine2_rotate(10.0);
    assert_int_equal(gnode_transform_create(m, &uv, NULL, &node, &err), G_OK);
    assert_true(flagged(node)); /* inherited from the (flagged) child */
    assert_int_equal(gmaterial_opaque(m, &f->sp), 1);
    assert_int_equal(gmaterial_opaque(node, &f->sp), 1);
    assert_int_equal(see_through_calls, 1);
    m->flags &= ~(unsigned)GMAT_OPAQUE;
    assert_int_equal(gmaterial_opaque(m, &f->sp), 0);
    assert_int_equal(see_through_calls, 2);
    gmaterial_unref(node);
    gmaterial_unref(m);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_leaf_materials),
        cmocka_unit_test_setup_teardown(test_nodes, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bit_skips_the_class, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
