/* mesh.c - triangle meshes from Wavefront OBJ files (v, vt, vn, f; polygons become fans; negative indices
 * count from the end; usemtl and g start a new surface index), other formats handed to their readers
 * (mesh_format.c), and the surface at a triangle hit. */
#include "geometry.h"
#include "mesh_format.h"

#include <generic/services/file.h>
#include <generic/services/spawn.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* What a mesh's arrays reserved against the memory budget while they grow, and the refusal when one was refused. */
typedef struct ArrBudget {
    size_t reserved;
    int refused;
    GError refusal;
} ArrBudget;

/* A growing array of elements of one size (doubles or ints here). */
typedef struct Arr {
    void *data;
    int n, cap; /* in elements */
    ArrBudget *budget;
} Arr;

/* Appends the `size`-byte element at x, doubling the storage (from 256 elements) when it is full; the growth is
 * reserved against the memory budget first. */
static int arr_push(Arr *a, const void *x, size_t size)
{
    if (a->n == a->cap) {
        if (a->cap >= 0x40000000) /* doubling would overflow an int */
            return G_ERR_NOMEM;
        int cap = a->cap ? a->cap * 2 : 256;
        size_t grow = (size_t)(cap - a->cap) * size;
        if (gmem_budget_reserve(grow, "a mesh's vertices and faces", &a->budget->refusal) != G_OK) {
            a->budget->refused = 1;
            return G_ERR_NOMEM;
        }
        a->budget->reserved += grow;
        void *nv = gmem_realloc(a->data, (size_t)cap * size);
        if (!nv)
            return G_ERR_NOMEM;
        a->data = nv;
        a->cap = cap;
    }
    memcpy((char *)a->data + (size_t)a->n++ * size, x, size);
    return G_OK;
}

static int dpush(Arr *a, double x) { return arr_push(a, &x, sizeof x); }
static int ipush(Arr *a, int x) { return arr_push(a, &x, sizeof x); }

void mesh_free(Mesh *m)
{
    if (!m)
        return;
    gmem_free(m->pos);
    gmem_free(m->uv);
    gmem_free(m->normal);
    gmem_free(m->tri);
    gmem_free(m->tri_uv);
    gmem_free(m->tri_normal);
    gmem_free(m->tri_surface);
    gmem_budget_release(m->budget);
    gmem_free(m);
}

size_t mesh_budget_bytes(size_t nverts, size_t ntris)
{
    return nverts * (8 * sizeof(double) + 16) + ntris * (9 * sizeof(int) + sizeof(int) + 12 + 64);
}

/* Resolves a 1-based or negative OBJ index against count; -1 for absent, -2 for out of range. */
static int resolve(long idx, int count)
{
    if (idx > 0 && idx <= count)
        return (int)idx - 1;
    if (idx < 0 && idx >= -(long)count) /* never -idx: it overflows for LONG_MIN */
        return count + (int)idx;
    return -2;
}

typedef struct Loader {
    const char *path;
    int line;
    Arr pos, uv, nrm;          /* doubles */
    Arr tri, tuv, tn, tsurf;   /* ints */
    int surface, used_surface;
    GError *err;
    ArrBudget *budget;
} Loader;

/* An array could not grow: the memory budget's refusal at the line, or out of memory. */
static int obj_nomem(Loader *L)
{
    if (L->budget->refused)
        return gerror_set(L->err, G_ERR_NOMEM, "%s:%d: %s", L->path, L->line, L->budget->refusal.message);
    return gerror_set(L->err, G_ERR_NOMEM, "%s: out of memory", L->path);
}

static int obj_error(Loader *L, int col, const char *msg)
{
    return gerror_set(L->err, G_ERR_PARSE, "%s:%d:%d: %s", L->path, L->line, col, msg);
}

/* Most numbers an OBJ statement keeps: a vertex's x y z and its optional w. */
#define OBJ_MAX_NUMBERS 4

/* Reads the numbers of a statement into out (room for OBJ_MAX_NUMBERS): at least min of them, the first max kept
 * (max at most OBJ_MAX_NUMBERS), the others read and dropped. Their count, or an error at the offending column. */
