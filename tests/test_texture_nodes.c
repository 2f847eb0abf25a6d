/* test_texture_nodes.c - the texture tree nodes: interpolate (blending, the one-child fast path, the cached
 * generator), interpolate-one, select, spline, bump (the analytic tilt), scale, and bad input (the transform
 * node: test_texture_transform.c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/materials.h>
#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

#include "node_fixture.h"

static void test_interpolate_fast_path(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.2, 0.2, 0.2), *b = countmat_new(f->rgb, 0.8, 0.8, 0.8);
    CountGen *g = countgen_new(0.0);
    GMaterial *n;
    GError err;
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, &g->base, &n, &err), G_OK);
    call_all(f, n);
    assert_int_equal(countmat_total(a), GNODE_METHOD_COUNT); /* each method once, on a only */
    assert_int_equal(countmat_total(b), 0);
    assert_int_equal(g->calls, 1); /* the generator once for all eleven methods */

    g->value = 1.0;
    gsurfpoint_invalidate(&f->sp);
    memset(a->calls, 0, sizeof a->calls);
    call_all(f, n);
    assert_int_equal(countmat_total(a), 0);
    assert_int_equal(countmat_total(b), GNODE_METHOD_COUNT);
    assert_int_equal(g->calls, 2);

    /* values outside [0, 1] clamp to the ends, still with one child */
    g->value = 7.0;
    gsurfpoint_invalidate(&f->sp);
    memset(b->calls, 0, sizeof b->calls);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    assert_int_equal(countmat_total(a), 0);
    assert_int_equal(b->calls[GNODE_DIFFUSE], 1);
    assert_float_equal(color_r(&f->c), 0.8, 1e-6);

    gmaterial_unref(n);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
    ggenerator_unref(&g->base);
}

static void test_interpolate_blend(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.2, 0.4, 0.0), *b = countmat_new(f->rgb, 1.0, 0.0, 0.5);
    a->normal = gvec3(0, 0, 1);
    b->normal = gvec3(1, 0, 0);
    a->refl_valid = 1;
    a->refl_dir = gvec3(0, 1, 0);
    b->opaque = 0;
    CountGen *g = countgen_new(0.25);
    GMaterial *n;
    GError err;
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, &g->base, &n, &err), G_OK);

    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(&f->c, GCOLOR_REFLECTANCE, rgb), G_OK);
    assert_float_equal(rgb[0], 0.75 * 0.2 + 0.25 * 1.0, 1e-6);
    assert_float_equal(rgb[1], 0.75 * 0.4, 1e-6);
    assert_float_equal(rgb[2], 0.25 * 0.5, 1e-6);

    /* the result may alias the incoming light */
    assert_int_equal(gcolor_from_rgb(&f->c, (double[3]){1, 1, 1}, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gmaterial_absorption(n, &f->sp, &f->c, 1.0, &f->c), G_OK);
    assert_int_equal(gcolor_to_rgb(&f->c, GCOLOR_REFLECTANCE, rgb), G_OK);
    assert_float_equal(rgb[0], 0.75 * 0.2 + 0.25 * 1.0, 1e-6);

    GVec3 nn;
    assert_int_equal(gmaterial_normal(n, &f->sp, &nn), G_OK);
    GVec3 want = gvec3_normalize(gvec3_lerp(a->normal, b->normal, 0.25));
    assert_float_equal(nn.x, want.x, 1e-12);
    assert_float_equal(nn.z, want.z, 1e-12);
    assert_float_equal(gvec3_length(nn), 1.0, 1e-12);

    /* only a has a reflection direction: it is returned as it is */
    GVec3 d;
    assert_int_equal(gmaterial_reflection_dir(n, &f->sp, gvec3(0, 0, -1), &d), 1);
    assert_float_equal(d.y, 1.0, 1e-12);
    /* both valid: blended and normalised */
    b->refl_valid = 1;
    b->refl_dir = gvec3(1, 0, 0);
    assert_int_equal(gmaterial_reflection_dir(n, &f->sp, gvec3(0, 0, -1), &d), 1);
    want = gvec3_normalize(gvec3(0.25, 0.75, 0));
    assert_float_equal(d.x, want.x, 1e-12);
    assert_float_equal(d.y, want.y, 1e-12);
    /* neither refracts: not valid */
    assert_int_equal(gmaterial_refraction_dir(n, &f->sp, gvec3(0, 0, -1), NULL, &d), 0);
    /* b transmits: the blend is not opaque */
    assert_int_equal(gmaterial_opaque(n, &f->sp), 0);
    assert_int_equal(g->calls, 1);

    gmaterial_unref(n);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
    ggenerator_unref(&g->base);
}

