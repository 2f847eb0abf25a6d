/* image_sink.c - an image encoder's output (image_sink.h). */
#include "image_sink.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

int gimage_sink_begin(GImageSink *s, const char *path, GError *err)
{
    memset(s, 0, sizeof *s);
    return gfile_output_begin(&s->file, path, err);
}

int gimage_sink_write(GImageSink *s, const void *data, size_t n, long long offset)
{
    const char *bytes = data;
    size_t done = 0;
    while (done < n && !s->error) {
        ssize_t w = pwrite(s->file.fd, bytes + done, n - done, (off_t)(offset + (long long)done));
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            s->error = w < 0 ? errno : ENOSPC;
        else
            done += (size_t)w;
    }
    if (s->error)
        return -1;
    if (offset + (long long)n > s->size)
        s->size = offset + (long long)n;
    return 0;
}

int gimage_sink_end(GImageSink *s, int rc, const char *path, GError *err)
{
    if (rc == G_OK && s->error)
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, strerror(s->error));
    if (rc == G_OK)
        return gfile_output_commit(&s->file, s->size, path, err);
    gfile_output_abort(&s->file);
    return rc;
}
