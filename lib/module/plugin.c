/* plugin.c - loads run-time modules with dlopen and registers the types they add while they initialise. */
#include "generic/plugin.h"
#include "generic/services/file.h"
#include "generic/memory.h"
#include "plugin_elf.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_TYPES 256

typedef struct Module {
    struct Module *next;
    char *real; /* canonical path */
    void *handle;
    int fd; /* the file checked and loaded, open as long as the module is (its /proc/self/fd name stays unique) */
} Module;

typedef struct Pending {
    GTypeInfo types[MAX_TYPES];
    int count;
    int open; /* add_type is allowed */
} Pending;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static Module *modules;
static int nmodules;

static int add_type(GModuleApi *api, const GTypeInfo *info, GError *err)
{
    Pending *p = api ? api->priv : NULL;
    if (!p || !p->open)
        return gerror_set(err, G_ERR_INVALID, "types can only be registered while a module initialises");
    GTypeInfo t;
    if (info)
        t = *info;
    if (!info || gtypeinfo_complete(&t, NULL) != G_OK)
        return gerror_set(err, G_ERR_INVALID, "module '%s' registers an invalid type", api->path);
    if (p->count == MAX_TYPES)
        return gerror_set(err, G_ERR_INVALID, "module '%s' registers more than %d types", api->path, MAX_TYPES);
    for (int i = 0; i < p->count; i++)
        if (p->types[i].kind == t.kind && strcmp(p->types[i].name, t.name) == 0)
            return gerror_set(err, G_ERR_EXISTS, "module '%s' registers %s type '%s' twice", api->path,
                              gkind_name(t.kind), t.name);
    p->types[p->count++] = t;
    return G_OK;
}

static int already_loaded(const char *real)
{
    for (Module *m = modules; m; m = m->next)
        if (strcmp(m->real, real) == 0)
            return 1;
    return 0;
}

/* Runs the module's init and commits its types; the caller holds the lock. */
static int init_module(void *h, const char *path, GError *err)
{
    dlerror();
    const int *abi = dlsym(h, GMODULE_ABI_SYMBOL);
    const char *e = dlerror();
    if (e || !abi)
        return gerror_set(err, G_ERR_IO, "module '%s' is not a libgeneric module: %s", path,
                          e ? e : "symbol " GMODULE_ABI_SYMBOL " is NULL");
    if (*abi != GMODULE_ABI_VERSION)
        return gerror_set(err, G_ERR_VERSION,
                          "module '%s' was built for module interface version %d, this library has version %d", path,
                          *abi, GMODULE_ABI_VERSION);
    GModuleInitFn init;
    *(void **)&init = dlsym(h, GMODULE_INIT_SYMBOL);
    e = dlerror();
    if (e || !init)
        return gerror_set(err, G_ERR_IO, "module '%s' has no entry point: %s", path,
                          e ? e : "symbol " GMODULE_INIT_SYMBOL " is NULL");
    Pending *p = gmem_calloc(1, sizeof *p);
    if (!p)
        return gerror_set(err, G_ERR_NOMEM, "out of memory loading module '%s'", path);
    GModuleApi api = {GMODULE_ABI_VERSION, GCOLOR_ABI_VERSION, GMATERIAL_ABI_VERSION, path, add_type, p};
    p->open = 1;
    GError ierr;
    gerror_clear(&ierr);
    int rc = init(&api, &ierr);
    p->open = 0;
    if (rc != G_OK) {
        gerror_set(err, rc < 0 ? rc : G_ERR_INVALID, "module '%s' failed to initialise: %s", path,
                   ierr.message[0] ? ierr.message : gstatus_string(rc));
        gmem_free(p);
        return rc < 0 ? rc : G_ERR_INVALID;
    }
    for (int i = 0; i < p->count; i++)
        if (gregistry_find(p->types[i].kind, p->types[i].name)) {
            rc = gerror_set(err, G_ERR_EXISTS, "module '%s': %s type '%s' is already registered", path,
                            gkind_name(p->types[i].kind), p->types[i].name);
            gmem_free(p);
            return rc;
        }
    for (int i = 0; i < p->count && rc == G_OK; i++)
        rc = gregistry_add(&p->types[i], err);
    gmem_free(p);
    /* a failure here leaves earlier types registered: the caller then keeps the module open */
    return rc == G_OK ? G_OK : 1;
}

