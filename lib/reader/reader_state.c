/* reader_state.c - where the reader is: tokens from the stream, the nesting stack of entries and blocks, and
 * errors placed at positions with the file (and `like`) each position comes from. */
#include "reader_state.h"
#include "generic/kit/texparam.h"
#include "generic/memory.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- errors ---- */

/* The file name and `like` message of a position (line, col) the reader reports: the origin of the current or
 * look-ahead token, or of a parameter name of an open entry, with that position; else the current file. */
static void origin(const GReader *r, int line, int col, const char **file, const char **via)
{
    int text = -1;
    const char *v = NULL;
    if (!gtokens_origin(&r->ts, line, col, &text, &v))
        for (int i = r->nframes - 1; i >= 0 && text < 0; i--)
            for (int k = 0; k < r->frames[i].nkeys; k++)
                if (r->frames[i].keys[k].line == line && r->frames[i].keys[k].col == col) {
                    text = r->frames[i].keys[k].text;
                    v = r->frames[i].keys[k].via;
                    break;
                }
    const char *name = NULL;
    if (text < 0 || !glibrary_text(r->lib, text, NULL, &name))
        name = r->ts.src ? r->ts.src->name : "?";
    *file = name;
    *via = v;
}

static int verror_at(GReader *r, GError *err, int code, int line, int col, const char *fmt, va_list ap)
{
    char msg[sizeof err->message];
    vsnprintf(msg, sizeof msg, fmt, ap);
    r->located = 1;
    const char *file = NULL, *via = NULL;
    origin(r, line, col, &file, &via);
    gerror_set(err, code, "%s:%d:%d: %s%s%s", file, line, col, msg, via ? " " : "", via ? via : "");
    if (err) {
        err->line = line;
        err->col = col;
    }
    return code;
}

int greader_error_at(GReader *r, GError *err, int code, int line, int col, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int rc = verror_at(r, err, code, line, col, fmt, ap);
    va_end(ap);
    return rc;
}

int greader_error(GReader *r, GError *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int rc = verror_at(r, err, G_ERR_PARSE, r->ts.cur.tok.line, r->ts.cur.tok.col, fmt, ap);
    va_end(ap);
    return rc;
}

/* Where the innermost entry being read wrote its parameter `name`: 1 with *line, *col, else 0. */
static int param_position(const GReader *r, const char *name, int *line, int *col)
{
    for (int i = r->nframes - 1; i >= 0; i--) {
        const GReaderFrame *f = &r->frames[i];
        if (f->is_block)
            continue;
        for (int k = 0; k < f->nkeys; k++)
            if (strcmp(f->keys[k].name, name) == 0) {
                *line = f->keys[k].line;
                *col = f->keys[k].col;
                return 1;
            }
        return 0;
    }
    return 0;
}

int greader_locate(GReader *r, GError *err)
{
    if (!err)
        return G_ERR_PARSE;
    int code = err->code < 0 ? err->code : G_ERR_PARSE;
    if (r->located)
        return code;
    int line = r->ts.cur.tok.line, col = r->ts.cur.tok.col;
    char param[sizeof err->param];
    snprintf(param, sizeof param, "%s", err->param);
    int at_param = param[0] && param_position(r, param, &line, &col);
    if (!at_param && r->ts.cur_via) /* past a re-read token: the entry derived with `like` says it */
        for (int i = r->nframes - 1; i >= 0; i--)
            if (!r->frames[i].is_block && r->frames[i].like_line) {
                line = r->frames[i].like_line;
                col = r->frames[i].like_col;
                break;
            }
    char msg[sizeof err->message];
    snprintf(msg, sizeof msg, "%s", err->message[0] ? err->message : gstatus_string(code));
    code = greader_error_at(r, err, code, line, col, "%s", msg);
    memcpy(err->param, param, sizeof param);
    return code;
}

static const char *token_type_name(int type)
{
    switch (type) {
    case GTOK_IDENT: return "a name";
    case GTOK_NUMBER: return "a number";
    case GTOK_STRING: return "a quoted string";
    case GTOK_LBRACE: return "'{'";
    case GTOK_RBRACE: return "'}'";
    case GTOK_LANGLE: return "'<'";
    case GTOK_RANGLE: return "'>'";
    case GTOK_COMMA: return "','";
    default: return "end of file";
    }
}

