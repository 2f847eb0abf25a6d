/* registry.c - per-kind tables of registered types (the kinds are lib/core/kinds.c's). The registry starts empty: it
 * knows no concrete type (programs register the built-ins with generic_register_builtins, modules add theirs while
 * they load). */
#include "generic/registry.h"
#include "generic/memory.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

/* Entries are copied to the heap one by one so pointers handed out stay valid as tables grow. */
typedef struct Table {
    GTypeInfo **items;
    int count, cap;
} Table;

static Table tables[GKIND_MAX];
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

void gtypeinfo_release(const GTypeInfo *type, void *object)
{
    if (!object)
        return;
    void (*destroy)(void *) = type ? type->destroy : NULL;
    const GKindInfo *kind = type && !destroy ? gkind_info(type->kind) : NULL;
    if (kind)
        destroy = kind->destroy;
    if (destroy)
        destroy(object);
    else
        gmem_free(object);
}

int gtypeinfo_complete(GTypeInfo *info, GError *err)
{
    if (!info || !gkind_info(info->kind))
        return gerror_set(err, G_ERR_INVALID, "invalid type registration: unknown kind");
    if ((!info->name || !info->summary) && info->vtable) {
        GClassHeader h; /* the vtable's leading members (copied: the vtable is of another struct type) */
        memcpy(&h, info->vtable, sizeof h);
        if (!info->name)
            info->name = h.name;
        if (!info->summary)
            info->summary = h.description;
    }
    if (!info->name || !info->name[0])
        return gerror_set(err, G_ERR_INVALID, "invalid %s type registration: no name", gkind_name(info->kind));
    if (!info->summary)
        info->summary = "";
    return G_OK;
}

/* The registered record of that kind and name, or NULL; the caller holds the lock. */
static const GTypeInfo *find_locked(GKind kind, const char *name)
{
    Table *t = &tables[kind];
    for (int i = 0; i < t->count; i++) /* the first bytes first: most names looked up are not types */
        if (t->items[i]->name[0] == name[0] && strcmp(t->items[i]->name, name) == 0)
            return t->items[i];
    return NULL;
}

/* Adds a completed record; the caller holds the lock. */
static int add_locked(const GTypeInfo *info, GError *err)
{
    Table *t = &tables[info->kind];
    if (find_locked(info->kind, info->name))
        return gerror_set(err, G_ERR_EXISTS, "%s type '%s' is already registered", gkind_name(info->kind),
                          info->name);
    if (t->count == t->cap) {
        int cap = t->cap ? t->cap * 2 : 16;
        GTypeInfo **n = gmem_realloc(t->items, (size_t)cap * sizeof *n);
        if (!n)
            return gerror_set(err, G_ERR_NOMEM, "out of memory registering '%s'", info->name);
        t->items = n;
        t->cap = cap;
    }
    GTypeInfo *copy = gmem_alloc(sizeof *copy);
    if (!copy)
        return gerror_set(err, G_ERR_NOMEM, "out of memory registering '%s'", info->name);
    *copy = *info;
    t->items[t->count++] = copy;
    return G_OK;
}

int gregistry_add(const GTypeInfo *info, GError *err)
{
    if (!info)
        return gerror_set(err, G_ERR_INVALID, "invalid type registration: no record");
    GTypeInfo t = *info;
    int rc = gtypeinfo_complete(&t, err);
    if (rc != G_OK)
        return rc;
    pthread_mutex_lock(&lock);
    rc = add_locked(&t, err);
    pthread_mutex_unlock(&lock);
    return rc;
}

int gregistry_add_list(const GTypeInfo *const *list, GError *err)
{
    int rc = G_OK;
    pthread_mutex_lock(&lock);
    for (const GTypeInfo *const *p = list; p && *p && rc == G_OK; p++) {
        GTypeInfo t = **p;
        if ((rc = gtypeinfo_complete(&t, err)) != G_OK)
            break;
        const GTypeInfo *have = find_locked(t.kind, t.name);
        if (have && have->vtable == t.vtable && have->parse == t.parse)
            continue; /* this very record: registered before */
        rc = add_locked(&t, err);
    }
    pthread_mutex_unlock(&lock);
    return rc;
}

const GTypeInfo *gregistry_find(GKind kind, const char *name)
{
    if (!gkind_info(kind) || !name)
        return NULL;
    pthread_mutex_lock(&lock);
    const GTypeInfo *found = find_locked(kind, name);
    pthread_mutex_unlock(&lock);
    return found;
}

int gregistry_list(GKind kind, const GTypeInfo **out, int max)
{
    if (!gkind_info(kind))
        return 0;
    pthread_mutex_lock(&lock);
    Table *t = &tables[kind];
    int n = t->count;
    for (int i = 0; out && i < n && i < max; i++)
        out[i] = t->items[i];
    pthread_mutex_unlock(&lock);
    return n;
}

void gregistry_names(GKind kind, char *buf, size_t size)
{
    if (!size)
        return;
    buf[0] = '\0';
    if (!gkind_info(kind))
        return;
    pthread_mutex_lock(&lock);
    Table *t = &tables[kind];
    size_t used = 0;
    for (int i = 0; i < t->count && used < size; i++) {
        int w = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", t->items[i]->name);
        if (w < 0)
            break;
        used += (size_t)w;
    }
    pthread_mutex_unlock(&lock);
}
