/* plugin.h - run-time modules: a shared object that registers colour models, colour literal types, materials,
 * texture nodes or generators (any GKind) while it loads.
 *
 * Every type, built-in or not, is described by one record beside its code, written with GENERIC_TYPE (or
 * GENERIC_TYPE_PARAMS, which adds the table of its parameters):
 *
 *     #include <generic/plugin.h>
 *     static const GMaterialClass my_class = {GMATERIAL_ABI_VERSION, "oren_nayar", "rough diffuse", ...};
 *     static int my_parse(GReader *r, const void *vtable, void **object, GError *err) { ... }
 *     GENERIC_TYPE(oren_nayar, GKIND_MATERIAL, &my_class, my_parse, NULL);
 *
 * In the library's own sources that line is all: the build collects every GENERIC_TYPE record of colormodels/,
 * colors/, materials/ and textures/ into the generated list of builtins.h. A file becomes a run-time module by one
 * more line naming its records,
 *
 *     GENERIC_MODULE(&gtype_oren_nayar);
 *
 * which defines the two symbols a module exports (generic_module_abi and generic_module_init; see
 * examples/plugins/ for complete modules). A module may also write generic_module_init by hand and call
 * api->add_type for each record; a type of a kind an application registers (registry.h: gtrace's object, light and
 * camera) has no constant kind to write in a record, so its module finds the kind with gkind_find in its init.
 *
 * The loader (gplugin_load, or a `plugin "file.so"` statement in a text file) first reads the file itself, without
 * running it: it must be an ELF shared object for this machine whose dynamic symbol table defines both module
 * symbols, and the generic_module_abi stored in it must be the library's GMODULE_ABI_VERSION (the message states
 * both) - so a file that is not a module, or a module for another interface, is refused before any of its code
 * (its ELF constructors included) runs. Only then is the same open file passed to dlopen(RTLD_NOW |
 * RTLD_LOCAL), and generic_module_init called. Types added through
 * api->add_type are collected and registered together when init returns 0; if init fails, or one of the names is
 * taken already, none is registered and the module is closed again. Registration is only possible during init.
 *
 * A module is built against the installed headers only and is not linked with libgeneric: the library's
 * functions are resolved from the program that loads it (programs link libgeneric.so, or the static library
 * with -rdynamic). A loaded module stays loaded for the life of the process (its types stay registered); loading
 * the same file again does nothing.
 *
 * Finding a module. A name that contains a slash is a path: as it is for gplugin_load (relative to the current
 * directory), relative to the including file for a `plugin` statement. A bare name ("grey.so") is looked up
 * in each directory of the environment variable GENERIC_PLUGIN_PATH (colon-separated, searched in order; empty
 * entries are skipped), then in the installed plug-in directory (PREFIX/lib/generic/plugins, fixed at build
 * time), and only then in a base directory (the current directory for gplugin_load, the including file's
 * directory for a `plugin` statement): a module beside a downloaded scene never replaces an installed one. The
 * first existing file is loaded; when none exists the error lists every directory searched.
 *
 * Consent. Loading a module runs its native code. Modules named on a tool's command line (--plugin) or by a
 * program (gplugin_load) are the user's choice; a `plugin` statement in a file is refused unless the caller
 * allows it (GReaderOptions.allow_plugins, the tools' --allow-plugins, or GENERIC_ALLOW_PLUGINS=1 in the
 * environment; see reader.h). */
#ifndef GENERIC_PLUGIN_H
#define GENERIC_PLUGIN_H