/* One generator shared by two nodes and a sequence of calls: one evaluation per point. */
static void test_generator_cached_per_point(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.1, 0.1, 0.1), *b = countmat_new(f->rgb, 0.9, 0.9, 0.9);
    CountGen *g = countgen_new(0.5);
    GMaterial *n1, *n2, *top;
    GError err;
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, &g->base, &n1, &err), G_OK);
    assert_int_equal(gnode_interpolate_create(&b->base, &a->base, &g->base, &n2, &err), G_OK);
    CountGen *g2 = countgen_new(0.5);
    assert_int_equal(gnode_interpolate_create(n1, n2, &g2->base, &top, &err), G_OK);
    f->sp.material = top;
    for (int light = 0; light < 4; light++)
        assert_int_equal(gmaterial_reflection(top, &f->sp, gvec3(0, 0, 1), &f->illum, gvec3(0, 0, 1), &f->c), G_OK);
    call_all(f, top);
    (void)gsurfpoint_normal(&f->sp);
    assert_int_equal(g->calls, 1);
    assert_int_equal(g2->calls, 1);
    /* a new point evaluates again */
    gsurfpoint_invalidate(&f->sp);
    assert_int_equal(gmaterial_diffuse(top, &f->sp, &f->c), G_OK);
    assert_int_equal(g->calls, 2);
    assert_float_equal(color_r(&f->c), 0.5, 1e-6);
    gmaterial_unref(top);
    gmaterial_unref(n1);
    gmaterial_unref(n2);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
    ggenerator_unref(&g->base);
    ggenerator_unref(&g2->base);
}

static void test_interpolate_one(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 1.5, 1.5, 1.5), *b = countmat_new(f->rgb, 1.3, 1.3, 1.3);
    CountGen *g = countgen_new(0.5);
    GMaterial *n;
    GError err;
    assert_int_equal(gnode_method_from_name("refraction_index"), GNODE_REFRACTION_INDEX);
    assert_int_equal(gnode_method_from_name("shininess"), -1);
    assert_string_equal(gnode_method_name(GNODE_OPAQUE), "opaque");
    assert_int_equal(
        gnode_interpolate_one_create(&a->base, &b->base, &g->base, GNODE_REFRACTION_INDEX, &n, &err), G_OK);
    assert_int_equal(gmaterial_refraction_index(n, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 1.4, 1e-6);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 1.5, 1e-6);
    assert_int_equal(b->calls[GNODE_DIFFUSE], 0);
    assert_int_equal(b->calls[GNODE_REFRACTION_INDEX], 1);
    /* without a surface point (a homogeneous medium query) the first child answers */
    assert_int_equal(gmaterial_refraction_index(n, NULL, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 1.5, 1e-6);
    gmaterial_unref(n);
    assert_int_equal(gnode_interpolate_one_create(&a->base, &b->base, &g->base, GNODE_METHOD_COUNT, &n, &err),
                     G_ERR_INVALID);
    assert_null(n);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
    ggenerator_unref(&g->base);
}

