/* test_gtrace_mesh_stl.c - STL meshes (mesh_stl.c's check, then assimp) and the choice of a mesh file's reader
 * (mesh_format.c): an ASCII and a binary STL load to the triangles written, whatever the file's name; truncated,
 * lying and malformed STL files, 3DS files and other formats gtrace does not read fail with a clear message (the
 * scene's FILE:LINE:COL at the entry's `file`), never a crash or a hang. */
#include "test_gtrace_common.h"

#include <generic/builtins.h>

#include <unistd.h>

/* Two triangles that are not coplanar, and their unit normals. */
static const float P[2][3][3] = {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0.5f}}, {{-1, -1, 0}, {1, 1, 0.5f}, {-1, 1, 0}}};

static void normal_of(int t, float n[3])
{
    double e1[3], e2[3], c[3];
    for (int k = 0; k < 3; k++)
        e1[k] = P[t][1][k] - P[t][0][k], e2[k] = P[t][2][k] - P[t][0][k];
    c[0] = e1[1] * e2[2] - e1[2] * e2[1], c[1] = e1[2] * e2[0] - e1[0] * e2[2], c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double len = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (int k = 0; k < 3; k++)
        n[k] = (float)(c[k] / len);
}

/* The two triangles as ASCII STL (as solid NAME, twice over when `solids` is 2: the second solid repeats them). */
static void stl_text(char *out, size_t size, int solids)
{
    int n = 0;
    for (int s = 0; s < solids; s++) {
        n += snprintf(out + n, size - (size_t)n, "solid part%d exported by a test\n", s);
        for (int t = 0; t < 2; t++) {
            float nn[3];
            normal_of(t, nn);
            n += snprintf(out + n, size - (size_t)n, "  facet normal %.9g %.9g %.9g\n    outer loop\n", nn[0], nn[1],
                          nn[2]);
            for (int v = 0; v < 3; v++)
                n += snprintf(out + n, size - (size_t)n, "      vertex %.9g %.9g %.9g\n", P[t][v][0], P[t][v][1],
                              P[t][v][2]);
            n += snprintf(out + n, size - (size_t)n, "    endloop\n  endfacet\n");
        }
        n += snprintf(out + n, size - (size_t)n, "endsolid part%d\n", s);
    }
    assert_true((size_t)n < size);
}

/* The two triangles as binary STL (an 80-byte header, the count, 50 bytes a triangle); its length. */
static size_t stl_binary(unsigned char *out, const char *header)
{
    memset(out, 0, 84);
    memcpy(out, header, strlen(header));
    uint32_t count = 2;
    memcpy(out + 80, &count, 4); /* this test runs on little-endian machines */
    size_t o = 84;
    for (int t = 0; t < 2; t++) {
        float nn[3];
        normal_of(t, nn);
        memcpy(out + o, nn, 12), o += 12;
        memcpy(out + o, P[t], 36), o += 36;
        out[o++] = 0, out[o++] = 0;
    }
    return o;
}

static Object *load_ok(const char *path)
{
    Object *o = object_new(SHAPE_MESH, NULL);
    GError err;
    gerror_clear(&err);
    if (object_mesh_load(o, path, &err) != G_OK)
        fail_msg("%s", err.message);
    return o;
}

/* path must fail with a message naming it, containing expect (unless NULL), the parameter "file" named. */
static void assert_refused(const char *path, const char *expect)
{
    Object *o = object_new(SHAPE_MESH, NULL);
    GError err;
    gerror_clear(&err);
    if (object_mesh_load(o, path, &err) == G_OK)
        fail_msg("%s loaded", path);
    if (!strstr(err.message, path) || (expect && !strstr(err.message, expect)))
        fail_msg("message for %s: %s", path, err.message);
    assert_string_equal(err.param, "file");
    assert_null(o->mesh);
    object_free(o);
}

