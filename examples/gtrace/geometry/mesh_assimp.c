/* mesh_assimp.c - triangle meshes from PLY and glTF 2.0 (.ply, .gltf, .glb) through assimp: positions, normals
 * and the first (u,v) set where the file has them, the node transforms baked in, and the material index of
 * each assimp mesh as the surface index of its triangles. OBJ stays with mesh.c's own reader. */
#include "object.h"

#include <generic/services/file.h>
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

/* assimp's PLY reader loops forever on some truncated headers, aborts on some truncated bodies and sizes its
 * arrays by the claimed counts, so a PLY file is checked completely first: a header of known lines only, element
 * counts the file can hold, and a body that has every value the header announces (ASCII numbers, or binary
 * bytes), face lists of at least 3 indices within the vertex count. */
#define PLY_MAX_ELEMENTS 16
#define PLY_MAX_PROPS 32

typedef struct PlyProp {
    int size, count_size; /* bytes of a value and, for a list, of its count (0: not a list) */
    int is_index;         /* the face's vertex_indices / vertex_index list */
} PlyProp;

typedef struct PlyElem {
    unsigned long long n;
    int nprops, is_vertex, is_face;
    PlyProp prop[PLY_MAX_PROPS];
} PlyElem;

static int ply_type_size(const char *t)
{
    static const char *names[] = {"char", "uchar", "int8", "uint8", "short", "ushort", "int16", "uint16",
                                  "int", "uint", "int32", "uint32", "float", "float32", "double", "float64"};
    static const int sizes[] = {1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8};
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++)
        if (strcmp(t, names[i]) == 0)
            return sizes[i];
    return 0;
}

typedef struct PlyBody {
    const char *p, *end;
    int ascii, big_endian;
} PlyBody;

/* The next value as a double: an ASCII number or `size` binary bytes (integers read as unsigned when used as
 * counts or indices: the caller only needs them for those). -1 when the file ends or holds no number there. */
static int ply_value(PlyBody *B, int size, double *out)
{
    if (B->ascii) {
        while (B->p < B->end && (*B->p == ' ' || *B->p == '\t' || *B->p == '\n' || *B->p == '\r'))
            B->p++;
        char tok[64];
        size_t k = 0;
        while (B->p < B->end && k + 1 < sizeof tok && !(*B->p == ' ' || *B->p == '\t' || *B->p == '\n' || *B->p == '\r'))
            tok[k++] = *B->p++;
        tok[k] = '\0';
        char *e;
        *out = strtod(tok, &e);
        return k > 0 && *e == '\0' ? 0 : -1;
    }
    if (B->end - B->p < size)
        return -1;
    unsigned long long v = 0;
    for (int i = 0; i < size; i++)
        v |= (unsigned long long)(unsigned char)B->p[B->big_endian ? i : size - 1 - i] << (8 * (size - 1 - i));
    B->p += size;
    *out = size <= 4 ? (double)(v & 0xffffffffull) : 0.0; /* counts and indices are at most 4 bytes */
    return 0;
}

