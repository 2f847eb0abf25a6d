/* test_texture_shapes.c - CSG solids and CPG shapes: inside/outside at known points, boolean operations,
 * transforms, points within 1e-6 of NURBS, Bézier and B-spline edges, and bad shapes. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/textures.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "generic/builtins.h"

static void test_csg_solids(void **state)
{
    (void)state;
    GError err;
    GCsgShape *s, *b, *c, *k, *h;
    assert_int_equal(gcsg_sphere(2.0, &s, &err), G_OK);
    assert_true(gcsg_inside(s, gvec3(0, 0, 2.0 - 1e-9)));
    assert_false(gcsg_inside(s, gvec3(0, 0, 2.0 + 1e-9)));
    assert_true(gcsg_inside(s, gvec3(1.15, 1.15, 1.15)));  /* |p| = 1.992 */
    assert_false(gcsg_inside(s, gvec3(1.16, 1.16, 1.16))); /* |p| = 2.009 */
    assert_int_equal(gcsg_box(gvec3(-1, 0, 2), gvec3(1, 3, 4), &b, &err), G_OK);
    assert_true(gcsg_inside(b, gvec3(0.99, 2.99, 2.01)));
    assert_false(gcsg_inside(b, gvec3(0, 1, 1.99)));
    assert_false(gcsg_inside(b, gvec3(1.01, 1, 3)));
    assert_int_equal(gcsg_cylinder(1.0, -1.0, 1.0, &c, &err), G_OK);
    assert_true(gcsg_inside(c, gvec3(0.7, 0.7, 0.99)));   /* r = 0.9899 */
    assert_false(gcsg_inside(c, gvec3(0.71, 0.71, 0.0))); /* r = 1.004 */
    assert_false(gcsg_inside(c, gvec3(0, 0, 1.01)));
    /* cone: radius 1 at z = 0 to 0 at z = 2: radius 0.5 at z = 1 */
    assert_int_equal(gcsg_cone(1.0, 0.0, 0.0, 2.0, &k, &err), G_OK);
    assert_true(gcsg_inside(k, gvec3(0.499, 0, 1)));
    assert_false(gcsg_inside(k, gvec3(0, 0.501, 1)));
    assert_true(gcsg_inside(k, gvec3(0, 0, 1.999)));
    assert_false(gcsg_inside(k, gvec3(0, 0, -0.001)));
    assert_int_equal(gcsg_halfspace(gvec3(0, 0, 2), 1.0, &h, &err), G_OK); /* z <= 0.5 */
    assert_true(gcsg_inside(h, gvec3(100, -50, 0.4999)));
    assert_false(gcsg_inside(h, gvec3(0, 0, 0.5001)));
    gcsg_destroy(s);
    gcsg_destroy(b);
    gcsg_destroy(c);
    gcsg_destroy(k);
    gcsg_destroy(h);
}

