/* reader_entry.h - entries: calling a type's parse routine, and values that are a nested entry or the name of one
 * (lib/reader/reader_entry.c). Private. */
#ifndef GENERIC_LIB_READER_ENTRY_H
#define GENERIC_LIB_READER_ENTRY_H

#include "generic/export.h"
#include "reader_state.h"

/** Finds a type of a kind, else of another kind of its namespace (materials and nodes look in each other's table). */
const GTypeInfo *greader_find_type(GKind kind, const char *name);
/** "lambert, phong, ..." for a kind, then for the other kinds of its namespace (materials also list node types). */
void greader_type_names(GKind kind, char *buf, size_t size);
/** Reads a VALUE: a nested entry or a name; add = 0 leaves a new object to the caller (*owned set to 1). A defined
 * name that is also a type keyword is the defined entry unless `{` follows it (then a new entry of that type);
 * a type whose first parameter is positional always wins. */
GENERIC_NODISCARD int greader_value(GReader *r, GKind kind, int add, void **object, const GTypeInfo **type, int *owned,
                                    GError *err);
/** Parses an entry of a known type (its keyword consumed at line:col) and returns the new object. */
GENERIC_NODISCARD int greader_invoke(GReader *r, const GTypeInfo *type, int line, int col, void **object, GError *err);

#endif
