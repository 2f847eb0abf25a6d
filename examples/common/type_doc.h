/* type_doc.h - the reference page of registered types, for the tools' `types --markdown`: a section per kind, and
 * per type its keyword, its summary and its parameter table (GTypeInfo.params, generic/registry.h) in Markdown.
 * Header only (static functions), as cli.h; it uses the public registry and libc. */
#ifndef EXAMPLES_TYPE_DOC_H
#define EXAMPLES_TYPE_DOC_H

#include <generic/registry.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/** The paragraph that explains the columns of every table, for a page's introduction. */
#define TYPE_DOC_COLUMNS                                                                                              \
    "Each type's table lists what its parse routine reads. *form*: `named` parameters are written `NAME VALUE`\n"   \
    "in the entry's optional `{ ... }` block, in any order, each at most once (an entry without the block takes\n"  \
    "every default); `positional` values follow the type keyword in the order of the table. *type* is the\n"       \
    "syntax of the value: number (a constant defined with `define` will do), numbers (several in a row),\n"          \
    "integer, bool (true/false, yes/no, on/off, 1/0), string (quoted), path (a quoted file name, relative to\n"     \
    "the file), vector (`<x, y, z>` or `x y z`), color (a colour literal or the name of a colour), material (a\n"  \
    "material or texture node: a nested entry or a name), generator, choice (one of the words the range\n"        \
    "lists), formula (a number or a keyword with numbers), block (a `{ ... }` of its own syntax), shape (a\n"     \
    "CSG or CPG shape tree). *range* gives the syntax of these. *default* is the value taken when the parameter\n"\
    "is left out; `required` means it must be given.\n"

/* Writes s as Markdown text that shows it as it is (a table cell's too): '\\', '|', '<' (`<axis>` would be an HTML
 * tag) and '*' escaped, line breaks as spaces; NULL or empty as `empty`. */
static inline void type_doc_cell(FILE *f, const char *s, const char *empty)
{
    if (!s || !*s)
        s = empty;
    for (; *s; s++) {
        if (strchr("\\|<*", *s))
            fputc('\\', f);
        fputc(*s == '\n' ? ' ' : *s, f);
    }
}

/** Writes one type: the heading `### KIND `NAME``, its summary, and its parameter table ("No parameters." for an
 * empty one, "No parameter table." when the record has none). */
static inline void type_doc_type(FILE *f, const GTypeInfo *t)
{
    fprintf(f, "### %s `%s`\n\n", gkind_name(t->kind), t->name);
    if (t->summary && *t->summary) {
        type_doc_cell(f, t->summary, "");
        fputs(".\n\n", f);
    }
    if (!t->params) {
        fputs("No parameter table.\n\n", f);
        return;
    }
    if (!t->params[0].name) {
        fputs("No parameters.\n\n", f);
        return;
    }
    fputs("| name | form | type | default | range | what it does |\n| --- | --- | --- | --- | --- | --- |\n", f);
    for (const GParamInfo *p = t->params; p->name; p++) {
        fprintf(f, "| `%s` | %s | ", p->name, p->form == GPARAM_POSITIONAL ? "positional" : "named");
        type_doc_cell(f, p->type, "");
        fputs(" | ", f);
        type_doc_cell(f, p->def, "required");
        fputs(" | ", f);
        type_doc_cell(f, p->range, "");
        fputs(" | ", f);
        type_doc_cell(f, p->doc, "");
        fputs(" |\n", f);
    }
    fputc('\n', f);
}

static int type_doc_by_name_(const void *a, const void *b)
{
    return strcmp((*(const GTypeInfo *const *)a)->name, (*(const GTypeInfo *const *)b)->name);
}

/** Writes the section of a kind: the heading `## KIND`, the paragraph intro (NULL: none), then every type
 * registered in that kind, by name. Returns the number of types written, or -1 when out of memory. */
static inline int type_doc_kind(FILE *f, GKind kind, const char *intro)
{
    int n = gregistry_list(kind, NULL, 0);
    const GTypeInfo **types = malloc((size_t)(n > 0 ? n : 1) * sizeof *types);
    if (!types)
        return -1;
    int m = gregistry_list(kind, types, n);
    n = m < n ? m : n;
    qsort(types, (size_t)n, sizeof *types, type_doc_by_name_);
    fprintf(f, "## %s\n\n", gkind_name(kind));
    if (intro)
        fprintf(f, "%s\n", intro);
    for (int i = 0; i < n; i++)
        type_doc_type(f, types[i]);
    free(types);
    return n;
}

#endif
