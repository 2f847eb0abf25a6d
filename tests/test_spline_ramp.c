/* test_spline_ramp.c - the spline node's ramp `ramp { KEY MATERIAL ... }`: the value at every key is that key's
 * child, between keys the linear basis interpolates linearly over the key interval and Catmull-Rom follows its
 * polynomial on the mapped segment, past the ends the end children hold; bad ramps (decreasing keys, keys out
 * of [0, 1], fewer than 2 keys, too many, children and ramp together) are refused at file:line:col, and a
 * generated ramp of GSPLINE_MAX_KEYS keys loads. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/materials.h"
#include "generic/nodes.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"
#include "reader_fixture.h"

/* The diffuse red of a spline over the ramp at t (the ramp's children are lambert greys), after the text
 * `prelude`; `param` is the spline's parameter ("ramp { ", "colors { ", "colors of x diffuse { "). */
static double ramp_with(const char *prelude, const char *param, const char *basis, const char *ramp, double t)
{
    char text[4096];
    snprintf(text, sizeof text, "%s\nnode n spline { t constant { value %.17g } basis %s %s %s } }\n", prelude, t,
             basis, param, ramp);
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    const GColorModel *m = glibrary_colormodel(lib);
    GMaterial *mat = glibrary_material(lib, "n");
    GScratch *s = gscratch_create(0);
    GSurfPoint sp;
    gsurfpoint_init(&sp, m, s);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.entering = 1;
    sp.material = mat;
    float v[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor out;
    assert_int_equal(gcolor_wrap(&out, m, v, 9), G_OK);
    assert_int_equal(gmaterial_diffuse(mat, &sp, &out), G_OK);
    gscratch_destroy(s);
    glibrary_destroy(lib);
    return v[0];
}

static double ramp_at(const char *basis, const char *ramp, double t) { return ramp_with("", "ramp {", basis, ramp, t); }

#define GREY(x) "lambert { reflectance rgb " #x " " #x " " #x " }"
static const char ramp3[] = "0 " GREY(0.9) " 0.8 " GREY(0.5) " 1 " GREY(0.2);

static void test_ramp_linear(void **state)
{
    (void)state;
    const double keys[] = {0, 0.8, 1}, vals[] = {0.9, 0.5, 0.2};
    for (int i = 0; i < 3; i++)
        assert_near(ramp_at("linear", ramp3, keys[i]), vals[i], 1e-6);
    const double ts[] = {0.1, 0.4, 0.79, 0.85, 0.95};
    for (int i = 0; i < 5; i++) {
        double t = ts[i];
        int k = t < 0.8 ? 0 : 1;
        double want = vals[k] + (vals[k + 1] - vals[k]) * (t - keys[k]) / (keys[k + 1] - keys[k]);
        assert_near(ramp_at("linear", ramp3, t), want, 1e-6);
    }
    /* keys that do not reach the ends: the end children hold */
    const char inner[] = "0.2 " GREY(0.1) " 0.6 " GREY(0.7);
    assert_near(ramp_at("linear", inner, 0.0), 0.1, 1e-6);
    assert_near(ramp_at("linear", inner, 0.4), 0.4, 1e-6);
    assert_near(ramp_at("linear", inner, 1.0), 0.7, 1e-6);
    /* equal keys make a step */
    const char step[] = "0 " GREY(0.1) " 0.5 " GREY(0.1) " 0.5 " GREY(0.9) " 1 " GREY(0.9);
    assert_near(ramp_at("linear", step, 0.4999), 0.1, 1e-6);
    assert_near(ramp_at("linear", step, 0.5001), 0.9, 1e-6);
}

static double catmull_rom(double p0, double p1, double p2, double p3, double t)
{
    return 0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
                  (-p0 + 3 * p1 - 3 * p2 + p3) * t * t * t);
}

static void test_ramp_catmull_rom(void **state)
{
    (void)state;
    const double keys[] = {0, 0.8, 1}, vals[] = {0.9, 0.5, 0.2};
    for (int i = 0; i < 3; i++) /* an interpolating spline passes through every key */
        assert_near(ramp_at("catmull-rom", ramp3, keys[i]), vals[i], 1e-6);
    double t = 0.3, f = t / 0.8; /* segment 0: children 0, 1 with the end repeated */
    assert_near(ramp_at("catmull-rom", ramp3, t), catmull_rom(vals[0], vals[0], vals[1], vals[2], f), 1e-6);
    t = 0.9, f = (t - 0.8) / 0.2;
    assert_near(ramp_at("catmull-rom", ramp3, t), catmull_rom(vals[0], vals[1], vals[2], vals[2], f), 1e-6);
}

/* colors { KEY COLOR ... }: lambert children with those reflectances, or children like a named material */
static void test_color_ramp(void **state)
{
    (void)state;
    const char ramp[] = "0 rgb 0.9 0.9 0.9  0.8 rgb 0.5 0.45 0.4  1 rgb 0.2 0.2 0.2";
    const double keys[] = {0, 0.8, 1}, vals[] = {0.9, 0.5, 0.2};
    for (int i = 0; i < 3; i++)
        assert_near(ramp_with("", "colors {", "linear", ramp, keys[i]), vals[i], 1e-6);
    assert_near(ramp_with("", "colors {", "linear", ramp, 0.4), 0.7, 1e-6);
    assert_near(ramp_with("", "colors {", "linear", ramp, 0.9), 0.35, 1e-6);
    assert_near(ramp_with("", "colors of lambert reflectance {", "linear", ramp, 0.9), 0.35, 1e-6);
    /* over a named phong: each child is `like tile { diffuse COLOR }` */
    const char tile[] = "material tile phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.1 0.1 0.1 exponent 20 }";
    assert_near(ramp_with(tile, "colors of tile diffuse {", "linear", ramp, 0.4), 0.7, 1e-6);
    assert_near(ramp_with(tile, "colors of tile diffuse {", "catmull-rom", ramp, 0.8), 0.5, 1e-6);
}

