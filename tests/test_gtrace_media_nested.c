/* test_gtrace_media_nested.c - media bounded by dielectrics in the path tracer, in every colour model:
 *
 * - an index-matched boundary passes light unchanged: an empty `dielectric { index 1 }` box shows the light behind it
 *   exactly; an absorbing atmosphere with such a box of the same medium in it transmits exactly what the atmosphere
 *   alone does, and both exp(-sigma_t d); in a scattering atmosphere lit by a point light, the box (its camera rays,
 *   its scattering events' shadow rays leaving it) changes no pixel beyond noise;
 * - an absorbing liquid in a glass slab (index 1.5 around a liquid of index 1.33, seen head-on against a white
 *   sky) transmits, band by band, what the interfaces' Fresnel factors and the liquid's exp(-sigma_t d) give,
 *   multiple reflections between the interfaces included (the incoherent sum over a stack of layers). */
#include "test_gtrace_common.h"
#include "test_gtrace_pixel_stats.h"
#include "media/medium.h"

#include "generic/builtins.h"

static const char *const models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
#define NMODELS ((int)(sizeof models / sizeof *models))

/* Under AddressSanitizer (several times slower) fewer samples. */
#ifdef __SANITIZE_ADDRESS__
#define SANITIZED 1
#else
#define SANITIZED 0
#endif

/* Loads a scene from text in a colour model and builds its accelerator. */
static Scene *scene_text(const char *name, const char *text, const char *model)
{
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(write_text(name, text), model, &s, &err) != G_OK)
        fail_msg("%s: %s", name, err.message);
    if (accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    return s;
}

/* Renders s with the path integrator at its camera's size and samples (the default sampler). */
static void render_path(Scene *s, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    RenderSettings rs = {.width = s->camera.width, .height = s->camera.height, .spp = s->camera.spp,
                         .depth = s->camera.depth, .threads = 2, .quiet = 1, .integrator = RENDER_PATH};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
    assert_int_equal(st.capped, 0);
}

/* ---- an index-matched boundary ---- */

/* The atmosphere ink (absorbing only) between the camera and a glowing wall 4 units away; box: an index-matched box
 * in the way, empty or (inked) bounding ink too; atmosphere: the camera is in ink. */
static void absorbing_text(char *text, size_t size, int atmosphere, int box, int inked)
{
    snprintf(text, size,
             "medium ink homogeneous { sigma_a rgb 0.2 0.35 0.5 }\n"
             "object plane { point <0, 0, -1> normal <0, 0, 1> material emitter { radiance rgb 1 1 1 } }\n"
             "%s%s\n"
             "camera orthographic { from <0, 0, 3> at <0, 0, 0> size 2 width 4 height 4 spp 1 depth 8 %s }\n",
             box ? "object box { min <-2, -2, -0.4> max <2, 2, 0.4> material dielectric { index 1 }" : "",
             box ? (inked ? " interior ink }" : " }") : "", atmosphere ? "atmosphere ink" : "");
}

static void test_index_matched_absorbing(void **state)
{
    (void)state;
    char text[1024];
    for (int k = 0; k < NMODELS; k++) {
        const char *model = models[k];
        Framebuffer fb[4];
        Scene *s[4];
        /* 0: the wall alone; 1: an empty box before it; 2: the atmosphere; 3: the atmosphere with a box of ink */
        static const int config[4][3] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}};
        for (int i = 0; i < 4; i++) {
            absorbing_text(text, sizeof text, config[i][0], config[i][1], config[i][2]);
            s[i] = scene_text("matched.scene", text, model);
            render_path(s[i], &fb[i]);
        }
        /* the expected transmittance: exp(-4 sigma_t) band by band, through the model's own conversion */
        const Medium *ink = s[2]->atmosphere;
        assert_non_null(ink);
        GColor e = {0}, tr = {0};
        assert_int_equal(gcolor_alloc(&e, s[2]->model), G_OK);
        assert_int_equal(gcolor_alloc(&tr, s[2]->model), G_OK);
        const double one[3] = {1, 1, 1};
        assert_int_equal(gcolor_from_rgb(&e, one, GCOLOR_LIGHT), G_OK);
        assert_int_equal(gcolor_exp(&tr, &ink->sigma_t, -4.0), G_OK);
        assert_int_equal(gcolor_mul(&tr, &tr, &e), G_OK);
        double want_wall[3], want[3];
        light_rgb(&e, want_wall);
        light_rgb(&tr, want);
        double worst_empty = 0.0, worst_box = 0.0, worst_exp = 0.0;
        for (int y = 0; y < 4; y++)
            for (int x = 0; x < 4; x++)
                for (int c = 0; c < 3; c++) {
                    double wall = pixel(&fb[0], x, y)[c], empty = pixel(&fb[1], x, y)[c];
                    double alone = pixel(&fb[2], x, y)[c], boxed = pixel(&fb[3], x, y)[c];
                    assert_near(wall, want_wall[c], 1e-5);
                    worst_empty = fmax(worst_empty, fabs(empty - wall));
                    worst_box = fmax(worst_box, fabs(boxed / alone - 1.0));
                    worst_exp = fmax(worst_exp, fabs(alone / want[c] - 1.0));
                }
        print_message("%s: empty index-matched box: largest change %.2g; atmosphere alone against exp(-sigma_t d): "
                      "%.2g relative; with a box of the same medium: %.2g relative (transmittance %.4f %.4f %.4f)\n",
                      model, worst_empty, worst_exp, worst_box, want[0] / want_wall[0], want[1] / want_wall[1],
                      want[2] / want_wall[2]);
        assert_true(worst_empty <= 1e-6);
        assert_true(worst_exp <= 1e-4);
        /* not bit for bit: a ray leaving a surface starts a hair off it (offset_origin), so each crossing shortens
         * the path through the medium by that much (3.5e-5 of the transmittance here) */
        assert_true(worst_box <= 1e-4);
        gcolor_free(&e);
        gcolor_free(&tr);
        for (int i = 0; i < 4; i++) {
            framebuffer_free(&fb[i]);
            scene_destroy(s[i]);
        }
    }
}

