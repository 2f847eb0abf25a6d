/* test_gtrace_instances.c - groups and instances: an instance renders like the object placed by hand (pixel
 * comparison, for analytic shapes, Embree quads and meshes, through nested groups and instances with composed
 * transforms), the material override, prototypes that are not rendered where they are defined, prototype
 * scenes shared by every placement, and the limits on generated hostile inputs (exponential expansion, deep
 * nesting) refused with a clear message at the entry that crosses them. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

#include <time.h>
#include <unistd.h>

static char *write_temp(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "%s/gtrace_inst_%d_%s", P_tmpdir, (int)getpid(), name);
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

static const char *common =
    "colormodel rgb\n"
    "material grey lambert { reflectance rgb 0.6 0.6 0.6 }\n"
    "material red lambert { reflectance rgb 0.8 0.1 0.1 }\n"
    "camera pinhole { from <0.5, 2, 6> at <0, 0.5, 0> fov 40 }\n"
    "light point { position <3, 6, 4> intensity rgb 40 40 40 }\n"
    "light background { color rgb 0.1 0.1 0.1 }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material grey }\n";

/* Renders common + body at 96x64 into fb (the caller frees it); fails with the message on error. */
static void render_text(const char *body, Framebuffer *fb)
{
    size_t n = strlen(common) + strlen(body) + 1;
    char *text = malloc(n);
    assert_non_null(text);
    snprintf(text, n, "%s%s", common, body);
    GError err;
    gerror_clear(&err);
    Scene *s = load_text(text, &err);
    free(text);
    if (!s)
        fail_msg("%s", err.message);
    render(s, 96, 64, 1, 3, fb);
    scene_destroy(s);
}

/* Largest difference of any channel of any pixel, and the fraction of pixels differing by more than tol. */
static double compare(const Framebuffer *a, const Framebuffer *b, double tol, double *frac)
{
    double worst = 0.0;
    int bad = 0, n = a->width * a->height;
    for (int i = 0; i < n; i++) {
        double d = 0.0;
        for (int c = 0; c < 3; c++)
            d = fmax(d, fabs(a->pixels[3 * i + c] - b->pixels[3 * i + c]));
        worst = fmax(worst, d);
        bad += d > tol;
    }
    *frac = (double)bad / n;
    return worst;
}

/* the image of by_hand and of placed, which must differ from the image without the object */
static void expect_same(const char *by_hand, const char *placed, double tol, double max_frac)
{
    Framebuffer a = {0}, b = {0}, none = {0};
    render_text(by_hand, &a);
    render_text(placed, &b);
    render_text("", &none);
    double frac, frac_none;
    double worst = compare(&a, &b, tol, &frac);
    compare(&a, &none, tol, &frac_none);
    print_message("largest difference %.3g, %.4f %% of pixels beyond %g (the object covers %.1f %%)\n", worst,
                  100 * frac, tol, 100 * frac_none);
    assert_true(frac_none > 0.01); /* the object is in the picture */
    assert_true(frac <= max_frac);
    framebuffer_free(&a);
    framebuffer_free(&b);
    framebuffer_free(&none);
}

static void test_instance_like_by_hand(void **state)
{
    (void)state;
    /* an analytic sphere: intersected in double precision through the placement's own transform */
    expect_same(
        "object sphere { center <0.2, 0.5, 0> radius 0.5 material red transform { scale <1, 1.5, 1> "
        "rotate <0, 0, 20> translate <0.3, 0.1, 0> } }\n",
        "object ball sphere { center <0.2, 0.5, 0> radius 0.5 material red }\n"
        "object instance { of ball transform { scale <1, 1.5, 1> rotate <0, 0, 20> translate <0.3, 0.1, 0> } }\n",
        1e-4, 0.0);
    /* a box and a quad in a group, placed by an instance with a material override */
    expect_same("object box { min <-0.5, 0, -0.5> max <0.5, 1, 0.5> material red transform { rotate <0, 35, 0> "
                "translate <-0.6, 0, 0> } }\n"
                "object quad { corner <0.6, 0, 0.5> edge1 <0.8, 0, 0> edge2 <0, 1, 0> material red "
                "transform { rotate <0, 35, 0> translate <-0.6, 0, 0> } }\n",
                "object thing group { box { min <-0.5, 0, -0.5> max <0.5, 1, 0.5> material grey }\n"
                "    quad { corner <0.6, 0, 0.5> edge1 <0.8, 0, 0> edge2 <0, 1, 0> material grey } }\n"
                "object instance { of thing material red transform { rotate <0, 35, 0> translate <-0.6, 0, 0> } }\n",
                1e-3, 0.003);
    /* nested: an instance of a group holding an instance of a group; the transforms compose inner first */
    expect_same("object cylinder { base <0, 0, 0> top <0, 0.8, 0> radius 0.2 material red "
                "transform { translate <0.5, 0, 0> rotate <0, 90, 0> translate <0, 0, 0.3> } }\n"
                "object sphere { center <0, 0.3, 0> radius 0.3 material red transform { translate <0, 0, 0.3> } }\n",
                "object post group { cylinder { base <0, 0, 0> top <0, 0.8, 0> radius 0.2 material red } }\n"
                "object pair group { sphere { center <0, 0.3, 0> radius 0.3 material red }\n"
                "    instance { of post transform { translate <0.5, 0, 0> rotate <0, 90, 0> } } }\n"
                "object instance { of pair transform { translate <0, 0, 0.3> } }\n",
                1e-4, 0.0);
}

