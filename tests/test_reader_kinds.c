/* test_reader_kinds.c - kinds an application registers at run time (gregistry_add_kind): registered once whatever
 * the number of calls, refused when the keyword is taken, not an identifier or a statement, or past GKIND_MAX;
 * entries of such a kind read from text (named, anonymous, derived with `like`), listed in the reader's messages,
 * and released through the kind's destroy when their types have none; a kind that shares the materials' names. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/reader.h"
#include "reader_fixture.h"

/* ---- a kind of the test's own: `widget NAME gadget { size S }` ---- */

typedef struct Gadget {
    double size;
} Gadget;

static int gadgets_released;

static void release_gadget(void *object)
{
    gadgets_released++;
    gmem_free(object);
}

static int parse_gadget(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    double size = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = strcmp(key, "size") == 0 ? greader_number_in(r, 0.0, 100.0, &size, err)
                                       : greader_unknown_param(r, "size", err);
        if (rc < 0)
            return rc;
    }
    Gadget *g = gmem_alloc(sizeof *g);
    if (!g)
        return greader_error(r, err, "out of memory");
    g->size = size;
    *object = g;
    return G_OK;
}

static const GKindInfo widget_info = {"widget", release_gadget, 0};

static void test_registering_kinds(void **state)
{
    (void)state;
    GError err;
    GKind widget, again;
    int before = gkind_count();
    assert_true(before >= GKIND_GENERATOR + 1);
    assert_int_equal(gregistry_add_kind(&widget_info, &widget, &err), G_OK);
    assert_int_equal(widget, before);
    assert_int_equal(gkind_count(), before + 1);
    assert_string_equal(gkind_name(widget), "widget");
    assert_ptr_equal(gkind_info(widget)->destroy, release_gadget);
    /* the same record again: the same kind */
    assert_int_equal(gregistry_add_kind(&widget_info, &again, &err), G_OK);
    assert_int_equal(again, widget);
    assert_int_equal(gkind_count(), before + 1);
    assert_int_equal(gkind_find("widget", &again), 1);
    assert_int_equal(again, widget);
    assert_int_equal(gkind_find("widgets", &again), 0);
    /* a keyword taken by another record, the library's among them */
    static const GKindInfo other = {"widget", NULL, 0}, material = {"material", NULL, 0};
    assert_int_equal(gregistry_add_kind(&other, &again, &err), G_ERR_EXISTS);
    assert_string_equal(err.message, "kind 'widget' is already registered");
    assert_int_equal(gregistry_add_kind(&material, &again, &err), G_ERR_EXISTS);
    /* keywords a file could not write as an entry */
    static const GKindInfo bad[] = {{"include", NULL, 0}, {"define", NULL, 0}, {"9lives", NULL, 0}, {"", NULL, 0},
                                    {"two words", NULL, 0}, {NULL, NULL, 0}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_int_equal(gregistry_add_kind(&bad[i], &again, &err), G_ERR_INVALID);
    assert_int_equal(gkind_count(), before + 1);
    /* the library's kinds keep their defaults; a number past the last is no kind */
    assert_non_null(gkind_info(GKIND_COLOR)->destroy);
    assert_null(gkind_info((GKind)gkind_count()));
    assert_string_equal(gkind_name((GKind)gkind_count()), "?");
    assert_int_equal(gkind_namespace(GKIND_NODE), GKIND_MATERIAL);
    assert_int_equal(gkind_namespace(widget), widget);
    /* a type of the kind is registered like any other; one without a kind is not */
    GTypeInfo gadget = {widget, "gadget", NULL, parse_gadget, "test gadget", NULL, NULL};
    assert_int_equal(gregistry_add(&gadget, &err), G_OK);
    assert_non_null(gregistry_find(widget, "gadget"));
    gadget.kind = (GKind)gkind_count();
    assert_int_equal(gregistry_add(&gadget, &err), G_ERR_INVALID);
}

static void test_entries_of_an_application_kind(void **state)
{
    (void)state;
    GKind widget;
    assert_int_equal(gregistry_add_kind(&widget_info, &widget, NULL), G_OK);
    gadgets_released = 0;
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(greader_load_string("widget w gadget { size 3 }\n"
                                         "widget gadget\n"
                                         "widget v like w\n"
                                         "define big 7\n"
                                         "widget u like w { size big }\n",
                                         "t.mat", NULL, &lib, &err),
                     G_OK);
    assert_int_equal(glibrary_count(lib, widget), 4);
    const Gadget *w = glibrary_find(lib, widget, "w"), *v = glibrary_find(lib, widget, "v");
    const Gadget *u = glibrary_find(lib, widget, "u"), *anon = glibrary_entry(lib, widget, 1, NULL, NULL);
    assert_non_null(w);
    assert_true(w->size == 3.0 && v->size == 3.0 && u->size == 7.0 && anon->size == 1.0);
    assert_string_equal(glibrary_entry_base(lib, widget, 3), "w");
    assert_null(glibrary_material(lib, "w")); /* a name of its own kind */
    glibrary_destroy(lib);
    assert_int_equal(gadgets_released, 4); /* through the kind's destroy: the type has none */
    /* messages name the kind, and list it with the statements */
    load_fails("widget w gizmo { }\n", "t.mat:1:10: unknown widget 'gizmo': neither a widget type (gadget) nor a "
                                        "defined widget (defined: none)");
    load_fails("widget w gadget { size 300 }\n", "t.mat:1:24: value 300 is out of range [0, 100]");
    load_fails("material m lambert { }\nwidget w gadget { }\nmaterial k w\n",
               "t.mat:3:12: 'w' is a widget, not a material");
    load_fails("widget w gadget\nwidgets w gadget\n",
               "t.mat:2:1: unknown statement 'widgets' (expected include, plugin, colormodel, define, color, material, "
               "node, generator, object, light, camera, widget)");
    load_fails("define widget 1\n", "t.mat:1:8: 'widget' cannot name a constant: it is a kind keyword");
    /* skipped like any kind */
    GReaderOptions skip = {.skip_kinds = 1u << widget};
    assert_int_equal(greader_load_string("widget w gadget { size 3 }\nmaterial m lambert { }\n", "t.mat", &skip,
                                         &lib, &err),
                     G_OK);
    assert_int_equal(glibrary_count(lib, widget), 0);
    assert_non_null(glibrary_material(lib, "m"));
    glibrary_destroy(lib);
}

/* ---- a kind that shares the materials' names: `shader NAME toon { base MATERIAL }` ---- */

static int shaders_released;

static void release_shader(void *object)
{
    shaders_released++;
    gmaterial_unref(object);
}

static int parse_toon(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GMaterial *base = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = strcmp(key, "base") == 0 ? greader_material(r, &base, err) : greader_unknown_param(r, "base", err);
        if (rc < 0)
            return rc;
    }
    if (!base)
        return greader_error(r, err, "toon: no base");
    *object = gmaterial_ref(base);
    return G_OK;
}

