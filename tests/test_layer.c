/* test_layer.c - the layer material: a smooth dielectric of index 1.5 over a lambert of albedo 0.5 against the
 * non-fluorescent part of the fluorescent varnish (the same index, a plain grey colour for its matrix, facets of
 * slope 0.01 degrees: a smooth boundary) in albedo at 10 angles, within 0.5%; lossless stacks (a white lambert
 * under one and two coats, a white scattering medium between) never reflect more than arrives; an evaluation is
 * deterministic and reciprocal; stacks deeper than the bound are refused at their place. */
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

static const char *const stack_text =
    "material coat layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.5 0.5 0.5 } samples 8 }\n"
    "material varnish fluorescent-varnish { matrix rgb 0.5 0.5 0.5 ior 1.5 slope 0.01 }\n"
    "material white layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 1 1 1 } bounces 64 "
    "samples 16 }\n"
    "material two_coats layer { top dielectric { index 1.3 } bottom layer { top dielectric { index 1.7 } "
    "bottom lambert { reflectance rgb 1 1 1 } bounces 12 } bounces 12 }\n"
    "material milky layer { top dielectric { index 1.4 } bottom lambert { reflectance rgb 1 1 1 } thickness 0.7 "
    "albedo rgb 1 1 1 bounces 64 samples 16 }\n";

typedef struct Stack {
    GLibrary *lib;
    const GColorModel *model;
    GScratch *scratch;
    GSurfPoint sp;
} Stack;

