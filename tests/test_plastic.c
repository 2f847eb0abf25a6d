/* test_plastic.c - the plastic material: its closed form against layer's random walks (a smooth coat of index 1.5
 * over a lambert of albedo 0.5: the same physics two ways) in albedo at 10 angles within 0.5%; white furnace: a
 * white base under a smooth or rough coat (alpha 0.05, 0.3, 0.8, GGX and Beckmann) reflects all the light, 1 within
 * 1e-3 at 10 angles, measured by its own sampling as a path tracer sees it (the mean weight over a stratified grid
 * of draws; Beckmann's by quadrature); a darker base reflects less; reciprocity; refusals of bad parameters at
 * their place. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"

#define DEG (M_PI / 180.0)

static const char *const text =
    "material smooth plastic { reflectance rgb 0.5 0.5 0.5 index 1.5 }\n"
    "material walked layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.5 0.5 0.5 } samples 8 }\n"
    "material w0 plastic { reflectance rgb 1 1 1 }\n"
    "material w005 plastic { reflectance rgb 1 1 1 roughness 0.05 }\n"
    "material w03 plastic { reflectance rgb 1 1 1 roughness 0.3 index 1.33 }\n"
    "material w08 plastic { reflectance rgb 1 1 1 roughness 0.8 index 2.2 }\n"
    "material b08 plastic { reflectance rgb 1 1 1 roughness 0.8 distribution beckmann index 2.2 }\n"
    "material grey03 plastic { reflectance rgb 0.3 0.3 0.3 roughness 0.3 }\n"
    "material black03 plastic { reflectance rgb 0 0 0 roughness 0.3 }\n";

typedef struct Fix {
    GLibrary *lib;
    const GColorModel *model;
    GScratch *scratch;
    GSurfPoint sp;
} Fix;

static GMaterial *fix_open(Fix *f, const char *name)
{
    GError err;
    GReaderOptions opt = {.colormodel = "rgb"};
    if (greader_load_string(text, "plastics", &opt, &f->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    f->model = glibrary_colormodel(f->lib);
    f->scratch = gscratch_create(0);
    gsurfpoint_init(&f->sp, f->model, f->scratch);
    f->sp.geometric_normal = gvec3(0, 0, 1);
    return name ? glibrary_material(f->lib, name) : NULL;
}

static void fix_close(Fix *f)
{
    gscratch_destroy(f->scratch);
    glibrary_destroy(f->lib);
}

static void fix_use(Fix *f, GMaterial *m)
{
    assert_non_null(m);
    f->sp.material = m, f->sp.from = NULL, f->sp.to = m;
    gsurfpoint_invalidate(&f->sp);
}

/* Albedo (luminance) for light from theta: the ideal ray's (if any) and the rest on an nt x 2nt grid (midpoints in
 * cos^2 theta_o and phi). */
static double grid_albedo(Fix *f, GMaterial *m, double theta, int nt)
{
    fix_use(f, m);
    GScratchMark mark = gscratch_mark(f->scratch);
    GColor one, r, acc;
    assert_int_equal(gcolor_scratch(&one, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&r, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&acc, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    GVec3 in = gvec3(sin(theta), 0, cos(theta));
    GVec3 ideal;
    if (gmaterial_reflection_dir(m, &f->sp, gvec3_neg(in), &ideal) == 1) /* an ideal ray: its reflectance */
        assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, ideal, &acc), G_OK);
    int np = 2 * nt;
    for (int i = 0; i < nt; i++) {
        double u = (i + 0.5) / nt, co = sqrt(u), so = sqrt(1.0 - u);
        for (int j = 0; j < np; j++) {
            double phi = (j + 0.5) * 2.0 * M_PI / np;
            assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, gvec3(so * cos(phi), so * sin(phi), co), &r),
                             G_OK);
            assert_int_equal(gcolor_axpy(&acc, M_PI / (nt * np) / in.z, &r, &acc), G_OK);
        }
    }
    double a = gcolor_brightness(&acc);
    gscratch_release(f->scratch, mark);
    return a;
}

static void test_against_layer(void **state)
{
    (void)state;
    Fix f;
    GMaterial *plastic = fix_open(&f, "smooth"), *walked = glibrary_material(f.lib, "walked");
    double worst = 0.0;
    for (int k = 0; k < 10; k++) {
        double theta = k * 8.5 * DEG;
        double a = grid_albedo(&f, plastic, theta, 32), b = grid_albedo(&f, walked, theta, 32);
        print_message("theta %4.1f: plastic %.5f, layer %.5f\n", theta / DEG, a, b);
        worst = fmax(worst, fabs(a - b) / a);
    }
    print_message("plastic against layer: within %.3f%% at 10 angles\n", 100.0 * worst);
    assert_true(worst <= 0.005);
    fix_close(&f);
}

