/* test_reader_like.c - entries derived with `like`: overridden and inherited parameters read back (phong,
 * a colour, a spline node, a test-only type registered here as a plug-in's would be), chains, where errors are
 * reported (an override, an inherited parameter at the base's line with the `like` that inherited it, across
 * an include), what glibrary_entry_base says, and the bounds (chain depth, re-read tokens). */
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
#include "generic/memory.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
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

/* ---- a type registered by the test, as a module would: `object pair { a A  b B }` with a < b ---- */

typedef struct Pair {
    double a, b;
} Pair;

static int parse_pair(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    double a = 0, b = 1;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "a") == 0)
            rc = greader_number(r, &a, err);
        else if (strcmp(key, "b") == 0)
            rc = greader_number(r, &b, err);
        else
            rc = greader_unknown_param(r, "a, b", err);
        if (rc < 0)
            return rc;
    }
    if (!(a < b)) /* the constructor's complaint names a parameter: the reader places it there */
        return gerror_set_param(err, G_ERR_INVALID, "a", "pair: a = %g must be below b = %g", a, b);
    Pair *p = gmem_alloc(sizeof *p);
    if (!p)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    p->a = a;
    p->b = b;
    *object = p;
    return G_OK;
}

static GKind object_kind; /* registered by register_types */
static GTypeInfo pair_type = {GKIND_MAX, "pair", NULL, parse_pair, "test pair", NULL, NULL};

static int register_types(void **state)
{
    (void)state;
    if (generic_register_builtins(NULL) != G_OK)
        return -1;
    object_kind = pair_type.kind = register_scene_kinds().object;
    if (!gregistry_find(object_kind, "pair"))
        assert_int_equal(gregistry_add(&pair_type, NULL), G_OK);
    return 0;
}

static const Pair *pair(GLibrary *lib, const char *name) { return glibrary_find(lib, object_kind, name); }

/* The diffuse colour and the reflection at 30 degrees off the mirror direction of a material. */
typedef struct Probe {
    float diffuse[9], refl[9]; /* rgb's capacity: room for a 3 x 3 matrix */
} Probe;

