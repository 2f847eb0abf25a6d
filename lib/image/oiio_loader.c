/* oiio_loader.c - loads the OpenImageIO module (oiio_module.h) on first use, and the public image and texture
 * functions that go through it. PNG output goes through libpng (image_png.h) and OpenEXR output without spectra
 * through OpenEXRCore (image_exr.h): neither needs the module.
 *
 * Where the module is looked for, in order: $GENERIC_OIIO_MODULE (a path; then nowhere else); beside the object
 * that holds this code (libgeneric.so, or the program it is linked into): DIR/generic/ and DIR/../lib/generic/;
 * the same beside the executable; the installed GENERIC_LIBDIR/generic/; and the dynamic loader's own search
 * (LD_LIBRARY_PATH, ld.so.cache). */
#include "oiio_module.h"

#include "image_exr.h"
#include "image_png.h"
#include "image_path.h"
#include "decode_isolated.h"
#include "generic/services/spawn.h"

#include "generic/memory.h"

#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__) && !defined(GENERIC_OIIO_STATIC)
#include "core/leak_check.h"
#define GENERIC_LEAK_CHECK_BEFORE_MODULE_EXIT 1
#endif

#ifndef GENERIC_LIBDIR
#define GENERIC_LIBDIR "/usr/local/lib"
#endif

static const GOiioHost host = {
    gerror_set, gmem_alloc, gmem_calloc, gmem_free, gfile_open_input, gfile_check_output, gfile_output_begin,
    gfile_output_commit, gfile_output_abort, gimage_memory_budget, gimage_srgb_encode, gimage_srgb_decode,
    gmem_budget_reserve, gmem_budget_release,
};

static pthread_once_t once = PTHREAD_ONCE_INIT;
static GOiioOps ops;
static int loaded;
static char failure[400]; /* why not, when not loaded */

#ifdef GENERIC_OIIO_STATIC
/* A build that links the module's objects into the library itself (the fuzzing build). */
int generic_oiio_module(unsigned abi, const GOiioHost *host, GOiioOps *ops);
#endif

/* Appends "; " and text to failure, cut to fit. */
static void note(const char *text)
{
    size_t len = strlen(failure);
    if (len && len + 2 < sizeof failure) {
        memcpy(failure + len, "; ", 2);
        len += 2;
    }
    size_t n = strlen(text), room = sizeof failure - 1 - len;
    n = n < room ? n : room;
    memcpy(failure + len, text, n);
    failure[len + n] = 0;
}

#ifndef GENERIC_OIIO_STATIC
/* Opens one candidate; 1 when the module is loaded and accepted. A missing file is noted only when named. */
static int try_module(const char *path, int named)
{
    if (!named && strchr(path, '/') && access(path, F_OK) != 0)
        return 0;
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *why = dlerror();
        if (named || strchr(path, '/'))
            note(why ? why : path);
        return 0;
    }
    GOiioEntry entry = (GOiioEntry)dlsym(h, GOIIO_MODULE_ENTRY);
    if (!entry) {
        char msg[PATH_MAX + 64];
        snprintf(msg, sizeof msg, "%s: no entry %s", path, GOIIO_MODULE_ENTRY);
        note(msg);
        dlclose(h);
        return 0;
    }
    if (entry(GOIIO_MODULE_ABI, &host, &ops) != 0) {
        char msg[PATH_MAX + 64];
        snprintf(msg, sizeof msg, "%s: built for another interface version (this library has %d)", path,
                 GOIIO_MODULE_ABI);
        note(msg);
        dlclose(h);
        return 0;
    }
    return 1;
}

/* Tries DIR/generic/FILE and DIR/../lib/generic/FILE for the directory of the file path. */
static int try_beside(const char *file)
{
    char real[PATH_MAX], cand[PATH_MAX + 64];
    if (!file || !realpath(file, real))
        return 0;
    char *slash = strrchr(real, '/');
    if (!slash)
        return 0;
    *slash = 0;
    snprintf(cand, sizeof cand, "%s/generic/%s", real, GOIIO_MODULE_FILE);
    if (try_module(cand, 0))
        return 1;
    snprintf(cand, sizeof cand, "%s/../lib/generic/%s", real, GOIIO_MODULE_FILE);
    return try_module(cand, 0);
}

#endif

#ifdef GENERIC_LEAK_CHECK_BEFORE_MODULE_EXIT
/* The module's libraries stop their own threads in their destructors at exit (OpenImageIO's thread pool, the
 * threads log4cplus starts when OpenColorIO loads). LeakSanitizer's check at exit would run while those threads are
 * exiting, and its thread tracer can crash on a thread that disappears under it (seldom, under load). A handler
 * registered after the module loaded runs before those destructors, while their threads are idle: the check runs
 * there, once (when no thread is exiting: leak_check.h), and the one at exit is skipped. Sanitizer builds only. */
