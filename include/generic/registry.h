/* registry.h - type keyword -> vtable + parse routine, one table per kind of object.
 *
 * Built-in types register themselves on first use of the registry (lib/builtins.c holds their table);
 * plug-in modules add theirs while they load. Names are unique within a kind. */
#ifndef GENERIC_REGISTRY_H
#define GENERIC_REGISTRY_H

#include <stddef.h>
#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The kinds of objects a text file can hold. */
typedef enum GKind {
    GKIND_COLORMODEL = 0,
    GKIND_COLOR,
    GKIND_MATERIAL,
    GKIND_NODE,
    GKIND_GENERATOR,
    GKIND_OBJECT,
    GKIND_LIGHT,
    GKIND_CAMERA,
    GKIND_COUNT
} GKind;

typedef struct GReader GReader;

/** Parse routine: reads an entry's parameters (after its keyword) and creates the object. */
typedef int (*GParseFn)(GReader *reader, const void *vtable, void **object, GError *err);

/** One registered type. */
typedef struct GTypeInfo {
    GKind kind;
    const char *name;    /**< the type keyword */
    const void *vtable;  /**< e.g. a GColorModelClass or GMaterialClass */
    GParseFn parse;      /**< NULL when the type cannot be read from text */
    const char *summary; /**< one line for listings and error messages */
    /** Releases an object the parse routine made (when the library that owns it is destroyed). NULL takes the
     * kind's default: material and node: gmaterial_unref; colormodel: gcolormodel_destroy; color:
     * gcolorspec_destroy (reader.h); generator: its class's release (texture.h); other kinds: gmem_free. */
    void (*destroy)(void *object);
} GTypeInfo;

/** Registers a type (the struct is copied, the strings and vtable must outlive the registry);
 * G_ERR_EXISTS for a name already taken in that kind. Thread safe. */
int gregistry_add(const GTypeInfo *info, GError *err);
/** Finds a type by kind and keyword; NULL when unknown. */
const GTypeInfo *gregistry_find(GKind kind, const char *name);
/** Number of types of a kind; with out != NULL copies up to max pointers, in registration order. */
int gregistry_list(GKind kind, const GTypeInfo **out, int max);
/** Writes the registered names of a kind, comma separated, into buf (for "expected one of ..." messages). */
void gregistry_names(GKind kind, char *buf, size_t size);
/** Keyword of a kind ("colormodel", "material", ...). */
const char *gkind_name(GKind kind);

#ifdef __cplusplus
}
#endif
#endif
