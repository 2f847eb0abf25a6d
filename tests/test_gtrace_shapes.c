/* test_gtrace_shapes.c - the quad and triangle (Embree's own quads and triangles) and the disc: the surface
 * point at known hits (point, outward normal, (u, v), tangents dpdu x dpdv along the normal, surface index,
 * t), misses just outside, transforms, the scene text entries and their errors; and what a material's GMAT_NO_UV
 * leaves out of the surface point for every shape. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

#include <unistd.h>

typedef struct Probe {
    Scene *scene;
    GScratch *scratch;
    TraceCtx ctx;
    GSurfPoint sp;
    GVec3 facing;
    Hit hit;
} Probe;

static void probe_open(Probe *p)
{
    memset(p, 0, sizeof *p);
    p->scene = new_scene("rgb", gvec3(0, 0, 5), gvec3(0, 0, 0), 40.0);
    p->scratch = gscratch_create(0);
    p->ctx.scene = p->scene;
    p->ctx.scratch = p->scratch;
}

static void probe_close(Probe *p)
{
    scene_destroy(p->scene);
    gscratch_destroy(p->scratch);
}

static int probe_cast(Probe *p, GVec3 o, GVec3 d)
{
    GError err;
    if (!p->scene->rtc && accel_build(p->scene, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    Ray r = {o, gvec3_normalize(d), 0.0, INFINITY, 0.0, 0.001};
    Media none = {{NULL}, 0};
    if (!accel_intersect(p->scene, &r, &p->hit))
        return 0;
    /* the parametrisation is under test: a material without GMAT_NO_UV, for which it is filled (clearing the bit
     * is always correct; test_no_uv_fields in test_gtrace_shapes.c checks what the bit leaves out) */
    ((GMaterial *)p->hit.material)->flags &= ~(unsigned)GMAT_NO_UV;
    surfpoint_fill(&p->ctx, &r, &p->hit, &none, &p->sp, &p->facing);
    return 1;
}

static void assert_vec(GVec3 a, GVec3 b, double tol)
{
    assert_near(a.x, b.x, tol);
    assert_near(a.y, b.y, tol);
    assert_near(a.z, b.z, tol);
}

static void assert_tangents_outward(const Probe *p)
{
    GVec3 n = p->sp.entering ? p->facing : gvec3_neg(p->facing);
    assert_near(gvec3_dot(gvec3_normalize(gvec3_cross(p->sp.dpdu, p->sp.dpdv)), n), 1.0, 1e-9);
}

