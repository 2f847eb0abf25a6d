/* grid_load.c - a grid medium's density from an OpenVDB file, read by gtrace-vdb in a process of its own
 * (grid_load.h). OpenVDB is a C++ library that is not hardened against hostile files; gtrace never loads it: the
 * reader is started with posix_spawn (no fork of this process and its threads) with the file, the grid's name and
 * its bounds as arguments, writes its answer on a pipe (vdb/vdb_protocol.h) and ends. It sets its own limits: CPU
 * time, address space (GRID_READER_BASE_MB plus three times the largest copy allowed), no core file. Whatever it
 * answers is checked again here before it is used.
 *
 * The reader is found as $GTRACE_VDB_READER (a path; then nowhere else), else beside the program: DIR/,
 * DIR/generic/ and DIR/../lib/generic/ (the build tree's build/lib/generic/ for build/bin/ and build/tests/). */
#include "grid_load.h"
#include "vdb_protocol.h"

#include <generic/memory.h>
#include <generic/services/file.h>
#include <generic/services/spawn.h>

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/** The reader's address space beyond its copy: the program, OpenVDB, TBB and their libraries. */
#define GRID_READER_BASE_MB 512

extern char **environ;

/* Waits for the reader; when it ended abnormally and rc is an error already set, says how it ended instead. */
static int finish(pid_t pid, int fd, int rc, int answered, const char *path, GError *err)
{
    if (fd >= 0)
        close(fd);
    if (rc != G_OK && answered) /* a refusal or a check of ours: the reader need not finish its output */
        kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (answered || rc != G_OK)
        return rc;
    if (WIFSIGNALED(status))
        return gerror_set(err, G_ERR_IO, "%s: the OpenVDB reader ended on signal %d (%s) without an answer: a file "
                          "it cannot read, or its limits of time and memory", path, WTERMSIG(status),
                          strsignal(WTERMSIG(status)));
    return gerror_set(err, G_ERR_IO, "%s: the OpenVDB reader ended (status %d) without an answer", path,
                      WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

/* Checks the reply's header: G_OK or G_ERR_IO naming the bound. */
static int check_reply(const VdbReply *h, long long max_voxels, const char *path, const char *name, GError *err)
{
    long long n = 1;
    for (int a = 0; a < 3; a++) {
        if (h->dims[a] < 1 || (long long)h->min[a] + h->dims[a] > INT_MAX)
            return gerror_set(err, G_ERR_IO, "%s: the reader answered an invalid extent for grid '%s'", path, name);
        n *= h->dims[a];
        if (n > max_voxels)
            return gerror_set(err, G_ERR_IO, "%s: grid '%s' of %dx%dx%d voxels exceeds the %lld voxels allowed", path,
                              name, h->dims[0], h->dims[1], h->dims[2], max_voxels);
    }
    for (int i = 0; i < 12; i++)
        if (!isfinite(h->index_to_world[i]))
            return gerror_set(err, G_ERR_IO, "%s: grid '%s' has a transform that is not finite", path, name);
    return G_OK;
}

/* Reads the reply and the copy from fd into g. answered: set once the reader gave a whole header. */
static int receive(int fd, long long max_voxels, const char *path, const char *name, Grid *g, int *answered,
                   GError *err)
{
    VdbReply h;
    if (gfile_read_exact(fd, &h, sizeof h) != 0)
        return G_OK; /* no answer: finish() says how the reader ended */
    *answered = 1;
    if (h.magic != VDB_REPLY_MAGIC)
        return gerror_set(err, G_ERR_IO, "%s: the OpenVDB reader answered something else than its protocol", path);
    if (h.status != 0) {
        h.message[sizeof h.message - 1] = 0;
        return gerror_set(err, G_ERR_IO, "%s: %s", path, h.message);
    }
    int rc = check_reply(&h, max_voxels, path, name, err);
    if (rc != G_OK)
        return rc;
    const double rows[3][4] = {{h.index_to_world[0], h.index_to_world[1], h.index_to_world[2], h.index_to_world[3]},
                               {h.index_to_world[4], h.index_to_world[5], h.index_to_world[6], h.index_to_world[7]},
                               {h.index_to_world[8], h.index_to_world[9], h.index_to_world[10], h.index_to_world[11]}};
    xform_identity(&g->place);
    /* voxel (0, 0, 0) of the copy is index min of the file */
    if (xform_translate(&g->place, gvec3(h.min[0], h.min[1], h.min[2])) != G_OK ||
        xform_matrix(&g->place, rows) != G_OK)
        return gerror_set(err, G_ERR_IO, "%s: grid '%s' has a singular transform", path, name);
    size_t count = (size_t)h.dims[0] * (size_t)h.dims[1] * (size_t)h.dims[2];
    char what[600];
    snprintf(what, sizeof what, "%s: grid '%s' of %dx%dx%d voxels", path, name, h.dims[0], h.dims[1], h.dims[2]);
    if ((rc = gmem_budget_reserve(count * sizeof(float), what, err)) != G_OK)
        return rc;
    g->charged = count * sizeof(float);
    g->density = gmem_alloc(count * sizeof(float));
    if (!g->density)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for grid '%s'", path, name);
    for (int a = 0; a < 3; a++) {
        g->n[a] = h.dims[a];
        g->min[a] = h.min[a];
    }
    g->active_voxels = h.active_voxels;
    if (gfile_read_exact(fd, g->density, count * sizeof(float)) != 0)
        return gerror_set(err, G_ERR_IO, "%s: the OpenVDB reader ended before the whole of grid '%s'", path, name);
    for (size_t i = 0; i < count; i++)
        if (!(g->density[i] >= 0.0f && isfinite(g->density[i])))
            return gerror_set(err, G_ERR_IO, "%s: grid '%s' has a density %g at voxel %zu: densities must be "
                              "finite and >= 0", path, name, g->density[i], i);
    return grid_build_bricks(g, path, err);
}

int grid_load(const char *path, const char *name, Grid *g, GError *err)
{
    *g = (Grid){0};
    struct stat st;
    if (stat(path, &st) != 0)
        return gerror_set(err, G_ERR_IO, "%s: %s", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return gerror_set(err, G_ERR_IO, "%s: not a regular file", path);
    char reader[PATH_MAX];
    if (!gspawn_find(VDB_READER_PROGRAM, "GTRACE_VDB_READER", (const void *)&grid_load, NULL, reader))
        return gerror_set(err, G_ERR_IO, "%s: grid media need the OpenVDB reader %s, which is not found (looked beside "
                          "the program, in generic/ and ../lib/generic/ there; GTRACE_VDB_READER may name it)", path,
                          VDB_READER_PROGRAM);
    size_t limit = gmem_budget_limit(), used = gmem_budget_used();
    long long max_voxels = (long long)((limit > used ? limit - used : 0) / sizeof(float));
    max_voxels = max_voxels < GRID_MAX_VOXELS ? max_voxels : GRID_MAX_VOXELS;
    char voxels_text[32], bytes_text[32];
    snprintf(voxels_text, sizeof voxels_text, "%lld", max_voxels);
    snprintf(bytes_text, sizeof bytes_text, "%llu",
             ((unsigned long long)GRID_READER_BASE_MB << 20) + 3ull * (unsigned long long)max_voxels * sizeof(float));
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot start the OpenVDB reader: %s", path, strerror(errno));
    char *const argv[] = {(char *)VDB_READER_PROGRAM, (char *)path, (char *)name, voxels_text, bytes_text, NULL};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, fds[1], 1);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclosefrom_np(&fa, 3); /* none of this process's other files */
    pid_t pid;
    int rc = posix_spawn(&pid, reader, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fds[1]);
    if (rc != 0) {
        close(fds[0]);
        return gerror_set(err, G_ERR_IO, "%s: cannot start the OpenVDB reader %s: %s", path, reader, strerror(rc));
    }
    int answered = 0;
    rc = receive(fds[0], max_voxels, path, name, g, &answered, err);
    rc = finish(pid, fds[0], rc, answered, path, err);
    if (rc != G_OK)
        grid_release(g);
    return rc;
}
