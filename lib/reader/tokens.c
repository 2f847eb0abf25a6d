/* tokens.c - the token stream: sources, look-ahead, replays of kept texts for `like`, recording. */
#include "tokens.h"
#include "reader_library.h"
#include "generic/memory.h"

#include <string.h>

struct GReplay {
    GReplay *prev;
    GSpan *spans;
    int n, i;
    int lexing; /* spans[i] is being scanned by lx */
    GLexer lx;
    const char *via;
    int has_saved; /* the look-ahead token that was there when the replay began */
    int saved_text;
    const char *saved_via;
    GLexToken saved;
};

static void copy_token(GLexToken *to, const GLexToken *from)
{
    to->tok = from->tok;
    to->start = from->start;
    to->end = from->end;
    memcpy(to->text, from->text, strlen(from->text) + 1);
    to->tok.text = to->text;
}

void gtokens_init(GTokens *ts, GLibrary *lib)
{
    memset(ts, 0, sizeof *ts);
    ts->lib = lib;
    ts->cur.tok.line = ts->cur.tok.col = 1;
    ts->cur.tok.text = ts->cur.text;
    ts->cur_text = ts->ahead_text = -1;
}

static void free_replay(GReplay *p)
{
    gmem_free(p->spans);
    gmem_free(p);
}

void gtokens_fini(GTokens *ts)
{
    while (ts->replay) {
        GReplay *p = ts->replay;
        ts->replay = p->prev;
        free_replay(p);
    }
    while (ts->src)
        gtokens_pop_source(ts);
}

/* ---- sources ---- */

int gtokens_push_source(GTokens *ts, GReaderSource *s, GError *err)
{
    /* the library keeps every text read, so that `like` can re-read an entry of a file already closed */
    char *kept = s->text;
    s->text = NULL;
    size_t budget = s->budget;
    s->budget = 0;
    if (glibrary_keep_text(ts->lib, kept, s->len, budget, s->name, &s->text_id) != G_OK) {
        greader_source_free(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    s->parent = ts->src;
    ts->src = s;
    ts->have_ahead = 0;
    glexer_init(&s->lx, s->name, kept, s->len);
    return G_OK;
}

void gtokens_pop_source(GTokens *ts)
{
    GReaderSource *s = ts->src;
    ts->src = s->parent;
    ts->have_ahead = 0;
    greader_source_free(s);
}

/* ---- reading ---- */

/* The next token of the innermost replay into ts->ahead: 1 when one was given, 0 when no replay is left. */
static int replay_fill(GTokens *ts, int *placed, GError *err)
{
    while (ts->replay) {
        GReplay *p = ts->replay;
        if (p->lexing) {
            const GSpan *sp = &p->spans[p->i];
            int rc = glexer_next(&p->lx, &ts->ahead, err);
            if (rc != G_OK)
                return rc;
            if (ts->ahead.tok.type != GTOK_EOF) {
                ts->ahead.start += sp->start;
                ts->ahead.end += sp->start;
                ts->ahead_text = sp->text;
                ts->ahead_via = p->via;
                ts->have_ahead = 1;
                unsigned long long limit = GREADER_LIKE_FACTOR * ts->lexed + GREADER_LIKE_SLACK;
                if (++ts->replayed > limit) {
                    ts->have_ahead = 0;
                    *placed = 0;
                    gerror_set(err, G_ERR_PARSE,
                               "entries derived with 'like' re-read more than %llu tokens (at most %d times the tokens "
                               "of the files, plus %d)",
                               limit, GREADER_LIKE_FACTOR, GREADER_LIKE_SLACK);
                    return G_ERR_PARSE;
                }
                return 1;
            }
            p->lexing = 0;
            p->i++;
        }
        if (p->i < p->n) {
            const GSpan *sp = &p->spans[p->i];
            size_t len = 0;
            const char *name = NULL;
            const char *text = glibrary_text(ts->lib, sp->text, &len, &name);
            if (!text || sp->end > len || sp->start > sp->end) { /* cannot happen: spans are made by the reader */
                p->i++;
                continue;
            }
            glexer_init(&p->lx, name, text + sp->start, sp->end - sp->start);
            p->lx.pos = 0; /* a span never begins with a byte-order mark */
            p->lx.line = sp->line;
            p->lx.col = sp->col;
            p->lexing = 1;
            continue;
        }
        ts->replay = p->prev;
        if (p->has_saved) {
            copy_token(&ts->ahead, &p->saved);
            ts->ahead_text = p->saved_text;
            ts->ahead_via = p->saved_via;
            ts->have_ahead = 1;
            free_replay(p);
            return 1;
        }
        free_replay(p);
    }
    return 0;
}

int gtokens_fill(GTokens *ts, int *placed, GError *err)
{
    *placed = 1;
    if (ts->have_ahead)
        return G_OK;
    int rc = replay_fill(ts, placed, err);
    if (rc != 0)
        return rc < 0 ? rc : G_OK;
    rc = glexer_next(&ts->src->lx, &ts->ahead, err);
    if (rc != G_OK)
        return rc;
    ts->ahead_text = ts->src->text_id;
    ts->ahead_via = NULL;
    ts->lexed++;
    ts->have_ahead = 1;
    return G_OK;
}

void gtokens_take(GTokens *ts)
{
    copy_token(&ts->cur, &ts->ahead);
    ts->cur_text = ts->ahead_text;
    ts->cur_via = ts->ahead_via;
    ts->have_ahead = 0;
    /* a token re-read for a value nested in the entry (another `like`) is not the entry's */
    if (ts->rec && (!ts->cur_via || ts->cur_via == ts->rec_via))
        gtemplate_add_token(ts->rec, (GSpan){ts->cur_text, ts->cur.start, ts->cur.end, ts->cur.tok.line,
                                             ts->cur.tok.col});
}

GSpan gtokens_ahead_span(const GTokens *ts)
{
    GSpan s = {ts->ahead_text, ts->ahead.start, ts->ahead.end, ts->ahead.tok.line, ts->ahead.tok.col};
    return s;
}

int gtokens_origin(const GTokens *ts, int line, int col, int *text, const char **via)
{
    if (ts->cur.tok.line == line && ts->cur.tok.col == col) {
        *text = ts->cur_text;
        *via = ts->cur_via;
        return 1;
    }
    if (ts->have_ahead && ts->ahead.tok.line == line && ts->ahead.tok.col == col) {
        *text = ts->ahead_text;
        *via = ts->ahead_via;
        return 1;
    }
    return 0;
}

/* ---- replays and recording ---- */

int gtokens_replay(GTokens *ts, GSpan *spans, int n, const char *via)
{
    GReplay *p = gmem_calloc(1, sizeof *p);
    if (!p) {
        gmem_free(spans);
        return G_ERR_NOMEM;
    }
    p->spans = spans;
    p->n = n;
    p->via = via;
    if (ts->have_ahead) {
        p->has_saved = 1;
        copy_token(&p->saved, &ts->ahead);
        p->saved_text = ts->ahead_text;
        p->saved_via = ts->ahead_via;
        ts->have_ahead = 0;
    }
    p->prev = ts->replay;
    ts->replay = p;
    return G_OK;
}

void gtokens_record(GTokens *ts, GTemplate *t, const char *via)
{
    ts->rec = t;
    ts->rec_via = via;
}

void gtokens_record_stop(GTokens *ts)
{
    ts->rec = NULL;
    ts->rec_via = NULL;
}
