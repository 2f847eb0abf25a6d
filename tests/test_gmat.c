/* test_gmat.c - the gmat tool, run as a program (GENERIC_BUILD_DIR/bin/gmat): albedo of a Lambertian 0.5 is
 * 0.5 at several incidence angles, a normalised Phong reflects kd + ks at normal incidence, eval gives rho/pi
 * cos(theta_in) for Lambert, plot writes an image with the lobe in it, and bad input exits non-zero with a
 * clear message. */
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

#include "generic/builtins.h"
#include "generic/services/image.h"
#include "test_util.h"

static char gmat[4096], dir[4096], matfile[4200];

static int setup(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    snprintf(gmat, sizeof gmat, "%s/bin/gmat", build ? build : "build");
    snprintf(dir, sizeof dir, "%s/tests", build ? build : "build");
    snprintf(matfile, sizeof matfile, "%s/test_gmat.mat", dir);
    return tu_write_file(matfile, "material half lambert { reflectance rgb 0.5 0.5 0.5 }\n"
                                  "material gloss phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.5 0.5 0.5 "
                                  "exponent 50 }\n"
                                  "material red lambert { reflectance rgb 0.8 0.05 0.05 }\n");
}

static int teardown(void **state)
{
    (void)state;
    unlink(matfile);
    return 0;
}

/* Runs gmat with arguments (a shell fragment), capturing stdout+stderr; returns the exit status. */
static int run(const char *args, char *out, size_t size)
{
    if (access(gmat, X_OK) != 0) {
        print_error("%s is not built\n", gmat);
        fail();
    }
    return tu_run_capture(gmat, args, out, size);
}

static double field(const char *out, const char *label)
{
    const char *p = strstr(out, label);
    if (!p) {
        print_error("no '%s' in:\n%s\n", label, out);
        fail();
    }
    return strtod(p + strlen(label), NULL);
}

static void test_albedo_lambert(void **state)
{
    (void)state;
    /* the integration is exact for a Lambertian surface at any resolution: a coarse grid keeps this fast */
    static const char *const angles[] = {"30", "85"};
    for (int i = 0; i < 2; i++) {
        char args[8600], out[8192];
        snprintf(args, sizeof args, "albedo '%s' half --in %s --samples 32", matfile, angles[i]);
        assert_int_equal(run(args, out, sizeof out), 0);
        double y = field(out, "albedo Y");
        if (fabs(y - 0.5) > 1e-3)
            print_error("theta %s: albedo %.6f\n", angles[i], y);
        assert_true(fabs(y - 0.5) <= 1e-3);
        assert_true(field(out, "specular Y") == 0.0);
    }
}

static void test_albedo_phong(void **state)
{
    (void)state;
    char args[8600], out[8192];
    snprintf(args, sizeof args, "albedo '%s' gloss --in 0 --samples 192", matfile);
    assert_int_equal(run(args, out, sizeof out), 0);
    double y = field(out, "albedo Y");
    if (fabs(y - 0.8) > 2e-3)
        print_error("phong albedo %.6f\n", y);
    assert_true(fabs(y - 0.8) <= 2e-3);
}

static void test_eval(void **state)
{
    (void)state;
    char args[8600], out[8192];
    snprintf(args, sizeof args, "eval '%s' half --in 60,0 --out 20,123", matfile);
    assert_int_equal(run(args, out, sizeof out), 0);
    /* unit white light has Y = 1: the reflected luminance is rho/pi cos(60) */
    double y = 0;
    const char *p = strstr(out, "reflected XYZ");
    assert_non_null(p);
    double x;
    assert_int_equal(sscanf(p, "reflected XYZ %lf %lf", &x, &y), 2);
    assert_true(fabs(y - 0.5 / M_PI * 0.5) < 1e-6);
    p = strstr(out, "reflected linear sRGB");
    double r, g, b;
    assert_int_equal(sscanf(p, "reflected linear sRGB %lf %lf %lf", &r, &g, &b), 3);
    assert_true(fabs(r - 0.25 / M_PI) < 1e-5 && fabs(b - 0.25 / M_PI) < 1e-5);
    /* the spectrum is printed on request */
    snprintf(args, sizeof args, "eval '%s' half --in 0 --out 0 --colormodel spectrum --step 10 --spectrum", matfile);
    assert_int_equal(run(args, out, sizeof out), 0);
    assert_non_null(strstr(out, "reflected spectrum"));
    assert_non_null(strstr(out, "   550.0 "));
}

/* Reads the --data table of gmat plot: angles and luminances; returns the number of rows. */
static int read_table(const char *path, double *angle, double *lum, float rgb[][3], int max)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[256];
    int n = 0;
    while (fgets(line, sizeof line, f))
        if (line[0] != '#' && n < max &&
            sscanf(line, "%lf %lf %f %f %f", &angle[n], &lum[n], &rgb[n][0], &rgb[n][1], &rgb[n][2]) == 5)
            n++;
    fclose(f);
    return n;
}

