/* test_gtrace_direct.c - the direct list of small scenes (examples/gtrace/accel_direct.c) against Embree: random
 * scenes of every analytic shape kind, with and without transforms, opaque and glass, traced by thousands of
 * random rays each through both paths; and which scenes get the direct list. */
#include "test_gtrace_common.h"
#include "generic/builtins.h"

/* Uniform in [a, b). */
static double uni(Rng *g, double a, double b) { return a + (b - a) * rng_next(g); }

/* A uniformly random unit vector. */
static GVec3 unit(Rng *g)
{
    double z = uni(g, -1.0, 1.0), phi = uni(g, 0.0, 2.0 * M_PI), r = sqrt(fmax(0.0, 1.0 - z * z));
    return gvec3(r * cos(phi), r * sin(phi), z);
}

/* Adds an object of the given kind with random parameters around the origin. */
static Object *add_random_shape(Scene *s, Rng *g, ShapeKind kind, GMaterial *m)
{
    Object *o = object_new(kind, m);
    gmaterial_unref(m);
    GError err;
    GVec3 c = gvec3(uni(g, -3, 3), uni(g, -3, 3), uni(g, -3, 3));
    int rc = G_ERR_INVALID;
    switch (kind) {
    case SHAPE_SPHERE: rc = object_sphere(o, c, uni(g, 0.2, 1.5), &err); break;
    case SHAPE_PLANE: rc = object_plane(o, c, unit(g), &err); break;
    case SHAPE_BOX: {
        GVec3 h = gvec3(uni(g, 0.1, 1.5), uni(g, 0.1, 1.5), uni(g, 0.1, 1.5));
        rc = object_box(o, gvec3_sub(c, h), gvec3_add(c, h), &err);
        break;
    }
    case SHAPE_DISC: rc = object_disc(o, c, unit(g), uni(g, 0.2, 1.5), &err); break;
    case SHAPE_CYLINDER:
        rc = object_cylinder(o, c, gvec3_madd(c, unit(g), uni(g, 0.2, 2.5)), uni(g, 0.1, 1.0), rng_next(g) < 0.3, &err);
        break;
    default: break;
    }
    assert_int_equal(rc, G_OK);
    if (rng_next(g) < 0.5) { /* a random affine placement: non-uniform scale, rotation, translation */
        o->has_xf = 1;
        assert_int_equal(xform_scale(&o->xf, gvec3(uni(g, 0.3, 2), uni(g, 0.3, 2), uni(g, 0.3, 2))), G_OK);
        assert_int_equal(xform_rotate(&o->xf, unit(g), uni(g, 0, 360)), G_OK);
        assert_int_equal(xform_translate(&o->xf, gvec3(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1))), G_OK);
    }
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

/* A random ray: from anywhere, from inside a shape's box, at a shape, or grazing a shape's box, sometimes from a
 * point of a shape's box or parallel to an axis; tmax unlimited, large or short. */
