/* test_texture_transform.c - the transform node: patterns move by the expected offsets, the footprint's axes
 * move with them, values cached below a transform belong to the moved coordinates yet are kept across
 * method calls, and a (u, v) transform leaves the bumps of object- and world-space height fields alone. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/materials.h>

#include "texture_fixtures.h"
#include "test_util.h"

#include <stdio.h>

#include "node_fixture.h"
#include "generic/builtins.h"

/* A checker of dimension dim (cell size 1) blending a (even cells) and b (odd cells); *chk gets the generator. */
static GMaterial *checker_tree(int dim, CountMat *a, CountMat *b, GGenerator **chk)
{
    GMaterial *pat;
    GError err;
    assert_int_equal(ggenerator_checker_create(dim, 1.0, chk, &err), G_OK);
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, *chk, &pat, &err), G_OK);
    return pat;
}

/* A checker between black and white under a transform, read at (u, v). */
static double checker_at(Fix *f, const GMaterial *tree, double u, double v)
{
    plane_point(&f->sp, f->rgb, f->scratch, u, v);
    f->sp.material = tree;
    assert_int_equal(gmaterial_diffuse(tree, &f->sp, &f->c), G_OK);
    return color_r(&f->c);
}

static void test_transform_moves_patterns(void **state)
{
    Fix *f = *state;
    CountMat *black = countmat_new(f->rgb, 0, 0, 0), *white = countmat_new(f->rgb, 1, 1, 1);
    GGenerator *chk;
    GMaterial *pat, *moved;
    GError err;
    pat = checker_tree(2, black, white, &chk);
    /* the pattern: cell (0,0) black, (1,0) white */
    assert_float_equal(checker_at(f, pat, 0.75, 0.5), 0.0, 1e-6);
    assert_float_equal(checker_at(f, pat, 1.25, 0.5), 1.0, 1e-6);

    GAffine2 t = gaffine2_translate(0.5, 0.0);
    assert_int_equal(gnode_transform_create(pat, &t, NULL, &moved, &err), G_OK);
    /* the edge at u = 1 moved to u = 1.5 */
    assert_float_equal(checker_at(f, moved, 1.25, 0.5), 0.0, 1e-6);
    assert_float_equal(checker_at(f, moved, 1.45, 0.5), 0.0, 1e-6);
    assert_float_equal(checker_at(f, moved, 1.55, 0.5), 1.0, 1e-6);
    gmaterial_unref(moved);

    GAffine2 s = gaffine2_scale(2.0, 2.0); /* cells twice as big */
    assert_int_equal(gnode_transform_create(pat, &s, NULL, &moved, &err), G_OK);
    assert_float_equal(checker_at(f, moved, 1.9, 0.5), 0.0, 1e-6);
    assert_float_equal(checker_at(f, moved, 2.1, 0.5), 1.0, 1e-6);
    gmaterial_unref(moved);

    GAffine2 r = gaffine2_rotate(90.0); /* the white cell at (1.5, 0.5) turns to (-0.5, 1.5) */
    assert_int_equal(gnode_transform_create(pat, &r, NULL, &moved, &err), G_OK);
    assert_float_equal(checker_at(f, moved, -0.5, 1.5), 1.0, 1e-6);
    assert_float_equal(checker_at(f, moved, 0.5, 1.5), 0.0, 1e-6);
    assert_float_equal(checker_at(f, moved, 1.5, 1.5), 1.0, 1e-6); /* (1.5, -1.5) before turning */
    gmaterial_unref(moved);
    gmaterial_unref(pat);
    ggenerator_unref(chk);

    /* 3D: a solid checker moved by (0, 0, 0.25) */
    pat = checker_tree(3, black, white, &chk);
    GAffine3 t3 = gaffine3_translate(gvec3(0, 0, 0.25));
    assert_int_equal(gnode_transform_create(pat, NULL, &t3, &moved, &err), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0, 0);
    f->sp.object_point = gvec3(0.5, 0.5, 0.2); /* below the moved edge at z = 0.25: cell z = -1 */
    assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 1.0, 1e-6);
    f->sp.object_point = gvec3(0.5, 0.5, 0.3);
    gsurfpoint_invalidate(&f->sp);
    assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.0, 1e-6);
    gmaterial_unref(moved);
    gmaterial_unref(pat);
    ggenerator_unref(chk);

    /* bumps under a rotation turn with the pattern: h = u rotated by 90 degrees rises along v */
    GGenerator *h;
    GMaterial *bump;
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(1, 0, 0), 0, &h, &err), G_OK);
    assert_int_equal(gnode_bump_create(&white->base, h, 1.0, &bump, &err), G_OK);
    assert_int_equal(gnode_transform_create(bump, &r, NULL, &moved, &err), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0.2, 0.3);
    GVec3 n;
    assert_int_equal(gmaterial_normal(moved, &f->sp, &n), G_OK);
    assert_float_equal(n.x, 0.0, 1e-12);
    assert_float_equal(n.y, -sqrt(0.5), 1e-12); /* leans away from +v, where the field now rises */
    gmaterial_unref(moved);
    gmaterial_unref(bump);
    ggenerator_unref(h);

    GAffine2 singular = {{1, 2, 0, 2, 4, 0}};
    assert_int_equal(gnode_transform_create(&white->base, &singular, NULL, &moved, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "singular"));
    gmaterial_unref(&black->base);
    gmaterial_unref(&white->base);
}

