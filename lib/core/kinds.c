/* kinds.c - the kinds of objects a text file holds: the library's five, and those applications register at run
 * time. Kinds are only ever added, so a kind's record never changes once its number is handed out: readers take
 * the count with an acquire load and read the records below it without the lock. */
#include "generic/registry.h"
#include "generic/colorspec.h"
#include "generic/material.h"
#include "generic/memory.h"
#include "generic/texture.h"

#include <ctype.h>
#include <pthread.h>
#include <stdatomic.h>
#include <string.h>

static void release_colormodel(void *object) { gcolormodel_destroy(object); }
static void release_colorspec(void *object) { gcolorspec_destroy(object); }
static void release_material(void *object) { gmaterial_unref(object); }
static void release_generator(void *object) { ggenerator_unref(object); }

static GKindInfo kinds[GKIND_MAX] = {
    [GKIND_COLORMODEL] = {"colormodel", release_colormodel, 0},
    [GKIND_COLOR] = {"color", release_colorspec, 0},
    [GKIND_MATERIAL] = {"material", release_material, 0},
    [GKIND_NODE] = {"node", release_material, 1},
    [GKIND_GENERATOR] = {"generator", release_generator, 0},
};
static atomic_int nkinds = GKIND_GENERATOR + 1;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

int gkind_count(void) { return atomic_load_explicit(&nkinds, memory_order_acquire); }

const GKindInfo *gkind_info(GKind kind)
{
    return (unsigned)kind < (unsigned)gkind_count() ? &kinds[kind] : NULL;
}

const char *gkind_name(GKind kind)
{
    const GKindInfo *k = gkind_info(kind);
    return k ? k->keyword : "?";
}

int gkind_find(const char *keyword, GKind *out)
{
    int n = gkind_count();
    for (int k = 0; keyword && k < n; k++)
        if (strcmp(kinds[k].keyword, keyword) == 0) {
            if (out)
                *out = (GKind)k;
            return 1;
        }
    return 0;
}

GKind gkind_namespace(GKind kind)
{
    const GKindInfo *k = gkind_info(kind);
    return k && k->shares_material_names ? GKIND_MATERIAL : kind;
}

/* An identifier of the format ([A-Za-z_][A-Za-z0-9_.-]*) that is none of its statements. */
static int valid_keyword(const char *s)
{
    static const char *const statements[] = {"include", "plugin", "define", NULL};
    if (!s || !(isalpha((unsigned char)s[0]) || s[0] == '_'))
        return 0;
    for (const char *p = s; *p; p++)
        if (!(isalnum((unsigned char)*p) || *p == '_' || *p == '.' || *p == '-'))
            return 0;
    for (int i = 0; statements[i]; i++)
        if (strcmp(s, statements[i]) == 0)
            return 0;
    return 1;
}

int gregistry_add_kind(const GKindInfo *info, GKind *out, GError *err)
{
    if (!info || !valid_keyword(info->keyword))
        return gerror_set(err, G_ERR_INVALID, "invalid kind registration: the keyword '%s' is not an identifier, or is "
                          "a statement of the format", info && info->keyword ? info->keyword : "");
    pthread_mutex_lock(&lock);
    int n = atomic_load_explicit(&nkinds, memory_order_relaxed), rc = G_OK;
    GKind have;
    if (gkind_find(info->keyword, &have)) {
        const GKindInfo *k = &kinds[have];
        if (k->destroy == info->destroy && !k->shares_material_names == !info->shares_material_names) {
            if (out)
                *out = have;
        } else {
            rc = gerror_set(err, G_ERR_EXISTS, "kind '%s' is already registered", info->keyword);
        }
    } else if (n == GKIND_MAX) {
        rc = gerror_set(err, G_ERR_INVALID, "cannot register kind '%s': there are %d kinds already, the most a "
                        "process has", info->keyword, GKIND_MAX);
    } else {
        kinds[n] = *info;
        atomic_store_explicit(&nkinds, n + 1, memory_order_release);
        if (out)
            *out = (GKind)n;
    }
    pthread_mutex_unlock(&lock);
    return rc;
}
