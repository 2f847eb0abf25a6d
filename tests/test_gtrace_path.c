/* test_gtrace_path.c - the path integrator (examples/gtrace/path.c): white furnace (lambert of albedo 1 and 0.5,
 * a dielectric sphere creates no energy), the ambient light as a uniform environment (a * A on a sphere, the
 * view factor's occlusion on a floor), Whitted and path agree where only ideal surfaces and point lights
 * are involved and through a dispersive sphere (hero band), the environment's MIS, RMSE convergence on a small
 * Cornell box over every pixel, fluorescence carried from wall to wall in bispectral only, images independent
 * of the thread count, and no allocation per ray. Images are tiny. (A probe technique's directional lights
 * under path tracing: test_gtrace_probe.c.) */
#include "test_gtrace_common.h"
#include "test_alloc.h"

#include "generic/builtins.h"
#include "generic/generators.h"
#include "generic/nodes.h"

#include <unistd.h>

/* Renders s with the path tracer's sampler `sampler` (trace/sampler.h). */
static void render_sampled(Scene *s, int w, int h, int spp, int depth, int threads, int integrator, int sampler,
                           Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = w, .height = h, .spp = spp, .depth = depth, .threads = threads, .quiet = 1,
                         .cutoff = 0.0, .integrator = integrator, .sampler = sampler};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

/* Renders s with the default sampler. */
static void render_with(Scene *s, int w, int h, int spp, int depth, int threads, int integrator, Framebuffer *fb)
{
    render_sampled(s, w, h, spp, depth, threads, integrator, SAMPLER_SOBOL, fb);
}

static double mean_luma(const Framebuffer *fb, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            sum += luma(pixel(fb, x, y));
    return sum / ((x1 - x0) * (y1 - y0));
}

static Scene *load_scene_file(const char *rel, const char *model)
{
    const char *root = getenv("GENERIC_SOURCE_DIR");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", root ? root : ".", rel);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(path, model, &s, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    return s;
}

/* ---- white furnace: a sphere in a uniform background of radiance 1 ---- */

/* Mean luma of the sphere's central pixels over the background's (the image's corners). */
static double furnace_ratio(const char *model, GMaterial *(*make)(const Scene *, double), double param)
{
    Scene *s = new_scene(model, gvec3(0, 0, 4), gvec3(0, 0, 0), 40);
    set_grey(&s->background, 1.0, GCOLOR_LIGHT);
    add_sphere(s, make(s, param), gvec3(0, 0, 0), 1.0);
    Framebuffer fb;
    render_with(s, 12, 12, 256, 16, 2, RENDER_PATH, &fb);
    double bg =
        (luma(pixel(&fb, 0, 0)) + luma(pixel(&fb, 11, 0)) + luma(pixel(&fb, 0, 11)) + luma(pixel(&fb, 11, 11))) / 4;
    double in = mean_luma(&fb, 4, 4, 8, 8);
    print_message("%s: background %.5f, sphere %.5f, ratio %.5f\n", model, bg, in, in / bg);
    assert_true(bg > 0.5);
    framebuffer_free(&fb);
    scene_destroy(s);
    return in / bg;
}

static void test_white_furnace(void **state)
{
    const char *model = *state;
    /* a convex lambert sphere: every bounce leaves it, so radiance = albedo * background exactly */
    assert_near(furnace_ratio(model, lambert, 1.0), 1.0, 0.01);
    assert_near(furnace_ratio(model, lambert, 0.5), 0.5, 0.005);
    /* clear glass loses nothing: what comes out is the background, no more (paths cut at depth 16 lose a
     * little at most) */
    double g = furnace_ratio(model, glass, 1.5);
    assert_true(g <= 1.01);
    assert_true(g >= 0.97);
}

/* ---- the ambient light: a uniform environment behind the background ---- */

/* A Lambert sphere of albedo a under an ambient light A and a black background: every path leaves the convex
 * sphere after one bounce and sees A, so the sphere shows a * A, which is also Whitted's material.ambient
 * term; camera rays see the background (black), not the ambient light. A ball resting on a Lambert floor
 * darkens the floor next to it by its view factor (ambient occlusion), which Whitted's ambient term cannot
 * show. */
