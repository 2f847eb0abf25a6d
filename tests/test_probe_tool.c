/* test_probe_tool.c - the gprobe command line: help, errors, approx output, irradiance, eval CSV and plot. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/image.h"
#include "generic/services/probe.h"

static char tool[1024], dir[256];

static int setup(void **state)
{
    (void)state;
    const char *b = getenv("GENERIC_BUILD_DIR");
    snprintf(tool, sizeof tool, "%s/bin/gprobe", b ? b : "build");
    snprintf(dir, sizeof dir, "/tmp/gprobe_test_XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static const char *in_dir(const char *name, char *buf)
{
    snprintf(buf, 600, "%s/%s", dir, name);
    return buf;
}

/* Runs gprobe with args (a shell fragment); returns its exit status, stdout+stderr in `out`. */
static int run(const char *env, const char *args, char *out, size_t size)
{
    if (access(tool, X_OK) != 0)
        skip();
    char cmd[4096], log[600];
    in_dir("log.txt", log);
    snprintf(cmd, sizeof cmd, "%s '%s' %s > '%s' 2>&1", env ? env : "", tool, args, log);
    int st = system(cmd);
    FILE *f = fopen(log, "r");
    size_t n = f ? fread(out, 1, size - 1, f) : 0;
    out[n] = '\0';
    if (f)
        fclose(f);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* A 64 x 32 probe: a dim constant sky and one bright pixel; returns its path. */
static const char *write_probe(const char *name, float sky, char *buf)
{
    GImage img;
    assert_int_equal(gimage_create(&img, 64, 32, 3, NULL), G_OK);
    for (int i = 0; i < 64 * 32 * 3; i++)
        img.pixels[i] = sky;
    img.pixels[3 * (8 * 64 + 20)] = 300.0f;
    img.pixels[3 * (8 * 64 + 20) + 1] = 200.0f;
    img.pixels[3 * (8 * 64 + 20) + 2] = 100.0f;
    assert_int_equal(gimage_write(in_dir(name, buf), &img, NULL, NULL), G_OK);
    gimage_free(&img);
    return buf;
}

static void test_help(void **state)
{
    (void)state;
    static char out[16384];
    assert_int_equal(run(NULL, "approx --help", out, sizeof out), 0);
    assert_non_null(strstr(out, "usage: gprobe approx"));
    assert_int_equal(run(NULL, "frobnicate", out, sizeof out), 2);
    assert_non_null(strstr(out, "unknown command"));
    assert_int_equal(run(NULL, "approx --probe x.exr -n 4", out, sizeof out), 2); /* no technique, no -o */
}

static void test_clear_errors(void **state)
{
    (void)state;
    static char out[16384];
    char path[600], args[1400];
    GImage img;
    assert_int_equal(gimage_create(&img, 50, 20, 3, NULL), G_OK);
    assert_int_equal(gimage_write(in_dir("wide.exr", path), &img, NULL, NULL), G_OK);
    gimage_free(&img);
    snprintf(args, sizeof args, "irradiance --probe '%s' --normal 0,0,1", path);
    assert_int_equal(run(NULL, args, out, sizeof out), 1);
    assert_non_null(strstr(out, "50x20"));
    assert_non_null(strstr(out, "twice as wide"));
    snprintf(args, sizeof args, "irradiance --probe '%s/missing.hdr' --normal 0,0,1", dir);
    assert_int_equal(run(NULL, args, out, sizeof out), 1);
    assert_non_null(strstr(out, "missing.hdr"));
    write_probe("p.exr", 0.5f, path);
    snprintf(args, sizeof args, "approx --probe '%s' --technique mediancut -n 6 -o x.txt", path);
    assert_int_equal(run(NULL, args, out, sizeof out), 2);
    assert_non_null(strstr(out, "power of two"));
    snprintf(args, sizeof args, "approx --probe '%s' --technique nope -n 6 -o x.txt", path);
    assert_int_equal(run(NULL, args, out, sizeof out), 2);
    assert_non_null(strstr(out, "nope"));
}

static void test_irradiance_of_constant_probe(void **state)
{
    (void)state;
    static char out[16384];
    char path[600], args[1400];
    GImage img;
    assert_int_equal(gimage_create(&img, 128, 64, 3, NULL), G_OK);
    for (int i = 0; i < 128 * 64 * 3; i++)
        img.pixels[i] = (i % 3 == 0) ? 1.0f : (i % 3 == 1) ? 2.0f : 4.0f;
    assert_int_equal(gimage_write(in_dir("const.exr", path), &img, NULL, NULL), G_OK);
    gimage_free(&img);
    snprintf(args, sizeof args, "irradiance --probe '%s' --normal 0.3,-2,0.7", path);
    assert_int_equal(run(NULL, args, out, sizeof out), 0);
    double e[3];
    assert_int_equal(sscanf(out, "%lf %lf %lf", &e[0], &e[1], &e[2]), 3);
    assert_true(fabs(e[0] / M_PI - 1.0) < 0.005);
    assert_true(fabs(e[1] / (2.0 * M_PI) - 1.0) < 0.005);
    assert_true(fabs(e[2] / (4.0 * M_PI) - 1.0) < 0.005);
}

static void test_approx_writes_lights(void **state)
{
    (void)state;
    static char out[16384];
    char path[600], lights[600], args[2000];
    write_probe("p.exr", 0.0f, path); /* black except the bright pixel */
    in_dir("lights.txt", lights);
    const char *techs[] = {"adaptive", "irradiance"}; /* all four: test_probe_techniques */
    for (int t = 0; t < 2; t++) {
        snprintf(args, sizeof args, "approx --probe '%s' --technique %s -n 8 -o '%s' -q", path, techs[t], lights);
        assert_int_equal(run(NULL, args, out, sizeof out), 0);
        FILE *f = fopen(lights, "r");
        assert_non_null(f);
        char line[512];
        int n = 0;
        double d[3], c[3];
        while (fgets(line, sizeof line, f)) {
            if (line[0] == '#')
                continue;
            assert_int_equal(sscanf(line, "light directional { direction %lf %lf %lf irradiance rgb %lf %lf %lf }",
                                    &d[0], &d[1], &d[2], &c[0], &c[1], &c[2]),
                             6);
            n++;
        }
        fclose(f);
        /* only the bright pixel carries energy: one light, travelling away from the pixel's direction */
        assert_int_equal(n, 1);
        const double ph = M_PI - 2 * M_PI * 20.5 / 64, th = M_PI * 8.5 / 32; /* probe.h's convention */
        GVec3 want = gvec3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
        assert_true(gvec3_dot(gvec3(d[0], d[1], d[2]), want) < -1.0 + 1e-6);
        double q = 2.0 * M_PI * M_PI * 300.0 * sin(M_PI * 8.5 / 32) / (64 * 32);
        assert_true(fabs(c[0] / q - 1.0) < 1e-5);
    }
    /* the output is complete or absent: a failing run leaves no file and no temporary */
    snprintf(args, sizeof args, "approx --probe '%s/none.exr' --technique adaptive -n 8 -o '%s/never.txt'", dir, dir);
    assert_int_equal(run(NULL, args, out, sizeof out), 1);
    char never[600];
    assert_int_not_equal(access(in_dir("never.txt", never), F_OK), 0);
}

static void test_eval_csv_and_plot(void **state)
{
    (void)state;
    static char out[16384];
    char path[600], csv[600], png[600], args[2600];
    write_probe("p.exr", 0.5f, path);
    in_dir("e.csv", csv);
    in_dir("e.png", png);
    const int plot = access("/usr/bin/gnuplot", X_OK) == 0;
    snprintf(args, sizeof args,
             "eval --probe '%s' --normals 500 --counts 2,3,4 --techniques mediancut,adaptive,irradiance,sh9,sh,sg-nnls "
             "--csv '%s' "
             "%s%s%s -q",
             path, csv, plot ? "--plot '" : "", plot ? png : "", plot ? "'" : "");
    assert_int_equal(run(NULL, args, out, sizeof out), 0);
    assert_non_null(strstr(out, "technique"));
    FILE *f = fopen(csv, "r");
    assert_non_null(f);
    char line[512];
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "technique,count,unit,mean_rel,max_rel,mean_norm,max_norm,smape,seconds\n");
    int rows = 0, sh9 = 0, sh = 0;
    double sh9_mean = -1.0, sh_mean = -2.0;
    while (fgets(line, sizeof line, f)) {
        char name[32], unit[32];
        int count;
        double v[6];
        assert_int_equal(sscanf(line, "%31[^,],%d,%31[^,],%lf,%lf,%lf,%lf,%lf,%lf", name, &count, unit, &v[0], &v[1],
                                &v[2], &v[3], &v[4], &v[5]),
                         9);
        assert_true(v[0] >= 0.0 && v[0] <= v[1]); /* mean <= max */
        assert_true(v[2] >= 0.0 && v[2] <= v[3]);
        assert_true(v[4] >= 0.0 && v[4] <= 200.0); /* sMAPE */
        if (strcmp(name, "mediancut") == 0)
            assert_true(count != 3); /* not a power of two: skipped */
        if (strcmp(name, "sh") == 0) {
            assert_string_equal(unit, "coefficients");
            assert_true(count == 4 || count == 9 || count == 16 || count == 25);
            if (count == 9)
                sh_mean = v[0];
            sh++;
        }
        if (strcmp(name, "sg-nnls") == 0)
            assert_string_equal(unit, "lobes");
        if (strcmp(name, "adaptive") == 0)
            assert_string_equal(unit, "lights");
        if (strcmp(name, "sh9") == 0)
            sh9_mean = v[0];
        sh9 += strcmp(name, "sh9") == 0;
        rows++;
    }
    fclose(f);
    assert_int_equal(rows, 2 + 3 + 3 + 1 + 4 + 3);
    assert_int_equal(sh9, 1);
    assert_int_equal(sh, 4);
    assert_true(fabs(sh9_mean - sh_mean) < 1e-9); /* SH of order 2 is SH9 */
    if (plot) {
        int w, h, c;
        assert_int_equal(gimage_info(png, &w, &h, &c, NULL), G_OK);
        assert_true(w >= 800 && h >= 400);
    }
    /* without gnuplot the plot fails at once with a clear message */
    snprintf(args, sizeof args, "eval --probe '%s' --normals 300 --plot '%s/x.png'", path, dir);
    assert_int_equal(run("PATH=/nonexistent", args, out, sizeof out), 1);
    assert_non_null(strstr(out, "gnuplot"));
}

