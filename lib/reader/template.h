/* template.h - what `like` re-reads of a named entry: the stretches of kept texts (spans) where the entry wrote its
 * parameters, recorded while the entry is read. The library keeps one per named entry. Private. */
#ifndef GENERIC_LIB_READER_TEMPLATE_H
#define GENERIC_LIB_READER_TEMPLATE_H

#include <stddef.h>
#include "generic/export.h"

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
    /* while recording: the end of the last token, and the parameter still open */
    int last_text;
    size_t last_end;
    int open_param;
} GTemplate;

/** Frees a template; NULL is a no-op. */
void gtemplate_free(GTemplate *t);
/** Notes a token of the entry (its span): `whole` grows by it, and the open parameter ends at the last one noted. */
void gtemplate_add_token(GTemplate *t, GSpan token);
/** Starts a parameter named name at the span of its name; the one still open ends first. G_ERR_NOMEM. */
GENERIC_NODISCARD int gtemplate_add_param(GTemplate *t, const char *name, GSpan at);
/** Ends the open parameter at the end of the last token noted (no-op when none is open). */
void gtemplate_end_param(GTemplate *t);

#endif