static void check_leaks_before_module_exit(void) { gleak_check_when_threads_settle(); }
#endif

static void load_module(void)
{
#ifdef GENERIC_OIIO_STATIC
    loaded = generic_oiio_module(GOIIO_MODULE_ABI, &host, &ops) == 0;
    if (!loaded)
        note("the linked-in OpenImageIO shim refused the interface version");
    return;
#else
    const char *named = secure_getenv("GENERIC_OIIO_MODULE");
    if (named && *named) {
        loaded = try_module(named, 1);
        return;
    }
    Dl_info self;
    if (dladdr((void *)&host, &self) && self.dli_fname && strchr(self.dli_fname, '/') && try_beside(self.dli_fname)) {
        loaded = 1;
        return;
    }
    if (try_beside("/proc/self/exe")) {
        loaded = 1;
        return;
    }
    loaded = try_module(GENERIC_LIBDIR "/generic/" GOIIO_MODULE_FILE, 0) || try_module(GOIIO_MODULE_FILE, 0);
#endif
}

static void load(void)
{
    load_module();
#ifdef GENERIC_LEAK_CHECK_BEFORE_MODULE_EXIT
    if (loaded)
        atexit(check_leaks_before_module_exit);
#endif
}

const GOiioOps *goiio_ops(GError *err)
{
    pthread_once(&once, load);
    if (loaded)
        return &ops;
    gerror_set(err, G_ERR_IO, "image input and output need the OpenImageIO module %s, which cannot be loaded: %s",
               GOIIO_MODULE_FILE, failure[0] ? failure :
               "not found (looked in generic/ and ../lib/generic/ beside the library and the program, in "
               GENERIC_LIBDIR "/generic/ and on the dynamic loader's path; GENERIC_OIIO_MODULE may name it)");
    return NULL;
}

/* ---- the public functions that need the module ---- */

int gimage_read(const char *path, unsigned flags, GImage *img, GError *err)
{
    if (!img)
        return gerror_set(err, G_ERR_INVALID, "no image given");
    img->width = img->height = img->channels = 0;
    img->pixels = NULL;
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if ((flags & GIMAGE_READ_RGB) && (flags & GIMAGE_READ_RGBA))
        return gerror_set(err, G_ERR_INVALID, "%s: GIMAGE_READ_RGB and GIMAGE_READ_RGBA exclude each other", path);
    int isolated = gspawn_isolated(err);
    if (isolated < 0)
        return isolated;
    if (isolated)
        return gdecode_run(path, GDECODE_READ, flags, img, NULL, NULL, NULL, err);
    /* in this process: the header, the decode charged to the budget, the decode */
    const GOiioOps *o = goiio_ops(err);
    if (!o)
        return G_ERR_IO;
    int w, h, ch;
    int rc = o->image_info(path, &w, &h, &ch, err);
    if (rc != G_OK)
        return rc;
    const double charge = gdecode_charge(w, h, ch);
    char what[PATH_MAX + 96];
    snprintf(what, sizeof what, "%s: decoding a %dx%d image with %d channels", path, w, h, ch);
    if ((rc = gmem_budget_reserve((size_t)charge, what, err)) != G_OK)
        return rc;
    rc = o->image_read(path, flags, img, err);
    gmem_budget_release((size_t)charge);
    return rc;
}

int gimage_info(const char *path, int *width, int *height, int *channels, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    int isolated = gspawn_isolated(err);
    if (isolated < 0)
        return isolated;
    if (isolated)
        return gdecode_run(path, GDECODE_INFO, 0, NULL, width, height, channels, err);
    const GOiioOps *o = goiio_ops(err);
    return o ? o->image_info(path, width, height, channels, err) : G_ERR_IO;
}

/* 1 when the extension ext (with its dot) is one of gimage_write_extensions(), ignoring case. */
static int listed_extension(const char *ext)
{
    size_t n = strlen(ext);
    for (const char *p = gimage_write_extensions(); *p;) {
        size_t len = strcspn(p, " ");
        if (len == n && strncasecmp(p, ext, n) == 0)
            return 1;
        p += len;
        p += *p == ' ';
    }
    return 0;
}

int gimage_window(const char *path, GImageWindow *win, GError *err)
{
    if (!win)
        return gerror_set(err, G_ERR_INVALID, "no window given");
    *win = (GImageWindow){0};
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    const GOiioOps *o = goiio_ops(err);
    return o ? o->image_window(path, win, err) : G_ERR_IO;
}

int gimage_read_spectra(const char *path, GImageSpectraBuf *out, GError *err)
{
    return gimage_read_spectra_layer(path, GIMAGE_SPECTRA_EMISSIVE, out, err);
}

