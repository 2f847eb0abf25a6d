/* test_material_flags.c - the instance flags of material.h:
 *  - GMAT_NO_EMISSION: which materials and nodes get the bit (every built-in material without an emission slot,
 *    not the emitter; a node over children that all have it, not one over an emitter, whose emission stays the
 *    weighted child's), and that it makes gmaterial_emission answer black without calling the class;
 *  - GMAT_OPAQUE: the same for opacity (every built-in but the dielectric; a node over glass has no bit and is
 *    transparent where the glass is blended in), and that it makes gmaterial_opaque answer 1 without the class;
 *  - GMAT_GEOMETRIC_NORMAL: every built-in material has it (none has a normal slot), every kit node over such
 *    children but bump, no node over a child that tilts the normal; it makes gmaterial_normal and gsurfpoint_normal
 *    answer the geometric normal without calling the class, with the normals the class computes;
 *  - GMAT_LAMBERTIAN: lambert has it, no other built-in material (test_material_lambertian.c: nodes, the property);
 *  - GMAT_NO_IDEAL: which leaves and nodes get it, and that the dispatch's answer without a call is the slots';
 *  - GMAT_NO_REL_INDEX: which leaves and nodes get it, and that their slots do not see the relative index;
 *  - GMAT_CONSTANT_INDEX: which leaves and nodes get it (every built-in; the kit's pass-throughs and transform over a
 *    child that has it, no blend), and that their refraction index is the same bits at generated points as for
 *    no point;
 *  - GMAT_CLEAR: which leaves and nodes get it (every built-in but a dielectric that absorbs and a thinfilm over
 *    one; the kit's pass-throughs, transform, select and interpolate-one of another method over children that have
 *    it, no blend of several, whose arithmetic the test shows is not always the light's bits), and that their
 *    absorption gives the light back bit for bit at generated points, lengths and lights;
 *  - the material interface's version rose with the header (and stayed for the normal and Lambertian bits). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/kit/affine.h>
#include <generic/materials.h>
#include <generic/kit/node_kit.h>
#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

#include "node_fixture.h"

/* 1 when every sample of c is exactly 0. */
static int is_black(const GColor *c)
{
    for (int j = 0; j < c->model->nvalues; j++)
        if (c->v[j] != 0.0f)
            return 0;
    return 1;
}

static int dark(const GMaterial *m) { return (m->flags & GMAT_NO_EMISSION) != 0; }
static int solid(const GMaterial *m) { return (m->flags & GMAT_OPAQUE) != 0; }
static int flat(const GMaterial *m) { return (m->flags & GMAT_GEOMETRIC_NORMAL) != 0; }

/* A lambert of grey reflectance r and an emitter of grey radiance e (two-sided) in f's model. */
static GMaterial *lambert(Fix *f, double r)
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

