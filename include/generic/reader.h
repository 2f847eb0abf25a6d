/* reader.h - the text format: loading files into a GLibrary, and the API parse routines read with.
 *
 * A file is a sequence of statements (docs/reference/format.md has the full grammar):
 *
 *     colormodel spectrum { step 5 }          # optional, before the first colour
 *     include "common.mat"                    # relative to this file; read once; cycles are refused
 *     plugin "oren_nayar.so"                  # loads a module (plugin.h), relative to this file
 *     color warm blackbody 3200               # KIND [NAME] TYPE parameters
 *     material wall lambert { reflectance rgb 0.5 0.5 0.5 }
 *     material floor phong { diffuse warm specular rgb 0.2 0.2 0.2 exponent 40 }
 *     define shine 60                         # a named number: usable wherever a number is read
 *     material floor2 like floor { exponent shine }   # floor's other parameters, re-read from its text
 *
 * Every entry is KIND [NAME] VALUE, where KIND is a kind keyword (gkind_name()), NAME an optional identifier
 * that is not a type keyword of that kind, and VALUE either `TYPE parameters` (the registered parse routine
 * of that type reads the parameters) or the name of an earlier entry of that kind. Wherever a parameter
 * expects an object, the same VALUE syntax nests an anonymous entry or refers to a named one (texture trees
 * are nested entries). Materials and texture nodes share one namespace: a node can stand wherever a
 * material is expected and the other way round.
 *
 * Parse routines (GParseFn in registry.h) are called right after their type keyword. They read parameters
 * with the functions below and store the new object in *object. The usual shape, for a type with named
 * parameters in an optional `{ ... }` block (any order, each at most once):
 *
 *     GColor refl = {0};          (a cleared handle)
 *     double sigma = 0.0;
 *     const char *key;
 *     int rc;
 *     while ((rc = greader_param(r, &key, err)) > 0) {
 *         if (strcmp(key, "reflectance") == 0)
 *             rc = greader_color(r, GCOLOR_REFLECTANCE, &refl, err);
 *         else if (strcmp(key, "sigma") == 0)
 *             rc = greader_number_in(r, 0.0, 90.0, &sigma, err);
 *         else
 *             rc = greader_unknown_param(r, "reflectance, sigma", err);
 *         if (rc < 0)
 *             break;
 *     }
 *     if (rc == 0) rc = create the object from the values (reporting bad combinations with greader_error);
 *     gcolor_free(&refl);
 *     return rc;
 *
 * The names greader_unknown_param lists are the named rows of the type's parameter table (GTypeInfo.params).
 *
 * Ownership. Every object a parse routine returns goes to the GLibrary being loaded, which releases it with
 * its type's GTypeInfo.destroy (or the kind's default, see GTypeInfo) when the library is destroyed, in
 * reverse order of creation. Objects handed to a parse routine by greader_object() and friends are borrowed
 * from the library: a routine that keeps one inside its own object takes its own reference where the kind
 * has references (materials and nodes: gmaterial_ref, released in its destroy). A parse routine that fails
 * frees whatever it created itself and leaves *object NULL; the reader never leaks on an error path.
 *
 * Errors. Every function returning int gives 0 (or a count where stated) on success and a negative status
 * on failure, with err filled as "file:line:col: message" at the offending token. Once a function has failed,
 * the routine returns that status at once (the reader stops at the first error).
 *
 * Thread safety: a GReader is used by one thread; several files may be loaded on different threads at once.
 * A loaded GLibrary is read-only and may then be shared between threads. */
#ifndef GENERIC_READER_H
#define GENERIC_READER_H

#include "export.h"
#include <stddef.h>
#include "color.h"
#include "colorspec.h"
#include "error.h"
#include "material.h"
#include "registry.h"
#include "vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Default limit on nesting (blocks, nested entries and includes together). */
#define GREADER_DEFAULT_MAX_DEPTH 64

/* ======================================================================================================
 * Loading files
 * ====================================================================================================== */