static Probe probe(GLibrary *lib, const char *name)
{
    const GColorModel *m = glibrary_colormodel(lib);
    GMaterial *mat = glibrary_material(lib, name);
    assert_non_null(mat);
    GScratch *s = gscratch_create(0);
    GSurfPoint sp;
    gsurfpoint_init(&sp, m, s);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.entering = 1;
    sp.material = mat;
    Probe p;
    float iv[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor illum, out;
    assert_int_equal(gcolor_wrap(&illum, m, iv, tu_floats(iv)), G_OK);
    double one[3] = {1, 1, 1};
    assert_int_equal(gcolor_from_rgb(&illum, one, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_wrap(&out, m, p.diffuse, tu_floats(p.diffuse)), G_OK);
    assert_int_equal(gmaterial_diffuse(mat, &sp, &out), G_OK);
    assert_int_equal(gcolor_wrap(&out, m, p.refl, tu_floats(p.refl)), G_OK);
    gsurfpoint_invalidate(&sp);
    assert_int_equal(gmaterial_reflection(mat, &sp, gvec3(0, 0, 1), &illum, gvec3(0.5, 0, sqrt(0.75)), &out), G_OK);
    gscratch_destroy(s);
    return p;
}

/* Phong's f_r at 30 degrees from the mirror direction: kd / pi + ks (n + 2) / (2 pi) cos^n(30). */
static double phong_fr(double kd, double ks, double n)
{
    return kd / M_PI + ks * (n + 2) / (2 * M_PI) * pow(0.75, n / 2);
}

static void test_like_overrides_and_inherits(void **state)
{
    (void)state;
    GLibrary *lib = load("material tile1 phong {\n"
                         "    diffuse rgb 0.3 0.2 0.1\n"
                         "    specular rgb 0.2 0.2 0.2\n"
                         "    exponent 4\n"
                         "}\n"
                         "material tile2 like tile1 { diffuse rgb 0.5 0.4 0.3 }\n"
                         "material tile3 like tile2 { exponent 2 }\n"
                         "material tile4 like tile1\n"
                         "material tile5 like tile1 { }\n");
    Probe p1 = probe(lib, "tile1"), p2 = probe(lib, "tile2"), p3 = probe(lib, "tile3"), p4 = probe(lib, "tile4");
    Probe p5 = probe(lib, "tile5");
    assert_near(p1.diffuse[0], 0.3, 1e-6);
    assert_near(p2.diffuse[0], 0.5, 1e-6); /* overridden */
    assert_near(p2.diffuse[2], 0.3, 1e-6);
    assert_near(p2.refl[0], phong_fr(0.5, 0.2, 4), 1e-5); /* specular and exponent inherited */
    assert_near(p3.diffuse[1], 0.4, 1e-6);                /* through the chain */
    assert_near(p3.refl[1], phong_fr(0.4, 0.2, 2), 1e-5);
    assert_near(p4.diffuse[0], 0.3, 1e-6); /* a copy */
    assert_near(p4.refl[0], p1.refl[0], 1e-7);
    assert_near(p5.refl[2], p1.refl[2], 1e-7);
    assert_true(glibrary_material(lib, "tile4") != glibrary_material(lib, "tile1")); /* a new object */

    /* gmat list's source: what each entry was derived from */
    const char *want[] = {NULL, "tile1", "tile2", "tile1", "tile1"};
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 5);
    for (int i = 0; i < 5; i++) {
        const char *base = glibrary_entry_base(lib, GKIND_MATERIAL, i);
        if (want[i])
            assert_string_equal(base, want[i]);
        else
            assert_null(base);
    }
    assert_null(glibrary_entry_base(lib, GKIND_MATERIAL, 5));
    glibrary_destroy(lib);
}

static void test_like_other_kinds(void **state)
{
    (void)state;
    GLibrary *lib = load("color warm rgb 0.6 0.3 0.1\n"
                         "color warm2 like warm\n"
                         "object p1 pair { a 1 b 5 }\n"
                         "object p2 like p1 { b 7 }\n"
                         "object p3 like p2 { a 2 }\n"
                         "node ramp1 spline { t constant { value 0.5 } basis linear\n"
                         "                    ramp { 0 lambert { reflectance rgb 0 0 0 } 1 lambert } }\n"
                         "node ramp2 like ramp1 { t constant { value 0.25 } }\n"
                         "material tile phong { diffuse rgb 0.1 0.1 0.1 specular rgb 0.1 0.1 0.1 }\n"
                         "node c1 spline { colors of tile diffuse { 0 rgb 0 0 0  1 rgb 0.4 0.4 0.4 }\n"
                         "                 basis linear t constant { value 0.5 } }\n"
                         "node c2 like c1 { t constant { value 0.25 } }\n");
    assert_near(pair(lib, "p2")->a, 1, 0);
    assert_near(pair(lib, "p2")->b, 7, 0);
    assert_near(pair(lib, "p3")->a, 2, 0);
    assert_near(pair(lib, "p3")->b, 7, 0);
    float v[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor c;
    assert_int_equal(gcolor_wrap(&c, glibrary_colormodel(lib), v, tu_floats(v)), G_OK);
    assert_int_equal(glibrary_color(lib, "warm2", GCOLOR_REFLECTANCE, &c, NULL), G_OK);
    assert_near(v[1], 0.3, 1e-6);
    assert_near(probe(lib, "ramp1").diffuse[0], 0.4, 1e-6); /* 0.5 of the way to lambert's default 0.8 */
    assert_near(probe(lib, "ramp2").diffuse[0], 0.2, 1e-6);
    assert_string_equal(glibrary_entry_base(lib, object_kind, 2), "p2");
    /* a parameter whose value re-reads another entry (a colour ramp over a named phong) is inherited whole */
    assert_near(probe(lib, "c1").diffuse[0], 0.2, 1e-6);
    assert_near(probe(lib, "c2").diffuse[0], 0.1, 1e-6);
    glibrary_destroy(lib);
}

static void test_like_errors(void **state)
{
    (void)state;
    /* an override that is wrong: at the override */
    load_fails("material a phong { diffuse rgb 0.3 0.3 0.3 }\n"
               "material b like a { exponent -1 }\n",
               "t.mat:2:30: value -1 is out of range [0, 1e+06]");
    /* an inherited parameter the constructor complains about: at the base's line, saying it was inherited */
    load_fails("object p1 pair {\n"
               "    a 4\n"
               "    b 5\n"
               "}\n"
               "object p2 like p1 { b 3 }\n",
               "t.mat:2:5: pair: a = 4 must be below b = 3 (inherited by object 'p2' via 'like' at t.mat:5:8)");
    /* a complaint about no parameter in particular: at the entry derived */
    load_fails("material a phong { diffuse rgb 0.6 0.6 0.6 specular rgb 0.3 0.3 0.3 }\n"
               "material b like a { mirror rgb 0.3 0.3 0.3 }\n",
               "t.mat:2:17: phong: kd + ks + mirror is 1.2 at sample 0; it must not exceed 1 (energy conservation)");
    load_fails("material a like b\n",
               "t.mat:1:17: 'like b': no material 'b' is defined before this line (defined: none)");
    load_fails("material a lambert\nmaterial like a\n",
               "t.mat:2:10: 'like' needs the new entry's name before it: material NAME like BASE { ... }");
    load_fails("material a lambert\nmaterial b a\nmaterial c like b\n",
               "t.mat:3:17: 'like b': material 'b' was not written with a type and parameters (it is another name "
               "for an entry, or was made by code), so it cannot be derived from");
    load_fails("color a rgb 1 1 1\ncolor b like a { x 1 }\n",
               "t.mat:2:16: 'like a': color type rgb takes no named parameters, so there is nothing to override "
               "('like' without a block copies it)");
    load_fails("material a lambert\nmaterial a like a\n", "t.mat:2:10: material 'a' is already defined");
    load_fails("material a lambert\nmaterial b like a { colour rgb 1 1 1 }\n",
               "t.mat:2:21: material lambert: unknown parameter 'colour' (expected one of: reflectance)");
    load_fails("material a lambert\nmaterial b like 1\n",
               "t.mat:2:17: expected the name of a material to derive from after 'like', found number 1");
}

static void test_like_across_files(void **state)
{
    (void)state;
    char dir[256], path[512], main_path[512];
    assert_int_equal(tu_tempdir(dir, sizeof dir, "like"), 0);
    snprintf(path, sizeof path, "%s/base.mat", dir);
    snprintf(main_path, sizeof main_path, "%s/main.mat", dir);
    assert_int_equal(tu_write_file(path, "# base\nobject p1 pair { a 2 b 9 }\n"), 0);
    assert_int_equal(tu_write_file(main_path, "include \"base.mat\"\nobject p2 like p1 { b 1 }\n"), 0);
    GLibrary *lib = NULL;
    GError err;
    assert_true(greader_load_file(main_path, NULL, &lib, &err) < 0);
    char want[1600];
    snprintf(want, sizeof want,
             "%s:2:18: pair: a = 2 must be below b = 1 (inherited by object 'p2' via 'like' at %s:2:8)", path,
             main_path);
    assert_string_equal(err.message, want);
    /* a second file loaded into the library derives from the first's entries */
    assert_int_equal(tu_write_file(main_path, "object p2 like p1 { b 4 }\n"), 0);
    assert_int_equal(greader_load_file(path, NULL, &lib, &err), G_OK);
    assert_int_equal(glibrary_load_file(lib, main_path, NULL, &err), G_OK);
    assert_near(pair(lib, "p2")->a, 2, 0);
    assert_near(pair(lib, "p2")->b, 4, 0);
    glibrary_destroy(lib);
    tu_rmtree(dir);
}

static void test_like_bounds(void **state)
{
    (void)state;
    /* a chain as deep as allowed loads; one more is refused at the base's name */
    size_t cap = 1 << 16;
    char *text = malloc(cap);
    size_t n = (size_t)snprintf(text, cap, "object p0 pair { a 0 b 1 }\n");
    for (int i = 1; i <= 32; i++)
        n += (size_t)snprintf(text + n, cap - n, "object p%d like p%d { a %d b %d }\n", i, i - 1, -i, i);
    GLibrary *lib = load(text);
    assert_near(pair(lib, "p32")->a, -32, 0);
    glibrary_destroy(lib);
    n += (size_t)snprintf(text + n, cap - n, "object p33 like p32\n");
    load_fails(text, "t.mat:34:17: 'like p32': a chain of entries derived with 'like' may be at most 32 deep");

    /* a base with many parameters copied by many entries: refused once the re-read tokens pass the budget */
    free(text);
    cap = 8u << 20;
    text = malloc(cap);
    n = (size_t)snprintf(text, cap, "color big spectrum {");
    for (int i = 0; i < 20000; i++)
        n += (size_t)snprintf(text + n, cap - n, " %d 0.5", 380 + i);
    n += (size_t)snprintf(text + n, cap - n, " }\n");
    /* spectrum reads a positional block: each copy re-reads ~40,000 tokens; 40 copies exceed 16x the file */
    for (int i = 0; i < 40; i++)
        n += (size_t)snprintf(text + n, cap - n, "color c%d like big\n", i);
    lib = (GLibrary *)0x1;
    GError err;
    assert_true(greader_load_string(text, "t.mat", NULL, &lib, &err) < 0);
    assert_non_null(strstr(err.message, "entries derived with 'like' re-read more than"));
    assert_null(lib);
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_like_overrides_and_inherits),
        cmocka_unit_test(test_like_other_kinds),
        cmocka_unit_test(test_like_errors),
        cmocka_unit_test(test_like_across_files),
        cmocka_unit_test(test_like_bounds),
    };
    return cmocka_run_group_tests(tests, register_types, NULL);
}
