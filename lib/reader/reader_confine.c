/* reader_confine.c - GReaderOptions.confine_dir: every file a load reads (the file itself, includes, plug-ins
 * and every path read with greader_path: BFC files, images, meshes, probes) must lie under one directory once
 * symbolic links are resolved. */
#include "reader_state.h"
#include "reader_confine.h"
#include "generic/memory.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

/* realpath of a file that need not exist yet: the resolved directory joined with the last component (which
 * must not be "." or ".."). NULL with errno set when the directory cannot be resolved. malloc'd. */
static char *resolve(const char *path)
{
    char *real = realpath(path, NULL);
    if (real || errno != ENOENT)
        return real;
    const char *slash = strrchr(path, '/');
    const char *last = slash ? slash + 1 : path;
    if (!last[0] || strcmp(last, ".") == 0 || strcmp(last, "..") == 0) {
        errno = ENOENT;
        return NULL;
    }
    char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : strdup(".");
    char *rdir = dir ? realpath(dir, NULL) : NULL;
    free(dir);
    if (!rdir)
        return NULL;
    size_t a = strlen(rdir), b = strlen(last);
    char *joined = malloc(a + b + 2);
    if (joined) {
        memcpy(joined, rdir, a);
        joined[a] = '/';
        memcpy(joined + a + 1 - (a == 1), last, b + 1); /* rdir "/" has its slash already */
    }
    free(rdir);
    return joined;
}

int greader_confine(const char *dir, const char *path, char **real, GError *err)
{
    *real = NULL;
    char *root = realpath(dir, NULL);
    if (!root)
        return gerror_set(err, G_ERR_IO, "the confinement directory \"%s\" cannot be resolved: %s", dir,
                          strerror(errno));
    char *full = resolve(path);
    if (!full) {
        int e = errno;
        free(root);
        return gerror_set(err, G_ERR_IO, "\"%s\" cannot be resolved (to check it against --confine \"%s\"): %s", path,
                          dir, strerror(e));
    }
    size_t n = strlen(root);
    int inside = strcmp(root, "/") == 0 || (strncmp(full, root, n) == 0 && (full[n] == '/' || full[n] == '\0'));
    int rc = G_OK;
    if (!inside)
        rc = gerror_set(err, G_ERR_INVALID, "\"%s\" is outside the directory the load is confined to (\"%s\"; it "
                                            "resolves to \"%s\")",
                        path, dir, full);
    else if (!(*real = gmem_strdup(full)))
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    free(full);
    free(root);
    return rc;
}

int greader_path_allowed(GReader *r, const char *path, GError *err)
{
    if (!r || !path)
        return gerror_set(err, G_ERR_INVALID, "no reader or path given");
    if (!r->opt.confine_dir)
        return G_OK;
    char *real = NULL;
    int rc = greader_confine(r->opt.confine_dir, path, &real, err);
    gmem_free(real);
    return rc;
}
