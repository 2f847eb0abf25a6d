/* reader.c - loading text files: the top-level statements (include, plugin, colormodel, define, KIND [NAME] VALUE)
 * read from the token stream, and the loaders of files and strings. */
#include "reader_confine.h"
#include "reader_define.h"
#include "reader_entry.h"
#include "reader_like.h"
#include "generic/memory.h"
#include "generic/plugin.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- statements ---- */

static int parse_statements(GReader *r, GError *err);

/* Reads the file name (taken over) and makes it the source read from here on. */
static int open_file(GReader *r, char *name, GError *err)
{
    GReaderSource *s = NULL;
    int rc = greader_source_file(name, r->opt.max_file_size, &s, err);
    return rc == G_OK ? gtokens_push_source(&r->ts, s, err) : rc;
}

static int do_include(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK && t.type != GTOK_STRING)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected a quoted file name after 'include'");
    char *path = NULL;
    if (rc == G_OK)
        rc = greader_path(r, &path, err);
    if (rc != G_OK)
        return rc;
    if (r->include_depth + r->nframes + 1 > r->opt.max_depth) {
        gmem_free(path);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "nesting deeper than %d levels (entries, blocks and includes)", r->opt.max_depth);
    }
    char *real = realpath(path, NULL);
    if (real) {
        for (GReaderSource *s = r->ts.src; s; s = s->parent) {
            if (!s->real || strcmp(s->real, real) != 0)
                continue;
            char chain[400] = "";
            size_t used = 0;
            /* the chain from the file that is included again down to here */
            GReaderSource *stack[64];
            int n = 0;
            for (GReaderSource *q = r->ts.src; q && n < 64; q = q->parent) {
                stack[n++] = q;
                if (q == s)
                    break;
            }
            for (int i = n - 1; i >= 0 && used < sizeof chain; i--)
                used += (size_t)snprintf(chain + used, sizeof chain - used, "%s -> ", stack[i]->name);
            free(real);
            rc = greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "include cycle: %s%s", chain, path);
            gmem_free(path);
            return rc;
        }
        for (int i = 0; i < r->nincluded; i++)
            if (strcmp(r->included[i], real) == 0) { /* read once: a second include is a no-op */
                free(real);
                gmem_free(path);
                return G_OK;
            }
        free(real);
    }
    GToken kw = r->ts.cur.tok;
    rc = open_file(r, path, err);
    if (rc != G_OK) {
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err->message);
        return greader_error_at(r, err, rc, kw.line, kw.col, "cannot include: %s", msg);
    }
    r->ts.src->lx.quiet = 1; /* until its first statement */
    r->include_depth++;
    rc = parse_statements(r, err);
    r->include_depth--;
    if (rc == G_OK && r->ts.src->real) {
        if (r->nincluded == r->capincluded) {
            int cap = r->capincluded ? r->capincluded * 2 : 8;
            char **n = gmem_realloc(r->included, (size_t)cap * sizeof *n);
            if (n)
                r->included = n, r->capincluded = cap;
        }
        char *copy = r->nincluded < r->capincluded ? gmem_strdup(r->ts.src->real) : NULL;
        if (copy)
            r->included[r->nincluded++] = copy;
        else
            rc = greader_error_at(r, err, G_ERR_NOMEM, kw.line, kw.col, "out of memory");
    }
    gtokens_pop_source(&r->ts);
    return rc;
}

/* 1 when `plugin` statements may load modules: the caller's option or GENERIC_ALLOW_PLUGINS=1. */
static int plugins_allowed(const GReader *r)
{
    const char *env = getenv(GPLUGIN_ALLOW_ENV);
    return r->opt.allow_plugins || (env && strcmp(env, "1") == 0);
}

