/* test_texture_parse.c - texture trees read from the text format: nested and named nodes and generators
 * evaluate as the same trees built in code, shape trees, clear file:line:col messages for bad input, and
 * every example in examples/textures/ loads. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"

#include <dirent.h>
#include <stdio.h>

typedef struct Fix {
    GScratch *scratch;
    GLibrary *lib;
    GColor c;
} Fix;

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    f->scratch = gscratch_create(0);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    gcolor_free(&f->c);
    glibrary_destroy(f->lib);
    gscratch_destroy(f->scratch);
    free(f);
    return 0;
}

static void load(Fix *f, const char *text)
{
    GError err;
    int rc = greader_load_string(text, "test.mat", NULL, &f->lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    assert_int_equal(gcolor_alloc(&f->c, glibrary_colormodel(f->lib)), G_OK);
}

static int load_error(const char *text, GError *err)
{
    GLibrary *lib = NULL;
    int rc = greader_load_string(text, "bad.mat", NULL, &lib, err);
    assert_null(lib);
    return rc;
}

/* Red channel of the diffuse colour of a named tree at (u, v) / object point p. */
static double diffuse_at(Fix *f, const char *name, double u, double v, GVec3 p)
{
    GMaterial *m = glibrary_material(f->lib, name);
    assert_non_null(m);
    GSurfPoint sp;
    plane_point(&sp, glibrary_colormodel(f->lib), f->scratch, u, v);
    sp.object_point = sp.point = p;
    sp.material = m;
    assert_int_equal(gmaterial_diffuse(m, &sp, &f->c), G_OK);
    return color_r(&f->c);
}

static void test_interpolate_checker(void **state)
{
    Fix *f = *state;
    load(f, "material black lambert { reflectance rgb 0.1 0.1 0.1 }\n"
            "material white lambert { reflectance rgb 0.9 0.9 0.9 }\n"
            "generator chk checker { frequency 2 }\n"
            "node board interpolate { a black  b white  t chk }\n"
            "node nested interpolate { a black  b lambert { reflectance rgb 0.5 0.5 0.5 }  t constant { value 0.5 } }\n"
            "node moved transform { child board  uv { translate 0.25 0 } }\n");
    assert_float_equal(diffuse_at(f, "board", 0.25, 0.25, gvec3(0, 0, 0)), 0.1, 1e-6);
    assert_float_equal(diffuse_at(f, "board", 0.75, 0.25, gvec3(0, 0, 0)), 0.9, 1e-6);
    assert_float_equal(diffuse_at(f, "nested", 0.1, 0.1, gvec3(0, 0, 0)), 0.3, 1e-6);
    assert_float_equal(diffuse_at(f, "moved", 0.6, 0.25, gvec3(0, 0, 0)), 0.1, 1e-6); /* edge moved to 0.75 */
    assert_float_equal(diffuse_at(f, "moved", 0.8, 0.25, gvec3(0, 0, 0)), 0.9, 1e-6);
    assert_non_null(glibrary_find(f->lib, GKIND_GENERATOR, "chk"));
    assert_int_equal(glibrary_count(f->lib, GKIND_NODE), 3);
}

static void test_select_spline_bump_scale(void **state)
{
    Fix *f = *state;
    load(f,
         "node faces select { index surface children {\n"
         "    lambert { reflectance rgb 0.2 0 0 } lambert { reflectance rgb 0.4 0 0 } lambert { reflectance rgb 0.6 0 "
         "0 } } }\n"
         "node bands spline { t gradient { space uv slope 1 0 0 } basis linear children {\n"
         "    lambert { reflectance rgb 0 0 0 } lambert { reflectance rgb 0.8 0.8 0.8 } } }\n"
         "node bumpy bump { child bands height gradient { slope 0.5 0 0 } strength 2 }\n"
         "node dim scale { child bands factor constant { value 0.5 } }\n"
         "node glass interpolate-one { method refraction_index a dielectric { index 1.5 } b dielectric { index 1.3 }\n"
         "    t constant { value 0.5 } }\n");
    GMaterial *faces = glibrary_material(f->lib, "faces");
    GSurfPoint sp;
    plane_point(&sp, glibrary_colormodel(f->lib), f->scratch, 0, 0);
    sp.surface = 2;
    assert_int_equal(gmaterial_diffuse(faces, &sp, &f->c), G_OK);
    assert_float_equal(color_r(&f->c), 0.6, 1e-6);
    assert_float_equal(diffuse_at(f, "bands", 0.25, 0, gvec3(0, 0, 0)), 0.2, 1e-6);
    assert_float_equal(diffuse_at(f, "dim", 0.25, 0, gvec3(0, 0, 0)), 0.1, 1e-6);
    /* bump: h = 0.5 u, strength 2: tilt atan(1) */
    GMaterial *b = glibrary_material(f->lib, "bumpy");
    plane_point(&sp, glibrary_colormodel(f->lib), f->scratch, 0.5, 0.5);
    GVec3 n;
    assert_int_equal(gmaterial_normal(b, &sp, &n), G_OK);
    assert_float_equal(n.x, -sqrt(0.5), 1e-12);
    assert_float_equal(n.z, sqrt(0.5), 1e-12);
    GMaterial *g = glibrary_material(f->lib, "glass");
    assert_int_equal(gmaterial_refraction_index(g, &sp, &f->c), G_OK);
    assert_float_equal(gcolor_brightness(&f->c), 1.4, 1e-3);
    assert_int_equal(gmaterial_opaque(g, &sp), 0);
}

