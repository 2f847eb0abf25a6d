/* tokens.h - the token stream the reader reads: tokens scanned from the files being read (a stack of sources, each
 * file above the one that includes it), one token of look-ahead, stretches of kept texts re-read for `like`
 * (replays, innermost first), and the recording of a named entry's tokens into its template. Tokens flow one way:
 * the reader asks for the next one and takes it; nothing above patches the stream. Private.
 *
 * Bounds: a load re-reads at most GREADER_LIKE_FACTOR times the tokens it scanned from files (plus
 * GREADER_LIKE_SLACK), so no input makes the reader quadratic. */
#ifndef GENERIC_LIB_READER_TOKENS_H
#define GENERIC_LIB_READER_TOKENS_H

#include "generic/export.h"
#include "generic/reader.h"
#include "lexer.h"
#include "reader_source.h"
#include "template.h"

/** Re-read tokens allowed for `like`: this many times the tokens read from files, plus GREADER_LIKE_SLACK. */
#define GREADER_LIKE_FACTOR 16
#define GREADER_LIKE_SLACK 100000

typedef struct GReplay GReplay;

/** The stream. Fields are read by the reader; only the functions below change them. */
typedef struct GTokens {
    GLibrary *lib;        /* keeps every source text (re-read by replays) */
    GReaderSource *src;   /* the file being read */
    GLexToken cur, ahead; /* the token taken last, and the look-ahead token when have_ahead */
    int have_ahead;
    int cur_text, ahead_text;        /* the kept text each comes from */
    const char *cur_via, *ahead_via; /* re-read for `like`: its message (NULL: written where it stands) */
    GReplay *replay;                 /* stretches being re-read, innermost first */
    GTemplate *rec;                  /* the template taken tokens are recorded into (NULL: none) */
    const char *rec_via;             /* ... the tokens re-read with this message too (the entry's own `like`) */
    unsigned long long lexed, replayed; /* tokens scanned from files, and re-read */
} GTokens;

/** An empty stream over the texts of lib. */
void gtokens_init(GTokens *ts, GLibrary *lib);
/** Frees the replays and every open source. */
void gtokens_fini(GTokens *ts);

/** Makes s (taken over) the source read from here on, above the current one; its text goes to the library.
 * On failure s is freed. */
GENERIC_NODISCARD int gtokens_push_source(GTokens *ts, GReaderSource *s, GError *err);
/** Returns to the source that included the current one, freeing it. */
void gtokens_pop_source(GTokens *ts);

/** Makes the next token the look-ahead (ts->ahead), unless there is one already. On failure err holds the message
 * and *placed says whether it is in its final form, placed in its file (a lexical error): 0 is a message about the
 * token in ts->ahead (not kept as look-ahead) for the caller to place. */
GENERIC_NODISCARD int gtokens_fill(GTokens *ts, int *placed, GError *err);
/** The look-ahead token becomes the current one (after a successful gtokens_fill), recorded when a template is. */
void gtokens_take(GTokens *ts);
/** The span of the look-ahead token (for templates). */
GSpan gtokens_ahead_span(const GTokens *ts);
/** 1 with the kept text and `like` message of the current or look-ahead token when it stands at (line, col). */
int gtokens_origin(const GTokens *ts, int line, int col, int *text, const char **via);

/** Re-reads the spans (n > 0, taken over; freed on failure) before anything else, with the `like` message via;
 * a look-ahead token comes after them. G_ERR_NOMEM. */
GENERIC_NODISCARD int gtokens_replay(GTokens *ts, GSpan *spans, int n, const char *via);

/** Records every token taken from here on into t, except those re-read with a message other than via. */
void gtokens_record(GTokens *ts, GTemplate *t, const char *via);
/** Stops recording. */
void gtokens_record_stop(GTokens *ts);

#endif