/* Values cached below a transform belong to the moved coordinates: never confused with the same generator's
 * value above it, yet kept across method calls through the transform (each generator once per point). */
static void test_transform_cache_semantics(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.2, 0.2, 0.2), *b = countmat_new(f->rgb, 0.6, 0.6, 0.6);
    GGenerator *chk;
    GMaterial *pat, *moved;
    GError err;
    /* the same checker generator above and below a transform */
    pat = checker_tree(2, a, b, &chk);
    GAffine2 t = gaffine2_translate(1.0, 0.0);
    assert_int_equal(gnode_transform_create(pat, &t, NULL, &moved, &err), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0.5, 0.5);
    /* evaluate above first (caches 0 for this point), then below: the moved pattern must give 1 */
    assert_int_equal(gmaterial_diffuse(pat, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.2, 1e-6);
    assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.6, 1e-6);
    assert_int_equal(gmaterial_diffuse(pat, &f->sp, &f->c), G_OK); /* and the cache above is untouched */
    assert_float_equal(color_r(&f->c), 0.2, 1e-6);
    assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK); /* and below, found again */
    assert_float_equal(color_r(&f->c), 0.6, 1e-6);

    /* a counting generator under two nested transforms: once per point over a sequence of calls */
    CountGen *g = countgen_new(0.5);
    GMaterial *inner, *mid, *outer;
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, &g->base, &inner, &err), G_OK);
    GAffine2 s2 = gaffine2_translate(0.25, 0.0);
    assert_int_equal(gnode_transform_create(inner, &s2, NULL, &mid, &err), G_OK);
    assert_int_equal(gnode_transform_create(mid, &t, NULL, &outer, &err), G_OK);
    gsurfpoint_invalidate(&f->sp);
    f->sp.material = outer;
    for (int light = 0; light < 4; light++)
        assert_int_equal(gmaterial_reflection(outer, &f->sp, gvec3(0, 0, 1), &f->illum, gvec3(0, 0, 1), &f->c), G_OK);
    call_all(f, outer);
    assert_int_equal(g->calls, 1);
    /* the same subtree reached without the outer transform is at other coordinates: evaluated again */
    assert_int_equal(gmaterial_diffuse(mid, &f->sp, &f->c), G_OK);
    assert_int_equal(g->calls, 2);
    assert_int_equal(gmaterial_diffuse(mid, &f->sp, &f->c), G_OK);
    assert_int_equal(gmaterial_diffuse(outer, &f->sp, &f->c), G_OK);
    assert_int_equal(g->calls, 2);
    gsurfpoint_invalidate(&f->sp); /* a new point evaluates again */
    assert_int_equal(gmaterial_diffuse(outer, &f->sp, &f->c), G_OK);
    assert_int_equal(g->calls, 3);
    gmaterial_unref(outer);
    gmaterial_unref(mid);
    gmaterial_unref(inner);
    ggenerator_unref(&g->base);
    gmaterial_unref(moved);
    gmaterial_unref(pat);
    ggenerator_unref(chk);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
}

/* The footprint's axes move with the coordinates: below a transform, each axis is the difference of the moved
 * coordinates of the point and of the point plus that axis (checked for a rotation with uneven scaling). */