static void test_shapes_from_text(void **state)
{
    Fix *f = *state;
    load(f, "material out lambert { reflectance rgb 0 0 0 }\n"
            "material in lambert { reflectance rgb 1 1 1 }\n"
            "generator ring cpg { shape difference { circle 0 0 1  circle 0 0 0.5 } }\n"
            "generator disk cpg { shape path { nurbs { degree 2\n"
            "    points { 1 0  1 1  0 1  -1 1  -1 0  -1 -1  0 -1  1 -1  1 0 }\n"
            "    weights { 1 0.7071067811865476 1 0.7071067811865476 1 0.7071067811865476 1 0.7071067811865476 1 }\n"
            "    knots { 0 0 0 0.25 0.25 0.5 0.5 0.75 0.75 1 1 1 } } } }\n"
            "generator blob cpg { shape transform { scale 2 translate 1 0 } path {\n"
            "    lines { 0 -1 } bezier { 0 -1  1 -1  1 1  0 1 } bspline { degree 2 points { 0 1  -1 1  -1 -1  0 -1 } } "
            "} }\n"
            "generator star cpg { shape polygon { 0 1  0.588 -0.809  -0.951 0.309  0.951 0.309  -0.588 -0.809 } }\n"
            "generator solid csg { shape difference { box -1 -1 -1 1 1 1  transform { translate 1 1 1 } sphere 1 } }\n"
            "node r interpolate { a out b in t ring }\n"
            "node d interpolate { a out b in t disk }\n"
            "node s interpolate { a out b in t solid }\n");
    assert_float_equal(diffuse_at(f, "r", 0.75, 0, gvec3(0, 0, 0)), 1.0, 1e-6);
    assert_float_equal(diffuse_at(f, "r", 0.25, 0, gvec3(0, 0, 0)), 0.0, 1e-6);
    double a = 0.3;
    assert_float_equal(diffuse_at(f, "d", (1 - 1e-6) * cos(a), (1 - 1e-6) * sin(a), gvec3(0, 0, 0)), 1.0, 1e-6);
    assert_float_equal(diffuse_at(f, "d", (1 + 1e-6) * cos(a), (1 + 1e-6) * sin(a), gvec3(0, 0, 0)), 0.0, 1e-6);
    assert_float_equal(diffuse_at(f, "s", 0, 0, gvec3(-0.5, -0.5, -0.5)), 1.0, 1e-6);
    assert_float_equal(diffuse_at(f, "s", 0, 0, gvec3(0.9, 0.9, 0.9)), 0.0, 1e-6);
    GGenerator *blob = glibrary_find(f->lib, GKIND_GENERATOR, "blob");
    GGenerator *star = glibrary_find(f->lib, GKIND_GENERATOR, "star");
    GSurfPoint sp;
    plane_point(&sp, NULL, NULL, 1.0 + 2 * 0.7, 0.0); /* (0.7, 0) before the transform: inside the Bézier */
    assert_float_equal(ggenerator_value(blob, &sp), 1.0, 0.0);
    sp.u = 1.0 + 2 * 0.8; /* the cubic reaches x = 0.75 at its middle */
    assert_float_equal(ggenerator_value(blob, &sp), 0.0, 0.0);
    sp.u = 0.0;
    sp.v = 0.0;
    assert_float_equal(ggenerator_value(star, &sp), 1.0, 0.0);
}

