/* test_gtrace_emissive.c - glowing geometry as light (examples/gtrace/lights/emissive.c): an emitter quad lights a
 * floor as a `light rectangle` of the same radiance and size does (patch means within 1%, per-pixel noise at equal
 * samples within 1.1x), an emitter sphere as a `light sphere`, in the path tracer; an emissive mesh of 3200
 * triangles converges to the material-sampling-only estimate at 16x the samples (within 1.5%) and equals a
 * rectangle light of its size (0.5%); the Whitted tracer lights a floor
 * with an emitter quad as with the rectangle light; the alias table chooses primitives by power. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"
#include "lights/emissive.h"

#define W 32
#define H 32

static void render_as(Scene *s, int spp, int integrator, int no_emissive, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = W, .height = H, .spp = spp, .depth = 4, .threads = 2, .quiet = 1,
                         .integrator = integrator, .no_emissive_lights = no_emissive};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

static double mean_luma(const Framebuffer *fb)
{
    double sum = 0.0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            sum += luma(pixel(fb, x, y));
    return sum / (W * H);
}

/* The root mean square of the per-pixel difference of a and a reference. */
static double rms_error(const Framebuffer *a, const Framebuffer *ref)
{
    double sum = 0.0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double d = luma(pixel(a, x, y)) - luma(pixel(ref, x, y));
            sum += d * d;
        }
    return sqrt(sum / (W * H));
}

/* A grey floor seen from above and aside, the light (out of view) 1.5 above it facing down. */
static Scene *floor_scene(void)
{
    Scene *s = new_scene("rgb", gvec3(0, 2.0, 4.0), gvec3(0, 0, 0.5), 40);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    return s;
}

static const GVec3 CORNER = {-0.5, 1.5, -0.5}, EDGE1 = {1, 0, 0}, EDGE2 = {0, 0, 1}; /* edge1 x edge2 points down */

