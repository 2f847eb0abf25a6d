/* mesh_gltf.c - the check a glTF 2.0 file (JSON, or binary .glb) passes before assimp reads it, decided by its
 * content whatever its name: the .glb header and chunk lengths against the file's size, the JSON scanned without
 * recursion to a bounded depth (mesh_json.c), then every buffer, buffer view and accessor against the bytes that
 * back it (a buffer file beside the mesh is opened by the library's rules: a regular file, allowed by the caller,
 * as large as it claims), every index against its array, and the node graph: no cycle, at most MESH_MAX_NODE_DEPTH
 * levels, at most GLTF_MAX_PLACEMENTS nodes once each node is expanded under every parent that names it (a node
 * named by two parents is copied twice), and the vertices and triangles those placements bake into the mesh at most
 * MESH_MAX_COUNT. assimp's own JSON reader and node import recurse, and it sizes its arrays by the claimed counts:
 * these checks are what keep a hostile file from taking the process down. */
#include "mesh_format.h"
#include "mesh_json.h"

#include <generic/memory.h>
#include <generic/services/file.h>

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define GLB_HEADER 12
#define GLB_CHUNK_JSON 0x4e4f534au
#define GLB_CHUNK_BIN 0x004e4942u
/* Longest buffer file name (the uri) accepted. */
#define GLTF_MAX_URI 1024

typedef struct View {
    unsigned long long buffer, offset, length, stride;
} View;

typedef struct Node {
    int tok;                    /* its object, for messages */
    long long mesh;             /* -1: none */
    uint32_t first, nchildren;  /* its children in Gltf.child */
    uint32_t parents, depth;
    double paths;               /* placements: the paths from a scene's root to it */
} Node;

typedef struct Gltf {
    const char *path, *where;
    Json j;
    const MeshFiles *files;
    GError *err;
    int glb, external;
    unsigned long long bin_len; /* the .glb's BIN chunk, when has_bin */
    int has_bin;
    uint32_t nbuffers, nviews, naccessors, nmeshes, nnodes, nchild;
    unsigned long long *buffer_len, *acc_count, *mesh_verts, *mesh_tris, buffer_bytes;
    View *view;
    Node *node;
    uint32_t *child;
} Gltf;

static unsigned long long le32(const unsigned char *p)
{
    return (unsigned long long)p[0] | (unsigned long long)p[1] << 8 | (unsigned long long)p[2] << 16 |
           (unsigned long long)p[3] << 24;
}

/* "PATH:LINE:COL: message" at token t (the top when t < 0). */
static int gltf_error(Gltf *G, int t, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    int line, col;
    const JsonTok *k = &G->j.tok[t < 0 ? 0 : t];
    json_position(&G->j, k->type == JSON_STRING && k->start > 0 ? k->start - 1 : k->start, &line, &col);
    return gerror_set(G->err, G_ERR_PARSE, "%s:%d:%d: %s%s", G->path, line, col, msg, G->where);
}

/* The array member key of object obj: its token in *arr (-1 when absent) and its length; every element an object. */
static int gltf_array(Gltf *G, int obj, const char *key, int *arr, uint32_t *n)
{
    *arr = json_get(&G->j, obj, key);
    *n = 0;
    if (*arr < 0)
        return G_OK;
    const JsonTok *a = &G->j.tok[*arr];
    if (a->type != JSON_ARRAY)
        return gltf_error(G, *arr, "\"%s\" must be an array", key);
    for (uint32_t k = (uint32_t)*arr + 1; k < a->next; k = G->j.tok[k].next)
        if (G->j.tok[k].type != JSON_OBJECT)
            return gltf_error(G, (int)k, "each element of \"%s\" must be an object", key);
    *n = a->count;
    return G_OK;
}

