/* test_texture_swatch.c - `gmat swatch`, run as a program (GENERIC_BUILD_DIR/bin/gmat): the pixels of a flat
 * checker swatch and of a sphere are the analytic shading of the lights the tool documents (a key light of
 * irradiance pi * 0.85 from (-0.5, 0.6, 1), ambient 0.15), and bad input fails with a clear message. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <generic/services/image.h>
#include "generic/builtins.h"
#include "test_util.h"

static char gmat[4096], matfile[4200], png[4200];

static int setup(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    snprintf(gmat, sizeof gmat, "%s/bin/gmat", build ? build : "build");
    snprintf(matfile, sizeof matfile, "%s/tests/test_texture_swatch.mat", build ? build : "build");
    snprintf(png, sizeof png, "%s/tests/test_texture_swatch.png", build ? build : "build");
    return tu_write_file(matfile, "material black lambert { reflectance rgb 0.05 0.05 0.05 }\n"
                                  "material white lambert { reflectance rgb 0.85 0.85 0.85 }\n"
                                  "node board interpolate { a black  b white  t checker { frequency 8 } }\n");
}

static int teardown(void **state)
{
    (void)state;
    unlink(matfile);
    unlink(png);
    return 0;
}

static int run(const char *args, char *out, size_t size)
{
    if (access(gmat, X_OK) != 0)
        skip();
    char swatch[10000];
    snprintf(swatch, sizeof swatch, "swatch %s", args);
    return tu_run_capture(gmat, swatch, out, size);
}

/* Lambertian reflectance rho under the swatch's lights with the shading normal n. */
static double shaded(double rho, double nx, double ny, double nz)
{
    double l = sqrt(0.25 + 0.36 + 1.0), c = (-0.5 * nx + 0.6 * ny + nz) / l;
    return rho * (0.85 * fmax(c, 0.0) + 0.15);
}

static double pixel(const GImage *img, int x, int y)
{
    return img->pixels[((size_t)y * img->width + x) * img->channels];
}

/* Renders a swatch of material with the given options into png and reads it back. */
static void render(const char *material, const char *options, GImage *img)
{
    char out[4096], args[9000];
    snprintf(args, sizeof args, "'%s' %s -o '%s' %s", matfile, material, png, options);
    assert_int_equal(run(args, out, sizeof out), 0);
    GError err;
    assert_int_equal(gimage_read(png, GIMAGE_READ_RGB, img, &err), G_OK);
}

static void test_flat_checker(void **state)
{
    (void)state;
    GImage img;
    render("board", "--size 32 --samples 1", &img);
    assert_int_equal(img.width, 32);
    /* 4 pixels per cell; the top-left cell is (0, 7): odd, white; the next one black */
    double white = shaded(0.85, 0, 0, 1), black = shaded(0.05, 0, 0, 1);
    for (int y = 0; y < 32; y += 3)
        for (int x = 0; x < 32; x += 5) {
            int odd = ((x / 4) + (7 - y / 4)) & 1;
            assert_float_equal(pixel(&img, x, y), odd ? white : black, 0.01);
        }
    gimage_free(&img);
}

static void test_sphere(void **state)
{
    (void)state;
    GImage img;
    render("white", "--size 64 --samples 1 --sphere", &img);
    /* a pixel's centre (x, y) in [-1, 1]^2 sees the sphere's normal (x, y, sqrt(1 - x^2 - y^2)) */
    const int px[][2] = {{32, 32}, {20, 12}, {45, 40}, {10, 30}};
    for (int i = 0; i < 4; i++) {
        double x = (px[i][0] + 0.5) / 32.0 - 1.0, y = 1.0 - (px[i][1] + 0.5) / 32.0;
        double z = sqrt(1.0 - x * x - y * y);
        assert_float_equal(pixel(&img, px[i][0], px[i][1]), shaded(0.85, x, y, z), 0.01);
    }
    assert_float_equal(pixel(&img, 0, 0), 0.18, 0.01); /* the background */
    gimage_free(&img);
}

static void test_bad_input(void **state)
{
    (void)state;
    char out[4096], args[9000];
    snprintf(args, sizeof args, "'%s' nosuch -o '%s'", matfile, png);
    assert_int_equal(run(args, out, sizeof out), 1);
    assert_non_null(strstr(out, "no material or texture node named 'nosuch'"));
    snprintf(args, sizeof args, "'%s' board", matfile);
    assert_int_equal(run(args, out, sizeof out), 2);
    assert_non_null(strstr(out, "-o SWATCH.png is required"));
    snprintf(args, sizeof args, "'%s' board -o '%s' --size 3", matfile, png);
    assert_int_equal(run(args, out, sizeof out), 2);
    assert_non_null(strstr(out, "--size"));
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat_checker),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
