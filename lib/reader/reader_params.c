/* reader_params.c - parameter blocks: the named parameters of an entry (greader_param), with those an entry derived
 * with `like` inherits merged in where its block of overrides ends, and positional blocks. A named entry being
 * recorded for `like` notes here where its block and each parameter begin and end. */
#include "reader_state.h"
#include "generic/memory.h"

#include <stdio.h>
#include <string.h>

static GReaderFrame *entry_frame(GReader *r) { return r->nframes ? &r->frames[r->nframes - 1] : NULL; }

static int missing_brace(GReader *r, const GToken *t, int line, int col, GError *err)
{
    return greader_error_at(r, err, G_ERR_PARSE, t->line, t->col, "missing '}' to close the block opened at %d:%d",
                            line, col);
}

/* ---- recording a named entry's block (its template, when the entry is recorded) ---- */

/* The block is looked for: it opens when the look-ahead token is `{`. */
static void record_open(GReader *r, const GReaderFrame *f)
{
    GTemplate *t = f->rec;
    if (!t)
        return;
    t->named = 1;
    if (f->state == 0 && r->ts.have_ahead && r->ts.ahead.tok.type == GTOK_LBRACE) {
        t->has_block = 1;
        t->open = gtokens_ahead_span(&r->ts);
    }
}

/* The block closes at the look-ahead token, `}`. */
static void record_close(GReader *r, const GReaderFrame *f)
{
    if (!f->rec)
        return;
    gtemplate_end_param(f->rec);
    f->rec->close = gtokens_ahead_span(&r->ts);
}

/* ---- `like`: the base's parameters the entry does not give ---- */

static int overridden(const GReaderFrame *f, const char *name)
{
    for (int i = 0; i < f->nkeys; i++)
        if (strcmp(f->keys[i].name, name) == 0)
            return 1;
    return 0;
}

/* The merge for the frame f of an entry derived with `like` (state 0: no block of overrides follows; state 1: the
 * block of overrides ends at the look-ahead token, `}`): re-reads the base's parameters the entry does not give,
 * then the base's `}`. 1 when a replay was started (peek again), 0 when nothing is inherited, negative on error. */
