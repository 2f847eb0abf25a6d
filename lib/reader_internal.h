/* reader_internal.h - state shared by the reader's files (lib/reader*.c, lib/colorparse.c). Private. */
#ifndef GENERIC_LIB_READER_INTERNAL_H
#define GENERIC_LIB_READER_INTERNAL_H

#include "generic/export.h"
#include "generic/reader.h"
#include "lexer.h"

/* ---- the library (lib/reader_library.c) ---- */

/** Adds an entry: owned entries are released with the library; toplevel ones are listed. On failure an owned
 * object is released at once. */
GENERIC_NODISCARD int glibrary_put(GLibrary *lib, const GTypeInfo *type, const char *name, void *object, int owned, int toplevel,
                 GError *err);
/** Releases an object the way its type (or kind) says. */
void gtype_release(const GTypeInfo *type, void *object);
/** The type an object of the library was defined with (by name), or NULL. */
const GTypeInfo *glibrary_find_type(const GLibrary *lib, GKind kind, const char *name);
/** Comma separated names defined in a kind (for messages). */
void glibrary_names(const GLibrary *lib, GKind kind, char *buf, size_t size);
/** Sets the model: `owned` is destroyed with the library. */
void glibrary_set_model(GLibrary *lib, GColorModel *owned, const GColorModel *borrowed);
/** The model, or NULL when none has been chosen yet. */
const GColorModel *glibrary_model_or_null(const GLibrary *lib);

/* ---- confinement (lib/reader_confine.c) ---- */

/** G_OK when path (resolved with its symbolic links; the file itself need not exist) lies under the directory
 * dir, with *real a gmem_alloc copy of the resolved path; G_ERR_INVALID naming both otherwise (or G_ERR_IO when
 * either cannot be resolved), *real NULL. */
GENERIC_NODISCARD int greader_confine(const char *dir, const char *path, char **real, GError *err);

/* ---- the reader (lib/reader.c) ---- */

/** A parameter name of an entry and where it was written (a constructor's complaint about it is placed there). */
typedef struct GReaderKey {
    char *name;
    int line, col;
} GReaderKey;

/** A frame on the nesting stack: an entry being parsed or a positional block. */
typedef struct GReaderFrame {
    int is_block;          /* 1 for greader_block_begin blocks */
    int state;             /* entries: 0 = block not looked for, 1 = inside `{`, 2 = done */
    int open_line, open_col;
    const GTypeInfo *type; /* entries: the type being read */
    GReaderKey *keys;      /* entries: parameter names seen, in order */
    int nkeys, capkeys;
} GReaderFrame;

typedef struct GReaderSource GReaderSource;

/** One file (or text) being read; parent is the file that includes it. */
struct GReaderSource {
    GReaderSource *parent;
    GLexer lx;
    char *text; /* owned contents */
    char *name; /* as shown in messages */
    char *dir;  /* for relative paths */
    char *real; /* canonical path for cycle detection (NULL for text in memory) */
};

/* ---- sources (lib/reader_source.c) ---- */

/** Reads a whole file of at most limit bytes (errors name the file, without a position). */
GENERIC_NODISCARD int greader_read_file(const char *path, size_t limit, char **text, size_t *len, GError *err);
/** Makes s (with its name set) the current source over text. */
GENERIC_NODISCARD int greader_push_source(GReader *r, GReaderSource *s, const char *text, size_t len);
/** Opens a file as the new current source; takes ownership of name. */
GENERIC_NODISCARD int greader_open_source(GReader *r, char *name, GError *err);
/** Returns to the including source, freeing the current one. */
void greader_pop_source(GReader *r);
/** Frees every open source. */
void greader_pop_all_sources(GReader *r);
/** Frees a source that was never pushed; NULL is a no-op. */
void greader_free_source(GReaderSource *s);

struct GReader {
    GLibrary *lib;
    GReaderOptions opt;
    GReaderSource *src;
    int include_depth;
    int model_fixed; /* colours have been read in the library's model */
    int model_pending; /* opt.colormodel is still to be created (after the plugin statements before the first entry) */
    int located;     /* the error in *err carries a position */
    GLexToken cur, ahead;
    int have_ahead;
    GReaderFrame *frames;
    int nframes, capframes;
    char keybuf[GLEX_TEXT_MAX];
    char **included; /* canonical paths of files included completely (each is read once) */
    int nincluded, capincluded;
};

/** Consumes the token a successful greader_peek just returned (it cannot fail, so it has no status). */
void greader_take(GReader *r, GToken *tok);
/** Pushes a frame, checking the nesting limit at (line, col). */
GENERIC_NODISCARD int greader_push_frame(GReader *r, int is_block, const GTypeInfo *type, int line, int col, GError *err);
/** Pops frames down to n. */
void greader_pop_frames(GReader *r, int n);
/** Total nesting (frames and includes). */
int greader_depth(const GReader *r);
/** Finds a type of a kind; materials and nodes look in each other's table. */
const GTypeInfo *greader_find_type(GKind kind, const char *name);
/** Reads a VALUE: a nested entry or a name; add = 0 leaves a new object to the caller (*owned set to 1). */
GENERIC_NODISCARD int greader_value(GReader *r, GKind kind, int add, void **object, const GTypeInfo **type, int *owned,
                  GError *err);
/** Parses an entry of a known type (its keyword consumed at line:col) and returns the new object. */
GENERIC_NODISCARD int greader_invoke(GReader *r, const GTypeInfo *type, int line, int col, void **object, GError *err);
/** Parses the options block of a colour model type and creates the model. */
GENERIC_NODISCARD int greader_colormodel_entry(GReader *r, const GTypeInfo *type, GColorModel **out, GError *err);

#endif