static Ray random_ray(const Scene *s, Rng *g)
{
    Ray r = {gvec3(uni(g, -6, 6), uni(g, -6, 6), uni(g, -6, 6)), unit(g), 0.0, INFINITY, 0.0, 0.0};
    const Object *o = s->objects[(int)(rng_next(g) * s->nobjects)];
    GVec3 lo, hi;
    object_world_bounds(o, &lo, &hi);
    if (o->kind == SHAPE_PLANE) /* its bounds reach 1e5: aim at its point */
        lo = hi = o->has_xf ? xform_point(&o->xf, o->center) : o->center;
    GVec3 mid = gvec3_scale(gvec3_add(lo, hi), 0.5);
    switch ((int)(rng_next(g) * 4)) {
    case 0: break;
    case 1: /* from inside (or near) the middle of the shape */
        r.o = gvec3_madd(mid, unit(g), uni(g, 0, 0.3));
        break;
    case 2: /* at the middle from afar */
        r.d = gvec3_normalize(gvec3_sub(mid, r.o));
        break;
    default: { /* at a point on the box's surface (a face, an edge or a corner): grazing */
        GVec3 p = gvec3(uni(g, lo.x, hi.x), uni(g, lo.y, hi.y), uni(g, lo.z, hi.z));
        int axis = (int)(rng_next(g) * 3);
        double *pc = axis == 0 ? &p.x : axis == 1 ? &p.y : &p.z;
        *pc = rng_next(g) < 0.5 ? (axis == 0 ? lo.x : axis == 1 ? lo.y : lo.z) : (axis == 0 ? hi.x : axis == 1 ? hi.y : hi.z);
        if (rng_next(g) < 0.5)
            p = gvec3(rng_next(g) < 0.5 ? lo.x : hi.x, rng_next(g) < 0.5 ? lo.y : hi.y, p.z);
        GVec3 d = gvec3_sub(p, r.o);
        if (gvec3_length(d) > 1e-9)
            r.d = gvec3_normalize(d);
        break;
    }
    }
    if (rng_next(g) < 0.1) { /* from a point of the shape's box (a face, an edge or a corner) */
        r.o = gvec3(rng_next(g) < 0.5 ? lo.x : hi.x, rng_next(g) < 0.5 ? lo.y : hi.y, uni(g, lo.z, hi.z));
        if (rng_next(g) < 0.5)
            r.o.x = mid.x;
    }
    if (rng_next(g) < 0.1) { /* parallel to an axis (zero components: the slab tests' reciprocals) */
        int axis = (int)(rng_next(g) * 3);
        double sgn = rng_next(g) < 0.5 ? -1.0 : 1.0;
        r.d = gvec3(axis == 0 ? sgn : 0.0, axis == 1 ? sgn : 0.0, axis == 2 ? sgn : 0.0);
    }
    double u = rng_next(g);
    r.tmin = rng_next(g) < 0.5 ? 0.0 : 1e-4;
    r.tmax = u < 0.4 ? INFINITY : u < 0.5 ? 1e30 : uni(g, 0.0, 12.0);
    return r;
}

/* The t at which r meets o in o's own space within (tmin, tmax) by shape_intersect itself (INFINITY: none), for
 * the direct list's t to be compared bit for bit. */
static double shape_t(const Object *o, const Ray *r)
{
    GVec3 ro = r->o, rd = r->d;
    if (o->has_xf) {
        ro = xform_inv_point(&o->xf, ro);
        rd = xform_inv_vector(&o->xf, rd);
    }
    double t;
    int surface;
    return shape_intersect(o, ro, rd, r->tmin, r->tmax < 3.0e38 ? r->tmax : INFINITY, &t, &surface) ? t : INFINITY;
}

/* 1 when an opaque-everywhere shape of s lies on r (brute force over the objects). */
static int opaque_on(const Scene *s, const Ray *r)
{
    for (int i = 0; i < s->nobjects; i++)
        if (gmaterial_opaque_everywhere(s->objects[i]->material) && shape_t(s->objects[i], r) < INFINITY)
            return 1;
    return 0;
}

typedef struct Traced {
    int hit, occ;
    Hit h;
} Traced;

/* Traces the rays through the scene as built. */
static void trace_all(const Scene *s, const Ray *rays, int n, Traced *out)
{
    for (int i = 0; i < n; i++) {
        out[i].hit = accel_intersect(s, &rays[i], &out[i].h);
        out[i].occ = accel_occluded(s, &rays[i]);
    }
}

/* Many random small scenes: the direct list gives Embree's hit (object, t to 1e-9 relative, surface) and a
 * consistent occlusion for every ray. */
