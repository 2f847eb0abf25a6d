/* spawn.c - the readers of untrusted files in processes of their own (generic/services/spawn.h). */
#include "generic/services/spawn.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

int gspawn_isolated(GError *err)
{
    const char *v = getenv("GENERIC_DECODE");
    if (!v || !*v || strcmp(v, "isolated") == 0)
        return 1;
    if (strcmp(v, "inprocess") == 0)
        return 0;
    return gerror_set(err, G_ERR_INVALID, "GENERIC_DECODE is '%s': it must be 'isolated' (the default: images and "
                      "meshes are read in processes of their own) or 'inprocess' (for trusted files)", v);
}

/* dir + sub + "/" + name, when executable, canonical into out: 1; else 0 with out empty. */
static int try_dir(const char *dir, const char *sub, const char *name, char *out)
{
    char cand[PATH_MAX + 64];
    if (snprintf(cand, sizeof cand, "%s%s/%s", dir, sub, name) < (int)sizeof cand && access(cand, X_OK) == 0 &&
        realpath(cand, out))
        return 1;
    out[0] = 0;
    return 0;
}

/* name in the folder of file, its generic/ and its ../lib/generic/. */
static int try_beside(const char *file, const char *name, char *out)
{
    char real[PATH_MAX];
    if (!file || !realpath(file, real))
        return 0;
    char *slash = strrchr(real, '/');
    if (!slash)
        return 0;
    *slash = 0;
    return try_dir(real, "", name, out) || try_dir(real, "/generic", name, out) ||
           try_dir(real, "/../lib/generic", name, out);
}

int gspawn_find(const char *name, const char *env, const void *code, const char *libdir, char *out)
{
    out[0] = 0;
    const char *named = env ? secure_getenv(env) : NULL;
    if (named && *named) {
        if (strlen(named) >= PATH_MAX)
            return 0;
        snprintf(out, PATH_MAX, "%s", named);
        return 1;
    }
    Dl_info self;
    if (code && dladdr(code, &self) && self.dli_fname && strchr(self.dli_fname, '/') &&
        try_beside(self.dli_fname, name, out))
        return 1;
    if (try_beside("/proc/self/exe", name, out))
        return 1;
    return libdir && try_dir(libdir, "/generic", name, out);
}

int gspawn_socketpair(int sv[2], int lowest)
{
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
        return -1;
    for (int i = 0; i < 2; i++) {
        if (sv[i] > lowest)
            continue;
        int moved = fcntl(sv[i], F_DUPFD_CLOEXEC, lowest + 1), e = errno;
        close(sv[i]);
        sv[i] = moved;
        errno = e;
    }
    if (sv[0] >= 0 && sv[1] >= 0)
        return 0;
    int e = errno;
    for (int i = 0; i < 2; i++)
        if (sv[i] >= 0)
            close(sv[i]);
    errno = e;
    return -1;
}