static void test_select_by_surface(void **state)
{
    Fix *f = *state;
    CountMat *m[3];
    for (int i = 0; i < 3; i++)
        m[i] = countmat_new(f->rgb, 0.1 * (i + 1), 0, 0);
    GMaterial *kids[3] = {&m[0]->base, &m[1]->base, &m[2]->base};
    GGenerator *surf;
    GMaterial *n;
    GError err;
    assert_int_equal(ggenerator_surface_create(&surf, &err), G_OK);
    assert_int_equal(gnode_select_create(kids, 3, surf, &n, &err), G_OK);
    const int faces[] = {0, 1, 2, -3, 99};
    const int want[] = {0, 1, 2, 0, 2}; /* out of range clamps */
    for (int i = 0; i < 5; i++) {
        gsurfpoint_invalidate(&f->sp);
        f->sp.surface = faces[i];
        memset(m[want[i]]->calls, 0, sizeof m[0]->calls);
        assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
        assert_float_equal(color_r(&f->c), 0.1 * (want[i] + 1), 1e-6);
        assert_int_equal(m[want[i]]->calls[GNODE_DIFFUSE], 1);
    }
    gmaterial_unref(n);
    ggenerator_unref(surf);
    for (int i = 0; i < 3; i++)
        gmaterial_unref(&m[i]->base);
}

static double catmull_rom(double p0, double p1, double p2, double p3, double t)
{
    return 0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                  (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
}

static void test_spline(void **state)
{
    Fix *f = *state;
    const double v[4] = {0.0, 0.2, 0.9, 0.6};
    CountMat *m[4];
    GMaterial *kids[4];
    for (int i = 0; i < 4; i++) {
        m[i] = countmat_new(f->rgb, v[i], v[i], v[i]);
        kids[i] = &m[i]->base;
    }
    CountGen *g = countgen_new(0.0);
    GMaterial *n;
    GError err;
    assert_int_equal(gnode_spline_create(kids, 4, &g->base, GSPLINE_CATMULL_ROM, &n, &err), G_OK);
    /* at the knots t = i/3 exactly one child is called and returned */
    for (int i = 0; i < 4; i++) {
        g->value = i / 3.0;
        gsurfpoint_invalidate(&f->sp);
        for (int k = 0; k < 4; k++)
            memset(m[k]->calls, 0, sizeof m[k]->calls);
        assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
        assert_float_equal(color_r(&f->c), v[i], 1e-6);
        int called = 0;
        for (int k = 0; k < 4; k++)
            called += m[k]->calls[GNODE_DIFFUSE];
        assert_int_equal(called, 1);
    }
    /* between knots: the Catmull-Rom polynomial (end children repeated) */
    const double ts[] = {0.1, 0.5, 0.61, 0.95};
    for (int i = 0; i < 4; i++) {
        g->value = ts[i];
        gsurfpoint_invalidate(&f->sp);
        double x = ts[i] * 3;
        int k = (int)x;
        double fr = x - k;
        double want = catmull_rom(v[k > 0 ? k - 1 : 0], v[k], v[k + 1], v[k + 2 < 4 ? k + 2 : 3], fr);
        assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
        assert_float_equal(color_r(&f->c), want, 1e-6);
    }
    gmaterial_unref(n);

    /* B-spline: weights are a partition of unity with no overshoot, so the blend stays within the children */
    assert_int_equal(gnode_spline_create(kids, 4, &g->base, GSPLINE_BSPLINE, &n, &err), G_OK);
    for (int i = 0; i <= 20; i++) {
        g->value = i / 20.0;
        gsurfpoint_invalidate(&f->sp);
        assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
        double r = color_r(&f->c);
        assert_true(r >= -1e-6 && r <= 0.9 + 1e-6);
    }
    g->value = 0.5; /* midway between children 1 and 2: (c0 + 23 c1 + 23 c2 + c3) / 48 */
    gsurfpoint_invalidate(&f->sp);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), (v[0] + 23 * v[1] + 23 * v[2] + v[3]) / 48.0, 1e-6);
    gmaterial_unref(n);

    assert_int_equal(gnode_spline_create(kids, 4, &g->base, GSPLINE_LINEAR, &n, &err), G_OK);
    g->value = 0.5;
    gsurfpoint_invalidate(&f->sp);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.5 * (v[1] + v[2]), 1e-6);
    gmaterial_unref(n);

    for (int i = 0; i < 4; i++)
        gmaterial_unref(kids[i]);
    ggenerator_unref(&g->base);
}