static void test_direct_matches_embree(void **state)
{
    (void)state;
    enum { SCENES = 200, RAYS = 4000 };
    const ShapeKind kinds[] = {SHAPE_SPHERE, SHAPE_PLANE, SHAPE_BOX, SHAPE_DISC, SHAPE_CYLINDER};
    Rng g;
    rng_seed(&g, 20261202u, 7u);
    Ray *rays = calloc(RAYS, sizeof *rays);
    Traced *d = calloc(RAYS, sizeof *d), *e = calloc(RAYS, sizeof *e);
    assert_non_null(rays);
    assert_non_null(d);
    assert_non_null(e);
    long hits = 0, passable = 0, opaque = 0, ties = 0, total = 0;
    for (int sc = 0; sc < SCENES; sc++) {
        Scene *s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
        int n = 1 + (int)(rng_next(&g) * ACCEL_DIRECT_MAX);
        for (int i = 0; i < n; i++) {
            ShapeKind k = kinds[(int)(rng_next(&g) * 5)];
            if (k == SHAPE_PLANE && rng_next(&g) < 0.5) /* fewer planes: they hide everything behind them */
                k = SHAPE_SPHERE;
            add_random_shape(s, &g, k, rng_next(&g) < 0.5 ? lambert(s, 0.5) : glass(s, 1.5));
        }
        for (int i = 0; i < RAYS; i++)
            rays[i] = random_ray(s, &g);
        GError err;
        assert_int_equal(accel_build(s, &err), G_OK);
        assert_int_equal(accel_uses_direct(s), 1);
        trace_all(s, rays, RAYS, d);
        s->accel_embree_only = 1;
        assert_int_equal(accel_build(s, &err), G_OK);
        assert_int_equal(accel_uses_direct(s), 0);
        trace_all(s, rays, RAYS, e);
        for (int i = 0; i < RAYS; i++) {
            const Traced *a = &d[i], *b = &e[i];
            total++;
            if (a->hit != b->hit || (a->hit && a->h.obj != b->h.obj)) {
                /* a near tie (accel_direct.c): two shapes within Embree's float rounding of each other */
                double ta = a->hit ? a->h.t : INFINITY, tb = b->hit ? b->h.t : INFINITY;
                if (a->hit && b->hit && fabs(ta - tb) <= 1e-6 * fmax(1.0, fabs(tb))) {
                    ties++;
                    continue;
                }
                fail_msg("scene %d ray %d: direct hit %d t %.17g, Embree hit %d t %.17g", sc, i, a->hit, ta, b->hit, tb);
            }
            if (a->hit) {
                hits++;
                assert_null(a->h.inst);
                assert_ptr_equal(a->h.material, b->h.material);
                assert_int_equal(a->h.surface, b->h.surface);
                assert_int_equal(a->h.prim, b->h.prim);
                assert_near(a->h.t, b->h.t, 1e-9 * fmax(1.0, fabs(b->h.t)));
                double ts = shape_t(a->h.obj, &rays[i]); /* bit for bit, the inline sphere and plane included */
                if (a->h.t != ts)
                    fail_msg("scene %d ray %d: direct t %.17g, shape_intersect %.17g", sc, i, a->h.t, ts);
            }
            if ((a->occ == OCCLUDED_CLEAR) != (b->occ == OCCLUDED_CLEAR))
                fail_msg("scene %d ray %d: direct occlusion %d, Embree %d", sc, i, a->occ, b->occ);
            if (b->occ == OCCLUDED_OPAQUE)
                assert_int_equal(a->occ, OCCLUDED_OPAQUE);
            if (a->occ == OCCLUDED_PASSABLE) {
                passable++;
                assert_false(opaque_on(s, &rays[i]));
            }
            opaque += a->occ == OCCLUDED_OPAQUE;
        }
        scene_destroy(s);
    }
    print_message("%ld rays: %ld hits, %ld opaque, %ld passable, %ld near ties\n", total, hits, opaque, passable, ties);
    assert_true(hits > total / 4);
    assert_true(passable > total / 50 && opaque > total / 20);
    assert_true(ties <= total / 10000);
    free(rays);
    free(d);
    free(e);
}

