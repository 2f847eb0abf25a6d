/* test_gtrace_probe.c - image-based lighting in gtrace (`light probe`): a constant probe lights a Lambert
 * plane with rho * L for every technique and for the Monte Carlo reference, in an RGB and a spectral colour
 * model; a probe with one bright pixel casts the shadow on the side the documented direction convention says;
 * rays leaving the scene see the probe's value for their direction; the reference matches the library's
 * ground-truth irradiance on a non-constant, turned probe; the sampling distribution's density is consistent;
 * `gprobe compare` gives 0 for identical images and the analytic RMSE for a known difference; errors, the
 * command-line overrides and allocation failures while loading. Probes are tiny (64 x 32) and written into a
 * temporary directory. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"
#include "test_alloc.h"

#include <generic/services/image.h>

#include <sys/wait.h>
#include <unistd.h>

static char tmpdir[64];

static int setup(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gtrace_probe_XXXXXX");
    GError err;
    return mkdtemp(tmpdir) && gtrace_register_types(&err) == G_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *in_tmp(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", tmpdir, name);
    return buf;
}

#define PW 64
#define PH 32

/* Writes a lat-long probe (linear float EXR, exact) into the temporary directory. */
static void write_probe(const char *name, const float *px, char *path, size_t size)
{
    GProbe *p = NULL;
    GError err;
    assert_int_equal(gprobe_create(PW, PH, px, &p, &err), G_OK);
    in_tmp(name, path, size);
    if (gprobe_save(p, path, GPROBE_LATLONG, &err) != G_OK)
        fail_msg("gprobe_save: %s", err.message);
    gprobe_destroy(p);
}

static void write_probe_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* Loads a scene written from text (NULL with err filled when it fails). */
static Scene *load_scene(const char *text, const char *model, const ProbeOverride *ov, GError *err)
{
    char path[128];
    write_probe_text(in_tmp("probe.scene", path, sizeof path), text);
    Scene *s = NULL;
    gerror_clear(err);
    int rc = scene_load_with(path, model, ov, &s, err);
    return rc == G_OK ? s : NULL;
}

static Scene *load_ok(const char *text, const char *model, const ProbeOverride *ov)
{
    GError err;
    Scene *s = load_scene(text, model, ov, &err);
    if (!s)
        fail_msg("scene did not load: %s", err.message);
    return s;
}

/* Linear sRGB radiance along a ray, averaged over `repeats` traces with different generator streams. */
static void trace_rgb(Scene *s, GVec3 o, GVec3 d, int repeats, double rgb[3])
{
    GError err;
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    TraceCtx c = {.scene = s, .max_depth = 2, .cutoff = 0.0};
    c.scratch = gscratch_create(0);
    assert_non_null(c.scratch);
    assert_int_equal(gcolor_alloc(&c.unit, s->model), G_OK);
    assert_int_equal(gmaterial_refraction_index(NULL, NULL, &c.unit), G_OK);
    GColor out, sum;
    assert_int_equal(gcolor_alloc(&out, s->model), G_OK);
    assert_int_equal(gcolor_alloc(&sum, s->model), G_OK);
    Media none = {{NULL}, 0};
    for (int k = 0; k < repeats; k++) {
        rng_seed(&c.rng, 12345 + k, 777);
        Ray r = {o, gvec3_normalize(d), 0.0, INFINITY, 0.0, 0.0};
        assert_int_equal(whitted_trace(&c, &r, &none, 0, &out), G_OK);
        assert_int_equal(gcolor_add(&sum, &sum, &out), G_OK);
    }
    assert_int_equal(gcolor_scale(&sum, &sum, 1.0 / repeats), G_OK);
    assert_int_equal(gcolor_to_rgb(&sum, GCOLOR_LIGHT, rgb), G_OK);
    gcolor_free(&out);
    gcolor_free(&sum);
    gcolor_free(&c.unit);
    gscratch_destroy(c.scratch);
}

static void assert_rel(double a, double b, double tol, const char *what)
{
    if (!(fabs(a - b) <= tol * fabs(b)))
        fail_msg("%s: %.7g, expected %.7g within %.2g%%", what, a, b, 100 * tol);
}