/** The objects a file defines, owned together: named and anonymous entries of every kind, the colour
 * model (unless the caller provided it). Destroyed at once with glibrary_destroy. Modules loaded by `plugin`
 * statements stay loaded for the life of the process (plugin.h). */
typedef struct GLibrary GLibrary;

/** Options for loading; a zeroed struct (or NULL) takes every default. */
typedef struct GReaderOptions {
    /** Use this model for every colour and ignore the file's `colormodel` entry (not owned; it must outlive
     * the library). NULL: see colormodel. */
    const GColorModel *model;
    /** Create this registered model instead of the file's (with colormodel_options, NULL = defaults).
     * NULL: the file's `colormodel` entry, else "rgb". Ignored when model is set. The model is created when
     * the first entry is read (or at the end of a file without entries), so it may be one that a `plugin`
     * statement before that entry registers; an unknown name fails the load. */
    const char *colormodel;
    const GColorModelOptions *colormodel_options;
    /** Nesting limit; 0 = GREADER_DEFAULT_MAX_DEPTH. */
    int max_depth;
    /** Per-file size limit in bytes; 0: none of its own. Every file's text is reserved against the memory budget
     * (memory.h, gmem_budget_reserve) before it is read, so the budget limits the files of a load together. */
    size_t max_file_size;
    /** Non-zero refuses `plugin` statements (for files from untrusted sources), whatever allow_plugins says. */
    int no_plugins;
    /** Non-zero allows `plugin` statements: a module runs native code, so a file may load one only with the
     * caller's consent - this field, or GENERIC_ALLOW_PLUGINS=1 in the environment (plugin.h). Without either, a
     * `plugin` statement fails naming these options. */
    int allow_plugins;
    /** When set, every file the load reads - the file itself, includes, plug-ins and every path read with
     * greader_path (BFC files, images, meshes, probes) - must lie under this directory once symbolic links are
     * resolved; others fail with G_ERR_INVALID at their name. NULL: no confinement. Not owned. */
    const char *confine_dir;
    /** Entry kinds to read past without interpreting them: bit (1u << kind) set skips every `KIND ... { ... }`
     * entry of that kind (its braces must balance), so that a program without those types (gmat reading a gtrace
     * scene registers gtrace's kinds object, light and camera, without types, and skips them) can read the rest of
     * the file. 0: skip nothing. */
    unsigned skip_kinds;
} GReaderOptions;

/** Takes the reader options of a tool's command line out of argv[1..*argc-1] into opt (the other fields are
 * left as they are): `--allow-plugins` sets opt->allow_plugins, `--confine DIR` (or `--confine=DIR`) sets
 * opt->confine_dir to that argument (borrowed from argv). The remaining arguments keep their order; argv[*argc]
 * becomes NULL. G_ERR_INVALID for a --confine without a value or whose DIR is not a directory. */
GENERIC_API GENERIC_NODISCARD int greader_options_args(int *argc, char **argv, GReaderOptions *opt, GError *err);

/** Reads a file into a new library. On failure *out is NULL, nothing is leaked and err holds
 * "file:line:col: message". */
GENERIC_API GENERIC_NODISCARD int greader_load_file(const char *path, const GReaderOptions *opt, GLibrary **out,
                                                    GError *err);
/** Reads text held in memory; `name` is used in messages, and relative paths (include, plugin, data files)
 * are resolved against the current directory. */
GENERIC_API GENERIC_NODISCARD int greader_load_string(const char *text, const char *name, const GReaderOptions *opt,
                                                      GLibrary **out, GError *err);

/** Creates an empty library using `model` (not owned; NULL: "rgb", created and owned by the library). */
GENERIC_API GENERIC_NODISCARD int glibrary_create(const GColorModel *model, GLibrary **out, GError *err);
/** Reads a file into an existing library (e.g. a scene after a material file). opt->model and
 * opt->colormodel are ignored: the library's model is used. On failure the entries read before the error stay
 * in the library (they are owned by it and freed with it). */
GENERIC_API GENERIC_NODISCARD int glibrary_load_file(GLibrary *lib, const char *path, const GReaderOptions *opt,
                                                     GError *err);