#include "export.h"
#include "error.h"
#include "registry.h"
#include "color.h"
#include "material.h"
#include "reader.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Version of the module interface: GModuleApi, GTypeInfo, GParseFn, the reader API, the vtables of every
 * kind and the layout of the structures they pass (GSurfPoint). Raised whenever any of them changes
 * incompatibly. The versions of the interfaces:
 *   module    2: GSurfPoint has the cache scopes of transform nodes and the footprint ellipse.
 *             3: GColor and GColorModelClass as in colour version 2; GError has the position and parameter
 *                fields; the GMaterial header has depth and cost.
 *             4: GSurfPoint's public fields, then its caches as one private member (GSurfPointPrivate); GTypeInfo
 *                has its parameter table (the loader copies a module's records whole).
 *   colour    2: GColor records its storage and capacity; GColorModelClass has the optional fill, exp_scaled
 *                and axpy slots. 3: the optional band slots (band_count, band_mask, band_value).
 *   material  2: the header has depth and cost. 3: the sampling slots sample, pdf and is_delta. 4: the header
 *                has flags. */
#define GMODULE_ABI_VERSION 4

/** Name of the exported `const int` holding the module's GMODULE_ABI_VERSION. */
#define GMODULE_ABI_SYMBOL "generic_module_abi"
/** Name of the exported GModuleInitFn. */
#define GMODULE_INIT_SYMBOL "generic_module_init"

/** Marks the two symbols a module exports (visible even when the module is built with -fvisibility=hidden). */
#if defined(__GNUC__)
#define GENERIC_MODULE_EXPORT __attribute__((visibility("default")))
#else
#define GENERIC_MODULE_EXPORT
#endif

typedef struct GModuleApi GModuleApi;

/** What the loader hands to generic_module_init. */
struct GModuleApi {
    int abi_version;          /**< the library's GMODULE_ABI_VERSION */
    int color_abi_version;    /**< the library's GCOLOR_ABI_VERSION */
    int material_abi_version; /**< the library's GMATERIAL_ABI_VERSION */
    const char *path;         /**< the module's file */
    /** Adds a type (copied; its strings, vtable and functions must live in the module). Only valid during
     * generic_module_init; the types are registered when init succeeds. */
    int (*add_type)(GModuleApi *api, const GTypeInfo *info, GError *err);
    void *priv; /**< the loader's */
};

/** The module's entry point: registers its types through api->add_type; 0 on success. */
typedef int (*GModuleInitFn)(GModuleApi *api, GError *err);

/** Defines `const GTypeInfo gtype_<id>`, the record of a type: its kind, vtable, parse routine (NULL when it
 * cannot be read from text) and destroy (NULL: the kind's default, see GTypeInfo); name and summary are the
 * vtable's GClassHeader (the keyword is written once, in the class). It has no parameter table. */
#define GENERIC_TYPE(id, kind, vtable, parse, destroy) \
    const GTypeInfo gtype_##id = {(kind), NULL, (vtable), (parse), NULL, (destroy), NULL}

/** GENERIC_TYPE with the type's parameter table (GParamInfo rows ended by {NULL}, registry.h):
 *
 *     static const GParamInfo my_params[] = {
 *         {"reflectance", GPARAM_NAMED, "color", "grey 0.8", "[0, 1] per sample", "the diffuse albedo"},
 *         {"sigma", GPARAM_NAMED, "number", "20", "[0, 90]", "the facets' slope deviation, in degrees"},
 *         {NULL},
 *     };
 *     GENERIC_TYPE_PARAMS(oren_nayar, GKIND_MATERIAL, &my_class, my_parse, NULL, my_params);
 *
 * Every built-in type has one; `gmat types --markdown` prints them as the reference pages. */
#define GENERIC_TYPE_PARAMS(id, kind, vtable, parse, destroy, params) \
    const GTypeInfo gtype_##id = {(kind), NULL, (vtable), (parse), NULL, (destroy), (params)}

/** The record of a type without a vtable (a colour literal type): name and summary are given here. */
#define GENERIC_TYPE_NAMED(id, kind, name, parse, summary, destroy) \
    const GTypeInfo gtype_##id = {(kind), (name), NULL, (parse), (summary), (destroy), NULL}

/** GENERIC_TYPE_NAMED with the type's parameter table (as GENERIC_TYPE_PARAMS). */
#define GENERIC_TYPE_NAMED_PARAMS(id, kind, name, parse, summary, destroy, params) \
    const GTypeInfo gtype_##id = {(kind), (name), NULL, (parse), (summary), (destroy), (params)}

/** Makes the file it ends a run-time module registering the given records (`&gtype_<id>`, ...): defines
 * generic_module_abi and a generic_module_init that adds each record with api->add_type. */
#define GENERIC_MODULE(...)                                                                        \
    GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;                      \
    GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)                    \
    {                                                                                              \
        static const GTypeInfo *const generic_module_types_[] = {__VA_ARGS__};                     \
        for (size_t i_ = 0; i_ < sizeof generic_module_types_ / sizeof generic_module_types_[0]; i_++) { \
            int rc_ = api->add_type(api, generic_module_types_[i_], err);                          \
            if (rc_ != G_OK)                                                                       \
                return rc_;                                                                        \
        }                                                                                          \
        return G_OK;                                                                               \
    }                                                                                              \
    typedef int generic_module_end_

/** Loads a module: G_ERR_IO with the dlerror() text when it cannot be opened or lacks a symbol, G_ERR_VERSION
 * when it was built for another GMODULE_ABI_VERSION, the init's status when that fails, G_ERR_EXISTS when it
 * registers a name taken already. Loading the same file twice is a no-op. Thread safe. */
GENERIC_API GENERIC_NODISCARD int gplugin_load(const char *path, GError *err);
/** Loads a module found by the rule above with `dir` as the base directory (NULL = the current directory):
 * a name with a slash is dir/name (or name itself when absolute); a bare name is looked up in the directories of
 * GENERIC_PLUGIN_PATH in order, then the installed plug-in directory, and only then dir/name, so that a module
 * beside a (downloaded) scene never replaces an installed one. G_ERR_IO naming the directories searched when no
 * file is found; otherwise as gplugin_load. */
GENERIC_API GENERIC_NODISCARD int gplugin_load_from(const char *name, const char *dir, GError *err);
/** Finds a module by the rule above without loading it: *path receives a gmem_alloc copy of the file to load
 * (free with gmem_free; NULL on failure). G_ERR_IO naming the directories searched when no file is found. */
GENERIC_API GENERIC_NODISCARD int gplugin_find(const char *name, const char *dir, char **path, GError *err);
/** Loads the module of every `--plugin FILE` (or `--plugin=FILE`) in argv[1..*argc-1], searched as
 * gplugin_load_from with the current directory, and removes those arguments from argv (keeping the order of the
 * others; argv[*argc] becomes NULL). Tools call it first, so that every later use of the registry sees the
 * modules. G_ERR_INVALID for a --plugin without a value, a module's load error otherwise (argv then unchanged
 * beyond the arguments consumed so far). */
GENERIC_API GENERIC_NODISCARD int gplugin_load_args(int *argc, char **argv, GError *err);
/** Name of the environment variable with the module search directories. */
#define GPLUGIN_PATH_ENV "GENERIC_PLUGIN_PATH"
/** Name of the environment variable that allows `plugin` statements in files when it is "1" (reader.h). */
#define GPLUGIN_ALLOW_ENV "GENERIC_ALLOW_PLUGINS"
/** Number of modules loaded so far. */
GENERIC_API GENERIC_NODISCARD int gplugin_count(void);

#ifdef __cplusplus
}
#endif
#endif
