/* test_reader_skip.c - GReaderOptions.skip_kinds: a program without gtrace's object, light and camera types reads
 * a scene's materials past those entries (named or not, nested braces, between other entries); a skipped entry
 * that does not close is an error at its keyword; kinds not asked for still fail; generated hostile token
 * streams never crash, hang or leak. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/reader.h"
#include "reader_fixture.h"

static SceneKinds kinds;   /* registered by main, without types */
static unsigned scene_kinds; /* their bits */

static int load(const char *text, unsigned skip, GLibrary **lib, GError *err)
{
    GReaderOptions opt = {.skip_kinds = skip};
    return greader_load_string(text, "scene", &opt, lib, err);
}

static void test_scene_entries_skipped(void **state)
{
    (void)state;
    const char *scene =
        "material grey lambert { reflectance rgb 0.5 0.5 0.5 }\n"
        "camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 40 height 30 }\n"
        "object floor plane { point <0, 0, 0> normal <0, 1, 0> material grey }\n"
        "object sphere { center <0, 0.5, 0> radius 0.5 material dielectric { index 1.5 } }\n"
        "light point { position <2, 4, 3> intensity rgb 20 20 20 }\n"
        "object group { object box { lo <0,0,0> hi <1,1,1> material node { checker { } } } }\n"
        "material red lambert { reflectance rgb 0.8 0.1 0.1 }\n";
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(load(scene, scene_kinds, &lib, &err), G_OK);
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 2);
    assert_non_null(glibrary_material(lib, "grey"));
    assert_non_null(glibrary_material(lib, "red"));
    assert_int_equal(glibrary_count(lib, kinds.object), 0);
    glibrary_destroy(lib);
    /* without the option the first camera fails, at its type */
    assert_int_not_equal(load(scene, 0, &lib, &err), G_OK);
    assert_null(lib);
    assert_non_null(strstr(err.message, "scene:2:8: unknown camera type 'pinhole'"));
    /* only the kinds asked for: the light still fails */
    assert_int_not_equal(load(scene, 1u << kinds.object | 1u << kinds.camera, &lib, &err), G_OK);
    assert_non_null(strstr(err.message, "scene:5:7: unknown light type 'point'"));
}

static void test_broken_skipped_entries(void **state)
{
    (void)state;
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"material m lambert { }\nobject sphere { center <0,0,0>\n", "scene:2:1: the object entry has no closing '}'"},
        {"object a b c { { { } }\n", "scene:1:1: the object entry has no closing '}'"},
        {"light point 3 { }\n", "scene:1:13: expected '{' of the light entry (skipped), found"},
        {"camera\n", "scene:2:1: expected '{' of the camera entry (skipped), found"},
        {"object sphere } {\n", "scene:1:15: expected '{' of the object entry (skipped), found"},
        {"object { } }\n", "scene:1:12: expected a statement"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        GLibrary *lib = NULL;
        GError err;
        assert_int_not_equal(load(cases[i].text, scene_kinds, &lib, &err), G_OK);
        assert_null(lib);
        if (!strstr(err.message, cases[i].message))
            fail_msg("case %zu: expected '%s', got '%s'", i, cases[i].message, err.message);
    }
}

/* Random streams of braces, names, numbers and keywords (skipped and not): the load succeeds or fails with a
 * message, and the sanitizer build sees no leak or overflow; a million-deep nesting is no recursion. */
static void test_generated_hostile_streams(void **state)
{
    (void)state;
    static const char *const pieces[] = {"object ", "light ", "camera ", "{ ", "} ", "} ", "{ ", "x ", "1.5 ",
                                         "<1,2,3> ", "\"s\" ", "material m lambert { } ", "# c\n", "\n", "rgb 1 1 1 "};
    const size_t np = sizeof pieces / sizeof pieces[0];
    char text[4096];
    uint64_t state_ = 12345;
    int ok = 0, failed = 0;
    for (int c = 0; c < 3000; c++) {
        size_t len = 0;
        int n = (int)(state_ % 40) + 1;
        for (int k = 0; k < n; k++) {
            state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
            const char *p = pieces[(state_ >> 33) % np];
            size_t l = strlen(p);
            if (len + l + 1 >= sizeof text)
                break;
            memcpy(text + len, p, l);
            len += l;
        }
        text[len] = '\0';
        GLibrary *lib = NULL;
        GError err;
        gerror_clear(&err);
        if (load(text, scene_kinds, &lib, &err) == G_OK) {
            ok++;
            glibrary_destroy(lib);
        } else {
            failed++;
            assert_null(lib);
            assert_true(err.message[0] != '\0');
        }
    }
    print_message("3000 generated streams: %d loaded, %d refused with a message\n", ok, failed);
    assert_true(ok > 0 && failed > 0);
    enum { DEPTH = 1000000 };
    char *deep = gmem_alloc(2 * DEPTH + 16);
    assert_non_null(deep);
    memcpy(deep, "object ", 7);
    memset(deep + 7, '{', DEPTH);
    memset(deep + 7 + DEPTH, '}', DEPTH);
    deep[7 + 2 * DEPTH] = '\0';
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(load(deep, scene_kinds, &lib, &err), G_OK);
    glibrary_destroy(lib);
    deep[7 + 2 * DEPTH - 1] = ' '; /* one brace short */
    assert_int_not_equal(load(deep, scene_kinds, &lib, &err), G_OK);
    assert_non_null(strstr(err.message, "scene:1:1: the object entry has no closing '}'"));
    gmem_free(deep);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    kinds = register_scene_kinds();
    scene_kinds = 1u << kinds.object | 1u << kinds.light | 1u << kinds.camera;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_entries_skipped),
        cmocka_unit_test(test_broken_skipped_entries),
        cmocka_unit_test(test_generated_hostile_streams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
