/* test_gtrace_mesh_formats.c - the same mesh as OBJ (mesh.c), ASCII PLY and glTF 2.0 (mesh_assimp.c, through
 * assimp) loads to the same corners (positions, normals, uv) and renders to the same pixels; truncated, garbage
 * and lying files fail with a message naming the file. Also a binary little-endian PLY of the same mesh, the header
 * lines PLY exporters write, and PLY layouts assimp mishandles, refused before it reads them. */
#include "test_gtrace_common.h"

#include <generic/builtins.h>

#include <unistd.h>

/* A bent quad: two triangles that are not coplanar, a normal and a (u,v) per vertex. */
static const double P[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0.5}, {-1, 1, 0}};
static const double N[4][3] = {{0, 0, 1}, {0.6, 0, 0.8}, {0, -0.6, 0.8}, {-0.28, 0, 0.96}};
static const double UV[4][2] = {{0, 0}, {2, 0}, {2, 1}, {0.25, 1}};
static const int TRI[2][3] = {{0, 1, 2}, {0, 2, 3}};

static void obj_text(char *out, size_t size)
{
    int n = 0;
    for (int i = 0; i < 4; i++)
        n += snprintf(out + n, size - (size_t)n, "v %g %g %g\nvn %g %g %g\nvt %g %g\n", P[i][0], P[i][1], P[i][2],
                      N[i][0], N[i][1], N[i][2], UV[i][0], UV[i][1]);
    for (int t = 0; t < 2; t++)
        n += snprintf(out + n, size - (size_t)n, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", TRI[t][0] + 1, TRI[t][0] + 1,
                      TRI[t][0] + 1, TRI[t][1] + 1, TRI[t][1] + 1, TRI[t][1] + 1, TRI[t][2] + 1, TRI[t][2] + 1,
                      TRI[t][2] + 1);
}

static void ply_text(char *out, size_t size)
{
    int n =
        snprintf(out, size,
                 "ply\nformat ascii 1.0\ncomment a bent quad\nelement vertex 4\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float s\n"
                 "property float t\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n");
    for (int i = 0; i < 4; i++)
        n += snprintf(out + n, size - (size_t)n, "%g %g %g %g %g %g %g %g\n", P[i][0], P[i][1], P[i][2], N[i][0],
                      N[i][1], N[i][2], UV[i][0], UV[i][1]);
    for (int t = 0; t < 2; t++)
        n += snprintf(out + n, size - (size_t)n, "3 %d %d %d\n", TRI[t][0], TRI[t][1], TRI[t][2]);
}

/* The same mesh as binary little-endian PLY (float properties, uchar count and int indices); its length. */
static size_t ply_binary(unsigned char *out, size_t size)
{
    int n = snprintf((char *)out, size,
                     "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                     "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
                     "property float v\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n");
    size_t o = (size_t)n;
    assert_true(o + 4 * 32 + 2 * 13 <= size);
    for (int i = 0; i < 4; i++) {
        float f[8] = {(float)P[i][0], (float)P[i][1], (float)P[i][2], (float)N[i][0],
                      (float)N[i][1], (float)N[i][2], (float)UV[i][0], (float)UV[i][1]};
        memcpy(out + o, f, sizeof f), o += sizeof f; /* this test runs on little-endian machines */
    }
    for (int t = 0; t < 2; t++) {
        out[o++] = 3;
        for (int k = 0; k < 3; k++) {
            int32_t v = TRI[t][k];
            memcpy(out + o, &v, 4), o += 4;
        }
    }
    return o;
}

static void base64(const unsigned char *in, size_t n, char *out)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t o = 0;
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)in[i] << 16 | (i + 1 < n ? (unsigned)in[i + 1] << 8 : 0) | (i + 2 < n ? in[i + 2] : 0);
        out[o++] = tab[v >> 18 & 63];
        out[o++] = tab[v >> 12 & 63];
        out[o++] = i + 1 < n ? tab[v >> 6 & 63] : '=';
        out[o++] = i + 2 < n ? tab[v & 63] : '=';
    }
    out[o] = '\0';
}