/* ---- a constant probe lights an unoccluded Lambert plane with rho * L ---- */

/* Technique settings for the constant probe. Median cut and its adaptive form put each light at its
 * region's energy centroid carrying the region's whole power, which overestimates a uniform environment by
 * 1 / |mean direction of the region| (9% at 16 lights, 0.7% at 256), so they need many lights for 1%;
 * k-means is within 0.3% from 64 lights; the irradiance fit, whose error at one normal of a uniform
 * environment is about 1.6% with 32 lights, is within 0.6% with 64. The bases as an ambient term give the
 * uniform environment's irradiance pi L along every normal (SH and the ambient cube exactly, the SG fit with
 * an ambient term through its constant), so the plane shows rho L. */
static const char *const constant_settings[] = {
    "technique mediancut count 256", "technique adaptive count 256", "technique kmeans count 128",
    "technique irradiance count 64", "technique reference samples 256", "technique sh count 9",
    "technique ambientcube count 6", "technique sg-ambient count 4", "technique variance count 256",
};

static void test_constant_probe(void **state)
{
    (void)state;
    const double L[3] = {1.0, 0.5, 0.25}, rho = 0.5;
    float px[PW * PH * 3];
    for (int i = 0; i < PW * PH; i++)
        for (int k = 0; k < 3; k++)
            px[3 * i + k] = (float)L[k];
    char probe[128], text[1024];
    write_probe("constant.exr", px, probe, sizeof probe);
    const char *models[] = {"rgb", "spectrum"};
    const double tol_model[] = {0.01, 0.02}; /* the spectral model adds its own RGB round-trip error */
    for (int m = 0; m < 2; m++) {
        for (size_t t = 0; t < sizeof constant_settings / sizeof *constant_settings; t++) {
            if (m == 1 && t != 2 && t != 4)
                continue; /* the spectral model: one technique and the reference are enough */
            snprintf(
                text, sizeof text,
                "light probe { file \"%s\" %s }\n"
                "object plane { point <0, 0, 0> normal <0, 0, 1> material lambert { reflectance rgb %g %g %g } }\n",
                probe, constant_settings[t], rho, rho, rho);
            Scene *s = load_ok(text, models[m], NULL);
            double rgb[3], sky[3];
            trace_rgb(s, gvec3(0.3, 0.2, 3.0), gvec3(0, 0, -1), t == 4 ? 16 : 1, rgb);
            trace_rgb(s, gvec3(0, 0, 1), gvec3(0.3, -0.2, 0.8), 1, sky);
            print_message("%-9s %-32s plane %.5f %.5f %.5f (expected %.5f %.5f %.5f)\n", models[m],
                          constant_settings[t], rgb[0], rgb[1], rgb[2], rho * L[0], rho * L[1], rho * L[2]);
            for (int k = 0; k < 3; k++) {
                assert_rel(rgb[k], rho * L[k], tol_model[m], constant_settings[t]);
                assert_rel(sky[k], L[k], m == 0 ? 1e-5 : 0.02, "background");
            }
            scene_destroy(s);
        }
    }
}

/* ---- one bright pixel: the shadow falls where the convention says ---- */

/* Writes a black probe with pixel (pu, pv) of radiance P in every channel; returns the pixel's weight Q, its
 * irradiance on a surface facing it (Eq. 4: P times its solid angle at the centre, 2 pi^2 sin theta / (W H)). */
static double write_bright_pixel(const char *name, int pu, int pv, double P, char *path, size_t size)
{
    float px[PW * PH * 3];
    memset(px, 0, sizeof px);
    for (int k = 0; k < 3; k++)
        px[3 * (pv * PW + pu) + k] = (float)P;
    write_probe(name, px, path, size);
    return 2.0 * M_PI * M_PI * P * sin(M_PI * (pv + 0.5) / PH) / (PW * PH);
}

