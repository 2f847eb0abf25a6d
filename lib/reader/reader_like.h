/* reader_like.h - entries derived from others with `like` (lib/reader/reader_like.c). Private. */
#ifndef GENERIC_LIB_READER_LIKE_H
#define GENERIC_LIB_READER_LIKE_H

#include "generic/export.h"
#include "reader_state.h"

/** Longest chain of entries derived from each other with `like`. */
#define GREADER_MAX_LIKE_DEPTH 32

/** `KIND NAME like BASE [{ overrides }]` after `like`: reads BASE and the entry, defines NAME (its keyword at
 * line:col). */
GENERIC_NODISCARD int greader_like_entry(GReader *r, GKind kind, const char *name, int line, int col, GError *err);
/** Frees the messages of `like`. */
void greader_like_fini(GReader *r);

#endif
