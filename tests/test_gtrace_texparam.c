/* test_gtrace_texparam.c - textured parameters rendered by gtrace (kit/texparam.h): a reflectance read from an image
 * renders exactly what the image node over a white lambert renders, and a checker-driven phong exponent (or
 * conductor, plastic or dielectric roughness, plastic reflectance, layer thickness and albedo) renders, in each
 * cell of the checker, exactly the render with that cell's constant value; both integrators, pixel for pixel (every
 * float equal). */
#include "test_gtrace_common.h"

#include "embed/render_file.h"

/* Renders text (with %s replaced by a material) with integrator (0 whitted, 1 path) in model into img. */
static void render_scene(const char *name, const char *text, const char *material, int integrator, const char *model,
                   GtraceImage *img)
{
    char scene[4096];
    snprintf(scene, sizeof scene, text, material);
    const char *path = write_text(name, scene);
    GtraceRenderRequest rq = {.scene = path, .colormodel = model, .depth = -1, .integrator = integrator,
                              .threads = 2};
    GError err;
    gerror_clear(&err);
    int rc = gtrace_render_file(&rq, img, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    unlink(path);
}

static const char image_scene[] =
    "camera pinhole { from <0, 1.6, 5> at <0, 0.6, 0> fov 35 width 64 height 48 spp 2 depth 4 }\n"
    "light background { color rgb 0.08 0.1 0.14 }\n"
    "light point { position <-3, 5, 4> intensity rgb 40 40 40 }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
    "object box { min <-1.6, 0, -0.5> max <1.6, 1.6, -0.45> material %1$s }\n"
    "object sphere { center <0.6, 0.6, 0.5> radius 0.5 material %1$s }\n";

/* lambert { reflectance image { file F } } equals image { child lambert { reflectance rgb 1 1 1 } file F }. */
static void test_image_reflectance_equals_image_node(void **state)
{
    (void)state;
    char cwd[1024], textured[1400], node[1400];
    assert_non_null(getcwd(cwd, sizeof cwd));
    snprintf(textured, sizeof textured,
             "lambert { reflectance image { file \"%s/examples/scenes/label.png\" wrap clamp } }", cwd);
    snprintf(node, sizeof node,
             "image { child lambert { reflectance rgb 1 1 1 } file \"%s/examples/scenes/label.png\" wrap clamp }", cwd);
    static const char *const models[] = {"rgb", "spectrum"};
    for (int m = 0; m < 2; m++)
        for (int integrator = 0; integrator < 2; integrator++) {
            GtraceImage a, b;
            render_scene("tex.scene", image_scene, textured, integrator, models[m], &a);
            render_scene("node.scene", image_scene, node, integrator, models[m], &b);
            assert_int_equal(a.width, b.width);
            assert_int_equal(a.height, b.height);
            double sum = 0.0;
            for (int i = 0; i < 3 * a.width * a.height; i++)
                sum += a.pixels[i];
            assert_true(sum > 1.0);
            assert_memory_equal(a.pixels, b.pixels, sizeof(float) * 3 * (size_t)a.width * (size_t)a.height);
            gtrace_image_free(&a);
            gtrace_image_free(&b);
        }
}

static const char checker_scene[] =
    "colormodel rgb\n"
    "camera pinhole { from <0, 3, 3> at <0, 0, 0> fov 40 width 64 height 48 spp 2 depth 3 }\n"
    "light point { position <0, 1.5, 0.3> intensity rgb 4 4 4 }\n"
    "light background { color rgb 0.2 0.2 0.25 }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material %s }\n";

/* A material whose parameter (the format's %s in `form`) is texture, driven by checker { dims 2 frequency 1 }:
 * where the checker is 0 (a mask rendered with an emitter of radiance mix { by the same checker a black b white })
 * the pixel equals the render with the constant LO, where it is 1 the render with HI; and the two constant renders
 * differ there, so the comparison can fail. Both integrators. */
static void check_cells_by(const char *form, const char *lo, const char *hi, const char *texture)
{
    char textured[512], a_text[512], b_text[512];
    snprintf(textured, sizeof textured, form, texture);
    snprintf(a_text, sizeof a_text, form, lo);
    snprintf(b_text, sizeof b_text, form, hi);
    for (int integrator = 0; integrator < 2; integrator++) {
        GtraceImage t, a, b, mask;
        render_scene("c.scene", checker_scene, textured, integrator, NULL, &t);
        render_scene("c10.scene", checker_scene, a_text, integrator, NULL, &a);
        render_scene("c200.scene", checker_scene, b_text, integrator, NULL, &b);
        render_scene("cm.scene", checker_scene,
                     "emitter { radiance mix { by checker { dims 2 frequency 1 } a rgb 0 0 0 b rgb 1 1 1 } }",
                     integrator, NULL, &mask); /* the same integrator: the same positions in each pixel */
        int n = t.width * t.height, cells[2] = {0, 0}, differ[2] = {0, 0};
        float white = 0.0f;
        for (int i = 0; i < 3 * n; i++)
            white = mask.pixels[i] > white ? mask.pixels[i] : white;
        assert_true(white > 0.0f);
        for (int i = 0; i < n; i++) {
            const float *m = mask.pixels + 3 * i;
            int cell = m[0] == 0.0f && m[1] == 0.0f && m[2] == 0.0f ? 0 : m[1] == white ? 1 : -1;
            if (cell < 0) /* a pixel on a cell's edge: the checker is filtered there */
                continue;
            const GtraceImage *want = cell ? &b : &a;
            assert_memory_equal(t.pixels + 3 * i, want->pixels + 3 * i, 3 * sizeof(float));
            cells[cell]++;
            differ[cell] += memcmp(a.pixels + 3 * i, b.pixels + 3 * i, 3 * sizeof(float)) != 0;
        }
        assert_true(cells[0] > n / 5 && cells[1] > n / 5);
        assert_true(differ[0] > n / 50 && differ[1] > n / 50);
        gtrace_image_free(&t);
        gtrace_image_free(&a);
        gtrace_image_free(&b);
        gtrace_image_free(&mask);
    }
}

/* check_cells_by with the number parameter driven by checker { dims 2 frequency 1 range LO HI }. */
static void check_cells(const char *form, const char *lo, const char *hi)
{
    char range[128];
    snprintf(range, sizeof range, "checker { dims 2 frequency 1 range %s %s }", lo, hi);
    check_cells_by(form, lo, hi, range);
}

/* check_cells_by with the colour parameter a mix of LO and HI by the checker. */
static void check_color_cells(const char *form, const char *lo, const char *hi)
{
    char mix[256];
    snprintf(mix, sizeof mix, "mix { by checker { dims 2 frequency 1 } a %s b %s }", lo, hi);
    check_cells_by(form, lo, hi, mix);
}

/* phong's exponent: 10 and 200 in the cells. */
static void test_checker_exponent_cells(void **state)
{
    (void)state;
    check_cells("phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.5 0.5 0.5 exponent %s }", "10", "200");
}

/* conductor's roughness: 0.05 and 0.6 in the cells (exactly the tabulated ends of the range). */
static void test_checker_roughness_cells(void **state)
{
    (void)state;
    check_cells("conductor { metal Au roughness %s }", "0.05", "0.6");
}

/* plastic's roughness: 0.05 and 0.5 (the ends of its tabulated levels); its reflectance: a mix of two colours. */
static void test_checker_plastic_cells(void **state)
{
    (void)state;
    check_cells("plastic { reflectance rgb 0.2 0.4 0.6 roughness %s }", "0.05", "0.5");
    check_color_cells("plastic { reflectance %s roughness 0.2 }", "rgb 0.2 0.4 0.6", "rgb 0.7 0.1 0.1");
}

/* dielectric's roughness: 0.05 and 0.5 (the ends of its tabulated levels). */
static void test_checker_dielectric_cells(void **state)
{
    (void)state;
    check_cells("dielectric { glass BK7 roughness %s }", "0.05", "0.5");
}

/* layer's medium: its thickness 0.2 and 2 in the cells; its albedo a mix of two colours. */
static void test_checker_layer_cells(void **state)
{
    (void)state;
    check_cells("layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 } thickness %s "
                "albedo rgb 0.8 0.5 0.3 }", "0.2", "2");
    check_color_cells("layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 } thickness 1 "
                      "albedo %s }", "rgb 0.8 0.5 0.3", "rgb 0.2 0.6 0.9");
}

int main(void)
{
    GError err;
    if (gtrace_embed_register(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_image_reflectance_equals_image_node),
        cmocka_unit_test(test_checker_exponent_cells),
        cmocka_unit_test(test_checker_roughness_cells),
        cmocka_unit_test(test_checker_plastic_cells),
        cmocka_unit_test(test_checker_dielectric_cells),
        cmocka_unit_test(test_checker_layer_cells),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