static void test_bright_pixel_shadow(void **state)
{
    (void)state;
    const int pu = 8, pv = 8;
    const double rho = 0.5;
    char probe[128], text[1024];
    const double Q = write_bright_pixel("pixel.exr", pu, pv, 100.0, probe, sizeof probe);
    /* probe.h: pixel (u, v) is centred on theta = pi (v + 0.5) / H, phi = pi - 2 pi (u + 0.5) / W, z up;
     * rotate <-90, 0, 0> turns the probe's +z into the world's +y and its +y into -z: (x, y, z) -> (x, z, -y).
     * Here phi = 132 degrees: the light comes from -x, -z and above (a mirrored map would put it at +x). */
    double theta = M_PI * (pv + 0.5) / PH, phi = M_PI - 2.0 * M_PI * (pu + 0.5) / PW;
    GVec3 local = gvec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
    GVec3 ell = gvec3(local.x, local.z, -local.y);
    assert_true(ell.x < -0.4 && ell.z < -0.4 && ell.y > 0.6);
    GVec3 C = gvec3(0, 1, 0);
    GVec3 shadow = gvec3_sub(C, gvec3_scale(ell, C.y / ell.y)); /* where the sphere's centre projects */
    GVec3 lit = gvec3(-shadow.x, 0, -shadow.z);
    const double expect = rho / M_PI * Q * ell.y;
    /* 16 samples are a jittered grid, 12 N-rooks strata */
    const char *settings[] = {"technique mediancut count 4", "technique adaptive count 4", "technique kmeans count 4",
                              "technique irradiance count 4", "technique reference samples 16",
                              "technique reference samples 12 shadows off"};
    for (int t = 0; t < 6; t++) {
        snprintf(text, sizeof text,
                 "light probe { file \"%s\" rotate <-90, 0, 0> %s }\n"
                 "material white lambert { reflectance rgb %g %g %g }\n"
                 "object plane { point <0, 0, 0> normal <0, 1, 0> material white }\n"
                 "object sphere { center <0, 1, 0> radius 0.5 material white }\n",
                 probe, settings[t], rho, rho, rho);
        Scene *s = load_ok(text, "rgb", NULL);
        double in_shadow[3], in_light[3];
        trace_rgb(s, gvec3_add(shadow, gvec3(0, 5, 0.01)), gvec3(0, -1, -0.002), 1, in_shadow);
        trace_rgb(s, gvec3_add(lit, gvec3(0, 5, 0.01)), gvec3(0, -1, -0.002), 1, in_light);
        print_message("%-44s shadow at (%.3f, 0, %.3f): %.6f, lit at (%.3f, 0, %.3f): %.6f (expected %.6f)\n",
                      settings[t], shadow.x, shadow.z, in_shadow[1], lit.x, lit.z, in_light[1], expect);
        for (int k = 0; k < 3; k++) {
            assert_rel(in_light[k], expect, t >= 4 ? 0.02 : 0.01, settings[t]);
            if (t == 5)
                assert_rel(in_shadow[k], expect, 0.02, "no shadows");
            else
                assert_true(in_shadow[k] <= 1e-3 * expect);
        }
        scene_destroy(s);
    }
}

/* ---- the path tracer: a technique's directional lights and the reference's estimator ---- */

