/* exr_core_lib.c - OpenEXRCore loaded on first use (exr_core_lib.h), through gdynlib_open. */
#include "exr_core_lib.h"

#include "generic/services/dynlib.h"

#ifndef GENERIC_EXRCORE_SONAME
#define GENERIC_EXRCORE_SONAME "libOpenEXRCore-3_1.so.30"
#endif

static ExrCoreLib lib;

#define ENTRY(field) {"exr_" #field, &lib.field}
static const GDynLibSymbol symbols[] = {
    ENTRY(start_write), ENTRY(add_part), ENTRY(initialize_required_attr), ENTRY(add_channel),
    ENTRY(attr_set_string), ENTRY(write_header), ENTRY(get_scanlines_per_chunk), ENTRY(write_scanline_chunk_info),
    ENTRY(encoding_initialize), ENTRY(encoding_update), ENTRY(encoding_choose_default_routines),
    ENTRY(encoding_run), ENTRY(encoding_destroy), ENTRY(finish), ENTRY(get_default_error_message),
};

static GDynLib exr_core = GDYNLIB_INIT(GENERIC_EXRCORE_SONAME, symbols, sizeof symbols / sizeof symbols[0]);

const ExrCoreLib *exr_core_lib(const char *path, GError *err)
{
    if (gdynlib_open(&exr_core))
        return &lib;
    gerror_set(err, G_ERR_IO, "%s: cannot write image: OpenEXR files need OpenEXRCore (%s), which cannot be loaded: "
               "%s", path, GENERIC_EXRCORE_SONAME, exr_core.why);
    return NULL;
}
