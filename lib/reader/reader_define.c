/* reader_define.c - named numeric constants: `define NAME VALUE` at the top level, then NAME wherever a number
 * is read (greader_number and everything built on it). A constant is defined before its use and once; its
 * value is a number or an earlier constant. Constants belong to the library, so a scene loaded after a
 * material file (glibrary_load_file) sees the file's constants. */
#include "reader_define.h"
#include "generic/memory.h"

#include <stdio.h>
#include <string.h>
#include <strings.h>

/* Words a constant may not be named: they mean something where a number could follow. */
static const char *reserved_word(const char *name)
{
    static const char *const words[] = {"include", "plugin", "colormodel", "define", "like", "true", "false", "yes",
                                        "no", "on", "off", NULL};
    for (int i = 0; words[i]; i++)
        if (strcmp(name, words[i]) == 0)
            return "a keyword of the format";
    if (strcasecmp(name, "nan") == 0 || strcasecmp(name, "inf") == 0 || strcasecmp(name, "infinity") == 0)
        return "not a finite number";
    for (int k = 0, n = gkind_count(); k < n; k++) {
        if (strcmp(name, gkind_name((GKind)k)) == 0)
            return "a kind keyword";
        if (gregistry_find((GKind)k, name))
            return "a type keyword";
    }
    return NULL;
}

int greader_define_statement(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_IDENT) {
        char found[96];
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "expected a constant's name after 'define', found %s", found);
    }
    greader_take(r, &t); /* peeked above */
    char name[GLEX_TEXT_MAX];
    memcpy(name, t.text, strlen(t.text) + 1);
    int line = t.line, col = t.col, text = r->ts.cur_text;
    const char *why = reserved_word(name);
    if (why)
        return greader_error_at(r, err, G_ERR_PARSE, line, col, "'%s' cannot name a constant: it is %s", name, why);
    int dl, dc, dt;
    if (glibrary_constant(r->lib, name, NULL, &dl, &dc, &dt)) {
        const char *file = NULL;
        if (!glibrary_text(r->lib, dt, NULL, &file))
            file = "?";
        return greader_error_at(r, err, G_ERR_EXISTS, line, col,
                                "constant '%s' is already defined (at %s:%d:%d); constants cannot be redefined", name,
                                file, dl, dc);
    }
    double v = 0.0;
    rc = greader_number(r, &v, err);
    if (rc != G_OK)
        return rc;
    rc = glibrary_define_constant(r->lib, name, v, line, col, text);
    return rc == G_OK ? G_OK : greader_error_at(r, err, rc, line, col, "out of memory");
}
