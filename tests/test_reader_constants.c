/* test_reader_constants.c - `define NAME VALUE`: constants read wherever a number is (parameters, colour
 * literals, vectors, optional trailing numbers, other constants), and the errors: use before definition,
 * redefinition, reserved names, a non-number value; many constants load in linear time. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/reader.h"
#include "test_util.h"
#include "reader_fixture.h"

static GLibrary *load(const char *text)
{
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return lib;
}

/* rgb values: room for the model's capacity (a 3 x 3 matrix) */
static void color_of(GLibrary *lib, const char *name, float v[9])
{
    GColor c;
    assert_int_equal(gcolor_wrap(&c, glibrary_colormodel(lib), v, 9), G_OK);
    assert_int_equal(glibrary_color(lib, name, GCOLOR_REFLECTANCE, &c, NULL), G_OK);
}

static void test_constants_used(void **state)
{
    (void)state;
    GLibrary *lib = load("define grey 0.35\n"
                         "define grey2 grey          # a constant's value may be another constant\n"
                         "define half 0.5\n"
                         "define power 3\n"
                         "color a rgb grey grey2 half\n"
                         "color b rgb <half, grey, 0.1>\n"
                         "color c line 550 power     # an optional trailing number\n"
                         "color d scale half rgb 1 1 1\n"
                         "material m dielectric { index half }\n");
    float v[9];
    color_of(lib, "a", v);
    assert_near(v[0], 0.35, 1e-6);
    assert_near(v[1], 0.35, 1e-6);
    assert_near(v[2], 0.5, 1e-6);
    color_of(lib, "b", v);
    assert_near(v[0], 0.5, 1e-6);
    assert_near(v[2], 0.1, 1e-6);
    color_of(lib, "d", v);
    assert_near(v[1], 0.5, 1e-6);
    const GColorSpec *c = glibrary_find(lib, GKIND_COLOR, "c");
    assert_non_null(c);
    assert_near(c->line_power, 3, 0);
    glibrary_destroy(lib);
}

static void test_constants_errors(void **state)
{
    (void)state;
    load_fails("color a rgb k 0 0\ndefine k 1\n",
               "t.mat:1:13: color rgb: expected a number or a constant defined before, found 'k'");
    load_fails("define k 1\ndefine k 2\n",
               "t.mat:2:8: constant 'k' is already defined (at t.mat:1:8); constants cannot be redefined");
    load_fails("define rgb 1\n", "t.mat:1:8: 'rgb' cannot name a constant: it is a type keyword");
    load_fails("define material 1\n", "t.mat:1:8: 'material' cannot name a constant: it is a kind keyword");
    load_fails("define yes 1\n", "t.mat:1:8: 'yes' cannot name a constant: it is a keyword of the format");
    load_fails("define k \"x\"\n", "t.mat:1:10: expected a number, found string \"x\"");
    load_fails("define k nope\n", "t.mat:1:10: expected a number or a constant defined before, found 'nope'");
    load_fails("define 3 4\n", "t.mat:1:8: expected a constant's name after 'define', found number 3");
    load_fails("define k\n", "t.mat:2:1: expected a number, found end of file");
    load_fails("define k 2\nmaterial m lambert { reflectance rgb k k k }\n",
               "t.mat:2:22: lambert: reflectance has the value 2 at sample 0 (must be <= 1)");
}

static void test_many_constants(void **state)
{
    (void)state;
    size_t cap = 8u << 20, n = 0;
    char *text = malloc(cap);
    for (int i = 0; i < 100000; i++)
        n += (size_t)snprintf(text + n, cap - n, "define k%d %d\n", i, i % 2);
    n += (size_t)snprintf(text + n, cap - n, "color c rgb k99999 k3 k100\n");
    double t0 = tu_seconds();
    GLibrary *lib = load(text);
    assert_true(tu_seconds() - t0 < 10.0);
    float v[9];
    color_of(lib, "c", v);
    assert_near(v[0], 1, 1e-6);
    assert_near(v[1], 1, 1e-6);
    assert_near(v[2], 0, 1e-6);
    glibrary_destroy(lib);
    free(text);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_constants_used),
        cmocka_unit_test(test_constants_errors),
        cmocka_unit_test(test_many_constants),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
