/* dynlib.h - a shared library opened by its soname on first use (lib/core/dynlib.c), so that a process maps a
 * dependency it rarely needs (OpenEXRCore for OpenEXR output, assimp for PLY, STL and glTF meshes) only when it
 * uses it. The library is opened at most once per process, whatever the number of threads asking; the functions
 * named in a table are resolved into the caller's function pointers, and the reason of a failure is kept for the
 * caller's message.
 *
 *     static MyLib lib;  // a struct of function pointers
 *     static const GDynLibSymbol symbols[] = {{"foo_open", &lib.open}, {"foo_close", &lib.close}};
 *     static GDynLib foo = GDYNLIB_INIT("libfoo.so.1", symbols, 2);
 *     if (!gdynlib_open(&foo))
 *         return gerror_set(err, G_ERR_IO, "libfoo.so.1 cannot be loaded: %s", foo.why);
 *     lib.open(...); */
#ifndef GENERIC_DYNLIB_H
#define GENERIC_DYNLIB_H

#include "../export.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A function to take from the library: its symbol's name and where to store its address. */
typedef struct GDynLibSymbol {
    const char *name; /**< the symbol, as dlsym looks it up */
    void *slot;       /**< the address of a function pointer (of any function type) set to the symbol */
} GDynLibSymbol;

/** A library and the functions taken from it: a static object initialised with GDYNLIB_INIT. soname, symbols and
 * count are the caller's; state and why belong to gdynlib_open. */
typedef struct GDynLib {
    const char *soname;           /**< the name dlopen is given */
    const GDynLibSymbol *symbols; /**< the functions to resolve, count of them */
    size_t count;
    int state;                    /**< 0 before the first gdynlib_open, 1 open, -1 failed (accessed atomically) */
    char why[256];                /**< why it failed: set once gdynlib_open returned 0, "" before */
} GDynLib;

/** The initialiser of a GDynLib: the library by its soname and the count entries of symbols to resolve. */
#define GDYNLIB_INIT(soname, symbols, count) {(soname), (symbols), (count), 0, ""}

/** Opens lib->soname (dlopen, RTLD_NOW | RTLD_LOCAL) and sets every slot of lib->symbols to its symbol's address,
 * at the first call for lib; later calls, from any thread, wait for that first one and give its outcome without
 * trying again. 1 when the library is open and has every symbol (it is then never closed); 0 otherwise, with no
 * slot changed and lib->why set: the loader's reason (dlerror) when the library cannot be opened, "it has no NAME"
 * for the first symbol it lacks (the library is then closed). */
GENERIC_API GENERIC_NODISCARD int gdynlib_open(GDynLib *lib);

#ifdef __cplusplus
}
#endif
#endif