static int do_plugin(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK && t.type != GTOK_STRING)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected a quoted module path after 'plugin'");
    if (rc == G_OK && r->opt.no_plugins)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "plugin statements are disabled for this file");
    if (rc == G_OK && !plugins_allowed(r))
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "plugin statements are not allowed: a module runs native code, so a file may load "
                                "one only with consent (--allow-plugins, " GPLUGIN_ALLOW_ENV "=1, or "
                                "GReaderOptions.allow_plugins; --plugin FILE on the command line loads one)");
    char *name = NULL, *path = NULL;
    if (rc == G_OK)
        rc = greader_string(r, &name, err);
    if (rc == G_OK && !name[0])
        rc = greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "empty module name");
    if (rc == G_OK) /* a path relative to the file, or a bare name searched as plugin.h says */
        rc = gplugin_find(name, greader_dir(r), &path, err);
    if (rc == G_OK && r->opt.confine_dir) { /* the module's file must lie under the directory too */
        char *real = NULL;
        rc = greader_confine(r->opt.confine_dir, path, &real, err);
        if (rc == G_OK) {
            gmem_free(path);
            path = real;
        }
    }
    if (rc == G_OK)
        rc = gplugin_load(path, err);
    if (rc != G_OK)
        rc = greader_locate(r, err);
    gmem_free(path);
    gmem_free(name);
    return rc;
}

static int colormodel_options(GReader *r, GColorModelOptions *o, GError *err)
{
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "step") == 0)
            rc = greader_number_in(r, 0.01, 400.0, &o->step_nm, err);
        else if (strcmp(key, "min") == 0)
            rc = greader_number_in(r, 100.0, 2000.0, &o->min_nm, err);
        else if (strcmp(key, "max") == 0)
            rc = greader_number_in(r, 100.0, 2000.0, &o->max_nm, err);
        else if (strcmp(key, "uplift") == 0) {
            static const char *const uplifts[] = {"sigmoid", "basis", NULL};
            int which = 0;
            rc = greader_choice(r, uplifts, &which, err);
            o->uplift = which == 0 ? GCOLOR_UPLIFT_SIGMOID : GCOLOR_UPLIFT_BASIS;
        } else
            rc = greader_unknown_param(r, "step, min, max, uplift", err);
        if (rc < 0)
            return rc;
    }
    return rc;
}

/* Parses the options block of a colour model type and creates the model. */
static int colormodel_entry(GReader *r, const GTypeInfo *type, GColorModel **out, GError *err)
{
    *out = NULL;
    if (type->parse) {
        void *obj = NULL;
        int rc = greader_invoke(r, type, r->ts.cur.tok.line, r->ts.cur.tok.col, &obj, err);
        *out = obj;
        return rc;
    }
    int line = r->ts.cur.tok.line, col = r->ts.cur.tok.col;
    int base = r->nframes;
    int rc = greader_push_frame(r, 0, type, line, col, err);
    GColorModelOptions o = {0, 0, 0, 0};
    if (rc == G_OK)
        rc = colormodel_options(r, &o, err);
    if (rc == G_OK) {
        rc = gcolormodel_create_class(type->vtable, &o, out, err);
        if (rc != G_OK) {
            char msg[sizeof err->message];
            snprintf(msg, sizeof msg, "%s", err ? err->message : "");
            rc = greader_error_at(r, err, rc, line, col, "%s", msg);
        }
    }
    greader_pop_frames(r, base);
    return rc;
}

static int do_colormodel(GReader *r, int override, GError *err)
{
    GToken t;
    int rc = greader_next(r, &t, err);
    if (rc != G_OK)
        return rc;
    const GTypeInfo *type = t.type == GTOK_IDENT ? gregistry_find(GKIND_COLORMODEL, t.text) : NULL;
    if (!type) {
        char names[512], found[96];
        gregistry_names(GKIND_COLORMODEL, names, sizeof names);
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_NOTFOUND, t.line, t.col,
                                "unknown colour model %s (registered colour models: %s)", found, names);
    }
    GColorModel *m = NULL;
    rc = colormodel_entry(r, type, &m, err);
    if (rc != G_OK)
        return rc;
    if (override) {
        gcolormodel_destroy(m); /* the caller chose the model */
        return G_OK;
    }
    if (r->model_fixed) {
        const char *now = gcolormodel_name(glibrary_model_or_null(r->lib));
        gcolormodel_destroy(m);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "colormodel must come before the first colour (colours were already read in '%s')",
                                now);
    }
    glibrary_set_model(r->lib, m, NULL);
    return G_OK;
}