static void test_csg_operations_and_transforms(void **state)
{
    (void)state;
    GError err;
    GCsgShape *a, *b, *u, *i, *d, *a2, *b2, *a3, *b3;
    /* two unit spheres at x = 0 and x = 1 */
    assert_int_equal(gcsg_sphere(1.0, &a, &err), G_OK);
    assert_int_equal(gcsg_sphere(1.0, &b, &err), G_OK);
    GAffine3 t = gaffine3_translate(gvec3(1, 0, 0));
    assert_int_equal(gcsg_transform(b, &t, &err), G_OK);
    assert_true(gcsg_inside(b, gvec3(1.9, 0, 0)));
    assert_false(gcsg_inside(b, gvec3(-0.1, 0, 0)));
    assert_int_equal(gcsg_combine(GSHAPE_UNION, a, b, &u, &err), G_OK);
    assert_true(gcsg_inside(u, gvec3(-0.9, 0, 0)));
    assert_true(gcsg_inside(u, gvec3(1.9, 0, 0)));
    assert_false(gcsg_inside(u, gvec3(0.5, 0.9, 0)));
    assert_int_equal(gcsg_sphere(1.0, &a2, &err), G_OK);
    assert_int_equal(gcsg_sphere(1.0, &b2, &err), G_OK);
    assert_int_equal(gcsg_transform(b2, &t, &err), G_OK);
    assert_int_equal(gcsg_combine(GSHAPE_INTERSECTION, a2, b2, &i, &err), G_OK);
    assert_true(gcsg_inside(i, gvec3(0.5, 0.8, 0)));
    assert_false(gcsg_inside(i, gvec3(-0.5, 0, 0)));
    assert_int_equal(gcsg_sphere(1.0, &a3, &err), G_OK);
    assert_int_equal(gcsg_sphere(1.0, &b3, &err), G_OK);
    assert_int_equal(gcsg_transform(b3, &t, &err), G_OK);
    assert_int_equal(gcsg_combine(GSHAPE_DIFFERENCE, a3, b3, &d, &err), G_OK);
    assert_true(gcsg_inside(d, gvec3(-0.5, 0, 0)));
    assert_false(gcsg_inside(d, gvec3(0.5, 0, 0)));

    /* a transform of the whole tree: scaled by 2 about the origin, then rotated 90 degrees about z */
    GAffine3 sc = gaffine3_scale(gvec3(2, 2, 2)), rot = gaffine3_rotate(gvec3(0, 0, 1), 90);
    assert_int_equal(gcsg_transform(d, &sc, &err), G_OK);
    assert_int_equal(gcsg_transform(d, &rot, &err), G_OK);
    /* the old (-0.5, 0, 0) is now at (0, -1, 0); the removed (0.5, 0, 0) at (0, 1, 0) */
    assert_true(gcsg_inside(d, gvec3(0, -1, 0)));
    assert_false(gcsg_inside(d, gvec3(0, 1, 0)));
    assert_true(gcsg_inside(d, gvec3(0, -1.99, 0)));
    assert_false(gcsg_inside(d, gvec3(0, -2.01, 0)));

    /* the generator reads the object-space point */
    GGenerator *g;
    assert_int_equal(ggenerator_csg_create(d, GGENERATOR_SPACE_OBJECT, &g, &err), G_OK);
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.point = gvec3(0, 1, 0); /* world point ignored */
    sp.object_point = gvec3(0, -1, 0);
    assert_float_equal(ggenerator_value(g, &sp), 1.0, 0.0);
    sp.object_point = gvec3(0, 1, 0);
    assert_float_equal(ggenerator_value(g, &sp), 0.0, 0.0);
    ggenerator_unref(g);
    gcsg_destroy(u);
    gcsg_destroy(i);

    GAffine3 singular = gaffine3_scale(gvec3(1, 0, 1));
    assert_int_equal(gcsg_sphere(1.0, &a, &err), G_OK);
    assert_int_equal(gcsg_transform(a, &singular, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "singular"));
    assert_true(gcsg_inside(a, gvec3(0.5, 0, 0))); /* unchanged */
    gcsg_destroy(a);
}

static void test_csg_bad_input(void **state)
{
    (void)state;
    GError err;
    GCsgShape *s = (GCsgShape *)1, *a;
    assert_int_equal(gcsg_sphere(0.0, &s, &err), G_ERR_INVALID);
    assert_null(s);
    assert_non_null(strstr(err.message, "radius"));
    assert_int_equal(gcsg_box(gvec3(0, 0, 0), gvec3(1, 0, 1), &s, &err), G_ERR_INVALID);
    assert_int_equal(gcsg_cylinder(1.0, 1.0, 1.0, &s, &err), G_ERR_INVALID);
    assert_int_equal(gcsg_cone(0.0, 0.0, 0.0, 1.0, &s, &err), G_ERR_INVALID);
    assert_int_equal(gcsg_halfspace(gvec3(0, 0, 0), 1.0, &s, &err), G_ERR_INVALID);
    assert_int_equal(gcsg_sphere(1.0, &a, &err), G_OK);
    assert_int_equal(gcsg_combine(GSHAPE_UNION, a, NULL, &s, &err), G_ERR_INVALID); /* frees a */
    GGenerator *g;
    assert_int_equal(ggenerator_csg_create(NULL, GGENERATOR_SPACE_OBJECT, &g, &err), G_ERR_INVALID);
}

/* ---- CPG ---- */

