/* mesh_assimp.c - triangle meshes from PLY, STL and glTF 2.0 through assimp: positions, normals and the first
 * (u,v) set where the file has them, the node transforms baked in, and the material index of each assimp mesh as
 * the surface index of its triangles. A file is checked whole first (mesh_ply.c, mesh_stl.c, mesh_gltf.c) and assimp
 * reads the checked bytes; the files a glTF file names go through mesh_assimp_io.c. OBJ stays with mesh.c's own
 * reader; mesh_format.c picks the reader. */
#include "mesh_assimp_lib.h"
#include "mesh_assimp_io.h"
#include "mesh_format.h"
#include "mesh_json.h"

#include <generic/memory.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* Bytes kept free in front of a PLY file read whole: the header mesh_ply_check writes is at most one byte longer
 * than the file's own, and goes there in front of the body. */
#define MESH_HEADROOM 16

int mesh_assimp_reads_extension(const char *ext)
{
    const MeshAssimpLib *ai = mesh_assimp_lib(NULL);
    return ai && ai->is_extension_supported(ext) == AI_TRUE;
}

/* Reads the regular file open as fd whole into *buf (gmem_alloc), its bytes from MESH_HEADROOM on, NUL-terminated:
 * *size of them (fewer than the file's size when it shrinks meanwhile), at most MESH_MAX_FILE_BYTES. The buffer is
 * reserved against the memory budget (*reserved bytes; release them with the buffer). */
