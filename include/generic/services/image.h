/* image.h - reading and writing images (the library's one OpenImageIO shim, lib/image/image.cpp).
 *
 * Pixels in memory are always linear float values, stored row by row from the top row down and left to
 * right, channels interleaved: pixel (x, y) channel c is pixels[(y * width + x) * channels + c].
 *
 * Reading accepts OpenEXR, Radiance HDR, PFM, PNM, PNG, JPEG and TIFF, decided by the file's first bytes whatever
 * its name; any other content (IFF, DPX, BMP, ...) is G_ERR_IO naming the format found. Unless the environment says
 * GENERIC_DECODE=inprocess, gimage_read and gimage_info run in a decoder process (generic-decode, installed beside
 * the OpenImageIO module) under limits on its address space and CPU time, so that a crash, a hang or a memory
 * blow-up of a reader is a G_ERR_IO for that file (docs/reference/format.md, "Untrusted files"). The result has
 * 3 channels (RGB) or 4 (RGBA): grey images are expanded to RGB, files with an alpha channel keep it as
 * channel 3 unless GIMAGE_READ_RGB is given, extra channels are dropped. Integer files whose colour
 * space is sRGB (what OpenImageIO reports for 8-bit PNG and JPEG, and what gimage_write stores) are
 * decoded to linear values unless GIMAGE_READ_RAW is given; float files are taken as linear. Alpha is
 * never decoded. Alpha is passed through as the file stores it, without (un)premultiplying: straight for
 * 8-bit formats (PNG, TIFF, ...), premultiplied by the usual convention of EXR.
 *
 * Writing picks the encoding from the file name's extension:
 *   .exr .hdr                           linear float (EXR: 32-bit float, exact);
 *   .pfm                                linear float where OpenImageIO has a PFM writer (Debian 12's 2.4
 *                                       has none: the write fails with G_ERR_IO and writes nothing);
 *   anything else (.png .jpg .jpeg .tif .tiff .bmp .tga ...)
 *                                       8 bits per channel, sRGB encoded after the exposure (or through an
 *                                       OpenColorIO display transform, GImageDisplay), clamped to [0, 1]
 *                                       (alpha is clamped, not encoded).
 * Only the extensions of gimage_write_extensions() are written (found when the library was built); OpenEXR
 * files may carry spectra beside the colour channels (GImageSpectra).
 * A write goes to a temporary file in the destination's directory (generic/services/file.h) which is renamed over the
 * destination only when it is complete and on the disk: every failed write (a full disk, an I/O error), a
 * failed flush and a size that differs from what was written are errors, and leave no partial file behind and
 * an existing file untouched. A destination that is a symbolic link is written through it (the link's target
 * is replaced, the link kept). gimage_check_output checks a destination before any work is done.
 *
 * Untrusted files. Only regular files are read (a FIFO or a device is refused, generic/services/file.h). Before any
 * pixel memory is allocated, a header is refused when it claims more pixels than the file can hold (a PFM's
 * floats are uncompressed, a PNG's deflate stream expands at most 1032 times, a Radiance HDR row takes at
 * least 2 bytes for every 127 bytes of a component), or when the decoded image,
 * width x height x max(channels, 3) 32-bit floats, would exceed the memory limit, or when its decode (the file's
 * channels and a 4-channel result as floats, and the copy a decoder process sends back) does not fit in what is
 * left of the process-wide memory budget (generic/memory.h: --memory-limit, GENERIC_MEMORY_LIMIT_MB), which it holds
 * while it runs. Light probes (generic/services/probe.h) and texture systems hold theirs while they live. No C++
 * exception leaves this library: OpenImageIO's are turned into statuses.
 *
 * Errors return a negative status (error.h) and put OpenImageIO's own message into the GError. All
 * functions are thread safe for distinct images. */
#ifndef GENERIC_IMAGE_H
#define GENERIC_IMAGE_H

#include "../export.h"
#include "../error.h"
#include "../memory.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A float image; see the top of this file for the layout. */
typedef struct GImage {
    int width;
    int height;
    int channels;  /**< 1..4 for writing; gimage_read gives 3 or 4 */
    float *pixels; /**< width * height * channels floats, from gmem_alloc; owned by the image */
} GImage;

