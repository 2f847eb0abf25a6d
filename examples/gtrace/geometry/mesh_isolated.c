/* mesh_isolated.c - PLY, STL and glTF files read by assimp in a process of its own, gtrace-mesh (mesh_protocol.h),
 * so that a crash, a hang or a memory blow-up of assimp is an error for that file and never takes gtrace down.
 *
 * One reader is started per mesh file with posix_spawn (no fork of this process and its threads), the file's
 * descriptor as its descriptor 3 and a socket pair as its standard input and output. It runs mesh_load_assimp
 * (the same checks and the same IO hooks as in this process) under limits it sets itself: an address space of
 * MESH_READER_BASE_MB MiB plus twice the room left in the memory budget, MESH_READER_CPU_SECONDS seconds of CPU time
 * plus one per 8 MiB of file, no core file, no file written. Before it opens any other file (a glTF's buffer file)
 * it asks here, and the caller's MeshFiles rule (--confine) answers: this process's rule stays the authority. The
 * mesh comes back as its arrays; their counts are bounded and reserved against the memory budget before anything
 * is allocated, and every index and position is checked again. A reader that does not answer within
 * MESH_READER_WALL_FACTOR times its CPU time (asleep, blocked) is killed; every reader is reaped.
 *
 * The file's content checks (mesh_assimp_check) run here first, so that a file they refuse starts no reader; the
 * reader runs them again on its own reading of the file, before assimp.
 *
 * The reader is found as $GTRACE_MESH_READER (a path; then nowhere else), else in DIR/, DIR/generic/ and
 * DIR/../lib/generic/ for the object holding this code (gtrace, libgtrace.so) and for the program, else in the
 * installed GTRACE_MESH_LIBDIR/generic/. GENERIC_DECODE=inprocess reads in this process (trusted files). */
#include "mesh_format.h"
#include "mesh_protocol.h"

#include <generic/memory.h>
#include <generic/services/file.h>
#include <generic/services/spawn.h>

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef GTRACE_MESH_LIBDIR
#define GTRACE_MESH_LIBDIR "/usr/local/lib"
#endif

/** The reader's address space beyond what it reads: the program, assimp and their libraries. */
#define MESH_READER_BASE_MB 1024
/** The reader's CPU time beyond one second per 8 MiB of file. */
#define MESH_READER_CPU_SECONDS 30
/** The wall-clock time a reader may take, in multiples of its CPU time. */
#define MESH_READER_WALL_FACTOR 4
/** The most questions a reader may ask (mesh_gltf_check and the IO hooks each ask once per buffer file). */
#define MESH_READER_MAX_ASKS (4 * MESH_MAX_FILES)

extern char **environ;

_Static_assert(sizeof(unsigned) == sizeof(uint32_t) && sizeof(int) == sizeof(int32_t), "the protocol's arrays");

/* ---- finding the reader ---- */

static pthread_once_t find_once = PTHREAD_ONCE_INIT;
static char reader[PATH_MAX];

static void find(void)
{
    gspawn_find(MESH_READER_PROGRAM, "GTRACE_MESH_READER", (const void *)&mesh_load_isolated, GTRACE_MESH_LIBDIR,
                reader);
}

/* ---- talking to the reader ---- */

typedef struct Reader {
    const char *path;
    pid_t pid;
    int sock;
    struct timespec deadline;
    unsigned long cpu;
    unsigned long long address_space;
    int late; /* the deadline passed */
} Reader;

static long long ms_left(const struct timespec *deadline)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (long long)(deadline->tv_sec - now.tv_sec) * 1000 + (deadline->tv_nsec - now.tv_nsec) / 1000000;
}

/* Reads exactly n bytes before the deadline: 0, or -1 (the reader ended, or R->late). */
static int recv_exact(Reader *R, void *buf, size_t n)
{
    char *p = buf;
    while (n > 0) {
        long long left = ms_left(&R->deadline);
        if (left <= 0) {
            R->late = 1;
            return -1;
        }
        struct pollfd pfd = {R->sock, POLLIN, 0};
        int ready = poll(&pfd, 1, left > INT_MAX ? INT_MAX : (int)left);
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready < 0)
            return -1;
        if (ready == 0)
            continue;
        ssize_t got = recv(R->sock, p, n, 0);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return -1;
        p += got;
        n -= (size_t)got;
    }
    return 0;
}

