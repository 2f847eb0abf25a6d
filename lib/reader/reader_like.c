/* reader_like.c - entries derived from others: `KIND NAME like BASE { overrides }`.
 *
 * While a named entry is read, the reader records where each of its named parameters was written (a stretch of
 * a text the library keeps, GTemplate). An entry derived with `like` is read by the base's own parse routine:
 * its block of overrides comes first, and where that block closes the reader re-reads, from the kept texts, the
 * base's parameters the overrides do not name, then the base's `}`. Nothing is specific to a type, so every
 * type with named parameters (plug-ins' too) can be derived from; a type read positionally (a colour literal)
 * is re-read whole, without overrides. Tokens re-read keep their own file and position, so an error in an
 * inherited parameter is reported where the base wrote it, with the `like` that inherited it.
 *
 * Bounds: a chain of `like` is at most GREADER_MAX_LIKE_DEPTH deep (a base is always defined earlier, so there
 * is no cycle), and a load re-reads at most GREADER_LIKE_FACTOR times the tokens it read from files (plus
 * GREADER_LIKE_SLACK), so no input makes the reader quadratic. */
#include "reader_internal.h"
#include "generic/memory.h"

#include <stdio.h>
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

static void free_replay(GReplay *p)
{
    gmem_free(p->spans);
    gmem_free(p);
}

void greader_like_fini(GReader *r)
{
    while (r->replay) {
        GReplay *p = r->replay;
        r->replay = p->prev;
        free_replay(p);
    }
    for (int i = 0; i < r->nvias; i++)
        gmem_free(r->vias[i]);
    gmem_free(r->vias);
    r->vias = NULL;
    r->nvias = r->capvias = 0;
}