static int read_numbers(Loader *L, char *s, const char *line, double out[OBJ_MAX_NUMBERS], int min, int max)
{
    int n = 0;
    max = max < OBJ_MAX_NUMBERS ? max : OBJ_MAX_NUMBERS;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s || *s == '\n' || *s == '\r' || *s == '#')
            break;
        char *end;
        errno = 0;
        double x = strtod(s, &end);
        if (end == s)
            return obj_error(L, (int)(s - line) + 1, "expected a number");
        if (!isfinite(x))
            return obj_error(L, (int)(s - line) + 1,
                             errno == ERANGE ? "number out of range (beyond +-1.8e308)" : "expected a finite number");
        if (n < max)
            out[n] = x;
        n++;
        s = end;
    }
    if (n < min)
        return obj_error(L, (int)(s - line) + 1, "too few numbers");
    return n;
}

static int read_face(Loader *L, char *s, const char *line)
{
    int vi[3], ti[3], ni[3], k = 0;
    int nv = L->pos.n / 3, nt = L->uv.n / 2, nn = L->nrm.n / 3;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s || *s == '\n' || *s == '\r' || *s == '#')
            break;
        int col = (int)(s - line) + 1;
        char *end;
        long a = strtol(s, &end, 10), b = 0, c = 0;
        if (end == s)
            return obj_error(L, col, "expected a vertex index");
        s = end;
        if (*s == '/') {
            s++;
            if (*s != '/') {
                b = strtol(s, &end, 10);
                if (end == s)
                    return obj_error(L, (int)(s - line) + 1, "expected a texture coordinate index");
                s = end;
            }
            if (*s == '/') {
                s++;
                c = strtol(s, &end, 10);
                if (end == s)
                    return obj_error(L, (int)(s - line) + 1, "expected a normal index");
                s = end;
            }
        }
        int v = resolve(a, nv), t = b ? resolve(b, nt) : -1, n = c ? resolve(c, nn) : -1;
        if (v < 0 || t == -2 || n == -2)
            return obj_error(L, col, "index out of range");
        if (k < 2) {
            vi[k] = v;
            ti[k] = t;
            ni[k] = n;
        } else {
            vi[2] = v;
            ti[2] = t;
            ni[2] = n;
            for (int j = 0; j < 3; j++) {
                if (ipush(&L->tri, vi[j]) || ipush(&L->tuv, ti[j]) || ipush(&L->tn, ni[j]))
                    return obj_nomem(L);
            }
            if (ipush(&L->tsurf, L->surface))
                return obj_nomem(L);
            L->used_surface = 1;
            vi[1] = vi[2];
            ti[1] = ti[2];
            ni[1] = ni[2];
        }
        k++;
    }
    if (k < 3)
        return obj_error(L, (int)(s - line) + 1, "a face needs at least 3 vertices");
    return G_OK;
}

/* Reads one line (its '\n' dropped) into buf, NUL-terminated, its length in *len (NUL bytes of the file
 * included, so that they can be reported as such): 1, 0 at the end of the file, -1 when the line does not fit. */
static int read_line(FILE *f, char *buf, size_t size, size_t *len)
{
    size_t n = 0;
    int c;
    while ((c = getc_unlocked(f)) != EOF && c != '\n') {
        if (n + 1 >= size) {
            buf[n] = '\0';
            *len = n;
            return -1;
        }
        buf[n++] = (char)c;
    }
    buf[n] = '\0';
    *len = n;
    return c == EOF && n == 0 ? 0 : 1;
}

static int parse_line(Loader *L, char *line)
{
    char *s = line;
    while (*s == ' ' || *s == '\t')
        s++;
    double x[OBJ_MAX_NUMBERS];
    if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
        int n = read_numbers(L, s + 2, line, x, 3, 4);
        if (n < 0)
            return n;
        return dpush(&L->pos, x[0]) || dpush(&L->pos, x[1]) || dpush(&L->pos, x[2]) ? G_ERR_NOMEM : G_OK;
    }
    if (s[0] == 'v' && s[1] == 't' && (s[2] == ' ' || s[2] == '\t')) {
        int n = read_numbers(L, s + 3, line, x, 2, 3);
        if (n < 0)
            return n;
        return dpush(&L->uv, x[0]) || dpush(&L->uv, x[1]) ? G_ERR_NOMEM : G_OK;
    }
    if (s[0] == 'v' && s[1] == 'n' && (s[2] == ' ' || s[2] == '\t')) {
        int n = read_numbers(L, s + 3, line, x, 3, 3);
        if (n < 0)
            return n;
        return dpush(&L->nrm, x[0]) || dpush(&L->nrm, x[1]) || dpush(&L->nrm, x[2]) ? G_ERR_NOMEM : G_OK;
    }
    if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t'))
        return read_face(L, s + 2, line);
    if ((strncmp(s, "usemtl", 6) == 0 || (s[0] == 'g' && (s[1] == ' ' || s[1] == '\t'))) && L->used_surface) {
        L->surface++;
        L->used_surface = 0;
    }
    return G_OK; /* comments, o, s, mtllib and other statements are ignored */
}

