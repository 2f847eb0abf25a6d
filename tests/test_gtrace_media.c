/* test_gtrace_media.c - participating media in the path tracer (examples/gtrace/media/): the transmittance of an
 * absorbing slab exp(-sigma_t d) in every colour model (rendered, and per band of the model), white furnaces of an
 * albedo-1 medium sphere (isotropic and Henyey-Greenstein g 0.7) that vanish, a chromatic medium sigma_t = (2, 6,
 * 9) that matches three single-channel renders within noise (spectral MIS over the bands), the phase functions'
 * normalisation and sampling density, and bad input refused at file:line:col. Images are tiny. */
#include "test_gtrace_common.h"
#include "media/medium.h"

#include "generic/builtins.h"

static const char *const models[] = {"rgb", "spectrum", "spectrum9", "bispectral"};
#define NMODELS ((int)(sizeof models / sizeof *models))

/* Loads a scene from text in a colour model (registering gtrace's types). */
static Scene *scene_text(const char *name, const char *text, const char *model)
{
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(write_text(name, text), model, &s, &err) != G_OK)
        fail_msg("%s: %s", name, err.message);
    return s;
}

/* Renders a loaded scene with the path integrator at its camera's size and samples. */
static void render_path(Scene *s, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = s->camera.width, .height = s->camera.height, .spp = s->camera.spp,
                         .depth = s->camera.depth, .threads = 2, .quiet = 1, .cutoff = 0.0,
                         .integrator = RENDER_PATH};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

/* ---- an absorbing slab: exp(-sigma_a d) ---- */

