/* check_file.h - `gmat check` as a function (check_file.c), the entry point a binding calls through libgmat.so
 * (examples/build.mk), so that types a program registers at run time (a binding's own) are checked in its
 * process. Exported from libgmat.so; everything else of gmat stays hidden. */
#ifndef GMAT_CHECK_FILE_H
#define GMAT_CHECK_FILE_H

#include <generic/error.h>

#define GMAT_EMBED_API __attribute__((visibility("default")))

/** Runs `gmat check FILE MATERIAL [--colormodel M] [--samples N]` (allow_plugins: --allow-plugins) in this
 * process, its report on standard output. 0 when every property passes, 1 when one fails, or a negative status
 * with err set when the file cannot be read or has no such material. */
GMAT_EMBED_API int gmat_check_file(const char *file, const char *material, const char *colormodel, int samples,
                                   int allow_plugins, GError *err);

#endif
