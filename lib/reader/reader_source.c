/* reader_source.c - the files being read: the stack of open sources (the file being read and the files that
 * include it), each loaded whole by gfile_read_all. */
#include "reader_internal.h"
#include "generic/services/file.h"
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
    int rc = gfile_read_all(name, r->opt.max_file_size, &s->text, &len, err);
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