static void test_slab_transmittance(void **state)
{
    (void)state;
    /* a slab 0.8 thick in the middle of the view, bounded by an index-matched dielectric; the corners see the
     * background past it */
    static const char text[] =
        "medium ink homogeneous { sigma_a rgb 1 1 1 scale 1.25 }\n"
        "object box { min <-0.5, -0.5, -0.4> max <0.5, 0.5, 0.4> material dielectric { index 1 } interior ink }\n"
        "light background { color rgb 1 1 1 }\n"
        "camera orthographic { from <0, 0, 3> at <0, 0, 0> size 2 width 8 height 8 spp 1 depth 8 }\n";
    for (int k = 0; k < NMODELS; k++) {
        Scene *s = scene_text("slab.scene", text, models[k]);
        Framebuffer fb;
        render_path(s, &fb);
        double bg = luma(pixel(&fb, 0, 0)), in = luma(pixel(&fb, 4, 4));
        print_message("%s: background %.6f, through the slab %.6f, ratio %.6f (exp(-1) %.6f)\n", models[k], bg, in,
                      in / bg, exp(-1.0));
        assert_true(bg > 0.5);
        assert_near(in / bg, exp(-1.25 * 0.8), 1e-3);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

/* Per band: a chromatic coefficient's transmittance over d is exp(-sigma_t d) in each band of every model. */
static void test_band_transmittance(void **state)
{
    (void)state;
    static const char text[] = "medium ink homogeneous { sigma_a rgb 0.3 0.6 0.9 sigma_s rgb 0.1 0.1 0.1 }\n"
                               "object sphere { radius 1 material dielectric { index 1 } interior ink }\n";
    for (int k = 0; k < NMODELS; k++) {
        Scene *s = scene_text("band.scene", text, models[k]);
        assert_true(s->has_media);
        assert_int_equal(s->ninteriors, 1);
        const Medium *m = s->interiors[0].medium;
        GScratch *scratch = gscratch_create(0);
        assert_non_null(scratch);
        GColor light = {0};
        assert_int_equal(gcolor_alloc(&light, s->model), G_OK);
        assert_int_equal(gcolor_fill(&light, 1.0), G_OK);
        double d = 1.7, worst = 0.0;
        assert_int_equal(medium_attenuate(m, d, &light, scratch), G_OK);
        for (int b = 0; b < m->bands; b++) {
            double st = gcolor_band_value(&m->sigma_a, b) + gcolor_band_value(&m->sigma_s, b);
            assert_near(gcolor_band_value(&m->sigma_t, b), st, 1e-6);
            worst = fmax(worst, fabs(gcolor_band_value(&light, b) - exp(-st * d)));
        }
        print_message("%s: %d bands, largest error of exp(-sigma_t d) %.2g\n", models[k], m->bands, worst);
        assert_true(worst < 1e-3);
        gcolor_free(&light);
        gscratch_destroy(scratch);
        scene_destroy(s);
    }
}

/* ---- white furnace: albedo 1, uniform background ---- */

static double furnace(const char *model, const char *phase)
{
    char text[1024];
    snprintf(text, sizeof text,
             "medium cloud homogeneous { sigma_s rgb 1 1 1 scale 1.5 phase %s }\n"
             "object sphere { radius 1 material dielectric { index 1 } interior cloud }\n"
             "light background { color rgb 1 1 1 }\n"
             "camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 12 height 12 spp 64 depth 1000 }\n",
             phase);
    Scene *s = scene_text("furnace.scene", text, model);
    Framebuffer fb;
    render_path(s, &fb);
    double bg = (luma(pixel(&fb, 0, 0)) + luma(pixel(&fb, 11, 0)) + luma(pixel(&fb, 0, 11)) + luma(pixel(&fb, 11, 11)))
                / 4.0;
    double in = 0.0;
    for (int y = 4; y < 8; y++)
        for (int x = 4; x < 8; x++)
            in += luma(pixel(&fb, x, y)) / 16.0;
    print_message("%s, phase %s: background %.5f, sphere %.5f, ratio %.5f\n", model, phase, bg, in, in / bg);
    assert_true(bg > 0.5);
    framebuffer_free(&fb);
    scene_destroy(s);
    return in / bg;
}

static void test_white_furnace(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        assert_near(furnace(models[k], "isotropic { }"), 1.0, 0.01);
        assert_near(furnace(models[k], "hg { g 0.7 }"), 1.0, 0.01);
    }
}

/* ---- a chromatic medium against three single-channel ones ---- */

/* Renders a scattering slab seen through an orthographic window (every pixel sees the same: its values are
 * independent draws) with sigma_t = (r, g, b) and albedo 0.8; the caller frees fb. */
static void slab_render(double r, double g, double b, Framebuffer *fb)
{
    char text[1024];
    snprintf(text, sizeof text,
             "medium haze homogeneous { sigma_a rgb %g %g %g sigma_s rgb %g %g %g phase hg { g 0.3 } }\n"
             "object box { min <-50, -50, -0.25> max <50, 50, 0.25> material dielectric { index 1 } interior haze }\n"
             "light background { color rgb 1 1 1 }\n"
             "light directional { direction <0.3, -1, -0.2> irradiance rgb 2 2 2 }\n"
             "camera orthographic { from <0, 0, 3> at <0, 0, 0> size 1 width 16 height 16 spp 16 depth 64 }\n",
             0.2 * r, 0.2 * g, 0.2 * b, 0.8 * r, 0.8 * g, 0.8 * b);
    Scene *s = scene_text("chroma.scene", text, "rgb");
    render_path(s, fb);
    scene_destroy(s);
}

/* Mean and variance of channel c over the pixels. */
static void stats(const Framebuffer *fb, int c, double *mean, double *var)
{
    int n = fb->width * fb->height;
    double m = 0.0, v = 0.0;
    for (int i = 0; i < n; i++)
        m += fb->pixels[3 * i + c] / n;
    for (int i = 0; i < n; i++)
        v += (fb->pixels[3 * i + c] - m) * (fb->pixels[3 * i + c] - m) / (n - 1);
    *mean = m;
    *var = v;
}

static void test_chromatic_medium(void **state)
{
    (void)state;
    static const double sigma[3] = {2.0, 6.0, 9.0};
    Framebuffer chroma, single;
    slab_render(sigma[0], sigma[1], sigma[2], &chroma);
    int n = chroma.width * chroma.height;
    for (int c = 0; c < 3; c++) {
        slab_render(sigma[c], sigma[c], sigma[c], &single);
        double mc, vc, ms, vs;
        stats(&chroma, c, &mc, &vc);
        stats(&single, c, &ms, &vs);
        double sd = sqrt(vc + vs), sd_mean = sd / sqrt((double)n);
        int beyond = 0;
        for (int i = 0; i < n; i++)
            beyond += fabs(chroma.pixels[3 * i + c] - single.pixels[3 * i + c]) > 3.0 * sd;
        print_message("channel %d (sigma_t %g): chromatic %.5f +- %.5f, single %.5f +- %.5f; %d of %d pixels beyond "
                      "3 sigma\n", c, sigma[c], mc, sqrt(vc), ms, sqrt(vs), beyond, n);
        assert_true(ms > 0.05);
        assert_true(fabs(mc - ms) < 3.0 * sd_mean);
        assert_true(beyond <= n / 50);
        framebuffer_free(&single);
    }
    framebuffer_free(&chroma);
}

/* ---- phase functions ---- */

static void test_phase_normalised(void **state)
{
    (void)state;
    static const char text[] = "phase a isotropic { }\nphase b hg { g 0.7 }\nphase c hg { g -0.4 }\n";
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    GLibrary *lib = NULL;
    GReaderOptions opt = {0};
    if (greader_load_file(write_text("phase.scene", text), &opt, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    const char *names[] = {"a", "b", "c"};
    GVec3 in = gvec3(0, 0, 1);
    for (int k = 0; k < 3; k++) {
        const Phase *ph = glibrary_find(lib, gtrace_kind_phase, names[k]);
        assert_non_null(ph);
        /* the integral over the sphere (midpoint rule in cos theta) and the mean cosine */
        double sum = 0.0, mean_cos = 0.0;
        int steps = 20000;
        for (int i = 0; i < steps; i++) {
            double ct = -1.0 + (i + 0.5) * 2.0 / steps, st = sqrt(1.0 - ct * ct);
            double p = phase_eval(ph, in, gvec3(st, 0, ct)) * 2.0 * M_PI * 2.0 / steps;
            sum += p;
            mean_cos += p * ct;
        }
        assert_near(sum, 1.0, 1e-4);
        assert_near(mean_cos, ph->g, 1e-3);
        /* sampling: the density it returns is eval's, and the sampled mean cosine is g */
        Rng rng;
        rng_seed(&rng, 7, 11);
        double sampled = 0.0;
        int ns = 200000;
        for (int i = 0; i < ns; i++) {
            GVec3 out;
            double pdf = phase_sample(ph, in, rng_next(&rng), rng_next(&rng), &out);
            assert_near(pdf, phase_eval(ph, in, out), 1e-9 * (1.0 + pdf));
            sampled += out.z / ns;
        }
        print_message("phase %s: g %.3f, integral %.6f, mean cosine %.4f, sampled %.4f\n", names[k], ph->g, sum,
                      mean_cos, sampled);
        assert_near(sampled, ph->g, 0.01);
    }
    glibrary_destroy(lib);
}

/* ---- bad input ---- */

static void refused(const char *text, const char *where, const char *what)
{
    GError err;
    gerror_clear(&err);
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    assert_true(scene_load(write_text("bad.scene", text), NULL, &s, &err) < 0);
    assert_null(s);
    print_message("%s\n", err.message);
    assert_non_null(strstr(err.message, where));
    assert_non_null(strstr(err.message, what));
}

static void test_bad_input(void **state)
{
    (void)state;
    refused("\nmedium m homogeneous { sigma_a rgb 1 -1 1 }\n", "bad.scene:2:32:", "sigma_a");
    refused("medium m homogeneous {\n  sigma_s rgb 1 1 1 phase hg { g 1 } }\n", "bad.scene:2:34:", "(-1, 1)");
    refused("phase p hg { g -1.5 }\n", "bad.scene:1:16:", "(-1, 1)");
    refused("object sphere { radius 1 material lambert { } interior fog }\n", "bad.scene:1:", "fog");
    refused("camera pinhole { atmosphere nowhere }\n", "bad.scene:1:", "nowhere");
    refused("medium m homogeneous { scale -2 }\n", "bad.scene:1:30:", "[0, 1e+09]");
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slab_transmittance), cmocka_unit_test(test_band_transmittance),
        cmocka_unit_test(test_white_furnace),      cmocka_unit_test(test_chromatic_medium),
        cmocka_unit_test(test_phase_normalised),   cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
