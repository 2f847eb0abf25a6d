/* test_gtrace.c - the tracer's shading against analytic values: a Lambert sphere under a point light,
 * a mirror sphere in a constant background, a glass slab against Fresnel, shadows of opaque and glass
 * occluders, area and spot lights against their closed forms, rgb against spectrum on a grey world
 * (CIEDE2000), the depth limit, and NaN never reaching a pixel. Every case renders a few hundred pixels. */
#include "generic/builtins.h"
#include "colour_difference.h"
#include "test_gtrace_common.h"

static const char *const all_models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};

/* ---- Lambert sphere: L = rho / pi * I * cos / d^2 at the centre pixel ---- */

static void lambert_point_in(const char *model)
{
    Scene *s = new_scene(model, gvec3(0, 0, 5), gvec3(0, 0, 0), 30.0);
    const double rho = 0.5, I = 20.0;
    add_sphere(s, lambert(s, rho), gvec3(0, 0, 0), 1.0);
    Light *l = add_light(s, LIGHT_POINT, I);
    l->position = gvec3(2, 3, 4);
    Framebuffer fb;
    render(s, 33, 33, 1, 4, &fb);
    /* the centre ray is the axis: it hits (0,0,1) with normal +z */
    GVec3 p = gvec3(0, 0, 1), L = gvec3_sub(l->position, p);
    double d = gvec3_length(L), cosv = L.z / d;
    double expect = rho / M_PI * I * cosv / (d * d);
    const float *px = pixel(&fb, 16, 16);
    print_message("%-10s centre pixel %.6f %.6f %.6f, expected %.6f\n", model, px[0], px[1], px[2], expect);
    for (int c = 0; c < 3; c++)
        assert_near(px[c], expect, 0.01 * expect);
    framebuffer_free(&fb);
    scene_destroy(s);
}

static void test_lambert_point(void **state)
{
    (void)state;
    for (int i = 0; i < 4; i++)
        lambert_point_in(all_models[i]);
}

/* ---- mirror sphere in a constant background: every pixel is the background ---- */