/* Every corner of the mesh's triangles is the one written (copies times over), its normal the facet's. */
static void assert_triangles(const Mesh *m, int copies)
{
    assert_int_equal(m->ntris, 2 * copies);
    for (int t = 0; t < m->ntris; t++) {
        float nn[3];
        normal_of(t % 2, nn);
        assert_int_equal(m->tri_surface[t], 0);
        for (int j = 0; j < 3; j++) {
            int v = (int)m->tri[3 * t + j], n = m->tri_normal[3 * t + j];
            assert_true(n >= 0);
            assert_int_equal(m->tri_uv[3 * t + j], -1); /* STL has no (u,v) */
            for (int k = 0; k < 3; k++) {
                assert_near(m->pos[3 * v + k], P[t % 2][j][k], 0.0);
                assert_near(m->normal[3 * n + k], nn[k], 1e-7);
            }
        }
    }
}

static void test_stl_loads(void **state)
{
    (void)state;
    char text[4096];
    stl_text(text, sizeof text, 1);
    Object *o = load_ok(write_text("a.stl", text));
    assert_triangles(o->mesh, 1);
    object_free(o);
    stl_text(text, sizeof text, 2); /* two solids: two assimp meshes, one surface */
    o = load_ok(write_text("two.stl", text));
    assert_triangles(o->mesh, 2);
    object_free(o);
    unsigned char bin[256];
    const char *headers[] = {"binary STL", "solid but binary all the same", "COLOR=\377\0\0\377 (Materialise)"};
    for (size_t h = 0; h < sizeof headers / sizeof *headers; h++) {
        size_t n = stl_binary(bin, headers[h]);
        assert_int_equal(n, 84 + 2 * 50);
        o = load_ok(write_file("b.stl", bin, n));
        assert_triangles(o->mesh, 1);
        object_free(o);
    }
    /* the content decides: a binary STL named .obj, an ASCII STL without an extension, a PLY named .stl */
    size_t n = stl_binary(bin, "binary STL");
    o = load_ok(write_file("b.obj", bin, n));
    assert_triangles(o->mesh, 1);
    object_free(o);
    stl_text(text, sizeof text, 1);
    o = load_ok(write_text("noext", text));
    assert_triangles(o->mesh, 1);
    object_free(o);
    o = load_ok(write_text("ply.stl", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                      "end_header\n-1 -1 0\n1 -1 0\n1 1 0.5\n3 0 1 2\n"));
    assert_int_equal(o->mesh->ntris, 1);
    object_free(o);
    const char *made[] = {"a.stl", "two.stl", "b.stl", "b.obj", "noext", "ply.stl"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

/* text with the first `from` replaced by `to` */
static void replace(char *out, size_t size, const char *text, const char *from, const char *to)
{
    const char *at = strstr(text, from);
    assert_non_null(at);
    snprintf(out, size, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
}

static void test_stl_hostile(void **state)
{
    (void)state;
    char text[4096], bad[4096];
    stl_text(text, sizeof text, 1);
    int cases = 0;
    /* every truncation of the ASCII file before its last facet ends, and of the binary file */
    size_t cut_at = (size_t)(strstr(text, "endsolid") - text);
    for (size_t n = 0; n < cut_at; n += 5, cases++)
        assert_refused(write_file("cut.stl", text, n), NULL);
    unsigned char bin[256];
    size_t blen = stl_binary(bin, "binary STL");
    for (size_t n = 0; n < blen; n++, cases++)
        assert_refused(write_file("cutb.stl", bin, n), NULL);
    /* lying counts: more triangles than the file holds; 0; a count whose 32-bit size wraps to the file's size */
    uint32_t counts[] = {3, 1000000000u, 0, 85899346u};
    for (size_t i = 0; i < sizeof counts / sizeof *counts; i++, cases++) {
        memcpy(bin + 80, &counts[i], 4);
        assert_refused(write_file("lie.stl", bin, blen), "header counts");
    }
    unsigned char wrap[184];
    memcpy(wrap, bin, sizeof wrap);
    uint32_t wrapped = 2147483650u; /* 84 + 50 * (2^31 + 2) = 2^32 * 25 + 184 */
    assert_int_equal((uint32_t)(84u + 50u * wrapped), 184);
    memcpy(wrap + 80, &wrapped, 4);
    assert_refused(write_file("wrap.stl", wrap, sizeof wrap),
                   "header counts 2147483650 triangles (107374182584 bytes)");
    cases++;
    /* malformed ASCII: each a clear message at FILE:LINE:COL */
    const struct {
        const char *from, *to, *expect;
    } edits[] = {
        {"vertex -1 -1 0\n", "vertex -1 -1 0\n      vertex 0 0 0\n", ":7:7: a facet with more than three vertices"},
        {"facet normal", "facet", ":2:9: expected \"normal\", not \"0\""},
        {"vertex -1 -1 0", "vertex -1 -1", ":4:19: a vertex needs three numbers on its line"},
        {"vertex -1 -1 0", "vertex -1 -1\n0", ":4:19: a vertex needs three numbers"},
        {"vertex -1 -1 0", "vertex -1 -1 nan",
         "a vertex needs finite numbers (digits, a point, an exponent), not \"nan\""},
        {"vertex -1 -1 0", "vertex -1 -1 inf", "not \"inf\""},
        {"vertex -1 -1 0", "vertex -1 -1 1e999", "not \"1e999\""},
        {"vertex -1 -1 0", "vertex -1 -1 0x10", "not \"0x10\""},
        {"vertex -1 -1 0", "vertex -1 -1 1,5", "not \"1,5\""},
        {"vertex -1 -1 0", "vertex -1 -1 1e", "not \"1e\""},
        {"outer loop", "outer", ":4:7: expected \"loop\", not \"vertex\""},
        {"endloop", "endloop endloop", "expected \"endfacet\", not \"endloop\""},
        {"solid part0 exported by a test", "solid part0 facet", ":1:13: \"facet\" on the line of \"solid\""},
        {"solid part0 exported by a test", "solidpart0", ":1:1: expected \"solid\""},
        {"endsolid part0\n", "", "the file ends before \"endsolid\""},
        {"endsolid part0\n", "endsolid part0\nsolid more\nendsolid more\n", ":18:1: a solid without facets"},
        {"endsolid part0\n", "endsolid part0\ntrailing words\n", ":17:1: expected \"solid\""},
        {"part0", "part0\001", "a control byte (0x01)"},
        {"vertex -1 -1 0", "vertex 1e39 -1 0", "a vertex position is not a finite number"}, /* beyond a float */
    };
    for (size_t i = 0; i < sizeof edits / sizeof *edits; i++, cases++) {
        replace(bad, sizeof bad, text, edits[i].from, edits[i].to);
        assert_refused(write_text("bad.stl", bad), edits[i].expect);
    }
    char name[1100];
    memset(name, 'n', 1001);
    name[1001] = '\0';
    snprintf(bad, sizeof bad, "solid %s\nendsolid\n", name);
    assert_refused(write_text("name.stl", bad), "a solid's name longer than 1000 bytes");
    /* garbage with an STL's start (seeded bytes) */
    unsigned seed = 4242;
    for (int trial = 0; trial < 40; trial++, cases++) {
        unsigned char junk[600];
        for (size_t i = 0; i < sizeof junk; i++)
            junk[i] = (unsigned char)((seed = seed * 1103515245u + 12345u) >> 16);
        if (trial % 2)
            memcpy(junk, "solid junk\n  facet normal 0 0 1\n", 33);
        assert_refused(write_file("junk.stl", junk, trial % 3 ? sizeof junk : 84 + 50 * (size_t)(trial % 5)), NULL);
    }
    print_message("%d hostile STL files refused\n", cases + 1);
    const char *made[] = {"cut.stl", "cutb.stl", "lie.stl", "wrap.stl", "bad.stl", "name.stl", "junk.stl"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

/* 3DS, the other formats assimp knows and binary data are refused by name, listing the formats gtrace reads; in a
 * scene, at the entry's `file` parameter. */
static void test_unsupported_formats(void **state)
{
    (void)state;
    unsigned char tds[64] = {0x4d, 0x4d, 64, 0, 0, 0, 0x02, 0x00, 10, 0, 0, 0, 3, 0, 0, 0};
    const char *listed = "not a mesh format gtrace reads (it reads Wavefront OBJ (.obj), PLY (.ply), STL (.stl) and "
                         "glTF 2.0 (.gltf, .glb))";
    assert_refused(write_file("m.3ds", tds, sizeof tds), "a 3DS (3D Studio) file, not a mesh format");
    assert_refused(write_file("m3.obj", tds, sizeof tds), listed);
    assert_refused(write_text("x.3DS", "not even a 3DS file\n"), "a 3DS (3D Studio) file");
    assert_refused(write_text("m.fbx", "; FBX 7.4.0 project file\n"), "a .fbx file, not a mesh format");
    assert_refused(write_text("m.dae", "<?xml version=\"1.0\"?>\n"), "a .dae file");
    static const unsigned char junk[] = {0x7f, 'E', 'L', 'F', 2, 1, 1, 0, 0, 0, '\n', 'v', ' ', '0'};
    assert_refused(write_file("elf.obj", junk, sizeof junk), "binary data (a NUL byte in its first line)");
    /* an OBJ with a NUL byte further on keeps the OBJ reader's message */
    static const char nul[] = "v 0 0 0\nv 1 0 0\nv 0 1\0 0\nf 1 2 3\n";
    assert_refused(write_file("nul.obj", nul, sizeof nul - 1), ":3:6: a NUL byte");

    MeshFormat f;
    char what[64];
    const unsigned char ply[] = "ply\nformat ascii 1.0\n", solid[] = "  solid x\n", gl[] = "glTF\2\0\0\0";
    f = mesh_format_detect(ply, sizeof ply - 1, 100, "m.obj", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_PLY);
    f = mesh_format_detect(solid, sizeof solid - 1, 100, "m.obj", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_STL);
    f = mesh_format_detect(gl, sizeof gl - 1, 100, "m.bin", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_GLTF);
    f = mesh_format_detect((const unsigned char *)"v 0 0 0\n", 8, 8, "m.txt", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_OBJ);
    f = mesh_format_detect((const unsigned char *)"v 0 0 0\n", 8, 8, "m.GLB", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_GLTF);
    f = mesh_format_detect((const unsigned char *)"solidity 1\n", 11, 11, "m.obj", what, sizeof what);
    assert_int_equal(f, MESH_FORMAT_OBJ);

    /* in a scene: the message is placed at the entry's file parameter (line 4, column 5) */
    char *scene = temp_path("s.scene");
    FILE *sf = fopen(scene, "w");
    assert_non_null(sf);
    fprintf(sf, "material m lambert { reflectance rgb 0.5 0.5 0.5 }\ncamera pinhole { from <0,0,5> at <0,0,0> }\n"
                "object mesh {\n    file \"%s\"\n    material m }\n", temp_path("m.3ds"));
    fclose(sf);
    Scene *s = NULL;
    GError err;
    gerror_clear(&err);
    assert_int_not_equal(scene_load(scene, "rgb", &s, &err), G_OK);
    assert_null(s);
    char expect[512];
    snprintf(expect, sizeof expect, "%s:4:5: %s: a 3DS (3D Studio) file", scene, temp_path("m.3ds"));
    if (strncmp(err.message, expect, strlen(expect)) != 0)
        fail_msg("scene message: %s (expected it to start with %s)", err.message, expect);
    const char *made[] = {"m.3ds", "m3.obj", "x.3DS", "m.fbx", "m.dae", "elf.obj", "nul.obj", "s.scene"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_stl_loads), cmocka_unit_test(test_stl_hostile),
                                       cmocka_unit_test(test_unsupported_formats)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