/* 1 when the token after a statement's first word v makes that word the entry's name: a type of the kind or
 * `like` follows (`material plastic lambert { ... }` names a lambert "plastic"); else a word that is a type
 * keyword begins an anonymous entry (`material lambert { ... }`). */
static int entry_name_follows(GKind kind, const GToken *v)
{
    return v->type == GTOK_IDENT && (strcmp(v->text, "like") == 0 || greader_find_type(kind, v->text));
}

static int do_entry(GReader *r, GKind kind, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    const char *kn = gkind_name(kind);
    if (t.type != GTOK_IDENT) {
        char found[96];
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected a %s type or a name after '%s', found %s",
                                kn, kn, found);
    }
    const GTypeInfo *type = NULL;
    void *obj = NULL;
    int owned = 0;
    if (strcmp(t.text, "like") == 0)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "'like' needs the new entry's name before it: %s NAME like BASE { ... }", kn);
    char *name = gmem_strdup(t.text);
    if (!name)
        return greader_error_at(r, err, G_ERR_NOMEM, t.line, t.col, "out of memory");
    greader_take(r, NULL); /* the name or type, peeked above */
    GToken v;
    rc = greader_peek(r, &v, err);
    const GTypeInfo *anonymous = greader_find_type(kind, name);
    if (rc == G_OK && anonymous && !entry_name_follows(kind, &v)) { /* anonymous: KIND TYPE parameters */
        gmem_free(name);
        rc = greader_invoke(r, anonymous, t.line, t.col, &obj, err);
        return rc ? rc : glibrary_put(r->lib, anonymous, NULL, obj, 1, 1, err);
    }
    if (rc == G_OK && glibrary_find(r->lib, kind, name)) {
        rc = greader_error_at(r, err, G_ERR_EXISTS, t.line, t.col, "%s '%s' is already defined", kn, name);
    } else if (rc == G_OK && v.type == GTOK_IDENT && strcmp(v.text, "like") == 0) {
        greader_take(r, NULL); /* `like`, peeked above */
        rc = greader_like_entry(r, kind, name, t.line, t.col, err);
    } else if (rc == G_OK && v.type != GTOK_IDENT) { /* most likely a misspelt type keyword */
        char names[512];
        greader_type_names(kind, names, sizeof names);
        rc = greader_error_at(r, err, G_ERR_NOTFOUND, t.line, t.col, "unknown %s type '%s' (registered: %s)", kn,
                              name, names[0] ? names : "none");
    } else if (rc == G_OK) {
        GTemplate *tmpl = gmem_calloc(1, sizeof *tmpl); /* for entries derived from this one */
        if (!tmpl)
            rc = greader_error_at(r, err, G_ERR_NOMEM, t.line, t.col, "out of memory");
        r->pending_rec = tmpl; /* recorded while its entry frame is open */
        if (rc == G_OK)
            rc = greader_value(r, kind, 0, &obj, &type, &owned, err);
        r->pending_rec = NULL;
        if (rc == G_OK) {
            rc = glibrary_put(r->lib, type, name, obj, owned, 1, err);
            if (rc != G_OK)
                rc = greader_error_at(r, err, rc, t.line, t.col, "%s '%s' could not be defined", kn, name);
        }
        if (rc == G_OK && owned) { /* made by a parse routine (not another name for an entry) */
            rc = glibrary_set_template(r->lib, kind, name, tmpl);
            if (rc != G_OK)
                rc = greader_error_at(r, err, rc, t.line, t.col, "out of memory");
        } else {
            gtemplate_free(tmpl);
        }
    }
    gmem_free(name);
    return rc;
}

/* Creates the caller's colour model (GReaderOptions.colormodel) once, before the first entry: a model a
 * `plugin` statement of the file registers can so be chosen. */