/* Mean luma of a w x h render of the loaded scene with the given integrator. */
static double render_mean(Scene *s, int integrator, int spp)
{
    GError err;
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = 8, .height = 8, .spp = spp, .depth = 4, .threads = 2, .quiet = 1,
                         .integrator = integrator};
    Framebuffer fb;
    RenderStats st;
    if (render_image(s, &rs, &fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    double sum = 0.0;
    for (int i = 0; i < 64; i++)
        sum += luma(fb.pixels + 3 * i);
    framebuffer_free(&fb);
    return sum / 64;
}

/* One bright pixel over a Lambert plane, seen from above: the plane's radiance is rho / pi * Q * cos, Q the
 * pixel's weight (its irradiance perpendicular to it). Path tracing gets it from the directional light that
 * mediancut count 1 makes (NEE; when rays leaving the plane also saw the probe, its light was counted twice:
 * measured 1.84x at 256 spp) and from the reference's estimator (NEE by the probe's distribution, MIS), as Whitted
 * does. */
static void test_path_probe_lights(void **state)
{
    (void)state;
    const int pv = 8;
    const double rho = 0.5;
    char probe[128], text[1024];
    const double Q = write_bright_pixel("pixel_path.exr", 8, pv, 100.0, probe, sizeof probe);
    /* rotate <-90, 0, 0>: the world's up is the probe's +z, cos theta */
    const double expect = rho / M_PI * Q * cos(M_PI * (pv + 0.5) / PH);
    const char *settings[] = {"technique mediancut count 1", "technique reference samples 16"};
    for (int t = 0; t < 2; t++) {
        snprintf(text, sizeof text,
                 "light probe { file \"%s\" rotate <-90, 0, 0> %s }\n"
                 "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb %g %g %g } }\n"
                 "camera pinhole { from <0, 5, 0.01> at <0, 0, 0> up <0, 0, -1> fov 20 }\n",
                 probe, settings[t], rho, rho, rho);
        Scene *s = load_ok(text, "rgb", NULL);
        double path = render_mean(s, RENDER_PATH, 256), whitted = render_mean(s, RENDER_WHITTED, 1);
        print_message("%-32s path %.6f, Whitted %.6f, expected %.6f\n", settings[t], path, whitted, expect);
        assert_rel(path, expect, 0.01, settings[t]);
        assert_rel(whitted, expect, 0.01, settings[t]);
        scene_destroy(s);
    }
}

/* ---- rays that leave the scene see the probe ---- */

static void test_background(void **state)
{
    (void)state;
    const float A[3] = {2.0f, 1.0f, 0.5f}, B[3] = {0.1f, 0.2f, 0.3f}, Cc[3] = {0.3f, 3.0f, 0.7f};
    float px[PW * PH * 3];
    for (int v = 0; v < PH; v++)
        for (int u = 0; u < PW; u++) {
            /* upper half A, lower half B, and C in the upper half around phi = 90 degrees (u = 16) */
            const float *c = v >= PH / 2 ? B : (u >= 10 && u < 22) ? Cc : A;
            memcpy(px + 3 * (v * PW + u), c, sizeof A);
        }
    char probe[128], text[512];
    write_probe("blocks.exr", px, probe, sizeof probe);
    /* world = (x, z, -y) of the probe's direction (rotate <-90, 0, 0>) */
    struct {
        GVec3 world;
        const float *expect;
    } cases[] = {
        {{-0.707, 0.707, 0.0}, A},   /* probe (-0.707, 0, 0.707): theta 45, phi 180 */
        {{0.0, 0.707, -0.707}, Cc},  /* probe (0, 0.707, 0.707): theta 45, phi 90 */
        {{0.3, -0.9, 0.1}, B},       /* below the horizon */
    };
    const char *models[] = {"rgb", "spectrum"};
    for (int m = 0; m < 2; m++) {
        for (int scaled = 0; scaled < 2; scaled++) {
            snprintf(text, sizeof text, "light probe { file \"%s\" rotate <-90, 0, 0> technique kmeans count 8 %s }\n",
                     probe, scaled ? "scale 2" : "");
            Scene *s = load_ok(text, models[m], NULL);
            for (int i = 0; i < 3; i++) {
                double rgb[3];
                trace_rgb(s, gvec3(0, 0, 0), cases[i].world, 1, rgb);
                for (int k = 0; k < 3; k++)
                    assert_rel(rgb[k], (scaled ? 2.0 : 1.0) * cases[i].expect[k], m == 0 ? 1e-5 : 0.03, "background");
            }
            scene_destroy(s);
        }
    }
    /* background off: the scene's background colour (black) */
    snprintf(text, sizeof text, "light probe { file \"%s\" technique kmeans count 8 background off }\n", probe);
    Scene *s = load_ok(text, "rgb", NULL);
    assert_null(s->env);
    double rgb[3];
    trace_rgb(s, gvec3(0, 0, 0), gvec3(0, 0, 1), 1, rgb);
    assert_true(rgb[0] == 0.0 && rgb[1] == 0.0 && rgb[2] == 0.0);
    scene_destroy(s);
}

/* ---- the reference against the library's ground truth on a non-constant, turned probe ---- */

static void test_reference_ground_truth(void **state)
{
    (void)state;
    float px[PW * PH * 3];
    for (int v = 0; v < PH; v++)
        for (int u = 0; u < PW; u++) {
            double t = (v + 0.5) / PH, s = (u + 0.5) / PW;
            float *p = px + 3 * (v * PW + u);
            p[0] = (float)(0.2 + 1.5 * (1.0 - t) * (1.0 - t));
            p[1] = (float)(0.3 + 0.4 * s);
            p[2] = (float)(0.1 + 0.8 * t);
            if (abs(u - 20) <= 1 && abs(v - 9) <= 1) /* a hot spot */
                p[0] += 40.0f, p[1] += 30.0f, p[2] += 20.0f;
        }
    char probe[128], text[1024];
    write_probe("smooth.exr", px, probe, sizeof probe);
    GProbe *p = NULL;
    GError err;
    assert_int_equal(gprobe_create(PW, PH, px, &p, &err), G_OK);
    double R[9];
    gprobe_rotation_xyz(-90, 0, 30, R);
    GVec3 n = gvec3(R[3], R[4], R[5]); /* R^T (0, 1, 0): the world's up in probe space */
    double E[3];
    assert_int_equal(gprobe_irradiance(p, &n, 1, E, &err), G_OK);
    gprobe_destroy(p);
    const double rho = 0.6;
    const char *models[] = {"rgb", "spectrum"};
    for (int m = 0; m < 2; m++) {
        snprintf(text, sizeof text,
                 "light probe { file \"%s\" rotate <-90, 0, 30> technique reference samples 256 }\n"
                 "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb %g %g %g } }\n",
                 probe, rho, rho, rho);
        Scene *s = load_ok(text, models[m], NULL);
        double rgb[3];
        trace_rgb(s, gvec3(0.1, 3, 0.2), gvec3(0, -1, 0), 32, rgb);
        print_message("%-8s reference %.5f %.5f %.5f, ground truth %.5f %.5f %.5f\n", models[m], rgb[0], rgb[1], rgb[2],
                      rho / M_PI * E[0], rho / M_PI * E[1], rho / M_PI * E[2]);
        for (int k = 0; k < 3; k++)
            assert_rel(rgb[k], rho / M_PI * E[k], m == 0 ? 0.01 : 0.025, "reference");
        scene_destroy(s);
    }
}

/* ---- the sampling distribution ---- */

static void test_distribution(void **state)
{
    (void)state;
    float px[PW * PH * 3];
    for (int i = 0; i < PW * PH; i++)
        for (int k = 0; k < 3; k++)
            px[3 * i + k] = (float)(0.5 + 1.5 * ((i * 7919 + k * 104729) % 1000) / 1000.0);
    px[3 * (5 * PW + 40)] = 0.0f; /* one black pixel is never sampled */
    px[3 * (5 * PW + 40) + 1] = 0.0f;
    px[3 * (5 * PW + 40) + 2] = 0.0f;
    GProbe *p = NULL;
    GError err;
    assert_int_equal(gprobe_create(PW, PH, px, &p, &err), G_OK);
    GColorModel *model = model_or_skip("rgb");
    ProbeDist d;
    assert_int_equal(probe_dist_build(&d, p, model, &err), G_OK);
    const int n = 256; /* a 256 x 256 grid of stratified points */
    double inv_sum = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            int u, v;
            GVec3 dir;
            double pdf = probe_dist_sample(&d, p, (i + 0.5) / n, (j + 0.5) / n, &u, &v, &dir);
            assert_true(pdf > 0.0);
            assert_false(u == 40 && v == 5);
            double x, y;
            gprobe_position(p, dir, &x, &y);
            assert_int_equal((int)floor(x), u);
            assert_int_equal((int)floor(y), v);
            assert_rel(probe_dist_pdf(&d, p, dir), pdf, 1e-9, "pdf");
            inv_sum += 1.0 / pdf;
        }
    /* E[1 / pdf] is the solid angle of the support: the sphere less one pixel */
    double omega_px = 2.0 * M_PI / PW * (cos(M_PI * 5 / PH) - cos(M_PI * 6 / PH));
    assert_rel(inv_sum / (n * n), 4.0 * M_PI - omega_px, 0.01, "mean of 1/pdf");
    probe_dist_free(&d);
    probe_dist_free(&d); /* twice is harmless */
    gcolormodel_destroy(model);
    gprobe_destroy(p);
}

