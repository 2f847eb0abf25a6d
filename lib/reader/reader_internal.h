/* reader_internal.h - state shared by the reader's files (lib/reader*.c, lib/reader/colorparse.c). Private. */
#ifndef GENERIC_LIB_READER_INTERNAL_H
#define GENERIC_LIB_READER_INTERNAL_H

#include "generic/export.h"
#include "generic/reader.h"
#include "lexer.h"

/* ---- the library (lib/reader/reader_library.c) ---- */

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

/* ---- kept texts, templates and constants (lib/reader/reader_library.c) ---- */

/** A stretch of a text the library keeps: which text, its byte range, the position of its first byte. */
typedef struct GSpan {
    int text;
    size_t start, end;
    int line, col;
} GSpan;

/** One named parameter of an entry's block as written: its name and its tokens (name and value). */
typedef struct GTemplateParam {
    char *name;
    GSpan span;
} GTemplateParam;

/** What `like` re-reads of a named entry (lib/reader/reader_like.c): the parameters its routine read by name, or,
 * for a type read positionally, all its tokens. */
typedef struct GTemplate {
    int named;          /* the routine read named parameters (greader_param) */
    int has_block;      /* named: the entry had a `{ ... }` block (open, close) */
    GSpan open, close;
    GTemplateParam *params;
    int nparams, capparams;
    GSpan whole;        /* every token after the type keyword (positional types) */
    int whole_state;    /* 0 = no token yet, 1 = one text, -1 = tokens of several texts */
    int depth;          /* 0 for an entry with a type, base's + 1 for `like` */
    char *base;         /* the entry it was derived from (NULL: none) */
    /* while recording: the end of the last token consumed, and the parameter still open */
    int last_text;
    size_t last_end;
    int open_param;
} GTemplate;

/** Frees a template; NULL is a no-op. */
void gtemplate_free(GTemplate *t);
/** Keeps a source text for the life of the library (`like` re-reads it); takes ownership of text (gmem_alloc'd,
 * NUL-terminated) and copies name. *id names it. On failure text is freed. */
GENERIC_NODISCARD int glibrary_keep_text(GLibrary *lib, char *text, size_t len, const char *name, int *id);
/** A kept text, its length and its file name (NULL when id is not one). */
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

/* ---- confinement (lib/reader/reader_confine.c) ---- */

/** G_OK when path (resolved with its symbolic links; the file itself need not exist) lies under the directory
 * dir, with *real a gmem_alloc copy of the resolved path; G_ERR_INVALID naming both otherwise (or G_ERR_IO when
 * either cannot be resolved), *real NULL. */
GENERIC_NODISCARD int greader_confine(const char *dir, const char *path, char **real, GError *err);

/* ---- the reader (lib/reader/reader.c) ---- */

/** A parameter name of an entry and where it was written (a constructor's complaint about it is placed there). */
typedef struct GReaderKey {
    char *name;
    int line, col;
    int text;        /* the kept text it was read from */
    const char *via; /* inherited through `like`: where (NULL when written in the entry itself) */
} GReaderKey;

/** A frame on the nesting stack: an entry being parsed or a positional block. */
typedef struct GReaderFrame {
    int is_block;          /* 1 for greader_block_begin blocks */
    int state;             /* entries: 0 = block not looked for, 1 = inside `{`, 2 = done */
    int open_line, open_col;
    const GTypeInfo *type; /* entries: the type being read */
    const GTemplate *like; /* entries derived with `like`: the base's parameters still to merge */
    const char *via;       /* ... and where (message suffix for errors in inherited parameters) */
    int like_line, like_col; /* entries derived with `like`: where (the base's name), else 0 */
    const char *single;    /* greader_material_with: the one parameter given (its value at the reader's position) */
    int single_state;      /* 1: its name is still to be returned, 2: its value was read, the block closes next */
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
    int text_id; /* the library's copy of the text (glibrary_keep_text) */
};

typedef struct GReplay GReplay;

/* ---- sources (lib/reader/reader_source.c) ---- */

/** Makes s (with its name set) the current source over text, which the library keeps (s->text, when set, is
 * handed to it; else text is copied). On failure s is freed. */
GENERIC_NODISCARD int greader_push_source(GReader *r, GReaderSource *s, const char *text, size_t len, GError *err);
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
    /* where the current and the look-ahead token come from: kept text and `like` (NULL: written there) */
    int cur_text, ahead_text;
    const char *cur_via, *ahead_via;
    /* `like` (lib/reader/reader_like.c) */
    GReplay *replay;           /* stretches of kept texts being re-read, innermost first */
    GTemplate *rec;            /* the template of the named entry being read */
    int rec_frame;             /* ... and its frame */
    const GTemplate *pending_like; /* for the next entry frame pushed */
    const char *pending_via;
    const char *pending_single;
    int single_taken; /* greader_param returned greader_material_with's parameter */
    char **vias;               /* the messages of every `like` read (owned) */
    int nvias, capvias;
    unsigned long long lexed, replayed; /* tokens read from files, and re-read for `like` */
};

/* ---- `like` (lib/reader/reader_like.c) ---- */

/** Longest chain of entries derived from each other with `like`. */
#define GREADER_MAX_LIKE_DEPTH 32
/** Re-read tokens allowed for `like`: this many times the tokens read from files, plus GREADER_LIKE_SLACK. */
#define GREADER_LIKE_FACTOR 16
#define GREADER_LIKE_SLACK 100000

/** The next token from the innermost replay into r->ahead: 1 when one was given, 0 when no replay is left. */
GENERIC_NODISCARD int greader_replay_fill(GReader *r, GError *err);
/** Notes the token just consumed (r->cur) in the template being recorded. */
void greader_record_token(GReader *r);
/** greader_param's hooks for the entry frame f: the block opened (`{` at the ahead token), a parameter name
 * (the ahead token) is about to be taken, the block closed (`}` ahead). */
void greader_record_open(GReader *r, const GReaderFrame *f);
GENERIC_NODISCARD int greader_record_key(GReader *r, const GReaderFrame *f, const char *name);
void greader_record_close(GReader *r, const GReaderFrame *f);
/** greader_param's `like` merge for the frame f (state 0: no block of overrides follows; state 1: the block of
 * overrides ends at the ahead token, `}`): starts re-reading the base's parameters the entry does not give.
 * Returns 1 when a replay was started (peek again), 0 when nothing is inherited, negative on error. */
GENERIC_NODISCARD int greader_like_merge(GReader *r, GReaderFrame *f, GError *err);
/** `KIND NAME like BASE [{ overrides }]` after `like`: reads BASE and the entry, defines NAME. */
GENERIC_NODISCARD int greader_like_entry(GReader *r, GKind kind, const char *name, int line, int col, GError *err);
/** `define NAME NUMBER|CONSTANT` after `define`. */
GENERIC_NODISCARD int greader_define_statement(GReader *r, GError *err);
/** Frees the replays and messages of `like`. */
void greader_like_fini(GReader *r);
/** The file name and `like` message of a position (line, col) the reader reports: the origin of the current
 * or look-ahead token, or of a parameter name of an open entry, with that position; else the current file. */
void greader_origin(GReader *r, int line, int col, const char **file, const char **via);

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