static int mesh_load(Object *o, const char *path, const MeshFiles *files, GError *err)
{
    int fd = gfile_open_input(path, err); /* a regular file: never a FIFO or a device */
    if (fd < 0)
        return fd;
    char what[128];
    MeshFormat format = mesh_format_of(fd, path, what, sizeof what);
    if (format == MESH_FORMAT_UNSUPPORTED) {
        close(fd);
        return gerror_set(err, G_ERR_UNSUPPORTED, "%s: %s, not a mesh format gtrace reads (it reads "
                          MESH_FORMATS_READ ")", path, what);
    }
    if (format != MESH_FORMAT_OBJ) {
        int isolated = gspawn_isolated(err); /* PLY, STL and glTF in gtrace-mesh */
        if (isolated < 0) {
            close(fd);
            return isolated;
        }
        return isolated ? mesh_load_isolated(o, path, fd, format, files, err)
                        : mesh_load_assimp(o, path, fd, format, files, err);
    }
    FILE *f = fdopen(fd, "r");
    if (!f) {
        close(fd);
        return gerror_set(err, G_ERR_NOMEM, "%s: cannot read: %s", path, strerror(errno));
    }
    ArrBudget budget = {0};
    Loader L = {.path = path, .err = err, .budget = &budget};
    Arr *arrays[] = {&L.pos, &L.uv, &L.nrm, &L.tri, &L.tuv, &L.tn, &L.tsurf};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
        arrays[i]->budget = &budget;
    char buf[4096];
    int rc = G_OK, got;
    size_t len;
    while (rc == G_OK && (got = read_line(f, buf, sizeof buf, &len)) != 0) {
        L.line++;
        char *nul = memchr(buf, '\0', len);
        char *text = buf;
        if (L.line == 1 && len >= 3 && memcmp(buf, "\xef\xbb\xbf", 3) == 0) /* a UTF-8 byte-order mark */
            text += 3;
        if (nul) {
            rc = obj_error(&L, (int)(nul - buf) + 1, "a NUL byte (not a text file?)");
            break;
        }
        if (got < 0) {
            rc = obj_error(&L, (int)sizeof buf, "line too long (the limit is 4095 bytes)");
            break;
        }
        rc = parse_line(&L, text);
        if (rc == G_ERR_NOMEM)
            obj_nomem(&L);
    }
    if (rc == G_OK && ferror(f))
        rc = gerror_set(err, G_ERR_IO, "%s: read error", path);
    fclose(f);
    if (rc == G_OK && L.tsurf.n == 0)
        rc = gerror_set(err, G_ERR_PARSE, "%s: no faces", path);
    /* the accelerator's copy and hierarchy (mesh_budget_bytes less the arrays reserved as they grew) */
    size_t accel = (size_t)L.tsurf.n * (12 + 64) + (size_t)(L.pos.n / 3) * 16;
    GError refusal;
    if (rc == G_OK && gmem_budget_reserve(accel, "a mesh's acceleration structure", &refusal) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "%s: %s", path, refusal.message);
    else if (rc == G_OK)
        budget.reserved += accel;
    Mesh *m = NULL;
    if (rc == G_OK) {
        m = gmem_calloc(1, sizeof *m);
        if (!m)
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    }
    if (rc == G_OK) {
        m->nverts = L.pos.n / 3;
        m->nuvs = L.uv.n / 2;
        m->nnormals = L.nrm.n / 3;
        m->ntris = L.tsurf.n;
        m->pos = L.pos.data;
        m->uv = L.uv.data;
        m->normal = L.nrm.data;
        m->tri_uv = L.tuv.data;
        m->tri_normal = L.tn.data;
        m->tri_surface = L.tsurf.data;
        m->budget = budget.reserved;
        m->tri = gmem_alloc((size_t)L.tri.n * sizeof *m->tri);
        if (!m->tri) {
            L.tri.n = 0;
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
        }
        for (int i = 0; i < L.tri.n; i++)
            m->tri[i] = (unsigned)((const int *)L.tri.data)[i];
        gmem_free(L.tri.data);
        if (rc != G_OK) {
            mesh_free(m);
            return rc;
        }
        mesh_free(o->mesh);
        o->mesh = m;
        return G_OK;
    }
    gmem_free(L.pos.data);
    gmem_free(L.uv.data);
    gmem_free(L.nrm.data);
    gmem_free(L.tri.data);
    gmem_free(L.tuv.data);
    gmem_free(L.tn.data);
    gmem_free(L.tsurf.data);
    gmem_budget_release(budget.reserved);
    return rc;
}