/* Opens the file that realpath names and checks it (plugin_elf.c) before dlopen runs anything of it; the file
 * checked is the one loaded (through /proc/self/fd when it exists, so it cannot be swapped in between). On
 * success *fd is the open file, to be kept open while the module is loaded: dlopen knows the module by that
 * name, and an fd number closed and reused would make a later module look loaded already. */
static void *open_checked(const char *real, const char *path, int *fd_out, int *rc, GError *err)
{
    *fd_out = -1;
    int fd = open(real, O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        *rc = gerror_set(err, G_ERR_IO, "cannot load module '%s': %s", path, strerror(errno));
        return NULL;
    }
    int abi = -1;
    *rc = gplugin_elf_check(fd, path, &abi, err);
    if (*rc == G_OK && abi != -1 && abi != GMODULE_ABI_VERSION)
        *rc = gerror_set(err, G_ERR_VERSION,
                         "module '%s' was built for module interface version %d, this library has version %d "
                         "(not loaded, nothing of it was run)",
                         path, abi, GMODULE_ABI_VERSION);
    void *h = NULL;
    if (*rc == G_OK) {
        char byfd[64];
        snprintf(byfd, sizeof byfd, "/proc/self/fd/%d", fd);
        h = dlopen(access(byfd, R_OK) == 0 ? byfd : real, RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            const char *e = dlerror();
            *rc = gerror_set(err, G_ERR_IO, "cannot load module '%s': %s", path, e ? e : "unknown dlopen error");
        }
    }
    if (h)
        *fd_out = fd;
    else
        close(fd);
    return h;
}

static int load_path(const char *path, GError *err)
{
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "no module path given");
    char *real = realpath(path, NULL);
    if (!real)
        return gerror_set(err, G_ERR_IO, "cannot load module '%s': file not found", path);
    GError why;
    if (gfile_check_input(real, &why) != G_OK) { /* dlopen would block on a FIFO */
        free(real);
        return gerror_set(err, G_ERR_IO, "cannot load module '%s': %s", path, why.message);
    }
    pthread_mutex_lock(&lock);
    int rc = G_OK;
    Module *m = NULL;
    if (already_loaded(real))
        goto done;
    int fd;
    void *h = open_checked(real, path, &fd, &rc, err);
    if (!h)
        goto done;
    rc = init_module(h, path, err);
    if (rc < 0) {
        dlclose(h);
        close(fd);
        goto done;
    }
    m = gmem_calloc(1, sizeof *m);
    if (m)
        m->real = gmem_strdup(real);
    if (!m || !m->real) { /* the module stays open (its types may be registered) but is not remembered */
        gmem_free(m);
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory loading module '%s'", path);
        goto done;
    }
    if (rc > 0) { /* partly registered: keep it open, report */
        rc = G_ERR_EXISTS;
    }
    m->handle = h;
    m->fd = fd;
    m->next = modules;
    modules = m;
    nmodules++;
done:
    pthread_mutex_unlock(&lock);
    free(real);
    return rc;
}

/* dir/name in fresh memory (name alone when dir is NULL or name is absolute). */
static char *join(const char *dir, const char *name)
{
    if (!dir || !dir[0] || name[0] == '/')
        return gmem_strdup(name);
    size_t a = strlen(dir), b = strlen(name);
    char *s = gmem_alloc(a + b + 2);
    if (s) {
        memcpy(s, dir, a);
        s[a] = '/';
        memcpy(s + a + 1, name, b + 1);
    }
    return s;
}

static int exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

/* Appends ", dir" (or "dir" first) to the list of searched directories, truncating quietly. */
static void note_dir(char *list, size_t size, const char *dir)
{
    size_t used = strlen(list);
    if (used + 1 < size)
        snprintf(list + used, size - used, "%s%s", used ? ", " : "", dir);
}

