/* reader_define.h - named numeric constants, `define NAME VALUE` (lib/reader/reader_define.c). Private. */
#ifndef GENERIC_LIB_READER_DEFINE_H
#define GENERIC_LIB_READER_DEFINE_H

#include "generic/export.h"
#include "reader_state.h"

/** `define NAME NUMBER|CONSTANT` after `define`. */
GENERIC_NODISCARD int greader_define_statement(GReader *r, GError *err);

#endif