/** Releases every object of the library (reverse order of creation) and its model if it owns it; NULL is a
 * no-op. Materials still referenced elsewhere (gmaterial_ref) live on, but can only be used while their colour
 * model exists: to keep materials beyond their library, load with your own model (GReaderOptions.model). */
GENERIC_API void glibrary_destroy(GLibrary *lib);
/** The model every colour of the library is in. */
GENERIC_API const GColorModel *glibrary_colormodel(const GLibrary *lib);
/** The object defined under name with the given kind (materials and nodes share one namespace); borrowed,
 * valid for the life of the library. NULL when not defined. */
GENERIC_API void *glibrary_find(const GLibrary *lib, GKind kind, const char *name);
/** The material (or texture node) defined under name, borrowed; NULL when not defined. */
GENERIC_API GMaterial *glibrary_material(const GLibrary *lib, const char *name);
/** Converts the colour defined under name into `out` (storage of the library's model provided by the
 * caller, see gcolor_wrap/gcolor_alloc), read in the given role. G_ERR_NOTFOUND when not defined. */
GENERIC_API GENERIC_NODISCARD int glibrary_color(const GLibrary *lib, const char *name, GColorRole role, GColor *out,
                                                 GError *err);
/** Number of top-level entries of a kind (named and anonymous, in file order; nested anonymous entries are
 * owned but not listed). Materials and nodes are listed under their own kind. Constant time. */
GENERIC_API GENERIC_NODISCARD int glibrary_count(const GLibrary *lib, GKind kind);
/** The i-th top-level entry of a kind (0 <= i < glibrary_count): its object, and its name (NULL when
 * anonymous) and type through the optional pointers. NULL when i is out of range. Constant time. */
GENERIC_API void *glibrary_entry(const GLibrary *lib, GKind kind, int i, const char **name, const GTypeInfo **type);
/** The name of the entry the i-th top-level entry of a kind was derived from with `like` (`material tile2 like
 * tile1 { ... }` gives "tile1"), borrowed; NULL when it was not derived or i is out of range. */
GENERIC_API const char *glibrary_entry_base(const GLibrary *lib, GKind kind, int i);
/** Adds an object made by code under name (NULL = anonymous); the library takes ownership and releases it
 * with type->destroy (or the kind's default). G_ERR_EXISTS when the name is taken in that kind, and then the
 * object is released at once (the caller never keeps a half-owned object). */
GENERIC_API GENERIC_NODISCARD int glibrary_add(GLibrary *lib, const GTypeInfo *type, const char *name, void *object,
                                               GError *err);

/* ======================================================================================================
 * The API of parse routines
 * ====================================================================================================== */

/** Token types. */
typedef enum GTokenType {
    GTOK_EOF = 0,
    GTOK_IDENT,  /**< keyword or name: [A-Za-z_][A-Za-z0-9_.-]* */
    GTOK_NUMBER, /**< a finite decimal number (NaN and infinity are refused) */
    GTOK_STRING, /**< "text" with \" \\ \n \t escapes, on one line; text is the decoded value */
    GTOK_LBRACE, /**< { */
    GTOK_RBRACE, /**< } */
    GTOK_LANGLE, /**< < */
    GTOK_RANGLE, /**< > */
    GTOK_COMMA   /**< , */
} GTokenType;

/** A token; text is NUL-terminated and valid until the reader moves past the next token. */
typedef struct GToken {
    int type;         /**< a GTokenType */
    const char *text; /**< its characters (decoded for strings; "end of file" for GTOK_EOF) */
    double number;    /**< the value of a GTOK_NUMBER */
    int line, col;    /**< 1-based position of its first character */
} GToken;

/* ---- tokens ---- */

