/* builtins.h - the table of built-in types (lib/builtins.c), read by the registry on first use. */
#ifndef GENERIC_LIB_BUILTINS_H
#define GENERIC_LIB_BUILTINS_H

#include "generic/registry.h"

/** NULL-terminated list of the built-in types. */
const GTypeInfo *const *gbuiltin_types(void);

#endif
