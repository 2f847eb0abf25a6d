/* mesh_assimp_lib.c - assimp's C API loaded on first use (mesh_assimp_lib.h): dlopen of the library by its
 * soname (GTRACE_ASSIMP_SONAME, the build's libassimp.so's; examples/gtrace/build.mk), once per process. */
#include "mesh_assimp_lib.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#ifndef GTRACE_ASSIMP_SONAME
#define GTRACE_ASSIMP_SONAME "libassimp.so.5"
#endif

static MeshAssimpLib lib;
static int loaded;
static char why[256];
static pthread_once_t once = PTHREAD_ONCE_INIT;

/* Sets *slot (size bytes: a function pointer) to the library h's symbol name: 1; 0 when h lacks it (why says so). */
static int find(void *h, const char *name, void *slot, size_t size)
{
    void *f = dlsym(h, name);
    if (!f) {
        snprintf(why, sizeof why, "it has no %s", name);
        return 0;
    }
    memcpy(slot, &f, size); /* a function pointer from dlsym's object pointer (POSIX guarantees they convert) */
    return 1;
}

static void load(void)
{
    void *h = dlopen(GTRACE_ASSIMP_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        snprintf(why, sizeof why, "%s", e ? e : "not found");
        return;
    }
    MeshAssimpLib l;
    loaded = find(h, "aiImportFileEx", &l.import_file_ex, sizeof l.import_file_ex) &&
             find(h, "aiImportFileFromMemory", &l.import_file_from_memory, sizeof l.import_file_from_memory) &&
             find(h, "aiReleaseImport", &l.release_import, sizeof l.release_import) &&
             find(h, "aiGetErrorString", &l.get_error_string, sizeof l.get_error_string) &&
             find(h, "aiIsExtensionSupported", &l.is_extension_supported, sizeof l.is_extension_supported);
    if (loaded)
        lib = l;
    else
        dlclose(h);
}

const MeshAssimpLib *mesh_assimp_lib(GError *err)
{
    pthread_once(&once, load);
    if (loaded)
        return &lib;
    gerror_set(err, G_ERR_UNSUPPORTED, "meshes of PLY, STL and glTF need assimp (%s), which cannot be loaded: %s",
               GTRACE_ASSIMP_SONAME, why);
    return NULL;
}
