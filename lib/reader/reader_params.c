/* reader_params.c - typed values (numbers, vectors, strings, names, paths) and parameter blocks. */
#include "reader_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

static const char *type_name(int type)
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

/* "expected WHAT, found TOKEN" at the next token (which is not consumed). */
static int expected(GReader *r, const char *what, GError *err)
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

int greader_expect(GReader *r, int type, const char *what, GError *err)
{
    int rc = greader_accept(r, type, err);
    if (rc < 0)
        return rc;
    return rc ? G_OK : expected(r, what ? what : type_name(type), err);
}

int greader_at_number(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    return rc ? rc : t.type == GTOK_NUMBER || (t.type == GTOK_IDENT && glibrary_constant(r->lib, t.text, NULL, NULL, NULL, NULL));
}

int greader_number(GReader *r, double *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_IDENT && (strcasecmp(t.text, "nan") == 0 || strcasecmp(t.text, "inf") == 0 ||
                                 strcasecmp(t.text, "infinity") == 0))
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "'%s' is not allowed: numbers must be finite",
                                t.text);
    double value = t.number;
    if (t.type == GTOK_IDENT && glibrary_constant(r->lib, t.text, &value, NULL, NULL, NULL)) {
        greader_take(r, NULL); /* a constant (`define`), peeked above */
        *out = value;
        return G_OK;
    }
    if (t.type == GTOK_IDENT)
        return expected(r, "a number or a constant defined before", err);
    if (t.type != GTOK_NUMBER)
        return expected(r, "a number", err);
    greader_take(r, NULL); /* the token peeked above */
    *out = t.number;
    return G_OK;
}

int greader_number_in(GReader *r, double lo, double hi, double *out, GError *err)
{
    double v;
    int rc = greader_number(r, &v, err);
    if (rc != G_OK)
        return rc;
    if (!(v >= lo && v <= hi))
        return greader_error(r, err, "value %g is out of range [%g, %g]", v, lo, hi);
    *out = v;
    return G_OK;
}

int greader_int(GReader *r, long lo, long hi, long *out, GError *err)
{
    double v;
    int rc = greader_number(r, &v, err);
    if (rc != G_OK)
        return rc;
    if (v != floor(v))
        return greader_error(r, err, "expected a whole number, found %g", v);
    if (!(v >= (double)lo && v <= (double)hi))
        return greader_error(r, err, "value %g is out of range [%ld, %ld]", v, lo, hi);
    *out = (long)v;
    return G_OK;
}

int greader_vec3(GReader *r, GVec3 *out, GError *err)
{
    int angle = greader_accept(r, GTOK_LANGLE, err);
    if (angle < 0)
        return angle;
    double v[3];
    for (int i = 0; i < 3; i++) {
        if (angle && i > 0) {
            int rc = greader_expect(r, GTOK_COMMA, "',' between vector components", err);
            if (rc != G_OK)
                return rc;
        }
        int rc = greader_number(r, &v[i], err);
        if (rc != G_OK)
            return rc;
    }
    if (angle) {
        int rc = greader_expect(r, GTOK_RANGLE, "'>' to close the vector", err);
        if (rc != G_OK)
            return rc;
    }
    *out = gvec3(v[0], v[1], v[2]);
    return G_OK;
}

int greader_bool(GReader *r, int *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_NUMBER && (t.number == 0.0 || t.number == 1.0)) {
        *out = t.number != 0.0;
        return greader_next(r, NULL, err);
    }
    static const char *const names[] = {"false", "true", "no", "yes", "off", "on", NULL};
    for (int i = 0; t.type == GTOK_IDENT && names[i]; i++)
        if (strcmp(t.text, names[i]) == 0) {
            *out = i & 1;
            return greader_next(r, NULL, err);
        }
    return expected(r, "true or false", err);
}

int greader_string(GReader *r, char **out, GError *err)
{
    *out = NULL;
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_STRING)
        return expected(r, "a quoted string", err);
    greader_take(r, &t); /* the token peeked above */
    *out = gmem_strdup(t.text);
    return *out ? G_OK : greader_error_at(r, err, G_ERR_NOMEM, t.line, t.col, "out of memory");
}