/** Flags for gimage_read (combine with |). */
enum {
    GIMAGE_READ_RAW = 1 << 0,  /**< keep the file's values: no sRGB decoding of integer files */
    GIMAGE_READ_RGB = 1 << 1,  /**< always 3 channels: drop alpha */
    GIMAGE_READ_RGBA = 1 << 2  /**< always 4 channels: alpha 1 where the file has none */
};

/** Emissive spectra stored beside an image's colour channels in OpenEXR, in the layout of Fichet, Pacanowski
 * and Wilkie 2021, "An OpenEXR Layout for Spectral Images" (JCGT 10(3)): one float channel per wavelength, named
 * S0.<wavelength with 6 decimals and a comma as separator>nm (e.g. S0.550,000000nm), and the string attributes
 * spectralLayoutVersion "1.0" and emissiveUnits "W.m^-2.sr^-1". */
typedef struct GImageSpectra {
    int count;                 /**< wavelengths per pixel, 1..GIMAGE_MAX_WAVELENGTHS */
    const double *wavelengths; /**< count of them, in nm, increasing, finite and > 0 */
    /** width * height * count values: pixel (x, y) at wavelength k is values[(y * width + x) * count + k] */
    const float *values;
} GImageSpectra;

/** The most wavelengths a GImageSpectra may have. */
#define GIMAGE_MAX_WAVELENGTHS 4096

/** A display transform through OpenColorIO 2 for 8-bit output, instead of the sRGB encoding: the view `view` of
 * the display `display` of an OCIO config, applied to the linear pixels (the config's scene_linear role) after
 * the exposure; the result is clamped to [0, 1] and quantised as it is. The config: `config` when given, else
 * the file named by $OCIO, else the one libgeneric ships (share/ocio/config.ocio, installed as
 * PREFIX/share/generic/ocio/config.ocio: linear Rec.709 scene, display sRGB with the views Standard (the sRGB
 * transfer function, the default), Log and Raw). OpenColorIO comes with the OpenImageIO module: it is loaded
 * only when a display transform is used. */
typedef struct GImageDisplay {
    const char *config;  /**< path of an OCIO config; NULL: $OCIO, else the shipped one */
    const char *display; /**< NULL: the config's default display */
    const char *view;    /**< NULL: the display's default view */
    /** NULL: the files the config names may lie anywhere. Else (gtrace's --confine DIR) every file it names (the LUTs
     * of its transforms) and every search path of it must lie under this folder once symbolic links are resolved;
     * the config file itself is the caller's choice (--ocio-config, $OCIO, the shipped one) and is not confined. */
    const char *confine_dir;
} GImageDisplay;

/** Options for gimage_write; NULL or a zeroed struct means exposure 0. */
typedef struct GImageWriteOptions {
    double exposure; /**< in stops: colour channels are multiplied by 2^exposure before encoding (all formats) */
    /** The image as a region of a larger one (a crop): its top-left pixel lies at (x, y) of a full_width x
     * full_height image. Formats with a data and a display window (OpenEXR) record it; the others ignore it.
     * full_width 0: the image is the whole picture. */
    int x, y, full_width, full_height;
    /** Spectra to store beside the colour channels (NULL: none). Only OpenEXR stores them: a write to another
     * format with spectra is G_ERR_INVALID, before anything is written. */
    const GImageSpectra *spectra;
    /** A display transform instead of the sRGB encoding (NULL: none). Only for 8-bit formats of RGB or RGBA
     * images: with a float format (.exr, .hdr) or fewer channels it is G_ERR_INVALID. */
    const GImageDisplay *display;
    /** A line of text stored with a crop (full_width > 0) in formats with a display window (OpenEXR: the string
     * attribute "generic:note"), read back by gimage_window; at most GIMAGE_NOTE_MAX - 1 bytes are kept. NULL or a
     * whole image: none. gtrace records there what render a piece belongs to. */
    const char *note;
} GImageWriteOptions;

/** Allocates a black image of the given size (channels 1..4); G_ERR_INVALID for bad sizes,
 * G_ERR_NOMEM when the allocation fails. */
GENERIC_API GENERIC_NODISCARD int gimage_create(GImage *img, int width, int height, int channels, GError *err);