int gimage_read_spectra_layer(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "no spectra given");
    *out = (GImageSpectraBuf){0};
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    const GOiioOps *o = goiio_ops(err);
    if (layer != GIMAGE_SPECTRA_EMISSIVE && layer != GIMAGE_SPECTRA_REFLECTIVE)
        return gerror_set(err, G_ERR_INVALID, "%s: unknown spectral layer %d", path, (int)layer);
    int rc = gdecode_check_whole(path, err);
    if (rc != G_OK)
        return rc;
    return o ? o->image_read_spectra(path, layer, out, err) : G_ERR_IO;
}

int gdecode_check_whole(const char *path, GError *err)
{
    int isolated = gspawn_isolated(err);
    if (isolated < 0)
        return isolated;
    return isolated ? gdecode_run(path, GDECODE_CHECK, 0, NULL, NULL, NULL, NULL, err) : G_OK;
}

int gdecode_read_spectra_checked(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err)
{
    *out = (GImageSpectraBuf){0};
    if (layer != GIMAGE_SPECTRA_EMISSIVE && layer != GIMAGE_SPECTRA_REFLECTIVE)
        return gerror_set(err, G_ERR_INVALID, "%s: unknown spectral layer %d", path, (int)layer);
    const GOiioOps *o = goiio_ops(err);
    return o ? o->image_read_spectra(path, layer, out, err) : G_ERR_IO;
}

int gimage_check_output(const char *path, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    int rc = gfile_check_output(path, err);
    if (rc != G_OK || gimage_path_has_extension(path, ".png") || gimage_path_has_extension(path, ".exr"))
        return rc;
    const char *dot = gimage_path_extension(path);
    if (!dot)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: no extension to choose the format by", path);
    if (!listed_extension(dot))
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: this OpenImageIO has no writer for '%s' files (it "
                          "writes %s)", path, dot, gimage_write_extensions());
    return G_OK;
}

/* Whether path's extension is one of the linear float formats (.exr, .hdr, .pfm: image.h). */
static int gimage_float_path(const char *path)
{
    return gimage_path_has_extension(path, ".exr") || gimage_path_has_extension(path, ".hdr") ||
           gimage_path_has_extension(path, ".pfm");
}

/* The spectra to write beside img: G_OK, or G_ERR_INVALID naming what is wrong. */
static int check_spectra(const char *path, const GImageSpectra *sp, GError *err)
{
    if (sp->count < 1 || sp->count > GIMAGE_MAX_WAVELENGTHS || !sp->wavelengths || !sp->values)
        return gerror_set(err, G_ERR_INVALID, "%s: spectra need 1..%d wavelengths and their values (got %d)", path,
                          GIMAGE_MAX_WAVELENGTHS, sp->count);
    for (int k = 0; k < sp->count; k++)
        if (!isfinite(sp->wavelengths[k]) || !(sp->wavelengths[k] > 0.0) ||
            (k > 0 && !(sp->wavelengths[k] > sp->wavelengths[k - 1])))
            return gerror_set(err, G_ERR_INVALID, "%s: the spectra's wavelengths must be positive and increasing",
                              path);
    return G_OK;
}

int gimage_write(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if (!img || !img->pixels || img->width <= 0 || img->height <= 0 || img->channels < 1 || img->channels > 4)
        return gerror_set(err, G_ERR_INVALID, "%s: invalid image to write", path);
    if (opt && opt->full_width > 0 &&
        (opt->x < 0 || opt->y < 0 || opt->full_height <= 0 || (long long)opt->x + img->width > opt->full_width ||
         (long long)opt->y + img->height > opt->full_height))
        return gerror_set(err, G_ERR_INVALID, "%s: the %dx%d image at %d,%d does not lie inside the %dx%d full image",
                          path, img->width, img->height, opt->x, opt->y, opt->full_width, opt->full_height);
    int rc0 = opt && opt->spectra ? check_spectra(path, opt->spectra, err) : G_OK;
    if (rc0 != G_OK)
        return rc0;
    const GImageDisplay *shown = opt ? opt->display : NULL;
    if (shown && (img->channels < 3 || gimage_float_path(path)))
        return gerror_set(err, G_ERR_INVALID, "%s: a display transform is for 8-bit formats of RGB images; %s", path,
                          img->channels < 3 ? "this image has fewer channels" : "this format stores linear floats");
    if (shown) { /* through OpenImageIO and OpenColorIO, PNG too, with the config found here */
        char config[PATH_MAX + 64];
        if ((rc0 = gimage_display_check(shown, config, sizeof config, err)) != G_OK)
            return rc0;
        GImageDisplay resolved = {config, shown->display, shown->view, shown->confine_dir};
        GImageWriteOptions o2 = *opt;
        o2.display = &resolved;
        const GOiioOps *o = goiio_ops(err);
        return o ? o->image_write(path, img, &o2, err) : G_ERR_IO;
    }
    const int png = gimage_path_has_extension(path, ".png");
    const int exr = gimage_path_has_extension(path, ".exr") && !(opt && opt->spectra);
    if (png || exr) { /* spectra go to OpenEXR through OpenImageIO */
        if (png && opt && opt->spectra)
            return gerror_set(err, G_ERR_INVALID, "%s: only OpenEXR files store spectra, not PNG files", path);
        double exposure = opt ? opt->exposure : 0.0;
        if (!isfinite(exposure))
            return gerror_set(err, G_ERR_INVALID, "%s: exposure must be finite", path);
        int rc = gfile_check_output(path, err);
        if (rc != G_OK)
            return rc;
        return png ? gimage_png_write(path, img, exp2(exposure), err)
                   : gimage_exr_write(path, img, opt, exp2(exposure), err);
    }
    const GOiioOps *o = goiio_ops(err);
    return o ? o->image_write(path, img, opt, err) : G_ERR_IO;
}

