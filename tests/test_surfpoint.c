/* test_surfpoint.c - the surface point's caches: the shading normal computed once, the generator cache
 * slots, and the cached relative refraction index; the layout (public fields, then the private caches) and the
 * constructor gsurfpoint_new. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/material.h"
#include "generic/materials.h"
#include "generic/surfpoint.h"
#include "test_alloc.h"
#include "test_util.h"

static int normal_calls;

/* A test material whose normal is tilted and counts its calls. */
static int counting_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    (void)self;
    normal_calls++;
    *n = gvec3_normalize(gvec3_add(sp->geometric_normal, gvec3(0.1, 0, 0)));
    return G_OK;
}

static void plain_destroy(GMaterial *self) { gmem_free(self); }

static const GMaterialClass counting_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "counting",
    .description = "test material counting normal() calls",
    .destroy = plain_destroy,
    .normal = counting_normal,
};

static int failing_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    (void)self;
    (void)sp;
    normal_calls++;
    *n = gvec3(1, 2, 3);
    return G_ERR_INVALID;
}

static const GMaterialClass failing_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "failing",
    .description = "test material whose normal() fails",
    .destroy = plain_destroy,
    .normal = failing_normal,
};

static GMaterial *new_test_material(const GMaterialClass *cls)
{
    GMaterial *m = gmem_calloc(1, sizeof *m);
    assert_non_null(m);
    GError err;
    assert_int_equal(gmaterial_init(m, cls, NULL, &err), G_OK);
    return m;
}

static void test_normal_cached(void **state)
{
    (void)state;
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.geometric_normal = gvec3(0, 0, 1);
    /* no material: the geometric normal */
    GVec3 n = gsurfpoint_normal(&sp);
    assert_true(n.x == 0 && n.y == 0 && n.z == 1);

    GMaterial *m = new_test_material(&counting_class);
    gsurfpoint_init(&sp, NULL, NULL);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.material = m;
    normal_calls = 0;
    n = gsurfpoint_normal(&sp);
    for (int i = 0; i < 10; i++) {
        GVec3 again = gsurfpoint_normal(&sp);
        assert_true(again.x == n.x && again.y == n.y && again.z == n.z);
    }
    assert_int_equal(normal_calls, 1);
    assert_true(fabs(n.x - 0.1 / sqrt(1.01)) < 1e-12);
    /* invalidate: computed again, once */
    gsurfpoint_invalidate(&sp);
    gsurfpoint_normal(&sp);
    gsurfpoint_normal(&sp);
    assert_int_equal(normal_calls, 2);
    /* an explicit normal replaces the cached one without calling the material */
    gsurfpoint_set_normal(&sp, gvec3(0, 1, 0));
    n = gsurfpoint_normal(&sp);
    assert_true(n.y == 1 && normal_calls == 2);
    gmaterial_unref(m);

    /* a failing normal() falls back to the geometric normal, still computed once */
    m = new_test_material(&failing_class);
    gsurfpoint_init(&sp, NULL, NULL);
    sp.geometric_normal = gvec3(0, 1, 0);
    sp.material = m;
    normal_calls = 0;
    n = gsurfpoint_normal(&sp);
    gsurfpoint_normal(&sp);
    assert_true(n.x == 0 && n.y == 1 && n.z == 0);
    assert_int_equal(normal_calls, 1);
    gmaterial_unref(m);
}