/** Frees the pixels and zeroes the struct; NULL, or an image already freed, is a no-op. */
GENERIC_API void gimage_free(GImage *img);

/** The memory budget's default, in MiB: GMEM_BUDGET_DEFAULT_MB (generic/memory.h). */
#define GIMAGE_DEFAULT_BUDGET_MB GMEM_BUDGET_DEFAULT_MB

/** The process-wide memory budget's limit in bytes: gmem_budget_limit() (generic/memory.h). */
GENERIC_API size_t gimage_memory_budget(void);

/** gmem_budget_set_limit(bytes): the process-wide limit; 0 returns to the environment's or the default. */
GENERIC_API void gimage_set_memory_budget(size_t bytes);

/** Reads the first subimage of a file into img (which is overwritten, not freed first). flags: GIMAGE_READ_*.
 * G_ERR_IO when the file is not a regular file, cannot be opened or decoded, or its header claims more than
 * the file can hold (the message names the file and gives the reason), G_ERR_NOMEM when the image would
 * exceed the memory budget or memory runs out. On failure img is zeroed. */
GENERIC_API GENERIC_NODISCARD int gimage_read(const char *path, unsigned flags, GImage *img, GError *err);

/** Reads only the size and channel count of a file (channels as the file has them, 1..n), with the checks
 * of gimage_read: G_ERR_IO when the file cannot be opened or its header gives a size or channel count below
 * 1 or more than the file can hold, G_ERR_NOMEM when the image would exceed the memory budget. */
GENERIC_API GENERIC_NODISCARD int gimage_info(const char *path, int *width, int *height, int *channels, GError *err);

/** Where an image file's pixels lie in its full picture: OpenEXR's data window inside its display window (a crop
 * written with GImageWriteOptions' x, y, full_width, full_height). Formats without windows report the image as
 * the whole picture (x = y = 0, full size = size). */
/** Size of GImageWindow.note with its NUL. */
#define GIMAGE_NOTE_MAX 512

typedef struct GImageWindow {
    int x, y;                    /**< the top-left pixel of the data, relative to the display window's corner */
    int width, height;           /**< the data's size: what gimage_read returns */
    int full_width, full_height; /**< the display window's size */
    char note[GIMAGE_NOTE_MAX];  /**< the note a crop was written with (GImageWriteOptions.note), "" for none */
} GImageWindow;

/** Reads the data and display windows of a file's header, with the checks of gimage_info. G_ERR_IO when the
 * file cannot be opened or its header is refused, G_ERR_NOMEM as gimage_info. */
GENERIC_API GENERIC_NODISCARD int gimage_window(const char *path, GImageWindow *win, GError *err);

/** Spectra read back from an OpenEXR file in the layout of GImageSpectra (gimage_read_spectra); the struct owns
 * its arrays, which gimage_spectra_free releases. */
typedef struct GImageSpectraBuf {
    int width, height;   /**< the data's size, as gimage_read gives it */
    int count;           /**< wavelengths per pixel, 0..GIMAGE_MAX_WAVELENGTHS; 0: the file has no spectral channel */
    double *wavelengths; /**< count of them, in nm, increasing (NULL when count is 0) */
    /** width * height * count values, laid out as GImageSpectra's (NULL when count is 0) */
    float *values;
    size_t charged; /**< bytes of values held against the memory budget (generic/memory.h) until
                         gimage_spectra_free; 0 for a buffer the caller filled */
} GImageSpectraBuf;

/** The two layers of spectral channels in the layout of Fichet, Pacanowski and Wilkie 2021 (GImageSpectra). */
typedef enum GImageSpectraLayer {
    GIMAGE_SPECTRA_EMISSIVE = 0,  /**< S0.<wavelength>nm: radiance (the first Stokes component) */
    GIMAGE_SPECTRA_REFLECTIVE = 1 /**< T.<wavelength>nm: reflectance (the diagonal of a re-radiation matrix) */
} GImageSpectraLayer;