/* Waits for the reader to end, until its deadline; then kills it (R->late). */
static void reap(Reader *R, int *status)
{
    long pause_ns = 20000;
    for (;;) {
        pid_t w = waitpid(R->pid, status, WNOHANG);
        if (w == R->pid || (w < 0 && errno != EINTR))
            return;
        if (w == 0 && ms_left(&R->deadline) <= 0) {
            R->late = 1;
            break;
        }
        struct timespec pause = {0, pause_ns};
        nanosleep(&pause, NULL);
        pause_ns = pause_ns < 10000000 ? 2 * pause_ns : pause_ns;
    }
    kill(R->pid, SIGKILL);
    while (waitpid(R->pid, status, 0) < 0 && errno == EINTR)
        ;
}

/* Ends the reader and reaps it: killed when kill_it (it answered, or must stop), else waited for until its
 * deadline. When why_err is given (the reader gave no answer), says how it ended in it. Returns rc, or G_ERR_IO
 * when it sets why_err. */
static int finish(Reader *R, int kill_it, int rc, GError *why_err)
{
    if (R->sock >= 0)
        close(R->sock);
    R->sock = -1;
    int status = 0;
    if (kill_it || R->late) {
        kill(R->pid, SIGKILL);
        while (waitpid(R->pid, &status, 0) < 0 && errno == EINTR)
            ;
    } else {
        reap(R, &status);
    }
    if (!why_err)
        return rc;
    const char *path = R->path;
    if (R->late)
        return gerror_set(why_err, G_ERR_IO, "%s: cannot read mesh: its reader %s gave no answer within %lu s",
                          path, MESH_READER_PROGRAM, R->cpu * MESH_READER_WALL_FACTOR);
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return gerror_set(why_err, G_ERR_IO, "%s: cannot read mesh: its reader %s took more than its %lu s of CPU "
                          "time", path, MESH_READER_PROGRAM, R->cpu);
    if (WIFSIGNALED(status))
        return gerror_set(why_err, G_ERR_IO, "%s: cannot read mesh: its reader %s crashed (%s) within its limits of "
                          "%.0f MiB of address space and %lu s of CPU time", path, MESH_READER_PROGRAM,
                          strsignal(WTERMSIG(status)), (double)R->address_space / 1048576.0, R->cpu);
    if (WIFEXITED(status) && WEXITSTATUS(status) == MESH_EXIT_VERSION)
        return gerror_set(why_err, G_ERR_IO, "%s: cannot read mesh: its reader %s speaks another version of the "
                          "protocol than gtrace's %d (a reader from another installation?)", path,
                          MESH_READER_PROGRAM, MESH_PROTOCOL_VERSION);
    return gerror_set(why_err, G_ERR_IO, "%s: cannot read mesh: its reader %s ended (exit status %d) without an "
                      "answer", path, MESH_READER_PROGRAM, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

static int broken(Reader *R, GError *err)
{
    return finish(R, 1, gerror_set(err, G_ERR_IO, "%s: cannot read mesh: its reader %s broke the protocol",
                                   R->path, MESH_READER_PROGRAM), NULL);
}

/* Answers one question of the reader: may it open the file named (text, len bytes)? */
static int answer(Reader *R, const char *text, const MeshFiles *files)
{
    GError refusal = {0};
    int rc = files && files->allowed ? files->allowed(files->ctx, text, &refusal) : G_OK;
    size_t mlen = rc == G_OK ? 0 : strnlen(refusal.message, sizeof refusal.message);
    MeshAnswer a = {MESH_PROTOCOL_MAGIC, rc == G_OK ? G_OK : (rc < 0 ? rc : G_ERR_IO), (uint32_t)mlen};
    if (gfile_send_exact(R->sock, &a, sizeof a) != 0 || gfile_send_exact(R->sock, refusal.message, mlen) != 0)
        return -1;
    return 0;
}

/* The reader's error, as it set it: the code (one of the library's), the position, the parameter, the text. */
static int reported(const MeshMessage *m, const char *text, GError *err)
{
    int code = m->status < 0 && m->status >= G_ERR_UNSUPPORTED ? m->status : G_ERR_IO;
    gerror_set(err, code, "%s", text);
    if (err) {
        err->line = m->line > 0 ? m->line : 0;
        err->col = m->col > 0 ? m->col : 0;
        memcpy(err->param, m->param, sizeof err->param);
        err->param[sizeof err->param - 1] = 0;
    }
    return code;
}

static int finite_positions(const double *a, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!(a[i] >= -1e30 && a[i] <= 1e30))
            return 0;
    return 1;
}

static int indices_in(const int *a, size_t n, int lowest, int count)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] < lowest || a[i] >= count)
            return 0;
    return 1;
}