/* Member key of obj as an integer in [lo, hi]: absent gives dflt, or an error when dflt < 0 (required). */
static int gltf_uint(Gltf *G, int obj, const char *owner, uint32_t i, const char *key, long long dflt,
                     unsigned long long lo, unsigned long long hi, unsigned long long *out)
{
    int t = json_get(&G->j, obj, key);
    if (t < 0) {
        if (dflt < 0)
            return gltf_error(G, obj, "%s[%u] needs \"%s\"", owner, i, key);
        *out = (unsigned long long)dflt;
        return G_OK;
    }
    if (!json_uint(&G->j, t, hi, out) || *out < lo)
        return gltf_error(G, t, "%s[%u].%s must be an integer in [%llu, %llu]", owner, i, key, lo, hi);
    return G_OK;
}

/* A buffer's file beside the mesh: allowed, a regular file, with at least need bytes. */
static int gltf_buffer_file(Gltf *G, int t, uint32_t i, unsigned long long need)
{
    const JsonTok *u = &G->j.tok[t];
    const char *s = G->j.text + u->start;
    size_t len = u->end - u->start;
    if (len == 0 || len > GLTF_MAX_URI || s[0] == '/' || memchr(s, '\\', len) || memchr(s, '%', len) ||
        memchr(s, ':', len) || memchr(s, '\0', len))
        return gltf_error(G, t, "buffers[%u].uri must be a data: URI or a relative file name of at most %d bytes "
                          "without '%%', '\\', ':' or a leading '/'", i, GLTF_MAX_URI);
    if (++G->external > MESH_MAX_FILES)
        return gltf_error(G, t, "more than %d buffer files", MESH_MAX_FILES);
    char *dir = gfile_dir_of(G->path);
    char *file = dir ? gmem_alloc(strlen(dir) + len + 2) : NULL;
    if (!file) {
        gmem_free(dir);
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    }
    sprintf(file, "%s/%.*s", dir, (int)len, s);
    gmem_free(dir);
    GError e = {0};
    int rc = G->files && G->files->allowed ? G->files->allowed(G->files->ctx, file, &e) : G_OK;
    int fd = rc == G_OK ? gfile_open_input(file, &e) : -1;
    off_t bytes = -1;
    if (rc == G_OK && fd < 0)
        rc = fd;
    if (rc == G_OK && (bytes = lseek(fd, 0, SEEK_END)) < 0)
        rc = gerror_set(&e, G_ERR_IO, "cannot read \"%s\"", file);
    if (fd >= 0)
        close(fd);
    if (rc == G_OK && (unsigned long long)bytes < need)
        rc = gerror_set(&e, G_ERR_PARSE, "\"%s\" has %lld bytes, fewer than the %llu of byteLength", file,
                        (long long)bytes, need);
    gmem_free(file);
    if (rc < 0) {
        gltf_error(G, t, "buffers[%u]: %s", i, e.message);
        if (G->err)
            G->err->code = rc;
    }
    return rc;
}

static int gltf_buffers(Gltf *G, int root)
{
    int arr, rc = gltf_array(G, root, "buffers", &arr, &G->nbuffers);
    if (rc < 0)
        return rc;
    G->buffer_len = gmem_calloc(G->nbuffers + 1, sizeof *G->buffer_len);
    if (!G->buffer_len)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    uint32_t i = 0;
    for (uint32_t b = (uint32_t)arr + 1; arr >= 0 && b < G->j.tok[arr].next; b = G->j.tok[b].next, i++) {
        unsigned long long n;
        if ((rc = gltf_uint(G, (int)b, "buffers", i, "byteLength", -1, 1, MESH_MAX_FILE_BYTES, &n)) < 0)
            return rc;
        G->buffer_len[i] = n;
        G->buffer_bytes += n;
        int u = json_get(&G->j, (int)b, "uri");
        if (u < 0) {
            if (!(G->glb && i == 0 && G->has_bin))
                return gltf_error(G, (int)b, "buffers[%u] has no uri (only a .glb's first buffer is its BIN chunk)", i);
            if (G->bin_len < n)
                return gltf_error(G, (int)b, "buffers[%u].byteLength is %llu, the BIN chunk holds %llu bytes", i, n,
                                  G->bin_len);
            continue;
        }
        if (G->j.tok[u].type != JSON_STRING)
            return gltf_error(G, u, "buffers[%u].uri must be a string", i);
        const char *s = G->j.text + G->j.tok[u].start;
        size_t len = G->j.tok[u].end - G->j.tok[u].start;
        if (len >= 5 && memcmp(s, "data:", 5) == 0) {
            const char *comma = memchr(s, ',', len);
            if (!comma || comma - s < 12 || memcmp(comma - 7, ";base64", 7) != 0)
                return gltf_error(G, u, "buffers[%u].uri: a data: URI must be base64 (\"data:...;base64,...\")", i);
            size_t payload = len - (size_t)(comma + 1 - s);
            if ((unsigned long long)payload / 4 * 3 < n)
                return gltf_error(G, u, "buffers[%u].byteLength is %llu, its data: URI holds at most %zu bytes", i, n,
                                  payload / 4 * 3);
        } else if ((rc = gltf_buffer_file(G, u, i, n)) < 0) {
            return rc;
        }
    }
    return G_OK;
}

