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
        *pc = rng_next(g) < 0.5 ? (axis == 0   ? lo.x
                                   : axis == 1 ? lo.y
                                               : lo.z)
                                : (axis == 0   ? hi.x
                                   : axis == 1 ? hi.y
                                               : hi.z);
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
                fail_msg("scene %d ray %d: direct hit %d t %.17g, Embree hit %d t %.17g", sc, i, a->hit, ta, b->hit,
                         tb);
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

/* A sphere's t in (tmin, tmax) by the quadratic and nothing else (shape_solve_quadratic, shape_pick): the reference
 * for shape_hit_sphere's early miss (INFINITY: none). */
static double ref_sphere(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax)
{
    GVec3 oc = gvec3_sub(ro, o->center);
    double t0, t1, t;
    if (!shape_solve_quadratic(gvec3_dot(rd, rd), gvec3_dot(oc, rd), gvec3_dot(oc, oc) - o->radius * o->radius, &t0,
                               &t1))
        return INFINITY;
    return shape_pick(t0, t1, tmin, tmax, &t) ? t : INFINITY;
}

/* A plane's t in (tmin, tmax) by the division and nothing else: the reference for shape_hit_plane's early miss. */
static double ref_plane(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax)
{
    double dn = gvec3_dot(rd, o->normal);
    if (dn == 0.0)
        return INFINITY;
    double th = gvec3_dot(gvec3_sub(o->center, ro), o->normal) / dn;
    if (!(th > tmin && th < tmax))
        return INFINITY;
    GVec3 d = gvec3_sub(gvec3_madd(ro, rd, th), o->center);
    if (fabs(gvec3_dot(d, o->t1)) > SHAPE_PLANE_EXTENT || fabs(gvec3_dot(d, o->t2)) > SHAPE_PLANE_EXTENT)
        return INFINITY;
    return th;
}

/* The same double, a NaN equal to a NaN. */
static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* A ray at o of the kinds where an early miss could differ from the arithmetic: from a point of its surface (and
 * just off it, both sides) outward, inward, along it (grazing) or anywhere; from the centre, from afar; with zero,
 * tiny, huge, infinite and NaN components. */
static void edge_ray(const Object *o, Rng *g, GVec3 *ro, GVec3 *rd)
{
    GVec3 n = o->kind == SHAPE_SPHERE ? unit(g) : o->normal;
    double rad = o->kind == SHAPE_SPHERE ? o->radius : 0.0;
    GVec3 tang = gvec3_normalize(gvec3_cross(n, fabs(n.x) < 0.9 ? gvec3(1, 0, 0) : gvec3(0, 1, 0)));
    if (o->kind == SHAPE_PLANE)
        tang = gvec3_madd(gvec3_scale(o->t1, uni(g, -1, 1)), o->t2, uni(g, -1, 1));
    const double offs[] = {0.0, 0.0, 1e-12, -1e-12, 1e-300, -1e-300, 1e-7, -1e-7, 1.0, -0.5};
    *ro = gvec3_madd(gvec3_madd(o->center, tang, o->kind == SHAPE_PLANE ? uni(g, -5, 5) : 0.0), n,
                     rad + offs[(int)(rng_next(g) * 10)]);
    switch ((int)(rng_next(g) * 6)) {
    case 0: *rd = n; break;
    case 1: *rd = gvec3_scale(n, -1.0); break;
    case 2: *rd = gvec3_normalize(gvec3_madd(tang, n, uni(g, -1e-9, 1e-9))); break; /* grazing */
    case 3: *rd = tang; break;
    default: *rd = unit(g); break;
    }
    if (rng_next(g) < 0.1)
        *ro = o->center;
    if (rng_next(g) < 0.1)
        *ro = gvec3_madd(o->center, unit(g), uni(g, 1e3, 1e15));
    if (rng_next(g) < 0.2) {
        const double odd[] = {0.0, -0.0, 1e-310, -1e-310, 1e300, -1e300, INFINITY, -INFINITY, NAN, 1e18};
        double v = odd[(int)(rng_next(g) * 10)];
        double *c = (int)(rng_next(g) * 2) ? (double *)rd : (double *)ro;
        c[(int)(rng_next(g) * 3)] = v;
    }
    if (rng_next(g) < 0.1)
        *rd = gvec3_scale(*rd, rng_next(g) < 0.5 ? 1e-160 : 1e150);
}

/* shape_hit_sphere and shape_hit_plane miss early (no square root, no division) only where the arithmetic misses
 * too: for any ray, tmin >= 0 and tmax (infinite, finite, NaN), the same answer and the same t, bit for bit, as
 * the quadratic and the division alone. */
