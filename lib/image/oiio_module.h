/* oiio_module.h - the interface between libgeneric and its OpenImageIO module, libgeneric_oiio.so (lib/image/image.cpp
 * and lib/image/texture_oiio.cpp). OpenImageIO pulls in some 260 shared libraries and 120k allocations, so the library
 * loads it only on the first call that needs it (lib/image/oiio_loader.c): a program that reads and writes no image
 * other than PNG output never maps it. The module is linked with OpenImageIO, never with libgeneric: the few
 * library functions it uses come in the host table, so it works the same beside libgeneric.so, a static
 * libgeneric.a with or without -rdynamic, and under a program that dlopened libgeneric.so with RTLD_LOCAL. */
#ifndef GENERIC_OIIO_MODULE_H
#define GENERIC_OIIO_MODULE_H

#include "generic/error.h"
#include "generic/services/file.h"
#include "generic/services/image.h"
#include "generic/services/texsys.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Raised whenever either table changes; a module of another version is refused. */
#define GOIIO_MODULE_ABI 7
/** The module's file name and the one symbol it exports (a GOiioEntry). */
#define GOIIO_MODULE_FILE "libgeneric_oiio.so"
#define GOIIO_MODULE_ENTRY "generic_oiio_module"

/** What the library gives the module. */
typedef struct GOiioHost {
    int (*error_set)(GError *err, int code, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
    void *(*mem_alloc)(size_t size);
    void *(*mem_calloc)(size_t n, size_t size);
    void (*mem_free)(void *ptr);
    int (*file_open_input)(const char *path, GError *err);
    int (*file_check_output)(const char *path, GError *err);
    int (*file_output_begin)(GFileOutput *o, const char *path, GError *err);
    int (*file_output_commit)(GFileOutput *o, long long expected_size, const char *path, GError *err);
    void (*file_output_abort)(GFileOutput *o);
    size_t (*image_memory_budget)(void);
    double (*srgb_encode)(double linear);
    double (*srgb_decode)(double encoded);
    int (*budget_reserve)(size_t bytes, const char *what, GError *err);
    void (*budget_release)(size_t bytes);
} GOiioHost;

/** What the module gives back: the OpenImageIO implementations of the public functions of the same names
 * (image.h, texsys.h). */
typedef struct GOiioOps {
    int (*image_read)(const char *path, unsigned flags, GImage *img, GError *err);
    int (*image_info)(const char *path, int *width, int *height, int *channels, GError *err);
    int (*image_write)(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err);
    int (*image_check_output)(const char *path, GError *err);
    int (*texsys_create)(GTextureSystem **out, GError *err);
    GTextureSystem *(*texsys_ref)(GTextureSystem *ts);
    void (*texsys_unref)(GTextureSystem *ts);
    GTextureSystem *(*texsys_default)(GError *err);
    int (*texsys_open)(GTextureSystem *ts, const char *path, GTexColorSpace space, GTexFile **file, int *channels,
                       int *srgb, GError *err);
    int (*texsys_lookup)(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap, double s, double t,
                         const double deriv[4], double blur, float rgb[3]);
    /** OpenColorIO (lib/image/ocio_display.cpp): applies the view of a display of the config file (NULL or "": the
     * config's defaults) to width x height pixels of 3 or 4 floats in place, from the config's scene_linear;
     * pixels NULL only checks that the config reads and has the display and view. The files the config names must
     * be regular files, and lie under confine_dir when it is not NULL (GImageDisplay.confine_dir), as its search
     * paths must: G_ERR_IO naming the file otherwise. G_ERR_PARSE for a config that does not read, G_ERR_NOTFOUND
     * for an unknown display or view (the message lists the config's names). */
    int (*display_transform)(const char *config, const char *confine_dir, const char *display, const char *view,
                             float *pixels, int width, int height, int channels, GError *err);
    int (*image_window)(const char *path, GImageWindow *win, GError *err);
    int (*image_read_spectra)(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err);
} GOiioOps;

/** The module's entry: checks abi, keeps host (it outlives the module), fills ops. 0, or -1 for another ABI. */
typedef int (*GOiioEntry)(unsigned abi, const GOiioHost *host, GOiioOps *ops);

/** The loaded module's operations (loading it on the first call, once, thread-safe), or NULL with the reason in
 * err (G_ERR_IO: the module or OpenImageIO is missing or refused). */
const GOiioOps *goiio_ops(GError *err);

#ifdef __cplusplus
}
#endif

/* Inside the module (image.cpp, texture_oiio.cpp): the library's functions through the host table. */
#ifdef GOIIO_MODULE_SOURCE
extern const GOiioHost *goiio_host;
#define gerror_set(...) (goiio_host->error_set(__VA_ARGS__))
#define gmem_alloc(n) (goiio_host->mem_alloc(n))
#define gmem_calloc(n, s) (goiio_host->mem_calloc((n), (s)))
#define gmem_free(p) (goiio_host->mem_free(p))
#define gfile_open_input(p, e) (goiio_host->file_open_input((p), (e)))
#define gfile_check_output(p, e) (goiio_host->file_check_output((p), (e)))
#define gfile_output_begin(o, p, e) (goiio_host->file_output_begin((o), (p), (e)))
#define gfile_output_commit(o, n, p, e) (goiio_host->file_output_commit((o), (n), (p), (e)))
#define gfile_output_abort(o) (goiio_host->file_output_abort(o))
#define gimage_memory_budget() (goiio_host->image_memory_budget())
#define gimage_srgb_encode(v) (goiio_host->srgb_encode(v))
#define gimage_srgb_decode(v) (goiio_host->srgb_decode(v))
#define gmem_budget_reserve(n, w, e) (goiio_host->budget_reserve((n), (w), (e)))
#define gmem_budget_release(n) (goiio_host->budget_release(n))
/* texture_oiio.cpp's and ocio_display.cpp's parts of the table, and image.cpp's header check which the first uses */
void goiio_texsys_ops(GOiioOps *ops);
void goiio_display_ops(GOiioOps *ops);
int goiio_image_info(const char *path, int *width, int *height, int *channels, GError *err);
struct GImageFormat;
/* The format of a file's content (image_format.h): G_OK when the library reads it, else G_ERR_IO naming it. */
int goiio_image_format(const char *path, struct GImageFormat *format, GError *err);
#endif

#endif