static int like_merge(GReader *r, GReaderFrame *f, GError *err)
{
    const GTemplate *b = f->like;
    f->like = NULL;
    if (!b)
        return 0;
    if (f->state == 1 && !b->has_block) { /* nothing to inherit: the overrides' `}` closes the entry */
        if (!f->single) {
            record_close(r, f);
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
        if (f->rec)
            gtemplate_end_param(f->rec);
        if (!f->single) /* greader_material_with has no `}` of its own */
            greader_take(r, NULL);
        for (int i = 0; i < b->nparams; i++)
            if (!overridden(f, b->params[i].name))
                spans[n++] = b->params[i].span;
    }
    spans[n++] = b->close;
    if (gtokens_replay(&r->ts, spans, n, f->via) != G_OK)
        return greader_error(r, err, "out of memory");
    return 1;
}

/* ---- named parameters ---- */

/* Notes a parameter name of the entry f, written at the token t (the look-ahead token). */
static int add_key(GReader *r, GReaderFrame *f, const char *name, const GToken *t, GError *err)
{
    if (f->nkeys == f->capkeys) {
        int cap = f->capkeys ? f->capkeys * 2 : 8;
        GReaderKey *k = gmem_realloc(f->keys, (size_t)cap * sizeof *k);
        if (!k)
            return greader_error_at(r, err, G_ERR_NOMEM, t->line, t->col, "out of memory");
        f->keys = k;
        f->capkeys = cap;
    }
    GReaderKey *k = &f->keys[f->nkeys];
    if (!(k->name = gmem_strdup(name)) ||
        (f->rec && gtemplate_add_param(f->rec, name, gtokens_ahead_span(&r->ts)) != G_OK)) {
        gmem_free(k->name);
        return greader_error_at(r, err, G_ERR_NOMEM, t->line, t->col, "out of memory");
    }
    k->line = t->line;
    k->col = t->col;
    k->text = r->ts.ahead_text;
    k->via = r->ts.ahead_via;
    f->nkeys++;
    return G_OK;
}

/* `range LO HI`, which every generator accepts: read here, for every generator type alike, and applied by
 * greader_invoke (ggenerator_range_create) when the type's parse routine has made its generator. */
static int generator_range(GReader *r, GReaderFrame *f, const GToken *key, GError *err)
{
    double lo, hi;
    int rc = greader_number(r, &lo, err);
    if (rc == G_OK)
        rc = greader_number(r, &hi, err);
    if (rc != G_OK)
        return rc;
    if (!(lo <= hi))
        return greader_error_at(r, err, G_ERR_PARSE, key->line, key->col,
                                "generator %s: range %g %g has LO > HI (must be LO <= HI)", f->type->name, lo, hi);
    f->has_range = 1;
    f->range_lo = lo;
    f->range_hi = hi;
    return G_OK;
}

int greader_param(GReader *r, const char **key, GError *err)
{
    *key = NULL;
    GReaderFrame *f = entry_frame(r);
    if (!f || f->is_block)
        return greader_error(r, err, "parameters read outside an entry");
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (f->single_state == 1) { /* greader_material_with: its one parameter, the value where the reader is */
        f->single_state = 2;
        f->state = 1;
        if ((rc = add_key(r, f, f->single, &t, err)) != G_OK)
            return rc;
        snprintf(r->keybuf, sizeof r->keybuf, "%s", f->single);
        *key = r->keybuf;
        r->single_taken = 1;
        return 1;
    }
    if (f->single_state == 2) { /* ... read: the block closes here, with the base's other parameters */
        f->single_state = 0;
        rc = f->like ? like_merge(r, f, err) : 0;
        if (rc < 0)
            return rc;
        if (rc == 0) {
            f->state = 2;
            return 0;
        }
        if ((rc = greader_peek(r, &t, err)) != G_OK)
            return rc;
    }
    if (f->state == 0) {
        if (t.type != GTOK_LBRACE && f->like) { /* `like` without overrides: the base's block */
            rc = like_merge(r, f, err);
            if (rc < 0)
                return rc;
            if (rc > 0 && (rc = greader_peek(r, &t, err)) != G_OK)
                return rc;
        }
        record_open(r, f);
        if (t.type != GTOK_LBRACE) {
            f->state = 2;
            return 0;
        }
        greader_take(r, NULL); /* the token peeked above */
        f->state = 1;
        f->open_line = t.line;
        f->open_col = t.col;
        rc = greader_peek(r, &t, err);
        if (rc != G_OK)
            return rc;
    }
    if (f->state == 2)
        return 0;
    if (t.type == GTOK_RBRACE && f->like) { /* the overrides end: the base's other parameters follow */
        rc = like_merge(r, f, err);
        if (rc < 0)
            return rc;
        if (rc == 0) {
            f->state = 2;
            return 0;
        }
        if ((rc = greader_peek(r, &t, err)) != G_OK)
            return rc;
    }
    if (t.type == GTOK_RBRACE) {
        record_close(r, f);
        greader_take(r, NULL); /* the token peeked above */
        f->state = 2;
        return 0;
    }
    if (t.type == GTOK_EOF)
        return missing_brace(r, &t, f->open_line, f->open_col, err);
    if (t.type != GTOK_IDENT) {
        char found[96];
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "%s %s: expected a parameter name or '}', found %s", gkind_name(f->type->kind),
                                f->type->name, found);
    }
    for (int i = 0; i < f->nkeys; i++)
        if (strcmp(f->keys[i].name, t.text) == 0)
            return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s %s: parameter '%s' is given twice",
                                    gkind_name(f->type->kind), f->type->name, t.text);
    if ((rc = add_key(r, f, t.text, &t, err)) != G_OK)
        return rc;
    greader_take(r, NULL); /* the token peeked above */
    if (f->type && f->type->kind == GKIND_GENERATOR && strcmp(t.text, "range") == 0) {
        rc = generator_range(r, f, &t, err);
        return rc != G_OK ? rc : greader_param(r, key, err);
    }
    memcpy(r->keybuf, t.text, strlen(t.text) + 1);
    *key = r->keybuf;
    return 1;
}

int greader_unknown_param(GReader *r, const char *expected_names, GError *err)
{
    GReaderFrame *f = entry_frame(r);
    if (!f || f->is_block || !f->nkeys)
        return greader_error(r, err, "unknown parameter");
    const GReaderKey *k = &f->keys[f->nkeys - 1];
    return greader_error_at(r, err, G_ERR_PARSE, k->line, k->col,
                            "%s %s: unknown parameter '%s' (expected one of: %s)", gkind_name(f->type->kind),
                            f->type->name, k->name, expected_names ? expected_names : "none");
}

/* ---- positional blocks ---- */

int greader_block_begin(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_LBRACE)
        return greader_expected(r, "'{'", err);
    rc = greader_push_frame(r, 1, NULL, t.line, t.col, err);
    if (rc != G_OK)
        return rc;
    return greader_next(r, NULL, err);
}

int greader_block_end(GReader *r, GError *err)
{
    GReaderFrame *f = entry_frame(r);
    if (!f || !f->is_block)
        return greader_error(r, err, "no block is open");
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_EOF)
        return missing_brace(r, &t, f->open_line, f->open_col, err);
    if (t.type != GTOK_RBRACE)
        return 0;
    greader_take(r, NULL); /* the token peeked above */
    greader_pop_frames(r, r->nframes - 1);
    return 1;
}
