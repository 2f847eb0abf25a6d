/* mesh_assimp_lib.h - the few functions of assimp's C API that gtrace calls (mesh_assimp.c), loaded with the
 * library on first use (mesh_assimp_lib.c), so that a process maps assimp and its dependencies (libdraco: about
 * 3 MiB of resident memory and 48,000 relocations at start) only when it reads a PLY, STL or glTF file itself. */
#ifndef GTRACE_MESH_ASSIMP_LIB_H
#define GTRACE_MESH_ASSIMP_LIB_H

#include <generic/error.h>

#include <assimp/cimport.h>

/** assimp's functions of the same names and types (assimp/cimport.h). */
typedef struct MeshAssimpLib {
    __typeof__(&aiImportFileEx) import_file_ex;
    __typeof__(&aiImportFileFromMemory) import_file_from_memory;
    __typeof__(&aiReleaseImport) release_import;
    __typeof__(&aiGetErrorString) get_error_string;
    __typeof__(&aiIsExtensionSupported) is_extension_supported;
} MeshAssimpLib;

/** The functions, from the library loaded once per process (thread-safe; never unloaded). NULL when it cannot be
 * loaded or lacks one of them, with err (may be NULL) set to G_ERR_UNSUPPORTED naming the library and why. */
const MeshAssimpLib *mesh_assimp_lib(GError *err);

#endif