static void stack_open(Stack *s)
{
    GError err;
    GReaderOptions opt = {.colormodel = "rgb"};
    if (greader_load_string(stack_text, "stacks", &opt, &s->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    s->model = glibrary_colormodel(s->lib);
    s->scratch = gscratch_create(0);
    gsurfpoint_init(&s->sp, s->model, s->scratch);
    s->sp.geometric_normal = gvec3(0, 0, 1);
}

static void stack_close(Stack *s)
{
    gscratch_destroy(s->scratch);
    glibrary_destroy(s->lib);
}

/* The albedo of material `name` for light from theta (luminance of the reflected white light): the ideal
 * reflection ray's, and the rest integrated on an nt x 2nt grid (midpoints in cos^2 theta and phi: the cosine
 * weight in the measure, no mirror pair on it). *ideal gets the ideal ray's share. */
static double albedo_of(Stack *s, const char *name, double theta, int nt, double *ideal)
{
    GMaterial *m = glibrary_material(s->lib, name);
    assert_non_null(m);
    s->sp.material = m, s->sp.from = NULL, s->sp.to = m;
    gsurfpoint_invalidate(&s->sp);
    GScratchMark mark = gscratch_mark(s->scratch);
    GColor one, r, acc;
    assert_int_equal(gcolor_scratch(&one, s->model, s->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&r, s->model, s->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&acc, s->model, s->scratch), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    GVec3 in = gvec3(sin(theta), 0, cos(theta)), mirror = gvec3(-sin(theta), 0, cos(theta));
    assert_int_equal(gmaterial_reflection(m, &s->sp, in, &one, mirror, &r), G_OK);
    *ideal = gcolor_brightness(&r);
    int np = 2 * nt;
    /* int f cos_o dw = int_0^1 d(cos^2) / 2 int dphi: midpoints in u = cos^2 theta_o */
    for (int i = 0; i < nt; i++) {
        double u = (i + 0.5) / nt, co = sqrt(u), so = sqrt(1.0 - u);
        for (int j = 0; j < np; j++) {
            double phi = (j + 0.5) * 2.0 * M_PI / np;
            GVec3 out = gvec3(so * cos(phi), so * sin(phi), co);
            assert_int_equal(gmaterial_reflection(m, &s->sp, in, &one, out, &r), G_OK);
            /* reflection is f cos_in: f cos_o dw = reflection / cos_in * (pi / (nt np)) per cell */
            assert_int_equal(gcolor_axpy(&acc, M_PI / (nt * np) / cos(theta), &r, &acc), G_OK);
        }
    }
    double a = gcolor_brightness(&acc);
    gscratch_release(s->scratch, mark);
    return a + *ideal;
}

static void test_against_varnish(void **state)
{
    (void)state;
    Stack s;
    stack_open(&s);
    double worst = 0.0;
    for (int k = 0; k < 10; k++) {
        double theta = k * 8.5 * DEG, ideal_l, ideal_v;
        double layer = albedo_of(&s, "coat", theta, 32, &ideal_l);
        double varnish = albedo_of(&s, "varnish", theta, 32, &ideal_v);
        /* the varnish's facets reflect within 0.01 degrees of the mirror ray, which the grid misses: its ideal
         * part is the smooth boundary's Fresnel reflectance, the layer's top's */
        double fresnel = goptics_fresnel(cos(theta), 1.0 / 1.5);
        double body_l = layer - ideal_l, body_v = varnish - ideal_v;
        double rel = fabs((body_l + fresnel) - (body_v + fresnel)) / (body_v + fresnel);
        print_message("theta %4.1f: layer %.5f (ideal %.5f), varnish %.5f + Fresnel %.5f: %.3f%%\n", theta / DEG,
                      layer, ideal_l, body_v, fresnel, 100.0 * rel);
        assert_true(fabs(ideal_l - fresnel) < 1e-6);
        worst = fmax(worst, rel);
    }
    print_message("layer against varnish: albedo within %.3f%% at 10 angles\n", 100.0 * worst);
    assert_true(worst <= 0.005);
    stack_close(&s);
}

static void test_lossless(void **state)
{
    (void)state;
    Stack s;
    stack_open(&s);
    const char *names[] = {"white", "two_coats", "milky"};
    for (int n = 0; n < 3; n++) {
        double most = 0.0, least = INFINITY, mean = 0.0;
        for (int k = 0; k < 10; k++) {
            double ideal, a = albedo_of(&s, names[n], k * 8.5 * DEG, 24, &ideal);
            most = fmax(most, a), least = fmin(least, a), mean += a / 10.0;
        }
        print_message("%s: albedo from %.4f to %.4f at 10 angles, mean %.4f\n", names[n], least, most, mean);
        /* each angle is one Monte Carlo estimate (about 0.5%% of noise): its expectation is at most 1 */
        assert_true(mean <= 1.003);
        assert_true(most <= 1.01);
        assert_true(least >= 0.9); /* lossless: only the walks cut short lose light */
    }
    stack_close(&s);
}

static void test_deterministic_reciprocal(void **state)
{
    (void)state;
    Stack s;
    stack_open(&s);
    GMaterial *m = glibrary_material(s.lib, "milky");
    s.sp.material = m, s.sp.to = m;
    GColor one, a, b;
    assert_int_equal(gcolor_scratch(&one, s.model, s.scratch), G_OK);
    assert_int_equal(gcolor_scratch(&a, s.model, s.scratch), G_OK);
    assert_int_equal(gcolor_scratch(&b, s.model, s.scratch), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    GVec3 in = gvec3_normalize(gvec3(0.3, 0.2, 0.9)), out = gvec3_normalize(gvec3(-0.6, 0.1, 0.5));
    assert_int_equal(gmaterial_reflection(m, &s.sp, in, &one, out, &a), G_OK);
    assert_int_equal(gmaterial_reflection(m, &s.sp, in, &one, out, &b), G_OK);
    assert_memory_equal(a.v, b.v, sizeof(float) * 3);
    assert_int_equal(gmaterial_reflection(m, &s.sp, out, &one, in, &b), G_OK);
    for (int i = 0; i < 3; i++) /* f(in, out) = f(out, in): reflection / cos_in */
        assert_true(fabs(a.v[i] / in.z - b.v[i] / out.z) <= 1e-5 * fabs(a.v[i] / in.z));
    stack_close(&s);
}

static void test_bounds(void **state)
{
    (void)state;
    const char *bad[][2] = {
        {"material m layer { top dielectric { } }", "layer: the bottom material is missing"},
        {"material m layer { top dielectric { } bottom lambert { } bounces 0 }", "[1, 64]"},
        {"material m layer { top dielectric { } bottom lambert { } samples 65 }", "[1, 64]"},
        {"material m layer { top dielectric { } bottom lambert { } thickness -1 }", "[0, 100]"},
        {"material m layer { top dielectric { } bottom lambert { } albedo rgb 2 2 2 }",
         "layer: albedo has the value 2"},
        {"material m layer { top thinfilm { base dielectric { } } bottom lambert { } bounces 64 samples 64 }",
         "GNODE_MAX_COST"},
        {"material L1 layer { top dielectric { } bottom lambert { } bounces 1 }\n"
         "material L2 layer { top dielectric { } bottom L1 bounces 1 }\n"
         "material L3 layer { top dielectric { } bottom L2 bounces 1 }\n"
         "material m layer { top dielectric { } bottom L3 bounces 1 }",
         "a stack of 4 layers, the limit is 3 (LAYER_MAX_STACK)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GLibrary *lib = NULL;
        GError err;
        assert_int_not_equal(greader_load_string(bad[i][0], "bad", NULL, &lib, &err), G_OK);
        assert_null(lib);
        print_message("-> %s\n", err.message);
        if (!strstr(err.message, bad[i][1]) || strncmp(err.message, "bad:", 4) != 0)
            fail_msg("'%s': message '%s' does not say %s at its place", bad[i][0], err.message, bad[i][1]);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_varnish),
        cmocka_unit_test(test_lossless),
        cmocka_unit_test(test_deterministic_reciprocal),
        cmocka_unit_test(test_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
