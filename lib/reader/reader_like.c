/* reader_like.c - entries derived from others: `KIND NAME like BASE { overrides }`, and greader_material_with.
 *
 * While a named entry is read, the token stream records where each of its named parameters was written (a stretch
 * of a text the library keeps, GTemplate). An entry derived with `like` is read by the base's own parse routine:
 * its block of overrides comes first, and where that block closes the reader re-reads, from the kept texts, the
 * base's parameters the overrides do not name, then the base's `}` (lib/reader/reader_params.c). Nothing is
 * specific to a type, so every type with named parameters (plug-ins' too) can be derived from; a type read
 * positionally (a colour literal) is re-read whole, without overrides. Tokens re-read keep their own file and
 * position, so an error in an inherited parameter is reported where the base wrote it, with the `like` that
 * inherited it.
 *
 * Bounds: a chain of `like` is at most GREADER_MAX_LIKE_DEPTH deep (a base is always defined earlier, so there
 * is no cycle), and the token stream re-reads a bounded number of tokens (lib/reader/tokens.h). */
#include "reader_like.h"
#include "reader_entry.h"
#include "generic/memory.h"

#include <stdio.h>
#include <string.h>

void greader_like_fini(GReader *r)
{
    for (int i = 0; i < r->nvias; i++)
        gmem_free(r->vias[i]);
    gmem_free(r->vias);
    r->vias = NULL;
    r->nvias = r->capvias = 0;
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
        rc = s && gtokens_replay(&r->ts, s, 1, via) == G_OK ? G_OK : greader_error(r, err, "out of memory");
    }
    if (rc == G_OK) {
        r->pending_like = bt->named ? bt : NULL;
        r->pending_via = via;
    }
    void *obj = NULL;
    if (rc == G_OK) {
        r->pending_rec = t;
        rc = greader_invoke(r, type, b.line, b.col, &obj, err);
        r->pending_rec = NULL;
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
    if (bt &&
        !(via = keep_via(r, "(inherited from %s '%s' by the value at %s:%d:%d)", "material", base, t.line, t.col)))
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
        gtypeinfo_release(type, obj);
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