static void test_cache_slots(void **state)
{
    (void)state;
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    int keys[3 * GSURF_CACHE_SLOTS];
    double v;
    GVec3 g;
    assert_int_equal(gsurfpoint_cache_get(&sp, &keys[0], &v, &g), 0);
    for (int i = 0; i < 3; i++)
        gsurfpoint_cache_put(&sp, &keys[i], 10.0 + i, gvec3(i, -i, 2 * i));
    for (int i = 2; i >= 0; i--) {
        assert_int_equal(gsurfpoint_cache_get(&sp, &keys[i], &v, &g), 1);
        assert_true(v == 10.0 + i && g.x == i && g.y == -i && g.z == 2 * i);
    }
    assert_int_equal(gsurfpoint_cache_get(&sp, &keys[3], NULL, NULL), 0);
    assert_int_equal(gsurfpoint_cache_get(&sp, &keys[1], NULL, NULL), 1); /* NULL outputs are allowed */
    /* putting a key again replaces its value */
    gsurfpoint_cache_put(&sp, &keys[1], 99.0, gvec3(9, 9, 9));
    assert_int_equal(gsurfpoint_cache_get(&sp, &keys[1], &v, &g), 1);
    assert_true(v == 99.0 && g.x == 9);
    assert_int_equal(gsurfpoint_cache_get(&sp, &keys[0], &v, NULL), 1);
    assert_true(v == 10.0);
    /* more keys than slots: the oldest are reused, the newest GSURF_CACHE_SLOTS are all found */
    for (int i = 3; i < 3 * GSURF_CACHE_SLOTS; i++)
        gsurfpoint_cache_put(&sp, &keys[i], 10.0 + i, gvec3(0, 0, 0));
    for (int i = 0; i < 3 * GSURF_CACHE_SLOTS; i++) {
        int found = gsurfpoint_cache_get(&sp, &keys[i], &v, NULL);
        assert_int_equal(found, i >= 2 * GSURF_CACHE_SLOTS);
        if (found)
            assert_true(v == 10.0 + i);
    }
    /* invalidate forgets everything */
    gsurfpoint_invalidate(&sp);
    for (int i = 0; i < 3 * GSURF_CACHE_SLOTS; i++)
        assert_int_equal(gsurfpoint_cache_get(&sp, &keys[i], NULL, NULL), 0);
}