static void test_ambient_environment(void **state)
{
    const char *model = *state;
    const double A = 0.8;
    for (int k = 0; k < 2; k++) {
        double a = k ? 0.5 : 1.0;
        Scene *s = new_scene(model, gvec3(0, 0, 4), gvec3(0, 0, 0), 40);
        set_grey(&s->ambient, A, GCOLOR_LIGHT);
        s->have_ambient = 1;
        add_sphere(s, lambert(s, a), gvec3(0, 0, 0), 1.0);
        Framebuffer fp, fw;
        render_with(s, 12, 12, 64, 4, 2, RENDER_PATH, &fp);
        render_with(s, 12, 12, 1, 4, 2, RENDER_WHITTED, &fw);
        double path = mean_luma(&fp, 4, 4, 8, 8), whitted = mean_luma(&fw, 4, 4, 8, 8);
        print_message("%s: albedo %.1f under ambient %.1f: path %.5f, Whitted %.5f, corner %.5f\n", model, a, A, path,
                      whitted, luma(pixel(&fp, 0, 0)));
        assert_near(path, a * A, 0.005 * A);
        assert_near(whitted, a * A, 0.005 * A);
        assert_true(luma(pixel(&fp, 0, 0)) == 0.0);
        framebuffer_free(&fp);
        framebuffer_free(&fw);
        scene_destroy(s);
    }
    /* occlusion: a floor of albedo 0.5 under a black ball of radius 1 resting on it. A floor point at distance
     * x from the contact point sees the ball with the view factor F = R^2 h / (x^2 + h^2)^(3/2) (h = R = 1,
     * the centre's height), so it shows 0.5 A (1 - F); compared over the floor pixels whose central ray misses
     * the ball by more than 0.05 */
    Scene *s = new_scene(model, gvec3(0, 4, 0.001), gvec3(0, 0, 0), 60);
    set_grey(&s->ambient, A, GCOLOR_LIGHT);
    s->have_ambient = 1;
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, lambert(s, 0.0), gvec3(0, 1, 0), 1.0);
    Framebuffer fb;
    enum { N = 24 };
    render_with(s, N, N, 64, 4, 2, RENDER_PATH, &fb);
    Camera cam = s->camera;
    camera_setup(&cam, N, N);
    double got = 0.0, expect = 0.0, occluded = 0.0;
    int used = 0;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            Ray r;
            camera_ray(&cam, x + 0.5, y + 0.5, &r);
            GVec3 oc = gvec3_sub(gvec3(0, 1, 0), r.o);
            double along = gvec3_dot(oc, r.d), miss = sqrt(fmax(0.0, gvec3_dot(oc, oc) - along * along));
            if (miss < 1.05)
                continue;
            GVec3 q = gvec3_madd(r.o, r.d, -r.o.y / r.d.y);
            double F = 1.0 / pow(q.x * q.x + q.z * q.z + 1.0, 1.5);
            got += luma(pixel(&fb, x, y));
            expect += 0.5 * A * (1.0 - F);
            occluded += F;
            used++;
        }
    print_message("%s: %d floor pixels beside a black ball: path %.5f, analytic %.5f (mean view factor %.3f)\n",
                  model, used, got / used, expect / used, occluded / used);
    assert_true(used > 300);
    assert_true(occluded / used > 0.05); /* without occlusion the floor would be 5% brighter */
    assert_near(got / expect, 1.0, 0.01);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- Whitted and path agree on ideal surfaces and point lights ---- */

static double compare_integrators(Scene *s, int depth, int spp, double *whitted, double *path)
{
    Framebuffer fw, fp; /* the same samples per pixel: the same pixel positions */
    render_with(s, 16, 12, spp, depth, 2, RENDER_WHITTED, &fw);
    render_with(s, 16, 12, spp, depth, 2, RENDER_PATH, &fp);
    *whitted = mean_luma(&fw, 0, 0, 16, 12);
    *path = mean_luma(&fp, 0, 0, 16, 12);
    /* the means over the four quarters: the two agree locally too */
    double worst = 0.0;
    for (int by = 0; by < 2; by++)
        for (int bx = 0; bx < 2; bx++) {
            double a = mean_luma(&fw, 8 * bx, 6 * by, 8 * bx + 8, 6 * by + 6);
            double b = mean_luma(&fp, 8 * bx, 6 * by, 8 * bx + 8, 6 * by + 6);
            worst = fmax(worst, fabs(a - b) / fmax(*whitted, 1e-6));
        }
    framebuffer_free(&fw);
    framebuffer_free(&fp);
    print_message("whitted %.5f, path %.5f, worst quarter's difference %.4f of the mean\n", *whitted, *path, worst);
    return worst;
}

/* Whitted and path tracing agree on s (over the image and in each quarter); s is destroyed. */
static void integrators_agree(Scene *s, int depth, int spp)
{
    double w, p;
    double worst = compare_integrators(s, depth, spp, &w, &p);
    assert_true(w > 0.01);
    assert_near(p / w, 1.0, 0.02);
    assert_true(worst < 0.05);
    scene_destroy(s);
}