int greader_expected(GReader *r, const char *what, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    char found[96];
    glexer_describe(&t, found, sizeof found);
    const GReaderFrame *f = r->nframes ? &r->frames[r->nframes - 1] : NULL;
    while (f && f->is_block && f > r->frames)
        f--;
    if (f && f->type && !f->is_block)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s %s: expected %s, found %s",
                                gkind_name(f->type->kind), f->type->name, what, found);
    return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected %s, found %s", what, found);
}

int greader_expect(GReader *r, int type, const char *what, GError *err)
{
    int rc = greader_accept(r, type, err);
    if (rc < 0)
        return rc;
    return rc ? G_OK : greader_expected(r, what ? what : token_type_name(type), err);
}

void greader_position(GReader *r, int *line, int *col)
{
    if (line)
        *line = r->ts.cur.tok.line;
    if (col)
        *col = r->ts.cur.tok.col;
}

const char *greader_dir(GReader *r) { return r->ts.src ? r->ts.src->dir : "."; }
const char *greader_file(GReader *r) { return r->ts.src ? r->ts.src->name : "?"; }
GLibrary *greader_library(GReader *r) { return r->lib; }

/* ---- tokens ---- */

static int fill(GReader *r, GError *err)
{
    int placed = 1;
    int rc = gtokens_fill(&r->ts, &placed, err);
    if (rc == G_OK)
        return G_OK;
    if (placed) {
        r->located = 1;
        return rc;
    }
    char msg[sizeof err->message];
    snprintf(msg, sizeof msg, "%s", err ? err->message : "");
    return greader_error_at(r, err, rc, r->ts.ahead.tok.line, r->ts.ahead.tok.col, "%s", msg);
}

int greader_peek(GReader *r, GToken *tok, GError *err)
{
    int rc = fill(r, err);
    if (rc == G_OK && tok)
        *tok = r->ts.ahead.tok;
    return rc;
}

void greader_take(GReader *r, GToken *tok)
{
    gtokens_take(&r->ts);
    if (tok)
        *tok = r->ts.cur.tok;
}

int greader_next(GReader *r, GToken *tok, GError *err)
{
    int rc = fill(r, err);
    if (rc != G_OK)
        return rc;
    greader_take(r, tok);
    return G_OK;
}

int greader_accept(GReader *r, int type, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != type)
        return 0;
    rc = greader_next(r, NULL, err);
    return rc ? rc : 1;
}

/* ---- the nesting stack ---- */

int greader_depth(const GReader *r) { return r->nframes + r->include_depth; }

int greader_push_frame(GReader *r, int is_block, const GTypeInfo *type, int line, int col, GError *err)
{
    if (greader_depth(r) + 1 > r->opt.max_depth)
        return greader_error_at(r, err, G_ERR_PARSE, line, col,
                                "nesting deeper than %d levels (entries, blocks and includes)", r->opt.max_depth);
    if (r->nframes == r->capframes) {
        int cap = r->capframes ? r->capframes * 2 : 16;
        GReaderFrame *f = gmem_realloc(r->frames, (size_t)cap * sizeof *f);
        if (!f)
            return greader_error_at(r, err, G_ERR_NOMEM, line, col, "out of memory");
        r->frames = f;
        r->capframes = cap;
    }
    GReaderFrame *f = &r->frames[r->nframes++];
    memset(f, 0, sizeof *f);
    f->is_block = is_block;
    f->type = type;
    if (!is_block) { /* the entry `like`, greader_material_with or a named entry's recording is reading */
        f->like = r->pending_like;
        f->via = r->pending_via;
        if (f->via)
            f->like_line = line, f->like_col = col;
        f->single = r->pending_single;
        f->single_state = f->single ? 1 : 0;
        f->rec = r->pending_rec;
        if (f->rec)
            gtokens_record(&r->ts, f->rec, f->via);
        r->pending_like = NULL;
        r->pending_via = NULL;
        r->pending_single = NULL;
        r->pending_rec = NULL;
    }
    f->open_line = line;
    f->open_col = col;
    return G_OK;
}

void greader_pop_frames(GReader *r, int n)
{
    while (r->nframes > n) {
        GReaderFrame *f = &r->frames[--r->nframes];
        if (f->rec)
            gtokens_record_stop(&r->ts);
        for (int i = 0; i < f->nkeys; i++)
            gmem_free(f->keys[i].name);
        gmem_free(f->keys);
        if (f->texcolor)
            gtexparam_color_release(f->texcolor);
        gmem_free(f->texcolor);
        gmem_free(f->tex_param);
    }
}