static int resolve_model(GReader *r, GError *err)
{
    if (!r->model_pending)
        return G_OK;
    r->model_pending = 0;
    GColorModel *m = NULL;
    int rc = gcolormodel_create(r->opt.colormodel, r->opt.colormodel_options, &m, err);
    if (rc != G_OK)
        return rc;
    glibrary_set_model(r->lib, m, NULL);
    r->opt.model = m;
    return G_OK;
}

/* An entry of a kind the caller skips (GReaderOptions.skip_kinds), its keyword read at (line, col): the names
 * and type keyword before its block, then the block up to its matching brace, without interpreting them. */
static int skip_entry(GReader *r, GKind kind, int line, int col, GError *err)
{
    GToken t;
    int rc;
    while ((rc = greader_next(r, &t, err)) == G_OK && t.type == GTOK_IDENT)
        ;
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_LBRACE) {
        char found[96];
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected '{' of the %s entry (skipped), found %s",
                                gkind_name(kind), found);
    }
    for (long depth = 1; depth > 0;) {
        if ((rc = greader_next(r, &t, err)) != G_OK)
            return rc;
        if (t.type == GTOK_EOF)
            return greader_error_at(r, err, G_ERR_PARSE, line, col, "the %s entry has no closing '}'",
                                    gkind_name(kind));
        depth += t.type == GTOK_LBRACE ? 1 : t.type == GTOK_RBRACE ? -1 : 0;
    }
    return G_OK;
}

/* "include, plugin, colormodel, define, color, material, ...": the statements, then the keywords of every other kind
 * (the applications' too), for messages. */
static void statement_list(char *buf, size_t size)
{
    size_t used = (size_t)snprintf(buf, size, "include, plugin, colormodel, define");
    for (int k = 0, n = gkind_count(); k < n && used < size; k++)
        if ((GKind)k != GKIND_COLORMODEL)
            used += (size_t)snprintf(buf + used, size - used, ", %s", gkind_name((GKind)k));
}

static int parse_statements(GReader *r, GError *err)
{
    for (;;) {
        GToken t;
        int rc = greader_peek(r, &t, err);
        if (rc != G_OK)
            return rc;
        if (t.type == GTOK_EOF)
            return G_OK;
        char found[96], statements[512]; /* made only for messages: for every statement it would be measurable */
        int foreign = r->ts.src->lx.quiet; /* no statement read from this file yet: quote nothing of it */
        if (t.type != GTOK_IDENT && foreign)
            return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s", GLEX_FOREIGN_MESSAGE);
        if (t.type != GTOK_IDENT) {
            glexer_describe(&t, found, sizeof found);
            statement_list(statements, sizeof statements);
            return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "expected a statement (%s), found %s",
                                    statements, found);
        }
        greader_take(r, &t);
        GKind kind = GKIND_COLORMODEL; /* the colormodel statement; other kinds are entries */
        int entry = gkind_find(t.text, &kind) && kind != GKIND_COLORMODEL;
        int known = entry || !strcmp(t.text, "include") || !strcmp(t.text, "plugin") ||
                    !strcmp(t.text, "colormodel") || !strcmp(t.text, "define");
        if (known)
            r->ts.src->lx.quiet = 0; /* the file is in the format: from here on its text may be quoted */
        if (strcmp(t.text, "include") == 0) {
            rc = do_include(r, err);
        } else if (strcmp(t.text, "plugin") == 0) {
            rc = do_plugin(r, err);
        } else if (strcmp(t.text, "colormodel") == 0) {
            rc = do_colormodel(r, r->opt.model != NULL || r->model_pending, err);
        } else if (strcmp(t.text, "define") == 0) {
            rc = greader_define_statement(r, err);
        } else {
            if (!entry && foreign)
                return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s", GLEX_FOREIGN_MESSAGE);
            if (!entry) {
                glexer_describe(&t, found, sizeof found);
                statement_list(statements, sizeof statements);
                return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "unknown statement %s (expected %s)",
                                        found, statements);
            }
            rc = resolve_model(r, err);
            if (rc == G_OK && (unsigned)kind < 32 && (r->opt.skip_kinds & (1u << kind)))
                rc = skip_entry(r, kind, t.line, t.col, err);
            else if (rc == G_OK)
                rc = do_entry(r, kind, err);
        }
        if (rc != G_OK)
            return rc;
    }
}