int object_mesh_load(Object *o, const char *path, GError *err) { return object_mesh_load_from(o, path, NULL, err); }

int object_mesh_load_from(Object *o, const char *path, const MeshFiles *files, GError *err)
{
    int rc = mesh_load(o, path, files, err);
    if (rc < 0 && err && !err->param[0]) /* a scene file's reader places the message at the entry's file */
        snprintf(err->param, sizeof err->param, "%s", "file");
    return rc;
}

static GVec3 vget(const double *a, int i) { return gvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

void mesh_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g)
{
    const Mesh *m = o->mesh;
    unsigned k = h->prim;
    (void)r;
    const unsigned *t = m->tri + 3 * k;
    double b1 = h->bu, b2 = h->bv, b0 = 1.0 - b1 - b2;
    GVec3 p0 = vget(m->pos, (int)t[0]), p1 = vget(m->pos, (int)t[1]), p2 = vget(m->pos, (int)t[2]);
    GVec3 e1 = gvec3_sub(p1, p0), e2 = gvec3_sub(p2, p0);
    GVec3 op = gvec3_add(gvec3_add(gvec3_scale(p0, b0), gvec3_scale(p1, b1)), gvec3_scale(p2, b2));
    GVec3 n = gvec3_normalize(gvec3_cross(e1, e2));
    GVec3 ns = n;
    const int *tn = m->tri_normal + 3 * k;
    if (tn[0] >= 0 && tn[1] >= 0 && tn[2] >= 0) {
        GVec3 s = gvec3_add(gvec3_add(gvec3_scale(vget(m->normal, tn[0]), b0), gvec3_scale(vget(m->normal, tn[1]), b1)),
                            gvec3_scale(vget(m->normal, tn[2]), b2));
        if (gvec3_length(s) > 0.0)
            ns = gvec3_normalize(s);
    }
    const int *tu = m->tri_uv + 3 * k;
    double u = b1, v = b2;
    GVec3 dpdu, dpdv;
    int have_uv = tu[0] >= 0 && tu[1] >= 0 && tu[2] >= 0;
    double du1 = 0, dv1 = 0, du2 = 0, dv2 = 0, det = 0;
    if (have_uv) {
        const double *a = m->uv + 2 * tu[0], *b = m->uv + 2 * tu[1], *c = m->uv + 2 * tu[2];
        u = b0 * a[0] + b1 * b[0] + b2 * c[0];
        v = b0 * a[1] + b1 * b[1] + b2 * c[1];
        du1 = b[0] - a[0];
        dv1 = b[1] - a[1];
        du2 = c[0] - a[0];
        dv2 = c[1] - a[1];
        det = du1 * dv2 - dv1 * du2;
    }
    if (have_uv && fabs(det) > 1e-12) {
        double id = 1.0 / det;
        dpdu = gvec3_scale(gvec3_sub(gvec3_scale(e1, dv2), gvec3_scale(e2, dv1)), id);
        dpdv = gvec3_scale(gvec3_sub(gvec3_scale(e2, du1), gvec3_scale(e1, du2)), id);
    } else if (!have_uv) {
        dpdu = e1; /* (u,v) are the barycentrics */
        dpdv = e2;
    } else {
        frame_from_normal(n, &dpdu, &dpdv);
    }
    g->u = u;
    g->v = v;
    g->surface = m->tri_surface[k];
    g->op = op;
    g->n_out = n;
    g->n_smooth = ns;
    g->dpdu = dpdu;
    g->dpdv = dpdv;
    hit_geom_to_world(o, g);
}