static void relative_index_case(const char *model_name)
{
    GError err;
    GColorModel *model;
    if (gcolormodel_create(model_name, NULL, &model, &err) != G_OK) {
        print_message("colour model '%s' not available: %s\n", model_name, err.message);
        skip();
    }
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    GMaterial *glass, *water;
    GDielectricParams p = {gdispersion_constant(1.5), NULL, NULL};
    assert_int_equal(gdielectric_create(model, &p, &glass, &err), G_OK);
    p.index = gdispersion_constant(1.33);
    assert_int_equal(gdielectric_create(model, &p, &water, &err), G_OK);
    GSurfPoint sp;
    gsurfpoint_init(&sp, model, s);
    sp.from = NULL; /* vacuum / air */
    sp.to = glass;
    double r = gsurfpoint_relative_index(&sp);
    print_message("%s: air -> glass 1.5: relative index %.9f\n", model_name, r);
    assert_true(fabs(r - 1.0 / 1.5) < 1e-7);
    /* cached: changing the media without invalidating keeps the value */
    sp.to = water;
    assert_true(gsurfpoint_relative_index(&sp) == r);
    gsurfpoint_invalidate(&sp);
    assert_true(fabs(gsurfpoint_relative_index(&sp) - 1.0 / 1.33) < 1e-7);
    sp.from = glass;
    gsurfpoint_invalidate(&sp);
    assert_true(fabs(gsurfpoint_relative_index(&sp) - 1.5 / 1.33) < 1e-6);
    sp.to = NULL;
    gsurfpoint_invalidate(&sp);
    assert_true(fabs(gsurfpoint_relative_index(&sp) - 1.5) < 1e-6);

    /* set from the colour a renderer divides: the same value as computed, bit for bit, and no call to the media
     * (a point without them would give 1) */
    GColor nf, nt;
    assert_int_equal(gcolor_alloc(&nf, model), G_OK);
    assert_int_equal(gcolor_alloc(&nt, model), G_OK);
    sp.from = glass;
    sp.to = water;
    gsurfpoint_invalidate(&sp);
    double computed = gsurfpoint_relative_index(&sp);
    assert_int_equal(gmaterial_refraction_index(glass, &sp, &nf), G_OK);
    assert_int_equal(gmaterial_refraction_index(water, &sp, &nt), G_OK);
    assert_int_equal(gcolor_div(&nf, &nf, &nt), G_OK);
    GSurfPoint bare;
    gsurfpoint_init(&bare, model, s);
    gsurfpoint_set_relative_index(&bare, &nf);
    assert_true(gsurfpoint_relative_index(&bare) == computed);
    assert_true(gsurfpoint_scalar_index(&nf) == computed); /* the rule a material applies to its rel_index */
    /* a material handed that colour reads the cached value (the renderer does not change it meanwhile: so the
     * changed colour below still gives the set value); another colour is computed */
    assert_true(gsurfpoint_index_of(&bare, &nf) == computed);
    assert_true(gsurfpoint_index_of(&bare, &nt) == gsurfpoint_scalar_index(&nt));
    assert_true(fabs(gsurfpoint_index_of(&bare, &nt) - 1.33) < 1e-6);
    assert_int_equal(gcolor_scale(&nf, &nf, 2.0), G_OK);
    assert_true(gsurfpoint_index_of(&bare, &nf) == computed);
    gsurfpoint_invalidate(&bare); /* forgotten like any cached value: no media, about 1 */
    assert_true(fabs(gsurfpoint_index_of(&bare, &nf) - 2.0 * computed) < 1e-6);
    assert_true(fabs(gsurfpoint_relative_index(&bare) - 1.0) < 1e-6);
    /* a value gsurfpoint_relative_index computed itself belongs to no colour */
    assert_true(gsurfpoint_index_of(&bare, &nf) == gsurfpoint_scalar_index(&nf));
    assert_int_equal(gcolor_scale(&nf, &nf, 0.5), G_OK);
    gcolor_black(&nf); /* not positive: 1, as computed */
    assert_true(gsurfpoint_scalar_index(&nf) == 1.0);
    gsurfpoint_set_relative_index(&bare, &nf);
    assert_true(gsurfpoint_relative_index(&bare) == 1.0);
    /* set with its scalar known: that value, for the point and for a material handed the colour, none taken again
     * (the colour's own scalar is 1 here, the known one is read); another colour is computed */
    gsurfpoint_set_relative_index_scalar(&bare, &nf, computed);
    assert_true(gsurfpoint_relative_index(&bare) == computed);
    assert_true(gsurfpoint_index_of(&bare, &nf) == computed);
    assert_true(gsurfpoint_index_of(&bare, &nt) == gsurfpoint_scalar_index(&nt));
    gsurfpoint_set_relative_index(&bare, &nf); /* set again without it: taken from the colour */
    assert_true(gsurfpoint_relative_index(&bare) == 1.0);

    /* the set colour's scalar is taken when first asked for, by either function, and then cached: a material's
     * gsurfpoint_index_of first gives the same value bit for bit, and so does gsurfpoint_relative_index after it; a
     * point set again forgets the old colour's scalar */
    assert_int_equal(gmaterial_refraction_index(glass, &sp, &nf), G_OK);
    assert_int_equal(gcolor_div(&nf, &nf, &nt), G_OK);
    gsurfpoint_set_relative_index(&bare, &nf);
    assert_true(gsurfpoint_index_of(&bare, &nf) == computed);
    assert_true(gsurfpoint_relative_index(&bare) == computed);
    assert_int_equal(gcolor_scale(&nf, &nf, 2.0), G_OK); /* cached now: the set value stays */
    assert_true(gsurfpoint_index_of(&bare, &nf) == computed);
    gsurfpoint_set_relative_index(&bare, &nf);
    assert_true(fabs(gsurfpoint_relative_index(&bare) - 2.0 * computed) < 1e-6);
    assert_true(gsurfpoint_index_of(&bare, &nf) == gsurfpoint_relative_index(&bare));
    /* a copy of a point made before the first ask reads the same colour */
    assert_int_equal(gcolor_scale(&nf, &nf, 0.5), G_OK);
    gsurfpoint_set_relative_index(&bare, &nf);
    GSurfPoint copy = bare;
    assert_true(gsurfpoint_relative_index(&copy) == computed);
    assert_true(gsurfpoint_relative_index(&bare) == computed);
    /* a colour of another model than the point's: its own scalar */
    GColorModel *other;
    assert_int_equal(gcolormodel_create(strcmp(model_name, "rgb") == 0 ? "spectrum9" : "rgb", NULL, &other, &err),
                     G_OK);
    GColor oc;
    assert_int_equal(gcolor_alloc(&oc, other), G_OK);
    assert_int_equal(gcolor_fill(&oc, 1.25), G_OK);
    gsurfpoint_set_relative_index(&bare, &oc);
    assert_true(gsurfpoint_relative_index(&bare) == gsurfpoint_scalar_index(&oc));
    assert_true(fabs(gsurfpoint_relative_index(&bare) - 1.25) < 1e-6);
    gcolor_free(&oc);
    gcolormodel_destroy(other);
    gcolor_free(&nf);
    gcolor_free(&nt);
    gmaterial_unref(glass);
    gmaterial_unref(water);
    gscratch_destroy(s);
    gcolormodel_destroy(model);
}