static void test_mirror_background(void **state)
{
    (void)state;
    for (int i = 0; i < 4; i++) {
        Scene *s = new_scene(all_models[i], gvec3(0, 0, 4), gvec3(0, 0, 0), 40.0);
        add_sphere(s, mirror(s, 1.0), gvec3(0, 0, 0), 1.0);
        Light *l = add_light(s, LIGHT_POINT, 50.0); /* a perfect mirror reflects no light source directly */
        l->position = gvec3(3, 3, 3);
        double bg[3] = {0.3, 0.5, 0.7};
        assert_int_equal(gcolor_from_rgb(&s->background, bg, GCOLOR_LIGHT), G_OK);
        Framebuffer fb;
        RenderStats st = render(s, 24, 24, 1, 4, &fb);
        assert_true(st.rays > 24 * 24 + 100); /* the sphere was hit and reflected */
        const float *ref = pixel(&fb, 0, 0);
        for (int c = 0; c < 3; c++)
            assert_near(ref[c], bg[c], 2e-3);
        double worst = 0.0;
        for (int y = 0; y < 24; y++)
            for (int x = 0; x < 24; x++)
                for (int c = 0; c < 3; c++)
                    worst = fmax(worst, fabs(pixel(&fb, x, y)[c] - ref[c]) / ref[c]);
        print_message("%-10s mirror sphere: worst relative difference to the background %.3g\n", all_models[i], worst);
        assert_true(worst < 1e-5);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

/* ---- glass slab: transmittance (1 - F)/(1 + F) with all inter-reflections, (1 - F)^2 at depth 2 ---- */

static Scene *slab_scene(const char *model, int with_slab)
{
    Scene *s = new_scene(model, gvec3(0, 0, 5), gvec3(0, 0, 0), 50.0);
    if (with_slab)
        add_box(s, glass(s, 1.5), gvec3(-50, -50, -0.25), gvec3(50, 50, 0.25));
    add_plane(s, emitter(s, 1.0), gvec3(0, 0, -3), gvec3(0, 0, 1));
    return s;
}

static void test_glass_slab(void **state)
{
    (void)state;
    const char *models[] = {"rgb", "spectrum"};
    const int W = 21, H = 21;
    for (int mi = 0; mi < 2; mi++) {
        Scene *open = slab_scene(models[mi], 0);
        Framebuffer ref;
        render(open, W, H, 1, 30, &ref);
        for (int depth = 2; depth <= 30; depth += 28) {
            Scene *s = slab_scene(models[mi], 1);
            Framebuffer fb;
            render(s, W, H, 1, depth, &fb);
            Camera cam = s->camera;
            camera_setup(&cam, W, H);
            const int xs[] = {10, 0, 20, 3}, ys[] = {10, 0, 7, 18};
            for (int k = 0; k < 4; k++) {
                Ray r;
                camera_ray(&cam, xs[k] + 0.5, ys[k] + 0.5, &r);
                double F = goptics_fresnel(-r.d.z, 1.0 / 1.5);
                double expect = depth == 2 ? (1 - F) * (1 - F) : (1 - F) / (1 + F);
                double got = luma(pixel(&fb, xs[k], ys[k])) / luma(pixel(&ref, xs[k], ys[k]));
                print_message("%-9s depth %2d, incidence %5.2f deg: T = %.6f, Fresnel %.6f\n", models[mi], depth,
                              acos(-r.d.z) * 180 / M_PI, got, expect);
                assert_near(got, expect, 1e-4);
            }
            framebuffer_free(&fb);
            scene_destroy(s);
        }
        /* adaptive depth: internal reflections below a weight of 1e-3 are not traced; the transmittance
         * loses only the R^4 terms and far fewer rays are cast */
        Scene *s = slab_scene(models[mi], 1), *s0 = slab_scene(models[mi], 1);
        s->camera.cutoff = 1e-3;
        Framebuffer fb, fb0;
        RenderStats st = render(s, W, H, 1, 30, &fb), st0 = render(s0, W, H, 1, 30, &fb0);
        double got = luma(pixel(&fb, 10, 10)) / luma(pixel(&ref, 10, 10));
        print_message("%-9s cutoff 1e-3: T = %.6f with %llu rays (%llu without the cutoff)\n", models[mi], got,
                      (unsigned long long)st.rays, (unsigned long long)st0.rays);
        assert_near(got, 0.96 / 1.04, 1e-4);
        assert_true(st.rays * 3 < st0.rays);
        framebuffer_free(&fb);
        framebuffer_free(&fb0);
        scene_destroy(s);
        scene_destroy(s0);
        framebuffer_free(&ref);
        scene_destroy(open);
    }
}

/* ---- absorption: Beer-Lambert over the distance travelled in a medium (the camera's and a glass's) ---- */

static GMaterial *absorbing(const Scene *s, double n, double a)
{
    GColor c;
    assert_int_equal(gcolor_alloc(&c, s->model), G_OK);
    set_grey(&c, a, GCOLOR_REFLECTANCE);
    GDielectricParams p = {gdispersion_constant(n), &c, NULL};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gdielectric_create(s->model, &p, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

static void test_absorption(void **state)
{
    (void)state;
    /* the camera sits in an absorbing medium of index 1; the emitter plane is 8 units away on the axis */
    Scene *s = new_scene("rgb", gvec3(0, 0, 5), gvec3(0, 0, 0), 30.0);
    add_plane(s, emitter(s, 2.0), gvec3(0, 0, -3), gvec3(0, 0, 1));
    s->medium = absorbing(s, 1.0, 0.1);
    Framebuffer fb;
    render(s, 9, 9, 1, 2, &fb);
    double got = luma(pixel(&fb, 4, 4));
    print_message("camera medium: %.6f, expected %.6f\n", got, 2.0 * exp(-0.1 * 8.0));
    assert_near(got, 2.0 * exp(-0.1 * 8.0), 1e-4);
    framebuffer_free(&fb);
    scene_destroy(s);

    /* through the centre of an absorbing glass sphere of radius 1 at depth 2: (1 - R)^2 exp(-2 a) */
    s = new_scene("rgb", gvec3(0, 0, 5), gvec3(0, 0, 0), 30.0);
    add_plane(s, emitter(s, 2.0), gvec3(0, 0, -3), gvec3(0, 0, 1));
    add_sphere(s, absorbing(s, 1.5, 0.3), gvec3(0, 0, 0), 1.0);
    render(s, 9, 9, 1, 2, &fb);
    got = luma(pixel(&fb, 4, 4));
    double expect = 2.0 * 0.96 * 0.96 * exp(-0.3 * 2.0);
    print_message("absorbing sphere: %.6f, expected %.6f\n", got, expect);
    assert_near(got, expect, 1e-4);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- shadows: the floor point under the light behind an opaque sphere is black; behind glass it gets the
 * Fresnel transmission of two normal-incidence surfaces ---- */

static double shadow_centre(const char *model, int occluder)
{
    Scene *s = new_scene(model, gvec3(0, 1, 4), gvec3(0, 0, 0), 30.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    if (occluder == 1)
        add_sphere(s, lambert(s, 0.5), gvec3(0, 2, 0), 0.5);
    else if (occluder == 2)
        add_sphere(s, glass(s, 1.5), gvec3(0, 2, 0), 0.5);
    Light *l = add_light(s, LIGHT_POINT, 25.0);
    l->position = gvec3(0, 5, 0);
    Framebuffer fb;
    render(s, 17, 17, 1, 6, &fb);
    double v = luma(pixel(&fb, 8, 8));
    framebuffer_free(&fb);
    scene_destroy(s);
    return v;
}

static void test_shadows(void **state)
{
    (void)state;
    for (int i = 0; i < 4; i++) {
        double lit = shadow_centre(all_models[i], 0);
        double dark = shadow_centre(all_models[i], 1);
        double glassy = shadow_centre(all_models[i], 2);
        double R = 0.04; /* ((1.5 - 1) / (1.5 + 1))^2 */
        print_message("%-10s lit %.6f (expected %.6f), behind lambert %.3g, behind glass %.6f (ratio %.5f, "
                      "expected %.5f)\n",
                      all_models[i], lit, 0.5 / M_PI, dark, glassy, glassy / lit, (1 - R) * (1 - R));
        assert_near(lit, 0.5 / M_PI, 0.01 * 0.5 / M_PI);
        assert_true(dark == 0.0);
        assert_near(glassy / lit, (1 - R) * (1 - R), 2e-3);
    }
}

/* ---- area and spot lights ---- */

/* Irradiance at the origin (normal +y) from a uniform rectangle of radiance 1 (Lambert's polygon formula). */
static double rect_irradiance(GVec3 c, GVec3 e1, GVec3 e2)
{
    GVec3 v[4] = {c, gvec3_add(c, e1), gvec3_add(gvec3_add(c, e1), e2), gvec3_add(c, e2)};
    double sum = 0.0;
    for (int i = 0; i < 4; i++) {
        GVec3 a = gvec3_normalize(v[i]), b = gvec3_normalize(v[(i + 1) % 4]);
        GVec3 cr = gvec3_cross(a, b);
        double ang = acos(fmax(-1.0, fmin(1.0, gvec3_dot(a, b))));
        sum += ang * gvec3_normalize(cr).y;
    }
    return 0.5 * fabs(sum);
}

static double floor_centre(const char *model, Light *(*setup)(Scene *), int spp)
{
    Scene *s = new_scene(model, gvec3(0, 1, 4), gvec3(0, 0, 0), 30.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    setup(s);
    Framebuffer fb;
    render(s, 17, 17, spp, 2, &fb);
    double v = luma(pixel(&fb, 8, 8));
    framebuffer_free(&fb);
    scene_destroy(s);
    return v;
}

static Light *setup_sphere_light(Scene *s)
{
    Light *l = add_light(s, LIGHT_SPHERE, 2.0);
    l->position = gvec3(0.5, 3, -0.5);
    l->radius = 0.6;
    l->samples = 64;
    return l;
}

static Light *setup_rect_light(Scene *s)
{
    Light *l = add_light(s, LIGHT_RECT, 2.0);
    l->position = gvec3(-1, 2, -1.5);
    l->edge1 = gvec3(1.5, 0, 0);
    l->edge2 = gvec3(0, 0.3, 1.0); /* tilted; edge1 x edge2 points down */
    l->samples = 256;
    return l;
}

static Light *setup_spot_inside(Scene *s)
{
    Light *l = add_light(s, LIGHT_SPOT, 10.0);
    l->position = gvec3(1, 2, 0);
    l->direction = gvec3_normalize(gvec3(-1, -2, 0)); /* straight at the origin */
    l->cos_inner = cos(10 * M_PI / 180);
    l->cos_outer = cos(15 * M_PI / 180);
    return l;
}

static Light *setup_spot_outside(Scene *s)
{
    Light *l = setup_spot_inside(s);
    l->direction = gvec3_normalize(gvec3(-1, -1, 0)); /* 18 degrees off the origin */
    return l;
}

static Light *setup_directional(Scene *s)
{
    Light *l = add_light(s, LIGHT_DIRECTIONAL, 3.0);
    l->direction = gvec3_normalize(gvec3(1, -2, 0.5));
    return l;
}

static void test_area_and_spot_lights(void **state)
{
    (void)state;
    for (int i = 0; i < 2; i++) {
        const char *m = all_models[i * 2];
        /* sphere of radiance L seen under the half angle a, fully above the horizon: E = L pi sin^2 a
         * times the cosine towards its centre */
        GVec3 c = gvec3(0.5, 3, -0.5);
        double dc = gvec3_length(c), sin2 = 0.36 / (dc * dc);
        double e_sphere = 2.0 * M_PI * sin2 * (c.y / dc);
        double got = floor_centre(m, setup_sphere_light, 1);
        print_message("%-9s sphere light: %.6f, expected %.6f\n", m, got, 0.5 / M_PI * e_sphere);
        assert_near(got, 0.5 / M_PI * e_sphere, 0.005 * 0.5 / M_PI * e_sphere);

        double e_rect = 2.0 * rect_irradiance(gvec3(-1, 2, -1.5), gvec3(1.5, 0, 0), gvec3(0, 0.3, 1.0));
        got = floor_centre(m, setup_rect_light, 1);
        print_message("%-9s rectangle light: %.6f, expected %.6f\n", m, got, 0.5 / M_PI * e_rect);
        assert_near(got, 0.5 / M_PI * e_rect, 0.005 * 0.5 / M_PI * e_rect);

        got = floor_centre(m, setup_spot_inside, 1);
        double cosv = 2.0 / sqrt(5.0), expect = 0.5 / M_PI * 10.0 * cosv / 5.0;
        assert_near(got, expect, 0.01 * expect);
        got = floor_centre(m, setup_spot_outside, 1);
        assert_true(got == 0.0);

        got = floor_centre(m, setup_directional, 1);
        expect = 0.5 / M_PI * 3.0 * (2.0 / sqrt(1 + 4 + 0.25));
        assert_near(got, expect, 0.01 * expect);
    }
}

/* ---- the same grey world in rgb and in spectrum: mean CIEDE2000 < 1 ---- */

static void to_lab(const float *rgb, double lab[3])
{
    double lin[3] = {rgb[0], rgb[1], rgb[2]}, xyz[3];
    gcie_rgb_to_xyz(lin, xyz);
    cd_xyz_to_lab(xyz, lab);
}

static Framebuffer grey_world(const char *model)
{
    Scene *s = new_scene(model, gvec3(0, 1.5, 6), gvec3(0, 0.7, 0), 40.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, lambert(s, 0.2), gvec3(-1.6, 0.7, 0), 0.7);
    add_sphere(s, lambert(s, 0.8), gvec3(0, 0.7, -0.5), 0.7);
    add_sphere(s, mirror(s, 0.8), gvec3(1.6, 0.7, 0), 0.7);
    add_box(s, lambert(s, 0.35), gvec3(-0.5, 0, 1), gvec3(0.3, 0.4, 1.6));
    Light *l = add_light(s, LIGHT_POINT, 30.0);
    l->position = gvec3(2, 5, 4);
    Light *a = add_light(s, LIGHT_SPHERE, 3.0);
    a->position = gvec3(-3, 4, 2);
    a->radius = 0.5;
    a->samples = 4;
    set_grey(&s->background, 0.2, GCOLOR_LIGHT);
    set_grey(&s->ambient, 0.05, GCOLOR_LIGHT);
    s->have_ambient = 1;
    Framebuffer fb;
    render(s, 40, 30, 1, 4, &fb);
    scene_destroy(s);
    return fb;
}

static void test_grey_world_models(void **state)
{
    (void)state;
    Framebuffer a = grey_world("rgb");
    const char *others[] = {"spectrum", "spectrum9", "bispectral"};
    for (int k = 0; k < 3; k++) {
        Framebuffer b = grey_world(others[k]);
        double sum = 0.0, worst = 0.0;
        int n = a.width * a.height;
        for (int i = 0; i < n; i++) {
            double la[3], lb[3];
            to_lab(a.pixels + 3 * i, la);
            to_lab(b.pixels + 3 * i, lb);
            double d = cd_delta_e2000(la, lb);
            sum += d;
            worst = fmax(worst, d);
        }
        print_message("grey world, rgb vs %s: mean deltaE2000 %.4f, max %.4f\n", others[k], sum / n, worst);
        if (strcmp(others[k], "spectrum") == 0)
            assert_true(sum / n < 1.0);
        framebuffer_free(&b);
    }
    framebuffer_free(&a);
}

/* ---- the depth limit: between two facing mirrors every pixel casts exactly depth + 1 rays ---- */

static void test_depth_limit(void **state)
{
    (void)state;
    const int depths[] = {0, 1, 7, 60};
    for (int i = 0; i < 4; i++) {
        Scene *s = new_scene("rgb", gvec3(0, 0, 0), gvec3(0, 0, -1), 30.0);
        add_plane(s, mirror(s, 0.9), gvec3(0, 0, -1), gvec3(0, 0, 1));
        add_plane(s, mirror(s, 0.9), gvec3(0, 0, 1), gvec3(0, 0, -1));
        Framebuffer fb;
        RenderStats st = render(s, 8, 8, 1, depths[i], &fb);
        assert_int_equal(st.rays, (uint64_t)64 * (uint64_t)(depths[i] + 1));
        for (int k = 0; k < 64 * 3; k++)
            assert_true(fb.pixels[k] == 0.0f);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

/* ---- NaN and infinity never reach a pixel ---- */

static int nan_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    (void)self;
    (void)out;
    double one[3] = {1, 1, 1};
    assert_int_equal(gcolor_from_rgb(result, one, GCOLOR_LIGHT), G_OK);
    /* NaN on one side of the sphere, infinity on the other */
    return gcolor_scale(result, result, sp->point.x > 0 ? NAN : INFINITY);
}

static void nan_destroy(GMaterial *m) { gmem_free(m); }

static const GMaterialClass nan_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "nan", .description = "emits NaN", .destroy = nan_destroy,
    .emission = nan_emission,
};

static void test_nonfinite_never_reaches_pixels(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 0, 4), gvec3(0, 0, 0), 40.0);
    GMaterial *m = gmem_calloc(1, sizeof *m);
    GError err;
    assert_int_equal(gmaterial_init(m, &nan_class, s->model, &err), G_OK);
    add_sphere(s, m, gvec3(0, 0, 0), 1.0);
    set_grey(&s->background, 0.25, GCOLOR_LIGHT);
    Framebuffer fb;
    RenderStats st = render(s, 16, 16, 4, 2, &fb);
    assert_true(st.nonfinite > 0);
    int black = 0;
    for (int i = 0; i < 16 * 16 * 3; i++) {
        assert_true(isfinite(fb.pixels[i]));
        black += fb.pixels[i] == 0.0f;
    }
    assert_true(black > 0);
    print_message("%llu non-finite samples dropped, %d black channels\n", (unsigned long long)st.nonfinite, black);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* With one sample a pixel, in every model (the spectral ones find a non-finite sample in the coordinates the pixel
 * converts to, gcolormodel_xyz_shows_nonfinite, not sample by sample): each sphere pixel's sample is counted once and
 * its pixel and wavelength values are black; the background's are not. */
static void test_nonfinite_one_sample_every_model(void **state)
{
    (void)state;
    const char *models[] = {"rgb", "spectrum", "spectrum9", "bispectral"};
    long counted[4];
    for (int i = 0; i < 4; i++) {
        Scene *s = new_scene(models[i], gvec3(0, 0, 4), gvec3(0, 0, 0), 40.0);
        GMaterial *m = gmem_calloc(1, sizeof *m);
        GError err;
        assert_int_equal(gmaterial_init(m, &nan_class, s->model, &err), G_OK);
        add_sphere(s, m, gvec3(0, 0, 0), 1.0);
        set_grey(&s->background, 0.25, GCOLOR_LIGHT);
        assert_int_equal(accel_build(s, &err), G_OK);
        RenderSettings rs = {.width = 16, .height = 16, .spp = 1, .depth = 2, .threads = 2, .quiet = 1,
                             .waves = i > 0, .cutoff = s->camera.cutoff}; /* rgb has no wavelengths */
        Framebuffer fb;
        RenderStats st;
        assert_int_equal(render_image(s, &rs, &fb, &st, &err), G_OK);
        assert_true(i == 0 || fb.nwaves > 0);
        long black = 0;
        for (int p = 0; p < 16 * 16; p++) {
            const float *px = fb.pixels + 3 * p, *wv = fb.waves ? fb.waves + (size_t)fb.nwaves * (size_t)p : NULL;
            int dark = px[0] == 0.0f && px[1] == 0.0f && px[2] == 0.0f;
            black += dark;
            for (int k = 0; wv && k < fb.nwaves; k++) {
                assert_true(isfinite(wv[k]));
                assert_true(dark ? wv[k] == 0.0f : wv[k] > 0.0f);
            }
            for (int ch = 0; ch < 3; ch++)
                assert_true(isfinite(px[ch]) && (dark || px[ch] > 0.0f));
        }
        assert_int_equal((long)st.nonfinite, black);
        counted[i] = black;
        print_message("%-10s %ld non-finite samples counted, as many black pixels\n", models[i], black);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
    assert_true(counted[0] > 0 && counted[0] < 16 * 16);
    for (int i = 1; i < 4; i++)
        assert_int_equal(counted[i], counted[0]);
}

/* ---- a material that fails stops the render: an error, and no image ---- */

static int failing_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                              GColor *result)
{
    (void)self, (void)sp, (void)in, (void)illum, (void)out, (void)result;
    return G_ERR_INVALID;
}

static const GMaterialClass failing_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "failing", .description = "fails", .destroy = nan_destroy,
    .reflection = failing_reflection,
};

static void test_material_error_stops_render(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 0, 4), gvec3(0, 0, 0), 40.0);
    GMaterial *m = gmem_calloc(1, sizeof *m);
    GError err;
    assert_int_equal(gmaterial_init(m, &failing_class, s->model, &err), G_OK);
    add_sphere(s, m, gvec3(0, 0, 0), 1.0);
    add_light(s, LIGHT_POINT, 10.0)->position = gvec3(0, 3, 3);
    assert_int_equal(accel_build(s, &err), G_OK);
    RenderSettings rs = {.width = 16, .height = 16, .spp = 1, .depth = 2, .threads = 2, .quiet = 1};
    Framebuffer fb = {0};
    RenderStats st;
    assert_int_equal(render_image(s, &rs, &fb, &st, &err), G_ERR_INVALID);
    assert_null(fb.pixels);
    print_message("%s\n", err.message);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert_point),
        cmocka_unit_test(test_mirror_background),
        cmocka_unit_test(test_glass_slab),
        cmocka_unit_test(test_absorption),
        cmocka_unit_test(test_shadows),
        cmocka_unit_test(test_area_and_spot_lights),
        cmocka_unit_test(test_grey_world_models),
        cmocka_unit_test(test_depth_limit),
        cmocka_unit_test(test_nonfinite_never_reaches_pixels),
        cmocka_unit_test(test_nonfinite_one_sample_every_model),
        cmocka_unit_test(test_material_error_stops_render),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
