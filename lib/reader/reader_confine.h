/* reader_confine.h - GReaderOptions.confine_dir: the check that a path lies under a directory
 * (lib/reader/reader_confine.c). Private. */
#ifndef GENERIC_LIB_READER_CONFINE_H
#define GENERIC_LIB_READER_CONFINE_H

#include "generic/export.h"
#include "generic/error.h"

/** G_OK when path (resolved with its symbolic links; the file itself need not exist) lies under the directory
 * dir, with *real a gmem_alloc copy of the resolved path; G_ERR_INVALID naming both otherwise (or G_ERR_IO when
 * either cannot be resolved), *real NULL. */
GENERIC_NODISCARD int greader_confine(const char *dir, const char *path, char **real, GError *err);

#endif