static int gltf_views(Gltf *G, int root)
{
    int arr, rc = gltf_array(G, root, "bufferViews", &arr, &G->nviews);
    if (rc < 0)
        return rc;
    G->view = gmem_calloc(G->nviews + 1, sizeof *G->view);
    if (!G->view)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    uint32_t i = 0;
    for (uint32_t b = (uint32_t)arr + 1; arr >= 0 && b < G->j.tok[arr].next; b = G->j.tok[b].next, i++) {
        View *v = &G->view[i];
        if (G->nbuffers == 0)
            return gltf_error(G, (int)b, "bufferViews[%u] names a buffer, and there is none", i);
        if ((rc = gltf_uint(G, (int)b, "bufferViews", i, "buffer", -1, 0, G->nbuffers - 1, &v->buffer)) < 0 ||
            (rc = gltf_uint(G, (int)b, "bufferViews", i, "byteOffset", 0, 0, MESH_MAX_FILE_BYTES, &v->offset)) < 0 ||
            (rc = gltf_uint(G, (int)b, "bufferViews", i, "byteLength", -1, 1, MESH_MAX_FILE_BYTES, &v->length)) < 0 ||
            (rc = gltf_uint(G, (int)b, "bufferViews", i, "byteStride", 0, 0, 252, &v->stride)) < 0)
            return rc;
        if (v->stride && v->stride < 4)
            return gltf_error(G, json_get(&G->j, (int)b, "byteStride"),
                              "bufferViews[%u].byteStride must be in [4, 252]", i);
        if (v->offset + v->length > G->buffer_len[v->buffer])
            return gltf_error(G, (int)b, "bufferViews[%u] ends at byte %llu of buffers[%llu], which has %llu bytes", i,
                              v->offset + v->length, v->buffer, G->buffer_len[v->buffer]);
    }
    return G_OK;
}

