/* exr_core_lib.c - OpenEXRCore loaded on first use (exr_core_lib.h). */
#include "exr_core_lib.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#ifndef GENERIC_EXRCORE_SONAME
#define GENERIC_EXRCORE_SONAME "libOpenEXRCore-3_1.so.30"
#endif

static ExrCoreLib lib;
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

#define FIND(h, l, field) find(h, "exr_" #field, &(l).field, sizeof (l).field)

static void load(void)
{
    void *h = dlopen(GENERIC_EXRCORE_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        snprintf(why, sizeof why, "%s", e ? e : "not found");
        return;
    }
    ExrCoreLib l;
    loaded = FIND(h, l, start_write) && FIND(h, l, add_part) && FIND(h, l, initialize_required_attr) &&
             FIND(h, l, add_channel) && FIND(h, l, attr_set_string) && FIND(h, l, write_header) &&
             FIND(h, l, get_scanlines_per_chunk) && FIND(h, l, write_scanline_chunk_info) &&
             FIND(h, l, encoding_initialize) && FIND(h, l, encoding_update) &&
             FIND(h, l, encoding_choose_default_routines) && FIND(h, l, encoding_run) &&
             FIND(h, l, encoding_destroy) && FIND(h, l, finish) &&
             FIND(h, l, get_default_error_message);
    if (loaded)
        lib = l;
    else
        dlclose(h);
}

const ExrCoreLib *exr_core_lib(const char *path, GError *err)
{
    pthread_once(&once, load);
    if (loaded)
        return &lib;
    gerror_set(err, G_ERR_IO, "%s: cannot write image: OpenEXR files need OpenEXRCore (%s), which cannot be loaded: "
               "%s", path, GENERIC_EXRCORE_SONAME, why);
    return NULL;
}
