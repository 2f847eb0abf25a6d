/* reader_library.c - GLibrary: the objects a text file defines, looked up by kind and name, freed at once. */
#include "reader_library.h"
#include "generic/memory.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef struct Entry {
    const GTypeInfo *type;
    char *name;  /* NULL for anonymous entries */
    void *object;
    int owned;   /* released with the library (aliases are not) */
    int toplevel;
    GTemplate *tmpl; /* what `like` re-reads of it (named entries read from text) */
} Entry;

typedef struct KeptText {
    char *text, *name; /* text NULL: dropped (no template reads it) */
    size_t len;
    size_t budget; /* bytes of the text reserved against the memory budget */
    size_t keep;   /* glibrary_drop_unused_texts: the end of the last span a template reads in it (0: none) */
} KeptText;

typedef struct Constant {
    char *name;
    double value;
    int line, col, text;
} Constant;

struct GLibrary {
    GColorModel *owned_model;
    const GColorModel *model;
    Entry *entries;
    int count, cap;
    int *slots; /* open addressing over named entries: index + 1, 0 = empty */
    int nslots, nnamed;
    int *toplevel[GKIND_MAX]; /* per kind, the indices of the top-level entries in order */
    int ntop[GKIND_MAX], captop[GKIND_MAX];
    KeptText *texts; /* every source text read, for `like` */
    int ntexts, captexts;
    Constant *consts; /* `define` */
    int nconsts, capconsts;
    int *cslots; /* open addressing over consts: index + 1 */
    int ncslots;
};

/* The namespace of a kind (materials and texture nodes share one). */
static int space(GKind kind) { return (int)gkind_namespace(kind); }