/* glTF 2.0 with one embedded buffer: positions, normals, texcoords (glTF's v runs downwards: 1 - v), indices.
 * count_override > 0 makes the position accessor claim that many vertices. */
static void gltf_text(char *out, size_t size, long long count_override)
{
    unsigned char buf[4 * 12 + 4 * 12 + 4 * 8 + 6 * 2];
    size_t o = 0;
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) {
            float f = (float)P[i][k];
            memcpy(buf + o, &f, 4), o += 4;
        }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) {
            float f = (float)N[i][k];
            memcpy(buf + o, &f, 4), o += 4;
        }
    for (int i = 0; i < 4; i++) {
        float uv[2] = {(float)UV[i][0], (float)(1.0 - UV[i][1])};
        memcpy(buf + o, uv, 8), o += 8;
    }
    for (int t = 0; t < 2; t++)
        for (int k = 0; k < 3; k++) {
            unsigned short s = (unsigned short)TRI[t][k];
            memcpy(buf + o, &s, 2), o += 2;
        }
    char b64[256];
    base64(buf, sizeof buf, b64);
    snprintf(out, size,
             "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\n"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},"
             "\"indices\":3}]}],\n"
             "\"buffers\":[{\"byteLength\":%zu,\"uri\":\"data:application/octet-stream;base64,%s\"}],\n"
             "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},"
             "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":48},{\"buffer\":0,\"byteOffset\":96,\"byteLength\":32},"
             "{\"buffer\":0,\"byteOffset\":128,\"byteLength\":12}],\n"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%lld,\"type\":\"VEC3\","
             "\"min\":[-1,-1,0],\"max\":[1,1,0.5]},"
             "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
             "{\"bufferView\":2,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
             "{\"bufferView\":3,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}]}\n",
             sizeof buf, b64, count_override > 0 ? count_override : 4);
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

/* A corner's position, normal (normalised) and uv. */
static void corner(const Mesh *m, int t, int j, double out[8])
{
    int v = (int)m->tri[3 * t + j], n = m->tri_normal[3 * t + j], u = m->tri_uv[3 * t + j];
    assert_true(n >= 0 && u >= 0);
    double len = sqrt(m->normal[3 * n] * m->normal[3 * n] + m->normal[3 * n + 1] * m->normal[3 * n + 1] +
                      m->normal[3 * n + 2] * m->normal[3 * n + 2]);
    for (int k = 0; k < 3; k++) {
        out[k] = m->pos[3 * v + k];
        out[3 + k] = m->normal[3 * n + k] / len;
    }
    out[6] = m->uv[2 * u];
    out[7] = m->uv[2 * u + 1];
}

/* Every triangle of b has the corners of a's triangle of the same index, in the same cyclic order. */
static void assert_same_corners(const Mesh *a, const Mesh *b)
{
    assert_int_equal(a->ntris, b->ntris);
    for (int t = 0; t < a->ntris; t++) {
        double ca[3][8], cb[3][8];
        for (int j = 0; j < 3; j++) {
            corner(a, t, j, ca[j]);
            corner(b, t, j, cb[j]);
        }
        int shift = -1;
        for (int s = 0; s < 3 && shift < 0; s++)
            if (fabs(ca[0][0] - cb[s][0]) + fabs(ca[0][1] - cb[s][1]) + fabs(ca[0][2] - cb[s][2]) < 1e-6)
                shift = s;
        assert_true(shift >= 0);
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 8; k++)
                assert_near(cb[(j + shift) % 3][k], ca[j][k], 1e-6);
        assert_int_equal(b->tri_surface[t], 0);
    }
}

/* A small render of the mesh in front of a checker-free grey wall, lit by a point light. */
static void render_mesh(const char *path, Framebuffer *fb)
{
    Scene *s = new_scene("rgb", gvec3(0.3, -0.4, 4), gvec3(0, 0, 0), 45.0);
    Object *o = load_ok(path);
    o->material = lambert(s, 0.7);
    GError err;
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    add_plane(s, lambert(s, 0.3), gvec3(0, 0, -1), gvec3(0, 0, 1));
    Light *l = add_light(s, LIGHT_POINT, 20.0);
    l->position = gvec3(2, 1, 3);
    render(s, 32, 32, 1, 2, fb);
    scene_destroy(s);
}