static void test_relative_index(void **state) { relative_index_case(*state); }

/* Footprint widths along u and v: uv_footprint for both without axes, else the extent of the ellipse. */
static void test_uv_widths(void **state)
{
    (void)state;
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.uv_footprint = 0.25;
    double wu, wv;
    gsurfpoint_uv_widths(&sp, &wu, &wv);
    assert_true(wu == 0.25 && wv == 0.25);
    sp.uv_axis1[0] = 0.3; /* an ellipse with half-axes 0.5 and 0.1 turned by atan(4/3) */
    sp.uv_axis1[1] = 0.4;
    sp.uv_axis2[0] = -0.08;
    sp.uv_axis2[1] = 0.06;
    gsurfpoint_uv_widths(&sp, &wu, &wv);
    assert_true(fabs(wu - sqrt(0.3 * 0.3 + 0.08 * 0.08)) < 1e-15);
    assert_true(fabs(wv - sqrt(0.4 * 0.4 + 0.06 * 0.06)) < 1e-15);
}

/* gsurfpoint_init clears every field of a point that held anything (each byte 0xA5 before), sets the model,
 * the arena and entering, and leaves the cache empty: a value put before is not found after. */
static void test_init_clears(void **state)
{
    (void)state;
    GSurfPoint sp;
    memset(&sp, 0xA5, sizeof sp);
    const GColorModel *model = (const GColorModel *)&sp; /* any distinct pointers: init only stores them */
    GScratch *arena = (GScratch *)&model;
    gsurfpoint_init(&sp, model, arena);
    const GVec3 *vecs[] = {&sp.point, &sp.object_point, &sp.geometric_normal, &sp.dpdu, &sp.dpdv,
                           &sp.object_dpdu, &sp.object_dpdv};
    for (size_t i = 0; i < sizeof vecs / sizeof *vecs; i++)
        assert_true(vecs[i]->x == 0.0 && vecs[i]->y == 0.0 && vecs[i]->z == 0.0);
    assert_true(sp.u == 0.0 && sp.v == 0.0 && sp.t == 0.0 && sp.footprint == 0.0 && sp.uv_footprint == 0.0);
    assert_true(sp.uv_axis1[0] == 0.0 && sp.uv_axis1[1] == 0.0 && sp.uv_axis2[0] == 0.0 && sp.uv_axis2[1] == 0.0);
    assert_int_equal(sp.surface, 0);
    assert_int_equal(sp.entering, 1);
    assert_null(sp.material);
    assert_null(sp.from);
    assert_null(sp.to);
    assert_ptr_equal(sp.model, model);
    assert_ptr_equal(sp.scratch, arena);
    double v;
    assert_false(gsurfpoint_cache_get(&sp, &sp, &v, NULL));
    gsurfpoint_cache_put(&sp, &sp, 2.5, gvec3(0, 0, 0));
    assert_true(gsurfpoint_cache_get(&sp, &sp, &v, NULL) && v == 2.5);
    gsurfpoint_init(&sp, model, arena);
    assert_false(gsurfpoint_cache_get(&sp, &sp, &v, NULL));
    /* no material: the shading normal is the geometric one, not a cached value from before */
    sp.geometric_normal = gvec3(0, 0, 1);
    GVec3 n = gsurfpoint_normal(&sp);
    assert_true(n.x == 0.0 && n.y == 0.0 && n.z == 1.0);
}

/* The public fields come first and the private caches are the last member: a binding lays out the struct up to
 * `priv` and nothing of it. */