static void test_transform_moves_footprint(void **state)
{
    Fix *f = *state;
    CountMat *a = countmat_new(f->rgb, 0.2, 0.2, 0.2), *b = countmat_new(f->rgb, 0.6, 0.6, 0.6);
    CountGen *g = countgen_new(0.5);
    GMaterial *pat, *moved;
    GError err;
    assert_int_equal(gnode_interpolate_create(&a->base, &b->base, &g->base, &pat, &err), G_OK);
    GAffine2 r = gaffine2_rotate(30), sc = gaffine2_scale(2.0, 0.5), t = gaffine2_mul(&r, &sc);
    assert_int_equal(gnode_transform_create(pat, &t, NULL, &moved, &err), G_OK);
    const double u = 0.3, v = 0.7, ax1[2] = {0.01, 0.002}, ax2[2] = {-0.001, 0.004};
    double at[3][2];
    const double du[3] = {0, ax1[0], ax2[0]}, dv[3] = {0, ax1[1], ax2[1]};
    for (int k = 0; k < 3; k++) { /* the moved coordinates of the point and of its two axis ends */
        plane_point(&f->sp, f->rgb, f->scratch, u + du[k], v + dv[k]);
        assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK);
        at[k][0] = g->u;
        at[k][1] = g->v;
    }
    plane_point(&f->sp, f->rgb, f->scratch, u, v);
    memcpy(f->sp.uv_axis1, ax1, sizeof ax1);
    memcpy(f->sp.uv_axis2, ax2, sizeof ax2);
    assert_int_equal(gmaterial_diffuse(moved, &f->sp, &f->c), G_OK);
    for (int c = 0; c < 2; c++) {
        assert_true(fabs(g->axis1[c] - (at[1][c] - at[0][c])) < 1e-12);
        assert_true(fabs(g->axis2[c] - (at[2][c] - at[0][c])) < 1e-12);
    }
    assert_true(fabs(g->axis1[0] - ax1[0]) > 1e-4); /* they did move */
    gmaterial_unref(moved);
    gmaterial_unref(pat);
    ggenerator_unref(&g->base);
    gmaterial_unref(&a->base);
    gmaterial_unref(&b->base);
}

/* A (u, v) transform moves no pattern in object or world space, so a bump of such a height field must keep its
 * normal under it, whatever the xyz part does not move either: the tangents along the new (u, v) and the height's
 * derivatives along them change together (Blinn's normal does not depend on the parametrisation). Checked for an
 * identity xyz part (object tangents taken from dpdu, dpdv) and with the renderer's own object tangents. */
static void test_transform_uv_keeps_solid_bumps(void **state)
{
    Fix *f = *state;
    CountMat *white = countmat_new(f->rgb, 1, 1, 1);
    GError err;
    const GGeneratorSpace spaces[] = {GGENERATOR_SPACE_OBJECT, GGENERATOR_SPACE_WORLD};
    GAffine2 r = gaffine2_rotate(90), r30 = gaffine2_rotate(30), sc = gaffine2_scale(2.0, -0.5);
    GAffine2 uvs[] = {r, gaffine2_mul(&sc, &r30)};
    GAffine3 same = gaffine3_translate(gvec3(0, 0, 0));
    for (int s = 0; s < 2; s++) {
        GGenerator *h;
        GMaterial *bump;
        assert_int_equal(ggenerator_gradient_create(spaces[s], gvec3(1, 0.5, 0), 0, &h, &err), G_OK);
        assert_int_equal(gnode_bump_create(&white->base, h, 0.8, &bump, &err), G_OK);
        for (int own = 0; own < 2; own++) { /* own: the renderer gives object tangents (object = world turned) */
            plane_point(&f->sp, f->rgb, f->scratch, 0.2, 0.3);
            if (own)
                f->sp.object_dpdu = gvec3(0, 1, 0), f->sp.object_dpdv = gvec3(-1, 0, 0);
            GSurfPoint at = f->sp;
            GVec3 n0, n;
            assert_int_equal(gmaterial_normal(bump, &at, &n0), G_OK);
            assert_true(n0.z < 0.9); /* it does tilt */
            for (int k = 0; k < 2; k++)
                for (int xyz = 0; xyz < 2; xyz++) {
                    GMaterial *moved;
                    assert_int_equal(gnode_transform_create(bump, &uvs[k], xyz ? &same : NULL, &moved, &err), G_OK);
                    at = f->sp;
                    assert_int_equal(gmaterial_normal(moved, &at, &n), G_OK);
                    assert_true(gvec3_length(gvec3_sub(n, n0)) < 1e-12);
                    gmaterial_unref(moved);
                }
        }
        gmaterial_unref(bump);
        ggenerator_unref(h);
    }
    gmaterial_unref(&white->base);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_transform_moves_patterns, setup, teardown),
        cmocka_unit_test_setup_teardown(test_transform_cache_semantics, setup, teardown),
        cmocka_unit_test_setup_teardown(test_transform_moves_footprint, setup, teardown),
        cmocka_unit_test_setup_teardown(test_transform_uv_keeps_solid_bumps, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