/* Angle between the bumped normal and +z, and its direction in the plane. */
static double tilt(GVec3 n, GVec3 *dir)
{
    *dir = gvec3_normalize(gvec3(n.x, n.y, 0));
    return atan2(sqrt(n.x * n.x + n.y * n.y), n.z);
}

static void test_bump_analytic_tilt(void **state)
{
    Fix *f = *state;
    GError err;
    GColor rho;
    assert_int_equal(gcolor_alloc(&rho, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&rho, (double[3]){0.5, 0.5, 0.5}, GCOLOR_REFLECTANCE), G_OK);
    GMaterial *lam, *bump;
    assert_int_equal(glambert_create(f->rgb, &rho, &lam, &err), G_OK);
    const double slopes[] = {0.1, 1.0, -2.5};
    const double strengths[] = {1.0, 0.3, 2.0};
    for (int i = 0; i < 3; i++) {
        GGenerator *h;
        double k = slopes[i], s = strengths[i];
        /* h = k u in (u, v) */
        assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(k, 0, 0), 0.0, &h, &err), G_OK);
        assert_int_equal(gnode_bump_create(lam, h, s, &bump, &err), G_OK);
        plane_point(&f->sp, f->rgb, f->scratch, 0.3, 0.7);
        f->sp.material = bump;
        GVec3 n = gsurfpoint_normal(&f->sp), d;
        assert_float_equal(gvec3_length(n), 1.0, 1e-12);
        assert_float_equal(tilt(n, &d), atan(fabs(s * k)), 1e-12);
        assert_float_equal(d.x, k * s > 0 ? -1.0 : 1.0, 1e-12); /* leans away from the rising side */
        /* the leaf sees the bumped normal: light along it gives cos = 1 */
        assert_int_equal(gmaterial_reflection(bump, &f->sp, n, &f->illum, gvec3(0, 0, 1), &f->c), G_OK);
        assert_float_equal(color_r(&f->c), 0.5 / M_PI, 1e-6);
        /* tangents twice as long along u: the displaced plane rises k s per 2 units of x */
        plane_point(&f->sp, f->rgb, f->scratch, 0.3, 0.7);
        f->sp.dpdu = gvec3(2, 0, 0);
        f->sp.material = bump;
        n = gsurfpoint_normal(&f->sp);
        assert_float_equal(tilt(n, &d), atan(fabs(s * k) / 2.0), 1e-12);
        /* from the back of the surface (not entering) the bump still rises towards the outside */
        plane_point(&f->sp, f->rgb, f->scratch, 0.3, 0.7);
        f->sp.geometric_normal = gvec3(0, 0, -1);
        f->sp.entering = 0;
        GVec3 nb;
        assert_int_equal(gmaterial_normal(bump, &f->sp, &nb), G_OK);
        /* lambert's normal is the geometric one here (-z); the bumped normal is the front's, negated */
        assert_float_equal(nb.z, -cos(atan(fabs(s * k))), 1e-12);
        assert_float_equal(nb.x, k * s > 0 ? sin(atan(fabs(s * k))) : -sin(atan(fabs(s * k))), 1e-12);
        gmaterial_unref(bump);
        ggenerator_unref(h);
    }
    /* a solid height field along x, through the object tangents (rotated object: object x is world y) */
    GGenerator *h;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_OBJECT, gvec3(0.5, 0, 0), 0.0, &h, &err), G_OK);
    assert_int_equal(gnode_bump_create(lam, h, 1.0, &bump, &err), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0.3, 0.7);
    f->sp.object_dpdu = gvec3(0, 1, 0);
    f->sp.object_dpdv = gvec3(-1, 0, 0);
    GVec3 n, d;
    assert_int_equal(gmaterial_normal(bump, &f->sp, &n), G_OK);
    /* dh/du = 0, dh/dv = -0.5: the normal leans towards +y */
    assert_float_equal(tilt(n, &d), atan(0.5), 1e-12);
    assert_float_equal(d.y, 1.0, 1e-12);
    gmaterial_unref(bump);
    ggenerator_unref(h);

    /* a noise height field: the normal is the finite-difference normal of the displaced surface */
    GNoiseParams np = {.space = GGENERATOR_SPACE_UV, .frequency = 3.0, .seed = 7};
    assert_int_equal(ggenerator_perlin_create(&np, &h, &err), G_OK);
    assert_int_equal(gnode_bump_create(lam, h, 0.2, &bump, &err), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0.37, 0.71);
    assert_int_equal(gmaterial_normal(bump, &f->sp, &n), G_OK);
    double e = 1e-6;
    GSurfPoint q = f->sp;
    q.u += e;
    double hu = ggenerator_value(h, &q);
    q.u -= 2 * e;
    hu = (hu - ggenerator_value(h, &q)) / (2 * e);
    q = f->sp;
    q.v += e;
    double hv = ggenerator_value(h, &q);
    q.v -= 2 * e;
    hv = (hv - ggenerator_value(h, &q)) / (2 * e);
    GVec3 want = gvec3_normalize(gvec3(-0.2 * hu, -0.2 * hv, 1.0));
    assert_float_equal(n.x, want.x, 1e-6);
    assert_float_equal(n.y, want.y, 1e-6);
    gmaterial_unref(bump);
    ggenerator_unref(h);

    gmaterial_unref(lam);
    gcolor_free(&rho);
}