enum { FOG_W = 8, FOG_H = 6, FOG_N = FOG_W * FOG_H };

static void test_index_matched_scattering(void **state)
{
    (void)state;
    /* a scattering atmosphere over a grey floor, lit by a point light; with a box of the same medium (index-matched)
     * around the middle of the view, holding the light's side of the shadow rays of its scattering events */
    static const char base[] =
        "medium fog homogeneous { sigma_a rgb 0.1 0.15 0.2 sigma_s rgb 0.6 0.5 0.4 phase hg { g 0.4 } }\n"
        "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.6 0.6 0.6 } }\n"
        "light point { position <0.5, 2.2, 0.5> intensity rgb 4 4 4 }\n"
        "camera pinhole { from <0, 1, 3> at <0, 0.6, 0> fov 50 width 8 height 6 spp 1 depth 32 atmosphere fog }\n";
    static const char box[] = "object box { min <-0.7, 0.3, -0.7> max <0.7, 1.4, 0.7> material dielectric { index 1 } "
                              "interior fog }\n";
    char text[2048];
    const int n = SANITIZED ? 64 : 512;
    const int nmodels = SANITIZED ? 1 : NMODELS;
    double *mean = malloc(2 * 3 * FOG_N * sizeof *mean), *var = malloc(2 * 3 * FOG_N * sizeof *var);
    assert_non_null(mean);
    assert_non_null(var);
    for (int k = 0; k < nmodels; k++) {
        for (int i = 0; i < 2; i++) {
            snprintf(text, sizeof text, "%s%s", base, i ? box : "");
            Scene *s = scene_text("fog.scene", text, models[k]);
            assert_true(s->has_media);
            pixel_stats(s, FOG_W, FOG_H, i * n, n, mean + 3 * FOG_N * i, var + 3 * FOG_N * i);
            scene_destroy(s);
        }
        int tested = 0, beyond = 0;
        double sum_z2 = 0.0, sum_d = 0.0, sum_v = 0.0, sum_m = 0.0;
        for (int j = 0; j < 3 * FOG_N; j++) {
            double d = mean[3 * FOG_N + j] - mean[j], v = var[j] + var[3 * FOG_N + j];
            assert_true(v > 0.0);
            double z = d / sqrt(v);
            tested++;
            beyond += fabs(z) > 3.0;
            sum_z2 += z * z;
            sum_d += d;
            sum_v += v;
            sum_m += mean[j];
        }
        print_message("%s: %d pixel channels, %d beyond 3 sigma, mean z^2 %.3f; summed, boxed minus open %.4f +- %.4f "
                      "(of %.3f)\n", models[k], tested, beyond, sum_z2 / tested, sum_d, sqrt(sum_v), sum_m);
        assert_true(beyond <= 2 + tested / 50);
        assert_true(sum_z2 / tested < 1.5);
        assert_true(fabs(sum_d) <= 4.0 * sqrt(sum_v)); /* 4: see test_gtrace_media_chroma.c */
        if (!SANITIZED) /* noise small against the light: the test can tell */
            assert_true(sqrt(sum_v) < 0.06 * sum_m);
    }
    free(mean);
    free(var);
}

/* ---- an absorbing liquid in a glass ---- */

/* A layer or an interface seen along one line: reflectance from the front and from the back, transmittance (the
 * same both ways). */
typedef struct Layer {
    double rf, rb, t;
} Layer;

/* a then b, with every multiple reflection between them (incoherent). */
static Layer stack(Layer a, Layer b)
{
    double k = 1.0 / (1.0 - a.rb * b.rf);
    return (Layer){a.rf + a.t * a.t * b.rf * k, b.rb + b.t * b.t * a.rb * k, a.t * b.t * k};
}

/* An interface between indices n1 and n2 at normal incidence. */
static Layer interface(double n1, double n2)
{
    double r = (n1 - n2) / (n1 + n2);
    return (Layer){r * r, r * r, 1.0 - r * r};
}