static void test_errors(void **state)
{
    (void)state;
    GError err;
    assert_int_equal(load_error("material m lambert\nnode n interpolate { a m b m t checker { dims 4 } }\n", &err),
                     G_ERR_PARSE);
    assert_non_null(strstr(err.message, "bad.mat:2:"));
    print_message("%s\n", err.message);

    assert_int_equal(load_error("material m lambert\nnode n select { index surface children { } }\n", &err),
                     G_ERR_INVALID);
    assert_non_null(strstr(err.message, "bad.mat:2:"));
    assert_non_null(strstr(err.message, "no children"));
    print_message("%s\n", err.message);

    assert_int_equal(load_error("generator g cpg { shape polygon { 0 0 1 1 } }\n", &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "bad.mat:1:"));
    assert_non_null(strstr(err.message, "at least 3 points"));
    print_message("%s\n", err.message);

    assert_int_equal(load_error("generator g cpg { shape path { nurbs { degree 2 points { 0 0 1 1 2 0 }\n"
                                "  weights { 1 0 1 } } } }\n",
                                &err),
                     G_ERR_INVALID);
    assert_non_null(strstr(err.message, "weight 2 is 0"));
    print_message("%s\n", err.message);

    assert_int_equal(load_error("material m lambert\nnode i image { child m file \"no/such/file.png\" }\n", &err),
                     G_ERR_IO);
    assert_non_null(strstr(err.message, "bad.mat:2:"));
    assert_non_null(strstr(err.message, "no such file"));
    print_message("%s\n", err.message);

    assert_int_equal(load_error("material m lambert\nnode n interpolate { a m t constant }\n", &err), G_ERR_PARSE);
    assert_non_null(strstr(err.message, "needs a, b and t"));
    assert_int_equal(load_error("material m lambert\nnode n interpolate-one { a m b m t constant method shine }\n",
                                &err),
                     G_ERR_PARSE);
    assert_non_null(strstr(err.message, "unknown method 'shine' (reflection, refraction, refraction_index, "
                                        "reflection_dir, refraction_dir, emission, ambient, absorption, normal, "
                                        "diffuse, opaque)"));
    assert_int_equal(load_error("node n bump { child nothing height constant }\n", &err), G_ERR_NOTFOUND);
    assert_non_null(strstr(err.message, "nothing"));
    assert_int_equal(load_error("generator w wood { latewood 2 }\n", &err), G_ERR_PARSE);
    assert_non_null(strstr(err.message, "out of range"));
    assert_int_equal(load_error("generator c csg { shape union { } }\n", &err), G_ERR_PARSE);
    assert_non_null(strstr(err.message, "no shapes"));
    assert_int_equal(load_error("material m lambert\nnode t transform { child m uv { scale 0 } }\n", &err),
                     G_ERR_INVALID);
    assert_non_null(strstr(err.message, "singular"));
    /* deep shape chains are refused, not recursed into without bound */
    char deep[4096] = "generator c cpg { shape ";
    for (int i = 0; i < 100; i++)
        strcat(deep, "transform { } ");
    strcat(deep, "circle 0 0 1 }\n");
    assert_int_equal(load_error(deep, &err), G_ERR_PARSE);
    assert_non_null(strstr(err.message, "nested more than"));
}

/* Every example file loads (image files it names are resolved next to it). */
static void test_examples_load(void **state)
{
    (void)state;
    const char *src = getenv("GENERIC_SOURCE_DIR");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/examples/textures", src ? src : ".");
    DIR *d = opendir(dir);
    if (!d)
        skip();
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (l < 5 || strcmp(e->d_name + l - 4, ".txt") != 0)
            continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        GLibrary *lib = NULL;
        GError err;
        int rc = greader_load_file(path, NULL, &lib, &err);
        if (rc != G_OK)
            print_error("%s\n", err.message);
        assert_int_equal(rc, G_OK);
        assert_true(glibrary_count(lib, GKIND_NODE) + glibrary_count(lib, GKIND_GENERATOR) > 0);
        glibrary_destroy(lib);
        n++;
    }
    closedir(d);
    print_message("%d example files loaded\n", n);
    assert_true(n >= 10);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_interpolate_checker, setup, teardown),
        cmocka_unit_test_setup_teardown(test_select_spline_bump_scale, setup, teardown),
        cmocka_unit_test_setup_teardown(test_shapes_from_text, setup, teardown),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_examples_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
