/* registry.h - the kinds of objects a text file holds, and per kind its types: keyword -> vtable + parse routine.
 *
 * Kinds. The library knows its own five (colormodel, color, material, node, generator); an application adds its
 * own at run time (gregistry_add_kind: a renderer's objects, lights and cameras), each with the statement keyword
 * of its entries and the default release of its objects. Types. The registry starts empty of types. Every type,
 * built-in or from a module, is described by one GTypeInfo record that sits beside the type's code (GENERIC_TYPE
 * in plugin.h). The built-in records are collected at build time into a generated list that a program registers
 * with one call, generic_register_builtins() (builtins.h); run-time modules register theirs while they load
 * (plugin.h). Names are unique within a kind. See docs/ARCHITECTURE.md. */
#ifndef GENERIC_REGISTRY_H
#define GENERIC_REGISTRY_H

#include "export.h"
#include <stddef.h>
#include "error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A kind of object a text file holds. The library's own kinds are these; the kinds an application registers
 * (gregistry_add_kind) take the numbers after them, in the order they are registered, below GKIND_MAX. */
typedef enum GKind {
    GKIND_COLORMODEL = 0, /**< colour models (GColorModel, color.h) */
    GKIND_COLOR,          /**< colour literals (GColorSpec, colorspec.h) */
    GKIND_MATERIAL,       /**< materials (GMaterial, material.h) */
    GKIND_NODE,           /**< texture tree nodes (GMaterial); they share the materials' names */
    GKIND_GENERATOR       /**< texture generators (GGenerator, texture.h) */
} GKind;

/** The most kinds a process has, the library's and the applications' together. */
#define GKIND_MAX 32

/** A kind of object an application adds (gregistry_add_kind). */
typedef struct GKindInfo {
    /** The keyword of its entries in a file (`object ball sphere { ... }`): an identifier, not the keyword of
     * another kind nor a statement of the format (include, plugin, define). The string must outlive the
     * registry. */
    const char *keyword;
    /** Releases an object of a type of this kind whose record has no destroy of its own (GTypeInfo.destroy);
     * NULL: gmem_free. */
    void (*destroy)(void *object);
    /** Non-zero: the kind's entries share the materials' names and type keywords, as texture nodes do (a name or
     * a type of either stands wherever the other is read), so its objects must be GMaterials. */
    int shares_material_names;
} GKindInfo;

typedef struct GReader GReader;

/** Parse routine: reads an entry's parameters (after its keyword) and creates the object. */
typedef int (*GParseFn)(GReader *reader, const void *vtable, void **object, GError *err);

/** The members every vtable begins with, in this order (GColorModelClass, GMaterialClass, GGeneratorClass
 * and any class a module defines for its own kind): the registry reads a type's name and summary from them. */
typedef struct GClassHeader {
    int abi_version;         /**< the kind's interface version */
    const char *name;        /**< the type keyword */
    const char *description; /**< one line for listings */
} GClassHeader;

/** One registered type. A record with a vtable may leave name and summary NULL: they are then the vtable's
 * (GClassHeader), so the keyword is written once, in the class. */
typedef struct GTypeInfo {
    GKind kind;
    const char *name;    /**< the type keyword (NULL: the vtable's name) */
    const void *vtable;  /**< e.g. a GColorModelClass or GMaterialClass */
    GParseFn parse;      /**< NULL when the type cannot be read from text */
    const char *summary; /**< one line for listings and error messages (NULL: the vtable's description) */
    /** Releases an object the parse routine made (when the library that owns it is destroyed). NULL takes the
     * kind's default: material and node: gmaterial_unref; colormodel: gcolormodel_destroy; color:
     * gcolorspec_destroy (colorspec.h); generator: ggenerator_unref (texture.h); a kind an application registers:
     * its GKindInfo.destroy. */
    void (*destroy)(void *object);
    /** The parameters the parse routine reads (GParamInfo below): rows ended by one whose name is NULL; a table
     * of that row alone says the type takes none. NULL when the type does not describe them. */
    const struct GParamInfo *params;
} GTypeInfo;

/** Registers a kind (the struct is copied) and gives its number in *out (optional). Registering a keyword again
 * with the same destroy and namespace gives the kind registered first, so a program may register its kinds at
 * every start of its work. G_ERR_EXISTS for a keyword taken otherwise (a library kind's among them),
 * G_ERR_INVALID for a keyword that is not an identifier or is a statement of the format, and beyond GKIND_MAX
 * kinds. Thread safe. */