/* ---- gprobe compare ---- */

static int run_compare(const char *args, char *out, size_t size)
{
    const char *b = getenv("GENERIC_BUILD_DIR");
    char tool[512], cmd[2048], log[128];
    snprintf(tool, sizeof tool, "%s/bin/gprobe", b ? b : "build");
    if (access(tool, X_OK) != 0)
        skip();
    snprintf(cmd, sizeof cmd, "'%s' compare %s > '%s' 2>&1", tool, args, in_tmp("compare.log", log, sizeof log));
    int st = system(cmd);
    FILE *f = fopen(log, "r");
    size_t n = f ? fread(out, 1, size - 1, f) : 0;
    out[n] = '\0';
    if (f)
        fclose(f);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void write_image(const char *name, const float *px, int w, int h, char *path, size_t size)
{
    GImage img;
    GError err;
    assert_int_equal(gimage_create(&img, w, h, 3, &err), G_OK);
    memcpy(img.pixels, px, sizeof(float) * 3 * w * h);
    in_tmp(name, path, size);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_OK);
    gimage_free(&img);
}

static double field(const char *out, const char *line, const char *key)
{
    const char *l = strstr(out, line);
    if (!l)
        fail_msg("no '%s' line in: %s", line, out);
    const char *k = strstr(l, key);
    assert_non_null(k);
    return strtod(k + strlen(key), NULL);
}