/** Looks at the next token without consuming it. */
GENERIC_API GENERIC_NODISCARD int greader_peek(GReader *r, GToken *tok, GError *err);
/** Consumes and returns the next token. */
GENERIC_API GENERIC_NODISCARD int greader_next(GReader *r, GToken *tok, GError *err);
/** Consumes the next token when it has the given type: 1 when consumed, 0 when not (nothing consumed). */
GENERIC_API GENERIC_NODISCARD int greader_accept(GReader *r, int type, GError *err);
/** Consumes a token of the given type or fails with "expected WHAT, found ..."; what may be NULL. */
GENERIC_API GENERIC_NODISCARD int greader_expect(GReader *r, int type, const char *what, GError *err);
/** 1 when the next token is a number (so optional trailing numbers can be read), 0 when not. */
GENERIC_API GENERIC_NODISCARD int greader_at_number(GReader *r, GError *err);

/* ---- values ---- */

/** Reads a number. */
GENERIC_API GENERIC_NODISCARD int greader_number(GReader *r, double *out, GError *err);
/** Reads a number and checks lo <= value <= hi ("value X out of range [lo, hi]" at the number). */
GENERIC_API GENERIC_NODISCARD int greader_number_in(GReader *r, double lo, double hi, double *out, GError *err);
/** Reads a whole number within [lo, hi]. */
GENERIC_API GENERIC_NODISCARD int greader_int(GReader *r, long lo, long hi, long *out, GError *err);
/** Reads a vector, written `<x, y, z>` or `x y z`. */
GENERIC_API GENERIC_NODISCARD int greader_vec3(GReader *r, GVec3 *out, GError *err);
/** Reads a boolean: true/false, yes/no, on/off, 1/0. */
GENERIC_API GENERIC_NODISCARD int greader_bool(GReader *r, int *out, GError *err);
/** Reads a quoted string; *out is a copy made with gmem_alloc (free it with gmem_free). */
GENERIC_API GENERIC_NODISCARD int greader_string(GReader *r, char **out, GError *err);
/** Reads an identifier into buf (an error when it does not fit). */
GENERIC_API GENERIC_NODISCARD int greader_ident(GReader *r, char *buf, size_t size, GError *err);
/** Reads an identifier that must be one of the NULL-terminated choices; *index gets its position. */
GENERIC_API GENERIC_NODISCARD int greader_choice(GReader *r, const char *const *choices, int *index, GError *err);
/** Reads a quoted file name and resolves it against the directory of the file being read; *out is a
 * gmem_alloc copy of the resulting path. When the load is confined (GReaderOptions.confine_dir) a path outside
 * the directory is an error at the name, and *out is the path with its symbolic links resolved. */
GENERIC_API GENERIC_NODISCARD int greader_path(GReader *r, char **out, GError *err);
/** G_OK when the load may read path: always without confinement, else when path lies under
 * GReaderOptions.confine_dir (see there); for parse routines that find files other than with greader_path. */
GENERIC_API GENERIC_NODISCARD int greader_path_allowed(GReader *r, const char *path, GError *err);

/* ---- parameter blocks ---- */

/** Iterates the named parameters of an optional `{ name value ... }` block: returns 1 with *key set to the
 * next parameter name (valid until the next read) for the routine to read its value; 0 when the block is
 * closed or when the entry has no block at all (a type keyword followed by anything but `{` keeps all its
 * defaults); negative on error. A name given twice and a missing `}` are reported by the reader. */
GENERIC_API GENERIC_NODISCARD int greader_param(GReader *r, const char **key, GError *err);
/** Reports the parameter just returned by greader_param as unknown, listing the expected names. */
GENERIC_API GENERIC_NODISCARD int greader_unknown_param(GReader *r, const char *expected, GError *err);
/** Reads a `{ ... }` block of positional values: consumes `{` and returns 0 (then read the values until
 * greader_block_end returns 1). */
GENERIC_API GENERIC_NODISCARD int greader_block_begin(GReader *r, GError *err);
/** 1 (and consumes `}`) when the block opened by greader_block_begin ends here, 0 when more follows;
 * a missing `}` at the end of the file is an error naming where the block opened. */
GENERIC_API GENERIC_NODISCARD int greader_block_end(GReader *r, GError *err);

/* ---- objects, colours, names ---- */

