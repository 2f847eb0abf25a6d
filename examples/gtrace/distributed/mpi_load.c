/* mpi_load.c - finds and opens gtrace's MPI module (mpi_module.h) with dlopen, only when gtrace runs under an MPI
 * launcher: a render or --help on one machine maps no MPI library. */
#include "mpi_load.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef GTRACE_MPI_LIBDIR
#define GTRACE_MPI_LIBDIR "/usr/local/lib"
#endif

int mpi_launched(void)
{
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
        if (getenv(vars[i]))
            return 1;
    return 0;
}

const char *mpi_build_note(void)
{
#ifdef GTRACE_MPI_BUILT
    return "distributed rendering: MPI module " GTRACE_MPI_BUILT ", opened when run under mpirun";
#else
    return "distributed rendering: built without MPI (no Open MPI development files were found); --crop and "
           "gtrace merge still work";
#endif
}

static GtMpiOps ops;
static int loaded;
static char failure[1024];

/* Appends "; " and text to failure, cut to fit. */
static void note(const char *text)
{
    size_t len = strlen(failure);
    int room = (int)(sizeof failure - len) - 3;
    if (room > 0)
        snprintf(failure + len, sizeof failure - len, "%s%.*s", len ? "; " : "", room, text);
}

/* Opens one candidate; 1 when loaded and accepted. A missing file is noted only when named. */
static int try_module(const char *path, int named)
{
    if (!named && access(path, F_OK) != 0)
        return 0;
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *why = dlerror();
        note(why ? why : path);
        return 0;
    }
    GtMpiEntry entry = (GtMpiEntry)dlsym(h, GTMPI_ENTRY);
    char msg[PATH_MAX + 80];
    if (!entry || entry(GTMPI_ABI, &ops) != 0) {
        snprintf(msg, sizeof msg, "%s: %s", path,
                 entry ? "built for another interface version" : "not a gtrace MPI module (no " GTMPI_ENTRY ")");
        note(msg);
        dlclose(h);
        return 0;
    }
    return 1; /* kept open for the life of the process */
}

static int load(void)
{
    const char *named = getenv("GTRACE_MPI_MODULE");
    if (named && *named)
        return try_module(named, 1);
    char exe[PATH_MAX], cand[PATH_MAX + 64];
    if (realpath("/proc/self/exe", exe)) {
        char *slash = strrchr(exe, '/');
        if (slash) {
            *slash = 0;
            snprintf(cand, sizeof cand, "%s/generic/%s", exe, GTMPI_MODULE_FILE);
            if (try_module(cand, 0))
                return 1;
            snprintf(cand, sizeof cand, "%s/../lib/generic/%s", exe, GTMPI_MODULE_FILE);
            if (try_module(cand, 0))
                return 1;
        }
    }
    return try_module(GTRACE_MPI_LIBDIR "/generic/" GTMPI_MODULE_FILE, 0);
}

const GtMpiOps *mpi_load(GError *err)
{
    if (!loaded && !failure[0])
        loaded = load();
    if (loaded)
        return &ops;
    gerror_set(err, G_ERR_IO, "running under mpirun needs gtrace's MPI module %s, which cannot be loaded: %s",
               GTMPI_MODULE_FILE, failure[0] ? failure :
               "not found (looked in generic/ and ../lib/generic/ beside gtrace and in " GTRACE_MPI_LIBDIR
               "/generic/; GTRACE_MPI_MODULE may name it)");
    return NULL;
}