static void test_whitted_agrees(void **state)
{
    (void)state;
    /* only ideal surfaces: an emitting sphere seen directly, in a mirror floor, through and in a glass
     * sphere and a mirror sphere; a point light that no ideal surface reflects */
    Scene *s = new_scene("rgb", gvec3(0, 1.2, 5), gvec3(0, 0.6, 0), 45);
    add_plane(s, mirror(s, 0.8), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, glass(s, 1.5), gvec3(-0.7, 0.6, 0), 0.6);
    add_sphere(s, mirror(s, 0.9), gvec3(0.7, 0.6, -0.3), 0.6);
    add_sphere(s, emitter(s, 2.0), gvec3(0.2, 1.8, -1.5), 0.5);
    Light *l = add_light(s, LIGHT_POINT, 5.0);
    l->position = gvec3(0, 3, 2);
    integrators_agree(s, 6, 256);

    /* a diffuse floor lit by a point light, seen directly and in ideal surfaces; depth 1 leaves no path with
     * a second diffuse vertex, so path tracing computes what Whitted does (its glass picks one lobe) */
    s = new_scene("rgb", gvec3(0, 1.2, 5), gvec3(0, 0.6, 0), 45);
    add_plane(s, lambert(s, 0.6), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, glass(s, 1.5), gvec3(-0.7, 0.6, 0), 0.6);
    add_sphere(s, mirror(s, 0.9), gvec3(0.7, 0.6, -0.3), 0.6);
    l = add_light(s, LIGHT_POINT, 20.0);
    l->position = gvec3(1, 3, 2);
    integrators_agree(s, 1, 64);
}

/* interpolate of a and b at t = 0.5 (the children's references are taken over). */
static GMaterial *half_blend(GMaterial *a, GMaterial *b)
{
    GGenerator *t = NULL;
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(ggenerator_constant_create(0.5, &t, &err), G_OK);
    if (gnode_interpolate_create(a, b, t, &m, &err) != G_OK)
        fail_msg("gnode_interpolate_create: %s", err.message);
    ggenerator_unref(t);
    gmaterial_unref(a);
    gmaterial_unref(b);
    return m;
}

/* Blends whose children share an ideal ray: reflection() along it gives the children's sum (materials.h), while a
 * sample stands for one child's lobe with that child's probability. An interpolate of two equal mirrors in a
 * uniform background of 1 is that mirror, 0.8 in every path; and an interpolate of a mirror and a glass over a
 * floor lit by a point light agrees with Whitted, which traces the shared reflection ray once (depth 1: no second
 * diffuse vertex). Both fail if a path weighs the sum by one child's
 * probability (the mirror part twice as bright). */