static void test_mesh_instance(void **state)
{
    (void)state;
    char *obj = write_temp("tri.obj", "v -0.5 0 0\nv 0.5 0 0\nv 0 1 0\nv 0 0.5 -0.5\nf 1 2 3\nf 1 3 4\nf 2 4 3\n");
    char a[1024], b[1024];
    snprintf(a, sizeof a, "object mesh { file \"%s\" material red transform { scale 1.5 translate <0.2, 0, 0.5> } }\n",
             obj);
    snprintf(b, sizeof b, "object m mesh { file \"%s\" material red }\n"
             "object instance { of m transform { scale 1.5 translate <0.2, 0, 0.5> } }\n", obj);
    expect_same(a, b, 1e-3, 0.003);
    unlink(obj);
}

/* A prototype is not rendered where it is defined; every placement shares one prototype scene. */
static void test_prototypes(void **state)
{
    (void)state;
    Framebuffer a = {0}, none = {0};
    render_text("object ball sphere { center <0, 0.5, 0> radius 0.5 material red }\n"
                "object instance { of ball transform { translate <0, -10, 0> } }\n", &a); /* out of sight */
    render_text("", &none);
    double frac;
    assert_near(compare(&a, &none, 0.0, &frac), 0.0, 0.0);
    framebuffer_free(&a);
    framebuffer_free(&none);
    GError err;
    Scene *s = load_text("material m lambert { }\n"
                         "object ball sphere { material m }\n"
                         "object row group { instance { of ball transform { translate <-2, 0, 0> } }\n"
                         "                   instance { of ball transform { translate <2, 0, 0> } } }\n"
                         "object square group { instance { of row transform { translate <0, 2, 0> } }\n"
                         "                      instance { of row transform { translate <0, -2, 0> } } }\n",
                         &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(s->nprotos, 1); /* the ball's scene, built once */
    assert_int_equal((int)s->ninstances, 4);
    /* the four placements, each hit at its own place with the composed transform */
    TraceCtx ctx = {0};
    ctx.scene = s;
    ctx.scratch = gscratch_create(0);
    const GVec3 at[] = {{-2, 2, 0}, {2, 2, 0}, {-2, -2, 0}, {2, -2, 0}};
    for (int i = 0; i < 4; i++) {
        Ray r = {gvec3_add(at[i], gvec3(0.3, 0.2, 5)), gvec3(0, 0, -1), 0.0, INFINITY, 0.0, 0.0};
        Hit h;
        assert_true(accel_intersect(s, &r, &h));
        assert_non_null(h.inst);
        assert_ptr_equal(h.obj, s->objects[0]);
        assert_near(h.t, 5.0 - sqrt(1.0 - 0.09 - 0.04), 1e-9);
        GSurfPoint sp;
        GVec3 facing;
        Media none = {{NULL}, 0};
        surfpoint_fill(&ctx, &r, &h, &none, &sp, &facing);
        assert_near(sp.point.x, at[i].x + 0.3, 1e-9);
        assert_near(facing.x, 0.3, 1e-9);
        assert_near(sp.object_point.x, 0.3, 1e-9);
    }
    gscratch_destroy(ctx.scratch);
    scene_destroy(s);
}

static void expect_error(const char *text, const char *what)
{
    GError err;
    gerror_clear(&err);
    Scene *s = load_text(text, &err);
    if (s) {
        int rc = accel_build(s, &err);
        scene_destroy(s);
        assert_int_not_equal(rc, G_OK);
    }
    print_message("%s\n", err.message);
    if (!strstr(err.message, what))
        fail_msg("expected '%s' in '%s'", what, err.message);
}

/* Generated hostile inputs: each level places the previous one twice (2^k placements), or once (depth k). */
static char *doubling_scene(int levels, int fan)
{
    size_t cap = 256 + (size_t)levels * (size_t)fan * 96;
    char *t = malloc(cap);
    assert_non_null(t);
    size_t n = (size_t)snprintf(t, cap, "material m lambert { }\nobject g0 group { sphere { material m } }\n");
    for (int k = 1; k <= levels; k++) {
        n += (size_t)snprintf(t + n, cap - n, "object g%d group {", k);
        for (int j = 0; j < fan; j++)
            n += (size_t)snprintf(t + n, cap - n, " instance { of g%d transform { translate <%d, 0, 0> } }", k - 1, j);
        n += (size_t)snprintf(t + n, cap - n, " }\n");
    }
    return t;
}

static void test_limits(void **state)
{
    (void)state;
    /* 2^k placements: fine up to the limit, refused beyond it at the entry that crosses it */
    for (int k = 1; k <= 40; k += 3) {
        char *t = doubling_scene(k, 2);
        GError err;
        gerror_clear(&err);
        clock_t t0 = clock();
        Scene *s = load_text(t, &err);
        int rc = s ? accel_build(s, &err) : -1;
        double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
        double expansion = ldexp(1.0, k);
        if (expansion <= GTRACE_MAX_INSTANCES) {
            if (rc != G_OK)
                fail_msg("%d levels: %s", k, err.message);
            assert_int_equal((int)s->ninstances, (int)expansion);
        } else {
            assert_null(s);
            char line[32];
            snprintf(line, sizeof line, ":%d:", 2 + 17); /* g17 is the first beyond 100000 */
            print_message("%d levels (%.3g placements) in %.2f s: %s\n", k, expansion, secs, err.message);
            assert_non_null(strstr(err.message, "placements, more than the limit of 100000"));
            assert_non_null(strstr(err.message, line));
        }
        assert_true(secs < 10.0);
        scene_destroy(s);
        free(t);
    }
    /* a wide fan: 400 placements of 400 placements of a sphere */
    char *t = doubling_scene(2, 400);
    expect_error(t, "expands to 160000 placements");
    free(t);
    /* a long chain: instance of instance of ... */
    size_t cap = 64 + 70 * 64;
    t = malloc(cap);
    assert_non_null(t);
    size_t n = (size_t)snprintf(t, cap, "material m lambert { }\nobject i0 sphere { material m }\n");
    for (int k = 1; k <= 70; k++)
        n += (size_t)snprintf(t + n, cap - n, "object i%d instance { of i%d }\n", k, k - 1);
    expect_error(t, "scene.scene:67:");
    expect_error(t, "nest 65 deep here, more than the limit of 64");
    free(t);
    /* several top-level placements that are each fine but too many together */
    t = doubling_scene(16, 2);
    cap = strlen(t) + 128;
    t = realloc(t, cap);
    assert_non_null(t);
    strcat(t, "object instance { of g16 }\nobject instance { of g16 transform { translate <0, 5, 0> } }\n");
    expect_error(t, "expand to 131072 placements, more than the limit");
    free(t);
    /* other mistakes */
    expect_error("object g group { }\n", "needs at least one object");
    expect_error("object instance { }\n", "needs the object it places");
    expect_error("material m lambert { }\nobject instance { of nothing }\n", "scene.scene:2:22:");
    expect_error("material m lambert { }\nobject instance { of m }\n", "scene.scene:2:22:");
    expect_error("material m lambert { }\nobject b sphere { material m }\n"
                 "object instance { of b transform { translate <2e15, 0, 0> } }\n", "beyond the scene's limit");
    /* placements a float cannot carry: a tiny quad scaled up by 1e40, a sphere scaled down by 1e-20 */
    expect_error("material m lambert { }\nobject q quad { edge1 <1e-50, 0, 0> edge2 <0, 1e-50, 0> material m }\n"
                 "object instance { of q transform { scale 1e40 } }\n", "beyond 1e30");
    expect_error("material m lambert { }\nobject b sphere { material m }\n"
                 "object instance { of b transform { scale 1e-20 } }\n", "singular");
}

/* Shapes and placements are charged against the memory budget as their entries are read, the placements a group or
 * an instance takes over counted once, all returned when the scene is freed; a budget that an entry would cross
 * refuses the scene at that entry. */
static void test_memory_budget(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text, "%s"
             "object b sphere { material red }\n"
             "object g group { b instance { of b transform { translate <1, 0, 0> } } }\n"
             "object instance { of g }\n"
             "object instance { of g transform { translate <0, 2, 0> } }\n"
             "object instance { of g transform { translate <0, 4, 0> } }\n", common);
    GError err;
    size_t base = gmem_budget_used();
    Scene *s = load_text(text, &err);
    assert_non_null(s);
    /* the plane and b: a share of the acceleration structure each; g's 2 placements (b's group and the nested
     * instance, which it took over) taken over by each of the 3 instances; the file's text, kept for `like` (it
     * defines named entries) */
    size_t want = 2 * OBJECT_SHAPE_ACCEL_BYTES + 3 * 2 * OBJECT_PLACEMENT_BYTES + strlen(text) + 1;
    assert_int_equal(gmem_budget_used() - base, want);
    assert_int_equal(accel_build(s, &err), G_OK);
    assert_int_equal(s->ninstances, 6);
    scene_destroy(s);
    assert_int_equal(gmem_budget_used(), base);
    /* room for all but the last instance: refused at its entry (line 12 of the file), the budget named */
    gmem_budget_set_limit(base + want - 1);
    s = load_text(text, &err);
    assert_null(s);
    print_message("%s\n", err.message);
    assert_non_null(strstr(err.message, "scene.scene:12:"));
    assert_non_null(strstr(err.message, "an instance of 2 placements needs 2.0 KiB, over the memory budget"));
    assert_int_equal(gmem_budget_used(), base);
    gmem_budget_set_limit(0);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_instance_like_by_hand), cmocka_unit_test(test_mesh_instance),
        cmocka_unit_test(test_prototypes),            cmocka_unit_test(test_limits),
        cmocka_unit_test(test_memory_budget),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