static Scene *quad_emitter_scene(void)
{
    Scene *s = floor_scene();
    Object *o = object_new(SHAPE_QUAD, emitter(s, 4.0));
    gmaterial_unref(o->material);
    GError err;
    assert_int_equal(object_quad(o, CORNER, EDGE1, EDGE2, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return s;
}

static Scene *rect_light_scene(void)
{
    Scene *s = floor_scene();
    Light *l = add_light(s, LIGHT_RECT, 4.0);
    l->position = CORNER;
    l->edge1 = EDGE1;
    l->edge2 = EDGE2;
    l->samples = 16;
    return s;
}

static void test_quad_equals_rectangle(void **state)
{
    (void)state;
    Scene *q = quad_emitter_scene(), *r = rect_light_scene();
    Framebuffer fq, fr, ref;
    render_as(q, 16, RENDER_PATH, 0, &fq);
    render_as(r, 16, RENDER_PATH, 0, &fr);
    render_as(r, 1024, RENDER_PATH, 0, &ref);
    double mq = mean_luma(&fq), mr = mean_luma(&fr), mref = mean_luma(&ref);
    double nq = rms_error(&fq, &ref), nr = rms_error(&fr, &ref);
    print_message("path, 16 spp: emitter quad mean %.5f, rectangle light %.5f (1024 spp %.5f); per-pixel rms error "
                  "%.5f against %.5f (ratio %.3f)\n", mq, mr, mref, nq, nr, nq / nr);
    assert_true(mref > 0.05);
    assert_near(mq / mref, 1.0, 0.01);
    assert_near(mr / mref, 1.0, 0.01);
    assert_true(nq <= 1.1 * nr);
    /* without the quad as a light, material sampling alone is much noisier at the same samples */
    Framebuffer fb;
    render_as(q, 16, RENDER_PATH, 1, &fb);
    double nb = rms_error(&fb, &ref);
    print_message("material sampling only, 16 spp: mean %.5f, rms error %.5f\n", mean_luma(&fb), nb);
    assert_true(nb > 2.0 * nq);
    framebuffer_free(&fb);
    framebuffer_free(&fq);
    framebuffer_free(&fr);
    framebuffer_free(&ref);
    scene_destroy(q);
    scene_destroy(r);
}

static void test_sphere_equals_sphere_light(void **state)
{
    (void)state;
    Scene *e = floor_scene(), *l = floor_scene();
    add_sphere(e, emitter(e, 6.0), gvec3(0.3, 1.2, 0.2), 0.25);
    Light *sl = add_light(l, LIGHT_SPHERE, 6.0);
    sl->position = gvec3(0.3, 1.2, 0.2);
    sl->radius = 0.25;
    Framebuffer fe, fl;
    render_as(e, 64, RENDER_PATH, 0, &fe);
    render_as(l, 64, RENDER_PATH, 0, &fl);
    double me = mean_luma(&fe), ml = mean_luma(&fl);
    print_message("path, 64 spp: emitter sphere %.5f, sphere light %.5f\n", me, ml);
    assert_true(ml > 0.02);
    assert_near(me / ml, 1.0, 0.01);
    framebuffer_free(&fe);
    framebuffer_free(&fl);
    scene_destroy(e);
    scene_destroy(l);
}

/* An OBJ of an n x n grid of squares (2 n^2 triangles) at height y over [x0, x0 + size] x [z0, z0 + size], facing
 * down. */
static char *grid_obj(int n, double x0, double z0, double size, double y)
{
    size_t cap = (size_t)(n + 1) * (n + 1) * 64 + (size_t)n * n * 96 + 64;
    char *text = malloc(cap), *p = text;
    assert_non_null(text);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            p += sprintf(p, "v %.9g %.9g %.9g\n", x0 + size * i / n, y, z0 + size * j / n);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            int a = i * (n + 1) + j + 1, b = a + n + 1; /* (i, j), (i + 1, j); +1: (.., j + 1) */
            p += sprintf(p, "f %d %d %d\nf %d %d %d\n", a, b, a + 1, b, b + 1, a + 1);
        }
    char *path = write_text("emissive_grid.obj", text);
    free(text);
    return path;
}

static void test_mesh_converges(void **state)
{
    (void)state;
    Scene *s = floor_scene();
    Object *o = object_new(SHAPE_MESH, emitter(s, 4.0));
    gmaterial_unref(o->material);
    GError err;
    if (object_mesh_load(o, grid_obj(40, -0.6, -0.6, 1.2, 1.5), &err) != G_OK)
        fail_msg("mesh: %s", err.message);
    assert_int_equal(o->mesh->ntris, 3200);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    Framebuffer nee, bsdf;
    int spp = getenv("EMISSIVE_SPP") ? atoi(getenv("EMISSIVE_SPP")) : 64;
    render_as(s, spp, RENDER_PATH, 0, &nee);
    render_as(s, 16 * spp, RENDER_PATH, 1, &bsdf);
    /* the panel is a rectangle light of its size, which the light's own estimate gives with little noise */
    Scene *r = floor_scene();
    Light *l = add_light(r, LIGHT_RECT, 4.0);
    l->position = gvec3(-0.6, 1.5, -0.6);
    l->edge1 = gvec3(1.2, 0, 0);
    l->edge2 = gvec3(0, 0, 1.2);
    Framebuffer ref;
    render_as(r, 16 * spp, RENDER_PATH, 0, &ref);
    double mn = mean_luma(&nee), mb = mean_luma(&bsdf), mr = mean_luma(&ref);
    print_message("3200 emissive triangles: NEE and MIS at %d spp %.5f, material sampling only at %d spp %.5f; the "
                  "rectangle light at %d spp %.5f\n", spp, mn, 16 * spp, mb, 16 * spp, mr);
    assert_true(mb > 0.05);
    assert_near(mn / mb, 1.0, 0.015);
    assert_near(mn / mr, 1.0, 0.005);
    framebuffer_free(&ref);
    scene_destroy(r);
    framebuffer_free(&nee);
    framebuffer_free(&bsdf);
    scene_destroy(s);
}

static void test_whitted_lights_floor(void **state)
{
    (void)state;
    Scene *q = quad_emitter_scene(), *r = rect_light_scene();
    Framebuffer fq, fr, fb;
    render_as(q, 4, RENDER_WHITTED, 0, &fq);
    render_as(r, 4, RENDER_WHITTED, 0, &fr);
    render_as(q, 4, RENDER_WHITTED, 1, &fb);
    double mq = mean_luma(&fq), mr = mean_luma(&fr), mb = mean_luma(&fb);
    print_message("Whitted: emitter quad %.5f, rectangle light %.5f, quad not a light %.5f\n", mq, mr, mb);
    assert_true(mr > 0.05);
    assert_near(mq / mr, 1.0, 0.01);
    assert_true(mb == 0.0); /* the floor is lit by nothing else */
    framebuffer_free(&fq);
    framebuffer_free(&fr);
    framebuffer_free(&fb);
    scene_destroy(q);
    scene_destroy(r);
}

/* Two quads of equal size, one 3 times as bright: chosen 3 to 1 (the alias table over evenly spread numbers gives
 * the probabilities exactly), and the density of a drawn direction asked again as a hit is the one drawn. */
static void test_choice_by_power(void **state)
{
    (void)state;
    Scene *s = floor_scene();
    GError err;
    for (int k = 0; k < 2; k++) {
        Object *o = object_new(SHAPE_QUAD, emitter(s, k ? 3.0 : 1.0));
        gmaterial_unref(o->material);
        assert_int_equal(object_quad(o, gvec3(-2.0 + 3.0 * k, 1.5, -0.5), EDGE1, EDGE2, &err), G_OK);
        assert_int_equal(scene_add_object(s, o, &err), G_OK);
    }
    assert_int_equal(accel_build(s, &err), G_OK);
    TraceCtx c = {.scene = s, .max_depth = 4, .band = -1};
    c.scratch = gscratch_create(1 << 16);
    assert_non_null(c.scratch);
    EmissiveSet *e = NULL;
    assert_int_equal(emissive_build(s, &c, &e, &err), G_OK);
    assert_int_equal(emissive_count(e), 2);
    GColor L;
    assert_int_equal(gcolor_scratch(&L, s->model, c.scratch), G_OK);
    int n = 4000, right = 0;
    for (int i = 0; i < n; i++) {
        GVec3 in, normal;
        double dist, pdf;
        double u0 = (i + 0.5) / n, u1 = 0.5, u2 = 0.5;
        assert_int_equal(emissive_sample(&c, e, gvec3(0, 0, 0), u0, u1, u2, &in, &dist, &normal, &pdf, &L), 1);
        right += in.x > 0.0;
        /* the density of the same direction asked as a hit equals the one drawn */
        Hit h = {0};
        h.obj = in.x > 0.0 ? s->objects[2] : s->objects[1];
        assert_near(emissive_pdf(e, &h, gvec3(0, 0, 0), in, dist), pdf, 1e-9 * pdf);
    }
    print_message("brighter quad chosen %d of %d (expected %d)\n", right, n, 3 * n / 4);
    assert_true(abs(right - 3 * n / 4) <= 1);
    emissive_free(e);
    gscratch_destroy(c.scratch);
    scene_destroy(s);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quad_equals_rectangle), cmocka_unit_test(test_sphere_equals_sphere_light),
        cmocka_unit_test(test_mesh_converges),        cmocka_unit_test(test_whitted_lights_floor),
        cmocka_unit_test(test_choice_by_power),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