static void test_blend_shared_ray(void **state)
{
    (void)state;
    const char *models[] = {"rgb", "spectrum"};
    for (int k = 0; k < 2; k++) {
        Scene *s = new_scene(models[k], gvec3(0, 0, 4), gvec3(0, 0, 0), 30);
        set_grey(&s->background, 1.0, GCOLOR_LIGHT);
        add_sphere(s, half_blend(mirror(s, 0.8), mirror(s, 0.8)), gvec3(0, 0, 0), 1.0);
        Framebuffer fb;
        render_with(s, 12, 12, 4, 8, 2, RENDER_PATH, &fb);
        double in = mean_luma(&fb, 4, 4, 8, 8), bg = luma(pixel(&fb, 0, 0));
        print_message("%s: two mirrors of 0.8 blended, path: sphere %.5f, background %.5f\n", models[k], in, bg);
        assert_near(in, 0.8, 1e-3);
        assert_near(bg, 1.0, 1e-3);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
    Scene *s = new_scene("rgb", gvec3(0, 1.2, 5), gvec3(0, 0.6, 0), 45);
    add_plane(s, lambert(s, 0.6), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, half_blend(mirror(s, 0.9), glass(s, 1.5)), gvec3(0, 0.6, 0), 0.6);
    Light *l = add_light(s, LIGHT_POINT, 20.0);
    l->position = gvec3(1, 3, 2);
    integrators_agree(s, 1, 256);
}

/* Dispersion: a strongly dispersive glass sphere (Cauchy 1.45 + 0.03 / lambda^2, lambda in um: 1.64 at 400 nm,
 * 1.51 at 700 nm) in front of a white emitter, over a mirror floor. Whitted splits every dispersive refraction
 * into all wavelength groups, the path tracer picks one group (hero band: its mask times the group count); the
 * images agree (without the factor the path image is 0.44 of Whitted's). */
static void test_dispersion_agrees(void **state)
{
    (void)state;
    Scene *s = new_scene("spectrum9", gvec3(0, 1.0, 5), gvec3(0, 0.6, 0), 35);
    add_plane(s, mirror(s, 0.8), gvec3(0, 0, 0), gvec3(0, 1, 0));
    GDielectricParams gp = {gdispersion_cauchy(1.45, 0.03, 0.0), NULL, NULL};
    GMaterial *g = NULL;
    GError err;
    assert_int_equal(gdielectric_create(s->model, &gp, &g, &err), G_OK);
    add_sphere(s, g, gvec3(0, 0.6, 0), 0.6);
    add_sphere(s, emitter(s, 2.0), gvec3(0.3, 1.0, -2.0), 0.7);
    integrators_agree(s, 6, 256);
}

/* ---- convergence: RMSE halves when the samples quadruple ---- */

/* RMSE against ref over every pixel, or with skip_lamp over every pixel but those that see the lamp (ref above
 * 2 in a channel); *used counts the pixels. */
static double rmse_over(const Framebuffer *a, const Framebuffer *ref, int skip_lamp, int *used)
{
    double sum = 0.0;
    int n = 0;
    for (int p = 0; p < ref->width * ref->height; p++) {
        const float *r = ref->pixels + 3 * p, *x = a->pixels + 3 * p;
        if (skip_lamp && (r[0] > 2.0f || r[1] > 2.0f || r[2] > 2.0f))
            continue;
        for (int ch = 0; ch < 3; ch++)
            sum += (x[ch] - r[ch]) * (double)(x[ch] - r[ch]);
        n++;
    }
    *used = n;
    return n ? sqrt(sum / (3.0 * n)) : 0.0;
}

/* The independent sampler (SAMPLER_INDEPENDENT). Every pixel counts, silhouettes included (the camera's stratified
 * pixel samples do not make their error fall measurably faster than 1 / sqrt(n) here). Measured over all 576 pixels:
 * 0.177 at 4 spp, 0.093 at 16, ratio 1.89; the 12 pixels that see the lamp carry most of that squared error, and
 * without them (564 pixels, every silhouette and wall edge kept): 0.0404 and 0.0221, ratio 1.83. Both are asserted.
 * The Sobol sampler (the default) against the same reference (which shares no samples with it): 0.198 and 0.030
 * over all pixels (at 16 spp 0.32 of the independent error: its pixel positions, a (0,m,2)-net, find the lamp's
 * edges), 0.0374 and 0.0190 without the lamp (0.93 and 0.86 of the independent error). Asserted at 16 spp: below
 * half the independent error over all pixels and below 0.95 of it without the lamp. */
static void test_convergence(void **state)
{
    (void)state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    Framebuffer ref, f1, f4, s1, s4;
    render_sampled(s, 24, 24, 2048, 6, 2, RENDER_PATH, SAMPLER_INDEPENDENT, &ref);
    render_sampled(s, 24, 24, 4, 6, 2, RENDER_PATH, SAMPLER_INDEPENDENT, &f1);
    render_sampled(s, 24, 24, 16, 6, 2, RENDER_PATH, SAMPLER_INDEPENDENT, &f4);
    render_sampled(s, 24, 24, 4, 6, 2, RENDER_PATH, SAMPLER_SOBOL, &s1);
    render_sampled(s, 24, 24, 16, 6, 2, RENDER_PATH, SAMPLER_SOBOL, &s4);
    for (int skip_lamp = 0; skip_lamp < 2; skip_lamp++) {
        int n1, n4, m;
        double e1 = rmse_over(&f1, &ref, skip_lamp, &n1), e4 = rmse_over(&f4, &ref, skip_lamp, &n4);
        double q1 = rmse_over(&s1, &ref, skip_lamp, &m), q4 = rmse_over(&s4, &ref, skip_lamp, &m);
        print_message("RMSE over %d pixels%s at 4 spp %.5f, at 16 spp %.5f: ratio %.3f; Sobol %.5f, %.5f: ratio "
                      "%.3f\n", n1, skip_lamp ? " (not the lamp's)" : "", e1, e4, e1 / e4, q1, q4, q1 / q4);
        assert_true(n1 >= (skip_lamp ? 540 : 576));
        assert_true(e4 > 0.0);
        assert_near(e1 / e4, 2.0, 0.3);
        assert_true(q4 < (skip_lamp ? 0.95 : 0.5) * e4);
    }
    framebuffer_free(&ref);
    framebuffer_free(&f1);
    framebuffer_free(&f4);
    framebuffer_free(&s1);
    framebuffer_free(&s4);
    scene_destroy(s);
}

/* ---- fluorescence: the white wall receives the fluorescent wall's orange in bispectral only ---- */

/* Red over blue of the white (right) wall's pixels. */
static double right_wall_red_over_blue(const char *model)
{
    GColorModel *probe_model = model_or_skip(model);
    gcolormodel_destroy(probe_model);
    Scene *s = load_scene_file("examples/scenes/cornell_fluorescent.scene", model);
    Framebuffer fb;
    render_with(s, 16, 16, 64, 4, 2, RENDER_PATH, &fb);
    double r = 0.0, b = 0.0, lr = 0.0, lb = 0.0;
    for (int y = 5; y < 11; y++) {
        for (int x = 13; x < 15; x++) { /* the right wall */
            r += pixel(&fb, x, y)[0];
            b += pixel(&fb, x, y)[2];
        }
        for (int x = 1; x < 3; x++) { /* the fluorescent wall */
            lr += pixel(&fb, x, y)[0];
            lb += pixel(&fb, x, y)[2];
        }
    }
    print_message("%s: right wall red %.5f blue %.5f (ratio %.3f); fluorescent wall red %.5f blue %.5f\n", model,
                  r, b, r / b, lr, lb);
    assert_true(b > 0.0);
    framebuffer_free(&fb);
    scene_destroy(s);
    return r / b;
}

static void test_fluorescence_between_walls(void **state)
{
    (void)state;
    double bi = right_wall_red_over_blue("bispectral"), sp = right_wall_red_over_blue("spectrum");
    /* the 450 nm light alone has red / blue of about 0.08 in linear sRGB */
    assert_true(sp < 0.2);
    assert_true(bi > 0.5);
}

/* ---- the environment: NEE with the probe's distribution, MIS with material sampling ---- */

/* Mean luma of probe.scene at depth 1 with the probe sampled as `technique` (count: its lights or coefficients,
 * 0: the scene's). */
static double probe_scene_mean(const char *technique, int count, int spp)
{
    const char *root = getenv("GENERIC_SOURCE_DIR");
    char path[2048];
    snprintf(path, sizeof path, "%s/examples/scenes/probe.scene", root ? root : ".");
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    ProbeOverride ov = {.technique = technique, .count = count, .shadows = -1};
    Scene *s = NULL;
    if (scene_load_with(path, NULL, &ov, &s, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    Framebuffer fb;
    render_with(s, 16, 12, spp, 1, 2, RENDER_PATH, &fb);
    double m = mean_luma(&fb, 0, 0, 16, 12);
    framebuffer_free(&fb);
    scene_destroy(s);
    return m;
}

static void test_environment_mis(void **state)
{
    (void)state;
    /* technique reference: the probe's distribution for NEE (probe_light_nee, the Whitted reference's
     * estimator), weighted against material sampling by MIS; sh: a basis is not used by the path tracer, the
     * probe is only reached by material sampling (noisy: the sun, which it finds rarely: at 4096 spp it was 2% low,
     * at 16384 0.9%; the MIS estimate at 64 spp was 0.5% off its converged value, at 256 0.03%). Both see the probe's
     * pixels as the light. */
    double mis = probe_scene_mean("reference", 0, 256), bsdf = probe_scene_mean("sh", 9, 16384);
    print_message("sky and sun at depth 1: MIS %.5f, material sampling only %.5f\n", mis, bsdf);
    assert_true(mis > 0.1);
    assert_near(bsdf / mis, 1.0, 0.02);
}

/* ---- determinism: the image does not depend on the thread count ---- */

static void test_thread_independent(void **state)
{
    (void)state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    const size_t bytes = sizeof(float) * 3 * 20 * 18;
    for (int sampler = SAMPLER_SOBOL; sampler <= SAMPLER_INDEPENDENT; sampler++) {
        Framebuffer a, b;
        render_sampled(s, 20, 18, 4, 6, 1, RENDER_PATH, sampler, &a);
        render_sampled(s, 20, 18, 4, 6, 2, RENDER_PATH, sampler, &b);
        assert_memory_equal(a.pixels, b.pixels, bytes);
        /* and a different sample count gives a different image (the sequences depend on the sample index) */
        Framebuffer c;
        render_sampled(s, 20, 18, 5, 6, 1, RENDER_PATH, sampler, &c);
        assert_memory_not_equal(a.pixels, c.pixels, bytes);
        /* the samplers differ */
        Framebuffer d;
        render_sampled(s, 20, 18, 4, 6, 2, RENDER_PATH, !sampler, &d);
        assert_memory_not_equal(a.pixels, d.pixels, bytes);
        framebuffer_free(&a);
        framebuffer_free(&b);
        framebuffer_free(&c);
        framebuffer_free(&d);
    }
    scene_destroy(s);
}

/* ---- the light sample of a rectangle light ---- */

/* The irradiance at x (normal n) from a polygon of uniform radiance 1 (Lambert's formula): half the sum over its
 * edges of the angle the edge subtends times the cosine of its plane through x with n. */
static double polygon_irradiance(const GVec3 *v, int nv, GVec3 x, GVec3 n)
{
    double sum = 0.0;
    for (int i = 0; i < nv; i++) {
        GVec3 a = gvec3_normalize(gvec3_sub(v[i], x)), b = gvec3_normalize(gvec3_sub(v[(i + 1) % nv], x));
        double theta = acos(fmax(-1.0, fmin(1.0, gvec3_dot(a, b))));
        sum += theta * gvec3_dot(gvec3_normalize(gvec3_cross(a, b)), n);
    }
    return 0.5 * fabs(sum);
}

/* path_light_sample_at for a rectangle light and a parallelogram: the points (u, v) map to lie on the light, the
 * density is what area_light_hit gives for the ray to the point (the MIS weights agree), and the irradiance estimated
 * from a 64 x 64 grid of (u, v) matches Lambert's formula within 0.1%, and its solid angle (a midpoint sum of
 * cos / d^2 over the light) the mean of 1 / density, from below the light, off to its side at a grazing angle, and
 * near its plane. */
static void test_rect_light_sampling(void **state)
{
    (void)state;
    GColorModel *m = model_or_skip("rgb");
    Light *l = light_new(m, LIGHT_RECT);
    assert_non_null(l);
    const GVec3 points[] = {gvec3(0.1, 0.2, 0.05), gvec3(2.5, 0.6, -1.0), gvec3(-0.4, 0.99, 0.6)};
    for (int shape = 0; shape < 2; shape++) {
        l->position = gvec3(-0.3, 1.0, -0.2);
        l->edge1 = gvec3(0.6, 0.0, 0.0);
        l->edge2 = shape == 0 ? gvec3(0.0, 0.0, 0.5) : gvec3(0.2, 0.0, 0.5); /* edge1 x edge2 points down */
        GVec3 corners[4] = {l->position, gvec3_add(l->position, l->edge1),
                            gvec3_add(l->position, gvec3_add(l->edge1, l->edge2)), gvec3_add(l->position, l->edge2)};
        GVec3 nl = gvec3_normalize(gvec3_cross(l->edge1, l->edge2));
        double area = gvec3_length(gvec3_cross(l->edge1, l->edge2));
        for (int k = 0; k < 3; k++) {
            GVec3 x = points[k], n = gvec3(0, 1, 0);
            double est = 0.0, omega = 0.0, inv_pdf = 0.0;
            enum { G = 64, A = 400 };
            for (int i = 0; i < A; i++) /* the solid angle by a midpoint sum over the parallelogram */
                for (int j = 0; j < A; j++) {
                    GVec3 y = gvec3_add(l->position, gvec3_add(gvec3_scale(l->edge1, (i + 0.5) / A),
                                                               gvec3_scale(l->edge2, (j + 0.5) / A)));
                    GVec3 w = gvec3_sub(y, x);
                    double d2 = gvec3_dot(w, w);
                    omega += -gvec3_dot(w, nl) / (d2 * sqrt(d2)) * area / (A * A);
                }
            for (int i = 0; i < G; i++) {
                for (int j = 0; j < G; j++) {
                    GVec3 in;
                    double dist, pdf, hit_pdf = 0.0;
                    GColor L;
                    assert_int_equal(gcolor_alloc(&L, m), G_OK);
                    assert_int_equal(path_light_sample_at(l, x, (i + 0.5) / G, (j + 0.5) / G, &in, &dist, &pdf, &L),
                                     1);
                    gcolor_free(&L);
                    /* on the light: its plane, within its edges */
                    GVec3 q = gvec3_sub(gvec3_madd(x, in, dist), l->position);
                    assert_true(fabs(gvec3_dot(q, nl)) < 1e-9);
                    Ray r = {x, in, 0.0, INFINITY, 0.0, 0.0};
                    double t = area_light_hit(l, &r, INFINITY, &hit_pdf);
                    assert_true(fabs(t - dist) < 1e-9 * (1.0 + dist) || isinf(t)); /* isinf: on an edge */
                    if (!isinf(t))
                        assert_true(fabs(hit_pdf / pdf - 1.0) < 1e-9);
                    inv_pdf += 1.0 / pdf;
                    est += fmax(0.0, gvec3_dot(in, n)) / pdf;
                }
            }
            est /= G * G;
            inv_pdf /= G * G;
            assert_near(inv_pdf / omega, 1.0, 1e-3);
            double exact = polygon_irradiance(corners, 4, x, n);
            print_message("%s, point %d: solid angle %.6f, irradiance %.6f, Lambert's %.6f\n",
                          shape ? "parallelogram" : "rectangle", k, omega, est, exact);
            assert_true(exact > 0.0);
            assert_near(est / exact, 1.0, 1e-3);
        }
    }
    light_free(l);
    gcolormodel_destroy(m);
}

/* ---- the samplers converge to the same image ---- */

/* The Cornell box at 24x24 (rgb, depth 6): the mean luminance of 14 patches of 6x6 pixels (the lamp's two left out)
 * with the Sobol sampler at 1024 spp (s) against the independent sampler at 1024 (a). Their difference is noise: the
 * independent render at 2048 spp is the mean of a and of an independent render b of the next 1024 samples, so
 * b = 2 m - a, and (a - b)^2 / 2 estimates a patch's noise variance. The statistic F = sum ((s - a) / a)^2 over
 * sum ((a - b) / a)^2 / 2 is about 1 to 2 when the samplers agree in expectation (2 if Sobol were as noisy as
 * independent numbers), a ratio of two sums of 14 squares; measured 1.1 (the patches' relative noise 0.54% on
 * average, the differences up to 1.1%). A sampler that is not uniform fails it: the Sobol values squared (a density
 * 1 / (2 sqrt(u)) in every dimension) give F = 940, patches off by up to 40%. */
static void test_samplers_agree(void **state)
{
    (void)state;
    Scene *s = load_scene_file("examples/scenes/cornell.scene", "rgb");
    Framebuffer fs, fa, fm;
    render_sampled(s, 24, 24, 1024, 6, 2, RENDER_PATH, SAMPLER_SOBOL, &fs);
    render_sampled(s, 24, 24, 1024, 6, 2, RENDER_PATH, SAMPLER_INDEPENDENT, &fa);
    render_sampled(s, 24, 24, 2048, 6, 2, RENDER_PATH, SAMPLER_INDEPENDENT, &fm);
    double diff = 0.0, noise = 0.0, worst = 0.0;
    for (int py = 0; py < 4; py++) {
        for (int px = 0; px < 4; px++) {
            if (py == 0 && (px == 1 || px == 2))
                continue; /* the lamp's patches */
            int x0 = 6 * px, y0 = 6 * py;
            double ms = mean_luma(&fs, x0, y0, x0 + 6, y0 + 6), ma = mean_luma(&fa, x0, y0, x0 + 6, y0 + 6);
            double mb = 2.0 * mean_luma(&fm, x0, y0, x0 + 6, y0 + 6) - ma;
            assert_true(ma > 0.01);
            diff += (ms / ma - 1.0) * (ms / ma - 1.0);
            noise += 0.5 * (mb / ma - 1.0) * (mb / ma - 1.0);
            worst = fmax(worst, fabs(ms / ma - 1.0));
        }
    }
    print_message("Sobol against independent at 1024 spp: patches within %.2f%%, F = %.2f (noise %.2f%% a patch)\n",
                  100.0 * worst, diff / noise, 100.0 * sqrt(noise / 14.0));
    assert_true(noise > 0.0);
    assert_true(diff / noise < 5.0);
    framebuffer_free(&fs);
    framebuffer_free(&fa);
    framebuffer_free(&fm);
    scene_destroy(s);
}

/* ---- Russian roulette keeps every band's expectation ---- */

/* Inside a Lambert sphere of radius 1 with a point light of intensity I at its centre, every wall point gets the
 * irradiance I and sees walls of one radiance: a band of reflectance a shows (I / pi) (a + a^2 + ... + a^(D+1)) at
 * depth D (one light sample at each of the D + 1 vertices), whatever direction each bounce takes. So the only noise
 * is Russian roulette's (from the fourth vertex on), and a survival probability not divided out, or one that
 * depended on a band, would show in the saturated colour's three channels: red 0.9, green 0.5, blue 0.1, each
 * within 1% of its sum. */
static void test_roulette_coloured_sphere(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 0, 0), gvec3(0, 0, -1), 60);
    const double rho[3] = {0.9, 0.5, 0.1}, I = 2.0;
    enum { D = 8 };
    GColor c;
    assert_int_equal(gcolor_alloc(&c, s->model), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rho, GCOLOR_REFLECTANCE), G_OK);
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(glambert_create(s->model, &c, &m, &err), G_OK);
    gcolor_free(&c);
    add_sphere(s, m, gvec3(0, 0, 0), 1.0);
    Light *l = add_light(s, LIGHT_POINT, I);
    l->position = gvec3(0, 0, 0);
    Framebuffer fb;
    render_with(s, 8, 8, 128, D, 2, RENDER_PATH, &fb);
    for (int ch = 0; ch < 3; ch++) {
        double expect = 0.0, ak = 1.0, got = 0.0;
        for (int k = 1; k <= D + 1; k++)
            expect += (ak *= rho[ch]) * I / M_PI;
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 8; x++)
                got += pixel(&fb, x, y)[ch] / 64.0;
        print_message("channel %d (reflectance %.1f): path %.5f, analytic %.5f\n", ch, rho[ch], got, expect);
        assert_near(got / expect, 1.0, 0.01);
    }
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- no allocation per ray ---- */

