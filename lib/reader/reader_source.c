/* reader_source.c - the files being read, each loaded whole by gfile_read_all, and texts held in memory. */
#include "reader_source.h"
#include "generic/services/file.h"
#include "generic/memory.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void greader_source_free(GReaderSource *s)
{
    if (!s)
        return;
    if (s->text)
        gmem_budget_release(s->budget);
    gmem_free(s->text);
    gmem_free(s->name);
    gmem_free(s->dir);
    gmem_free(s->real);
    gmem_free(s);
}

int greader_source_file(char *name, size_t max_size, GReaderSource **out, GError *err)
{
    *out = NULL;
    GReaderSource *s = gmem_calloc(1, sizeof *s);
    if (!s) {
        gmem_free(name);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    s->name = name;
    /* the text is charged to the memory budget before it is read: its size now, and no more may be read */
    size_t limit = max_size ? max_size : SIZE_MAX - 1;
    struct stat st;
    int rc = G_OK;
    if (stat(name, &st) == 0 && S_ISREG(st.st_mode) && (unsigned long long)st.st_size <= limit) {
        char what[160];
        snprintf(what, sizeof what, "the file \"%.100s\" (%lld bytes)", name, (long long)st.st_size);
        limit = (size_t)st.st_size;
        if ((rc = gmem_budget_reserve(limit + 1, what, err)) == G_OK)
            s->budget = limit + 1;
    }
    if (rc == G_OK)
        rc = gfile_read_all(name, limit, &s->text, &s->len, err);
    if (rc != G_OK && s->budget) {
        gmem_budget_release(s->budget);
        s->budget = 0;
    }
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
        greader_source_free(s);
        return rc;
    }
    *out = s;
    return G_OK;
}

int greader_source_string(const char *name, const char *text, GReaderSource **out, GError *err)
{
    *out = NULL;
    GReaderSource *s = gmem_calloc(1, sizeof *s);
    if (s && (s->name = gmem_strdup(name)) && (s->dir = gmem_strdup("."))) {
        s->len = strlen(text);
        s->text = gmem_alloc(s->len + 1);
    }
    if (!s || !s->text) {
        greader_source_free(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    memcpy(s->text, text, s->len + 1);
    *out = s;
    return G_OK;
}