static uint32_t hash(int sp, const char *name)
{
    uint32_t h = 2166136261u ^ (uint32_t)sp;
    for (const unsigned char *p = (const unsigned char *)name; *p; p++)
        h = (h ^ *p) * 16777619u;
    /* FNV's low bits, the ones the table uses, mix poorly for names that differ in their last digits */
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

static int find_index(const GLibrary *lib, GKind kind, const char *name)
{
    if (!lib || !name || !lib->nslots)
        return -1;
    int sp = space(kind);
    for (uint32_t i = hash(sp, name) & (uint32_t)(lib->nslots - 1);; i = (i + 1) & (uint32_t)(lib->nslots - 1)) {
        int s = lib->slots[i];
        if (!s)
            return -1;
        const Entry *e = &lib->entries[s - 1];
        if (space(e->type->kind) == sp && strcmp(e->name, name) == 0)
            return s - 1;
    }
}

static void insert_slot(int *slots, int nslots, const Entry *e, int index)
{
    uint32_t i = hash(space(e->type->kind), e->name) & (uint32_t)(nslots - 1);
    while (slots[i])
        i = (i + 1) & (uint32_t)(nslots - 1);
    slots[i] = index + 1;
}

static int grow_slots(GLibrary *lib)
{
    int n = lib->nslots ? lib->nslots * 2 : 64;
    int *s = gmem_calloc((size_t)n, sizeof *s);
    if (!s)
        return G_ERR_NOMEM;
    for (int i = 0; i < lib->count; i++)
        if (lib->entries[i].name)
            insert_slot(s, n, &lib->entries[i], i);
    gmem_free(lib->slots);
    lib->slots = s;
    lib->nslots = n;
    return G_OK;
}

int glibrary_create(const GColorModel *model, GLibrary **out, GError *err)
{
    *out = NULL;
    GLibrary *lib = gmem_calloc(1, sizeof *lib);
    if (!lib)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating a library");
    lib->model = model;
    *out = lib;
    return G_OK;
}

void glibrary_destroy(GLibrary *lib)
{
    if (!lib)
        return;
    for (int i = lib->count - 1; i >= 0; i--) {
        Entry *e = &lib->entries[i];
        if (e->owned)
            gtypeinfo_release(e->type, e->object);
        gmem_free(e->name);
        gtemplate_free(e->tmpl);
    }
    for (int i = 0; i < lib->ntexts; i++) {
        if (lib->texts[i].text)
            gmem_budget_release(lib->texts[i].budget);
        gmem_free(lib->texts[i].text);
        gmem_free(lib->texts[i].name);
    }
    gmem_free(lib->texts);
    for (int i = 0; i < lib->nconsts; i++)
        gmem_free(lib->consts[i].name);
    gmem_free(lib->consts);
    gmem_free(lib->cslots);
    gmem_free(lib->entries);
    gmem_free(lib->slots);
    for (int k = 0; k < GKIND_MAX; k++)
        gmem_free(lib->toplevel[k]);
    gcolormodel_destroy(lib->owned_model);
    gmem_free(lib);
}

void glibrary_set_model(GLibrary *lib, GColorModel *owned, const GColorModel *borrowed)
{
    gcolormodel_destroy(lib->owned_model);
    lib->owned_model = owned;
    lib->model = owned ? owned : borrowed;
}

const GColorModel *glibrary_model_or_null(const GLibrary *lib) { return lib->model; }

const GColorModel *glibrary_colormodel(const GLibrary *lib)
{
    if (!lib)
        return NULL;
    if (!lib->model) { /* an empty library made without a model: the default is created on first use */
        GColorModel *m = NULL;
        if (gcolormodel_create("rgb", NULL, &m, NULL) == G_OK)
            glibrary_set_model((GLibrary *)lib, m, NULL);
    }
    return lib->model;
}

int glibrary_put(GLibrary *lib, const GTypeInfo *type, const char *name, void *object, int owned, int toplevel,
                 GError *err)
{
    int rc = G_OK;
    char *copy = NULL;
    if (!lib || !type || !object) {
        rc = gerror_set(err, G_ERR_INVALID, "nothing to add to the library");
    } else if (name && find_index(lib, type->kind, name) >= 0) {
        rc = gerror_set(err, G_ERR_EXISTS, "%s '%s' is already defined", gkind_name(type->kind), name);
    } else if (name && !(copy = gmem_strdup(name))) {
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    } else if (lib->count == lib->cap) {
        int cap = lib->cap ? lib->cap * 2 : 32;
        Entry *n = gmem_realloc(lib->entries, (size_t)cap * sizeof *n);
        if (!n)
            rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
        else
            lib->entries = n, lib->cap = cap;
    }
    if (rc == G_OK && name && (lib->nnamed + 1) * 2 > lib->nslots && grow_slots(lib) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    int kind = type ? (int)type->kind : 0;
    if (rc == G_OK && toplevel && (unsigned)kind < GKIND_MAX && lib->ntop[kind] == lib->captop[kind]) {
        int cap = lib->captop[kind] ? lib->captop[kind] * 2 : 16;
        int *t = gmem_realloc(lib->toplevel[kind], (size_t)cap * sizeof *t);
        if (!t)
            rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
        else
            lib->toplevel[kind] = t, lib->captop[kind] = cap;
    }
    if (rc != G_OK) {
        gmem_free(copy);
        if (owned)
            gtypeinfo_release(type, object);
        return rc;
    }
    Entry *e = &lib->entries[lib->count];
    e->type = type;
    e->name = copy;
    e->object = object;
    e->owned = owned;
    e->toplevel = toplevel;
    e->tmpl = NULL;
    if (copy) {
        insert_slot(lib->slots, lib->nslots, e, lib->count);
        lib->nnamed++;
    }
    if (toplevel && (unsigned)kind < GKIND_MAX)
        lib->toplevel[kind][lib->ntop[kind]++] = lib->count;
    lib->count++;
    return G_OK;
}

int glibrary_add(GLibrary *lib, const GTypeInfo *type, const char *name, void *object, GError *err)
{
    return glibrary_put(lib, type, name, object, 1, 1, err);
}

void *glibrary_find(const GLibrary *lib, GKind kind, const char *name)
{
    int i = find_index(lib, kind, name);
    return i >= 0 ? lib->entries[i].object : NULL;
}

const GTypeInfo *glibrary_find_type(const GLibrary *lib, GKind kind, const char *name)
{
    int i = find_index(lib, kind, name);
    return i >= 0 ? lib->entries[i].type : NULL;
}

GMaterial *glibrary_material(const GLibrary *lib, const char *name)
{
    return glibrary_find(lib, GKIND_MATERIAL, name);
}

int glibrary_color(const GLibrary *lib, const char *name, GColorRole role, GColor *out, GError *err)
{
    const GColorSpec *s = glibrary_find(lib, GKIND_COLOR, name);
    if (!s)
        return gerror_set(err, G_ERR_NOTFOUND, "no colour named '%s'", name ? name : "");
    return gcolorspec_to_color(s, role, out, err);
}

int glibrary_count(const GLibrary *lib, GKind kind)
{
    return lib && (unsigned)kind < GKIND_MAX ? lib->ntop[kind] : 0;
}

void *glibrary_entry(const GLibrary *lib, GKind kind, int index, const char **name, const GTypeInfo **type)
{
    if (!lib || (unsigned)kind >= GKIND_MAX || index < 0 || index >= lib->ntop[kind])
        return NULL;
    const Entry *e = &lib->entries[lib->toplevel[kind][index]];
    if (name)
        *name = e->name;
    if (type)
        *type = e->type;
    return e->object;
}

void glibrary_names(const GLibrary *lib, GKind kind, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; lib && i < lib->count && used + 1 < size; i++) {
        const Entry *e = &lib->entries[i];
        if (!e->name || space(e->type->kind) != space(kind))
            continue;
        int w = snprintf(buf + used, size - used, "%s%s", used ? ", " : "", e->name);
        if (w < 0)
            break;
        used += (size_t)w;
    }
    if (!used)
        snprintf(buf, size, "none");
}

/* ---- kept texts, templates, constants ---- */

int glibrary_keep_text(GLibrary *lib, char *text, size_t len, size_t budget, const char *name, int *id)
{
    char *n = NULL;
    if (lib->ntexts == lib->captexts) {
        int cap = lib->captexts ? lib->captexts * 2 : 8;
        KeptText *k = gmem_realloc(lib->texts, (size_t)cap * sizeof *k);
        if (!k) {
            gmem_budget_release(budget);
            gmem_free(text);
            return G_ERR_NOMEM;
        }
        lib->texts = k;
        lib->captexts = cap;
    }
    if (!(n = gmem_strdup(name ? name : "?"))) {
        gmem_budget_release(budget);
        gmem_free(text);
        return G_ERR_NOMEM;
    }
    lib->texts[lib->ntexts] = (KeptText){text, n, len, budget, 0};
    *id = lib->ntexts++;
    return G_OK;
}

/* The shortest tail of a text worth cutting off when no template reads it (a smaller one is not worth the copy). */
#define GLIBRARY_TEXT_TAIL_MIN (64u * 1024u)

/* Notes the end of a span a template reads in its text. */
static void mark_span(GLibrary *lib, const GSpan *sp)
{
    if (sp->text >= 0 && sp->text < lib->ntexts && sp->end > lib->texts[sp->text].keep)
        lib->texts[sp->text].keep = sp->end;
}

void glibrary_drop_unused_texts(GLibrary *lib)
{
    for (int i = 0; i < lib->ntexts; i++)
        lib->texts[i].keep = 0;
    for (int i = 0; i < lib->count; i++) {
        const GTemplate *t = lib->entries[i].tmpl;
        if (!t)
            continue;
        if (t->has_block) {
            mark_span(lib, &t->open);
            mark_span(lib, &t->close);
        }
        if (t->whole_state == 1)
            mark_span(lib, &t->whole);
        for (int k = 0; k < t->nparams; k++)
            mark_span(lib, &t->params[k].span);
    }
    for (int i = 0; i < lib->ntexts; i++) {
        KeptText *k = &lib->texts[i];
        if (!k->text || (k->keep && k->len - k->keep < GLIBRARY_TEXT_TAIL_MIN))
            continue;
        if (!k->keep) {
            gmem_budget_release(k->budget);
            gmem_free(k->text);
            k->text = NULL;
            k->len = 0;
            continue;
        }
        /* the spans lie in the text's first keep bytes: the rest goes (when the smaller block cannot be had, the
         * text stays whole, still charged in full) */
        char *shorter = gmem_realloc(k->text, k->keep + 1);
        if (shorter)
            k->text = shorter;
        k->text[k->keep] = '\0';
        k->len = k->keep;
        if (shorter && k->budget > k->keep + 1) {
            gmem_budget_release(k->budget - (k->keep + 1));
            k->budget = k->keep + 1;
        }
    }
}

const char *glibrary_text(const GLibrary *lib, int id, size_t *len, const char **name)
{
    if (!lib || id < 0 || id >= lib->ntexts)
        return NULL;
    if (len)
        *len = lib->texts[id].len;
    if (name)
        *name = lib->texts[id].name;
    return lib->texts[id].text ? lib->texts[id].text : "";
}

int glibrary_set_template(GLibrary *lib, GKind kind, const char *name, GTemplate *t)
{
    int i = find_index(lib, kind, name);
    if (i < 0) {
        gtemplate_free(t);
        return G_ERR_NOTFOUND;
    }
    gtemplate_free(lib->entries[i].tmpl);
    lib->entries[i].tmpl = t;
    return G_OK;
}

const GTemplate *glibrary_template(const GLibrary *lib, GKind kind, const char *name)
{
    int i = find_index(lib, kind, name);
    return i >= 0 ? lib->entries[i].tmpl : NULL;
}

const char *glibrary_entry_base(const GLibrary *lib, GKind kind, int index)
{
    if (!lib || (unsigned)kind >= GKIND_MAX || index < 0 || index >= lib->ntop[kind])
        return NULL;
    const Entry *e = &lib->entries[lib->toplevel[kind][index]];
    return e->tmpl ? e->tmpl->base : NULL;
}

static int find_constant(const GLibrary *lib, const char *name)
{
    if (!lib->ncslots)
        return -1;
    uint32_t mask = (uint32_t)lib->ncslots - 1;
    for (uint32_t i = hash(-1, name) & mask;; i = (i + 1) & mask) {
        int s = lib->cslots[i];
        if (!s)
            return -1;
        if (strcmp(lib->consts[s - 1].name, name) == 0)
            return s - 1;
    }
}

int glibrary_define_constant(GLibrary *lib, const char *name, double value, int line, int col, int text)
{
    if (find_constant(lib, name) >= 0)
        return G_ERR_EXISTS;
    if ((lib->nconsts + 1) * 2 > lib->ncslots) {
        int n = lib->ncslots ? lib->ncslots * 2 : 64;
        int *s = gmem_calloc((size_t)n, sizeof *s);
        if (!s)
            return G_ERR_NOMEM;
        for (int i = 0; i < lib->nconsts; i++) {
            uint32_t j = hash(-1, lib->consts[i].name) & (uint32_t)(n - 1);
            while (s[j])
                j = (j + 1) & (uint32_t)(n - 1);
            s[j] = i + 1;
        }
        gmem_free(lib->cslots);
        lib->cslots = s;
        lib->ncslots = n;
    }
    if (lib->nconsts == lib->capconsts) {
        int cap = lib->capconsts ? lib->capconsts * 2 : 16;
        Constant *c = gmem_realloc(lib->consts, (size_t)cap * sizeof *c);
        if (!c)
            return G_ERR_NOMEM;
        lib->consts = c;
        lib->capconsts = cap;
    }
    char *copy = gmem_strdup(name);
    if (!copy)
        return G_ERR_NOMEM;
    lib->consts[lib->nconsts] = (Constant){copy, value, line, col, text};
    uint32_t j = hash(-1, name) & (uint32_t)(lib->ncslots - 1);
    while (lib->cslots[j])
        j = (j + 1) & (uint32_t)(lib->ncslots - 1);
    lib->cslots[j] = ++lib->nconsts;
    return G_OK;
}

int glibrary_constant(const GLibrary *lib, const char *name, double *value, int *line, int *col, int *text)
{
    int i = lib ? find_constant(lib, name) : -1;
    if (i < 0)
        return 0;
    const Constant *c = &lib->consts[i];
    if (value)
        *value = c->value;
    if (line)
        *line = c->line;
    if (col)
        *col = c->col;
    if (text)
        *text = c->text;
    return 1;
}
