/* image_png.h - PNG output through libpng, without OpenImageIO: the common case (a tool writing its picture)
 * then maps a handful of small libraries instead of OpenImageIO's 260. The same encoding as the OpenImageIO
 * path (image.cpp): 8-bit sRGB, straight alpha, through a temporary that replaces the file only when complete. */
#ifndef GENERIC_IMAGE_PNG_H
#define GENERIC_IMAGE_PNG_H

#include "generic/services/image.h"

/** Writes img (1..4 channels: grey, grey+alpha, RGB, RGBA) to path, colour channels multiplied by scale, then
 * sRGB-encoded and clamped. G_OK, G_ERR_IO or G_ERR_NOMEM. */
GENERIC_NODISCARD int gimage_png_write(const char *path, const GImage *img, double scale, GError *err);

#endif