static GMaterial *emitter(Fix *f, double r, double g, double b)
{
    GColor c;
    double rgb[3] = {r, g, b};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gcolor_alloc(&c, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gemitter_create(f->rgb, &c, 1, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

/* Every built-in material type: GMAT_NO_EMISSION exactly when the class has no emission slot (all but the
 * emitter; the fluorescent materials re-radiate in reflection(), their emission is black), GMAT_OPAQUE exactly when
 * it has no opaque slot (all but the dielectric), GMAT_LAMBERTIAN for lambert alone (its class sets it: phong has a
 * glossy lobe, mirror and dielectric are delta, the fluorescent ones have specular parts, the emitter reflects
 * nothing and says it is delta). */
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
        "material d dielectric\n"
        "material fv fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
        "material fp fluorescent-phong { matrix dayglo ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
        "material e emitter { radiance rgb 1 0.5 0.25 }\n";
    GLibrary *lib = NULL;
    GError err;
    if (greader_load_string(text, "emission.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    static const struct {
        const char *name;
        int emits, opaque, lambertian;
    } want[] = {{"l", 0, 1, 1}, {"p", 0, 1, 0}, {"m", 0, 1, 0}, {"d", 0, 0, 0},
                {"fv", 0, 1, 0}, {"fp", 0, 1, 0}, {"e", 1, 1, 0}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        GMaterial *m = glibrary_material(lib, want[i].name);
        assert_non_null(m);
        assert_int_equal(m->cls->emission != NULL, want[i].emits);
        assert_int_equal(dark(m), !want[i].emits);
        assert_int_equal(gmaterial_emits(m), want[i].emits);
        assert_int_equal(m->cls->opaque == NULL, want[i].opaque);
        assert_int_equal(solid(m), want[i].opaque);
        assert_int_equal(gmaterial_opaque_everywhere(m), want[i].opaque);
        assert_null(m->cls->normal); /* no built-in material changes the normal */
        assert_true(flat(m));
        assert_int_equal(gmaterial_lambertian(m), want[i].lambertian);
    }
    assert_int_equal(gmaterial_emits(NULL), 0);                /* vacuum emits nothing */
    assert_int_equal(gmaterial_opaque_everywhere(NULL), 0);    /* and lets light through */
    glibrary_destroy(lib);
}

/* Nodes of every kit kind over the lamberts a, b and c (blends, one-child nodes, a node of nodes) into n[8]. */
static void plain_nodes(GMaterial *a, GMaterial *b, GMaterial *c, CountGen *g, GMaterial *n[8])
{
    GError err;
    GMaterial *kids[3] = {a, b, c};
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
}

/* Releases, parents before children, the nm nodes m[nm - 1] down to m[0] a test made over plain_nodes' (m may be
 * NULL when nm is 0), then plain_nodes' n[7] down to n[0], the lamberts a, b and c, and the generator g. */
static void release_plain_nodes(GMaterial **m, int nm, GMaterial *n[8], GMaterial *a, GMaterial *b, GMaterial *c,
                                CountGen *g)
{
    for (int i = nm - 1; i >= 0; i--)
        gmaterial_unref(m[i]);
    for (int i = 7; i >= 0; i--)
        gmaterial_unref(n[i]);
    gmaterial_unref(a);
    gmaterial_unref(b);
    gmaterial_unref(c);
    ggenerator_unref(&g->base);
}

/* Nodes over lamberts have both bits, and their class's own slots agree: black emission, opaque. */
static void test_nodes_of_plain_leaves(void **state)
{
    Fix *f = *state;
    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8];
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    for (int i = 0; i < 8; i++) {
        assert_non_null(n[i]->cls->emission); /* the bits come from the children, not missing slots */
        assert_non_null(n[i]->cls->opaque);
        if (!solid(n[i]))
            fail_msg("node %d (%s) has no GMAT_OPAQUE", i, gmaterial_name(n[i]));
        assert_int_equal(n[i]->cls->opaque(n[i], &f->sp), 1);
        if (!dark(n[i]))
            fail_msg("node %d (%s) has no GMAT_NO_EMISSION", i, gmaterial_name(n[i]));
        assert_int_equal(gmaterial_emits(n[i]), 0);
        call_all(f, n[i]); /* every method still answers */
        /* the class's own slot agrees: black */
        assert_int_equal(n[i]->cls->emission(n[i], &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
        assert_true(is_black(&f->c));
    }
    release_plain_nodes(NULL, 0, n, a, b, c, g);
}

/* A node with a glass child has no GMAT_OPAQUE anywhere up the tree, and is transparent where the generator
 * blends the glass in (t = 0.4) and opaque where it shows the lambert alone (t = 0). */
static void test_nodes_over_glass(void **state)
{
    Fix *f = *state;
    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *glass = NULL, *n[8], *m[4];
    GError err;
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &m[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, NULL, &m[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &m[2], &err), G_OK);
    GMaterial *mixed[2] = {n[0], m[0]};
    assert_int_equal(gnode_spline_create(mixed, 2, &g->base, GSPLINE_LINEAR, &m[3], &err), G_OK);
    for (int i = 0; i < 4; i++) {
        if (solid(m[i]))
            fail_msg("node %d (%s) over glass has GMAT_OPAQUE", i, gmaterial_name(m[i]));
        assert_int_equal(gmaterial_opaque_everywhere(m[i]), 0);
    }
    assert_int_equal(gmaterial_opaque(m[0], &f->sp), 0);
    g->value = 0.0;
    GSurfPoint fresh;
    plane_point(&fresh, f->rgb, f->scratch, 0.3, 0.4); /* no cached generator value */
    assert_int_equal(gmaterial_opaque(m[0], &fresh), 1);
    release_plain_nodes(m, 4, n, a, b, c, g);
    gmaterial_unref(glass);
}

/* Reads the three channels of an rgb light. */
static void light_rgb(const GColor *c, double rgb[3]) { assert_int_equal(gcolor_to_rgb(c, GCOLOR_LIGHT, rgb), G_OK); }

/* A node with one emitting child has no bit, and its emission is the weighted child's: interpolate at t = 0.25
 * is 0.25 E, a linear spline halfway between a lambert and the emitter 0.5 E, scale by 0.6 is 0.6 E, and the
 * one-child nodes pass E on. */
static void test_nodes_with_an_emitter(void **state)
{
    Fix *f = *state;
    GMaterial *l = lambert(f, 0.5), *e = emitter(f, 2.0, 1.0, 0.5);
    CountGen *t = countgen_new(0.25), *half = countgen_new(0.25), *factor = countgen_new(0.6), *one = countgen_new(1.0);
    GError err;
    GMaterial *kids[3] = {l, e, l}, *n[6];
    GAffine2 uv = gaffine2_translate(0.1, 0.2);
    assert_int_equal(gnode_interpolate_create(l, e, &t->base, &n[0], &err), G_OK);
    assert_int_equal(gnode_spline_create(kids, 3, &half->base, GSPLINE_LINEAR, &n[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(e, &factor->base, &n[2], &err), G_OK);
    assert_int_equal(gnode_bump_create(e, &t->base, 1.0, &n[3], &err), G_OK);
    assert_int_equal(gnode_transform_create(e, &uv, NULL, &n[4], &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 3, &one->base, &n[5], &err), G_OK); /* index 1: the emitter */
    static const double weight[6] = {0.25, 0.5, 0.6, 1.0, 1.0, 1.0};
    double want[3], got[3];
    assert_int_equal(gmaterial_emission(e, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    light_rgb(&f->c, want);
    assert_float_equal(want[0], 2.0, 1e-5);
    for (int i = 0; i < 6; i++) {
        if (dark(n[i]))
            fail_msg("node %d (%s) over an emitter has GMAT_NO_EMISSION", i, gmaterial_name(n[i]));
        assert_int_equal(gmaterial_emits(n[i]), 1);
        assert_int_equal(gmaterial_emission(n[i], &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
        light_rgb(&f->c, got);
        for (int k = 0; k < 3; k++)
            if (fabs(got[k] - weight[i] * want[k]) > 1e-5)
                fail_msg("node %d (%s) channel %d: emission %g, expected %g * %g", i, gmaterial_name(n[i]), k, got[k],
                         weight[i], want[k]);
    }
    /* one emitting leaf deep in a tree: every node above it emits */
    GMaterial *top;
    assert_int_equal(gnode_interpolate_create(l, n[0], &t->base, &top, &err), G_OK);
    assert_false(dark(top));
    gmaterial_unref(top);
    for (int i = 5; i >= 0; i--)
        gmaterial_unref(n[i]);
    gmaterial_unref(l);
    gmaterial_unref(e);
    ggenerator_unref(&t->base);
    ggenerator_unref(&half->base);
    ggenerator_unref(&factor->base);
    ggenerator_unref(&one->base);
}

/* ---- a class with an emission slot that counts its calls and always glows ---- */

static int glow_calls;

static int glow_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    (void)self, (void)sp, (void)out;
    glow_calls++;
    return gcolor_fill(result, 1.0);
}

static void glow_destroy(GMaterial *self) { gmem_free(self); }

static const GMaterialClass glow_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "glow", .description = "emits 1 (tests)",
    .destroy = glow_destroy, .emission = glow_emission,
};

static const GMaterialClass plain_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "plain", .description = "no methods (tests)",
    .destroy = glow_destroy,
};

/* With the bit set by hand after init, gmaterial_emission answers black without calling the class; a node over
 * it takes the bit from it (the kit trusts the child's bit), so the class is not called through the node either. */
static void test_bit_skips_the_class(void **state)
{
    Fix *f = *state;
    GMaterial *m = gmem_calloc(1, sizeof *m), *p = gmem_calloc(1, sizeof *p);
    GError err;
    assert_int_equal(gmaterial_init(m, &glow_class, f->rgb, &err), G_OK);
    assert_int_equal(gmaterial_init(p, &plain_class, f->rgb, &err), G_OK);
    assert_int_equal(m->flags & GMAT_NO_EMISSION, 0u); /* a slot: the class decides */
    assert_int_equal(p->flags & GMAT_NO_EMISSION, (unsigned)GMAT_NO_EMISSION); /* no slot: black by default */
    glow_calls = 0;
    assert_int_equal(gmaterial_emission(m, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_int_equal(glow_calls, 1);
    assert_false(is_black(&f->c));
    m->flags |= GMAT_NO_EMISSION;
    assert_int_equal(gcolor_fill(&f->c, 3.0), G_OK);
    assert_int_equal(gmaterial_emission(m, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_int_equal(glow_calls, 1); /* not called */
    assert_true(is_black(&f->c));
    assert_int_equal(gmaterial_emits(m), 0);

    CountGen *g = countgen_new(0.5);
    GMaterial *n;
    assert_int_equal(gnode_interpolate_create(m, p, &g->base, &n, &err), G_OK);
    assert_true(dark(n));
    assert_int_equal(gmaterial_emission(n, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_int_equal(glow_calls, 1);
    assert_true(is_black(&f->c));
    assert_int_equal(g->calls, 0); /* not even the node's pick ran */
    gmaterial_unref(n);

    /* cleared again (always safe): the class is called, through the node only once rebuilt */
    m->flags &= ~(unsigned)GMAT_NO_EMISSION;
    assert_int_equal(gnode_interpolate_create(m, p, &g->base, &n, &err), G_OK);
    assert_false(dark(n));
    assert_int_equal(gmaterial_emission(n, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_int_equal(glow_calls, 1 + 1);
    double rgb[3];
    light_rgb(&f->c, rgb);
    assert_true(rgb[0] > 0.0);
    gmaterial_unref(n);
    ggenerator_unref(&g->base);

    /* a header made without gmaterial_init (flags 0) keeps calling its class: only slower, never wrong */
    GMaterial raw = {.cls = &glow_class, .model = f->rgb, .refcount = 1};
    assert_int_equal(gmaterial_emits(&raw), 1);
    assert_int_equal(gmaterial_emission(&raw, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_int_equal(glow_calls, 3);
    gmaterial_unref(m);
    gmaterial_unref(p);
}

/* ---- a class whose opaque slot says 0 and counts its calls ---- */

static int see_through_calls;

static int see_through_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    see_through_calls++;
    return 0;
}

static const GMaterialClass see_through_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "see_through", .description = "transparent everywhere (tests)",
    .destroy = glow_destroy, .opaque = see_through_opaque,
};

/* Without GMAT_OPAQUE the slot decides (0); set by hand, gmaterial_opaque answers 1 and never calls the class,
 * also through a node that inherits it; cleared, the slot answers again. */
static void test_opaque_bit_skips_the_class(void **state)
{
    Fix *f = *state;
    GMaterial *m = gmem_calloc(1, sizeof *m), *node = NULL;
    GError err;
    assert_int_equal(gmaterial_init(m, &see_through_class, f->rgb, &err), G_OK);
    assert_false(solid(m));
    see_through_calls = 0;
    assert_int_equal(gmaterial_opaque(m, &f->sp), 0);
    assert_int_equal(see_through_calls, 1);
    m->flags |= GMAT_OPAQUE;
    GAffine2 uv = gaffine2_rotate(10.0);
    assert_int_equal(gnode_transform_create(m, &uv, NULL, &node, &err), G_OK);
    assert_true(solid(node));
    assert_int_equal(gmaterial_opaque(m, &f->sp), 1);
    assert_int_equal(gmaterial_opaque(node, &f->sp), 1);
    assert_int_equal(see_through_calls, 1);
    m->flags &= ~(unsigned)GMAT_OPAQUE;
    assert_int_equal(gmaterial_opaque(m, &f->sp), 0);
    assert_int_equal(see_through_calls, 2);
    gmaterial_unref(node);
    gmaterial_unref(m);
}

/* ---- a class whose normal slot tilts the normal and counts its calls ---- */

static int tilt_calls;

static int tilt_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    (void)self;
    tilt_calls++;
    *n = gvec3_normalize(gvec3_add(sp->geometric_normal, gvec3(0.5, 0, 0)));
    return G_OK;
}

static const GMaterialClass tilt_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "tilt", .description = "a tilted normal (tests)",
    .destroy = glow_destroy, .normal = tilt_normal,
};

/* 1 when a and b are within 1e-12 (a blend of equal normals may round in its last bit). */
static int same_dir(GVec3 a, GVec3 b) { return gvec3_length(gvec3_sub(a, b)) <= 1e-12; }

/* The kit's nodes over lamberts have GMAT_GEOMETRIC_NORMAL, bump not; their class's own normal slot gives the
 * geometric normal, as the dispatch now does without it, at points where the generator blends both children;
 * bump's normal is still computed (and differs). Nodes over a tilting child or over bump have no bit. */
static void test_normal_bit_of_nodes(void **state)
{
    Fix *f = *state;
    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8], *m[5];
    GMaterial *t = gmem_calloc(1, sizeof *t);
    GError err;
    assert_int_equal(gmaterial_init(t, &tilt_class, f->rgb, &err), G_OK);
    assert_false(flat(t)); /* a slot: the class decides */
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    for (int i = 0; i < 8; i++) {
        assert_non_null(n[i]->cls->normal); /* the bit comes from the children, not a missing slot */
        if (flat(n[i]) != (i != 4))
            fail_msg("node %d (%s): GMAT_GEOMETRIC_NORMAL %d", i, gmaterial_name(n[i]), flat(n[i]));
        for (int k = 0; k < 4; k++) {
            GSurfPoint sp;
            plane_point(&sp, f->rgb, f->scratch, 0.1 + 0.2 * k, 0.7 - 0.15 * k);
            sp.geometric_normal = gvec3_normalize(gvec3(0.1 * k, -0.2, 1.0));
            sp.material = n[i];
            GVec3 own = gvec3(0, 0, 0), fast;
            assert_int_equal(n[i]->cls->normal(n[i], &sp, &own), G_OK);
            assert_int_equal(gmaterial_normal(n[i], &sp, &fast), G_OK);
            assert_true(same_dir(own, fast));
            assert_true(same_dir(own, gsurfpoint_normal(&sp)));
            if (i != 4)
                assert_true(same_dir(own, sp.geometric_normal));
        }
    }
    /* bump over a node with the bit still tilts the normal (a height ramp along u: atan(0.5) towards -x) */
    GGenerator *h;
    GMaterial *bumped;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(0.5, 0, 0), 0.0, &h, &err), G_OK);
    assert_int_equal(gnode_bump_create(n[0], h, 1.0, &bumped, &err), G_OK);
    assert_false(flat(bumped));
    GSurfPoint bp;
    plane_point(&bp, f->rgb, f->scratch, 0.3, 0.4);
    bp.material = bumped;
    GVec3 nb = gsurfpoint_normal(&bp);
    assert_float_equal(acos(nb.z), atan(0.5), 1e-12);
    assert_true(nb.x < 0.0);
    gmaterial_unref(bumped);
    ggenerator_unref(h);
    GAffine2 uv = gaffine2_rotate(30.0);
    GMaterial *kids[3] = {a, t, b};
    assert_int_equal(gnode_interpolate_create(a, t, &g->base, &m[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(t, &uv, NULL, &m[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(t, &g->base, &m[2], &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 3, &g->base, &m[3], &err), G_OK);
    assert_int_equal(gnode_interpolate_create(n[4], b, &g->base, &m[4], &err), G_OK); /* over bump */
    for (int i = 0; i < 5; i++)
        if (flat(m[i]))
            fail_msg("node %d (%s) over a tilting child has GMAT_GEOMETRIC_NORMAL", i, gmaterial_name(m[i]));
    tilt_calls = 0;
    GSurfPoint sp;
    plane_point(&sp, f->rgb, f->scratch, 0.3, 0.4);
    sp.material = m[1];
    GVec3 tilted = gsurfpoint_normal(&sp);
    assert_int_equal(tilt_calls, 1);
    assert_false(same_dir(tilted, sp.geometric_normal));
    release_plain_nodes(m, 5, n, a, b, c, g);
    gmaterial_unref(t);
}

/* With the bit set by hand, gmaterial_normal and gsurfpoint_normal answer the geometric normal without calling the
 * class, also through a node that inherits it (its pick does not run); cleared, the slot is called again. */
static void test_normal_bit_skips_the_class(void **state)
{
    Fix *f = *state;
    GMaterial *t = gmem_calloc(1, sizeof *t), *p = gmem_calloc(1, sizeof *p), *node = NULL;
    GError err;
    assert_int_equal(gmaterial_init(t, &tilt_class, f->rgb, &err), G_OK);
    assert_int_equal(gmaterial_init(p, &plain_class, f->rgb, &err), G_OK);
    assert_true(flat(p)); /* no slot: the geometric normal by default */
    GSurfPoint sp;
    plane_point(&sp, f->rgb, f->scratch, 0.3, 0.4);
    sp.material = t;
    tilt_calls = 0;
    GVec3 n = gsurfpoint_normal(&sp);
    assert_false(same_dir(n, sp.geometric_normal));
    n = gsurfpoint_normal(&sp); /* cached */
    assert_int_equal(tilt_calls, 1);
    t->flags |= GMAT_GEOMETRIC_NORMAL;
    gsurfpoint_invalidate(&sp);
    n = gsurfpoint_normal(&sp);
    assert_true(n.x == 0.0 && n.y == 0.0 && n.z == 1.0);
    assert_int_equal(gmaterial_normal(t, &sp, &n), G_OK);
    assert_true(n.x == 0.0 && n.y == 0.0 && n.z == 1.0);
    assert_int_equal(tilt_calls, 1); /* not called */

    CountGen *g = countgen_new(0.5);
    assert_int_equal(gnode_interpolate_create(t, p, &g->base, &node, &err), G_OK);
    assert_true(flat(node));
    GSurfPoint q;
    plane_point(&q, f->rgb, f->scratch, 0.3, 0.4);
    q.material = node;
    n = gsurfpoint_normal(&q);
    assert_true(n.x == 0.0 && n.y == 0.0 && n.z == 1.0);
    assert_int_equal(tilt_calls, 1);
    assert_int_equal(g->calls, 0); /* not even the node's pick ran */
    gmaterial_unref(node);

    /* cleared again (always safe): the class is called, through the node only once rebuilt */
    t->flags &= ~(unsigned)GMAT_GEOMETRIC_NORMAL;
    assert_int_equal(gnode_interpolate_create(t, p, &g->base, &node, &err), G_OK);
    assert_false(flat(node));
    plane_point(&q, f->rgb, f->scratch, 0.3, 0.4);
    q.material = node;
    n = gsurfpoint_normal(&q);
    assert_false(same_dir(n, q.geometric_normal));
    assert_int_equal(tilt_calls, 2);
    gmaterial_unref(node);
    ggenerator_unref(&g->base);
    gmaterial_unref(t);
    gmaterial_unref(p);
}

static int no_ideal(const GMaterial *m) { return (m->flags & GMAT_NO_IDEAL) != 0; }

/* GMAT_NO_IDEAL: the leaves without direction slots have it (lambert, emitter), mirror, dielectric and phong not;
 * every kit node over lamberts has it (transform too), a node over a mirror or a glass has not. Where it is set,
 * the dispatch (no call, no generator evaluated) gives what the node's own slots give by picking and blending:
 * 0 (not valid), with the direction untouched, over generated points, views, indices and generator values. */
static void test_no_ideal_bit(void **state)
{
    Fix *f = *state;
    GError err;
    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *e = emitter(f, 1, 1, 1), *n[8];
    GMaterial *mirror = NULL, *glass = NULL, *m[3];
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    assert_int_equal(gmirror_create(f->rgb, &f->illum, &mirror, &err), G_OK);
    assert_true(no_ideal(a) && no_ideal(e));
    assert_false(no_ideal(mirror) || no_ideal(glass));
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    for (int i = 0; i < 8; i++)
        if (!no_ideal(n[i]))
            fail_msg("node %d (%s) over lamberts has no GMAT_NO_IDEAL", i, gmaterial_name(n[i]));
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gnode_interpolate_create(a, mirror, &g->base, &m[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, NULL, &m[1], &err), G_OK);
    GMaterial *mixed[2] = {n[0], m[0]};
    assert_int_equal(gnode_spline_create(mixed, 2, &g->base, GSPLINE_LINEAR, &m[2], &err), G_OK);
    for (int i = 0; i < 3; i++)
        if (no_ideal(m[i]))
            fail_msg("node %d (%s) over a mirror or glass has GMAT_NO_IDEAL", i, gmaterial_name(m[i]));
    GColor ri;
    assert_int_equal(gcolor_alloc(&ri, f->rgb), G_OK);
    unsigned long long s = 5;
    for (int k = 0; k < 200; k++) {
        double r1 = tu_uniform(&s), r2 = tu_uniform(&s);
        g->value = (k % 5) / 4.0; /* 0, 0.25, ..., 1: one child or a blend of two */
        GVec3 view = gvec3_normalize(gvec3(r1 - 0.5, r2 - 0.5, k & 1 ? 0.7 : -0.7));
        assert_int_equal(gcolor_fill(&ri, k & 2 ? 1.5 : 1.0 / 1.5), G_OK);
        for (int i = 0; i < 8; i++) {
            GSurfPoint sp;
            plane_point(&sp, f->rgb, f->scratch, r1 * 4.0, r2 * 4.0); /* no cached generator value */
            GVec3 d0 = gvec3(7, 7, 7), d1 = d0, d2 = d0, d3 = d0;
            int before = g->calls;
            assert_int_equal(gmaterial_reflection_dir(n[i], &sp, view, &d0), 0);
            assert_int_equal(gmaterial_refraction_dir(n[i], &sp, view, &ri, &d1), 0);
            assert_int_equal(g->calls, before); /* the dispatch asked nothing */
            assert_int_equal(n[i]->cls->reflection_dir(n[i], &sp, view, &d2), 0);
            assert_int_equal(n[i]->cls->refraction_dir(n[i], &sp, view, &ri, &d3), 0);
            assert_true(d0.x == 7 && d1.x == 7 && d2.x == 7 && d3.x == 7); /* no direction written */
        }
    }
    gcolor_free(&ri);
    release_plain_nodes(m, 3, n, a, b, c, g);
    gmaterial_unref(e);
    gmaterial_unref(mirror);
    gmaterial_unref(glass);
}

/* The header grew, so the interface version rose to 4: a class of version 3 is refused, naming both. */
static void test_interface_version(void **state)
{
    (void)state;
    assert_int_equal(GMATERIAL_ABI_VERSION, 4);
    GMaterialClass old = glow_class;
    old.abi_version = 3;
    GMaterial m = {0};
    GError err;
    assert_int_equal(gmaterial_init(&m, &old, NULL, &err), G_ERR_VERSION);
    assert_non_null(strstr(err.message, "interface version 3, the library has 4"));
}

/* Every built-in leaf material by name, in bispectral (the fluorescent ones need its matrices): the flag tests
 * read which of them have a bit. */
static const char *const leaves_text =
    "colormodel bispectral\n"
    "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"
    "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"
    "material l lambert { reflectance rgb 0.5 0.5 0.5 }\n"
    "material p phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.5 0.5 0.5 exponent 50 }\n"
    "material m mirror\n"
    "material e emitter { radiance rgb 1 0.5 0.25 }\n"
    "material c conductor { metal Au roughness 0.3 }\n"
    "material pl plastic { reflectance rgb 0.3 0.5 0.2 roughness 0.2 }\n"
    "material t thindielectric { index 1.5 }\n"
    "material fv fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
    "material fp fluorescent-phong { matrix dayglo ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
    "material d dielectric\n"
    "material tf thinfilm { thickness 400 base lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
    "material ly layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.5 0.5 0.5 } }\n";

static int no_rel_index(const GMaterial *m) { return (m->flags & GMAT_NO_REL_INDEX) != 0; }

/* The class's own slots of m at two copies of one point, one with the relative index ri[0] and one with ri[1] (set
 * on the point and handed as the argument), for light from in leaving towards out: 1 when every status, colour,
 * direction, density and flag agrees bit for bit (sample with the numbers u1, u2). */
static int same_for_both_indices(Fix *f, const GMaterial *m, GSurfPoint sp[2], const GColor ri[2], GVec3 in,
                                 GVec3 out, double u1, double u2)
{
    const GMaterialClass *c = m->cls;
    GColor r[2], w[2];
    GVec3 d[2][3];
    double pdf[2];
    int rc[2][8], flags[2];
    GMaterialSample smp[2];
    for (int k = 0; k < 2; k++) {
        assert_int_equal(gcolor_alloc(&r[k], f->rgb), G_OK);
        assert_int_equal(gcolor_alloc(&w[k], f->rgb), G_OK);
    }
    int same = 1;
    for (int slot = 0; slot < 6; slot++) {
        for (int k = 0; k < 2; k++) {
            GSurfPoint *q = &sp[k];
            d[k][0] = d[k][1] = d[k][2] = gvec3(7, 7, 7);
            pdf[k] = -1.0;
            flags[k] = -1;
            memset(&smp[k], 0, sizeof smp[k]);
            gcolor_black(&r[k]);
            gcolor_black(&w[k]);
            switch (slot) {
            case 0: rc[k][0] = c->reflection ? c->reflection(m, q, in, &f->illum, out, &r[k]) : 0; break;
            case 1: rc[k][1] = c->refraction ? c->refraction(m, q, in, &f->illum, &ri[k], out, &r[k]) : 0; break;
            case 2:
                rc[k][2] = c->reflection_dir ? c->reflection_dir(m, q, gvec3_neg(out), &d[k][0]) : 0;
                rc[k][3] = c->refraction_dir ? c->refraction_dir(m, q, gvec3_neg(out), &ri[k], &d[k][1]) : 0;
                break;
            case 3:
                rc[k][4] = c->sample ? c->sample(m, q, out, &ri[k], u1, u2, &smp[k], &w[k]) : 0;
                d[k][2] = smp[k].in;
                pdf[k] = smp[k].pdf;
                flags[k] = smp[k].flags;
                break;
            case 4: pdf[k] = c->pdf ? c->pdf(m, q, in, out, &ri[k]) : 0.0; break;
            default:
                rc[k][5] = c->diffuse ? c->diffuse(m, q, &r[k]) : 0;
                rc[k][6] = c->is_delta ? c->is_delta(m, q) : 0;
                rc[k][7] = c->opaque ? c->opaque(m, q) : 1;
                break;
            }
        }
        same = same && memcmp(r[0].v, r[1].v, 3 * sizeof(float)) == 0 && memcmp(w[0].v, w[1].v, 3 * sizeof(float)) == 0;
        same = same && memcmp(d[0], d[1], sizeof d[0]) == 0 && memcmp(&pdf[0], &pdf[1], sizeof pdf[0]) == 0;
        same = same && flags[0] == flags[1];
    }
    for (int j = 0; j < 8; j++)
        same = same && rc[0][j] == rc[1][j];
    for (int k = 0; k < 2; k++) {
        gcolor_free(&r[k]);
        gcolor_free(&w[k]);
    }
    return same;
}

/* GMAT_NO_REL_INDEX: the built-ins whose methods read no relative index have it (lambert, phong, mirror, emitter,
 * conductor, plastic, the thin pane, the fluorescent materials), those that read it not (dielectric, thinfilm,
 * layer). The kit's nodes over lamberts have it (blends, bump, scale, transform, a node of nodes), so has a blend
 * of a lambert and a mirror and a scale over the thin pane (a pass-through); a node over a dielectric has not, nor
 * a blend over the thin pane (its ideal-refraction test reads the point's index). The flagged materials' slots give
 * the same results, bit for bit, for the relative indices 1.5 and 1 / 1.5 over generated points, directions (the
 * ideal ones among them), numbers and generator values; the dielectric does not. */
static void test_no_rel_index_bit(void **state)
{
    Fix *f = *state;
    GLibrary *lib = NULL;
    GError err;
    if (greader_load_string(leaves_text, "relindex.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    static const struct {
        const char *name;
        int flagged;
    } want[] = {{"l", 1}, {"p", 1}, {"m", 1}, {"e", 1}, {"c", 1}, {"pl", 1}, {"t", 1},
                {"fv", 1}, {"fp", 1}, {"d", 0}, {"tf", 0}, {"ly", 0}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        GMaterial *m = glibrary_material(lib, want[i].name);
        assert_non_null(m);
        if (no_rel_index(m) != want[i].flagged || gmaterial_no_rel_index(m) != want[i].flagged)
            fail_msg("%s: GMAT_NO_REL_INDEX %d, expected %d", want[i].name, no_rel_index(m), want[i].flagged);
    }
    glibrary_destroy(lib);
    assert_int_equal(gmaterial_no_rel_index(NULL), 1); /* vacuum reads nothing */

    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8], *yes[3], *no[5];
    GMaterial *mirror = NULL, *glass = NULL, *thin = NULL;
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    GDispersion thin_index = gdispersion_constant(1.5);
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    assert_int_equal(gmirror_create(f->rgb, &f->illum, &mirror, &err), G_OK);
    assert_int_equal(gthindielectric_create(f->rgb, &thin_index, &thin, &err), G_OK);
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    for (int i = 0; i < 8; i++)
        if (!no_rel_index(n[i]))
            fail_msg("node %d (%s) over lamberts has no GMAT_NO_REL_INDEX", i, gmaterial_name(n[i]));
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gnode_interpolate_create(a, mirror, &g->base, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(thin, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[0], &uv, NULL, &yes[2], &err), G_OK);
    for (int i = 0; i < 3; i++)
        if (!no_rel_index(yes[i]))
            fail_msg("node %d (%s) has no GMAT_NO_REL_INDEX", i, gmaterial_name(yes[i]));
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, NULL, &no[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &no[2], &err), G_OK);
    GMaterial *mixed[2] = {n[0], no[0]};
    assert_int_equal(gnode_spline_create(mixed, 2, &g->base, GSPLINE_LINEAR, &no[3], &err), G_OK);
    assert_int_equal(gnode_interpolate_create(a, thin, &g->base, &no[4], &err), G_OK);
    for (int i = 0; i < 5; i++)
        if (no_rel_index(no[i]))
            fail_msg("node %d (%s) over a dielectric or a blended pane has GMAT_NO_REL_INDEX", i,
                     gmaterial_name(no[i]));

    /* the property: every flagged material above, and the dielectric as the control that reads the index */
    const GMaterial *all[14];
    int nall = 0;
    for (int i = 0; i < 8; i++)
        all[nall++] = n[i];
    for (int i = 0; i < 3; i++)
        all[nall++] = yes[i];
    all[nall++] = mirror;
    all[nall++] = thin;
    all[nall++] = glass;
    GColor ri[2];
    for (int k = 0; k < 2; k++) {
        assert_int_equal(gcolor_alloc(&ri[k], f->rgb), G_OK);
        assert_int_equal(gcolor_fill(&ri[k], k ? 1.0 / 1.5 : 1.5), G_OK);
    }
    int rounds = TU_SANITIZED ? 40 : 200, glass_differs = 0;
    unsigned long long s = 11;
    for (int r = 0; r < rounds; r++) {
        double x[4];
        for (int j = 0; j < 4; j++)
            x[j] = tu_uniform(&s);
        g->value = (r % 5) / 4.0; /* 0, 0.25, ..., 1: one child or a blend of two */
        int below = r & 1;
        double up = below ? -1.0 : 1.0;
        GVec3 out = gvec3_normalize(gvec3(x[0] - 0.5, x[1] - 0.5, up * (0.2 + x[2]))), in;
        switch (r % 4) {
        case 0: in = gvec3(-out.x, -out.y, out.z); break; /* the mirror direction */
        case 1: /* the ideal refraction of the view -out for one of the indices */
            if (!goptics_refract(gvec3_neg(out), gvec3(0, 0, up), r & 2 ? 1.5 : 1.0 / 1.5, &in))
                in = gvec3_neg(out);
            else
                in = gvec3_neg(in);
            break;
        case 2: in = gvec3_neg(out); break; /* straight through */
        default: in = gvec3_normalize(gvec3(x[1] - 0.5, x[3] - 0.5, x[2] - 0.5)); break;
        }
        for (int i = 0; i < nall; i++) {
            GSurfPoint sp[2];
            for (int k = 0; k < 2; k++) {
                plane_point(&sp[k], f->rgb, f->scratch, x[0] * 4.0, x[1] * 4.0);
                if (below)
                    sp[k].geometric_normal = gvec3(0, 0, -1);
                sp[k].material = all[i];
                sp[k].entering = !below;
                sp[k].from = below ? all[i] : NULL;
                sp[k].to = below ? NULL : all[i];
                gsurfpoint_set_relative_index(&sp[k], &ri[k]);
            }
            int same = same_for_both_indices(f, all[i], sp, ri, in, out, x[2], x[3]);
            if (all[i] == glass)
                glass_differs += !same;
            else if (!same)
                fail_msg("%s (%d) gives other results for another relative index (round %d)", gmaterial_name(all[i]),
                         i, r);
        }
    }
    assert_true(glass_differs > rounds / 4); /* the comparison sees an index that is read */
    for (int k = 0; k < 2; k++)
        gcolor_free(&ri[k]);
    for (int i = 4; i >= 0; i--)
        gmaterial_unref(no[i]);
    for (int i = 2; i >= 0; i--)
        gmaterial_unref(yes[i]);
    release_plain_nodes(NULL, 0, n, a, b, c, g);
    gmaterial_unref(mirror);
    gmaterial_unref(glass);
    gmaterial_unref(thin);
}

static int constant_index(const GMaterial *m) { return (m->flags & GMAT_CONSTANT_INDEX) != 0; }

/* A class with a refraction_index slot of its own: the index 1.4 + 0.1 u (no bit: gmaterial_init cannot tell). */
static int varying_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)self;
    return gcolor_fill(result, 1.4 + (sp ? 0.1 * sp->u : 0.0));
}

static const GMaterialClass varying_index_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "varying-index", .description = "index 1.4 + 0.1 u (tests)",
    .destroy = glow_destroy, .refraction_index = varying_index,
};

/* 1 when the two colours hold the same kind and samples, bit for bit. */
static int same_bits(const GColor *x, const GColor *y)
{
    return x->kind == y->kind && memcmp(x->v, y->v, (size_t)x->model->nvalues * sizeof(float)) == 0;
}

/* Which leaves and nodes have GMAT_CONSTANT_INDEX, and, over generated points (both sides, positions, normals,
 * (u, v), generator values), the flagged ones' refraction index is the same bits as for sp NULL, which a blend of a
 * lambert and glass, the control, is not. */
static void test_constant_index_bit(void **state)
{
    Fix *f = *state;
    GLibrary *lib = NULL;
    GError err;
    if (greader_load_string(leaves_text, "constindex.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    static const char *const leaves[] = {"l", "p", "m", "e", "c", "pl", "t", "fv", "fp", "d", "tf", "ly"};
    for (size_t i = 0; i < sizeof leaves / sizeof leaves[0]; i++) {
        GMaterial *m = glibrary_material(lib, leaves[i]);
        assert_non_null(m);
        if (!constant_index(m) || !gmaterial_constant_index(m))
            fail_msg("%s has no GMAT_CONSTANT_INDEX", leaves[i]);
    }
    glibrary_destroy(lib);
    assert_int_equal(gmaterial_constant_index(NULL), 1); /* vacuum: 1 */

    GMaterial *plain = gmem_calloc(1, sizeof *plain), *varying = gmem_calloc(1, sizeof *varying);
    assert_int_equal(gmaterial_init(plain, &plain_class, f->rgb, &err), G_OK);
    assert_int_equal(gmaterial_init(varying, &varying_index_class, f->rgb, &err), G_OK);
    assert_int_equal(constant_index(plain), 1);   /* no slot: the default 1, set by gmaterial_init */
    assert_int_equal(constant_index(varying), 0); /* a slot of its own: not set */

    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8], *glass = NULL, *cauchy = NULL;
    GMaterial *yes[5], *no[4];
    GDielectricParams gp = {.index = gdispersion_constant(1.5)}, cp = {.index = gdispersion_cauchy(1.5, 4200.0, 0.0)};
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    assert_int_equal(gdielectric_create(f->rgb, &cp, &cauchy, &err), G_OK);
    assert_int_equal(constant_index(cauchy), 1); /* a fit of the wavelength, read at no point */
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    /* the one-child nodes (bump, scale, transform) pass their child's index; the blends do not get the bit */
    static const int over_lamberts[8] = {0, 0, 0, 0, 1, 1, 1, 0};
    for (int i = 0; i < 8; i++)
        if (constant_index(n[i]) != over_lamberts[i])
            fail_msg("node %d (%s) over lamberts: GMAT_CONSTANT_INDEX %d, expected %d", i, gmaterial_name(n[i]),
                     constant_index(n[i]), over_lamberts[i]);
    GAffine2 uv = gaffine2_rotate(30.0);
    GAffine3 move = gaffine3_translate(gvec3(1.0, -2.0, 0.5));
    assert_int_equal(gnode_bump_create(glass, &g->base, 1.0, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(cauchy, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, &move, &yes[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[1], NULL, &move, &yes[3], &err), G_OK);
    assert_int_equal(gnode_bump_create(plain, &g->base, 0.5, &yes[4], &err), G_OK);
    for (int i = 0; i < 5; i++)
        if (!constant_index(yes[i]))
            fail_msg("node %d (%s) over one constant index has no GMAT_CONSTANT_INDEX", i, gmaterial_name(yes[i]));
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(varying, &uv, NULL, &no[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(varying, &g->base, &no[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(no[0], &uv, NULL, &no[3], &err), G_OK);
    for (int i = 0; i < 4; i++)
        if (constant_index(no[i]))
            fail_msg("node %d (%s) over a blend or a varying index has GMAT_CONSTANT_INDEX", i, gmaterial_name(no[i]));

    /* the property: every flagged material's index at generated points is its index for no point, bit for bit */
    const GMaterial *all[20];
    int nall = 0;
    for (int i = 4; i < 7; i++)
        all[nall++] = n[i];
    for (int i = 0; i < 5; i++)
        all[nall++] = yes[i];
    all[nall++] = glass;
    all[nall++] = cauchy;
    all[nall++] = plain;
    all[nall++] = a;
    const GMaterial *control = no[0];
    GColor ref, at, first;
    assert_int_equal(gcolor_alloc(&ref, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&at, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&first, f->rgb), G_OK);
    int rounds = TU_SANITIZED ? 40 : 300, control_differs = 0;
    unsigned long long s = 17;
    for (int r = 0; r < rounds; r++) {
        double x[6];
        for (int j = 0; j < 6; j++)
            x[j] = tu_uniform(&s);
        g->value = x[5]; /* the generators' value: a blend of the lambert and the glass follows it */
        int below = r & 1;
        GSurfPoint sp;
        plane_point(&sp, f->rgb, f->scratch, 4.0 * x[0] - 1.0, 4.0 * x[1] - 1.0);
        sp.point = sp.object_point = gvec3(10.0 * x[2] - 5.0, 10.0 * x[3] - 5.0, 10.0 * x[4] - 5.0);
        sp.geometric_normal = gvec3_normalize(gvec3(x[2] - 0.5, x[3] - 0.5, (below ? -1.0 : 1.0) * (0.2 + x[4])));
        sp.entering = !below;
        sp.surface = r % 6;
        for (int i = 0; i <= nall; i++) {
            const GMaterial *m = i < nall ? all[i] : control;
            sp.material = m;
            sp.from = below ? m : NULL;
            sp.to = below ? NULL : m;
            gsurfpoint_invalidate(&sp);
            assert_int_equal(gmaterial_refraction_index(m, &sp, &at), G_OK);
            if (m == control) {
                if (r == 0)
                    assert_int_equal(gcolor_copy(&first, &at), G_OK);
                control_differs += !same_bits(&at, &first);
                continue;
            }
            assert_int_equal(gmaterial_refraction_index(m, NULL, &ref), G_OK);
            if (!same_bits(&at, &ref))
                fail_msg("%s (%d): another refraction index at a generated point (round %d)", gmaterial_name(m), i, r);
        }
    }
    assert_true(control_differs > rounds / 2); /* the comparison sees an index that varies */
    gcolor_free(&ref);
    gcolor_free(&at);
    gcolor_free(&first);
    for (int i = 3; i >= 0; i--)
        gmaterial_unref(no[i]);
    for (int i = 4; i >= 0; i--)
        gmaterial_unref(yes[i]);
    release_plain_nodes(NULL, 0, n, a, b, c, g);
    gmaterial_unref(glass);
    gmaterial_unref(cauchy);
    gmaterial_unref(plain);
    gmaterial_unref(varying);
}

static int clear(const GMaterial *m) { return (m->flags & GMAT_CLEAR) != 0; }

/* A class with an absorption slot of its own: half the light passes at any length (no bit: gmaterial_init cannot
 * tell). */
static int half_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    (void)self, (void)sp, (void)length;
    return gcolor_scale(result, illum, 0.5);
}

static const GMaterialClass absorbing_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "absorbing", .description = "half the light passes (tests)",
    .destroy = glow_destroy, .absorption = half_absorption,
};

/* A light of rgb values drawn in [0, 10) from *s, black one time in four. */
static void draw_light(GColor *light, unsigned long long *s)
{
    double rgb[3];
    for (int j = 0; j < 3; j++)
        rgb[j] = 10.0 * tu_uniform(s);
    if (tu_uniform(s) < 0.25)
        gcolor_black(light);
    else
        assert_int_equal(gcolor_from_rgb(light, rgb, GCOLOR_LIGHT), G_OK);
}

/* m's absorption of light over length at sp (NULL: none) into at, filled with NaN bits first: 1 when it is the
 * light, bit for bit. */
static int gives_light_back(const GMaterial *m, GSurfPoint *sp, const GColor *light, double length, GColor *at)
{
    memset(at->v, 0xff, (size_t)at->model->nvalues * sizeof(float));
    return gmaterial_absorption(m, sp, light, length, at) == G_OK && same_bits(at, light);
}

/* Which leaves and nodes have GMAT_CLEAR; over generated points (both sides, positions, normals, (u, v), surface
 * indices, generator values), lengths and lights (black among them) the flagged ones give the light back bit for
 * bit, and so for sp NULL. A blend of two clear children, which does not get the bit, is shown to give other bits
 * for some lights and weights: w x + (1 - w) x rounds. */
static void test_clear_bit(void **state)
{
    Fix *f = *state;
    GLibrary *lib = NULL;
    GError err;
    static const char *const absorbing_text =
        "material da dielectric { index 1.5 absorption rgb 0.5 0.2 0.1 }\n"
        "material dz dielectric { index 1.5 absorption rgb 0 0 0 }\n"
        "material tfa thinfilm { thickness 400 base dielectric { index 1.5 absorption rgb 0.5 0.2 0.1 } }\n";
    char text[4096];
    snprintf(text, sizeof text, "%s%s", leaves_text, absorbing_text);
    if (greader_load_string(text, "clear.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    static const struct {
        const char *name;
        int clear;
    } leaves[] = {{"l", 1},  {"p", 1},  {"m", 1},  {"e", 1},  {"c", 1},  {"pl", 1}, {"t", 1},   {"fv", 1},
                  {"fp", 1}, {"d", 1},  {"tf", 1}, {"ly", 1}, {"da", 0}, {"dz", 1}, {"tfa", 0}};
    for (size_t i = 0; i < sizeof leaves / sizeof leaves[0]; i++) {
        GMaterial *m = glibrary_material(lib, leaves[i].name);
        assert_non_null(m);
        if (clear(m) != leaves[i].clear || gmaterial_clear(m) != leaves[i].clear)
            fail_msg("%s: GMAT_CLEAR %d, expected %d", leaves[i].name, clear(m), leaves[i].clear);
    }
    glibrary_destroy(lib);
    assert_int_equal(gmaterial_clear(NULL), 1); /* vacuum absorbs nothing */

    GMaterial *plain = gmem_calloc(1, sizeof *plain), *absorbing = gmem_calloc(1, sizeof *absorbing);
    assert_int_equal(gmaterial_init(plain, &plain_class, f->rgb, &err), G_OK);
    assert_int_equal(gmaterial_init(absorbing, &absorbing_class, f->rgb, &err), G_OK);
    assert_int_equal(clear(plain), 1);     /* no slot: the light itself, set by gmaterial_init */
    assert_int_equal(clear(absorbing), 0); /* a slot of its own: not set */

    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8], *glass = NULL, *tinted = NULL;
    GMaterial *yes[7], *no[7];
    GColor coeff;
    double k[3] = {0.5, 0.2, 0.1};
    assert_int_equal(gcolor_alloc(&coeff, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&coeff, k, GCOLOR_REFLECTANCE), G_OK);
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    GDielectricParams tp = {.index = gdispersion_constant(1.5), .absorption = &coeff};
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    assert_int_equal(gdielectric_create(f->rgb, &tp, &tinted, &err), G_OK);
    gcolor_free(&coeff);
    assert_int_equal(clear(glass), 1);
    assert_int_equal(clear(tinted), 0);
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    /* interpolate-one of the diffuse colour, select, bump, scale and transform give one child's absorption */
    static const int over_lamberts[8] = {0, 1, 0, 1, 1, 1, 1, 0};
    for (int i = 0; i < 8; i++)
        if (clear(n[i]) != over_lamberts[i])
            fail_msg("node %d (%s) over lamberts: GMAT_CLEAR %d, expected %d", i, gmaterial_name(n[i]), clear(n[i]),
                     over_lamberts[i]);
    GAffine2 uv = gaffine2_rotate(30.0);
    GAffine3 move = gaffine3_translate(gvec3(1.0, -2.0, 0.5));
    GMaterial *clear_kids[3] = {glass, a, plain}, *mixed_kids[3] = {glass, tinted, a};
    assert_int_equal(gnode_bump_create(glass, &g->base, 1.0, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, &move, &yes[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[1], NULL, &move, &yes[3], &err), G_OK);
    assert_int_equal(gnode_select_create(clear_kids, 3, &g->base, &yes[4], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(glass, tinted, &g->base, GNODE_REFLECTION, &yes[5], &err), G_OK);
    assert_int_equal(gnode_bump_create(plain, &g->base, 0.5, &yes[6], &err), G_OK);
    for (int i = 0; i < 7; i++)
        if (!clear(yes[i]))
            fail_msg("node %d (%s) over clear children has no GMAT_CLEAR", i, gmaterial_name(yes[i]));
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_bump_create(tinted, &g->base, 1.0, &no[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(absorbing, &uv, NULL, &no[2], &err), G_OK);
    assert_int_equal(gnode_select_create(mixed_kids, 3, &g->base, &no[3], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(glass, a, &g->base, GNODE_ABSORPTION, &no[4], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(tinted, glass, &g->base, GNODE_DIFFUSE, &no[5], &err), G_OK);
    assert_int_equal(gnode_scale_create(no[0], &g->base, &no[6], &err), G_OK);
    for (int i = 0; i < 7; i++)
        if (clear(no[i]))
            fail_msg("node %d (%s) over a blend or an absorbing child has GMAT_CLEAR", i, gmaterial_name(no[i]));

    /* the property: every flagged material gives the light back, bit for bit, at generated points and for none */
    const GMaterial *all[24];
    int nall = 0;
    for (int i = 0; i < 8; i++)
        if (over_lamberts[i])
            all[nall++] = n[i];
    for (int i = 0; i < 7; i++)
        all[nall++] = yes[i];
    all[nall++] = glass;
    all[nall++] = plain;
    all[nall++] = a;
    const GMaterial *blends[2] = {no[0], no[4]}; /* two clear children blended: not flagged */
    static const double lengths[] = {0.0, 1e-3, 1.0, 1e3};
    GColor light, at;
    assert_int_equal(gcolor_alloc(&light, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&at, f->rgb), G_OK);
    int rounds = TU_SANITIZED ? 40 : 300, blend_calls = 0, blend_differs = 0;
    unsigned long long s = 23;
    for (int r = 0; r < rounds; r++) {
        double x[6];
        for (int j = 0; j < 6; j++)
            x[j] = tu_uniform(&s);
        /* the generators' value: the blends' weights (in (0, 1) every other round) and select's child follow it */
        g->value = r % 2 ? x[5] : 3.0 * x[5];
        int below = r & 1;
        GSurfPoint sp;
        plane_point(&sp, f->rgb, f->scratch, 4.0 * x[0] - 1.0, 4.0 * x[1] - 1.0);
        sp.point = sp.object_point = gvec3(10.0 * x[2] - 5.0, 10.0 * x[3] - 5.0, 10.0 * x[4] - 5.0);
        sp.geometric_normal = gvec3_normalize(gvec3(x[2] - 0.5, x[3] - 0.5, (below ? -1.0 : 1.0) * (0.2 + x[4])));
        sp.entering = !below;
        sp.surface = r % 6;
        sp.t = 5.0 * x[4];
        double length = r % 5 < 4 ? lengths[r % 5] : 100.0 * tu_uniform(&s);
        draw_light(&light, &s);
        for (int i = 0; i < nall + 2; i++) {
            const GMaterial *m = i < nall ? all[i] : blends[i - nall];
            sp.material = m;
            sp.from = below ? m : NULL;
            sp.to = below ? NULL : m;
            gsurfpoint_invalidate(&sp);
            if (i >= nall) {
                blend_calls++;
                blend_differs += !gives_light_back(m, &sp, &light, length, &at);
                continue;
            }
            if (!gives_light_back(m, &sp, &light, length, &at))
                fail_msg("%s (%d): absorption over %g is not the light (round %d)", gmaterial_name(m), i, length, r);
            if (!gives_light_back(m, NULL, &light, length, &at))
                fail_msg("%s (%d): absorption for no point over %g is not the light (round %d)", gmaterial_name(m), i,
                         length, r);
        }
    }
    /* the blend's arithmetic changes some lights' bits: the kit must not give a blend the bit */
    assert_true(blend_differs > 0);
    assert_true(blend_differs < blend_calls); /* black light, weights 0 and 1 give the light itself */
    gcolor_free(&light);
    gcolor_free(&at);
    for (int i = 6; i >= 0; i--)
        gmaterial_unref(no[i]);
    for (int i = 6; i >= 0; i--)
        gmaterial_unref(yes[i]);
    release_plain_nodes(NULL, 0, n, a, b, c, g);
    gmaterial_unref(glass);
    gmaterial_unref(tinted);
    gmaterial_unref(plain);
    gmaterial_unref(absorbing);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_leaf_materials),
        cmocka_unit_test_setup_teardown(test_nodes_of_plain_leaves, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nodes_over_glass, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nodes_with_an_emitter, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bit_skips_the_class, setup, teardown),
        cmocka_unit_test_setup_teardown(test_opaque_bit_skips_the_class, setup, teardown),
        cmocka_unit_test_setup_teardown(test_normal_bit_of_nodes, setup, teardown),
        cmocka_unit_test_setup_teardown(test_normal_bit_skips_the_class, setup, teardown),
        cmocka_unit_test_setup_teardown(test_no_ideal_bit, setup, teardown),
        cmocka_unit_test(test_interface_version),
        cmocka_unit_test_setup_teardown(test_no_rel_index_bit, setup, teardown),
        cmocka_unit_test_setup_teardown(test_constant_index_bit, setup, teardown),
        cmocka_unit_test_setup_teardown(test_clear_bit, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
