/* test_material_flags.c - the instance flags of material.h about emission, opacity, normals and ideal directions
 * (test_material_media_flags.c: the flags about the media, GMAT_NO_REL_INDEX, GMAT_CONSTANT_INDEX, GMAT_CLEAR):
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

#include "material_flags_fixture.h"

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

static const GMaterialClass glow_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "glow", .description = "emits 1 (tests)",
    .destroy = bare_destroy, .emission = glow_emission,
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
    .destroy = bare_destroy, .opaque = see_through_opaque,
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
    .destroy = bare_destroy, .normal = tilt_normal,
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
    plain_nodes_have(n, GMAT_NO_IDEAL, "GMAT_NO_IDEAL");
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
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}