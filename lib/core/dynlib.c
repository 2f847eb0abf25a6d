/* dynlib.c - shared libraries opened by soname on first use (generic/services/dynlib.h). */
#include "generic/services/dynlib.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

/* dlsym's object pointer is stored into function pointers as it is (POSIX guarantees the two convert) */
_Static_assert(sizeof(void *) == sizeof(void (*)(void)), "function pointers are not the size of void *");

/* Held by the first gdynlib_open of each library while it opens it: a few opens per process, so one lock for all. */
static pthread_mutex_t open_lock = PTHREAD_MUTEX_INITIALIZER;

/* Opens lib and fills its slots (all of them, or none): 1, or -1 with lib->why set. */
static int open_once(GDynLib *lib)
{
    void *h = dlopen(lib->soname, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *e = dlerror();
        snprintf(lib->why, sizeof lib->why, "%s", e ? e : "not found");
        return -1;
    }
    for (size_t i = 0; i < lib->count; i++)
        if (!dlsym(h, lib->symbols[i].name)) {
            snprintf(lib->why, sizeof lib->why, "it has no %s", lib->symbols[i].name);
            dlclose(h);
            return -1;
        }
    for (size_t i = 0; i < lib->count; i++) {
        void *f = dlsym(h, lib->symbols[i].name);
        memcpy(lib->symbols[i].slot, &f, sizeof f);
    }
    return 1;
}

int gdynlib_open(GDynLib *lib)
{
    int state = __atomic_load_n(&lib->state, __ATOMIC_ACQUIRE);
    if (!state) {
        pthread_mutex_lock(&open_lock);
        if (!(state = lib->state)) {
            state = open_once(lib);
            __atomic_store_n(&lib->state, state, __ATOMIC_RELEASE); /* after the slots and why */
        }
        pthread_mutex_unlock(&open_lock);
    }
    return state > 0;
}