static void test_liquid_in_glass(void **state)
{
    (void)state;
    /* glass from z -0.5 to 0.5, the liquid from -0.3 to 0.3 in it (d = 0.6); the light reflected back towards the
     * camera meets a black wall behind it, so a pixel is the sky's light times the stack's transmittance */
    static const char text[] =
        "medium ink homogeneous { sigma_a rgb 0.4 1.2 2.5 }\n"
        "object box { min <-50, -50, -0.5> max <50, 50, 0.5> material dielectric { index 1.5 } }\n"
        "object box { min <-40, -40, -0.3> max <40, 40, 0.3> material dielectric { index 1.33 } interior ink }\n"
        "object plane { point <0, 0, 5> normal <0, 0, -1> material lambert { reflectance rgb 0 0 0 } }\n"
        "light background { color rgb 1 1 1 }\n"
        "camera orthographic { from <0, 0, 3> at <0, 0, 0> size 1 width 4 height 4 spp 16384 depth 64 }\n";
    const double d = 0.6;
    const int nmodels = SANITIZED ? 1 : NMODELS;
    for (int k = 0; k < nmodels; k++) {
        Scene *s = scene_text("liquid.scene", text, models[k]);
        if (SANITIZED)
            s->camera.spp = 256;
        Framebuffer fb;
        render_path(s, &fb);
        assert_int_equal(s->ninteriors, 1);
        const Medium *ink = s->interiors[0].medium;
        /* the expected light: per band, the stack's transmittance times the sky's light in that band */
        GColor want = {0}, once = {0}, mask = {0};
        assert_int_equal(gcolor_alloc(&want, s->model), G_OK);
        assert_int_equal(gcolor_alloc(&once, s->model), G_OK);
        assert_int_equal(gcolor_alloc(&mask, s->model), G_OK);
        Layer glass = {0.0, 0.0, 1.0};
        double lo = 1.0, hi = 0.0;
        for (int b = 0; b < ink->bands; b++) {
            Layer liquid = {0.0, 0.0, exp(-gcolor_band_value(&ink->sigma_t, b) * d)};
            Layer all = stack(stack(stack(stack(stack(stack(interface(1.0, 1.5), glass), interface(1.5, 1.33)), liquid),
                                    interface(1.33, 1.5)), glass), interface(1.5, 1.0));
            assert_int_equal(gcolor_band_mask(&mask, b), G_OK);
            assert_int_equal(gcolor_add_scaled(&want, &mask, all.t), G_OK);
            /* the product of the Fresnel factors and exp(-sigma_t d) alone: one pass, no inter-reflection */
            double t_once = pow(interface(1.0, 1.5).t * interface(1.5, 1.33).t, 2.0) * liquid.t;
            assert_int_equal(gcolor_add_scaled(&once, &mask, t_once), G_OK);
            lo = fmin(lo, all.t);
            hi = fmax(hi, all.t);
        }
        assert_int_equal(gcolor_mul(&want, &want, &s->background), G_OK);
        assert_int_equal(gcolor_mul(&once, &once, &s->background), G_OK);
        double w[3], w1[3], sky[3];
        light_rgb(&want, w);
        light_rgb(&once, w1);
        light_rgb(&s->background, sky);
        double got[3] = {0}, sd[3] = {0};
        for (int c = 0; c < 3; c++) {
            double m = 0.0, v = 0.0;
            for (int p = 0; p < 16; p++)
                m += pixel(&fb, p % 4, p / 4)[c] / 16.0;
            for (int p = 0; p < 16; p++)
                v += (pixel(&fb, p % 4, p / 4)[c] - m) * (pixel(&fb, p % 4, p / 4)[c] - m) / 15.0;
            got[c] = m;
            sd[c] = sqrt(v / 16.0);
        }
        print_message("%s: band transmittance %.4f .. %.4f; rendered %.5f %.5f %.5f, stack %.5f %.5f %.5f "
                      "(relative %+.2e %+.2e %+.2e, noise %.1e; single pass without the inter-reflections "
                      "%.5f %.5f %.5f)\n",
                      models[k], lo, hi, got[0], got[1], got[2], w[0], w[1], w[2], got[0] / w[0] - 1.0,
                      got[1] / w[1] - 1.0, got[2] / w[2] - 1.0, sd[0] / w[0], w1[0], w1[1], w1[2]);
        for (int c = 0; c < 3; c++) {
            assert_true(w[c] > 0.05 * sky[c]);
            /* within 1e-3 (the single pass, without the inter-reflections, is 1.5e-3 below in rgb's red) */
            assert_near(got[c], w[c], (SANITIZED ? 1e-2 : 1e-3) * w[c]);
            assert_true(sd[c] < (SANITIZED ? 3e-3 : 5e-4) * w[c]);
        }
        gcolor_free(&want);
        gcolor_free(&once);
        gcolor_free(&mask);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_index_matched_absorbing),
        cmocka_unit_test(test_index_matched_scattering),
        cmocka_unit_test(test_liquid_in_glass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