static void test_formats_agree(void **state)
{
    (void)state;
    char text[8192];
    obj_text(text, sizeof text);
    char *obj = write_text("m.obj", text);
    ply_text(text, sizeof text);
    char *ply = write_text("m.ply", text);
    gltf_text(text, sizeof text, 0);
    char *gltf = write_text("m.gltf", text);
    unsigned char bin[2048];
    size_t nbin = ply_binary(bin, sizeof bin);
    char *plyb = write_file("mb.ply", bin, nbin);
    Object *a = load_ok(obj), *b = load_ok(ply), *c = load_ok(gltf), *d = load_ok(plyb);
    assert_int_equal(a->mesh->ntris, 2);
    assert_same_corners(a->mesh, b->mesh);
    assert_same_corners(a->mesh, c->mesh);
    assert_same_corners(a->mesh, d->mesh);
    object_free(a);
    object_free(b);
    object_free(c);
    object_free(d);
    unlink(plyb);

    Framebuffer fa, fb, fc;
    render_mesh(obj, &fa);
    render_mesh(ply, &fb);
    render_mesh(gltf, &fc);
    double worst_b = 0, worst_c = 0, sum = 0;
    for (size_t i = 0; i < (size_t)3 * 32 * 32; i++) {
        worst_b = fmax(worst_b, fabs(fa.pixels[i] - fb.pixels[i]));
        worst_c = fmax(worst_c, fabs(fa.pixels[i] - fc.pixels[i]));
        sum += fa.pixels[i];
    }
    print_message("32x32 renders: mean %g; largest difference PLY %g, glTF %g\n", sum / (3 * 32 * 32), worst_b,
                  worst_c);
    assert_true(sum > 0.01 * 3 * 32 * 32); /* the image is not black */
    assert_true(worst_b < 1e-4);
    assert_true(worst_c < 1e-4);
    framebuffer_free(&fa);
    framebuffer_free(&fb);
    framebuffer_free(&fc);
    unlink(obj);
    unlink(ply);
    unlink(gltf);
}

/* An OBJ whose vertices carry the optional weight w (v x y z w) and whose texture coordinates carry the optional w
 * (vt u v w): the same mesh as without them (found by the scene fuzzer: the weight was written past the reader's
 * array of three numbers). */
static void test_obj_optional_weights(void **state)
{
    (void)state;
    char text[8192];
    obj_text(text, sizeof text);
    char *plain = write_text("plain.obj", text);
    size_t n = 0;
    for (int i = 0; i < 4; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, "v %.17g %.17g %.17g 1.5\nvn %.17g %.17g %.17g\n"
                              "vt %.17g %.17g 0.25\n", P[i][0], P[i][1], P[i][2], N[i][0], N[i][1], N[i][2],
                              UV[i][0], UV[i][1]);
    for (int t = 0; t < 2; t++)
        n += (size_t)snprintf(text + n, sizeof text - n, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", TRI[t][0] + 1,
                              TRI[t][0] + 1, TRI[t][0] + 1, TRI[t][1] + 1, TRI[t][1] + 1, TRI[t][1] + 1,
                              TRI[t][2] + 1, TRI[t][2] + 1, TRI[t][2] + 1);
    char *weighted = write_text("weighted.obj", text);
    Object *a = load_ok(plain), *b = load_ok(weighted);
    assert_int_equal(b->mesh->ntris, 2);
    assert_same_corners(a->mesh, b->mesh);
    object_free(a);
    object_free(b);
    unlink(plain);
    unlink(weighted);
}

