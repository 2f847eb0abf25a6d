/* reader_fixture.h - shared by the text-reader tests (include after <cmocka.h> and generic/reader.h): loading
 * a text that must load or must fail, with the exact message it must give; a point of the xy plane to evaluate what
 * was loaded at; the kinds of a renderer's scene entries. */
#ifndef GENERIC_TEST_READER_FIXTURE_H
#define GENERIC_TEST_READER_FIXTURE_H

#include <string.h>

/* Loads text as "t.mat"; the load must succeed (the message is printed when it does not). */
static inline GLibrary *load_ok(const char *text)
{
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return lib;
}

/* A point of the xy plane (normal +z, tangents x and y) at (u, v) = (x, y), without a footprint (no filtering),
 * on the scratch arena s. */
static inline GSurfPoint *plane_point(const GColorModel *m, GScratch *s, double u, double v)
{
    GError err;
    GSurfPoint *sp = gsurfpoint_new(m, s, gvec3(u, v, 0), gvec3(0, 0, 1), gvec3(1, 0, 0), gvec3(0, 1, 0), u, v, 0,
                                    &err);
    assert_non_null(sp);
    return sp;
}

/* Loads text as "t.mat"; the load must fail, leave no library and give exactly `message` (printed beside
 * what came when it differs). */
static inline void load_fails(const char *text, const char *message)
{
    GLibrary *lib = (GLibrary *)0x1;
    GError err;
    assert_true(greader_load_string(text, "t.mat", NULL, &lib, &err) < 0);
    assert_null(lib);
    if (strcmp(err.message, message) != 0)
        print_error("got:  %s\nwant: %s\n", err.message, message);
    assert_string_equal(err.message, message);
}

/* The kinds of a renderer's scene entries, registered as gtrace registers them (object, light, camera, in that
 * order, without types): the tests read such entries with test types, and the reader's messages list them. */
typedef struct SceneKinds {
    GKind object, light, camera;
} SceneKinds;

static inline SceneKinds register_scene_kinds(void)
{
    static const GKindInfo kinds[3] = {{"object", NULL, 0}, {"light", NULL, 0}, {"camera", NULL, 0}};
    GKind k[3];
    for (int i = 0; i < 3; i++)
        assert_int_equal(gregistry_add_kind(&kinds[i], &k[i], NULL), G_OK);
    return (SceneKinds){k[0], k[1], k[2]};
}

#endif