static void test_direct_early_miss(void **state)
{
    (void)state;
    Rng g;
    rng_seed(&g, 20261202u, 11u);
    Scene *s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
    Object *sp = add_sphere(s, lambert(s, 0.5), gvec3(0.3, -0.2, 0.1), 0.7);
    Object *pl = add_plane(s, lambert(s, 0.5), gvec3(0.2, -1, 0.3), gvec3(0, 1, 0));
    Object *tilted = add_plane(s, lambert(s, 0.5), gvec3(0.1, 0.2, -2), gvec3_normalize(gvec3(1, 2, 3)));
    const Object *shapes[] = {sp, pl, tilted};
    const double tmins[] = {0.0, 1e-4, 1e-12, 5e-324, 2.0};
    const double tmaxs[] = {INFINITY, 1e30, 3.0, 1e-6, NAN, 0.0};
    long hits = 0, early = 0;
    for (int i = 0; i < 300000; i++) {
        const Object *o = shapes[i % 3];
        GVec3 ro, rd;
        edge_ray(o, &g, &ro, &rd);
        double tmin = tmins[(int)(rng_next(&g) * 5)], tmax = tmaxs[(int)(rng_next(&g) * 6)];
        double t = -1.0, want;
        int hit;
        if (o->kind == SHAPE_SPHERE) {
            hit = shape_hit_sphere(o, ro, rd, tmin, tmax, &t);
            want = ref_sphere(o, ro, rd, tmin, tmax);
            GVec3 oc = gvec3_sub(ro, o->center);
            early += gvec3_dot(oc, rd) > 0.0 && gvec3_dot(oc, oc) - o->radius * o->radius >= 0.0;
        } else {
            hit = shape_hit_plane(o, ro, rd, tmin, tmax, &t);
            want = ref_plane(o, ro, rd, tmin, tmax);
        }
        if (hit != (want != INFINITY) || (hit && !same_bits(t, want)))
            fail_msg("ray %d (%s): o <%.17g %.17g %.17g> d <%.17g %.17g %.17g> (%g, %g): hit %d t %.17g, want %.17g", i,
                     o->kind == SHAPE_SPHERE ? "sphere" : "plane", ro.x, ro.y, ro.z, rd.x, rd.y, rd.z, tmin, tmax, hit,
                     t, want);
        hits += hit;
    }
    print_message("%ld hits, %ld early sphere misses\n", hits, early);
    assert_true(hits > 20000 && early > 20000);
    scene_destroy(s);
}

/* Rays from a sphere's or a plane's surface (and just off it), grazing ones, rays along an axis, tmax infinite,
 * large and short, through the direct list of one shape: the hit and its t bit for bit, and the occlusion, as the
 * quadratic and the division alone give them. */
static void test_direct_surface_rays(void **state)
{
    (void)state;
    Rng g;
    rng_seed(&g, 20261202u, 13u);
    for (int kind = 0; kind < 2; kind++) {
        Scene *s = new_scene("rgb", gvec3(0, 0, 10), gvec3(0, 0, 0), 40.0);
        Object *o = kind == 0 ? add_sphere(s, lambert(s, 0.5), gvec3(0.3, -0.2, 0.1), 0.7)
                              : add_plane(s, lambert(s, 0.5), gvec3(0.2, -1, 0.3), gvec3(0, 1, 0));
        GError err;
        assert_int_equal(accel_build(s, &err), G_OK);
        assert_int_equal(accel_uses_direct(s), 1);
        long hits = 0;
        for (int i = 0; i < 100000; i++) {
            GVec3 ro, rd;
            edge_ray(o, &g, &ro, &rd);
            if (!(fabs(ro.x) + fabs(ro.y) + fabs(ro.z) < 100.0 && gvec3_length(rd) > 1e-3 && gvec3_length(rd) < 1e3))
                continue; /* near the shape (its box is met wherever it is), traceable */
            if (rng_next(&g) < 0.1) {
                int axis = (int)(rng_next(&g) * 3);
                rd = gvec3(axis == 0 ? 1.0 : 0.0, axis == 1 ? -1.0 : 0.0, axis == 2 ? 1.0 : 0.0);
            }
            double u = rng_next(&g);
            Ray r = {ro, rd, rng_next(&g) < 0.5 ? 0.0 : 1e-4, u < 0.4 ? INFINITY : u < 0.5 ? 1e30 : uni(&g, 0, 3), 0.0,
                     0.0};
            double tmax = r.tmax < 3.0e38 ? r.tmax : INFINITY;
            double want = kind == 0 ? ref_sphere(o, ro, rd, r.tmin, tmax) : ref_plane(o, ro, rd, r.tmin, tmax);
            Hit h;
            int hit = accel_intersect(s, &r, &h);
            if (hit != (want != INFINITY) || (hit && !same_bits(h.t, want)))
                fail_msg("%s ray %d: hit %d t %.17g, want %.17g", kind == 0 ? "sphere" : "plane", i, hit,
                         hit ? h.t : 0.0, want);
            double wocc = kind == 0 ? ref_sphere(o, ro, rd, r.tmin, r.tmax) : ref_plane(o, ro, rd, r.tmin, r.tmax);
            assert_int_equal(accel_occluded(s, &r), wocc != INFINITY ? OCCLUDED_OPAQUE : OCCLUDED_CLEAR);
            hits += hit;
        }
        print_message("%s: %ld hits\n", kind == 0 ? "sphere" : "plane", hits);
        assert_true(hits > (kind == 0 ? 20000 : 5000));
        scene_destroy(s);
    }
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
        cmocka_unit_test(test_direct_early_miss),
        cmocka_unit_test(test_direct_surface_rays),
        cmocka_unit_test(test_direct_threshold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
