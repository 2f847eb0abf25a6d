/* image_sink.h - where an image encoder's bytes go (image_png.c, image_exr.c): the temporary of the file being
 * written (generic/services/file.h's outputs), the end of the furthest write and the first error. An encoder's
 * callback cannot return a GError: the sink keeps the first failure, stops writing, and reports it once the encoder
 * is done (gimage_sink_end), so the destination is replaced only by a complete file. */
#ifndef GENERIC_IMAGE_SINK_H
#define GENERIC_IMAGE_SINK_H

#include "generic/services/file.h"

#include <stddef.h>

/** An output being encoded. */
typedef struct GImageSink {
    GFileOutput file;  /**< the temporary */
    long long size;    /**< the end of the furthest write, in bytes */
    int error;         /**< errno of the first failed write (ENOSPC for a write that took nothing); 0 before */
    char message[200]; /**< the encoder's own first error, for the caller's message; "" before */
} GImageSink;

/** Starts the output of path (gfile_output_begin) into s, cleared otherwise: G_OK, or its G_ERR_IO/G_ERR_NOMEM. */
GENERIC_NODISCARD int gimage_sink_begin(GImageSink *s, const char *path, GError *err);

/** Writes the n bytes of data at offset into the temporary, going on after interruptions (EINTR) and short writes:
 * 0, or -1 with s->error set (by this write, or by an earlier one: nothing is written after a failure). The failure
 * stays in s for gimage_sink_end, so a caller that cannot stop its encoder may ignore the result. */
int gimage_sink_write(GImageSink *s, const void *data, size_t n, long long offset);

/** Ends the output, given the encoder's status rc: when rc is G_OK and no write failed, commits the temporary as
 * path (gfile_output_commit, checked to hold s->size bytes) and returns its status; else removes it and returns rc,
 * or G_ERR_IO with "PATH: cannot write image: REASON" for a failed write. */
GENERIC_NODISCARD int gimage_sink_end(GImageSink *s, int rc, const char *path, GError *err);

#endif
