/* test_gtrace_mesh_gltf.c - glTF and .glb files checked before assimp reads them (mesh_gltf.c, mesh_json.c) and the
 * files they name opened by the library's rules (mesh_assimp_io.c): a triangle from a data: URI, a buffer file and a
 * .glb's BIN chunk; node DAGs expanded to the counted copies; PLY content under a glTF name read as PLY; and the
 * hostile classes refused with their bound named: JSON nested 200000 deep, nodes nested 300 deep, a DAG of 40
 * levels (2^40 placements), cycles, .glb chunk lengths that lie, accessors and views beyond their bytes, buffer files
 * that are FIFOs, devices, or outside --confine by a path or a symbolic link. */
#include "test_gtrace_common.h"

#include <generic/builtins.h>

#include <sys/stat.h>

/* The 9 floats (0,0,0, 1,0,0, 0,1,0) in base64. */
#define TRI_B64 "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"

static const float TRI[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};

/* A glTF of one triangle mesh whose buffer is `buffer` (a JSON object's members), with the nodes and the scene's
 * root list given. */
static char *gltf(char *out, size_t size, const char *nodes, const char *roots, const char *buffer) {
    snprintf(out, size,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":%s}],\"nodes\":%s,\n"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\n\"buffers\":[{%s}],\n"
             "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\n\"accessors\":[{\"bufferView\":0,"
             "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[1,1,0]}]}\n",
             roots, nodes, buffer);
    return out;
}

static const char *const DATA_BUFFER = "\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64," TRI_B64 "\"";

static Object *load(const char *path, const MeshFiles *files, GError *err) {
    Object *o = object_new(SHAPE_MESH, NULL);
    gerror_clear(err);
    if (object_mesh_load_from(o, path, files, err) != G_OK) {
        assert_null(o->mesh);
        object_free(o);
        return NULL;
    }
    return o;
}

static Object *load_ok(const char *path) {
    GError err;
    Object *o = load(path, NULL, &err);
    if (!o)
        fail_msg("%s", err.message);
    return o;
}

/* path must be refused with a message naming it and containing expect, within the memory budget. */
static void assert_refused(const char *path, const char *expect) {
    GError err;
    size_t used = gmem_budget_used();
    Object *o = load(path, NULL, &err);
    if (o)
        fail_msg("%s loaded", path);
    if (!strstr(err.message, path) || !strstr(err.message, expect))
        fail_msg("message for %s: %s (expected \"%s\")", path, err.message, expect);
    assert_int_equal(gmem_budget_used(), used); /* nothing left reserved */
}

/* Each of the mesh's triangles is the triangle TRI; there are n of them. */
static void assert_triangles(const Object *o, int n) {
    const Mesh *m = o->mesh;
    assert_int_equal(m->ntris, n);
    for (int t = 0; t < n; t++)
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                assert_true(m->pos[3 * m->tri[3 * t + k] + c] == TRI[3 * k + c]);
}

static size_t glb(unsigned char *out, const char *json, const void *bin, uint32_t bin_len, uint32_t claim_total,
                  uint32_t claim_json, uint32_t claim_bin) {
    size_t jl = strlen(json), pad = (4 - jl % 4) % 4, o = 12;
    uint32_t jlen = (uint32_t)(jl + pad);
    memcpy(out + o, claim_json ? &claim_json : &jlen, 4);
    memcpy(out + o + 4, "JSON", 4);
    memcpy(out + o + 8, json, jl);
    memset(out + o + 8 + jl, ' ', pad);
    o += 8 + jlen;
    if (bin) {
        memcpy(out + o, claim_bin ? &claim_bin : &bin_len, 4);
        memcpy(out + o + 4, "BIN\0", 4);
        memcpy(out + o + 8, bin, bin_len);
        o += 8 + bin_len;
    }
    uint32_t version = 2, total = claim_total ? claim_total : (uint32_t)o;
    memcpy(out, "glTF", 4);
    memcpy(out + 4, &version, 4);
    memcpy(out + 8, &total, 4);
    return o;
}

