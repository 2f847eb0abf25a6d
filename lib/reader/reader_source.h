/* reader_source.h - one file (or text) being read: its contents, loaded whole, and the scanner over them. Private. */
#ifndef GENERIC_LIB_READER_SOURCE_H
#define GENERIC_LIB_READER_SOURCE_H

#include <stddef.h>
#include "generic/export.h"
#include "generic/error.h"
#include "lexer.h"

typedef struct GReaderSource GReaderSource;

/** One file (or text) being read; parent is the file that includes it. */
struct GReaderSource {
    GReaderSource *parent;
    GLexer lx;
    char *text;  /* the contents (gmem_alloc'd, NUL-terminated) until the library keeps them, then NULL */
    size_t len;
    char *name;  /* as shown in messages */
    char *dir;   /* for relative paths */
    char *real;  /* canonical path for cycle detection (NULL for text in memory) */
    int text_id; /* the library's copy of the text (glibrary_keep_text) */
    size_t budget; /* bytes of the text reserved against the memory budget (the library's once it keeps it) */
};

/** Reads the file name (taken over: owned by the source from here on, freed on failure) into a new source, its
 * size reserved against the memory budget (gmem_budget_reserve) before it is read; max_size > 0 is a limit of its
 * own on the file's size. */
GENERIC_NODISCARD int greader_source_file(char *name, size_t max_size, GReaderSource **out, GError *err);
/** A new source over a copy of text held in memory, named name in messages; relative paths resolve against the
 * current directory. */
GENERIC_NODISCARD int greader_source_string(const char *name, const char *text, GReaderSource **out, GError *err);
/** Frees a source (not its parent); NULL is a no-op. */
void greader_source_free(GReaderSource *s);

#endif