/* A ray that is not finite hits nothing on either path (accel.c's traceable). */
static void test_direct_untraceable(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    add_sphere(s, lambert(s, 0.5), gvec3(0, 0, 0), 1.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, -1, 0), gvec3(0, 1, 0));
    GError err;
    for (int embree = 0; embree < 2; embree++) {
        s->accel_embree_only = embree;
        assert_int_equal(accel_build(s, &err), G_OK);
        assert_int_equal(accel_uses_direct(s), !embree);
        Ray bad[] = {{gvec3(NAN, 0, 5), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, INFINITY, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, 0, -1), -1.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, 0, -1), 2.0, 1.0, 0.0, 0.0},
                     /* each of the six components beyond 1e18, or not a number */
                     {gvec3(0, -1e18, 5), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 2e18), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(-1e19, 0, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, 0, NAN), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(-INFINITY, 0, 5), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, 0, -1), NAN, INFINITY, 0.0, 0.0},
                     {gvec3(0, 0, 5), gvec3(0, 0, -1), 3.5e38, INFINITY, 0.0, 0.0}};
        for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
            Hit h;
            assert_int_equal(accel_intersect(s, &bad[i], &h), 0);
            assert_int_equal(accel_occluded(s, &bad[i]), OCCLUDED_CLEAR);
        }
        Ray good = {gvec3(0, 0, 5), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0};
        Hit h;
        assert_int_equal(accel_intersect(s, &good, &h), 1);
        assert_near(h.t, 4.0, 1e-12);
        assert_int_equal(accel_occluded(s, &good), OCCLUDED_OPAQUE);
        /* just below the limit (the direct list finds the sphere; Embree's float ray may not), and a NaN tmax
         * (not below tmin; unlimited as infinity): traced */
        Ray near_big = {gvec3(0, 0, 9.9e17), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0};
        if (!embree)
            assert_int_equal(accel_intersect(s, &near_big, &h), 1);
        Ray nan_tmax = {gvec3(0, 0, 5), gvec3(0, 0, -1), 0.0, NAN, 0.0, 0.0};
        assert_int_equal(accel_intersect(s, &nan_tmax, &h), 1);
        assert_near(h.t, 4.0, 1e-12);
    }
    scene_destroy(s);
}

/* Adds n spheres in a row. */
static void add_spheres(Scene *s, int n)
{
    for (int i = 0; i < n; i++)
        add_sphere(s, lambert(s, 0.5), gvec3(2.0 * i, 0, 0), 0.5);
}

/* Which scenes get the direct list: at most ACCEL_DIRECT_MAX analytic shapes, nothing of Embree's own, no
 * groups, not accel_embree_only. */
static void test_direct_threshold(void **state)
{
    (void)state;
    GError err;
    Scene *s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    add_spheres(s, ACCEL_DIRECT_MAX);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(accel_uses_direct(s), 1);
    assert_int_equal(s->ndirect, ACCEL_DIRECT_MAX);
    add_spheres(s, 1); /* one above the threshold */
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(accel_uses_direct(s), 0);
    scene_destroy(s);

    /* a triangle (Embree's own) among few shapes */
    s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    add_spheres(s, 2);
    Object *t = object_new(SHAPE_TRIANGLE, NULL);
    assert_int_equal(object_triangle(t, gvec3(-1, -1, 3), gvec3(1, -1, 3), gvec3(0, 1, 3), &err), G_OK);
    assert_int_equal(scene_add_object(s, t, &err), G_OK);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(accel_uses_direct(s), 0);
    scene_destroy(s);

    /* a group of two spheres: Embree (the group's prototype and its placement) */
    s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    Object *m[2];
    m[0] = add_sphere(s, lambert(s, 0.5), gvec3(0, 0, 0), 0.5);
    m[1] = add_sphere(s, lambert(s, 0.5), gvec3(2, 0, 0), 0.5);
    Object *grp = object_new(SHAPE_GROUP, NULL);
    assert_int_equal(object_group(grp, m, 2, &err), G_OK);
    assert_int_equal(scene_add_object(s, grp, &err), G_OK);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(accel_uses_direct(s), 0);
    Ray r = {gvec3(2, 0, 5), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0};
    Hit h;
    assert_int_equal(accel_intersect(s, &r, &h), 1);
    assert_ptr_equal(h.obj, m[1]);
    assert_non_null(h.inst);
    scene_destroy(s);

    /* an empty scene: the direct list, which hits nothing */
    s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(accel_uses_direct(s), 1);
    assert_int_equal(accel_intersect(s, &r, &h), 0);
    assert_int_equal(accel_occluded(s, &r), OCCLUDED_CLEAR);
    accel_release(s);
    assert_int_equal(accel_uses_direct(s), 0);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_direct_matches_embree),
        cmocka_unit_test(test_direct_untraceable),
        cmocka_unit_test(test_direct_threshold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