static void test_scale(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.8, 0.6, 0.4);
    GGenerator *half, *zero;
    GMaterial *n, *nz;
    GError err;
    assert_int_equal(ggenerator_constant_create(0.5, &half, &err), G_OK);
    assert_int_equal(ggenerator_constant_create(0.0, &zero, &err), G_OK);
    assert_int_equal(gnode_scale_create(&a->base, half, &n, &err), G_OK);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(&f->c, GCOLOR_REFLECTANCE, rgb), G_OK);
    assert_float_equal(rgb[0], 0.4, 1e-6);
    assert_float_equal(rgb[2], 0.2, 1e-6);
    assert_int_equal(gmaterial_refraction_index(n, &f->sp, &f->c), G_OK); /* not scaled */
    assert_float_equal(color_r(&f->c), 0.8, 1e-6);
    assert_int_equal(gnode_scale_create(&a->base, zero, &nz, &err), G_OK);
    int before = countmat_total(a);
    assert_int_equal(gmaterial_emission(nz, &f->sp, gvec3(0, 0, 1), &f->c), G_OK);
    assert_float_equal(gcolor_brightness(&f->c), 0.0, 0.0);
    assert_int_equal(countmat_total(a), before); /* a factor of 0 does not call the child */
    gmaterial_unref(n);
    gmaterial_unref(nz);
    ggenerator_unref(half);
    ggenerator_unref(zero);
    gmaterial_unref(&a->base);
}

/* A negative factor (a gradient or noise below 0) scales by 0: black, never negative light, in every method and in
 * sample()'s weight. */