/* Bytes of one component of an accessor's componentType, 0 for an unknown type. */
static unsigned component_size(unsigned long long type)
{
    switch (type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

/* Components of an accessor's type, 0 for an unknown type. */
static unsigned type_components(const Json *j, int t)
{
    static const char *const names[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
    static const unsigned comps[] = {1, 2, 3, 4, 4, 9, 16};
    for (int k = 0; k < 7; k++)
        if (json_string_is(j, t, names[k]))
            return comps[k];
    return 0;
}

static int gltf_accessors(Gltf *G, int root)
{
    int arr, rc = gltf_array(G, root, "accessors", &arr, &G->naccessors);
    if (rc < 0)
        return rc;
    G->acc_count = gmem_calloc(G->naccessors + 1, sizeof *G->acc_count);
    if (!G->acc_count)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    uint32_t i = 0;
    for (uint32_t a = (uint32_t)arr + 1; arr >= 0 && a < G->j.tok[arr].next; a = G->j.tok[a].next, i++) {
        unsigned long long view, offset, count, ctype;
        if (json_get(&G->j, (int)a, "sparse") >= 0)
            return gltf_error(G, json_get(&G->j, (int)a, "sparse"), "accessors[%u]: sparse accessors are not read", i);
        if (json_get(&G->j, (int)a, "bufferView") < 0)
            return gltf_error(G, (int)a, "accessors[%u] has no bufferView (accessors of zeros are not read)", i);
        if (G->nviews == 0)
            return gltf_error(G, (int)a, "accessors[%u] names a buffer view, and there is none", i);
        if ((rc = gltf_uint(G, (int)a, "accessors", i, "bufferView", -1, 0, G->nviews - 1, &view)) < 0 ||
            (rc = gltf_uint(G, (int)a, "accessors", i, "byteOffset", 0, 0, MESH_MAX_FILE_BYTES, &offset)) < 0 ||
            (rc = gltf_uint(G, (int)a, "accessors", i, "count", -1, 1, MESH_MAX_COUNT, &count)) < 0 ||
            (rc = gltf_uint(G, (int)a, "accessors", i, "componentType", -1, 0, 1u << 20, &ctype)) < 0)
            return rc;
        unsigned size = component_size(ctype), comps = type_components(&G->j, json_get(&G->j, (int)a, "type"));
        if (!size)
            return gltf_error(G, json_get(&G->j, (int)a, "componentType"), "accessors[%u].componentType %llu is not "
                              "one of 5120, 5121, 5122, 5123, 5125, 5126", i, ctype);
        if (!comps)
            return gltf_error(G, (int)a, "accessors[%u].type must be SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4", i);
        const View *v = &G->view[view];
        unsigned long long elem = (unsigned long long)size * comps, stride = v->stride ? v->stride : elem;
        unsigned long long end = offset + (count - 1) * stride + elem;
        if (end > v->length)
            return gltf_error(G, (int)a, "accessors[%u]: %llu elements of %llu bytes need %llu bytes of "
                              "bufferViews[%llu], which has %llu", i, count, elem, end, view, v->length);
        G->acc_count[i] = count;
    }
    return G_OK;
}

/* An accessor index at member key of obj (required when dflt < 0). */
static int gltf_accessor_ref(Gltf *G, int obj, const char *owner, uint32_t i, const char *key, long long dflt,
                             unsigned long long *out)
{
    if (G->naccessors == 0 && (dflt < 0 || json_get(&G->j, obj, key) >= 0))
        return gltf_error(G, obj, "%s[%u].%s names an accessor, and there is none", owner, i, key);
    return gltf_uint(G, obj, owner, i, key, dflt, 0, G->naccessors ? G->naccessors - 1 : 0, out);
}

static int gltf_meshes(Gltf *G, int root)
{
    int arr, rc = gltf_array(G, root, "meshes", &arr, &G->nmeshes);
    if (rc < 0)
        return rc;
    G->mesh_verts = gmem_calloc(G->nmeshes + 1, sizeof *G->mesh_verts);
    G->mesh_tris = gmem_calloc(G->nmeshes + 1, sizeof *G->mesh_tris);
    if (!G->mesh_verts || !G->mesh_tris)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    uint32_t i = 0;
    for (uint32_t m = (uint32_t)arr + 1; arr >= 0 && m < G->j.tok[arr].next; m = G->j.tok[m].next, i++) {
        int prims;
        uint32_t np;
        if ((rc = gltf_array(G, (int)m, "primitives", &prims, &np)) < 0)
            return rc;
        if (np == 0)
            return gltf_error(G, (int)m, "meshes[%u] needs a non-empty \"primitives\" array", i);
        for (uint32_t p = (uint32_t)prims + 1; p < G->j.tok[prims].next; p = G->j.tok[p].next) {
            int attrs = json_get(&G->j, (int)p, "attributes");
            unsigned long long pos, idx, mode, acc;
            if (attrs < 0 || G->j.tok[attrs].type != JSON_OBJECT)
                return gltf_error(G, (int)p, "meshes[%u]: a primitive needs an \"attributes\" object", i);
            for (uint32_t k = (uint32_t)attrs + 1; k < G->j.tok[attrs].next; k = G->j.tok[k + 1].next)
                if (!json_uint(&G->j, (int)k + 1, G->naccessors ? G->naccessors - 1 : 0, &acc) || !G->naccessors)
                    return gltf_error(G, (int)k + 1, "meshes[%u]: an attribute must name one of the %u accessors", i,
                                      G->naccessors);
            if ((rc = gltf_accessor_ref(G, attrs, "meshes' attributes", i, "POSITION", -1, &pos)) < 0 ||
                (rc = gltf_uint(G, (int)p, "meshes' primitives", i, "mode", 4, 0, 6, &mode)) < 0)
                return rc;
            int has_idx = json_get(&G->j, (int)p, "indices") >= 0;
            if (has_idx && (rc = gltf_accessor_ref(G, (int)p, "meshes' primitives", i, "indices", 0, &idx)) < 0)
                return rc;
            unsigned long long n = has_idx ? G->acc_count[idx] : G->acc_count[pos];
            G->mesh_verts[i] += G->acc_count[pos];
            G->mesh_tris[i] += mode == 4 ? n / 3 : mode >= 5 && n >= 3 ? n - 2 : 0;
        }
    }
    return G_OK;
}

static int gltf_nodes(Gltf *G, int root)
{
    int arr, rc = gltf_array(G, root, "nodes", &arr, &G->nnodes);
    if (rc < 0)
        return rc;
    G->node = gmem_calloc(G->nnodes + 1, sizeof *G->node);
    if (!G->node)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    uint32_t i = 0;
    for (uint32_t t = (uint32_t)arr + 1; arr >= 0 && t < G->j.tok[arr].next; t = G->j.tok[t].next, i++) {
        Node *nd = &G->node[i];
        nd->tok = (int)t;
        nd->mesh = -1;
        if (json_get(&G->j, (int)t, "mesh") >= 0) {
            unsigned long long m;
            if (G->nmeshes == 0)
                return gltf_error(G, (int)t, "nodes[%u] names a mesh, and there is none", i);
            if ((rc = gltf_uint(G, (int)t, "nodes", i, "mesh", 0, 0, G->nmeshes - 1, &m)) < 0)
                return rc;
            nd->mesh = (long long)m;
        }
        int ch = json_get(&G->j, (int)t, "children");
        if (ch >= 0 && G->j.tok[ch].type != JSON_ARRAY)
            return gltf_error(G, ch, "nodes[%u].children must be an array", i);
        nd->first = G->nchild;
        nd->nchildren = ch >= 0 ? G->j.tok[ch].count : 0;
        G->nchild += nd->nchildren;
    }
    G->child = gmem_alloc(((size_t)G->nchild + 1) * sizeof *G->child);
    if (!G->child)
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    for (i = 0; i < G->nnodes; i++) {
        int ch = json_get(&G->j, G->node[i].tok, "children");
        uint32_t c = G->node[i].first;
        for (uint32_t k = (uint32_t)ch + 1; ch >= 0 && k < G->j.tok[ch].next; k = G->j.tok[k].next, c++) {
            unsigned long long v;
            if (!json_uint(&G->j, (int)k, G->nnodes - 1, &v))
                return gltf_error(G, (int)k, "nodes[%u].children: each must be one of the %u nodes' index", i,
                                  G->nnodes);
            G->child[c] = (uint32_t)v;
            G->node[v].parents++;
        }
    }
    return G_OK;
}

/* Seeds the placements of the scenes' root nodes (every scene's: an upper bound of what assimp imports; without
 * scenes, every node without a parent). */
static int gltf_scenes(Gltf *G, int root)
{
    int arr;
    uint32_t nscenes;
    int rc = gltf_array(G, root, "scenes", &arr, &nscenes);
    if (rc < 0)
        return rc;
    unsigned long long s;
    if (json_get(&G->j, root, "scene") >= 0 &&
        (nscenes == 0 || (rc = gltf_uint(G, root, "the file", 0, "scene", 0, 0, nscenes - 1, &s)) < 0))
        return rc < 0 ? rc
                      : gltf_error(G, json_get(&G->j, root, "scene"), "\"scene\" names a scene, and there is none");
    if (nscenes == 0) {
        for (uint32_t i = 0; i < G->nnodes; i++)
            G->node[i].paths = G->node[i].parents == 0;
        return G_OK;
    }
    uint32_t i = 0;
    for (uint32_t t = (uint32_t)arr + 1; t < G->j.tok[arr].next; t = G->j.tok[t].next, i++) {
        int nodes = json_get(&G->j, (int)t, "nodes");
        if (nodes >= 0 && G->j.tok[nodes].type != JSON_ARRAY)
            return gltf_error(G, nodes, "scenes[%u].nodes must be an array", i);
        for (uint32_t k = (uint32_t)nodes + 1; nodes >= 0 && k < G->j.tok[nodes].next; k = G->j.tok[k].next) {
            unsigned long long v;
            if (!G->nnodes || !json_uint(&G->j, (int)k, G->nnodes - 1, &v))
                return gltf_error(G, (int)k, "scenes[%u].nodes: each must be one of the %u nodes' index", i, G->nnodes);
            G->node[v].paths += 1.0;
        }
    }
    return G_OK;
}

/* The node graph in topological order (Kahn): a cycle, nesting deeper than MESH_MAX_NODE_DEPTH, more placements
 * than GLTF_MAX_PLACEMENTS and more placed vertices or triangles than MESH_MAX_COUNT are refused. */
static int gltf_graph(Gltf *G, MeshGltfCounts *counts)
{
    uint32_t *queue = gmem_alloc(((size_t)G->nnodes + 1) * sizeof *queue), *pending;
    pending = gmem_alloc(((size_t)G->nnodes + 1) * sizeof *pending);
    if (!queue || !pending) {
        gmem_free(queue);
        gmem_free(pending);
        return gerror_set(G->err, G_ERR_NOMEM, "%s: out of memory", G->path);
    }
    uint32_t head = 0, tail = 0;
    for (uint32_t i = 0; i < G->nnodes; i++) {
        pending[i] = G->node[i].parents;
        G->node[i].depth = 1;
        if (!pending[i])
            queue[tail++] = i;
    }
    double placements = 0, verts = 0, tris = 0;
    int rc = G_OK;
    while (head < tail && rc == G_OK) {
        const Node *nd = &G->node[queue[head++]];
        placements += nd->paths;
        if (nd->mesh >= 0) {
            verts += nd->paths * (double)G->mesh_verts[nd->mesh];
            tris += nd->paths * (double)G->mesh_tris[nd->mesh];
        }
        if (nd->depth > MESH_MAX_NODE_DEPTH)
            rc = gltf_error(G, nd->tok, "nodes nested deeper than %d levels", MESH_MAX_NODE_DEPTH);
        else if (placements > GLTF_MAX_PLACEMENTS)
            rc = gltf_error(G, nd->tok, "the nodes expand to more than %d placements (a node is copied under each "
                            "parent that names it)", GLTF_MAX_PLACEMENTS);
        else if (verts > MESH_MAX_COUNT || tris > MESH_MAX_COUNT)
            rc = gltf_error(G, nd->tok, "the placed meshes have more than %d vertices or triangles", MESH_MAX_COUNT);
        for (uint32_t c = nd->first; rc == G_OK && c < nd->first + nd->nchildren; c++) {
            Node *ch = &G->node[G->child[c]];
            ch->paths += nd->paths;
            if (ch->depth < nd->depth + 1)
                ch->depth = nd->depth + 1;
            if (--pending[G->child[c]] == 0)
                queue[tail++] = G->child[c];
        }
    }
    if (rc == G_OK && tail < G->nnodes) {
        uint32_t i = 0;
        while (pending[i] == 0)
            i++;
        rc = gltf_error(G, G->node[i].tok, "nodes[%u] is its own descendant (the nodes' children form a cycle)", i);
    }
    gmem_free(queue);
    gmem_free(pending);
    counts->placements = (unsigned long long)placements;
    counts->verts = (unsigned long long)verts;
    counts->tris = (unsigned long long)tris;
    counts->buffer_bytes = G->buffer_bytes;
    return rc;
}

/* The .glb container: its header and chunks against the file's size; *json and *json_len its JSON chunk. */
static int glb_chunks(Gltf *G, const unsigned char *data, size_t size, const char **json, size_t *json_len)
{
    if (size < GLB_HEADER + 8)
        return gerror_set(G->err, G_ERR_PARSE, "%s: a .glb of %zu bytes, shorter than its header and first chunk "
                          "header (20 bytes)", G->path, size);
    if (le32(data + 4) != 2)
        return gerror_set(G->err, G_ERR_PARSE, "%s: .glb version %llu (only 2 is read)", G->path, le32(data + 4));
    if (le32(data + 8) != size)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb header claims %llu bytes, the file has %zu", G->path,
                          le32(data + 8), size);
    unsigned long long len = le32(data + 12);
    if (le32(data + 16) != GLB_CHUNK_JSON)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb's first chunk is not JSON", G->path);
    if (len > size - 20)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb's JSON chunk claims %llu bytes, %zu follow its header",
                          G->path, len, size - 20);
    if (len % 4)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb's JSON chunk length %llu is not a multiple of 4", G->path,
                          len);
    *json = (const char *)data + 20;
    *json_len = (size_t)len;
    size_t at = 20 + (size_t)len;
    if (at == size)
        return G_OK;
    if (size - at < 8)
        return gerror_set(G->err, G_ERR_PARSE, "%s: %zu bytes after the .glb's JSON chunk, too few for a chunk header",
                          G->path, size - at);
    unsigned long long bin = le32(data + at);
    if (le32(data + at + 4) != GLB_CHUNK_BIN)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb's second chunk is not BIN", G->path);
    if (bin > size - at - 8)
        return gerror_set(G->err, G_ERR_PARSE, "%s: the .glb's BIN chunk claims %llu bytes, %zu follow its header",
                          G->path, bin, size - at - 8);
    G->has_bin = 1;
    G->bin_len = bin;
    return G_OK;
}