/** Reads the spectral channels of a file (the first subimage): every channel whose name starts with "S0." is one,
 * and its wavelength is parsed from its name, which must be S0.<digits>[,<digits>]nm (at most 15 digits, a
 * wavelength above 0; e.g. S0.550,000000nm). They are returned sorted by wavelength, whatever their order in
 * the file (OpenEXR stores channels sorted by name: S0.1000,000000nm before S0.380,000000nm). The other
 * channels are ignored; a file without spectral channels, or of a format without channel names, gives
 * count 0. out is overwritten, not freed first. G_OK; G_ERR_IO as gimage_read, and when a spectral channel's
 * name is malformed, two channels name the same wavelength or there are more than GIMAGE_MAX_WAVELENGTHS of
 * them (the message names the file and the channels); G_ERR_NOMEM when the values would exceed the image
 * memory budget or memory runs out. On failure out is zeroed. */
GENERIC_API GENERIC_NODISCARD int gimage_read_spectra(const char *path, GImageSpectraBuf *out, GError *err);

/** gimage_read_spectra for either layer: GIMAGE_SPECTRA_EMISSIVE reads the S0. channels as gimage_read_spectra
 * does; GIMAGE_SPECTRA_REFLECTIVE the channels named T.<digits>[,<digits>]nm with the same rules (re-radiation
 * channels T.<nm>nm.<nm>nm, the off-diagonal of a bispectral file, are ignored). The values are reserved against
 * the memory budget before they are allocated and held until gimage_spectra_free (out->charged): G_ERR_NOMEM
 * names the image and the limit when they do not fit. The channels are read in this process, after a decoder
 * process (as gimage_read's, unless GENERIC_DECODE=inprocess) decoded the file whole under its limits: a file that
 * crashes, hangs or blows up the reader is G_ERR_IO there. G_ERR_INVALID for another layer. */
GENERIC_API GENERIC_NODISCARD int gimage_read_spectra_layer(const char *path, GImageSpectraLayer layer,
                                                            GImageSpectraBuf *out, GError *err);

/** Frees what gimage_read_spectra allocated, releases out->charged from the memory budget, and zeroes the struct;
 * NULL, or spectra already freed, is a no-op. */
GENERIC_API void gimage_spectra_free(GImageSpectraBuf *s);

/** Writes img to path, encoding chosen by the extension (see the top of this file); the file appears
 * complete or not at all. G_ERR_INVALID for a bad image, G_ERR_IO when the format is unknown, the
 * destination cannot be written or the write fails. */
GENERIC_API GENERIC_NODISCARD int gimage_write(const char *path, const GImage *img, const GImageWriteOptions *opt,
                                               GError *err);

/** Checks before any work that gimage_write can write path: its directory exists and is writable, path is
 * not something other than a regular file (gfile_check_output), and its extension is one of
 * gimage_write_extensions() (Debian 12's OpenImageIO has no writer for .pfm). Loads no OpenImageIO. G_OK or
 * G_ERR_IO naming path and the reason. */
GENERIC_API GENERIC_NODISCARD int gimage_check_output(const char *path, GError *err);

/** The file extensions gimage_write writes, with their dots, sorted and separated by one space
 * (".bmp .exr ... .png ... .webp"): the ones this OpenImageIO wrote and read back when the library was built
 * (scripts/gen_image_writers.cpp), so that a program can list them without loading OpenImageIO. Case is ignored
 * when a path's extension is matched against them. A static string. */
GENERIC_API const char *gimage_write_extensions(void);

/** Checks a display transform before any work: finds its config (see GImageDisplay; writes the path used into
 * config_used, of size bytes, when not NULL), reads it and checks that it has the display and the view. G_OK;
 * G_ERR_IO when no config is found or OpenColorIO cannot be loaded, G_ERR_PARSE when the config does not read
 * (OpenColorIO's reason), G_ERR_NOTFOUND for an unknown display or view (the message lists the config's
 * displays, or the display's views). */
GENERIC_API GENERIC_NODISCARD int gimage_display_check(const GImageDisplay *d, char *config_used, size_t size,
                                                       GError *err);

/** The sRGB transfer function (IEC 61966-2-1): linear value in [0, 1] to its encoded value. */
GENERIC_API double gimage_srgb_encode(double linear);

/** The inverse of gimage_srgb_encode. */
GENERIC_API double gimage_srgb_decode(double encoded);

#ifdef __cplusplus
}
#endif
#endif