static void test_scale_negative_factor(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.8, 0.6, 0.4);
    GGenerator *neg;
    GMaterial *n;
    GError err;
    assert_int_equal(ggenerator_constant_create(-0.5, &neg, &err), G_OK);
    assert_int_equal(gnode_scale_create(&a->base, neg, &n, &err), G_OK);
    f->sp.material = n;
    GVec3 in = gvec3(0, 0.6, 0.8), out = gvec3(0, -0.6, 0.8);
    assert_int_equal(gmaterial_diffuse(n, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.0, 0.0);
    assert_int_equal(gmaterial_reflection(n, &f->sp, in, &f->illum, out, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.0, 0.0);
    assert_int_equal(gmaterial_ambient(n, &f->sp, &f->illum, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.0, 0.0);
    GMaterialSample s;
    int rc = gmaterial_sample(n, &f->sp, out, NULL, 0.3, 0.7, &s, &f->c);
    assert_true(rc >= 0);
    if (rc == 1)
        assert_true(gcolor_is_nonnegative(&f->c) && color_r(&f->c) == 0.0);
    f->sp.material = NULL;
    gmaterial_unref(n);
    ggenerator_unref(neg);
    gmaterial_unref(&a->base);
}

static void test_bad_input(void **state)
{
    Fix *f = *state;
    GError err;
    GMaterial *n = (GMaterial *)1;
    GGenerator *g;
    assert_int_equal(ggenerator_constant_create(0.5, &g, &err), G_OK);
    CountMat *a = countmat_new(f->rgb, 0.5, 0.5, 0.5);
    GMaterial *one[1] = {&a->base};

    assert_int_equal(gnode_select_create(NULL, 0, g, &n, &err), G_ERR_INVALID);
    assert_null(n);
    assert_non_null(strstr(err.message, "select: no children"));
    assert_int_equal(gnode_spline_create(one, 0, g, GSPLINE_CATMULL_ROM, &n, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "no children"));
    assert_int_equal(gnode_spline_create(one, 1, g, GSPLINE_CATMULL_ROM, &n, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "at least 2"));
    assert_int_equal(gnode_interpolate_create(&a->base, NULL, g, &n, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "child 2 is missing"));
    assert_int_equal(gnode_interpolate_create(&a->base, &a->base, NULL, &n, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "no generator"));
    assert_int_equal(gnode_bump_create(&a->base, g, NAN, &n, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "strength"));

    GColorModel *s9;
    assert_int_equal(gcolormodel_create("spectrum9", NULL, &s9, &err), G_OK);
    CountMat *b = countmat_new(s9, 0.5, 0.5, 0.5);
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, g, &n, &err), G_ERR_MISMATCH);
    assert_non_null(strstr(err.message, "colour model"));
    gmaterial_unref(&b->base);
    gcolormodel_destroy(s9);

    /* the references a node takes are released with it */
    assert_int_equal(gnode_interpolate_create(&a->base, &a->base, g, &n, &err), G_OK);
    assert_int_equal(a->base.refcount, 3);
    assert_int_equal(g->refcount, 2);
    gmaterial_unref(n);
    assert_int_equal(a->base.refcount, 1);
    assert_int_equal(g->refcount, 1);
    gmaterial_unref(&a->base);
    ggenerator_unref(g);
}

/* ---- out of memory at every allocation of a tree's construction: clean failure, no leak ---- */
static int build_tree(const GColorModel *m, GError *err)
{
    CountMat *a = countmat_new(m, 0.1, 0.1, 0.1), *b = countmat_new(m, 0.9, 0.9, 0.9);
    GGenerator *g = NULL, *h = NULL;
    GMaterial *i = NULL, *s = NULL, *bump = NULL, *t = NULL, *sel = NULL;
    GNoiseParams np = {0};
    int rc = ggenerator_perlin_create(&np, &g, err);
    if (rc == G_OK)
        rc = ggenerator_checker_create(2, 4.0, &h, err);
    if (rc == G_OK)
        rc = gnode_interpolate_create(&a->base, &b->base, h, &i, err);
    GMaterial *kids[3] = {&a->base, i, &b->base};
    if (rc == G_OK)
        rc = gnode_spline_create(kids, 3, g, GSPLINE_CATMULL_ROM, &s, err);
    if (rc == G_OK)
        rc = gnode_bump_create(s, g, 0.1, &bump, err);
    GAffine2 r = gaffine2_rotate(30);
    if (rc == G_OK)
        rc = gnode_transform_create(bump, &r, NULL, &t, err);
    if (rc == G_OK)
        rc = gnode_select_create(kids, 3, g, &sel, err);
    gmaterial_unref(sel);
    gmaterial_unref(t);
    gmaterial_unref(bump);
    gmaterial_unref(s);
    gmaterial_unref(i);
    ggenerator_unref(g);
    ggenerator_unref(h);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
    return rc;
}