static void test_compare_tool(void **state)
{
    (void)state;
    enum { W = 8, H = 4, N = W * H };
    float ref[N * 3], img[N * 3], mask[N * 3], open[N * 3];
    for (int i = 0; i < N * 3; i++)
        ref[i] = img[i] = open[i] = (float)(0.25 + 0.5 * ((i * 37) % 11) / 11.0);
    memset(mask, 0, sizeof mask);
    const int changed[4] = {3, 9, 17, 30}, extra = 22; /* four pixels differ by d in red */
    const double d = 0.3;
    for (int i = 0; i < 4; i++)
        img[3 * changed[i]] += (float)d;
    for (int i = 0; i < 5; i++) {
        int p = i < 4 ? changed[i] : extra;
        for (int k = 0; k < 3; k++) {
            mask[3 * p + k] = 1.0f;
            open[3 * p + k] = ref[3 * p + k] * 1.5f; /* a third of the light blocked in the reference */
        }
    }
    char a[128], r[128], mk[128], op[128], wm[128], args[1024], out[2048];
    write_image("a.exr", img, W, H, a, sizeof a);
    write_image("r.exr", ref, W, H, r, sizeof r);
    write_image("mask.exr", mask, W, H, mk, sizeof mk);
    write_image("open.exr", open, W, H, op, sizeof op);
    /* identical images */
    snprintf(args, sizeof args, "'%s' '%s'", r, r);
    assert_int_equal(run_compare(args, out, sizeof out), 0);
    assert_true(field(out, "whole", "rmse ") == 0.0);
    /* a known difference: sqrt(4 d^2 / (3 N)) over the image, sqrt(4 d^2 / (3 * 5)) in a 5-pixel mask */
    snprintf(args, sizeof args, "'%s' '%s' --mask '%s'", a, r, mk);
    assert_int_equal(run_compare(args, out, sizeof out), 0);
    print_message("%s", out);
    assert_near(field(out, "whole", "rmse "), sqrt(4 * d * d / (3.0 * N)), 1e-5);
    assert_near(field(out, "shadow", "rmse "), sqrt(4 * d * d / 15.0), 1e-5);
    assert_near(field(out, "shadow", "pixels "), 5, 0);
    /* the same mask found from the unshadowed image (luminance below 0.9 of it), and written out */
    snprintf(args, sizeof args, "'%s' '%s' --unshadowed '%s' --write-mask '%s'", a, r, op,
             in_tmp("m.exr", wm, sizeof wm));
    assert_int_equal(run_compare(args, out, sizeof out), 0);
    assert_near(field(out, "shadow", "rmse "), sqrt(4 * d * d / 15.0), 1e-5);
    GImage m;
    GError err;
    assert_int_equal(gimage_read(wm, GIMAGE_READ_RGB, &m, &err), G_OK);
    for (int i = 0; i < N; i++)
        assert_true(m.pixels[3 * i] == mask[3 * i]);
    gimage_free(&m);
    /* a threshold above the blocked share finds no shadows */
    snprintf(args, sizeof args, "'%s' '%s' --unshadowed '%s' --threshold 0.5", a, r, op);
    assert_int_equal(run_compare(args, out, sizeof out), 0);
    assert_near(field(out, "shadow", "pixels "), 0, 0);
    /* errors: sizes differ, missing file, bad usage */
    float small[3 * 4] = {0};
    char sm[128];
    write_image("small.exr", small, 2, 2, sm, sizeof sm);
    snprintf(args, sizeof args, "'%s' '%s'", a, sm);
    assert_int_equal(run_compare(args, out, sizeof out), 1);
    assert_non_null(strstr(out, "is 2x2"));
    assert_int_equal(run_compare("only_one.exr", out, sizeof out), 2);
    snprintf(args, sizeof args, "'%s' '%s/missing.exr'", a, tmpdir);
    assert_int_equal(run_compare(args, out, sizeof out), 1);
    assert_non_null(strstr(out, "missing.exr"));
}