int greader_ident(GReader *r, char *buf, size_t size, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_IDENT)
        return expected(r, "a name", err);
    greader_take(r, &t); /* the token peeked above */
    if (strlen(t.text) >= size)
        return greader_error(r, err, "name '%.40s...' is too long (at most %zu characters)", t.text, size - 1);
    memcpy(buf, t.text, strlen(t.text) + 1);
    return G_OK;
}

int greader_choice(GReader *r, const char *const *choices, int *index, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    for (int i = 0; t.type == GTOK_IDENT && choices[i]; i++)
        if (strcmp(t.text, choices[i]) == 0) {
            *index = i;
            return greader_next(r, NULL, err);
        }
    char list[400];
    size_t used = 0;
    list[0] = '\0';
    for (int i = 0; choices[i] && used < sizeof list; i++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", choices[i]);
    char what[420];
    snprintf(what, sizeof what, "one of %s", list);
    return expected(r, what, err);
}

int greader_path(GReader *r, char **out, GError *err)
{
    char *rel = NULL;
    int rc = greader_string(r, &rel, err);
    if (rc != G_OK)
        return rc;
    if (!rel[0]) {
        gmem_free(rel);
        return greader_error(r, err, "empty file name");
    }
    const char *dir = greader_dir(r);
    if (rel[0] == '/' || strcmp(dir, ".") == 0) {
        *out = rel;
    } else {
        size_t a = strlen(dir), b = strlen(rel);
        *out = gmem_alloc(a + b + 2);
        if (*out) {
            memcpy(*out, dir, a);
            (*out)[a] = '/';
            memcpy(*out + a + 1, rel, b + 1);
        }
        gmem_free(rel);
        if (!*out)
            return greader_error(r, err, "out of memory");
    }
    if (r->opt.confine_dir) { /* the file read is the resolved one that was checked */
        char *real = NULL;
        int rc = greader_confine(r->opt.confine_dir, *out, &real, err);
        gmem_free(*out);
        *out = real;
        if (rc != G_OK) {
            char msg[sizeof err->message];
            snprintf(msg, sizeof msg, "%s", err ? err->message : "");
            return greader_error_at(r, err, rc, r->cur.tok.line, r->cur.tok.col, "%s", msg);
        }
    }
    return G_OK;
}

/* ---- parameter blocks ---- */

static GReaderFrame *entry_frame(GReader *r) { return r->nframes ? &r->frames[r->nframes - 1] : NULL; }

static int missing_brace(GReader *r, const GToken *t, int line, int col, GError *err)
{
    return greader_error_at(r, err, G_ERR_PARSE, t->line, t->col, "missing '}' to close the block opened at %d:%d",
                            line, col);
}

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
    if (!(k->name = gmem_strdup(name)) || greader_record_key(r, f, name) != G_OK) {
        gmem_free(k->name);
        return greader_error_at(r, err, G_ERR_NOMEM, t->line, t->col, "out of memory");
    }
    k->line = t->line;
    k->col = t->col;
    k->text = r->ahead_text;
    k->via = r->ahead_via;
    f->nkeys++;
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
        rc = f->like ? greader_like_merge(r, f, err) : 0;
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
            rc = greader_like_merge(r, f, err);
            if (rc < 0)
                return rc;
            if (rc > 0 && (rc = greader_peek(r, &t, err)) != G_OK)
                return rc;
        }
        greader_record_open(r, f);
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
        rc = greader_like_merge(r, f, err);
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
        greader_record_close(r, f);
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
    return greader_error_at(r, err, G_ERR_PARSE, k->line, k->col, "%s %s: unknown parameter '%s' (expected one of: %s)",
                            gkind_name(f->type->kind), f->type->name, k->name, expected_names ? expected_names : "none");
}

int greader_block_begin(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_LBRACE)
        return expected(r, "'{'", err);
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