int mesh_gltf_check(const char *path, const unsigned char *data, size_t size, const MeshFiles *files,
                    MeshGltfCounts *counts, GError *err)
{
    Gltf G = {.path = path, .where = "", .files = files, .err = err};
    memset(counts, 0, sizeof *counts);
    const char *json = (const char *)data;
    size_t json_len = size;
    int rc = G_OK;
    if (size >= 4 && memcmp(data, "glTF", 4) == 0) {
        G.glb = 1;
        G.where = " (in the .glb's JSON chunk)";
        rc = glb_chunks(&G, data, size, &json, &json_len);
    }
    size_t at = 0;
    while (!G.glb && at < size && (data[at] == ' ' || data[at] == '\t' || data[at] == '\r' || data[at] == '\n'))
        at++;
    if (!G.glb && (at == size || data[at] != '{'))
        return gerror_set(err, G_ERR_PARSE, "%s: neither a .glb (the \"glTF\" magic) nor glTF's JSON (an object)",
                          path);
    if (rc == G_OK)
        rc = json_scan(&G.j, path, G.where, json, json_len, err);
    if (rc < 0)
        return rc;
    int root = 0, asset = json_get(&G.j, 0, "asset"), version = json_get(&G.j, asset, "version");
    if (G.j.tok[0].type != JSON_OBJECT)
        rc = gltf_error(&G, 0, "a glTF file is a JSON object");
    else if (version < 0 || G.j.tok[version].type != JSON_STRING || G.j.tok[version].end - G.j.tok[version].start < 2 ||
             memcmp(G.j.text + G.j.tok[version].start, "2.", 2) != 0)
        rc = gltf_error(&G, version >= 0 ? version : asset, "asset.version must be \"2.x\" (glTF 2.0)");
    if (rc == G_OK && (rc = gltf_buffers(&G, root)) == G_OK && (rc = gltf_views(&G, root)) == G_OK &&
        (rc = gltf_accessors(&G, root)) == G_OK && (rc = gltf_meshes(&G, root)) == G_OK &&
        (rc = gltf_nodes(&G, root)) == G_OK && (rc = gltf_scenes(&G, root)) == G_OK)
        rc = gltf_graph(&G, counts);
    json_free(&G.j);
    gmem_free(G.buffer_len);
    gmem_free(G.view);
    gmem_free(G.acc_count);
    gmem_free(G.mesh_verts);
    gmem_free(G.mesh_tris);
    gmem_free(G.node);
    gmem_free(G.child);
    return rc;
}