static int read_whole(const char *path, int fd, char **buf, size_t *size, size_t *reserved, GError *err)
{
    off_t n = lseek(fd, 0, SEEK_END);
    if (n < 0 || lseek(fd, 0, SEEK_SET) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    if ((unsigned long long)n > MESH_MAX_FILE_BYTES)
        return gerror_set(err, G_ERR_PARSE, "%s: larger than %llu bytes", path, MESH_MAX_FILE_BYTES);
    GError refusal;
    if (gmem_budget_reserve((size_t)n + MESH_HEADROOM + 1, "a mesh file read whole", &refusal) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "%s: %s", path, refusal.message);
    char *b = gmem_alloc((size_t)n + MESH_HEADROOM + 1);
    if (!b) {
        gmem_budget_release((size_t)n + MESH_HEADROOM + 1);
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    }
    size_t got = 0;
    while (got < (size_t)n) {
        ssize_t r = read(fd, b + MESH_HEADROOM + got, (size_t)n - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            break;
        got += (size_t)r;
    }
    b[MESH_HEADROOM + got] = '\0';
    *buf = b;
    *size = got;
    *reserved = (size_t)n + MESH_HEADROOM + 1;
    return G_OK;
}

/* The scene assimp makes of a PLY or STL file: read whole, checked, and handed to assimp from memory (a PLY file
 * as mesh_ply_check rewrote it: its header in front of the body), so that assimp reads the bytes that were checked. */
static int import_checked(const MeshAssimpLib *ai, const char *path, int fd, MeshFormat format, unsigned flags,
                          const struct aiScene **sc, GError *err)
{
    char *buf = NULL, *header = NULL;
    size_t size = 0, hlen = 0, body = 0, body_len = 0, reserved = 0;
    int rc = read_whole(path, fd, &buf, &size, &reserved, err);
    if (rc != G_OK)
        return rc;
    char *data = buf + MESH_HEADROOM, *start = data;
    size_t len = size;
    if (format == MESH_FORMAT_PLY) {
        rc = mesh_ply_check(path, data, size, &header, &hlen, &body, &body_len, err);
        if (rc == G_OK && hlen > body + MESH_HEADROOM)
            rc = gerror_set(err, G_ERR_PARSE, "%s: the PLY header would not fit", path);
        if (rc == G_OK) {
            start = data + body - hlen;
            memcpy(start, header, hlen);
            len = hlen + body_len;
        }
    } else {
        rc = mesh_stl_check(path, data, size, err);
    }
    if (rc == G_OK)
        *sc = ai->import_file_from_memory(start, (unsigned)len, flags, format == MESH_FORMAT_PLY ? "ply" : "stl");
    gmem_free(header);
    gmem_free(buf);
    gmem_budget_release(reserved);
    return rc;
}

typedef struct Counts {
    long long verts, tris;
} Counts;

/* Vertices and triangles the node tree places (a mesh used by n nodes counts n times), stopping at the limit. */
static int count_node(const struct aiScene *sc, const struct aiNode *nd, int depth, Counts *c)
{
    if (depth > MESH_MAX_NODE_DEPTH)
        return -1;
    for (unsigned i = 0; i < nd->mNumMeshes; i++) {
        if (nd->mMeshes[i] >= sc->mNumMeshes)
            return -1;
        const struct aiMesh *m = sc->mMeshes[nd->mMeshes[i]];
        c->verts += m->mNumVertices;
        for (unsigned f = 0; f < m->mNumFaces; f++)
            c->tris += m->mFaces[f].mNumIndices == 3;
        if (c->verts > MESH_MAX_COUNT || c->tris > MESH_MAX_COUNT)
            return -2;
    }
    for (unsigned i = 0; i < nd->mNumChildren; i++) {
        int rc = count_node(sc, nd->mChildren[i], depth + 1, c);
        if (rc < 0)
            return rc;
    }
    return 0;
}

static struct aiMatrix4x4 mat_mul(const struct aiMatrix4x4 *a, const struct aiMatrix4x4 *b)
{
    const float *x = &a->a1, *y = &b->a1;
    struct aiMatrix4x4 r;
    float *z = &r.a1;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            z[4 * i + j] =
                x[4 * i] * y[j] + x[4 * i + 1] * y[4 + j] + x[4 * i + 2] * y[8 + j] + x[4 * i + 3] * y[12 + j];
    return r;
}

typedef struct Fill {
    Mesh *m;
    int v, t; /* vertices and triangles written */
} Fill;

/* Copies the meshes of nd and its children under the transform parent * nd (row-major, column vectors). */
static void fill_node(const struct aiScene *sc, const struct aiNode *nd, const struct aiMatrix4x4 *parent, Fill *F)
{
    struct aiMatrix4x4 x = mat_mul(parent, &nd->mTransformation);
    const float *a = &x.a1;
    /* normals: the cofactor matrix (det times the inverse transpose) of the linear part, sign of det kept */
    double c[9] = {a[5] * a[10] - a[6] * a[9], a[6] * a[8] - a[4] * a[10], a[4] * a[9] - a[5] * a[8],
                   a[2] * a[9] - a[1] * a[10], a[0] * a[10] - a[2] * a[8], a[1] * a[8] - a[0] * a[9],
                   a[1] * a[6] - a[2] * a[5],  a[2] * a[4] - a[0] * a[6],  a[0] * a[5] - a[1] * a[4]};
    double det = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
    double sgn = det < 0 ? -1.0 : 1.0;
    Mesh *m = F->m;
    for (unsigned i = 0; i < nd->mNumMeshes; i++) {
        const struct aiMesh *am = sc->mMeshes[nd->mMeshes[i]];
        int base = F->v;
        for (unsigned k = 0; k < am->mNumVertices; k++) {
            const struct aiVector3D *p = &am->mVertices[k];
            double *o = m->pos + 3 * (size_t)(base + (int)k);
            for (int r = 0; r < 3; r++)
                o[r] =
                    (double)a[4 * r] * p->x + (double)a[4 * r + 1] * p->y + (double)a[4 * r + 2] * p->z + a[4 * r + 3];
            double *n = m->normal + 3 * (size_t)(base + (int)k);
            if (am->mNormals) {
                const struct aiVector3D *q = &am->mNormals[k];
                for (int r = 0; r < 3; r++)
                    n[r] = sgn * (c[3 * r] * q->x + c[3 * r + 1] * q->y + c[3 * r + 2] * q->z);
            } else {
                n[0] = n[1] = n[2] = 0.0;
            }
            double *uv = m->uv + 2 * (size_t)(base + (int)k);
            uv[0] = am->mTextureCoords[0] ? am->mTextureCoords[0][k].x : 0.0;
            uv[1] = am->mTextureCoords[0] ? am->mTextureCoords[0][k].y : 0.0;
        }
        for (unsigned f = 0; f < am->mNumFaces; f++) {
            const struct aiFace *fc = &am->mFaces[f];
            if (fc->mNumIndices != 3) /* points and lines left by triangulation */
                continue;
            int t = F->t++;
            for (int j = 0; j < 3; j++) {
                int vi = base + (int)fc->mIndices[j];
                m->tri[3 * t + j] = (unsigned)vi;
                m->tri_normal[3 * t + j] = am->mNormals ? vi : -1;
                m->tri_uv[3 * t + j] = am->mTextureCoords[0] ? vi : -1;
            }
            m->tri_surface[t] = (int)am->mMaterialIndex;
        }
        F->v += (int)am->mNumVertices;
    }
    for (unsigned i = 0; i < nd->mNumChildren; i++)
        fill_node(sc, nd->mChildren[i], &x, F);
}

/* Every face index within its mesh (assimp's validation step checks this too; the copy relies on it). */
static int indices_ok(const struct aiScene *sc)
{
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *m = sc->mMeshes[i];
        if (!m || !m->mVertices)
            return 0;
        for (unsigned f = 0; f < m->mNumFaces; f++)
            for (unsigned j = 0; j < m->mFaces[f].mNumIndices; j++)
                if (m->mFaces[f].mIndices[j] >= m->mNumVertices)
                    return 0;
    }
    return 1;
}

/* The scene assimp makes of a glTF file: read whole (a file of JSON at most JSON_MAX_BYTES), checked, and handed to
 * assimp under a name with the extension of its content (assimp picks its reader by the name first), from memory;
 * the buffer files it names are opened by files' rules. */
static int import_gltf(const MeshAssimpLib *ai, const char *path, int fd, unsigned flags, const MeshFiles *files,
                       const struct aiScene **sc, GError *err)
{
    unsigned char magic[4] = {0};
    off_t n = lseek(fd, 0, SEEK_END);
    int glb = pread(fd, magic, 4, 0) == 4 && memcmp(magic, "glTF", 4) == 0;
    if (n >= 0 && !glb && (unsigned long long)n > JSON_MAX_BYTES)
        return gerror_set(err, G_ERR_PARSE, "%s: a glTF file of JSON of %lld bytes, more than the limit of %u", path,
                          (long long)n, JSON_MAX_BYTES);
    char *buf = NULL, *name = NULL;
    size_t size = 0, reserved = 0, assimp = 0;
    int rc = read_whole(path, fd, &buf, &size, &reserved, err);
    if (rc != G_OK)
        return rc;
    MeshGltfCounts counts;
    rc = mesh_gltf_check(path, (const unsigned char *)buf + MESH_HEADROOM, size, files, &counts, err);
    GError refusal;
    if (rc == G_OK) { /* assimp's scene: its copy of the buffers' data, twice over, and about 1 KB a node; and the
                       * triangles the placements bake, so that a mesh too large for the budget is refused first */
        assimp = 2 * (size_t)counts.buffer_bytes + (size_t)counts.placements * 1200 +
                 mesh_budget_bytes(0, (size_t)counts.tris);
        if (gmem_budget_reserve(assimp, "assimp's copy of a glTF file", &refusal) != G_OK) {
            assimp = 0;
            rc = gerror_set(err, G_ERR_NOMEM, "%s: %s", path, refusal.message);
        }
    }
    const char *ext = glb ? ".glb" : ".gltf";
    size_t len = strlen(path), elen = strlen(ext);
    if (rc == G_OK && !(len > elen && strcasecmp(path + len - elen, ext) == 0)) {
        name = gmem_alloc(len + elen + 1);
        if (!name)
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
        else
            memcpy(name, path, len), memcpy(name + len, ext, elen + 1);
    }
    if (rc == G_OK) {
        MeshIO io;
        mesh_io_init(&io, name ? name : path, buf + MESH_HEADROOM, size, files);
        *sc = ai->import_file_ex(name ? name : path, flags, &io.hooks);
        if (!*sc && io.refusal.code)
            rc = gerror_set(err, io.refusal.code, "%s: %s", path, io.refusal.message);
    }
    gmem_free(name);
    gmem_free(buf);
    gmem_budget_release(reserved);
    gmem_budget_release(assimp);
    return rc;
}

int mesh_assimp_check(const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err)
{
    if (format == MESH_FORMAT_GLTF) {
        unsigned char magic[4] = {0};
        off_t n = lseek(fd, 0, SEEK_END);
        int glb = pread(fd, magic, 4, 0) == 4 && memcmp(magic, "glTF", 4) == 0;
        if (n >= 0 && !glb && (unsigned long long)n > JSON_MAX_BYTES)
            return gerror_set(err, G_ERR_PARSE, "%s: a glTF file of JSON of %lld bytes, more than the limit of %u",
                              path, (long long)n, JSON_MAX_BYTES);
    }
    char *buf = NULL, *header = NULL;
    size_t size = 0, reserved = 0, hlen = 0, body = 0, body_len = 0;
    int rc = read_whole(path, fd, &buf, &size, &reserved, err);
    if (rc != G_OK)
        return rc;
    char *data = buf + MESH_HEADROOM;
    MeshGltfCounts counts;
    if (format == MESH_FORMAT_PLY)
        rc = mesh_ply_check(path, data, size, &header, &hlen, &body, &body_len, err);
    else if (format == MESH_FORMAT_STL)
        rc = mesh_stl_check(path, data, size, err);
    else
        rc = mesh_gltf_check(path, (const unsigned char *)data, size, files, &counts, err);
    gmem_free(header);
    gmem_free(buf);
    gmem_budget_release(reserved);
    return rc;
}

int mesh_load_assimp(Object *o, const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err)
{
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;
    const struct aiScene *sc = NULL;
    GError why;
    const MeshAssimpLib *ai = mesh_assimp_lib(&why);
    if (!ai) {
        close(fd);
        return gerror_set(err, why.code, "%s: %s", path, why.message);
    }
    int rc = format == MESH_FORMAT_GLTF ? import_gltf(ai, path, fd, flags, files, &sc, err)
                                        : import_checked(ai, path, fd, format, flags, &sc, err);
    close(fd);
    if (rc != G_OK)
        return rc;
    if (!sc)
        return gerror_set(err, G_ERR_PARSE, "%s: %s", path, ai->get_error_string());
    Counts cnt = {0, 0};
    int walk = sc->mRootNode && indices_ok(sc) ? count_node(sc, sc->mRootNode, 0, &cnt) : -1;
    if (walk == -1)
        rc = gerror_set(err, G_ERR_PARSE, "%s: inconsistent scene (bad mesh reference or nodes nested deeper than %d)",
                        path, MESH_MAX_NODE_DEPTH);
    else if (walk == -2)
        rc = gerror_set(err, G_ERR_PARSE, "%s: more than %d vertices or triangles", path, MESH_MAX_COUNT);
    else if (cnt.tris == 0)
        rc = gerror_set(err, G_ERR_PARSE, "%s: no faces", path);
    Mesh *m = NULL;
    if (rc == G_OK) {
        size_t nv = (size_t)cnt.verts, nt = (size_t)cnt.tris, bytes = mesh_budget_bytes(nv, nt);
        char what[96];
        GError refusal;
        snprintf(what, sizeof what, "a mesh of %zu vertices and %zu triangles", nv, nt);
        if (gmem_budget_reserve(bytes, what, &refusal) != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "%s: %s", path, refusal.message);
        else if (!(m = gmem_calloc(1, sizeof *m)))
            gmem_budget_release(bytes);
        else
            m->budget = bytes;
        if (m) {
            m->pos = gmem_alloc(nv * 3 * sizeof *m->pos);
            m->normal = gmem_alloc(nv * 3 * sizeof *m->normal);
            m->uv = gmem_alloc(nv * 2 * sizeof *m->uv);
            m->tri = gmem_alloc(nt * 3 * sizeof *m->tri);
            m->tri_uv = gmem_alloc(nt * 3 * sizeof *m->tri_uv);
            m->tri_normal = gmem_alloc(nt * 3 * sizeof *m->tri_normal);
            m->tri_surface = gmem_alloc(nt * sizeof *m->tri_surface);
        }
        if (rc == G_OK &&
            (!m || !m->pos || !m->normal || !m->uv || !m->tri || !m->tri_uv || !m->tri_normal || !m->tri_surface)) {
            mesh_free(m);
            m = NULL;
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
        }
    }
    if (rc == G_OK) {
        m->nverts = m->nuvs = m->nnormals = (int)cnt.verts;
        m->ntris = (int)cnt.tris;
        struct aiMatrix4x4 id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        Fill F = {m, 0, 0};
        fill_node(sc, sc->mRootNode, &id, &F);
        for (int i = 0; i < 3 * m->nverts && rc == G_OK; i++)
            if (!(m->pos[i] >= -1e30 && m->pos[i] <= 1e30)) /* NaN or overflow from the transform */
                rc = gerror_set(err, G_ERR_PARSE, "%s: a vertex position is not a finite number", path);
        if (rc == G_OK) {
            mesh_free(o->mesh);
            o->mesh = m;
        } else {
            mesh_free(m);
        }
    }
    ai->release_import(sc);
    return rc;
}
