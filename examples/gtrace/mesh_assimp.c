/* mesh_assimp.c - triangle meshes from PLY and glTF 2.0 (.ply, .gltf, .glb) through assimp: positions, normals
 * and the first (u,v) set where the file has them, the node transforms baked in, and the material index of
 * each assimp mesh as the surface index of its triangles. OBJ stays with mesh.c's own reader. */
#include "object.h"

#include <generic/file.h>
#include <generic/memory.h>

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* The OBJ reader's bound: its arrays hold at most 2^30 ints, 3 per triangle or vertex. */
#define MESH_MAX_COUNT (0x40000000 / 3)
/* Largest node depth walked (a hostile file may nest nodes deeply). */
#define MESH_MAX_NODE_DEPTH 256

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcasecmp(s + n - k, suffix) == 0;
}

int mesh_is_assimp_file(const char *path)
{
    return ends_with(path, ".ply") || ends_with(path, ".gltf") || ends_with(path, ".glb");
}

/* A PLY header's element counts against the bytes that follow it: every element takes at least one byte in
 * the ASCII and binary encodings, so a larger claim is a lie, refused before assimp sizes arrays by it. */
static int ply_counts_check(const char *path, int fd, GError *err)
{
    off_t size = lseek(fd, 0, SEEK_END);
    if (size < 0 || lseek(fd, 0, SEEK_SET) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    char head[65536];
    ssize_t got = read(fd, head, sizeof head - 1);
    if (got < 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    head[got] = '\0';
    if (got < 4 || memcmp(head, "ply", 3) != 0 || (head[3] != '\n' && head[3] != '\r'))
        return gerror_set(err, G_ERR_PARSE, "%s: not a PLY file (no \"ply\" line)", path);
    char *end = strstr(head, "end_header");
    if (!end || memchr(head, '\0', (size_t)got))
        return gerror_set(err, G_ERR_PARSE, "%s: no end_header in the first %zu bytes", path, sizeof head - 1);
    *end = '\0';
    long long body = (long long)size - (long long)(end - head) - 10;
    int line = 1;
    for (char *s = head; *s; line++) {
        char *nl = strchr(s, '\n');
        if (nl)
            *nl = '\0';
        if (strncmp(s, "element", 7) == 0 && (s[7] == ' ' || s[7] == '\t')) {
            char name[64];
            char *p;
            if (sscanf(s + 8, "%63s", name) != 1 || !(p = strstr(s + 8, name)))
                return gerror_set(err, G_ERR_PARSE, "%s:%d: an element needs a name and a count", path, line);
            p += strlen(name);
            char *e;
            errno = 0;
            unsigned long long n = strtoull(p, &e, 10);
            if (e == p || errno == ERANGE || strchr(p, '-'))
                return gerror_set(err, G_ERR_PARSE, "%s:%d: the element %s needs a count", path, line, name);
            if (n > MESH_MAX_COUNT || (long long)n > body)
                return gerror_set(err, G_ERR_PARSE,
                                  "%s:%d: element %s claims %llu entries, more than the %lld bytes after the "
                                  "header can hold (limit %d)",
                                  path, line, name, n, body, MESH_MAX_COUNT);
        }
        if (!nl)
            break;
        s = nl + 1;
    }
    return G_OK;
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
            z[4 * i + j] = x[4 * i] * y[j] + x[4 * i + 1] * y[4 + j] + x[4 * i + 2] * y[8 + j] + x[4 * i + 3] * y[12 + j];
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
                o[r] = (double)a[4 * r] * p->x + (double)a[4 * r + 1] * p->y + (double)a[4 * r + 2] * p->z + a[4 * r + 3];
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

int mesh_load_assimp(Object *o, const char *path, GError *err)
{
    int fd = gfile_open_input(path, err); /* a regular file: never a FIFO or a device */
    if (fd < 0)
        return fd;
    int rc = ends_with(path, ".ply") ? ply_counts_check(path, fd, err) : G_OK;
    close(fd);
    if (rc != G_OK)
        return rc;
    const struct aiScene *sc = aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                      aiProcess_ValidateDataStructure);
    if (!sc)
        return gerror_set(err, G_ERR_PARSE, "%s: %s", path, aiGetErrorString());
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
        size_t nv = (size_t)cnt.verts, nt = (size_t)cnt.tris;
        m = gmem_calloc(1, sizeof *m);
        if (m) {
            m->pos = gmem_alloc(nv * 3 * sizeof *m->pos);
            m->normal = gmem_alloc(nv * 3 * sizeof *m->normal);
            m->uv = gmem_alloc(nv * 2 * sizeof *m->uv);
            m->tri = gmem_alloc(nt * 3 * sizeof *m->tri);
            m->tri_uv = gmem_alloc(nt * 3 * sizeof *m->tri_uv);
            m->tri_normal = gmem_alloc(nt * 3 * sizeof *m->tri_normal);
            m->tri_surface = gmem_alloc(nt * sizeof *m->tri_surface);
        }
        if (!m || !m->pos || !m->normal || !m->uv || !m->tri || !m->tri_uv || !m->tri_normal || !m->tri_surface) {
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
    aiReleaseImport(sc);
    return rc;
}
