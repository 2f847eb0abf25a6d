/* plugin_elf.h - what the module loader checks in a file before dlopen runs any of its code. Private. */
#ifndef GENERIC_LIB_PLUGIN_ELF_H
#define GENERIC_LIB_PLUGIN_ELF_H

#include "generic/export.h"
#include "generic/error.h"

/** Reads the open file fd (named path in messages) as an ELF shared object without running it: it must be a
 * regular file holding a shared object (ET_DYN) of this machine's class, byte order and architecture whose
 * dynamic symbol table defines both module symbols (generic_module_abi, an int, and generic_module_init, a
 * function). *abi receives the value of generic_module_abi when the file holds it (-1 when it cannot be read
 * from the file). G_ERR_IO with a message saying what is missing otherwise. */
GENERIC_NODISCARD int gplugin_elf_check(int fd, const char *path, int *abi, GError *err);

#endif