/* Nodes need no arena from the caller, whatever the model's size: without sp->scratch their temporaries come
 * from the thread's own arena (gscratch_thread). A 1 nm spectrum has 401 samples, more than any stack buffer. */
static void test_blend_without_arena(void **state)
{
    (void)state;
    GColorModelOptions o = {.step_nm = 1};
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create("spectrum", &o, &m, &err), G_OK);
    assert_true(m->capacity > 64);
    GReaderOptions ro = {.model = m};
    GLibrary *lib;
    assert_int_equal(greader_load_string("node n interpolate { a lambert { reflectance rgb 0.2 0.2 0.2 }\n"
                                         "    b lambert { reflectance rgb 0.6 0.6 0.6 }  t constant { value 0.25 } }\n",
                                         "n.txt", &ro, &lib, &err),
                     G_OK);
    GMaterial *n = glibrary_material(lib, "n");
    assert_non_null(n);
    GSurfPoint sp;
    gsurfpoint_init(&sp, m, NULL);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.material = n;
    GColor c, illum;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gcolor_alloc(&illum, m), G_OK);
    assert_int_equal(gmaterial_diffuse(n, &sp, &c), G_OK);
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(&c, GCOLOR_REFLECTANCE, rgb), G_OK);
    for (int k = 0; k < 3; k++)
        assert_float_equal(rgb[k], 0.75 * 0.2 + 0.25 * 0.6, 1e-4);
    /* reflection of white light at normal incidence: rho / pi */
    assert_int_equal(gcolor_from_rgb(&illum, (double[3]){1, 1, 1}, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gmaterial_reflection(n, &sp, gvec3(0, 0, 1), &illum, gvec3(0, 0, 1), &c), G_OK);
    assert_int_equal(gcolor_to_rgb(&c, GCOLOR_LIGHT, rgb), G_OK);
    for (int k = 0; k < 3; k++)
        assert_float_equal(rgb[k], 0.3 / M_PI, 1e-4);
    gcolor_free(&c);
    gcolor_free(&illum);
    glibrary_destroy(lib);
    gcolormodel_destroy(m);
}

static void test_out_of_memory(void **state)
{
    Fix *f = *state;
    GError err;
    int failures = 0;
    for (long k = 0; k < 200; k++) {
        static TuAlloc alloc;
        alloc = (TuAlloc){.fail_call = k + 1};
        tu_alloc_install(&alloc);
        int rc = build_tree(f->rgb, &err);
        gmem_set_allocator(NULL);
        if (rc == G_OK)
            break;
        assert_int_equal(rc, G_ERR_NOMEM);
        assert_non_null(strstr(err.message, "out of memory"));
        failures++;
    }
    assert_true(failures >= 8); /* every library allocation of the tree was made to fail once */
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_interpolate_fast_path, setup, teardown),
        cmocka_unit_test_setup_teardown(test_interpolate_blend, setup, teardown),
        cmocka_unit_test_setup_teardown(test_generator_cached_per_point, setup, teardown),
        cmocka_unit_test_setup_teardown(test_interpolate_one, setup, teardown),
        cmocka_unit_test_setup_teardown(test_select_by_surface, setup, teardown),
        cmocka_unit_test_setup_teardown(test_spline, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bump_analytic_tilt, setup, teardown),
        cmocka_unit_test_setup_teardown(test_scale, setup, teardown),
        cmocka_unit_test_setup_teardown(test_scale_negative_factor, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_input, setup, teardown),
        cmocka_unit_test_setup_teardown(test_out_of_memory, setup, teardown),
        cmocka_unit_test(test_blend_without_arena),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