static long allocations_of_render(Scene *s, int spp)
{
    static TuAlloc counter;
    tu_alloc_install(&counter);
    Framebuffer fb;
    render_with(s, 12, 12, spp, 8, 1, RENDER_PATH, &fb);
    gmem_set_allocator(NULL);
    long n = counter.calls;
    framebuffer_free(&fb);
    return n;
}

static void test_no_allocation_per_ray(void **state)
{
    const char *model = *state;
    GColorModel *m = model_or_skip(model);
    gcolormodel_destroy(m);
    /* every light type the path tracer samples, glass (media, transmission) and a diffuse box */
    Scene *s = load_scene_file("examples/scenes/cornell.scene", model);
    GError err;
    /* the scene's library owns what the file made; what is added here is freed here */
    Light *l1 = add_light(s, LIGHT_POINT, 1.0), *l2 = add_light(s, LIGHT_SPHERE, 2.0);
    Light *l3 = add_light(s, LIGHT_DIRECTIONAL, 0.5);
    l1->position = gvec3(0.5, 1.5, 0.5);
    l2->position = gvec3(-0.5, 1.6, 0.5);
    l2->radius = 0.1;
    l3->direction = gvec3_normalize(gvec3(0.2, -1, -0.3));
    Object *ball = add_sphere(s, glass(s, 1.5), gvec3(0.3, 0.9, 0.4), 0.25);
    assert_int_equal(accel_build(s, &err), G_OK);
    long a1 = allocations_of_render(s, 1), a16 = allocations_of_render(s, 16);
    print_message("%s: %ld allocations at 1 spp, %ld at 16 spp\n", model, a1, a16);
    assert_int_equal(a1, a16);
    scene_destroy(s);
    light_free(l1);
    light_free(l2);
    light_free(l3);
    object_free(ball);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        {"test_white_furnace (rgb)", test_white_furnace, NULL, NULL, (void *)"rgb"},
        {"test_white_furnace (spectrum)", test_white_furnace, NULL, NULL, (void *)"spectrum"},
        {"test_white_furnace (bispectral)", test_white_furnace, NULL, NULL, (void *)"bispectral"},
        {"test_ambient_environment (rgb)", test_ambient_environment, NULL, NULL, (void *)"rgb"},
        {"test_ambient_environment (bispectral)", test_ambient_environment, NULL, NULL, (void *)"bispectral"},
        cmocka_unit_test(test_whitted_agrees),
        cmocka_unit_test(test_blend_shared_ray),
        cmocka_unit_test(test_dispersion_agrees),
        cmocka_unit_test(test_convergence),
        cmocka_unit_test(test_fluorescence_between_walls),
        cmocka_unit_test(test_environment_mis),
        cmocka_unit_test(test_thread_independent),
        cmocka_unit_test(test_samplers_agree),
        cmocka_unit_test(test_rect_light_sampling),
        cmocka_unit_test(test_roulette_coloured_sphere),
        {"test_no_allocation_per_ray (rgb)", test_no_allocation_per_ray, NULL, NULL, (void *)"rgb"},
        {"test_no_allocation_per_ray (bispectral)", test_no_allocation_per_ray, NULL, NULL, (void *)"bispectral"},
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
