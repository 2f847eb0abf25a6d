/* builtins.h - the built-in types: every GENERIC_TYPE record (plugin.h) in the library's own sources, in a list
 * generated at build time (scripts/gen_builtins.sh), the only place that lists them.
 *
 * The registry starts empty; a program that wants the built-in colour models, colour literals, materials,
 * texture nodes and generators registers them once, before it reads files or creates models by name:
 *
 *     GError err;
 *     if (generic_register_builtins(&err) != G_OK) { fprintf(stderr, "%s\n", err.message); return 1; }
 *
 * A program may instead register only some of them (gregistry_add with records of generic_builtin_types())
 * and take others from run-time modules. */
#ifndef GENERIC_BUILTINS_H
#define GENERIC_BUILTINS_H

#include "export.h"
#include "error.h"
#include "registry.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The NULL-terminated list of built-in type records, in the order they register (by source file). */
GENERIC_API const GTypeInfo *const *generic_builtin_types(void);

/** Registers every built-in type (gregistry_add_list): idempotent and thread safe; G_ERR_EXISTS when a module
 * registered one of the built-in names before. */
GENERIC_API GENERIC_NODISCARD int generic_register_builtins(GError *err);

#ifdef __cplusplus
}
#endif
#endif
