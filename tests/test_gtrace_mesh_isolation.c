/* test_gtrace_mesh_isolation.c - PLY, STL and glTF files read by assimp in the mesh reader process, gtrace-mesh
 * (geometry/mesh_isolated.c, mesh_reader/gtrace_mesh.c):
 * - the mesh read in the reader is the mesh read in this process (GENERIC_DECODE=inprocess), bit for bit in every
 *   array, for OBJ (read by gtrace itself either way), ASCII and binary PLY and STL, a glTF with a buffer file,
 *   normals, (u,v), node transforms and a DAG, and the same as a .glb;
 * - the files a glTF names are allowed by this process's rule (the caller's MeshFiles, --confine), asked by the
 *   reader before it opens them; a refusal is the caller's message;
 * - a reader that crashes, spins past its CPU time or grows past its address space is G_ERR_IO naming the file and
 *   how it ended, leaving no child process and nothing reserved against the memory budget;
 * - a mesh over the memory budget is refused with the budget's figures; GENERIC_DECODE takes two values only. */
#include "test_gtrace_common.h"

#include "geometry/mesh_format.h"

#include <errno.h>
#include <sys/stat.h>
#include <sys/wait.h>

/* A sanitizer build (as tests/test_util.h says it) sets no address space limit on the reader. */
#ifdef __SANITIZE_ADDRESS__
#define SANITIZED 1
#else
#define SANITIZED 0
#endif

static const float POS[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0.5f};
static const float NRM[9] = {0, 0, 1, 0.6f, 0, 0.8f, 0, -0.6f, 0.8f};
static const float UV[6] = {0, 0, 2, 0, 0.25f, 1};

/* The glTF's JSON: POSITION, NORMAL and TEXCOORD_0 of one triangle in buffer 0 (`buffer`: its members), placed
 * by three nodes: translated, rotated and scaled, and a node naming the scaled one twice (a DAG). */
static void gltf_json(char *out, size_t size, const char *buffer)
{
    snprintf(out, size,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,3]}],\n"
             "\"nodes\":[{\"children\":[1,2]},{\"mesh\":0,\"translation\":[1,2,3]},\n"
             "{\"mesh\":0,\"rotation\":[0,0,0.6,0.8],\"scale\":[2,2,-2]},{\"children\":[2,2]}],\n"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2}}]}],\n"
             "\"buffers\":[{%s}],\n\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},"
             "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":72,\"byteLength\":24}],\n"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],"
             "\"max\":[1,1,0.5]},{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
             "{\"bufferView\":2,\"componentType\":5126,\"count\":3,\"type\":\"VEC2\"}]}\n",
             buffer);
}

static size_t buffer_bytes(unsigned char *out)
{
    memcpy(out, POS, 36);
    memcpy(out + 36, NRM, 36);
    memcpy(out + 72, UV, 24);
    return 96;
}

static size_t glb(unsigned char *out, const char *json, const unsigned char *bin, uint32_t bin_len)
{
    size_t jl = strlen(json), pad = (4 - jl % 4) % 4, o = 12;
    uint32_t jlen = (uint32_t)(jl + pad), version = 2;
    memcpy(out + o, &jlen, 4);
    memcpy(out + o + 4, "JSON", 4);
    memcpy(out + o + 8, json, jl);
    memset(out + o + 8 + jl, ' ', pad);
    o += 8 + jlen;
    memcpy(out + o, &bin_len, 4);
    memcpy(out + o + 4, "BIN\0", 4);
    memcpy(out + o + 8, bin, bin_len);
    o += 8 + bin_len;
    uint32_t total = (uint32_t)o;
    memcpy(out, "glTF", 4);
    memcpy(out + 4, &version, 4);
    memcpy(out + 8, &total, 4);
    return o;
}

static Object *load(const char *path, const MeshFiles *files, GError *err)
{
    Object *o = object_new(SHAPE_MESH, NULL);
    gerror_clear(err);
    if (object_mesh_load_from(o, path, files, err) != G_OK) {
        assert_null(o->mesh);
        object_free(o);
        return NULL;
    }
    return o;
}

static Object *load_mode(const char *path, const char *mode)
{
    if (mode)
        setenv("GENERIC_DECODE", mode, 1);
    else
        unsetenv("GENERIC_DECODE");
    GError err;
    Object *o = load(path, NULL, &err);
    unsetenv("GENERIC_DECODE");
    if (!o)
        fail_msg("%s (%s): %s", path, mode ? mode : "isolated", err.message);
    return o;
}

/* No child process is left: every reader is reaped. */
static void assert_no_child(void)
{
    int status;
    errno = 0;
    assert_int_equal(waitpid(-1, &status, WNOHANG), -1);
    assert_int_equal(errno, ECHILD);
}