static void test_plot(void **state)
{
    (void)state;
    char png[4300], data[4300], args[16000], out[8192];
    snprintf(png, sizeof png, "%s/test_gmat_plot.png", dir);
    snprintf(data, sizeof data, "%s/test_gmat_plot.dat", dir);
    unlink(png);
    unlink(data);
    snprintf(args, sizeof args, "plot '%s' red --in=30 -o '%s' --size 256 --data '%s'", matfile, png, data);
    assert_int_equal(run(args, out, sizeof out), 0);
    GImage img = {0};
    GError err;
    assert_int_equal(gimage_read(png, GIMAGE_READ_RGB, &img, &err), G_OK);
    assert_int_equal(img.width, 256);
    assert_int_equal(img.height, 192);
    int red = 0; /* the lobe is filled with the material's colour: red, lighter where it is transparent */
    for (int i = 0; i < img.width * img.height; i++) {
        const float *px = img.pixels + 3 * (size_t)i;
        red += px[0] > 0.3f && px[1] < 0.6f * px[0] && px[2] < 0.6f * px[0];
    }
    print_message("%d of %d pixels are the lobe's red\n", red, img.width * img.height);
    assert_true(red > img.width * img.height / 10);
    gimage_free(&img);
    /* the plotted values: a Lambertian lobe is rho_Y / pi * cos(theta_in) in every direction */
    static double angle[400], lum[400];
    static float rgb[400][3];
    int n = read_table(data, angle, lum, rgb, 400);
    assert_int_equal(n, 361);
    const double y = (0.2126 * 0.8 + 0.7152 * 0.05 + 0.0722 * 0.05) / M_PI * cos(30.0 * M_PI / 180.0);
    for (int i = 0; i < n; i++) {
        assert_true(fabs(angle[i] - (-90.0 + 0.5 * i)) < 1e-9);
        assert_true(fabs(lum[i] - y) < 2e-3 * y);
        assert_true(rgb[i][0] == 1.0f && rgb[i][1] < 0.1f && rgb[i][2] < 0.1f);
    }
    unlink(png);
    unlink(data);
    /* a logarithmic radius: the glossy lobe peaks at the mirror direction (+30), and the diffuse part is there */
    snprintf(args, sizeof args, "plot '%s' gloss --in 30 -o '%s' --log-radius --data='%s'", matfile, png, data);
    assert_int_equal(run(args, out, sizeof out), 0);
    assert_non_null(strstr(out, "logarithmic radius"));
    assert_int_equal(gimage_read(png, GIMAGE_READ_RGB, &img, &err), G_OK);
    assert_int_equal(img.width, 512);
    assert_int_equal(img.height, 384);
    gimage_free(&img);
    n = read_table(data, angle, lum, rgb, 400);
    assert_int_equal(n, 361);
    int peak = 0;
    for (int i = 0; i < n; i++)
        peak = lum[i] > lum[peak] ? i : peak;
    assert_true(fabs(angle[peak] - 30.0) <= 0.5);
    assert_true(lum[0] > 0.0 && lum[0] < 0.05 * lum[peak]); /* grazing on the light's side: diffuse only */
    unlink(png);
    unlink(data);
}

static void test_bad_input(void **state)
{
    (void)state;
    char args[8600], out[8192];
    assert_int_equal(run("--help", out, sizeof out), 0);
    assert_non_null(strstr(out, "usage: gmat COMMAND"));
    assert_int_equal(run("plot --help", out, sizeof out), 0);
    assert_non_null(strstr(out, "usage: gmat plot FILE MATERIAL --in THETA -o PLOT.png"));
    assert_int_equal(run("frobnicate x y", out, sizeof out), 2);
    assert_non_null(strstr(out, "unknown command 'frobnicate'"));
    snprintf(args, sizeof args, "albedo '%s' half --in 95", matfile);
    assert_int_equal(run(args, out, sizeof out), 2);
    assert_non_null(strstr(out, "--in: '95' is not THETA[,PHI]"));
    snprintf(args, sizeof args, "eval '%s' half --in 10", matfile);
    assert_int_equal(run(args, out, sizeof out), 2);
    assert_non_null(strstr(out, "--out THETA[,PHI] is required"));
    snprintf(args, sizeof args, "albedo '%s' nosuch --in 10", matfile);
    assert_int_equal(run(args, out, sizeof out), 1);
    assert_non_null(strstr(out, "defines no material named 'nosuch' (it defines: half, gloss, red)"));
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_albedo_lambert),
        cmocka_unit_test(test_albedo_phong),
        cmocka_unit_test(test_eval),
        cmocka_unit_test(test_plot),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