static void test_cpg_primitives(void **state)
{
    (void)state;
    GError err;
    GCpgShape *sq, *ci, *poly, *star;
    assert_int_equal(gcpg_square(1.0, 1.0, 2.0, &sq, &err), G_OK);
    assert_true(gcpg_inside(sq, 0.001, 1.999));
    assert_false(gcpg_inside(sq, -0.001, 1.0));
    assert_int_equal(gcpg_circle(0.5, -0.5, 0.25, &ci, &err), G_OK);
    assert_true(gcpg_inside(ci, 0.5 + 0.25 - 1e-9, -0.5));
    assert_false(gcpg_inside(ci, 0.5, -0.5 + 0.25 + 1e-9));
    /* an L: the notch at the top right is outside */
    const double L[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
    assert_int_equal(gcpg_polygon(L, 6, &poly, &err), G_OK);
    assert_true(gcpg_inside(poly, 0.5, 1.5));
    assert_true(gcpg_inside(poly, 1.5, 0.5));
    assert_false(gcpg_inside(poly, 1.5, 1.5));
    assert_false(gcpg_inside(poly, -0.1, 0.5));
    assert_false(gcpg_inside(poly, 0.5, 2.1));
    /* vertices at the point's height (the half-open rule counts them once) */
    assert_true(gcpg_inside(poly, 0.5, 1.0));
    assert_false(gcpg_inside(poly, 2.5, 1.0));
    assert_false(gcpg_inside(poly, -0.5, 1.0));
    /* a pentagram drawn in one stroke: the centre has winding number 2, inside by the non-zero rule */
    double pts[10];
    for (int i = 0; i < 5; i++) {
        double a = M_PI / 2 + i * 4 * M_PI / 5;
        pts[2 * i] = cos(a);
        pts[2 * i + 1] = sin(a);
    }
    assert_int_equal(gcpg_polygon(pts, 5, &star, &err), G_OK);
    assert_true(gcpg_inside(star, 0.0, 0.0));
    assert_true(gcpg_inside(star, 0.0, 0.9));
    assert_false(gcpg_inside(star, 0.9, 0.9));
    gcpg_destroy(sq);
    gcpg_destroy(ci);
    gcpg_destroy(poly);
    gcpg_destroy(star);
}

/* The classic quadratic NURBS circle: nine control points on the unit square, corner weights sqrt(2)/2. */
static int nurbs_circle(GCpgShape **out, GError *err)
{
    const double h = sqrt(0.5);
    const double xy[] = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
    const double w[] = {1, h, 1, h, 1, h, 1, h, 1};
    const double knots[] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    GCpgPath *p;
    int rc = gcpg_path_create(&p, err);
    if (rc == G_OK)
        rc = gcpg_path_nurbs(p, 2, xy, w, 9, knots, err);
    if (rc != G_OK) {
        gcpg_path_destroy(p);
        return rc;
    }
    return gcpg_path_close(p, out, err);
}

static void test_cpg_nurbs_circle_is_exact(void **state)
{
    (void)state;
    GError err;
    GCpgShape *c;
    assert_int_equal(nurbs_circle(&c, &err), G_OK);
    int n = 0;
    for (int i = 0; i < 3600; i++) {
        double a = 2 * M_PI * (i + 0.5) / 3600; /* includes angles next to the arcs' middles */
        assert_true(gcpg_inside(c, (1 - 1e-6) * cos(a), (1 - 1e-6) * sin(a)));
        assert_false(gcpg_inside(c, (1 + 1e-6) * cos(a), (1 + 1e-6) * sin(a)));
        n++;
    }
    /* exactly at 45 degrees, where the weights matter most */
    assert_true(gcpg_inside(c, (1 - 1e-6) * sqrt(0.5), (1 - 1e-6) * sqrt(0.5)));
    assert_false(gcpg_inside(c, (1 + 1e-6) * sqrt(0.5), (1 + 1e-6) * sqrt(0.5)));
    assert_true(gcpg_inside(c, 0, 0));
    assert_int_equal(n, 3600);

    /* moved: radius 2 about (3, 0) */
    GAffine2 sc = gaffine2_scale(2, 2), tr = gaffine2_translate(3, 0);
    assert_int_equal(gcpg_transform(c, &sc, &err), G_OK);
    assert_int_equal(gcpg_transform(c, &tr, &err), G_OK);
    assert_true(gcpg_inside(c, 3 + 2 * (1 - 1e-6) * cos(1.0), 2 * (1 - 1e-6) * sin(1.0)));
    assert_false(gcpg_inside(c, 3 + 2 * (1 + 1e-6) * cos(1.0), 2 * (1 + 1e-6) * sin(1.0)));
    assert_false(gcpg_inside(c, 0, 0));

    /* the generator reads (u, v) */
    GGenerator *g;
    assert_int_equal(ggenerator_cpg_create(c, &g, &err), G_OK);
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.u = 3.5;
    sp.v = 1.0;
    assert_float_equal(ggenerator_value(g, &sp), 1.0, 0.0);
    sp.u = 0.5;
    assert_float_equal(ggenerator_value(g, &sp), 0.0, 0.0);
    ggenerator_unref(g);
}

/* Point and tangent of a cubic Bézier by the power form (independent of the library's de Casteljau). */
static void bezier3(const double *P, double t, double *x, double *y, double *dx, double *dy)
{
    double s = 1 - t;
    *x = s * s * s * P[0] + 3 * s * s * t * P[2] + 3 * s * t * t * P[4] + t * t * t * P[6];
    *y = s * s * s * P[1] + 3 * s * s * t * P[3] + 3 * s * t * t * P[5] + t * t * t * P[7];
    *dx = 3 * (s * s * (P[2] - P[0]) + 2 * s * t * (P[4] - P[2]) + t * t * (P[6] - P[4]));
    *dy = 3 * (s * s * (P[3] - P[1]) + 2 * s * t * (P[5] - P[3]) + t * t * (P[7] - P[5]));
}

static void test_cpg_bezier_edge(void **state)
{
    (void)state;
    GError err;
    /* a lens: a cubic arching up from (0, 0) to (2, 0), closed by the straight line back (the gap rule) */
    const double P[] = {0, 0, 0.3, 1.5, 1.7, 1.2, 2, 0};
    GCpgPath *p;
    GCpgShape *s;
    assert_int_equal(gcpg_path_create(&p, &err), G_OK);
    assert_int_equal(gcpg_path_bezier(p, 3, P, &err), G_OK);
    assert_int_equal(gcpg_path_close(p, &s, &err), G_OK);
    for (int i = 1; i < 400; i++) {
        double t = i / 400.0, x, y, dx, dy;
        bezier3(P, t, &x, &y, &dx, &dy);
        double l = hypot(dx, dy), nx = dy / l, ny = -dx / l; /* the right of the direction: inside */
        assert_true(gcpg_inside(s, x + 1e-6 * nx, y + 1e-6 * ny));
        assert_false(gcpg_inside(s, x - 1e-6 * nx, y - 1e-6 * ny));
    }
    assert_false(gcpg_inside(s, 1.0, -1e-6)); /* below the closing line */
    gcpg_destroy(s);
}

/* A periodic uniform cubic B-spline by its basis matrix (independent of the library's blossoms). */
static void bspline3(const double *P, int n, int seg, double t, double *x, double *y, double *dx, double *dy)
{
    double b[4] = {(1 - t) * (1 - t) * (1 - t) / 6, (3 * t * t * t - 6 * t * t + 4) / 6,
                   (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
    double d[4] = {-(1 - t) * (1 - t) / 2, (3 * t * t - 4 * t) / 2, (-3 * t * t + 2 * t + 1) / 2, t * t / 2};
    *x = *y = *dx = *dy = 0;
    for (int k = 0; k < 4; k++) {
        int j = (seg + k) % n;
        *x += b[k] * P[2 * j];
        *y += b[k] * P[2 * j + 1];
        *dx += d[k] * P[2 * j];
        *dy += d[k] * P[2 * j + 1];
    }
}

static void test_cpg_bspline_edges(void **state)
{
    (void)state;
    GError err;
    /* a closed periodic cubic B-spline around a star-like control polygon, counter-clockwise */
    const double P[] = {2, 0, 1, 1, 0, 2, -1, 1, -2, 0, -1, -1, 0, -2, 1, -1};
    GCpgPath *p;
    GCpgShape *s;
    assert_int_equal(gcpg_path_create(&p, &err), G_OK);
    assert_int_equal(gcpg_path_bspline(p, 3, P, 8, 1, &err), G_OK);
    assert_int_equal(gcpg_path_close(p, &s, &err), G_OK);
    for (int seg = 0; seg < 8; seg++)
        for (int i = 0; i < 50; i++) {
            double x, y, dx, dy;
            bspline3(P, 8, seg, i / 50.0, &x, &y, &dx, &dy);
            double l = hypot(dx, dy), nx = -dy / l, ny = dx / l; /* left of a counter-clockwise curve */
            assert_true(gcpg_inside(s, x + 1e-6 * nx, y + 1e-6 * ny));
            assert_false(gcpg_inside(s, x - 1e-6 * nx, y - 1e-6 * ny));
        }
    assert_true(gcpg_inside(s, 0, 0));
    gcpg_destroy(s);

    /* an open uniform B-spline edge plus straight edges: the gaps close with lines */
    const double Q[] = {0, 0, 1, 2, 2, -1, 3, 1, 4, 0};
    assert_int_equal(gcpg_path_create(&p, &err), G_OK);
    assert_int_equal(gcpg_path_bspline(p, 2, Q, 5, 0, &err), G_OK);
    const double back[] = {3.5, -3, 0.5, -3};
    assert_int_equal(gcpg_path_lines(p, back, 2, &err), G_OK);
    assert_int_equal(gcpg_path_close(p, &s, &err), G_OK);
    assert_true(gcpg_inside(s, 2.0, -2.0));
    assert_false(gcpg_inside(s, 2.0, -3.1));
    assert_false(gcpg_inside(s, 2.0, 1.5));
    gcpg_destroy(s);
}

static void test_cpg_operations(void **state)
{
    (void)state;
    GError err;
    GCpgShape *sq, *ci, *d, *ring, *inner, *outer;
    /* a frame: square minus a circle */
    assert_int_equal(gcpg_square(0, 0, 2, &sq, &err), G_OK);
    assert_int_equal(gcpg_circle(0, 0, 0.5, &ci, &err), G_OK);
    assert_int_equal(gcpg_combine(GSHAPE_DIFFERENCE, sq, ci, &d, &err), G_OK);
    assert_false(gcpg_inside(d, 0.1, 0.1));
    assert_true(gcpg_inside(d, 0.9, 0.9));
    GAffine2 r = gaffine2_rotate(45);
    assert_int_equal(gcpg_transform(d, &r, &err), G_OK);
    assert_true(gcpg_inside(d, 0, 1.4));    /* the square's corner turned up */
    assert_false(gcpg_inside(d, 0.9, 0.9)); /* and its old corner is now outside */
    gcpg_destroy(d);
    assert_int_equal(gcpg_circle(0, 0, 1, &outer, &err), G_OK);
    assert_int_equal(gcpg_circle(0, 0, 0.5, &inner, &err), G_OK);
    assert_int_equal(gcpg_combine(GSHAPE_INTERSECTION, outer, inner, &ring, &err), G_OK);
    assert_true(gcpg_inside(ring, 0.4, 0));
    assert_false(gcpg_inside(ring, 0.6, 0));
    gcpg_destroy(ring);
}

static void test_cpg_bad_input(void **state)
{
    (void)state;
    GError err;
    GCpgShape *s = (GCpgShape *)1;
    const double two[] = {0, 0, 1, 1};
    assert_int_equal(gcpg_polygon(two, 2, &s, &err), G_ERR_INVALID);
    assert_null(s);
    assert_non_null(strstr(err.message, "at least 3 points"));
    const double same[] = {1, 1, 1, 1, 1, 1, 2, 2};
    assert_int_equal(gcpg_polygon(same, 4, &s, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "3 distinct points"));
    const double bad[] = {0, 0, NAN, 1, 1, 1};
    assert_int_equal(gcpg_polygon(bad, 3, &s, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "not finite"));

    GCpgPath *p;
    const double xy[] = {0, 0, 1, 1, 2, 0};
    const double zero[] = {1, 0, 1}, neg[] = {1, -0.5, 1};
    assert_int_equal(gcpg_path_create(&p, &err), G_OK);
    assert_int_equal(gcpg_path_nurbs(p, 2, xy, zero, 3, NULL, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "weight 2 is 0"));
    assert_int_equal(gcpg_path_nurbs(p, 2, xy, neg, 3, NULL, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "weight 2 is -0.5"));
    const double dec[] = {0, 0, 0, 1, 0.5, 1};
    assert_int_equal(gcpg_path_nurbs(p, 2, xy, NULL, 3, dec, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "knot"));
    const double flat[] = {0, 0, 0, 0, 0, 0};
    assert_int_equal(gcpg_path_nurbs(p, 2, xy, NULL, 3, flat, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "empty domain"));
    assert_int_equal(gcpg_path_nurbs(p, 3, xy, NULL, 3, NULL, &err), G_ERR_INVALID);
    assert_int_equal(gcpg_path_bezier(p, GCPG_MAX_DEGREE + 1, xy, &err), G_ERR_INVALID);
    assert_int_equal(gcpg_path_bspline(p, 0, xy, 3, 0, &err), G_ERR_INVALID);
    /* nothing was added: closing an empty path fails */
    assert_int_equal(gcpg_path_close(p, &s, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "no edges"));
    GGenerator *g;
    assert_int_equal(ggenerator_cpg_create(NULL, &g, &err), G_ERR_INVALID);
    gcpg_path_destroy(NULL);
    gcpg_destroy(NULL);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_csg_solids),
        cmocka_unit_test(test_csg_operations_and_transforms),
        cmocka_unit_test(test_csg_bad_input),
        cmocka_unit_test(test_cpg_primitives),
        cmocka_unit_test(test_cpg_nurbs_circle_is_exact),
        cmocka_unit_test(test_cpg_bezier_edge),
        cmocka_unit_test(test_cpg_bspline_edges),
        cmocka_unit_test(test_cpg_operations),
        cmocka_unit_test(test_cpg_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