/* The mean weight of sample() for light leaving at theta over an n x n stratified grid of (u1, u2): the albedo a
 * path tracer sees (luminance). */
static double sampled_albedo(Fix *f, GMaterial *m, double theta, int n)
{
    fix_use(f, m);
    GScratchMark mark = gscratch_mark(f->scratch);
    GColor w, ri;
    assert_int_equal(gcolor_scratch(&w, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&ri, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_fill(&ri, 1.0 / 1.5), G_OK);
    GVec3 out = gvec3(sin(theta), 0, cos(theta));
    double sum = 0.0;
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++) {
            GMaterialSample s;
            GScratchMark inner = gscratch_mark(f->scratch);
            int rc = gmaterial_sample(m, &f->sp, out, &ri, (a + 0.5) / n, (b + 0.5) / n, &s, &w);
            assert_true(rc >= 0);
            if (rc == 1)
                sum += gcolor_brightness(&w);
            gscratch_release(f->scratch, inner);
        }
    gscratch_release(f->scratch, mark);
    return sum / ((double)n * n);
}

static void test_white_furnace(void **state)
{
    (void)state;
    Fix f;
    fix_open(&f, NULL);
    const char *names[] = {"w0", "w005", "w03", "w08"};
    for (int i = 0; i < 4; i++) {
        double worst = 0.0;
        for (int k = 0; k < 10; k++)
            worst = fmax(worst, fabs(sampled_albedo(&f, glibrary_material(f.lib, names[i]), k * 8.5 * DEG, 400) -
                                     1.0));
        print_message("%s: |albedo - 1| <= %.2e at 10 angles (160000 stratified draws each)\n", names[i], worst);
        assert_true(worst <= 1e-3);
    }
    /* Beckmann's visible normals are drawn by a numerical inversion (kit/microfacet.h), whose density differs from the
     * analytic pdf by about 1e-3 at alpha 0.8: its furnace is measured by quadrature of reflection() instead */
    double worst = 0.0;
    for (int k = 0; k < 10; k++)
        worst = fmax(worst, fabs(grid_albedo(&f, glibrary_material(f.lib, "b08"), k * 8.5 * DEG, 128) - 1.0));
    print_message("b08: |albedo - 1| <= %.2e at 10 angles (quadrature)\n", worst);
    assert_true(worst <= 1e-3);
    /* the coat alone (a black base) < a grey base < a white one */
    double grey = sampled_albedo(&f, glibrary_material(f.lib, "grey03"), 30.0 * DEG, 200);
    double coat = sampled_albedo(&f, glibrary_material(f.lib, "black03"), 30.0 * DEG, 200);
    print_message("at 30 degrees: black base %.4f, grey 0.3 %.4f\n", coat, grey);
    assert_true(coat > 0.03 && coat < 0.1 && grey > coat + 0.05 && grey < 0.5);
    fix_close(&f);
}

static void test_reciprocal(void **state)
{
    (void)state;
    Fix f;
    GMaterial *m = fix_open(&f, "grey03");
    fix_use(&f, m);
    GColor one, a, b;
    assert_int_equal(gcolor_scratch(&one, f.model, f.scratch), G_OK);
    assert_int_equal(gcolor_scratch(&a, f.model, f.scratch), G_OK);
    assert_int_equal(gcolor_scratch(&b, f.model, f.scratch), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    GVec3 in = gvec3_normalize(gvec3(0.5, 0.2, 0.6)), out = gvec3_normalize(gvec3(-0.4, -0.1, 0.7));
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &one, out, &a), G_OK);
    assert_int_equal(gmaterial_reflection(m, &f.sp, out, &one, in, &b), G_OK);
    assert_true(fabs(a.v[1] / in.z - b.v[1] / out.z) <= 1e-6 * (a.v[1] / in.z));
    fix_close(&f);
}

static void test_bounds(void **state)
{
    (void)state;
    const char *bad[][2] = {
        {"material m plastic { roughness 1.5 }", "[0, 1]"},
        {"material m plastic { roughness -0.1 }", "[0, 1]"},
        {"material m plastic { index 0 }", "[1, 4]"},
        {"material m plastic { distribution phong }", "phong"},
        {"material m plastic { reflectance rgb 3 3 3 }", "plastic: reflectance has the value 3"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GLibrary *lib = NULL;
        GError err;
        assert_int_not_equal(greader_load_string(bad[i][0], "bad", NULL, &lib, &err), G_OK);
        assert_null(lib);
        print_message("-> %s\n", err.message);
        if (!strstr(err.message, bad[i][1]) || strncmp(err.message, "bad:1:", 6) != 0)
            fail_msg("'%s': message '%s' does not say %s at its place", bad[i][0], err.message, bad[i][1]);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_layer),
        cmocka_unit_test(test_white_furnace),
        cmocka_unit_test(test_reciprocal),
        cmocka_unit_test(test_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