GENERIC_API GENERIC_NODISCARD int gregistry_add_kind(const GKindInfo *info, GKind *out, GError *err);
/** The number of kinds, the library's and the applications': every kind is below it. Thread safe. */
GENERIC_API GENERIC_NODISCARD int gkind_count(void);
/** What is known of a kind (the library's kinds have the defaults GTypeInfo.destroy lists); NULL when kind is
 * not one. Valid for the life of the process. */
GENERIC_API const GKindInfo *gkind_info(GKind kind);
/** 1 with *out the kind whose entries are written with that keyword, 0 when none is. */
GENERIC_API GENERIC_NODISCARD int gkind_find(const char *keyword, GKind *out);
/** The kind whose names an entry of kind shares: GKIND_MATERIAL for materials, nodes and every kind registered
 * with shares_material_names; kind itself otherwise. */
GENERIC_API GKind gkind_namespace(GKind kind);

/** Registers a type (the struct is copied, with name and summary filled from the vtable when NULL; the
 * strings and vtable must outlive the registry); G_ERR_EXISTS for a name already taken in that kind,
 * G_ERR_INVALID for a record without a registered kind or a name. Thread safe. */
GENERIC_API GENERIC_NODISCARD int gregistry_add(const GTypeInfo *info, GError *err);
/** Registers every record of a NULL-terminated list, in order. A record registered already (the same kind,
 * name, vtable and parse routine) is skipped, so registering a list twice is a no-op; the first other failure
 * stops and is returned (the records before it stay registered). Thread safe. */
GENERIC_API GENERIC_NODISCARD int gregistry_add_list(const GTypeInfo *const *list, GError *err);
/** Completes a copy of a record: name and summary from its vtable's GClassHeader when they are NULL.
 * G_ERR_INVALID when the kind is unknown or no name can be found. */
GENERIC_API GENERIC_NODISCARD int gtypeinfo_complete(GTypeInfo *info, GError *err);
/** Finds a type by kind and keyword; NULL when unknown. */
GENERIC_API const GTypeInfo *gregistry_find(GKind kind, const char *name);
/** Number of types of a kind; with out != NULL copies up to max pointers, in registration order. */
GENERIC_API GENERIC_NODISCARD int gregistry_list(GKind kind, const GTypeInfo **out, int max);
/** Writes the registered names of a kind, comma separated, into buf (for "expected one of ..." messages). */
GENERIC_API void gregistry_names(GKind kind, char *buf, size_t size);
/** Releases an object a type made: with type->destroy, else the default of its kind (see GTypeInfo.destroy);
 * NULL object is a no-op. */
GENERIC_API void gtypeinfo_release(const GTypeInfo *type, void *object);
/** Keyword of a kind ("colormodel", "material", ...; "?" when kind is not one). */
GENERIC_API const char *gkind_name(GKind kind);

/** How a parameter is written in an entry. */
typedef enum GParamForm {
    GPARAM_NAMED = 0, /**< `NAME VALUE` in the entry's optional `{ ... }` block: any order, each at most once */
    GPARAM_POSITIONAL /**< a value after the type keyword (or inside its positional block), in table order */
} GParamForm;

/** One row of a type's parameter table (GTypeInfo.params): what a parse routine reads, for the reference pages
 * (`gmat types --markdown`) and for the checks that the table and the routine agree. Every string is static.
 * `type` is the syntax of the value: "number" (or a defined constant), "numbers" (several in a row; `doc` says how
 * many), "integer", "bool", "string" (quoted), "path" (a quoted file name, relative to the file), "vector"
 * (`<x, y, z>` or `x y z`), "color", "material" (a material or texture node), "generator", "choice" (one of the
 * words `range` lists), "formula" (a number or a keyword with numbers; `range` lists the forms), "block" (a
 * `{ ... }` of its own syntax, which `range` gives), "shape" (a CSG or CPG shape tree, its grammar in `range`),
 * "texnumber" (a number or a generator: a textured parameter, kit/texparam.h), "texcolor" (a colour, `image { ... }`
 * or `mix { ... }`: a textured colour, kit/texparam.h), or the keyword of a kind an application registers. */
typedef struct GParamInfo {
    const char *name;  /**< the keyword of a named parameter; a placeholder (e.g. "KELVIN") for a positional one */
    GParamForm form;   /**< how it is written */
    const char *type;  /**< the value's syntax (above) */
    const char *def;   /**< the value taken when it is left out, as text; NULL: it must be given */
    const char *range; /**< the values accepted ("[0, 1]", "object, world, uv"); NULL: any value of the type */
    const char *doc;   /**< what it does, in a sentence */
} GParamInfo;

#ifdef __cplusplus
}
#endif
#endif