static void test_layout(void **state)
{
    (void)state;
    size_t priv = offsetof(GSurfPoint, priv);
    const size_t public_ends[] = {
        offsetof(GSurfPoint, point) + sizeof(GVec3),          offsetof(GSurfPoint, scratch) + sizeof(GScratch *),
        offsetof(GSurfPoint, object_dpdv) + sizeof(GVec3),    offsetof(GSurfPoint, uv_axis2) + 2 * sizeof(double),
        offsetof(GSurfPoint, material) + sizeof(GMaterial *),
    };
    for (size_t i = 0; i < sizeof public_ends / sizeof *public_ends; i++)
        assert_true(public_ends[i] <= priv);
    assert_int_equal(priv + sizeof(GSurfPointPrivate), sizeof(GSurfPoint));
    assert_int_equal(gsurfpoint_size(), sizeof(GSurfPoint));
}

static const GVec3 P = {1.0, -2.0, 0.5}, N = {0.0, 0.0, 2.0}, DU = {0.5, 0.0, 0.0}, DV = {0.0, 0.25, 0.0};

/* gsurfpoint_new sets the fields it is given (the normal normalised, the object point the point), leaves every other
 * public field as gsurfpoint_init does, and starts with empty caches. */
static void test_new_fields(void **state)
{
    (void)state;
    GError err;
    GColorModel *model;
    assert_int_equal(gcolormodel_create("rgb", NULL, &model, &err), G_OK);
    GScratch *arena = gscratch_create(0);
    assert_non_null(arena);
    GSurfPoint *sp = gsurfpoint_new(model, arena, P, N, DU, DV, 0.25, 0.75, 3, &err);
    assert_non_null(sp);
    assert_true(sp->point.x == 1.0 && sp->point.y == -2.0 && sp->point.z == 0.5);
    assert_true(sp->object_point.x == 1.0 && sp->object_point.y == -2.0 && sp->object_point.z == 0.5);
    assert_true(sp->geometric_normal.x == 0.0 && sp->geometric_normal.y == 0.0 && sp->geometric_normal.z == 1.0);
    assert_true(sp->dpdu.x == 0.5 && sp->dpdu.y == 0.0 && sp->dpdv.y == 0.25 && sp->dpdv.x == 0.0);
    assert_true(sp->u == 0.25 && sp->v == 0.75);
    assert_int_equal(sp->surface, 3);
    assert_int_equal(sp->entering, 1);
    assert_true(sp->t == 0.0 && sp->footprint == 0.0 && sp->uv_footprint == 0.0);
    assert_true(sp->uv_axis1[0] == 0.0 && sp->uv_axis1[1] == 0.0 && sp->uv_axis2[0] == 0.0 && sp->uv_axis2[1] == 0.0);
    assert_true(sp->object_dpdu.x == 0.0 && sp->object_dpdv.y == 0.0);
    assert_null(sp->material);
    assert_null(sp->from);
    assert_null(sp->to);
    assert_ptr_equal(sp->model, model);
    assert_ptr_equal(sp->scratch, arena);
    /* empty caches: no generator value, the shading normal is the geometric one, the relative index is computed
     * (vacuum on both sides: 1) and belongs to no colour */
    double v;
    assert_false(gsurfpoint_cache_get(sp, sp, &v, NULL));
    GVec3 n = gsurfpoint_normal(sp);
    assert_true(n.x == 0.0 && n.y == 0.0 && n.z == 1.0);
    assert_near(gsurfpoint_relative_index(sp), 1.0, 1e-6);
    GColor ri;
    assert_int_equal(gcolor_alloc(&ri, model), G_OK);
    assert_int_equal(gcolor_fill(&ri, 0.5), G_OK);
    assert_near(gsurfpoint_index_of(sp, &ri), 0.5, 1e-6);
    /* the caches work on it, and a material evaluates at it */
    gsurfpoint_cache_put(sp, sp, 4.5, gvec3(1, 2, 3));
    assert_true(gsurfpoint_cache_get(sp, sp, &v, NULL) && v == 4.5);
    GMaterial *m;
    GColor albedo;
    assert_int_equal(gcolor_alloc(&albedo, model), G_OK);
    assert_int_equal(gcolor_fill(&albedo, 0.5), G_OK);
    assert_int_equal(glambert_create(model, &albedo, &m, &err), G_OK);
    gcolor_free(&albedo);
    sp->material = m;
    GVec3 in = gvec3_normalize(gvec3(0.0, 0.6, 0.8));
    double one[3] = {1.0, 1.0, 1.0}, rgb[3];
    GColor light;
    assert_int_equal(gcolor_alloc(&light, model), G_OK);
    assert_int_equal(gcolor_from_rgb(&light, one, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gmaterial_reflection(m, sp, in, &light, gvec3(0, 0, 1), &ri), G_OK);
    assert_int_equal(gcolor_to_rgb(&ri, GCOLOR_LIGHT, rgb), G_OK);
    assert_near(rgb[1], 0.5 * 0.8 / M_PI, 1e-6); /* albedo times cos(in) over pi */
    gcolor_free(&light);
    gcolor_free(&ri);
    gmaterial_unref(m);
    gsurfpoint_free(sp);
    gsurfpoint_free(NULL); /* a no-op */
    gscratch_destroy(arena);
    gcolormodel_destroy(model);
}

/* Missing or invalid arguments are refused with G_ERR_INVALID naming what is wrong; running out of memory is
 * G_ERR_NOMEM. err may be NULL. */
static void test_new_refuses(void **state)
{
    (void)state;
    GError err;
    GColorModel *model;
    assert_int_equal(gcolormodel_create("rgb", NULL, &model, &err), G_OK);
    GScratch *arena = gscratch_create(0);
    const GVec3 nan3 = {NAN, 0.0, 0.0}, inf3 = {0.0, INFINITY, 0.0}, zero = {0.0, 0.0, 0.0};
    struct {
        const GColorModel *model;
        GScratch *arena;
        GVec3 p, n, du, dv;
        double u, v;
        int surface;
        const char *message;
    } bad[] = {
        {NULL, arena, P, N, DU, DV, 0, 0, 0, "no colour model"},
        {model, NULL, P, N, DU, DV, 0, 0, 0, "no scratch arena"},
        {model, arena, nan3, N, DU, DV, 0, 0, 0, "the point is not finite"},
        {model, arena, inf3, N, DU, DV, 0, 0, 0, "the point is not finite"},
        {model, arena, P, zero, DU, DV, 0, 0, 0, "the normal is zero"},
        {model, arena, P, nan3, DU, DV, 0, 0, 0, "the normal is zero or not finite"},
        {model, arena, P, N, inf3, DV, 0, 0, 0, "a tangent is not finite"},
        {model, arena, P, N, DU, nan3, 0, 0, 0, "a tangent is not finite"},
        {model, arena, P, N, DU, DV, NAN, 0, 0, "(u, v) is not finite"},
        {model, arena, P, N, DU, DV, 0, -INFINITY, 0, "(u, v) is not finite"},
        {model, arena, P, N, DU, DV, 0, 0, -1, "the surface index is negative"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        gerror_clear(&err);
        assert_null(gsurfpoint_new(bad[i].model, bad[i].arena, bad[i].p, bad[i].n, bad[i].du, bad[i].dv, bad[i].u,
                                   bad[i].v, bad[i].surface, &err));
        assert_int_equal(err.code, G_ERR_INVALID);
        assert_non_null(strstr(err.message, bad[i].message));
        assert_null(gsurfpoint_new(bad[i].model, bad[i].arena, bad[i].p, bad[i].n, bad[i].du, bad[i].dv, bad[i].u,
                                   bad[i].v, bad[i].surface, NULL));
    }
    static TuAlloc a;
    a = (TuAlloc){.fail_call = 1}; /* the first allocation fails */
    tu_alloc_install(&a);
    GSurfPoint *sp = gsurfpoint_new(model, arena, P, N, DU, DV, 0, 0, 0, &err);
    gmem_set_allocator(NULL);
    assert_null(sp);
    assert_int_equal(err.code, G_ERR_NOMEM);
    assert_int_equal(a.calls, 1);
    gscratch_destroy(arena);
    gcolormodel_destroy(model);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layout),
        cmocka_unit_test(test_new_fields),
        cmocka_unit_test(test_new_refuses),
        cmocka_unit_test(test_init_clears),
        cmocka_unit_test(test_normal_cached),
        cmocka_unit_test(test_cache_slots),
        cmocka_unit_test(test_uv_widths),
        {"test_relative_index (rgb)", test_relative_index, NULL, NULL, (void *)"rgb"},
        {"test_relative_index (spectrum)", test_relative_index, NULL, NULL, (void *)"spectrum"},
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
