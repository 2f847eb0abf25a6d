/* lexer.h - tokenizer of the text format (private to lib/; the token types are public in reader.h). */
#ifndef GENERIC_LIB_LEXER_H
#define GENERIC_LIB_LEXER_H

#include <stddef.h>
#include "generic/export.h"
#include "generic/error.h"
#include "generic/reader.h"

/** What a quiet lexer (and the reader, for a first token that is not a statement) reports. */
#define GLEX_FOREIGN_MESSAGE                                                                                \
    "not a libgeneric text file: it does not begin with a statement (include, color, material, ...; its text is " \
    "not shown)"

/** Longest token text, including the terminating NUL. */
#define GLEX_TEXT_MAX 4096

/** A token with its own text storage. */
typedef struct GLexToken {
    GToken tok;
    size_t start, end; /**< byte offsets of the token in the scanned text (for re-reading it, `like`) */
    char text[GLEX_TEXT_MAX];
} GLexToken;

/** Scanner state over a text that outlives it. */
typedef struct GLexer {
    const char *name; /**< file name used in messages */
    const char *src;
    size_t len, pos;
    int line, col;
    /** Non-zero while the text is not known to be in the format (no statement read yet): errors then quote
     * nothing of it. glexer_init clears it. */
    int quiet;
} GLexer;

/** Starts scanning text of len bytes; name is used in messages. */
void glexer_init(GLexer *lx, const char *name, const char *text, size_t len);
/** Scans the next token into out (tok.text points into out->text); on a lexical error fills err with
 * "name:line:col: message" and returns G_ERR_PARSE. At the end returns GTOK_EOF tokens forever. */
GENERIC_NODISCARD int glexer_next(GLexer *lx, GLexToken *out, GError *err);
/** A short printable description of a token for messages ("'abc'", "number 1.5", "end of file"). */
void glexer_describe(const GToken *tok, char *buf, size_t size);

#endif