/* Checks the counts of a RESULT, reserves the mesh against the memory budget, allocates it and reads its arrays. */
static int receive_mesh(Reader *R, const MeshMessage *h, Mesh **out, GError *err)
{
    const char *path = R->path;
    if (h->nverts < 1 || h->nverts > MESH_MAX_COUNT || h->ntris < 1 || h->ntris > MESH_MAX_COUNT ||
        h->nuvs < 0 || h->nuvs > h->nverts || h->nnormals < 0 || h->nnormals > h->nverts)
        return broken(R, err);
    size_t nv = (size_t)h->nverts, nt = (size_t)h->ntris, bytes = mesh_budget_bytes(nv, nt);
    char what[96];
    GError refusal;
    snprintf(what, sizeof what, "a mesh of %zu vertices and %zu triangles", nv, nt);
    if (gmem_budget_reserve(bytes, what, &refusal) != G_OK)
        return finish(R, 1, gerror_set(err, G_ERR_NOMEM, "%s: %s", path, refusal.message), NULL);
    Mesh *m = gmem_calloc(1, sizeof *m);
    if (!m) {
        gmem_budget_release(bytes);
        return finish(R, 1, gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path), NULL);
    }
    m->budget = bytes;
    m->nverts = h->nverts, m->ntris = h->ntris, m->nuvs = h->nuvs, m->nnormals = h->nnormals;
    const size_t nn = (size_t)h->nnormals, nu = (size_t)h->nuvs;
    m->pos = gmem_alloc(nv * 3 * sizeof *m->pos);
    m->normal = gmem_alloc((nn ? nn : 1) * 3 * sizeof *m->normal);
    m->uv = gmem_alloc((nu ? nu : 1) * 2 * sizeof *m->uv);
    m->tri = gmem_alloc(nt * 3 * sizeof *m->tri);
    m->tri_uv = gmem_alloc(nt * 3 * sizeof *m->tri_uv);
    m->tri_normal = gmem_alloc(nt * 3 * sizeof *m->tri_normal);
    m->tri_surface = gmem_alloc(nt * sizeof *m->tri_surface);
    if (!m->pos || !m->normal || !m->uv || !m->tri || !m->tri_uv || !m->tri_normal || !m->tri_surface) {
        mesh_free(m);
        return finish(R, 1, gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path), NULL);
    }
    if (recv_exact(R, m->pos, nv * 3 * sizeof *m->pos) != 0 ||
        recv_exact(R, m->normal, nn * 3 * sizeof *m->normal) != 0 ||
        recv_exact(R, m->uv, nu * 2 * sizeof *m->uv) != 0 || recv_exact(R, m->tri, nt * 3 * sizeof *m->tri) != 0 ||
        recv_exact(R, m->tri_uv, nt * 3 * sizeof *m->tri_uv) != 0 ||
        recv_exact(R, m->tri_normal, nt * 3 * sizeof *m->tri_normal) != 0 ||
        recv_exact(R, m->tri_surface, nt * sizeof *m->tri_surface) != 0) {
        mesh_free(m);
        return finish(R, 0, G_OK, err);
    }
    /* what mesh_load_assimp guarantees in this process: finite positions, indices within their arrays (normals
     * and (u,v) are taken as assimp gives them, as there) */
    int ok = finite_positions(m->pos, nv * 3) && indices_in(m->tri_uv, nt * 3, -1, (int)nu) &&
             indices_in(m->tri_normal, nt * 3, -1, (int)nn) && indices_in(m->tri_surface, nt, 0, INT_MAX);
    for (size_t i = 0; ok && i < nt * 3; i++)
        ok = m->tri[i] < (unsigned)nv;
    if (!ok) {
        mesh_free(m);
        return broken(R, err);
    }
    *out = m;
    return finish(R, 1, G_OK, NULL); /* it answered: whatever it does after is of no use */
}