static void test_kind_sharing_material_names(void **state)
{
    (void)state;
    static const GKindInfo shader_info = {"shader", release_shader, 1};
    GKind shader;
    assert_int_equal(gregistry_add_kind(&shader_info, &shader, NULL), G_OK);
    assert_int_equal(gkind_namespace(shader), GKIND_MATERIAL);
    static GTypeInfo toon = {GKIND_MAX, "toon", NULL, parse_toon, "test toon", NULL, NULL};
    toon.kind = shader;
    if (!gregistry_find(shader, "toon"))
        assert_int_equal(gregistry_add(&toon, NULL), G_OK);
    shaders_released = 0;
    GLibrary *lib = NULL;
    GError err;
    /* a shader's name stands for a material, a material type is read as a shader's value and the other way round */
    assert_int_equal(greader_load_string("material red lambert { reflectance rgb 1 0 0 }\n"
                                         "shader s toon { base red }\n"
                                         "material t toon { base s }\n"
                                         "shader plain lambert { }\n",
                                         "t.mat", NULL, &lib, &err),
                     G_OK);
    assert_int_equal(glibrary_count(lib, shader), 2);
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 2);
    assert_ptr_equal(glibrary_material(lib, "s"), glibrary_material(lib, "red"));
    assert_ptr_equal(glibrary_material(lib, "t"), glibrary_material(lib, "red"));
    assert_string_equal(gmaterial_name(glibrary_material(lib, "plain")), "lambert");
    glibrary_destroy(lib);
    assert_int_equal(shaders_released, 2); /* s and t: toon has no destroy; lambert's kind is material's */
    load_fails("material red lambert { }\nshader red toon { base red }\n",
               "t.mat:2:8: shader 'red' is already defined");
    /* the types a material may be: the materials', the nodes', then the shaders' */
    assert_int_not_equal(greader_load_string("material red lambert { }\nmaterial m tooon { }\n", "t.mat", NULL, &lib,
                                             &err),
                         G_OK);
    assert_non_null(strstr(err.message, "t.mat:2:12: unknown material 'tooon': neither a material type ("));
    assert_non_null(strstr(err.message, ", dielectric, "));
    assert_non_null(strstr(err.message, ", transform, toon) nor a defined material (defined: red)"));
}

