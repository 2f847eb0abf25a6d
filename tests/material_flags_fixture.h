/* material_flags_fixture.h - the fixture of the material flag tests (test_material_flags.c,
 * test_material_media_flags.c): node_fixture.h's Fix (an rgb model, a scratch arena, a point, a colour, a white
 * light) with setup and teardown; grey lamberts and emitters; nodes of every kit kind over three lamberts and their
 * release; a class with no methods, made by gmaterial_init (bare_destroy frees such hand-made materials). Include
 * after cmocka.h. */
#ifndef MATERIAL_FLAGS_FIXTURE_H
#define MATERIAL_FLAGS_FIXTURE_H

#include <generic/kit/affine.h>
#include <generic/materials.h>
#include <generic/kit/node_kit.h>

#include "texture_fixtures.h"
#include "node_fixture.h"

/* A lambert of reflectance (r, g, b), or an emitter (two-sided) of radiance (r, g, b) when emits, in f's model. */
static inline GMaterial *coloured(Fix *f, double r, double g, double b, int emits)
{
    GColor c;
    double rgb[3] = {r, g, b};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gcolor_alloc(&c, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, emits ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(emits ? gemitter_create(f->rgb, &c, 1, &m, &err) : glambert_create(f->rgb, &c, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

/* A lambert of grey reflectance r and an emitter of radiance (r, g, b) (two-sided) in f's model. */
static inline GMaterial *lambert(Fix *f, double r) { return coloured(f, r, r, r, 0); }

static inline GMaterial *emitter(Fix *f, double r, double g, double b) { return coloured(f, r, g, b, 1); }

/* Nodes of every kit kind over the lamberts a, b and c (blends, one-child nodes, a node of nodes) into n[8]. */
static inline void plain_nodes(GMaterial *a, GMaterial *b, GMaterial *c, CountGen *g, GMaterial *n[8])
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

/* Fails the test unless each of plain_nodes' eight nodes in n has the material flag bit (named name). */
static inline void plain_nodes_have(GMaterial *const n[8], unsigned bit, const char *name)
{
    for (int i = 0; i < 8; i++)
        if (!(n[i]->flags & bit))
            fail_msg("node %d (%s) over lamberts has no %s", i, gmaterial_name(n[i]), name);
}

/* Releases, parents before children, the nm nodes m[nm - 1] down to m[0] a test made over plain_nodes' (m may be
 * NULL when nm is 0), then plain_nodes' n[7] down to n[0], the lamberts a, b and c, and the generator g. */
static inline void release_plain_nodes(GMaterial **m, int nm, GMaterial *n[8], GMaterial *a, GMaterial *b, GMaterial *c,
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

/* Frees a material made with gmem_calloc and gmaterial_init (the destroy slot of the test classes). */
static inline void bare_destroy(GMaterial *self) { gmem_free(self); }

/* A class without methods: every bit that a missing slot gives is set by gmaterial_init. */
static const GMaterialClass plain_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "plain", .description = "no methods (tests)",
    .destroy = bare_destroy,
};

#endif