/* ---- errors and command-line overrides ---- */

static void expect_load_error(const char *text, const ProbeOverride *ov, const char *what)
{
    GError err;
    Scene *s = load_scene(text, NULL, ov, &err);
    if (s)
        fail_msg("loaded, but expected an error with '%s'", what);
    print_message("%s\n", err.message);
    if (!strstr(err.message, what))
        fail_msg("error '%s' does not say '%s'", err.message, what);
}

static void test_errors_and_overrides(void **state)
{
    (void)state;
    float px[PW * PH * 3];
    for (int i = 0; i < PW * PH * 3; i++)
        px[i] = 1.0f;
    char probe[128], text[1024];
    write_probe("ones.exr", px, probe, sizeof probe);
    snprintf(text, sizeof text, "\nlight probe { file \"%s\" technique lightcuts }\n", probe);
    expect_load_error(text, NULL, "probe.scene:2:");
    expect_load_error(text, NULL, "unknown probe technique 'lightcuts'");
    snprintf(text, sizeof text, "light probe { file \"%s\" technique mediancut count 12 }\n", probe);
    expect_load_error(text, NULL, "power of two");
    snprintf(text, sizeof text, "light probe { file \"%s\" technique kmeans shadows off }\n", probe);
    expect_load_error(text, NULL, "only for technique reference");
    expect_load_error("light probe { technique kmeans }\n", NULL, "needs its image");
    expect_load_error("\n\nlight probe { file \"nowhere.hdr\" }\n", NULL, "probe.scene:3:7: light probe:");
    expect_load_error("light probe { file \"nowhere.hdr\" }\n", NULL, "nowhere.hdr");
    /* relative paths resolve against the scene file's directory */
    Scene *s = load_ok("light probe { file \"ones.exr\" technique adaptive count 8 }\n", NULL, NULL);
    assert_int_equal(s->nlights, 8);
    scene_destroy(s);
    /* overrides */
    snprintf(text, sizeof text, "light probe { file \"%s\" technique adaptive count 8 }\n", probe);
    ProbeOverride ov = {.shadows = -1, .count = 5};
    s = load_ok(text, NULL, &ov);
    assert_int_equal(s->nlights, 5);
    assert_int_equal(s->lights[0]->kind, LIGHT_DIRECTIONAL);
    scene_destroy(s);
    ov = (ProbeOverride){.shadows = 0, .technique = "reference", .samples = 9, .scale = 3.0};
    s = load_ok(text, NULL, &ov);
    assert_int_equal(s->nlights, 1);
    assert_int_equal(s->lights[0]->kind, LIGHT_PROBE);
    assert_int_equal(s->lights[0]->samples, 9);
    assert_int_equal(s->lights[0]->env->shadows, 0);
    double sky[3];
    trace_rgb(s, gvec3(0, 0, 0), gvec3(0, 0, 1), 1, sky);
    assert_rel(sky[1], 3.0, 1e-5, "scaled background");
    scene_destroy(s);
    ov = (ProbeOverride){.shadows = -1, .file = "/nonexistent/probe.exr"};
    expect_load_error(text, &ov, "/nonexistent/probe.exr");
    ov = (ProbeOverride){.shadows = -1, .technique = "mediancut", .count = 6};
    expect_load_error(text, &ov, "power of two");
    ov = (ProbeOverride){.shadows = -1, .technique = "nope"};
    expect_load_error(text, &ov, "unknown probe technique");
    ov = (ProbeOverride){.shadows = -1, .count = 4};
    expect_load_error("light directional { direction <0, -1, 0> irradiance rgb 1 1 1 }\n", &ov, "no `light probe`");
    snprintf(text, sizeof text, "light probe { file \"%s\" }\nlight probe { file \"%s\" }\n", probe, probe);
    expect_load_error(text, NULL, "already the background");
}