/* path is read alike in this process and in the reader: the same counts and the same bits in every array. */
static void assert_same_both_ways(const char *path, int ntris)
{
    Object *a = load_mode(path, "inprocess"), *b = load_mode(path, NULL);
    const Mesh *x = a->mesh, *y = b->mesh;
    assert_int_equal(x->ntris, ntris);
    assert_int_equal(x->ntris, y->ntris);
    assert_int_equal(x->nverts, y->nverts);
    assert_int_equal(x->nuvs, y->nuvs);
    assert_int_equal(x->nnormals, y->nnormals);
    assert_int_equal(x->budget, y->budget);
    const size_t nt = (size_t)x->ntris;
    assert_memory_equal(x->pos, y->pos, (size_t)x->nverts * 3 * sizeof(double));
    if (x->nnormals)
        assert_memory_equal(x->normal, y->normal, (size_t)x->nnormals * 3 * sizeof(double));
    if (x->nuvs)
        assert_memory_equal(x->uv, y->uv, (size_t)x->nuvs * 2 * sizeof(double));
    assert_memory_equal(x->tri, y->tri, nt * 3 * sizeof(unsigned));
    assert_memory_equal(x->tri_uv, y->tri_uv, nt * 3 * sizeof(int));
    assert_memory_equal(x->tri_normal, y->tri_normal, nt * 3 * sizeof(int));
    assert_memory_equal(x->tri_surface, y->tri_surface, nt * sizeof(int));
    object_free(a);
    object_free(b);
    assert_no_child();
}