/* Every type keyword of the material namespace may name a material: `material plastic lambert { }` is a lambert
 * named "plastic". A reference to it is the defined material; with a block after it, the keyword is the type. */
static void test_type_keywords_as_names(void **state)
{
    (void)state;
    char types[4096];
    gregistry_names(GKIND_MATERIAL, types, sizeof types / 2);
    size_t used = strlen(types);
    types[used++] = ',';
    gregistry_names(GKIND_NODE, types + used, sizeof types - used);
    int checked = 0;
    for (char *save = NULL, *name = strtok_r(types, ", ", &save); name; name = strtok_r(NULL, ", ", &save)) {
        char text[1024];
        snprintf(text, sizeof text,
                 "material %s lambert { reflectance rgb 0.25 0.25 0.25 }\n"
                 "material derived like %s { reflectance rgb 0.5 0.5 0.5 }\n"
                 "material mix interpolate { a %s b lambert { } t checker { dims 2 } }\n"
                 "material lambert { }\n",
                 name, name, name);
        GLibrary *lib = NULL;
        GError err;
        int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
        if (rc != G_OK)
            print_error("%s: %s\n", name, err.message);
        assert_int_equal(rc, G_OK);
        assert_string_equal(gmaterial_name(glibrary_material(lib, name)), "lambert");
        assert_string_equal(gmaterial_name(glibrary_material(lib, "derived")), "lambert");
        assert_string_equal(gmaterial_name(glibrary_material(lib, "mix")), "interpolate");
        assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 3); /* the anonymous lambert too */
        assert_int_equal(glibrary_count(lib, GKIND_NODE), 1);
        const char *anonymous = "";
        glibrary_entry(lib, GKIND_MATERIAL, 2, &anonymous, NULL);
        assert_null(anonymous);
        glibrary_destroy(lib);
        checked++;
    }
    assert_true(checked >= 20); /* every built-in material and node type */
    /* a type keyword followed by its block is still the type, a defined name of the same spelling or not */
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(greader_load_string("material mirror lambert { }\n"
                                         "material m2 interpolate { a mirror { } b mirror t checker { dims 2 } }\n",
                                         "t.mat", NULL, &lib, &err),
                     G_OK);
    glibrary_destroy(lib);
}

/* Past GKIND_MAX kinds a kind is refused, and every kind registered before keeps working. */
static void test_kind_limit(void **state)
{
    (void)state;
    static char names[GKIND_MAX][16];
    static GKindInfo infos[GKIND_MAX];
    GKind k;
    GError err;
    for (int i = 0; gkind_count() < GKIND_MAX; i++) {
        snprintf(names[i], sizeof names[i], "filler%d", i);
        infos[i] = (GKindInfo){names[i], NULL, 0};
        assert_int_equal(gregistry_add_kind(&infos[i], &k, &err), G_OK);
        assert_true(k < GKIND_MAX);
    }
    static const GKindInfo one_more = {"one_more", NULL, 0};
    assert_int_equal(gregistry_add_kind(&one_more, &k, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "there are 32 kinds already"));
    assert_int_equal(gregistry_add_kind(&widget_info, &k, &err), G_OK); /* registered before: still there */
    assert_string_equal(gkind_name(k), "widget");
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    register_scene_kinds(); /* as gtrace does: its kinds come first, and the messages list them */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registering_kinds),
        cmocka_unit_test(test_entries_of_an_application_kind),
        cmocka_unit_test(test_kind_sharing_material_names),
        cmocka_unit_test(test_type_keywords_as_names),
        cmocka_unit_test(test_kind_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