static int ply_check(const char *path, int fd, GError *err)
{
    off_t size = lseek(fd, 0, SEEK_END);
    if (size < 0 || lseek(fd, 0, SEEK_SET) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    if ((unsigned long long)size > (unsigned long long)MESH_MAX_COUNT * 64)
        return gerror_set(err, G_ERR_PARSE, "%s: larger than %lld bytes", path, (long long)MESH_MAX_COUNT * 64);
    char *data = gmem_alloc((size_t)size + 1);
    if (!data)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    ssize_t got = 0;
    while (got < size) {
        ssize_t r = read(fd, data + got, (size_t)(size - got));
        if (r <= 0)
            break;
        got += r;
    }
    data[got] = '\0';
    int rc = G_OK, line = 1, ascii = -1, big = 0, nel = 0, header_done = 0;
    PlyElem *el = gmem_calloc(PLY_MAX_ELEMENTS, sizeof *el);
    char *s = data, *end = data + got;
    if (!el)
        rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    while (rc == G_OK && !header_done) {
        char *nl = memchr(s, '\n', (size_t)(end - s));
        if (!nl) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: the header ends before end_header", path, line);
            break;
        }
        *nl = '\0';
        size_t len = (size_t)(nl - s);
        if (len > 0 && nl[-1] == '\r')
            nl[-1] = '\0', len--;
        if (strlen(s) != len)
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: a NUL byte in the header", path, line);
        char w[4][64];
        int nw = rc == G_OK ? sscanf(s, "%63s %63s %63s %63s", w[0], w[1], w[2], w[3]) : 0;
        if (rc != G_OK) {
        } else if (line == 1) {
            if (nw != 1 || strcmp(w[0], "ply") != 0)
                rc = gerror_set(err, G_ERR_PARSE, "%s:1: not a PLY file (no \"ply\" line)", path);
        } else if (nw >= 1 && (strcmp(w[0], "comment") == 0 || strcmp(w[0], "obj_info") == 0)) {
        } else if (nw == 3 && strcmp(w[0], "format") == 0 && strcmp(w[2], "1.0") == 0 && ascii < 0 &&
                   (strcmp(w[1], "ascii") == 0 || strcmp(w[1], "binary_little_endian") == 0 ||
                    strcmp(w[1], "binary_big_endian") == 0)) {
            ascii = strcmp(w[1], "ascii") == 0;
            big = strcmp(w[1], "binary_big_endian") == 0;
        } else if (nw == 3 && strcmp(w[0], "element") == 0 && nel < PLY_MAX_ELEMENTS) {
            char *e;
            errno = 0;
            unsigned long long n = strtoull(w[2], &e, 10);
            if (*e || errno || w[2][0] == '-')
                rc = gerror_set(err, G_ERR_PARSE, "%s:%d: the element %s needs a count", path, line, w[1]);
            else if (n > MESH_MAX_COUNT || n > (unsigned long long)got)
                rc = gerror_set(err, G_ERR_PARSE,
                                "%s:%d: element %s claims %llu entries, more than the %lld-byte file can hold "
                                "(limit %d)", path, line, w[1], n, (long long)got, MESH_MAX_COUNT);
            el[nel].n = n;
            el[nel].is_vertex = strcmp(w[1], "vertex") == 0;
            el[nel].is_face = strcmp(w[1], "face") == 0;
            nel++;
        } else if (nel > 0 && el[nel - 1].nprops < PLY_MAX_PROPS && nw == 3 && strcmp(w[0], "property") == 0 &&
                   ply_type_size(w[1])) {
            el[nel - 1].prop[el[nel - 1].nprops++] = (PlyProp){ply_type_size(w[1]), 0, 0};
        } else if (nel > 0 && el[nel - 1].nprops < PLY_MAX_PROPS && strcmp(w[0], "property") == 0 && nw == 4 &&
                   strcmp(w[1], "list") == 0 && ply_type_size(w[2]) && ply_type_size(w[2]) <= 4 &&
                   sscanf(s, "%*s %*s %*s %63s %63s", w[0], w[1]) == 2 && ply_type_size(w[0])) {
            el[nel - 1].prop[el[nel - 1].nprops++] = (PlyProp){
                ply_type_size(w[0]), ply_type_size(w[2]),
                el[nel - 1].is_face && (strcmp(w[1], "vertex_indices") == 0 || strcmp(w[1], "vertex_index") == 0)};
        } else if (nw == 1 && strcmp(w[0], "end_header") == 0 && ascii >= 0) {
            header_done = 1;
        } else {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: not a PLY header line this reader accepts: %.60s", path,
                            line, s);
        }
        s = nl + 1;
        line++;
    }
    unsigned long long nverts = 0;
    for (int e = 0; e < nel; e++)
        if (el[e].is_vertex)
            nverts = el[e].n;
    PlyBody B = {s, end, ascii == 1, big};
    for (int e = 0; e < nel && rc == G_OK; e++)
        for (unsigned long long i = 0; i < el[e].n && rc == G_OK; i++)
            for (int k = 0; k < el[e].nprops && rc == G_OK; k++) {
                const PlyProp *pp = &el[e].prop[k];
                double x, cnt = 1;
                if (pp->count_size && ply_value(&B, pp->count_size, &cnt) < 0) {
                    rc = gerror_set(err, G_ERR_PARSE, "%s: the data ends early or holds a non-number "
                                    "(entry %llu of element %d)", path, i, e);
                    break;
                }
                if (cnt < 0 || cnt != (long long)cnt || cnt > (double)(end - B.p) ||
                    (pp->is_index && cnt < 3)) {
                    rc = gerror_set(err, G_ERR_PARSE, "%s: entry %llu of element %d: a list of %g values", path,
                                    i, e, cnt);
                    break;
                }
                for (long long j = 0; j < (long long)cnt && rc == G_OK; j++) {
                    if (ply_value(&B, pp->size, &x) < 0)
                        rc = gerror_set(err, G_ERR_PARSE, "%s: the data ends early or holds a non-number "
                                        "(entry %llu of element %d)", path, i, e);
                    else if (pp->is_index && !(x >= 0 && x < (double)nverts))
                        rc = gerror_set(err, G_ERR_PARSE, "%s: face %llu: vertex index %g out of range", path, i, x);
                }
                if (rc == G_OK && B.p > B.end)
                    rc = gerror_set(err, G_ERR_PARSE, "%s: the data ends early", path);
            }
    gmem_free(el);
    gmem_free(data);
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
    int rc = ends_with(path, ".ply") ? ply_check(path, fd, err) : G_OK;
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