/* A material type that reads nothing (as a positional one would not read named parameters): a grey lambert. */
static int parse_plain(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GColor refl = {0};
    int rc = gcolor_alloc(&refl, greader_colormodel(r));
    double grey[3] = {0.5, 0.5, 0.5};
    if (rc == G_OK)
        rc = gcolor_from_rgb(&refl, grey, GCOLOR_REFLECTANCE);
    GMaterial *m = NULL;
    if (rc == G_OK)
        rc = glambert_create(greader_colormodel(r), &refl, &m, err);
    gcolor_free(&refl);
    *object = m;
    return rc;
}

static const GTypeInfo plain_type = {GKIND_MATERIAL, "plain", NULL, parse_plain, "test: reads nothing", NULL, NULL};

static void test_ramp_refused(void **state)
{
    (void)state;
    load_fails("node n spline { t constant ramp { 0.5 lambert 0.2 lambert } }\n",
               "t.mat:1:47: spline: ramp key 0.2 comes after 0.5 (keys must not decrease)");
    load_fails("node n spline { t constant ramp { 0 lambert 1.5 lambert } }\n",
               "t.mat:1:45: value 1.5 is out of range [0, 1]");
    load_fails("node n spline { t constant ramp { -0.1 lambert 1 lambert } }\n",
               "t.mat:1:35: value -0.1 is out of range [0, 1]");
    load_fails("node n spline { t constant ramp { } }\n",
               "t.mat:1:35: spline: a ramp needs at least 2 keys, got 0 (the block opened at 1:33)");
    load_fails("node n spline { t constant ramp {\n 0.5 lambert } }\n",
               "t.mat:2:14: spline: a ramp needs at least 2 keys, got 1 (the block opened at 1:33)");
    load_fails("node n spline { t constant ramp { 0 lambert 1 } }\n",
               "t.mat:1:47: expected a material (a type or a defined name), found '}'");
    load_fails("node n spline { t constant children { lambert lambert } ramp { 0 lambert 1 lambert } }\n",
               "t.mat:1:57: spline: children, ramp and colors exclude each other");
    /* colour ramps: a colour that is wrong, for the base it is given to, is reported at that colour */
    load_fails("material tile phong {\n"
               "    diffuse rgb 0.3 0.3 0.3\n"
               "    specular rgb 0.1 0.1 0.1\n"
               "}\n"
               "node n spline { t constant colors of tile diffuse { 0 rgb 0.2 0.2 0.2  1 rgb 0.95 0.95 0.95 } }\n",
               "t.mat:5:74: phong: kd + ks + mirror is 1.05 at sample 0; it must not exceed 1 (energy conservation)");
    load_fails("node n spline { t constant colors { 0 rgb 0.2 0.2 0.2  1 rgb 2 2 2 } }\n",
               "t.mat:1:58: lambert: reflectance has the value 2 at sample 0 (must be <= 1)");
    load_fails("node n spline { t constant colors of nothing diffuse { 0 rgb 1 1 1  1 rgb 0 0 0 } }\n",
               "t.mat:1:38: spline: colors of 'nothing': neither a material defined before nor a material type");
    load_fails("node n spline { t constant colors of phong colour { 0 rgb 1 1 1  1 rgb 0 0 0 } }\n",
               "t.mat:1:55: material phong: unknown parameter 'colour' (expected one of: diffuse, specular, exponent, "
               "mirror)");
    load_fails("node n spline { t constant colors of plain x { 0 rgb 1 1 1  1 rgb 0 0 0 } }\n",
               "t.mat:1:50: material type plain takes no named parameters (no 'x')");
    /* generated: the largest ramp loads, one key more is refused at that key */
    size_t cap = 1 << 20, n = 0;
    char *text = malloc(cap);
    n += (size_t)snprintf(text + n, cap - n, "material g lambert\nnode n spline { t constant ramp {\n");
    for (int i = 0; i < GSPLINE_MAX_KEYS; i++)
        n += (size_t)snprintf(text + n, cap - n, "%.17g g\n", (double)i / (GSPLINE_MAX_KEYS - 1));
    snprintf(text + n, cap - n, "} }\n");
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(greader_load_string(text, "t.mat", NULL, &lib, &err), G_OK);
    glibrary_destroy(lib);
    snprintf(text + n, cap - n, "1 g } }\n");
    char want[200];
    snprintf(want, sizeof want, "t.mat:%d:1: spline: a ramp has at most %d keys", GSPLINE_MAX_KEYS + 3,
             GSPLINE_MAX_KEYS);
    load_fails(text, want);
    free(text);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK || gregistry_add(&plain_type, NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ramp_linear),
        cmocka_unit_test(test_ramp_catmull_rom),
        cmocka_unit_test(test_color_ramp),
        cmocka_unit_test(test_ramp_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
