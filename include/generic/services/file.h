/* file.h - opening the files the library and its tools read and write (lib/core/file.c).
 *
 * Inputs. Every file the library or a tool reads (text files and their includes, BFC files, meshes, images,
 * light probes, plug-ins, CSV files) is opened with gfile_open_input, or checked with gfile_check_input when
 * a dependency opens it by name (OpenImageIO, dlopen). Only regular files are accepted: a FIFO, a device
 * (/dev/zero, /dev/urandom), a socket or a directory is refused with its path and what it is
 * ("cannot read "x": it is a FIFO"). The open uses O_NONBLOCK, so a FIFO without a writer cannot block it,
 * and the flag is cleared once the file is known to be regular.
 *
 * Outputs. A file is written to a temporary in the destination's directory, which gfile_output_commit
 * flushes to the disk, checks (every write error, the close, the size) and renames over the destination:
 * the destination appears complete or not at all, and an existing file is untouched when anything fails.
 * A destination that is a symbolic link is written through the link: the link's target (followed to the
 * end of a chain of links) is replaced and the link is kept. A destination that exists but is not a
 * regular file (a directory, /dev/null, /dev/full, a FIFO) is refused. Pending temporaries are removed
 * when the process ends by exit(), SIGINT, SIGTERM or SIGHUP: the handlers are installed at the first
 * temporary for each of those signals whose disposition is the default (a program's own handler is kept
 * and called after the temporaries are removed); a default disposition is then restored and the signal
 * raised again, so the process still ends by it. */
#ifndef GENERIC_FILE_H
#define GENERIC_FILE_H

#include "../export.h"
#include "../error.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The directory part of path ("." when it has none, "/" for a file in the root), in gmem_alloc storage;
 * NULL when out of memory. */
GENERIC_API char *gfile_dir_of(const char *path);

/** Opens a regular file for reading (close-on-exec, blocking once checked). Returns the descriptor (>= 0), or
 * G_ERR_IO with "cannot open "PATH": REASON" or "cannot read "PATH": it is a FIFO" (a character device,
 * a block device, a socket, a directory). */
GENERIC_API GENERIC_NODISCARD int gfile_open_input(const char *path, GError *err);

/** The same check without keeping the file open, for files a dependency opens by name: G_OK or G_ERR_IO. */
GENERIC_API GENERIC_NODISCARD int gfile_check_input(const char *path, GError *err);
/** Reads the regular file at path whole, at most limit bytes, into a NUL-terminated buffer *text of *len bytes (free
 * with gmem_free). Errors name the file but no position. */
GENERIC_API GENERIC_NODISCARD int gfile_read_all(const char *path, size_t limit, char **text, size_t *len, GError *err);
/** Reads exactly n bytes from the descriptor fd into buf, going on after interruptions (EINTR): 0, or -1 at an
 * error or at the end of the input before n bytes (the protocol of a helper process's pipe or socket). */
GENERIC_API GENERIC_NODISCARD int gfile_read_exact(int fd, void *buf, size_t n);
/** Writes exactly n bytes of buf to the descriptor fd, going on after interruptions: 0, or -1 at an error. */
GENERIC_API GENERIC_NODISCARD int gfile_write_exact(int fd, const void *buf, size_t n);
/** gfile_write_exact for a socket, without SIGPIPE when its peer has gone (send with MSG_NOSIGNAL): 0, or -1. */
GENERIC_API GENERIC_NODISCARD int gfile_send_exact(int fd, const void *buf, size_t n);

/** An output being written; see the top of this file. */
typedef struct GFileOutput {
    char *target; /**< the destination with symbolic links followed; owned */
    char *temp;   /**< the temporary next to it; owned */
    int fd;       /**< open on temp, for writing; -1 when closed */
    int slot;     /**< internal: the temporary's entry in the cleanup registry */
} GFileOutput;

/** Checks before any work that path can be written: its directory exists, is a directory and is writable,
 * and path does not name something other than a regular file (symbolic links followed). G_OK or G_ERR_IO
 * with the reason. */
GENERIC_API GENERIC_NODISCARD int gfile_check_output(const char *path, GError *err);

/** Starts writing path: checks it (gfile_check_output), creates the temporary (named .BASE.XXXXXX followed
 * by the extension of path, with the mode of the existing file, or 0666 less the umask) and registers it
 * for removal on exit and the signals above. G_ERR_IO or G_ERR_NOMEM on failure (o is then cleared). */
GENERIC_API GENERIC_NODISCARD int gfile_output_begin(GFileOutput *o, const char *path, GError *err);

/** Finishes an output: flushes it to the disk (fsync), checks that the file has expected_size bytes
 * (when >= 0), closes it and renames it over the target. On any failure the temporary is removed and the
 * target is untouched. o is cleared in both cases. G_ERR_IO with the reason naming path. */
GENERIC_API GENERIC_NODISCARD int gfile_output_commit(GFileOutput *o, long long expected_size, const char *path,
                                                      GError *err);

/** Abandons an output: closes and removes the temporary, clears o. A cleared o is a no-op. */
GENERIC_API void gfile_output_abort(GFileOutput *o);

#ifdef __cplusplus
}
#endif
#endif