static void test_same_mesh_both_ways(void **state)
{
    (void)state;
    size_t used = gmem_budget_used();
    assert_same_both_ways(write_text("iso.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0.5\nv 1 1 0\nvn 0 0 1\nvt 0.5 0.5\n"
                                                "f 1/1/1 2/1/1 3/1/1\nusemtl b\nf 2/1/1 4/1/1 3/1/1\n"), 2);
    assert_same_both_ways(write_text("iso.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                                "property float y\nproperty float z\nproperty float nx\n"
                                                "property float ny\nproperty float nz\nproperty float s\n"
                                                "property float t\nelement face 2\n"
                                                "property list uchar int vertex_indices\nend_header\n"
                                                "-1 -1 0 0 0 1 0 0\n1 -1 0 0.6 0 0.8 2 0\n1 1 0.5 0 -0.6 0.8 2 1\n"
                                                "-1 1 0 -0.28 0 0.96 0.25 1\n3 0 1 2\n4 0 2 3 1\n"), 3);
    /* binary PLY: 3 float vertices and one face */
    unsigned char bin[1024];
    const char *head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    size_t n = strlen(head);
    memcpy(bin, head, n);
    memcpy(bin + n, POS, sizeof POS), n += sizeof POS;
    bin[n++] = 3;
    for (int32_t k = 0; k < 3; k++)
        memcpy(bin + n, &k, 4), n += 4;
    assert_same_both_ways(write_file("isob.ply", bin, n), 1);
    assert_same_both_ways(write_text("iso.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                "vertex 1 0 0\nvertex 0 1 0.5\nendloop\nendfacet\nendsolid t\n"), 1);
    /* binary STL: 80-byte header, a count, one 50-byte triangle */
    memset(bin, 0, 134);
    uint32_t one = 1;
    memcpy(bin + 80, &one, 4);
    memcpy(bin + 84 + 12, POS, sizeof POS);
    assert_same_both_ways(write_file("isob.stl", bin, 134), 1);
    /* glTF with its buffer in a file beside it; the same as a .glb with a BIN chunk */
    unsigned char data[96];
    write_file("iso.bin", data, buffer_bytes(data));
    char json[4096], buffer[256];
    snprintf(buffer, sizeof buffer, "\"byteLength\":96,\"uri\":\"gtrace_test_%d_iso.bin\"", (int)getpid());
    gltf_json(json, sizeof json, buffer);
    assert_same_both_ways(write_text("iso.gltf", json), 4);
    gltf_json(json, sizeof json, "\"byteLength\":96");
    assert_same_both_ways(write_file("iso.glb", bin, glb(bin, json, data, 96)), 4);
    unlink(temp_path("iso.bin"));
    assert_int_equal(gmem_budget_used(), used);
}

typedef struct Asked {
    int count;
    char last[512];
} Asked;

static int refuse_outside(void *ctx, const char *path, GError *err)
{
    Asked *a = ctx;
    a->count++;
    snprintf(a->last, sizeof a->last, "%s", path);
    return strstr(path, "outside") ? gerror_set(err, G_ERR_INVALID, "\"%s\" is outside the confined folder", path)
                                   : G_OK;
}

/* The reader opens the files a glTF names only when this process's rule allows them. */
static void test_rule_stays_here(void **state)
{
    (void)state;
    unsetenv("GENERIC_DECODE");
    unsigned char data[96];
    write_file("outside.bin", data, buffer_bytes(data));
    write_file("inside.bin", data, buffer_bytes(data));
    char json[4096], buffer[256];
    Asked asked = {0};
    MeshFiles rule = {refuse_outside, &asked};
    GError err;
    snprintf(buffer, sizeof buffer, "\"byteLength\":96,\"uri\":\"gtrace_test_%d_inside.bin\"", (int)getpid());
    gltf_json(json, sizeof json, buffer);
    Object *o = load(write_text("in.gltf", json), &rule, &err);
    if (!o)
        fail_msg("%s", err.message);
    assert_int_equal(o->mesh->ntris, 4);
    object_free(o);
    assert_true(asked.count >= 1);
    assert_non_null(strstr(asked.last, "inside.bin"));
    size_t used = gmem_budget_used();
    asked.count = 0;
    snprintf(buffer, sizeof buffer, "\"byteLength\":96,\"uri\":\"gtrace_test_%d_outside.bin\"", (int)getpid());
    gltf_json(json, sizeof json, buffer);
    char *path = write_text("out.gltf", json);
    assert_null(load(path, &rule, &err));
    assert_int_equal(asked.count, 1);
    assert_non_null(strstr(err.message, "is outside the confined folder"));
    assert_non_null(strstr(err.message, path));
    assert_int_equal(gmem_budget_used(), used);
    assert_no_child();
    unlink(temp_path("outside.bin"));
    unlink(temp_path("inside.bin"));
}

/* A reader that fails in the way named by fault-NAME.ply: G_ERR_IO naming the file and containing expect. */
static void assert_fault(const char *name, const char *expect)
{
    static const char ply[] = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    char file[64];
    snprintf(file, sizeof file, "x/fault-%s.ply", name);
    char *path = temp_path("x");
    mkdir(path, 0700);
    path = write_text(file, ply);
    size_t used = gmem_budget_used();
    GError err;
    assert_null(load(path, NULL, &err));
    assert_int_equal(err.code, G_ERR_IO);
    if (!strstr(err.message, path) || !strstr(err.message, expect))
        fail_msg("%s: %s (expected \"%s\")", name, err.message, expect);
    assert_int_equal(gmem_budget_used(), used);
    assert_no_child();
    unlink(path);
    rmdir(temp_path("x"));
}

static void test_reader_faults(void **state)
{
    (void)state;
    unsetenv("GENERIC_DECODE");
    setenv("GENERIC_DECODE_FAULT", "by-name", 1);
    /* a sanitizer build's reader reports the fault itself and exits 1 */
    assert_fault("crash", SANITIZED ? "ended (exit status 1) without an answer" : "crashed (Segmentation fault)");
    assert_fault("spin", "CPU time");
    if (!SANITIZED) { /* a sanitizer build sets no address space limit: the reader would take the machine's memory */
        gmem_budget_set_limit(gmem_budget_used() + (16u << 20)); /* its limit: 1 GiB and twice the budget's room */
        assert_fault("grow", "crashed (Aborted) within its limits of 1056 MiB");
        gmem_budget_set_limit(0);
    }
    unsetenv("GENERIC_DECODE_FAULT");
    /* the next file reads as before */
    Object *o = load_mode(write_text("after.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                  "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n"),
                          NULL);
    assert_int_equal(o->mesh->ntris, 1);
    object_free(o);
}

static void test_budget_and_switch(void **state)
{
    (void)state;
    unsetenv("GENERIC_DECODE");
    char *path = write_text("budget.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                          "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    size_t used = gmem_budget_used();
    gmem_budget_set_limit(used + 64); /* less than any mesh */
    GError err;
    assert_null(load(path, NULL, &err));
    gmem_budget_set_limit(0);
    assert_int_equal(err.code, G_ERR_NOMEM);
    assert_non_null(strstr(err.message, path));
    assert_non_null(strstr(err.message, "over the memory budget"));
    assert_int_equal(gmem_budget_used(), used);
    assert_no_child();
    setenv("GENERIC_DECODE", "sandbox", 1);
    assert_null(load(path, NULL, &err));
    unsetenv("GENERIC_DECODE");
    assert_int_equal(err.code, G_ERR_INVALID);
    assert_non_null(strstr(err.message, "GENERIC_DECODE is 'sandbox'"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_mesh_both_ways),
        cmocka_unit_test(test_rule_stays_here),
        cmocka_unit_test(test_reader_faults),
        cmocka_unit_test(test_budget_and_switch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
