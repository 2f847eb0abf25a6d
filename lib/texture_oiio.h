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

/** A filtered lookup of 3 channels (grey files are replicated) at (s, t) (t = 0 at the top row) with an
 * isotropic filter width (in s, t units; 0 = the finest level), trilinear MIP-mapping and the wrap modes;
 * G_ERR_IO when OpenImageIO fails (rgb is then black). Thread safe. */
int gtexsys_lookup(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap, double s, double t,
                   double width, double blur, float rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