/* ---- allocation failures while loading a probe scene fail cleanly ---- */

static void test_allocation_failures(void **state)
{
    (void)state;
    float px[PW * PH * 3];
    for (int i = 0; i < PW * PH * 3; i++)
        px[i] = (float)(i % 5);
    char probe[128], text[1024], path[128];
    write_probe("alloc.exr", px, probe, sizeof probe);
    for (int variant = 0; variant < 2; variant++) {
        snprintf(text, sizeof text,
                 "light probe { file \"%s\" %s }\n"
                 "object plane { point <0, 0, 0> normal <0, 0, 1> material lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
                 "camera pinhole { from <0, -3, 2> at <0, 0, 0> up <0, 0, 1> width 4 height 3 }\n",
                 probe, variant ? "technique reference samples 4" : "technique adaptive count 4");
        write_probe_text(in_tmp("alloc.scene", path, sizeof path), text);
        static TuAlloc alloc;
        int failures = 0, k;
        for (k = 0; k < 5000; k++) {
            alloc = (TuAlloc){.fail_call = k + 1, .fail_after = 1}; /* k calls succeed */
            tu_alloc_install(&alloc);
            Scene *s = NULL;
            Framebuffer fb = {0};
            RenderStats st;
            GError err;
            int rc = scene_load(path, NULL, &s, &err);
            if (rc == G_OK)
                rc = accel_build(s, &err);
            if (rc == G_OK) {
                RenderSettings rs = {.width = 4, .height = 3, .spp = 1, .depth = 2, .threads = 1, .quiet = 1};
                rc = render_image(s, &rs, &fb, &st, &err);
            }
            framebuffer_free(&fb);
            scene_destroy(s);
            gmem_set_allocator(NULL);
            if (rc == G_OK)
                break;
            assert_true(rc < 0);
            failures++;
        }
        print_message("variant %d: failed cleanly at each of the first %d allocations, then succeeded\n", variant,
                      failures);
        assert_true(k < 5000 && failures > 10);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_constant_probe),       cmocka_unit_test(test_bright_pixel_shadow),
        cmocka_unit_test(test_background),           cmocka_unit_test(test_reference_ground_truth),
        cmocka_unit_test(test_distribution),         cmocka_unit_test(test_compare_tool),
        cmocka_unit_test(test_errors_and_overrides), cmocka_unit_test(test_allocation_failures),
        cmocka_unit_test(test_path_probe_lights),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