static void test_gltf_loads(void **state) {
    (void)state;
    char text[4096];
    Object *o = load_ok(write_text("tri.gltf", gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", DATA_BUFFER)));
    assert_triangles(o, 1);
    object_free(o);
    /* a buffer file beside the mesh */
    write_file("tri.bin", TRI, sizeof TRI);
    char buffer[512];
    snprintf(buffer, sizeof buffer, "\"byteLength\":36,\"uri\":\"gtrace_test_%d_tri.bin\"", (int)getpid());
    o = load_ok(write_text("ext.gltf", gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", buffer)));
    assert_triangles(o, 1);
    object_free(o);
    /* a .glb with its BIN chunk, under any name */
    unsigned char bin[4096];
    size_t n = glb(bin, gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", "\"byteLength\":36"), TRI, 36, 0, 0, 0);
    o = load_ok(write_file("tri.glb", bin, n));
    assert_triangles(o, 1);
    object_free(o);
    o = load_ok(write_file("tri_glb.obj", bin, n));
    assert_triangles(o, 1);
    object_free(o);
    /* a DAG: node 0 names node 1 twice, node 1 names node 2 twice: 4 placements of the mesh */
    o = load_ok(
        write_text("dag.gltf", gltf(text, sizeof text, "[{\"children\":[1,1]},{\"children\":[2,2]},{\"mesh\":0}]",
                                    "[0]", DATA_BUFFER)));
    assert_triangles(o, 4);
    /* the mesh's memory is charged to the budget while it lives */
    assert_true(o->mesh->budget >= mesh_budget_bytes(12, 4));
    size_t used = gmem_budget_used();
    object_free(o);
    assert_true(gmem_budget_used() < used);
    /* PLY content named .glb is read as PLY */
    static const char ply[] = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    o = load_ok(write_text("ply_named.glb", ply));
    assert_triangles(o, 1);
    object_free(o);
}

static void test_gltf_hostile(void **state) {
    (void)state;
    static char text[1 << 20];
    char nodes[16384];
    /* JSON nested 200000 deep in extras (assimp's JSON reader recurses) */
    size_t deep = 200000;
    gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", DATA_BUFFER);
    size_t len = strlen(text) - 2; /* before "}\n" */
    memcpy(text + len, ",\"extras\":", 10);
    len += 10;
    memset(text + len, '[', deep);
    memset(text + len + deep, ']', deep);
    memcpy(text + len + 2 * deep, "}\n", 3);
    assert_refused(write_text("deep.gltf", text), "JSON nested deeper than 64 levels");
    /* nodes nested 300 deep */
    size_t o = 0;
    o += (size_t)snprintf(nodes + o, sizeof nodes - o, "[");
    for (int i = 0; i < 299; i++)
        o += (size_t)snprintf(nodes + o, sizeof nodes - o, "{\"children\":[%d]},", i + 1);
    snprintf(nodes + o, sizeof nodes - o, "{\"mesh\":0}]");
    assert_refused(write_text("chain.gltf", gltf(text, sizeof text, nodes, "[0]", DATA_BUFFER)),
                   "nodes nested deeper than 256 levels");
    /* a DAG of 40 levels: 2^40 placements */
    o = 0;
    o += (size_t)snprintf(nodes + o, sizeof nodes - o, "[");
    for (int i = 0; i < 40; i++)
        o += (size_t)snprintf(nodes + o, sizeof nodes - o, "{\"children\":[%d,%d]},", i + 1, i + 1);
    snprintf(nodes + o, sizeof nodes - o, "{\"mesh\":0}]");
    assert_refused(write_text("dag40.gltf", gltf(text, sizeof text, nodes, "[0]", DATA_BUFFER)),
                   "more than 100000 placements");
    /* cycles, and a child index beyond the nodes (one digit over a bound of 0) */
    assert_refused(
        write_text("cycle.gltf",
                   gltf(text, sizeof text, "[{\"children\":[1]},{\"children\":[0],\"mesh\":0}]", "[0]", DATA_BUFFER)),
        "form a cycle");
    assert_refused(
        write_text("self.gltf", gltf(text, sizeof text, "[{\"children\":[0],\"mesh\":0}]", "[0]", DATA_BUFFER)),
        "form a cycle");
    assert_refused(
        write_text("child.gltf", gltf(text, sizeof text, "[{\"children\":[7],\"mesh\":0}]", "[0]", DATA_BUFFER)),
        "nodes[0].children: each must be one of the 1 nodes' index");
    /* buffers, views and accessors that claim more than there is */
    assert_refused(write_text("short.gltf",
                              gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]",
                                   "\"byteLength\":3600,\"uri\":\"data:application/octet-stream;base64," TRI_B64 "\"")),
                   "its data: URI holds at most 36 bytes");
    gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", DATA_BUFFER);
    char *count = strstr(text, "\"count\":3");
    count[8] = '4';
    assert_refused(write_text("acc.gltf", text), "accessors[0]: 4 elements of 12 bytes need 48 bytes");
    count[8] = '3';
    char *view = strstr(text, "\"byteLength\":36}");
    memcpy(view, "\"byteLength\":96}", 16);
    assert_refused(write_text("view.gltf", text), "bufferViews[0] ends at byte 96 of buffers[0], which has 36 bytes");
    /* .glb chunk lies */
    unsigned char bin[8192];
    const char *json = gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", "\"byteLength\":36");
    size_t n = glb(bin, json, TRI, 36, 0, 0x80000000u, 0);
    assert_refused(write_file("json_lie.glb", bin, n), "the .glb's JSON chunk claims 2147483648 bytes");
    n = glb(bin, json, TRI, 36, 0, 0, 0x80000000u);
    assert_refused(write_file("bin_lie.glb", bin, n), "the .glb's BIN chunk claims 2147483648 bytes");
    n = glb(bin, json, TRI, 36, 444, 0, 0);
    assert_refused(write_file("len_lie.glb", bin, n), "the .glb header claims 444 bytes");
    n = glb(bin, json, NULL, 0, 0, 0, 0);
    assert_refused(write_file("no_bin.glb", bin, n), "buffers[0] has no uri");
    /* PLY content named .gltf, truncated in its header (assimp's PLY reader spins on it) */
    assert_refused(
        write_text("ply_cut.gltf", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty flo"),
        "the header ends before end_header");
    /* neither JSON nor .glb under a glTF name */
    assert_refused(write_text("junk.gltf", "v 0 0 0\n"), "neither a .glb");
    assert_refused(write_text("trail.gltf", "{\"asset\":{\"version\":\"2.0\"}} x"), "text after the JSON value");
    assert_refused(write_text("v1.gltf", "{\"asset\":{\"version\":\"1.0\"}}"), "asset.version must be \"2.x\"");
}

static int refuse_outside(void *ctx, const char *path, GError *err) {
    (void)ctx;
    return strstr(path, "outside") ? gerror_set(err, G_ERR_INVALID, "\"%s\" is outside", path) : G_OK;
}

static void test_gltf_files(void **state) {
    (void)state;
    char text[4096], buffer[512], *fifo = temp_path("fifo.bin");
    unlink(fifo);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    snprintf(buffer, sizeof buffer, "\"byteLength\":36,\"uri\":\"gtrace_test_%d_fifo.bin\"", (int)getpid());
    assert_refused(write_text("fifo.gltf", gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", buffer)), "it is a FIFO");
    unlink(fifo);
    char *zero = temp_path("zero.bin");
    unlink(zero);
    assert_int_equal(symlink("/dev/zero", zero), 0);
    snprintf(buffer, sizeof buffer, "\"byteLength\":36,\"uri\":\"gtrace_test_%d_zero.bin\"", (int)getpid());
    assert_refused(write_text("zero.gltf", gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", buffer)),
                   "not a regular file");
    unlink(zero);
    /* the caller's rule (a scene's --confine) decides for every file the mesh names */
    write_file("outside.bin", TRI, sizeof TRI);
    snprintf(buffer, sizeof buffer, "\"byteLength\":36,\"uri\":\"gtrace_test_%d_outside.bin\"", (int)getpid());
    MeshFiles rule = {refuse_outside, NULL};
    GError err;
    char *path = write_text("out.gltf", gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", buffer));
    assert_null(load(path, &rule, &err));
    assert_non_null(strstr(err.message, "is outside"));
    Object *o = load(path, NULL, &err);
    assert_non_null(o);
    object_free(o);
    unlink(temp_path("outside.bin"));
    /* a scene under --confine: a buffer at ../ and a symbolic link out of the folder are refused at the entry */
    char dir[256], sub[300], scene[400], secret[300], file[400];
    snprintf(dir, sizeof dir, "/tmp/gtrace_test_%d_confine", (int)getpid());
    snprintf(sub, sizeof sub, "%s/in", dir);
    snprintf(secret, sizeof secret, "%s/secret.bin", dir);
    mkdir(dir, 0700);
    mkdir(sub, 0700);
    FILE *f = fopen(secret, "wb");
    assert_non_null(f);
    fwrite(TRI, sizeof TRI, 1, f);
    fclose(f);
    snprintf(file, sizeof file, "%s/link.bin", sub);
    unlink(file);
    assert_int_equal(symlink(secret, file), 0);
    const char *uris[] = {"../secret.bin", "link.bin"};
    for (int i = 0; i < 2; i++) {
        snprintf(buffer, sizeof buffer, "\"byteLength\":36,\"uri\":\"%s\"", uris[i]);
        snprintf(file, sizeof file, "%s/m.gltf", sub);
        f = fopen(file, "w");
        assert_non_null(f);
        fputs(gltf(text, sizeof text, "[{\"mesh\":0}]", "[0]", buffer), f);
        fclose(f);
        snprintf(scene, sizeof scene, "%s/s.scene", sub);
        f = fopen(scene, "w");
        assert_non_null(f);
        fputs("material m lambert { reflectance rgb 0.5 0.5 0.5 }\ncamera pinhole { from <0,0,3> at <0,0,0> }\n"
              "object mesh { file \"m.gltf\" material m }\n",
              f);
        fclose(f);
        GReaderOptions opt = {0};
        opt.confine_dir = sub;
        Scene *s = NULL;
        assert_int_not_equal(scene_load_opts(scene, NULL, NULL, &opt, &s, &err), G_OK);
        assert_null(s);
        if (!strstr(err.message, "s.scene:3:15:") || !strstr(err.message, "outside the directory the load is confined"))
            fail_msg("%s: %s", uris[i], err.message);
        opt.confine_dir = dir; /* confined to the folder above, both are inside */
        assert_int_equal(scene_load_opts(scene, NULL, NULL, &opt, &s, &err), G_OK);
        scene_destroy(s);
    }
    snprintf(file, sizeof file, "%s/link.bin", sub), unlink(file);
    snprintf(file, sizeof file, "%s/m.gltf", sub), unlink(file);
    unlink(scene);
    unlink(secret);
    rmdir(sub);
    rmdir(dir);
    const char *made[] = {"tri.gltf",      "tri.bin",    "ext.gltf",     "tri.glb",    "tri_glb.obj",  "dag.gltf",
                          "ply_named.glb", "deep.gltf",  "chain.gltf",   "dag40.gltf", "cycle.gltf",   "self.gltf",
                          "child.gltf",    "short.gltf", "acc.gltf",     "view.gltf",  "json_lie.glb", "bin_lie.glb",
                          "len_lie.glb",   "no_bin.glb", "ply_cut.gltf", "junk.gltf",  "trail.gltf",   "v1.gltf",
                          "fifo.gltf",     "zero.gltf",  "out.gltf"};
    for (size_t i = 0; i < sizeof made / sizeof made[0]; i++)
        unlink(temp_path(made[i]));
}

int main(void) {
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_gltf_loads), cmocka_unit_test(test_gltf_hostile),
                                       cmocka_unit_test(test_gltf_files)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
