/* gtrace_mesh.c - the mesh reader process, gtrace-mesh (geometry/mesh_protocol.h): reads one PLY, STL or glTF file
 * with gtrace's own checks and assimp (mesh_load_assimp) under resource limits, so that a crash, a hang or a
 * memory blow-up of assimp ends this process only. It reads the file gtrace opened (descriptor 3), asks gtrace
 * before it opens any other file, charges its reservations to a copy of gtrace's memory budget, and writes the mesh
 * on its standard output. Not a program for users. */
#include "geometry/mesh_assimp_lib.h"
#include "geometry/mesh_format.h"
#include "geometry/mesh_protocol.h"

#include <generic/memory.h>
#include <generic/services/file.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

static int send_message(const MeshMessage *m, const char *text)
{
    return gfile_write_exact(1, m, sizeof *m) != 0 || gfile_write_exact(1, text, m->text_length) != 0 ? -1 : 0;
}

/* MeshFiles.allowed: gtrace's rule answers. */
static int ask(void *ctx, const char *path, GError *err)
{
    (void)ctx;
    size_t len = strlen(path);
    if (len > MESH_TEXT_MAX)
        return gerror_set(err, G_ERR_IO, "\"%.64s...\": a path of %zu bytes is too long", path, len);
    MeshMessage m = {.magic = MESH_PROTOCOL_MAGIC, .kind = MESH_MSG_ASK, .text_length = (uint32_t)len};
    MeshAnswer a;
    char message[MESH_TEXT_MAX + 1];
    if (send_message(&m, path) != 0 || gfile_read_exact(0, &a, sizeof a) != 0 || a.magic != MESH_PROTOCOL_MAGIC ||
        a.message_length > MESH_TEXT_MAX || gfile_read_exact(0, message, a.message_length) != 0)
        exit(1); /* gtrace went away */
    message[a.message_length] = 0;
    if (a.status == G_OK)
        return G_OK;
    return gerror_set(err, a.status < 0 ? a.status : G_ERR_IO, "%s", message);
}

/* Lowers a limit to soft and hard, never above the limits this process inherited (ulimit). */
static void limit(int resource, rlim_t soft, rlim_t hard)
{
    struct rlimit now;
    if (getrlimit(resource, &now) == 0) {
        hard = hard < now.rlim_max ? hard : now.rlim_max;
        soft = soft < hard ? soft : hard;
    }
    struct rlimit r = {soft, hard};
    setrlimit(resource, &r);
}

/* GENERIC_DECODE_FAULT=by-name, for the tests of the isolation (tests/test_gtrace_mesh_isolation.c, the fuzz
 * generator's fault-* families), as for images (lib/image/decoder/generic_decode.c): a file whose name holds
 * fault-crash., fault-spin. or fault-grow. crashes, spins until its CPU time ends (a limit of 1 s), or allocates and
 * touches memory until its address space ends. */
static void fault(const char *path)
{
    const char *f = getenv("GENERIC_DECODE_FAULT"), *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (!f || strcmp(f, "by-name") != 0)
        return;
    if (strstr(base, "fault-crash.")) {
        volatile int *nowhere = NULL;
        *nowhere = 1;
    } else if (strstr(base, "fault-spin.")) {
        limit(RLIMIT_CPU, 1, RLIM_INFINITY);
        for (volatile unsigned long i = 0;; i++)
            ;
    } else if (strstr(base, "fault-grow.")) {
        for (;;) {
            char *p = malloc(64u << 20);
            if (!p)
                abort(); /* what assimp does when an allocation fails: std::bad_alloc */
            memset(p, 1, 64u << 20);
        }
    }
}