/* ---- loading ---- */

static void reader_init(GReader *r, GLibrary *lib, const GReaderOptions *opt)
{
    memset(r, 0, sizeof *r);
    r->lib = lib;
    if (opt)
        r->opt = *opt;
    if (r->opt.max_depth <= 0)
        r->opt.max_depth = GREADER_DEFAULT_MAX_DEPTH;
    gtokens_init(&r->ts, lib);
}

static void reader_fini(GReader *r)
{
    greader_like_fini(r);
    greader_pop_frames(r, 0);
    gmem_free(r->frames);
    for (int i = 0; i < r->nincluded; i++)
        gmem_free(r->included[i]);
    gmem_free(r->included);
    gtokens_fini(&r->ts);
}

/* Reads a source into lib; create_model: create opt->colormodel (when set) before the first entry. */
static int run(GLibrary *lib, const GReaderOptions *opt, int create_model, const char *path, const char *text,
               const char *name, GError *err)
{
    GReader r;
    reader_init(&r, lib, opt);
    r.opt.model = glibrary_model_or_null(lib); /* a model chosen before the file overrides its statement */
    r.model_pending = create_model && !r.opt.model && r.opt.colormodel != NULL;
    int rc;
    if (path) {
        char *copy = NULL;
        rc = G_OK;
        if (r.opt.confine_dir) { /* the file itself must lie under the directory */
            char *real = NULL;
            rc = greader_confine(r.opt.confine_dir, path, &real, err);
            gmem_free(real);
        }
        if (rc == G_OK)
            rc = (copy = gmem_strdup(path)) ? open_file(&r, copy, err) : gerror_set(err, G_ERR_NOMEM, "out of memory");
    } else {
        GReaderSource *s = NULL;
        rc = greader_source_string(name ? name : "<string>", text, &s, err);
        if (rc == G_OK)
            rc = gtokens_push_source(&r.ts, s, err);
    }
    if (rc == G_OK) {
        r.ts.src->lx.quiet = 1; /* until its first statement */
        rc = parse_statements(&r, err);
    }
    if (rc == G_OK)
        rc = resolve_model(&r, err); /* a file without entries */
    reader_fini(&r);
    glibrary_drop_unused_texts(lib);
    return rc;
}

static int load(const char *path, const char *text, const char *name, const GReaderOptions *opt, GLibrary **out,
                GError *err)
{
    GError local;
    gerror_clear(&local);
    *out = NULL;
    GLibrary *lib = NULL;
    int rc = glibrary_create(opt ? opt->model : NULL, &lib, &local);
    if (rc == G_OK) /* opt->colormodel is created by the reader, after the file's leading plugin statements */
        rc = run(lib, opt, 1, path, text, name, &local);
    if (rc == G_OK && !glibrary_colormodel(lib))
        rc = gerror_set(&local, G_ERR_NOMEM, "out of memory creating the colour model");
    if (rc != G_OK) {
        glibrary_destroy(lib);
        if (err)
            *err = local;
        return rc;
    }
    *out = lib;
    gerror_clear(err);
    return G_OK;
}

int greader_load_file(const char *path, const GReaderOptions *opt, GLibrary **out, GError *err)
{
    if (!out || !path)
        return gerror_set(err, G_ERR_INVALID, "no file given");
    return load(path, NULL, NULL, opt, out, err);
}

int greader_load_string(const char *text, const char *name, const GReaderOptions *opt, GLibrary **out, GError *err)
{
    if (!out || !text)
        return gerror_set(err, G_ERR_INVALID, "no text given");
    return load(NULL, text, name, opt, out, err);
}

int glibrary_load_file(GLibrary *lib, const char *path, const GReaderOptions *opt, GError *err)
{
    if (!lib || !path)
        return gerror_set(err, G_ERR_INVALID, "no library or file given");
    GError local;
    gerror_clear(&local);
    int rc = run(lib, opt, 0, path, NULL, NULL, &local);
    if (err)
        *err = local;
    return rc;
}
