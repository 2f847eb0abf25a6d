/* texsys.h - texture systems (OpenImageIO's TextureSystem behind lib/image/texture_oiio.cpp): reference-counted
 * systems shared by the image nodes of a scene, opened files and filtered lookups. */
#ifndef GENERIC_TEXSYS_H
#define GENERIC_TEXSYS_H

#include "../export.h"
#include "../error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A texture system: OpenImageIO's TextureSystem with its tile cache, shared by the image nodes of a scene.
 * Thread safe; reference counted. */
typedef struct GTextureSystem GTextureSystem;

/** Creates a texture system (MIP maps made on the fly for files that have none). */
GENERIC_API GENERIC_NODISCARD int gtexsys_create(GTextureSystem **out, GError *err);
/** Adds an owner; returns ts. */
GENERIC_API GTextureSystem *gtexsys_ref(GTextureSystem *ts);
/** Drops an owner; the last frees the system and its cache. NULL is a no-op. */
GENERIC_API void gtexsys_unref(GTextureSystem *ts);
/** The process's default texture system, created on first use and freed when its last owner lets go;
 * returns a new reference (or NULL with err filled). Image nodes created without a system use it. */
GENERIC_API GTextureSystem *gtexsys_default(GError *err);

/** How lookups outside [0, 1] behave. */
typedef enum GTexWrap {
    GTEX_WRAP_PERIODIC = 0, /**< repeat */
    GTEX_WRAP_CLAMP,        /**< the edge texels continue */
    GTEX_WRAP_BLACK,        /**< black outside */
    GTEX_WRAP_MIRROR        /**< repeat mirrored */
} GTexWrap;

/** How stored values relate to linear values. */
typedef enum GTexColorSpace {
    GTEX_COLORSPACE_AUTO = 0, /**< sRGB for 8- and 16-bit files that say sRGB (PNG, JPEG), linear otherwise */
    GTEX_COLORSPACE_SRGB,     /**< decode the sRGB curve */
    GTEX_COLORSPACE_LINEAR    /**< values are linear */
} GTexColorSpace;


/** An opened texture file (OpenImageIO's TextureHandle), valid while its texture system lives. */
typedef struct GTexFile GTexFile;

/** The most pixels a texture file may have: 8192 x 8192. A texture lookup never needs more than the pixels a
 * render shows it with, and OpenImageIO builds the MIP levels of a file that has none (PNG, JPEG) from the whole
 * image, so that a small file of a huge image (a 32 KB PNG of 12000 x 12000) would cost minutes: such a file is
 * refused from its header, before any decode, with the advice to reduce it. */
#define GTEXSYS_MAX_PIXELS (8192LL * 8192LL)

/** Opens (and checks) a texture file: G_ERR_IO with OpenImageIO's reason when it is missing or cannot be
 * decoded, or when it has more than GTEXSYS_MAX_PIXELS pixels; G_ERR_INVALID for a space outside GTexColorSpace.
 * Its content decides its format (generic/services/image.h: the formats read) and, unless GENERIC_DECODE=inprocess,
 * a decoder process decodes it whole before the texture system opens it in this process. space says how its
 * values relate to linear ones: with GTEX_COLORSPACE_SRGB, or GTEX_COLORSPACE_AUTO and integer data not marked
 * linear (8- and 16-bit PNG, JPEG), the system holds the file's colour channels decoded from the sRGB curve
 * (gimage_srgb_decode), so that MIP levels and filtered lookups average linear light: 8-bit data as halfs (the
 * nearest half of each code's decode, within a relative 4.6e-4 of it), other data as floats; *srgb is then 1.
 * Otherwise the values are taken as linear and *srgb is 0. The same file opened both ways is held twice. Every
 * lookup of the file gives linear values. */
GENERIC_API GENERIC_NODISCARD int gtexsys_open(GTextureSystem *ts, const char *path, GTexColorSpace space,
                                               GTexFile **file, int *channels, int *srgb, GError *err);

/** A filtered lookup of 3 channels (grey files are replicated) at (s, t) (t = 0 at the top row) over the
 * footprint spanned by the two axes (dsdx, dtdx) and (dsdy, dtdy) (full widths in s, t units; all 0 = the
 * finest level), anisotropic with trilinear MIP-mapping of linear values (gtexsys_open), and the wrap modes;
 * G_ERR_IO when OpenImageIO fails (rgb is then black). An isotropic width w is (w, 0, 0, w). Thread safe. */
GENERIC_API GENERIC_NODISCARD int gtexsys_lookup(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap,
                                                 double s, double t, const double deriv[4], double blur, float rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
