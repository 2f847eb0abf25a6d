/* texture_oiio.h - the C side of lib/texture_oiio.cpp, the thin shim over OpenImageIO's TextureSystem
 * used by the image node (textures/image.c). The public part (GTextureSystem) is in generic/textures.h. */
#ifndef GENERIC_LIB_TEXTURE_OIIO_H
#define GENERIC_LIB_TEXTURE_OIIO_H

#include "generic/textures.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An opened texture file (OpenImageIO's TextureHandle), valid while its texture system lives. */
typedef struct GTexFile GTexFile;

/** Opens (and checks) a texture file: G_ERR_IO with OpenImageIO's reason when it is missing or cannot be
 * decoded. *srgb is 1 for integer data not marked linear (8-bit PNG/JPEG), 0 for float data. */
int gtexsys_open(GTextureSystem *ts, const char *path, GTexFile **file, int *channels, int *srgb, GError *err);

/** A filtered lookup of 3 channels (grey files are replicated) at (s, t) (t = 0 at the top row) over the
 * footprint spanned by the two axes (dsdx, dtdx) and (dsdy, dtdy) (full widths in s, t units; all 0 = the
 * finest level), anisotropic with trilinear MIP-mapping, and the wrap modes; G_ERR_IO when OpenImageIO fails
 * (rgb is then black). An isotropic width w is (w, 0, 0, w). Thread safe. */
int gtexsys_lookup(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap, double s, double t,
                   const double deriv[4], double blur, float rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
