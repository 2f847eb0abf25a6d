/* mesh_assimp_io.h - the files assimp opens while it reads a mesh, through assimp's IO hooks (mesh_assimp_io.c). */
#ifndef GTRACE_MESH_ASSIMP_IO_H
#define GTRACE_MESH_ASSIMP_IO_H

#include "object.h"

#include <assimp/cfileio.h>

#include <stddef.h>

/** assimp's file system for one mesh: the name assimp is given is served from the bytes that were checked; any
 * other file (a glTF's buffer file) is opened read-only as the library opens inputs: allowed by files (--confine),
 * a regular file (never a FIFO or a device, gfile_open_input), at most MESH_MAX_FILE_BYTES, at most MESH_MAX_FILES
 * opens. Writing is refused. hooks is handed to aiImportFileEx; refusal keeps the first refusal's message. */
typedef struct MeshIO {
    struct aiFileIO hooks;
    const char *name;
    const char *data;
    size_t size;
    const MeshFiles *files;
    int opens;
    GError refusal; /**< code 0 while nothing was refused */
} MeshIO;

/** Sets io up to serve name from data (size bytes, borrowed) and other files by files' rules (NULL: any path). */
void mesh_io_init(MeshIO *io, const char *name, const char *data, size_t size, const MeshFiles *files);

#endif