/** Reads a VALUE of a kind: a nested anonymous entry `TYPE parameters` (calling its parse routine) or the
 * name of an entry defined before. *object is borrowed from the library (see Ownership above); *type, when
 * type is not NULL, receives the type the object was made by. */
GENERIC_API GENERIC_NODISCARD int greader_object(GReader *r, GKind kind, void **object, const GTypeInfo **type,
                                                 GError *err);
/** greader_object for a material or texture node; borrowed (gmaterial_ref to keep it). */
GENERIC_API GENERIC_NODISCARD int greader_material(GReader *r, GMaterial **out, GError *err);
/** A new anonymous material with one parameter given, its value read at the reader's position: `base` is a
 * material type keyword (the material `TYPE { PARAM VALUE }`) or a material or node defined before (the
 * material `like BASE { PARAM VALUE }`: its other parameters inherited). E.g. the spline's `colors` ramp makes
 * each key's child with greader_material_with(r, "lambert", "reflectance", ...). *out is borrowed from the
 * library. */
GENERIC_API GENERIC_NODISCARD int greader_material_with(GReader *r, const char *base, const char *param,
                                                        GMaterial **out, GError *err);
/** Reads a colour literal (rgb, spectrum, blackbody, illuminant, line, bfc, scale, or a registered colour
 * type) or a colour name, and converts it in the given role into the reader's colour model. `out` must be a
 * cleared handle ({0}); it receives heap storage (free with gcolor_free), also when it is left black by a
 * failure, so gcolor_free is always right. */
GENERIC_API GENERIC_NODISCARD int greader_color(GReader *r, GColorRole role, GColor *out, GError *err);
/** The colour model of the file (fixed from here on: a `colormodel` entry after this is an error). */
GENERIC_API const GColorModel *greader_colormodel(GReader *r);
/** The library being loaded. */
GENERIC_API GLibrary *greader_library(GReader *r);
/** The object defined under name of a kind (materials and nodes share a namespace), borrowed; NULL when
 * not defined. */
GENERIC_API void *greader_lookup(GReader *r, GKind kind, const char *name);
/** Defines an object under a name (NULL = anonymous) in the library being loaded, which takes ownership
 * (see glibrary_add; errors are reported at the last token read). */
GENERIC_API GENERIC_NODISCARD int greader_define(GReader *r, const GTypeInfo *type, const char *name, void *object,
                                                 GError *err);
/** Directory of the file being read ("." for text in memory), for resolving relative paths. */
GENERIC_API const char *greader_dir(GReader *r);
/** Name of the file being read, as given to the loader or the include statement. */
GENERIC_API const char *greader_file(GReader *r);
/** Position of the last token read (line and col may be NULL). */
GENERIC_API void greader_position(GReader *r, int *line, int *col);

/* ---- errors ---- */

/** Fails with G_ERR_PARSE and "file:line:col: message" at the last token read (err->line, err->col hold the
 * position); returns G_ERR_PARSE. */
GENERIC_API GENERIC_NODISCARD int greader_error(GReader *r, GError *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/** The same at an explicit position (e.g. a token kept from earlier), with a status code. */
GENERIC_API GENERIC_NODISCARD int greader_error_at(GReader *r, GError *err, int code, int line, int col,
                                                   const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;
/** Places a message already in err (e.g. from a constructor) in the file, keeping its code: at the parameter
 * err->param of the entry being read when the constructor named one it was given (gerror_set_param), else at
 * the last token read; the message gets the "file:line:col: " prefix and err->line, err->col the position. A
 * message that already has a position is left as it is. A parse routine that returns a constructor's failure
 * need not call this: the reader places every failure of a parse routine so. Returns err->code. */
GENERIC_API GENERIC_NODISCARD int greader_locate(GReader *r, GError *err);

/* ======================================================================================================
 * Colour literals: GColorSpec (colorspec.h)
 * ====================================================================================================== */

/** Reads a colour literal or name at the reader's position into a new spec (what greader_color parses). */
GENERIC_API GENERIC_NODISCARD int greader_color_spec(GReader *r, GColorSpec **out, GError *err);

#ifdef __cplusplus
}
#endif
#endif