static Object *put_flat(Scene *s, ShapeKind kind, GVec3 a, GVec3 b, GVec3 c)
{
    Object *o = object_new(kind, NULL);
    o->material = lambert(s, 0.5);
    GError err;
    if (kind == SHAPE_QUAD)
        assert_int_equal(object_quad(o, a, b, c, &err), G_OK);
    else
        assert_int_equal(object_triangle(o, a, b, c, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

/* A slanted parallelogram: every hit gives p = corner + u edge1 + v edge2 with the (u, v) it reports. */
static void test_quad_surface(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    GVec3 c = gvec3(-1, -0.5, 0), e1 = gvec3(2, 0, 0.5), e2 = gvec3(0.5, 1.5, 0);
    Object *q = put_flat(p.scene, SHAPE_QUAD, c, e1, e2);
    GVec3 n = gvec3_normalize(gvec3_cross(e1, e2));
    const double uv[][2] = {{0.5, 0.5}, {0.1, 0.9}, {0.9, 0.05}, {0.02, 0.02}, {0.97, 0.96}};
    for (int i = 0; i < 5; i++) {
        GVec3 target = gvec3_madd(gvec3_madd(c, e1, uv[i][0]), e2, uv[i][1]);
        GVec3 o = gvec3_madd(target, n, 3.0);
        assert_true(probe_cast(&p, o, gvec3_neg(n)));
        assert_ptr_equal(p.hit.obj, q);
        assert_true(p.sp.entering);
        assert_near(p.sp.u, uv[i][0], 1e-5);
        assert_near(p.sp.v, uv[i][1], 1e-5);
        assert_vec(p.sp.point, target, 1e-5);
        assert_near(p.sp.t, 3.0, 1e-5);
        assert_vec(p.facing, n, 1e-12);
        assert_vec(p.sp.dpdu, e1, 1e-12);
        assert_vec(p.sp.dpdv, e2, 1e-12);
        assert_int_equal(p.sp.surface, 0);
        assert_tangents_outward(&p);
        /* from behind: the same point, leaving */
        assert_true(probe_cast(&p, gvec3_madd(target, n, -2.0), n));
        assert_false(p.sp.entering);
        assert_near(p.sp.u, uv[i][0], 1e-5);
        assert_tangents_outward(&p);
    }
    /* just outside each edge: a miss */
    const double out[][2] = {{-0.02, 0.5}, {1.02, 0.5}, {0.5, -0.02}, {0.5, 1.02}};
    for (int i = 0; i < 4; i++) {
        GVec3 target = gvec3_madd(gvec3_madd(c, e1, out[i][0]), e2, out[i][1]);
        assert_false(probe_cast(&p, gvec3_madd(target, n, 3.0), gvec3_neg(n)));
    }
    probe_close(&p);
}

/* A triangle: (u, v) are the barycentrics of b and c; the hypotenuse u + v = 1 bounds it. */
static void test_triangle_surface(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    GVec3 a = gvec3(0, 0, 0), b = gvec3(2, 0, 0), c = gvec3(0, 1, -1);
    Object *t = put_flat(p.scene, SHAPE_TRIANGLE, a, b, c);
    GVec3 e1 = gvec3_sub(b, a), e2 = gvec3_sub(c, a), n = gvec3_normalize(gvec3_cross(e1, e2));
    const double uv[][2] = {{0.25, 0.25}, {0.6, 0.3}, {0.05, 0.9}, {0.9, 0.05}};
    for (int i = 0; i < 4; i++) {
        GVec3 target = gvec3_madd(gvec3_madd(a, e1, uv[i][0]), e2, uv[i][1]);
        assert_true(probe_cast(&p, gvec3_madd(target, n, 2.0), gvec3_neg(n)));
        assert_ptr_equal(p.hit.obj, t);
        assert_near(p.sp.u, uv[i][0], 1e-5);
        assert_near(p.sp.v, uv[i][1], 1e-5);
        assert_vec(p.sp.point, target, 1e-5);
        assert_vec(p.facing, n, 1e-12);
        assert_vec(p.sp.dpdu, e1, 1e-12);
        assert_vec(p.sp.dpdv, e2, 1e-12);
        assert_int_equal(p.sp.surface, 0);
        assert_tangents_outward(&p);
    }
    GVec3 beyond = gvec3_madd(gvec3_madd(a, e1, 0.52), e2, 0.52); /* u + v = 1.04 */
    assert_false(probe_cast(&p, gvec3_madd(beyond, n, 2.0), gvec3_neg(n)));
    probe_close(&p);
}

/* Transformed: the world point, normal and tangents follow the transform; (u, v) stay the object's. */
static void test_transformed_quad(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    Object *q = put_flat(p.scene, SHAPE_QUAD, gvec3(0, 0, 0), gvec3(1, 0, 0), gvec3(0, 1, 0));
    q->has_xf = 1;
    assert_int_equal(xform_scale(&q->xf, gvec3(2, 3, 1)), G_OK);
    assert_int_equal(xform_rotate(&q->xf, gvec3(0, 1, 0), 90.0), G_OK);
    assert_int_equal(xform_translate(&q->xf, gvec3(0, 0, 1)), G_OK);
    /* object (0.25, 0.5, 0) -> scaled (0.5, 1.5, 0) -> rotated about y by 90: (0, 1.5, -0.5) -> (0, 1.5, 0.5) */
    assert_true(probe_cast(&p, gvec3(5, 1.5, 0.5), gvec3(-1, 0, 0)));
    assert_near(p.sp.u, 0.25, 1e-5);
    assert_near(p.sp.v, 0.5, 1e-5);
    assert_vec(p.sp.point, gvec3(0, 1.5, 0.5), 1e-5);
    assert_vec(p.facing, gvec3(1, 0, 0), 1e-9);
    assert_vec(p.sp.dpdu, gvec3(0, 0, -2), 1e-9);
    assert_vec(p.sp.dpdv, gvec3(0, 3, 0), 1e-9);
    assert_vec(p.sp.object_point, gvec3(0.25, 0.5, 0), 1e-5);
    probe_close(&p);
}

/* Disc: (u, v) = 0.5 + the offsets along its frame over the diameter, surface 0. */
static void test_disc_surface(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    Object *d = object_new(SHAPE_DISC, NULL);
    d->material = lambert(p.scene, 0.5);
    GError err;
    assert_int_equal(object_disc(d, gvec3(1, 2, 3), gvec3(0, 0, 2), 0.5, &err), G_OK);
    assert_int_equal(scene_add_object(p.scene, d, &err), G_OK);
    GVec3 at = gvec3_madd(gvec3_madd(gvec3(1, 2, 3), d->t1, 0.2), d->t2, -0.1);
    assert_true(probe_cast(&p, gvec3_add(at, gvec3(0, 0, 4)), gvec3(0, 0, -1)));
    assert_near(p.sp.u, 0.5 + 0.2, 1e-9);
    assert_near(p.sp.v, 0.5 - 0.1, 1e-9);
    assert_near(p.sp.t, 4.0, 1e-9);
    assert_vec(p.facing, gvec3(0, 0, 1), 1e-12);
    assert_vec(p.sp.dpdu, gvec3_scale(d->t1, 1.0), 1e-12);
    assert_int_equal(p.sp.surface, 0);
    assert_tangents_outward(&p);
    assert_false(probe_cast(&p, gvec3(1.51, 2, 7), gvec3(0, 0, -1)));
    probe_close(&p);
}

static char *write_temp(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/gtrace_shapes_%d_%s", P_tmpdir, (int)getpid(), name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return path;
}

static Scene *load_text(const char *text, GError *err)
{
    assert_int_equal(gtrace_register_types(err), G_OK);
    char *path = write_temp("scene.scene", text);
    Scene *s = NULL;
    int rc = scene_load(path, NULL, &s, err);
    unlink(path);
    return rc == G_OK ? s : NULL;
}

static void expect_error(const char *text, const char *what)
{
    GError err;
    gerror_clear(&err);
    Scene *s = load_text(text, &err);
    assert_null(s);
    print_message("%s\n", err.message);
    if (!strstr(err.message, what))
        fail_msg("expected '%s' in '%s'", what, err.message);
}

static void test_shape_entries(void **state)
{
    (void)state;
    GError err;
    Scene *s = load_text("material g lambert { }\n"
                         "object quad { corner <1, 2, 3> edge1 <0, 0, 2> edge2 <0, 4, 0> material g }\n"
                         "object triangle { a <0, 0, 0> b <1, 0, 0> c <0, 0, -1> material g }\n",
                         &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(s->nobjects, 2);
    assert_int_equal(s->objects[0]->kind, SHAPE_QUAD);
    assert_vec(s->objects[0]->center, gvec3(1, 2, 3), 0);
    assert_vec(s->objects[0]->normal, gvec3(-1, 0, 0), 1e-12);
    assert_int_equal(s->objects[1]->kind, SHAPE_TRIANGLE);
    assert_vec(s->objects[1]->t2, gvec3(0, 0, -1), 0);
    assert_vec(s->objects[1]->normal, gvec3(0, 1, 0), 1e-12);
    scene_destroy(s);
    expect_error("material g lambert { }\nobject quad { edge1 <1,0,0> edge2 <2,0,0> material g }\n", "not parallel");
    expect_error("material g lambert { }\nobject triangle { a <0,0,0> b <1,1,1> c <2,2,2> material g }\n",
                 "not on one line");
    expect_error("material g lambert { }\nobject quad { corner <0,0,0> radius 1 material g }\n", "scene.scene:2:30:");
    expect_error("material g lambert { }\nobject triangle { a <0,0,0> b <1e16,0,0> material g }\n", "beyond the scene");
    expect_error("object quad { }\n", "needs a material");
}

/* Every shape, plain and transformed, hit at random: with GMAT_NO_UV on the material the surface point is the same
 * but for its parametrisation, which stays zero; without it the parametrisation is filled. */
static void test_no_uv_fields(void **state)
{
    (void)state;
    GError err;
    Scene *s = load_text("material g lambert { }\n"
                         "object sphere { center <0, 0, 0> radius 1 material g }\n"
                         "object sphere { center <3, 0, 0> radius 1 transform { scale <1, 2, 1> rotate <0, 30, 10> } "
                         "material g }\n"
                         "object box { min <-4, -1, -1> max <-2, 1, 1> transform { rotate <20, 0, 0> } material g }\n"
                         "object cylinder { base <0, 2.5, 0> top <0, 3.5, 0> radius 1 material g }\n"
                         "object disc { center <3, 3, 0> normal <0, 0, 1> radius 1 material g }\n"
                         "object quad { corner <-4, 3, 0> edge1 <2, 0, 0> edge2 <0, 2, 0> material g }\n"
                         "object plane { point <0, -2, 0> normal <0, 1, 0> material g }\n",
                         &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(accel_build(s, &err), G_OK);
    GScratch *scratch = gscratch_create(0);
    TraceCtx ctx = {.scene = s, .scratch = scratch};
    GMaterial *g = (GMaterial *)s->objects[0]->material;
    assert_true(g->flags & GMAT_NO_UV); /* lambert's */
    unsigned long long seed = 7;
    int hits = 0, kinds = 0;
    for (int k = 0; k < 2000; k++) {
        double a[3];
        for (int i = 0; i < 3; i++) { /* test_util.h's tu_uniform; that header clashes with test_gtrace_common.h */
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            a[i] = (double)(seed >> 11) * 0x1.0p-53;
        }
        GVec3 target = gvec3(-4.5 + 8 * a[0], -2.5 + 6.5 * a[1], -0.5 + a[2]);
        GVec3 o = gvec3(0.3 * a[2], 0.5, 12), d = gvec3_normalize(gvec3_sub(target, o));
        Ray r = {o, d, 0.0, INFINITY, 0.0, 0.001};
        Media none = {{NULL}, 0};
        Hit h;
        if (!accel_intersect(s, &r, &h))
            continue;
        GSurfPoint full, bare;
        GVec3 ff, fb;
        g->flags &= ~(unsigned)GMAT_NO_UV;
        surfpoint_fill(&ctx, &r, &h, &none, &full, &ff);
        g->flags |= GMAT_NO_UV;
        surfpoint_fill(&ctx, &r, &h, &none, &bare, &fb);
        hits++;
        kinds |= 1 << h.obj->kind;
        assert_memory_equal(&full.point, &bare.point, sizeof full.point);
        assert_memory_equal(&full.object_point, &bare.object_point, sizeof full.point);
        assert_memory_equal(&full.geometric_normal, &bare.geometric_normal, sizeof full.point);
        assert_memory_equal(&ff, &fb, sizeof ff);
        assert_true(full.t == bare.t && full.footprint == bare.footprint && full.surface == bare.surface);
        assert_true(full.entering == bare.entering && full.material == bare.material);
        assert_true(full.from == bare.from && full.to == bare.to);
        assert_true(gvec3_length(full.dpdu) > 0.0 && gvec3_length(full.dpdv) > 0.0 && full.uv_footprint > 0.0);
        /* object-space tangents for a transformed object; zero (which means dpdu, dpdv) for the others */
        if (h.obj->has_xf)
            assert_true(gvec3_length(full.object_dpdu) > 0.0 && gvec3_length(full.object_dpdv) > 0.0);
        else
            assert_true(gvec3_length(full.object_dpdu) == 0.0 && gvec3_length(full.object_dpdv) == 0.0);
        const GVec3 *zero[] = {&bare.dpdu, &bare.dpdv, &bare.object_dpdu, &bare.object_dpdv};
        for (int i = 0; i < 4; i++)
            assert_true(zero[i]->x == 0.0 && zero[i]->y == 0.0 && zero[i]->z == 0.0);
        assert_true(bare.u == 0.0 && bare.v == 0.0 && bare.uv_footprint == 0.0);
        assert_true(bare.uv_axis1[0] == 0.0 && bare.uv_axis1[1] == 0.0);
        assert_true(bare.uv_axis2[0] == 0.0 && bare.uv_axis2[1] == 0.0);
    }
    print_message("%d hits, shape kinds 0x%x\n", hits, kinds);
    assert_true(hits > 1000);
    const ShapeKind want[] = {SHAPE_SPHERE, SHAPE_BOX, SHAPE_CYLINDER, SHAPE_DISC, SHAPE_QUAD, SHAPE_PLANE};
    for (int i = 0; i < 6; i++)
        assert_true(kinds & (1 << want[i]));
    gscratch_destroy(scratch);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quad_surface),     cmocka_unit_test(test_triangle_surface),
        cmocka_unit_test(test_transformed_quad), cmocka_unit_test(test_disc_surface),
        cmocka_unit_test(test_shape_entries),    cmocka_unit_test(test_no_uv_fields),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