/* Looks for name in directory d (len bytes of it): 1 with *path set when the file is there, 0 when not (d noted in
 * searched), G_ERR_NOMEM. */
static int find_in(const char *d, size_t len, const char *name, char *searched, size_t size, char **path)
{
    char *copy = gmem_alloc(len + 1), *p;
    if (!copy)
        return G_ERR_NOMEM;
    memcpy(copy, d, len);
    copy[len] = '\0';
    p = join(copy, name);
    note_dir(searched, size, copy);
    gmem_free(copy);
    if (!p)
        return G_ERR_NOMEM;
    if (exists(p)) {
        *path = p;
        return 1;
    }
    gmem_free(p);
    return 0;
}

int gplugin_find(const char *name, const char *dir, char **path, GError *err)
{
    *path = NULL;
    if (!name || !name[0])
        return gerror_set(err, G_ERR_INVALID, "no module path given");
    if (strchr(name, '/')) { /* a path: relative to dir */
        *path = join(dir, name);
        return *path ? G_OK : gerror_set(err, G_ERR_NOMEM, "out of memory loading module '%s'", name);
    }
    /* a bare name: the directories the user installed modules in come before the base directory (a scene's own
     * folder, which may have been downloaded with it, cannot replace an installed module) */
    char searched[1024] = "";
    const char *env = getenv(GPLUGIN_PATH_ENV);
    int found = 0;
    for (const char *s = env; s && *s && !found;) {
        const char *colon = strchr(s, ':');
        size_t len = colon ? (size_t)(colon - s) : strlen(s);
        if (len > 0)
            found = find_in(s, len, name, searched, sizeof searched, path);
        s += len + (colon ? 1 : 0);
    }
#ifdef GENERIC_PLUGIN_DIR /* where `make install` puts the example plug-ins (PREFIX/lib/generic/plugins) */
    if (!found)
        found = find_in(GENERIC_PLUGIN_DIR, strlen(GENERIC_PLUGIN_DIR), name, searched, sizeof searched, path);
#endif
    const char *base = dir && dir[0] ? dir : ".";
    if (!found)
        found = find_in(base, strlen(base), name, searched, sizeof searched, path);
    if (found < 0)
        return gerror_set(err, G_ERR_NOMEM, "out of memory loading module '%s'", name);
    if (found)
        return G_OK;
    return gerror_set(err, G_ERR_IO, "cannot load module '%s': file not found in %s (%s%s)", name, searched,
                      env && env[0] ? GPLUGIN_PATH_ENV "=" : GPLUGIN_PATH_ENV " is not set",
                      env && env[0] ? env : "");
}

int gplugin_load_from(const char *name, const char *dir, GError *err)
{
    char *path;
    int rc = gplugin_find(name, dir, &path, err);
    if (rc == G_OK)
        rc = load_path(path, err);
    gmem_free(path);
    return rc;
}

int gplugin_load(const char *path, GError *err) { return gplugin_load_from(path, NULL, err); }

int gplugin_count(void)
{
    pthread_mutex_lock(&lock);
    int n = nmodules;
    pthread_mutex_unlock(&lock);
    return n;
}

int gplugin_load_args(int *argc, char **argv, GError *err)
{
    static const char opt[] = "--plugin";
    int n = 1;
    for (int i = 1; i < *argc; i++) {
        const char *name = NULL;
        if (strcmp(argv[i], opt) == 0) {
            if (i + 1 >= *argc)
                return gerror_set(err, G_ERR_INVALID, "--plugin needs a value (a module FILE.so)");
            name = argv[++i];
        } else if (strncmp(argv[i], opt, sizeof opt - 1) == 0 && argv[i][sizeof opt - 1] == '=') {
            name = argv[i] + sizeof opt;
        } else {
            argv[n++] = argv[i];
            continue;
        }
        int rc = gplugin_load_from(name, ".", err);
        if (rc != G_OK)
            return rc;
    }
    *argc = n;
    argv[n] = NULL;
    return G_OK;
}
