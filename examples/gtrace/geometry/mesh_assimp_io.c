/* mesh_assimp_io.c - assimp's file system for a mesh (aiFileIO, assimp's C IO hooks): the mesh from memory, the
 * files it names by the library's rules, so that a buffer file that is a FIFO, a device or a link out of the
 * confined folder is refused as any input of a scene is, and assimp never opens a path on its own. */
#include "mesh_assimp_io.h"
#include "mesh_format.h"

#include <generic/memory.h>
#include <generic/services/file.h>

#include <errno.h>
#include <string.h>
#include <unistd.h>

/* One open file: bytes in memory (data) or a descriptor (fd >= 0), read from pos. */
typedef struct MeshIOFile {
    struct aiFile file;
    const char *data;
    int fd;
    size_t size, pos;
} MeshIOFile;

static MeshIOFile *io_file(struct aiFile *f) { return (MeshIOFile *)(void *)f->UserData; }

static size_t io_read(struct aiFile *f, char *buf, size_t size, size_t count)
{
    MeshIOFile *F = io_file(f);
    if (size == 0 || count == 0 || F->pos >= F->size)
        return 0;
    size_t want = count > (F->size - F->pos) / size ? (F->size - F->pos) / size * size : size * count, got = 0;
    if (F->data) {
        memcpy(buf, F->data + F->pos, want);
        got = want;
    } else {
        while (got < want) {
            ssize_t r = pread(F->fd, buf + got, want - got, (off_t)(F->pos + got));
            if (r < 0 && errno == EINTR)
                continue;
            if (r <= 0)
                break;
            got += (size_t)r;
        }
    }
    F->pos += got;
    return got / size;
}

static size_t io_write(struct aiFile *f, const char *buf, size_t size, size_t count)
{
    (void)f, (void)buf, (void)size, (void)count;
    return 0;
}

static size_t io_tell(struct aiFile *f) { return io_file(f)->pos; }
static size_t io_size(struct aiFile *f) { return io_file(f)->size; }
static void io_flush(struct aiFile *f) { (void)f; }

static enum aiReturn io_seek(struct aiFile *f, size_t offset, enum aiOrigin origin)
{
    MeshIOFile *F = io_file(f);
    size_t base = origin == aiOrigin_SET ? 0 : origin == aiOrigin_CUR ? F->pos : F->size;
    if (origin != aiOrigin_SET && origin != aiOrigin_CUR && origin != aiOrigin_END)
        return aiReturn_FAILURE;
    if (offset > F->size - base && !(origin == aiOrigin_END && offset == 0))
        return aiReturn_FAILURE;
    F->pos = base + offset;
    return aiReturn_SUCCESS;
}

/* Keeps the first refusal's message (assimp replaces it by its own, which does not say why). */
static void io_refuse(MeshIO *io, const GError *e)
{
    if (io->refusal.code == 0)
        io->refusal = *e;
}

static struct aiFile *io_open(struct aiFileIO *hooks, const char *name, const char *mode)
{
    MeshIO *io = (MeshIO *)(void *)hooks;
    GError e = {0};
    if (!name || !mode || strpbrk(mode, "wa+")) {
        gerror_set(&e, G_ERR_INVALID, "assimp asked to write \"%s\"", name ? name : "");
        io_refuse(io, &e);
        return NULL;
    }
    MeshIOFile *F = gmem_calloc(1, sizeof *F);
    if (!F)
        return NULL;
    F->fd = -1;
    if (strcmp(name, io->name) == 0) {
        F->data = io->data;
        F->size = io->size;
    } else {
        int rc = G_OK;
        off_t bytes = -1;
        if (++io->opens > MESH_MAX_FILES)
            rc = gerror_set(&e, G_ERR_INVALID, "\"%s\": more than %d files opened for one mesh", name, MESH_MAX_FILES);
        if (rc == G_OK && io->files && io->files->allowed)
            rc = io->files->allowed(io->files->ctx, name, &e);
        if (rc == G_OK && (F->fd = gfile_open_input(name, &e)) < 0)
            rc = F->fd;
        if (rc == G_OK && (bytes = lseek(F->fd, 0, SEEK_END)) < 0)
            rc = gerror_set(&e, G_ERR_IO, "cannot read \"%s\": %s", name, strerror(errno));
        if (rc == G_OK && (unsigned long long)bytes > MESH_MAX_FILE_BYTES)
            rc = gerror_set(&e, G_ERR_INVALID, "\"%s\" is larger than %llu bytes", name, MESH_MAX_FILE_BYTES);
        if (rc < 0) {
            if (F->fd >= 0)
                close(F->fd);
            gmem_free(F);
            io_refuse(io, &e);
            return NULL;
        }
        F->size = (size_t)bytes;
    }
    F->file = (struct aiFile){io_read, io_write, io_tell, io_size, io_seek, io_flush, (aiUserData)(void *)F};
    return &F->file;
}

static void io_close(struct aiFileIO *hooks, struct aiFile *f)
{
    (void)hooks;
    if (!f)
        return;
    MeshIOFile *F = io_file(f);
    if (F->fd >= 0)
        close(F->fd);
    gmem_free(F);
}

void mesh_io_init(MeshIO *io, const char *name, const char *data, size_t size, const MeshFiles *files)
{
    memset(io, 0, sizeof *io);
    io->hooks.OpenProc = io_open;
    io->hooks.CloseProc = io_close;
    io->name = name;
    io->data = data;
    io->size = size;
    io->files = files;
}