int greader_replay_fill(GReader *r, GError *err)
{
    while (r->replay) {
        GReplay *p = r->replay;
        if (p->lexing) {
            const GSpan *sp = &p->spans[p->i];
            int rc = glexer_next(&p->lx, &r->ahead, err);
            if (rc != G_OK) {
                r->located = 1;
                return rc;
            }
            if (r->ahead.tok.type != GTOK_EOF) {
                r->ahead.start += sp->start;
                r->ahead.end += sp->start;
                r->ahead_text = sp->text;
                r->ahead_via = p->via;
                r->have_ahead = 1;
                unsigned long long limit = GREADER_LIKE_FACTOR * r->lexed + GREADER_LIKE_SLACK;
                if (++r->replayed > limit) {
                    r->have_ahead = 0;
                    const GToken *t = &r->ahead.tok;
                    int rc2 = greader_error_at(r, err, G_ERR_PARSE, t->line, t->col,
                                               "entries derived with 'like' re-read more than %llu tokens (at most "
                                               "%d times the tokens of the files, plus %d)",
                                               limit, GREADER_LIKE_FACTOR, GREADER_LIKE_SLACK);
                    return rc2;
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
            const char *text = glibrary_text(r->lib, sp->text, &len, &name);
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
        r->replay = p->prev;
        if (p->has_saved) {
            r->ahead.tok = p->saved.tok;
            r->ahead.start = p->saved.start;
            r->ahead.end = p->saved.end;
            memcpy(r->ahead.text, p->saved.text, strlen(p->saved.text) + 1);
            r->ahead.tok.text = r->ahead.text;
            r->ahead_text = p->saved_text;
            r->ahead_via = p->saved_via;
            r->have_ahead = 1;
            free_replay(p);
            return 1;
        }
        free_replay(p);
    }
    return 0;
}

/* Starts re-reading spans (taken over; n > 0), keeping a token already looked at for after them. */
static int push_replay(GReader *r, GSpan *spans, int n, const char *via, GError *err)
{
    GReplay *p = gmem_calloc(1, sizeof *p);
    if (!p) {
        gmem_free(spans);
        return greader_error(r, err, "out of memory");
    }
    p->spans = spans;
    p->n = n;
    p->via = via;
    if (r->have_ahead) {
        p->has_saved = 1;
        p->saved.tok = r->ahead.tok;
        p->saved.start = r->ahead.start;
        p->saved.end = r->ahead.end;
        memcpy(p->saved.text, r->ahead.text, strlen(r->ahead.text) + 1);
        p->saved.tok.text = p->saved.text;
        p->saved_text = r->ahead_text;
        p->saved_via = r->ahead_via;
        r->have_ahead = 0;
    }
    p->prev = r->replay;
    r->replay = p;
    return G_OK;
}

/* ---- recording ---- */

static GTemplate *recording(GReader *r, const GReaderFrame *f)
{
    return r->rec && r->rec_frame < r->nframes && f == &r->frames[r->rec_frame] ? r->rec : NULL;
}

static GSpan ahead_span(const GReader *r)
{
    GSpan s = {r->ahead_text, r->ahead.start, r->ahead.end, r->ahead.tok.line, r->ahead.tok.col};
    return s;
}

void greader_record_token(GReader *r)
{
    GTemplate *t = r->rec;
    if (r->nframes <= r->rec_frame) /* the type keyword, before the entry's frame */
        return;
    if (r->cur_via && r->cur_via != r->frames[r->rec_frame].via) /* re-read for a value nested in it */
        return;
    t->last_text = r->cur_text;
    t->last_end = r->cur.end;
    if (t->whole_state == 0) {
        t->whole = (GSpan){r->cur_text, r->cur.start, r->cur.end, r->cur.tok.line, r->cur.tok.col};
        t->whole_state = 1;
    } else if (t->whole_state == 1 && t->whole.text == r->cur_text && r->cur.end >= t->whole.end) {
        t->whole.end = r->cur.end;
    } else {
        t->whole_state = -1;
    }
}

static void end_param(GTemplate *t)
{
    if (t->open_param) {
        t->params[t->open_param - 1].span.end = t->last_end;
        t->open_param = 0;
    }
}

void greader_record_open(GReader *r, const GReaderFrame *f)
{
    GTemplate *t = recording(r, f);
    if (!t)
        return;
    t->named = 1;
    if (f->state == 0 && r->have_ahead && r->ahead.tok.type == GTOK_LBRACE) {
        t->has_block = 1;
        t->open = ahead_span(r);
    }
}

int greader_record_key(GReader *r, const GReaderFrame *f, const char *name)
{
    GTemplate *t = recording(r, f);
    if (!t)
        return G_OK;
    end_param(t);
    if (t->nparams == t->capparams) {
        int cap = t->capparams ? t->capparams * 2 : 8;
        GTemplateParam *p = gmem_realloc(t->params, (size_t)cap * sizeof *p);
        if (!p)
            return G_ERR_NOMEM;
        t->params = p;
        t->capparams = cap;
    }
    char *copy = gmem_strdup(name);
    if (!copy)
        return G_ERR_NOMEM;
    t->params[t->nparams].name = copy;
    t->params[t->nparams].span = ahead_span(r);
    t->open_param = ++t->nparams;
    return G_OK;
}

void greader_record_close(GReader *r, const GReaderFrame *f)
{
    GTemplate *t = recording(r, f);
    if (!t)
        return;
    end_param(t);
    t->close = ahead_span(r);
}

/* ---- merging ---- */

static int overridden(const GReaderFrame *f, const char *name)
{
    for (int i = 0; i < f->nkeys; i++)
        if (strcmp(f->keys[i].name, name) == 0)
            return 1;
    return 0;
}

int greader_like_merge(GReader *r, GReaderFrame *f, GError *err)
{
    const GTemplate *b = f->like;
    f->like = NULL;
    if (!b)
        return 0;
    if (f->state == 1 && !b->has_block) { /* nothing to inherit: the overrides' `}` closes the entry */
        if (!f->single) {
            greader_record_close(r, f);
            greader_take(r, NULL);
        }
        return 0;
    }
    if (!b->has_block)
        return 0;
    GSpan *spans = gmem_alloc((size_t)(b->nparams + 2) * sizeof *spans);
    if (!spans)
        return greader_error(r, err, "out of memory");
    int n = 0;
    if (f->state == 0) { /* no overrides: the base's block as it was written */
        spans[n++] = b->open;
        for (int i = 0; i < b->nparams; i++)
            spans[n++] = b->params[i].span;
    } else { /* after the overrides (their `}` is dropped): the parameters they do not name */
        GTemplate *t = recording(r, f);
        if (t)
            end_param(t);
        if (!f->single) /* greader_material_with has no `}` of its own */
            greader_take(r, NULL);
        for (int i = 0; i < b->nparams; i++)
            if (!overridden(f, b->params[i].name))
                spans[n++] = b->params[i].span;
    }
    spans[n++] = b->close;
    int rc = push_replay(r, spans, n, f->via, err);
    return rc < 0 ? rc : 1;
}

/* ---- the statement ---- */

/* Keeps a message for errors in tokens re-read (their lifetime is the load's). */
static const char *keep_via(GReader *r, const char *fmt_by, const char *kn, const char *name, int line, int col)
{
    if (r->nvias == r->capvias) {
        int cap = r->capvias ? r->capvias * 2 : 8;
        char **v = gmem_realloc(r->vias, (size_t)cap * sizeof *v);
        if (!v)
            return NULL;
        r->vias = v;
        r->capvias = cap;
    }
    char buf[400];
    snprintf(buf, sizeof buf, fmt_by, kn, name, greader_file(r), line, col);
    char *copy = gmem_strdup(buf);
    if (copy)
        r->vias[r->nvias++] = copy;
    return copy;
}

int greader_like_entry(GReader *r, GKind kind, const char *name, int line, int col, GError *err)
{
    const char *kn = gkind_name(kind);
    GToken b;
    int rc = greader_peek(r, &b, err);
    if (rc != G_OK)
        return rc;
    if (b.type != GTOK_IDENT) {
        char found[96];
        glexer_describe(&b, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, b.line, b.col,
                                "expected the name of a %s to derive from after 'like', found %s", kn, found);
    }
    greader_take(r, &b); /* peeked above */
    char base[GLEX_TEXT_MAX];
    memcpy(base, b.text, strlen(b.text) + 1);
    if (!glibrary_find(r->lib, kind, base)) {
        char names[512];
        glibrary_names(r->lib, kind, names, sizeof names);
        return greader_error_at(r, err, G_ERR_NOTFOUND, b.line, b.col,
                                "'like %s': no %s '%s' is defined before this line (defined: %s)", base, kn, base,
                                names);
    }
    const GTemplate *bt = glibrary_template(r->lib, kind, base);
    const GTypeInfo *type = glibrary_find_type(r->lib, kind, base);
    if (!bt || !type)
        return greader_error_at(r, err, G_ERR_INVALID, b.line, b.col,
                                "'like %s': %s '%s' was not written with a type and parameters (it is another name "
                                "for an entry, or was made by code), so it cannot be derived from",
                                base, kn, base);
    if (bt->depth + 1 > GREADER_MAX_LIKE_DEPTH)
        return greader_error_at(r, err, G_ERR_PARSE, b.line, b.col,
                                "'like %s': a chain of entries derived with 'like' may be at most %d deep", base,
                                GREADER_MAX_LIKE_DEPTH);
    const char *via = keep_via(r, "(inherited by %s '%s' via 'like' at %s:%d:%d)", kn, name, line, col);
    GTemplate *t = via ? gmem_calloc(1, sizeof *t) : NULL;
    if (t && !(t->base = gmem_strdup(base))) {
        gtemplate_free(t);
        t = NULL;
    }
    if (!t)
        return greader_error_at(r, err, G_ERR_NOMEM, line, col, "out of memory");
    t->depth = bt->depth + 1;
    GToken nx;
    rc = greader_peek(r, &nx, err);
    if (rc == G_OK && !bt->named && nx.type == GTOK_LBRACE)
        rc = greader_error_at(r, err, G_ERR_PARSE, nx.line, nx.col,
                              "'like %s': %s type %s takes no named parameters, so there is nothing to override "
                              "('like' without a block copies it)",
                              base, kn, type->name);
    if (rc == G_OK && !bt->named && bt->whole_state == 1) { /* a positional type: re-read it whole */
        GSpan *s = gmem_alloc(sizeof *s);
        if (s)
            s[0] = bt->whole;
        rc = s ? push_replay(r, s, 1, via, err) : greader_error(r, err, "out of memory");
    }
    if (rc == G_OK) {
        r->pending_like = bt->named ? bt : NULL;
        r->pending_via = via;
    }
    void *obj = NULL;
    if (rc == G_OK) {
        r->rec = t;
        r->rec_frame = r->nframes;
        rc = greader_invoke(r, type, b.line, b.col, &obj, err);
        r->rec = NULL;
        r->pending_like = NULL;
        r->pending_via = NULL;
    }
    if (rc == G_OK) {
        rc = glibrary_put(r->lib, type, name, obj, 1, 1, err);
        if (rc != G_OK)
            rc = greader_error_at(r, err, rc, line, col, "%s '%s' could not be defined", kn, name);
    }
    if (rc == G_OK) {
        rc = glibrary_set_template(r->lib, kind, name, t);
        if (rc != G_OK)
            rc = greader_error_at(r, err, rc, line, col, "out of memory");
    } else {
        gtemplate_free(t);
    }
    return rc;
}

/* ---- where a reported position comes from ---- */

void greader_origin(GReader *r, int line, int col, const char **file, const char **via)
{
    int text = -1;
    const char *v = NULL;
    if (r->cur.tok.line == line && r->cur.tok.col == col) {
        text = r->cur_text;
        v = r->cur_via;
    } else if (r->have_ahead && r->ahead.tok.line == line && r->ahead.tok.col == col) {
        text = r->ahead_text;
        v = r->ahead_via;
    } else {
        for (int i = r->nframes - 1; i >= 0 && text < 0; i--)
            for (int k = 0; k < r->frames[i].nkeys; k++)
                if (r->frames[i].keys[k].line == line && r->frames[i].keys[k].col == col) {
                    text = r->frames[i].keys[k].text;
                    v = r->frames[i].keys[k].via;
                    break;
                }
    }
    const char *name = NULL;
    if (text < 0 || !glibrary_text(r->lib, text, NULL, &name))
        name = r->src ? r->src->name : "?";
    *file = name;
    *via = v;
}

/* ---- one parameter over a base: greader_material_with ---- */

int greader_material_with(GReader *r, const char *base, const char *param, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!base || !param || !param[0])
        return greader_error(r, err, "no base or parameter given");
    const GTypeInfo *type = glibrary_find_type(r->lib, GKIND_MATERIAL, base);
    const GTemplate *bt = type ? glibrary_template(r->lib, GKIND_MATERIAL, base) : NULL;
    if (type && !bt)
        return greader_error(r, err,
                             "material '%s' was not written with a type and parameters (it is another name for an "
                             "entry, or was made by code), so it cannot be derived from",
                             base);
    if (!type && !(type = greader_find_type(GKIND_MATERIAL, base)))
        return greader_error(r, err, "'%s' is neither a material defined before nor a material type", base);
    if (bt && !bt->named)
        return greader_error(r, err, "material '%s' takes no named parameters", base);
    if (bt && bt->depth + 1 > GREADER_MAX_LIKE_DEPTH)
        return greader_error(r, err, "'%s': a chain of entries derived with 'like' may be at most %d deep", base,
                             GREADER_MAX_LIKE_DEPTH);
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    const char *via = NULL;
    if (bt && !(via = keep_via(r, "(inherited from %s '%s' by the value at %s:%d:%d)", "material", base, t.line, t.col)))
        return greader_error(r, err, "out of memory");
    r->pending_like = bt;
    r->pending_via = via;
    r->pending_single = param;
    void *obj = NULL;
    r->single_taken = 0;
    rc = greader_invoke(r, type, t.line, t.col, &obj, err);
    r->pending_like = NULL;
    r->pending_via = NULL;
    r->pending_single = NULL;
    if (rc == G_OK && !r->single_taken) { /* a type read positionally: the value is still there */
        gtype_release(type, obj);
        rc = greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s type %s takes no named parameters (no '%s')",
                              gkind_name(type->kind), type->name, param);
    }
    if (rc == G_OK) {
        rc = glibrary_put(r->lib, type, NULL, obj, 1, 0, err);
        if (rc != G_OK)
            rc = greader_locate(r, err);
    }
    if (rc == G_OK)
        *out = obj;
    return rc;
}
