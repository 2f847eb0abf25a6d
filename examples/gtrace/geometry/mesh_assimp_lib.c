/* mesh_assimp_lib.c - assimp's C API loaded on first use (mesh_assimp_lib.h): gdynlib_open of the library by its
 * soname (GTRACE_ASSIMP_SONAME, the build's libassimp.so's; examples/gtrace/build.mk), once per process. */
#include "mesh_assimp_lib.h"

#include <generic/services/dynlib.h>

#ifndef GTRACE_ASSIMP_SONAME
#define GTRACE_ASSIMP_SONAME "libassimp.so.5"
#endif

static MeshAssimpLib lib;

static const GDynLibSymbol symbols[] = {
    {"aiImportFileEx", &lib.import_file_ex},
    {"aiImportFileFromMemory", &lib.import_file_from_memory},
    {"aiReleaseImport", &lib.release_import},
    {"aiGetErrorString", &lib.get_error_string},
    {"aiIsExtensionSupported", &lib.is_extension_supported},
};

static GDynLib assimp = GDYNLIB_INIT(GTRACE_ASSIMP_SONAME, symbols, sizeof symbols / sizeof symbols[0]);

const MeshAssimpLib *mesh_assimp_lib(GError *err)
{
    if (gdynlib_open(&assimp))
        return &lib;
    gerror_set(err, G_ERR_UNSUPPORTED, "meshes of PLY, STL and glTF need assimp (%s), which cannot be loaded: %s",
               GTRACE_ASSIMP_SONAME, assimp.why);
    return NULL;
}
