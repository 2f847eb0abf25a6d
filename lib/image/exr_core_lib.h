/* exr_core_lib.h - OpenEXRCore (OpenEXR's C library) loaded on first use: a process that writes no OpenEXR file
 * never maps it. The functions image_exr.c calls, resolved by gdynlib_open (generic/services/dynlib.h) from the
 * library's soname (GENERIC_EXRCORE_SONAME, the build's libOpenEXRCore.so's; lib/build.mk), once per process. */
#ifndef GENERIC_EXR_CORE_LIB_H
#define GENERIC_EXR_CORE_LIB_H

#include "generic/error.h"

#include <OpenEXR/openexr.h>

/** The entries of OpenEXRCore, each with the prototype of the function of the same name (exr_ prefix dropped). */
typedef struct ExrCoreLib {
    __typeof__(&exr_start_write) start_write;
    __typeof__(&exr_add_part) add_part;
    __typeof__(&exr_initialize_required_attr) initialize_required_attr;
    __typeof__(&exr_add_channel) add_channel;
    __typeof__(&exr_attr_set_string) attr_set_string;
    __typeof__(&exr_write_header) write_header;
    __typeof__(&exr_get_scanlines_per_chunk) get_scanlines_per_chunk;
    __typeof__(&exr_write_scanline_chunk_info) write_scanline_chunk_info;
    __typeof__(&exr_encoding_initialize) encoding_initialize;
    __typeof__(&exr_encoding_update) encoding_update;
    __typeof__(&exr_encoding_choose_default_routines) encoding_choose_default_routines;
    __typeof__(&exr_encoding_run) encoding_run;
    __typeof__(&exr_encoding_destroy) encoding_destroy;
    __typeof__(&exr_finish) finish;
    __typeof__(&exr_get_default_error_message) get_default_error_message;
} ExrCoreLib;

/** The library's entries, loaded at the first call (thread-safe); NULL with G_ERR_IO in err, naming the soname and
 * the loader's reason, when it cannot be loaded or lacks one of them. path names the file being written. */
const ExrCoreLib *exr_core_lib(const char *path, GError *err);

#endif
