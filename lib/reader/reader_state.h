/* reader_state.h - the reader a parse routine reads with (GReader): its options, the token stream, the stack of
 * entries and blocks being read, and errors placed at positions (lib/reader/reader_state.c). Private. */
#ifndef GENERIC_LIB_READER_STATE_H
#define GENERIC_LIB_READER_STATE_H

#include "generic/export.h"
#include "generic/reader.h"
#include "reader_library.h"
#include "tokens.h"

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
    GTemplate *rec;        /* entries: the template this entry is recorded into (NULL: not recorded) */
    const GTemplate *like; /* entries derived with `like`: the base's parameters still to merge */
    const char *via;       /* ... and where (message suffix for errors in inherited parameters) */
    int like_line, like_col; /* entries derived with `like`: where (the base's name), else 0 */
    const char *single;    /* greader_material_with: the one parameter given (its value at the reader's position) */
    int single_state;      /* 1: its name is still to be returned, 2: its value was read, the block closes next */
    GReaderKey *keys;      /* entries: parameter names seen, in order */
    int nkeys, capkeys;
    int has_range;         /* generator entries: `range LO HI` was read (greader_param), applied by greader_invoke */
    double range_lo, range_hi;
    struct GTexColor *texcolor; /* material entries: a textured colour greader_color read (owned), applied by
                                   greader_invoke (gtexparam_texture_material) */
    char *tex_param;            /* ... the parameter it was read for, and where */
    int tex_line, tex_col;
} GReaderFrame;

struct GReader {
    GLibrary *lib;
    GReaderOptions opt;
    GTokens ts;
    int include_depth;
    int model_fixed;   /* colours have been read in the library's model */
    int model_pending; /* opt.colormodel is still to be created (after the plugin statements before the first entry) */
    int located;       /* the error in *err carries a position */
    GReaderFrame *frames;
    int nframes, capframes;
    char keybuf[GLEX_TEXT_MAX];
    char **included; /* canonical paths of files included completely (each is read once) */
    int nincluded, capincluded;
    /* for the next entry frame pushed: `like` and greader_material_with (lib/reader/reader_like.c), recording */
    const GTemplate *pending_like;
    const char *pending_via;
    const char *pending_single;
    GTemplate *pending_rec;
    int single_taken; /* greader_param returned greader_material_with's parameter */
    char **vias;      /* the messages of every `like` read (owned) */
    int nvias, capvias;
};

/** Consumes the token a successful greader_peek just returned (it cannot fail, so it has no status). */
void greader_take(GReader *r, GToken *tok);
/** "expected WHAT, found TOKEN" at the next token (which is not consumed), naming the entry's type. */
GENERIC_NODISCARD int greader_expected(GReader *r, const char *what, GError *err);
/** Pushes a frame, checking the nesting limit at (line, col). An entry frame takes the pending `like`,
 * greader_material_with parameter and template, and records into that template while it is open. */
GENERIC_NODISCARD int greader_push_frame(GReader *r, int is_block, const GTypeInfo *type, int line, int col,
                                         GError *err);
/** Pops frames down to n. */
void greader_pop_frames(GReader *r, int n);
/** Total nesting (frames and includes). */
int greader_depth(const GReader *r);

#endif
