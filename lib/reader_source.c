/* reader_source.c - the files being read: loading a file whole (with the size limit), the stack of open
 * sources (the file being read and the files that include it). */
#include "reader_internal.h"
#include "generic/file.h"
#include "generic/memory.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void greader_free_source(GReaderSource *s)
{
    if (!s)
        return;
    gmem_free(s->text);
    gmem_free(s->name);
    gmem_free(s->dir);
    gmem_free(s->real);
    gmem_free(s);
}

/* Reads a file whole; errors name the file but no position (the caller adds the include's). */
int greader_read_file(const char *path, size_t limit, char **text, size_t *len, GError *err)
{
    *text = NULL;
    int fd = gfile_open_input(path, err); /* a regular file, or a message naming what it is */
    if (fd < 0)
        return fd;
    struct stat st;
    if (fstat(fd, &st) == 0 && (unsigned long long)st.st_size > limit) {
        close(fd);
        return gerror_set(err, G_ERR_IO, "\"%s\" is %lld bytes, more than the limit of %zu bytes", path,
                          (long long)st.st_size, limit);
    }
    size_t cap = 4096, n = 0;
    char *buf = gmem_alloc(cap);
    int rc = buf ? G_OK : gerror_set(err, G_ERR_NOMEM, "out of memory reading \"%s\"", path);
    while (rc == G_OK) {
        if (n + 1 >= cap) {
            char *b = gmem_realloc(buf, cap * 2);
            if (!b) {
                rc = gerror_set(err, G_ERR_NOMEM, "out of memory reading \"%s\"", path);
                break;
            }
            buf = b;
            cap *= 2;
        }
        ssize_t got = read(fd, buf + n, cap - n - 1);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            rc = gerror_set(err, G_ERR_IO, "cannot read \"%s\": %s", path, strerror(errno));
        else if (got == 0)
            break;
        else if ((n += (size_t)got) > limit)
            rc = gerror_set(err, G_ERR_IO, "\"%s\" is more than the limit of %zu bytes", path, limit);
    }
    close(fd);
    if (rc != G_OK) {
        gmem_free(buf);
        return rc;
    }
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return G_OK;
}

int greader_push_source(GReader *r, GReaderSource *s, const char *text, size_t len, GError *err)
{
    /* the library keeps every text read, so that `like` can re-read an entry of a file already closed */
    char *kept = s->text;
    s->text = NULL;
    if (!kept && (kept = gmem_alloc(len + 1))) {
        memcpy(kept, text, len);
        kept[len] = '\0';
    }
    if (!kept || glibrary_keep_text(r->lib, kept, len, s->name, &s->text_id) != G_OK) {
        if (!kept)
            gmem_free(kept);
        greader_free_source(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    s->parent = r->src;
    r->src = s;
    r->have_ahead = 0;
    glexer_init(&s->lx, s->name, kept, len);
    return G_OK;
}

void greader_pop_source(GReader *r)
{
    GReaderSource *s = r->src;
    r->src = s->parent;
    r->have_ahead = 0;
    greader_free_source(s);
}

void greader_pop_all_sources(GReader *r)
{
    while (r->src)
        greader_pop_source(r);
}

/* Opens a file as a new source; `name` is owned by the source from here on. */
int greader_open_source(GReader *r, char *name, GError *err)
{
    GReaderSource *s = gmem_calloc(1, sizeof *s);
    if (!s) {
        gmem_free(name);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    s->name = name;
    size_t len = 0;
    int rc = greader_read_file(name, r->opt.max_file_size, &s->text, &len, err);
    if (rc == G_OK && (!(s->dir = gfile_dir_of(name)) || !(s->real = realpath(name, NULL))))
        rc = gerror_set(err, s->dir ? G_ERR_IO : G_ERR_NOMEM, "cannot resolve \"%s\": %s", name, strerror(errno));
    if (rc == G_OK && s->real) { /* realpath() uses malloc: keep our allocator's copy */
        char *copy = gmem_strdup(s->real);
        free(s->real);
        s->real = copy;
        if (!copy)
            rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    if (rc != G_OK) {
        greader_free_source(s);
        return rc;
    }
    return greader_push_source(r, s, s->text, len, err);
}

