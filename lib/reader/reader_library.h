/* reader_library.h - what the reader asks of the GLibrary it fills (lib/reader/reader_library.c): entries by kind
 * and name, the source texts it keeps, the templates of named entries and the constants. Private. */
#ifndef GENERIC_LIB_READER_LIBRARY_H
#define GENERIC_LIB_READER_LIBRARY_H

#include "generic/export.h"
#include "generic/reader.h"
#include "template.h"

/* ---- entries ---- */

/** Adds an entry: owned entries are released with the library; toplevel ones are listed. On failure an owned
 * object is released at once. */
GENERIC_NODISCARD int glibrary_put(GLibrary *lib, const GTypeInfo *type, const char *name, void *object, int owned,
                                   int toplevel, GError *err);
/** The type an object of the library was defined with (by name), or NULL. */
const GTypeInfo *glibrary_find_type(const GLibrary *lib, GKind kind, const char *name);
/** Comma separated names defined in a kind (for messages). */
void glibrary_names(const GLibrary *lib, GKind kind, char *buf, size_t size);
/** Sets the model: `owned` is destroyed with the library. */
void glibrary_set_model(GLibrary *lib, GColorModel *owned, const GColorModel *borrowed);
/** The model, or NULL when none has been chosen yet. */
const GColorModel *glibrary_model_or_null(const GLibrary *lib);

/* ---- kept texts, templates and constants ---- */

/** Keeps a source text for the life of the library (`like` re-reads it); takes ownership of text (gmem_alloc'd,
 * NUL-terminated) and of its `budget` bytes reserved against the memory budget, and copies name. *id names it. On
 * failure text is freed and its budget released. */
GENERIC_NODISCARD int glibrary_keep_text(GLibrary *lib, char *text, size_t len, size_t budget, const char *name,
                                         int *id);
/** Frees the kept texts that no entry's template reads, and cuts off a text's tail of 64 KiB or more after the last
 * byte a template reads, releasing their budget: a load's texts are needed after it only by `like`, which re-reads
 * named entries. Their names stay (messages name the files). */
void glibrary_drop_unused_texts(GLibrary *lib);
/** A kept text, its length and its file name (NULL when id is not one; "" of length 0 once dropped). */
const char *glibrary_text(const GLibrary *lib, int id, size_t *len, const char **name);
/** Gives the template to the named entry of a kind (the library frees it); on failure it is freed. */
GENERIC_NODISCARD int glibrary_set_template(GLibrary *lib, GKind kind, const char *name, GTemplate *t);
/** The template of a named entry, NULL when it has none (e.g. an alias or an entry made by code). */
const GTemplate *glibrary_template(const GLibrary *lib, GKind kind, const char *name);
/** Defines a numeric constant: G_ERR_EXISTS when the name is taken, G_ERR_NOMEM. */
GENERIC_NODISCARD int glibrary_define_constant(GLibrary *lib, const char *name, double value, int line, int col,
                                               int text);
/** 1 with *value (and where it was defined) when name is a constant, else 0. */
int glibrary_constant(const GLibrary *lib, const char *name, double *value, int *line, int *col, int *text);

#endif