static int send_mesh(const Mesh *m)
{
    MeshMessage r = {.magic = MESH_PROTOCOL_MAGIC, .kind = MESH_MSG_RESULT, .status = G_OK, .nverts = m->nverts,
                     .ntris = m->ntris, .nuvs = m->nuvs, .nnormals = m->nnormals};
    const size_t nv = (size_t)m->nverts, nt = (size_t)m->ntris;
    return send_message(&r, "") != 0 || gfile_write_exact(1, m->pos, nv * 3 * sizeof *m->pos) != 0 ||
           gfile_write_exact(1, m->normal, (size_t)m->nnormals * 3 * sizeof *m->normal) != 0 ||
           gfile_write_exact(1, m->uv, (size_t)m->nuvs * 2 * sizeof *m->uv) != 0 ||
           gfile_write_exact(1, m->tri, nt * 3 * sizeof *m->tri) != 0 ||
           gfile_write_exact(1, m->tri_uv, nt * 3 * sizeof *m->tri_uv) != 0 ||
           gfile_write_exact(1, m->tri_normal, nt * 3 * sizeof *m->tri_normal) != 0 ||
           gfile_write_exact(1, m->tri_surface, nt * sizeof *m->tri_surface) != 0
               ? -1
               : 0;
}

static int send_error(const GError *err)
{
    MeshMessage r = {.magic = MESH_PROTOCOL_MAGIC, .kind = MESH_MSG_RESULT, .line = err->line, .col = err->col};
    r.status = err->code < 0 ? err->code : G_ERR_IO;
    size_t len = strnlen(err->message, sizeof err->message);
    r.text_length = (uint32_t)(len < MESH_TEXT_MAX ? len : MESH_TEXT_MAX);
    memcpy(r.param, err->param, sizeof r.param);
    r.param[sizeof r.param - 1] = 0;
    return send_message(&r, err->message);
}

int main(int argc, char **argv)
{
    if (argc != 9 || isatty(0)) {
        fprintf(stderr, "%s is gtrace's mesh reader process; it is not run by hand\n", MESH_READER_PROGRAM);
        return 2;
    }
    if (strtol(argv[1], NULL, 10) != MESH_PROTOCOL_VERSION)
        return MESH_EXIT_VERSION;
    const int format = (int)strtol(argv[2], NULL, 10);
    const char *path = argv[3];
    const unsigned long long budget = strtoull(argv[4], NULL, 10), used = strtoull(argv[5], NULL, 10);
    const unsigned long long address_space = strtoull(argv[6], NULL, 10), cpu = strtoull(argv[7], NULL, 10);
    const int asks = strcmp(argv[8], "1") == 0;
    if (format != MESH_FORMAT_PLY && format != MESH_FORMAT_STL && format != MESH_FORMAT_GLTF)
        return 2;
    /* assimp loaded before the limits: the dynamic loader opens and maps its files (and writes LD_DEBUG_OUTPUT's) */
    GError err = {0};
    if (!mesh_assimp_lib(&err))
        return send_error(&err) != 0;
    limit(RLIMIT_CORE, 0, 0);
    limit(RLIMIT_FSIZE, 0, 0); /* no file written */
    limit(RLIMIT_CPU, (rlim_t)cpu, RLIM_INFINITY);
#if !defined(__SANITIZE_ADDRESS__) /* the sanitizers' shadow memory needs terabytes of address space */
    limit(RLIMIT_AS, (rlim_t)address_space, (rlim_t)address_space);
#else
    (void)address_space;
#endif
    /* gtrace's budget as it stands: what it has reserved, reserved here too, so refusals give its figures */
    gmem_budget_set_limit((size_t)budget);
    if (used && gmem_budget_reserve((size_t)used, "what gtrace holds", &err) != G_OK)
        return send_error(&err) != 0;
    fault(path);
    Object o;
    memset(&o, 0, sizeof o);
    MeshFiles files = {ask, NULL};
    int rc = mesh_load_assimp(&o, path, MESH_READER_FD, (MeshFormat)format, asks ? &files : NULL, &err);
    if (rc != G_OK)
        return send_error(&err) != 0;
    rc = send_mesh(o.mesh);
    mesh_free(o.mesh);
    return rc != 0;
}