/* Serves the reader's questions until its RESULT, and takes the result. */
static int converse(Reader *R, const MeshFiles *files, Mesh **out, GError *err)
{
    char *text = gmem_alloc(MESH_TEXT_MAX + 1);
    if (!text)
        return finish(R, 1, gerror_set(err, G_ERR_NOMEM, "%s: out of memory", R->path), NULL);
    int rc = G_OK;
    for (int asks = 0;; asks++) {
        MeshMessage m;
        if (recv_exact(R, &m, sizeof m) != 0) {
            rc = finish(R, 0, G_OK, err);
            break;
        }
        if (m.magic != MESH_PROTOCOL_MAGIC || m.text_length > MESH_TEXT_MAX ||
            (m.kind != MESH_MSG_ASK && m.kind != MESH_MSG_RESULT) ||
            (m.kind == MESH_MSG_ASK && asks >= MESH_READER_MAX_ASKS)) {
            rc = broken(R, err);
            break;
        }
        if (recv_exact(R, text, m.text_length) != 0) {
            rc = finish(R, 0, G_OK, err);
            break;
        }
        text[m.text_length] = 0;
        if (m.kind == MESH_MSG_ASK) {
            if (strlen(text) != m.text_length || answer(R, text, files) != 0) {
                rc = broken(R, err);
                break;
            }
            continue;
        }
        rc = m.status == G_OK ? receive_mesh(R, &m, out, err) : finish(R, 1, reported(&m, text, err), NULL);
        break;
    }
    gmem_free(text);
    return rc;
}

int mesh_load_isolated(Object *o, const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err)
{
    struct stat st;
    if (fstat(fd, &st) != 0) {
        close(fd);
        return gerror_set(err, G_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    }
    int rc = mesh_assimp_check(path, fd, format, files, err); /* a file the checks refuse starts no reader */
    if (rc != G_OK) {
        close(fd);
        return rc;
    }
    pthread_once(&find_once, find);
    if (!reader[0]) {
        close(fd);
        return gerror_set(err, G_ERR_IO, "%s: cannot read mesh: its reader %s is not found (looked beside gtrace, "
                          "in generic/ and ../lib/generic/ there, and in " GTRACE_MESH_LIBDIR "/generic/; "
                          "GTRACE_MESH_READER may name it, GENERIC_DECODE=inprocess reads trusted files without it)",
                          path, MESH_READER_PROGRAM);
    }
    const size_t limit = gmem_budget_limit(), used = gmem_budget_used(), room = limit > used ? limit - used : 0;
    Reader R = {.path = path, .sock = -1};
    R.cpu = MESH_READER_CPU_SECONDS + (unsigned long)(st.st_size >> 23);
    R.address_space = ((unsigned long long)MESH_READER_BASE_MB << 20) + 2ull * room;
    clock_gettime(CLOCK_MONOTONIC, &R.deadline);
    R.deadline.tv_sec += (time_t)(R.cpu * MESH_READER_WALL_FACTOR);
    char version[16], fmt[16], limit_text[32], used_text[32], as_text[32], cpu_text[32];
    snprintf(version, sizeof version, "%d", MESH_PROTOCOL_VERSION);
    snprintf(fmt, sizeof fmt, "%d", (int)format);
    snprintf(limit_text, sizeof limit_text, "%zu", limit);
    snprintf(used_text, sizeof used_text, "%zu", used);
    snprintf(as_text, sizeof as_text, "%llu", R.address_space);
    snprintf(cpu_text, sizeof cpu_text, "%lu", R.cpu);
    char *const argv[] = {(char *)MESH_READER_PROGRAM, version, fmt, (char *)path, limit_text, used_text, as_text,
                          cpu_text, (char *)(files && files->allowed ? "1" : "0"), NULL};
    if (fd < MESH_READER_FD) { /* above the standard descriptors the reader's socket takes */
        int moved = fcntl(fd, F_DUPFD_CLOEXEC, MESH_READER_FD);
        close(fd);
        if (moved < 0)
            return gerror_set(err, G_ERR_IO, "%s: cannot start the mesh reader: %s", path, strerror(errno));
        fd = moved;
    }
    int sv[2];
    if (gspawn_socketpair(sv, MESH_READER_FD) != 0) {
        int e = errno;
        close(fd);
        return gerror_set(err, G_ERR_IO, "%s: cannot start the mesh reader: %s", path, strerror(e));
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 0);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 1);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, fd, MESH_READER_FD);
    posix_spawn_file_actions_addclosefrom_np(&fa, MESH_READER_FD + 1); /* none of this process's other files */
    rc = posix_spawn(&R.pid, reader, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(sv[1]);
    close(fd);
    if (rc != 0) {
        close(sv[0]);
        return gerror_set(err, G_ERR_IO, "%s: cannot start the mesh reader %s: %s", path, reader, strerror(rc));
    }
    R.sock = sv[0];
    Mesh *m = NULL;
    rc = converse(&R, files, &m, err);
    if (rc == G_OK) {
        mesh_free(o->mesh);
        o->mesh = m;
    }
    return rc;
}