/* gprobe report: the page, the table, the CSV and every image it names, of the report's size. */
static void test_report(void **state)
{
    (void)state;
    static char out[16384];
    char path[600], rdir[600], args[2600], file[1400];
    write_probe("r.exr", 0.5f, path);
    in_dir("report", rdir);
    snprintf(
        args, sizeof args,
        "report --probe '%s' -o '%s' --size 8 --normals 400 --counts 4 --techniques adaptive,sh,sg-ls,ambientcube -q",
        path, rdir);
    assert_int_equal(run(NULL, args, out, sizeof out), 0);
    const char *names[] = {"index.html", "report.md", "errors.csv", "images/error-scale.png",
                           "images/reference-radiance.png", "images/reference-irradiance.png",
                           "images/adaptive-4-radiance.png", "images/sh-25-error.png", "images/sg-ls-4-irradiance.png",
                           "images/ambientcube-6-error.png"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        snprintf(file, sizeof file, "%s/%s", rdir, names[i]);
        assert_int_equal(access(file, R_OK), 0);
        if (strstr(names[i], "images/") && !strstr(names[i], "scale")) {
            int w, h, c;
            assert_int_equal(gimage_info(file, &w, &h, &c, NULL), G_OK);
            assert_int_equal(w, 16);
            assert_int_equal(h, 8);
        }
    }
    snprintf(file, sizeof file, "%s/report.md", rdir);
    FILE *f = fopen(file, "r");
    assert_non_null(f);
    char line[512];
    int rows = 0;
    while (fgets(line, sizeof line, f))
        rows += line[0] == '|';
    fclose(f);
    assert_int_equal(rows, 2 + 1 + 4 + 1 + 1); /* header, rule, adaptive, sh x 4, sg-ls, ambient cube */
    snprintf(file, sizeof file, "%s/index.html", rdir);
    f = fopen(file, "r");
    assert_non_null(f);
    static char html[65536];
    size_t n = fread(html, 1, sizeof html - 1, f);
    html[n] = 0;
    fclose(f);
    assert_non_null(strstr(html, "images/sh-9-radiance.png"));
    assert_int_equal(strstr(html, "fig6.png") != NULL, access("/usr/bin/gnuplot", X_OK) == 0);
    /* a file where the directory should be */
    snprintf(args, sizeof args, "report --probe '%s' -o '%s' -q", path, path);
    assert_int_equal(run(NULL, args, out, sizeof out), 1);
    assert_non_null(strstr(out, "not a directory"));
    assert_int_equal(run(NULL, "report --probe x.exr", out, sizeof out), 2);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_clear_errors),
        cmocka_unit_test(test_irradiance_of_constant_probe),
        cmocka_unit_test(test_approx_writes_lights),
        cmocka_unit_test(test_eval_csv_and_plot),
        cmocka_unit_test(test_report),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