int gtexsys_create(GTextureSystem **out, GError *err)
{
    *out = NULL;
    const GOiioOps *o = goiio_ops(err);
    return o ? o->texsys_create(out, err) : G_ERR_IO;
}

/* A texture system exists only once the module is loaded, so NULL needs no module. */
GTextureSystem *gtexsys_ref(GTextureSystem *ts)
{
    const GOiioOps *o = ts ? goiio_ops(NULL) : NULL;
    return o ? o->texsys_ref(ts) : NULL;
}

void gtexsys_unref(GTextureSystem *ts)
{
    const GOiioOps *o = ts ? goiio_ops(NULL) : NULL;
    if (o)
        o->texsys_unref(ts);
}

GTextureSystem *gtexsys_default(GError *err)
{
    const GOiioOps *o = goiio_ops(err);
    return o ? o->texsys_default(err) : NULL;
}

/* An image refusal ("PATH: cannot read image: REASON") worded as the texture system's own: "image 'PATH' cannot be
 * read: REASON". Returns rc. */
static int texture_refusal(const char *path, int rc, GError *err)
{
    if (!err)
        return rc;
    char reason[sizeof err->message];
    const char *why = err->message;
    size_t len = strlen(path);
    if (strncmp(why, path, len) == 0 && strncmp(why + len, ": ", 2) == 0)
        why += len + 2;
    if (strncmp(why, "cannot read image: ", 19) == 0)
        why += 19;
    snprintf(reason, sizeof reason, "%s", why);
    return gerror_set(err, rc, "image '%s' cannot be read: %s", path, reason);
}

int gtexsys_open(GTextureSystem *ts, const char *path, GTexColorSpace space, GTexFile **file, int *channels, int *srgb,
                 GError *err)
{
    *file = NULL;
    if (!ts || !path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "image: no file name given");
    if ((unsigned)space > GTEX_COLORSPACE_LINEAR)
        return gerror_set(err, G_ERR_INVALID, "image '%s': unknown colour space %d", path, (int)space);
    if (access(path, F_OK) != 0 && errno == ENOENT)
        return gerror_set(err, G_ERR_IO, "image '%s': no such file", path);
    /* the header first: a texture of too many pixels is refused before any decode */
    int w, h;
    int rc = gimage_info(path, &w, &h, NULL, err);
    if (rc != G_OK)
        return texture_refusal(path, rc, err);
    if ((long long)w * h > GTEXSYS_MAX_PIXELS)
        return gerror_set(err, G_ERR_IO, "image '%s' is %dx%d pixels, more than a texture may have (%lld, 8192x8192): "
                          "reduce it first (e.g. oiiotool IN --resize 25%% -o OUT)", path, w, h, GTEXSYS_MAX_PIXELS);
    /* OpenImageIO's texture system reads the file in this process: a decoder process decodes it whole first */
    int isolated = gspawn_isolated(err);
    if (isolated < 0)
        return isolated;
    if (isolated && (rc = gdecode_run(path, GDECODE_CHECK, 0, NULL, NULL, NULL, NULL, err)) != G_OK)
        return texture_refusal(path, rc, err);
    const GOiioOps *o = goiio_ops(err);
    return o ? o->texsys_open(ts, path, space, file, channels, srgb, err) : G_ERR_IO;
}

int gtexsys_lookup(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap, double s, double t,
                   const double deriv[4], double blur, float rgb[3])
{
    const GOiioOps *o = ts ? goiio_ops(NULL) : NULL;
    if (!o) {
        rgb[0] = rgb[1] = rgb[2] = 0.0f;
        return G_ERR_IO;
    }
    return o->texsys_lookup(ts, file, swrap, twrap, s, t, deriv, blur, rgb);
}