/* path must fail to load with a message naming it. */
static void assert_refused(const char *path, const char *expect)
{
    Object *o = object_new(SHAPE_MESH, NULL);
    GError err;
    gerror_clear(&err);
    int rc = object_mesh_load(o, path, &err);
    if (rc == G_OK)
        fail_msg("%s loaded", path);
    if (!strstr(err.message, path) || (expect && !strstr(err.message, expect)))
        fail_msg("message for %s: %s", path, err.message);
    assert_null(o->mesh);
    object_free(o);
}

static void test_hostile_files(void **state)
{
    (void)state;
    char ply[8192], gltf[8192];
    ply_text(ply, sizeof ply);
    gltf_text(gltf, sizeof gltf, 0);
    /* every truncation of the PLY before its last face, and of the glTF, fails cleanly */
    size_t plen = strlen(ply), glen = strlen(gltf);
    int cuts = 0;
    for (size_t n = 0; n + 8 < plen; n += 3, cuts++)
        assert_refused(write_file("cut.ply", ply, n), NULL);
    unsigned char bin[2048];
    size_t blen = ply_binary(bin, sizeof bin);
    for (size_t n = 0; n < blen; n += 2, cuts++)
        assert_refused(write_file("cutb.ply", bin, n), NULL);
    bin[blen - 13] = 2; /* the second face claims 2 indices */
    assert_refused(write_file("two.ply", bin, blen), "a list of 2 values");
    bin[blen - 13] = 3;
    bin[blen - 1] = 0x7f; /* its last index far beyond the 4 vertices */
    assert_refused(write_file("far.ply", bin, blen), "out of range");
    for (size_t n = 0; n + 4 < glen; n += 7, cuts++)
        assert_refused(write_file("cut.gltf", gltf, n), NULL);
    /* garbage under every extension (seeded bytes; some starting like the real thing) */
    unsigned seed = 12345;
    const char *names[] = {"junk.ply", "junk.gltf", "junk.glb"};
    const char *heads[] = {"ply\nformat ascii 1.0\n", "{\"asset\":{\"version\":\"2.0\"},", "glTF\002\000\000\000"};
    for (int trial = 0; trial < 30; trial++, cuts++) {
        unsigned char junk[512];
        for (size_t i = 0; i < sizeof junk; i++)
            junk[i] = (unsigned char)((seed = seed * 1103515245u + 12345u) >> 16);
        int k = trial % 3;
        if (trial % 2)
            memcpy(junk, heads[k], k == 2 ? 8 : strlen(heads[k]));
        assert_refused(write_file(names[k], junk, sizeof junk), NULL);
    }
    /* lying counts: a PLY claiming 1e9 vertices or faces, a glTF accessor claiming 1e9 vertices, a glTF buffer
     * claiming a terabyte */
    char *cut = strstr(ply, "element vertex 4");
    assert_non_null(cut);
    char big[8192];
    snprintf(big, sizeof big, "%.*selement vertex 1000000000%s", (int)(cut - ply), ply, cut + 16);
    assert_refused(write_text("big.ply", big), "claims 1000000000 entries");
    cut = strstr(ply, "element face 2");
    snprintf(big, sizeof big, "%.*selement face 1000000000%s", (int)(cut - ply), ply, cut + 14);
    assert_refused(write_text("bigf.ply", big), "claims 1000000000 entries");
    gltf_text(big, sizeof big, 1000000000);
    assert_refused(write_text("big.gltf", big), "accessors[0].count must be an integer in [1, 357913941]");
    cut = strstr(gltf, "\"byteLength\":140");
    assert_non_null(cut);
    snprintf(big, sizeof big, "%.*s\"byteLength\":1000000000000%s", (int)(cut - gltf), gltf, cut + 16);
    assert_refused(write_text("bigb.gltf", big), "buffers[0].byteLength must be an integer in [1, ");
    /* not a regular file */
    assert_refused("/dev/zero.ply", NULL);
    print_message("%d hostile files refused\n", cuts + 5);
    const char *made[] = {"cut.ply", "cutb.ply", "two.ply", "far.ply", "cut.gltf", "junk.ply", "junk.gltf", "junk.glb",
                          "big.ply", "bigf.ply", "big.gltf", "bigb.gltf"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

/* text with `insert` put after the first occurrence of `after` */
static void insert_after(char *out, size_t size, const char *text, const char *after, const char *insert)
{
    const char *at = strstr(text, after);
    assert_non_null(at);
    at += strlen(after);
    snprintf(out, size, "%.*s%s%s", (int)(at - text), text, insert, at);
}

/* Header lines real exporters write load to the same mesh: Blender 2.4x's line without "comment", obj_info, a
 * "comment TextureFile" line and an obj_info line between one element's properties (assimp alone drops the
 * properties after them), a comment before the format line, CR LF line ends; a binary body whose first byte is a
 * line feed (which assimp alone drops). */
static void test_ply_exporter_headers(void **state)
{
    (void)state;
    char obj[8192], ply[8192], a[8192], b[8192];
    obj_text(obj, sizeof obj);
    Object *ref = load_ok(write_text("ref.obj", obj));
    ply_text(ply, sizeof ply);
    insert_after(a, sizeof a, ply, "format ascii 1.0\n",
                 "Created by Blender3D 247 - www.blender.org, source file: quad.blend\nobj_info vertices 4\n");
    insert_after(b, sizeof b, a, "property float y\n", "obj_info between properties\ncomment TextureFile quad.png\n");
    Object *o = load_ok(write_text("blender.ply", b));
    assert_same_corners(ref->mesh, o->mesh);
    object_free(o);
    insert_after(a, sizeof a, ply, "ply\n", "comment before the format\n");
    o = load_ok(write_text("first.ply", a));
    assert_same_corners(ref->mesh, o->mesh);
    object_free(o);
    size_t k = 0;
    for (const char *c = ply; *c && k + 2 < sizeof a; c++) { /* CR LF everywhere */
        if (*c == '\n')
            a[k++] = '\r';
        a[k++] = *c;
    }
    a[k] = '\0';
    o = load_ok(write_text("crlf.ply", a));
    assert_same_corners(ref->mesh, o->mesh);
    object_free(o);

    unsigned char bin[2048];
    size_t n = ply_binary(bin, sizeof bin);
    unsigned char *body = (unsigned char *)strstr((char *)bin, "end_header\n") + strlen("end_header\n");
    body[0] = 0x0a; /* the first vertex's x: -1 with its lowest mantissa byte a line feed */
    float x0;
    memcpy(&x0, body, 4);
    assert_true(x0 != -1.0f && fabs(x0 + 1.0) < 1e-5);
    o = load_ok(write_file("lf.ply", bin, n));
    assert_int_equal(o->mesh->ntris, 2);
    int found = 0;
    for (int i = 0; i < o->mesh->nverts; i++) {
        const double *q = o->mesh->pos + 3 * i;
        found |= q[0] == (double)x0 && q[1] == -1.0 && q[2] == 0.0;
        for (int j = 1; j < 4; j++)
            found |= (q[0] == P[j][0] && q[1] == P[j][1] && q[2] == P[j][2]) << j;
    }
    assert_int_equal(found, 15); /* every vertex where it was written */
    object_free(o);
    object_free(ref);
    const char *made[] = {"ref.obj", "blender.ply", "first.ply", "crlf.ply", "lf.ply"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

/* Layouts assimp's PLY reader mishandles are refused before it reads them: a face's texcoord list without its
 * index list (assimp follows a null pointer) or longer than two per corner (it reads past the index list), a
 * second vertex or face element (it writes past its arrays), malformed keyword lines; elements other than vertex
 * and face (assimp reads the data of one of a name it does not know as the next element's) are left out. */
static void test_ply_hostile_layouts(void **state)
{
    (void)state;
    const char *head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\n";
    const char *verts = "0 0 0\n1 0 0\n0 1 0\n";
    const struct {
        const char *header, *body, *expect;
    } bad[] = {
        {"element face 1\nproperty list uchar float texcoord\n", "6 0 0 1 0 0 1\n", "no vertex_indices list"},
        {"element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n",
         "3 0 1 2 8 0 0 1 0 0 1 1 1\n", "8 texture coordinates for 3 corners"},
        {"element vertex 2\nproperty float x\n", "1\n2\n", "a second vertex element"},
        {"element face 1\nproperty list uchar int vertex_indices\nelement tristrips 1\nproperty list int int "
         "vertex_indices\n", "3 0 1 2\n3 0 1 2\n", "a second face or tristrips element"},
        {"property float w\n", "", NULL}, /* a fourth vertex property: the vertices run short */
        {"element face 1\nproperty list uchar int128 vertex_indices\n", "3 0 1 2\n", "expected \"property TYPE"},
        {"format ascii 1.0\n", "", "expected one line \"format ascii 1.0\""},
        {"element face\n", "", "expected \"element NAME COUNT\""},
        {"element face -1\n", "", "needs a count"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char text[1024];
        snprintf(text, sizeof text, "%send_header\n%s%s", bad[i].header, verts, bad[i].body);
        char full[1200];
        snprintf(full, sizeof full, "%s%s", head, text);
        assert_refused(write_text("layout.ply", full), bad[i].expect);
    }
    assert_refused(write_text("prop.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n1\n"),
                   "a property before any element");
    assert_refused(write_text("end.ply", "ply\nend_header\nformat ascii 1.0\n"), "end_header before the format");
    /* the same face with 6 texture coordinates loads */
    char full[1200];
    snprintf(full, sizeof full, "%selement face 1\nproperty list uchar int vertex_indices\nproperty list uchar float "
             "texcoord\nend_header\n%s3 0 1 2 6 0 0 1 0 0 1\n", head, verts);
    Object *o = load_ok(write_text("layout.ply", full));
    assert_int_equal(o->mesh->ntris, 1);
    object_free(o);
    /* elements other than vertex and face (assimp gives one of an unknown name no entries and reads its data as
     * the next element's), before and after the vertices, ASCII and binary: the vertices stay where they were */
    snprintf(full, sizeof full, "ply\nformat ascii 1.0\nelement junk 2\nproperty float a\nproperty list uchar int b\n"
             "element material 1\nproperty uchar red\n%s", head + strlen("ply\nformat ascii 1.0\n"));
    snprintf(full + strlen(full), sizeof full - strlen(full), "element face 1\nproperty list uchar int "
             "vertex_indices\nelement edge 1\nproperty int vertex1\nend_header\n7 2 7 7\n8 0\n255\n%s3 0 1 2\n9\n",
             verts);
    o = load_ok(write_text("other.ply", full));
    static const double tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    assert_int_equal(o->mesh->ntris, 1);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            assert_near(o->mesh->pos[3 * o->mesh->tri[j] + k], tri[j][k], 0.0);
    object_free(o);
    unsigned char bin[512];
    int hn = snprintf((char *)bin, sizeof bin, "ply\nformat binary_little_endian 1.0\nelement junk 1\nproperty "
                      "double a\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    size_t bn = (size_t)hn;
    double junk = 1e300;
    memcpy(bin + bn, &junk, 8), bn += 8;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++) {
            float f = (float)tri[j][k];
            memcpy(bin + bn, &f, 4), bn += 4;
        }
    bin[bn++] = 3;
    for (int32_t j = 0; j < 3; j++)
        memcpy(bin + bn, &j, 4), bn += 4;
    o = load_ok(write_file("otherb.ply", bin, bn));
    assert_int_equal(o->mesh->ntris, 1);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            assert_near(o->mesh->pos[3 * o->mesh->tri[j] + k], tri[j][k], 0.0);
    object_free(o);
    const char *made[] = {"layout.ply", "prop.ply", "end.ply", "other.ply", "otherb.ply"};
    for (size_t i = 0; i < sizeof made / sizeof *made; i++)
        unlink(temp_path(made[i]));
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_formats_agree), cmocka_unit_test(test_hostile_files),
                                       cmocka_unit_test(test_obj_optional_weights),
                                       cmocka_unit_test(test_ply_exporter_headers),
                                       cmocka_unit_test(test_ply_hostile_layouts)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
