/* registry.c - per-kind tables of registered types. */
#include "generic/registry.h"
#include "generic/memory.h"
#include "builtins.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

/* Entries are copied to the heap one by one so pointers handed out stay valid as tables grow. */
typedef struct Table {
    GTypeInfo **items;
    int count, cap;
} Table;

static Table tables[GKIND_COUNT];
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static const char *const kind_names[GKIND_COUNT] = {
    "colormodel", "color", "material", "node", "generator", "object", "light", "camera",
};

const char *gkind_name(GKind kind)
{
    return (unsigned)kind < GKIND_COUNT ? kind_names[kind] : "?";
}

static int add_locked(const GTypeInfo *info, GError *err)
{
    Table *t = &tables[info->kind];
    for (int i = 0; i < t->count; i++)
        if (strcmp(t->items[i]->name, info->name) == 0)
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

static void register_builtins(void)
{
    for (const GTypeInfo *const *p = gbuiltin_types(); *p; p++)
        add_locked(*p, NULL);
}

static void ensure_init(void) { pthread_once(&once, register_builtins); }

int gregistry_add(const GTypeInfo *info, GError *err)
{
    if (!info || !info->name || !info->name[0] || (unsigned)info->kind >= GKIND_COUNT)
        return gerror_set(err, G_ERR_INVALID, "invalid type registration");
    ensure_init();
    pthread_mutex_lock(&lock);
    int rc = add_locked(info, err);
    pthread_mutex_unlock(&lock);
    return rc;
}

const GTypeInfo *gregistry_find(GKind kind, const char *name)
{
    if ((unsigned)kind >= GKIND_COUNT || !name)
        return NULL;
    ensure_init();
    const GTypeInfo *found = NULL;
    pthread_mutex_lock(&lock);
    Table *t = &tables[kind];
    for (int i = 0; i < t->count && !found; i++)
        if (strcmp(t->items[i]->name, name) == 0)
            found = t->items[i];
    pthread_mutex_unlock(&lock);
    return found;
}

int gregistry_list(GKind kind, const GTypeInfo **out, int max)
{
    if ((unsigned)kind >= GKIND_COUNT)
        return 0;
    ensure_init();
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
    if ((unsigned)kind >= GKIND_COUNT)
        return;
    ensure_init();
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
