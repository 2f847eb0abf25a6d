/* image_exr.h - OpenEXR output through OpenEXRCore (OpenEXR's C library), without OpenImageIO: writing a
 * render's EXR then maps a few small libraries instead of OpenImageIO's 260. The same file as the OpenImageIO
 * path (image.cpp) writes: 32-bit float channels Y (grey), R G (two channels), R G B, R G B A, ZIP compression
 * in chunks of 16 scanlines, a crop's data window inside its display window with its note, through a temporary
 * that replaces the file only when complete. */
#ifndef GENERIC_IMAGE_EXR_H
#define GENERIC_IMAGE_EXR_H

#include "generic/services/image.h"

/** Writes img (1..4 channels) to path as float channels, the colour channels multiplied by scale (the alpha of
 * 2 and 4 channels as it is). opt (NULL: none) gives the crop (x, y, full_width, full_height, already checked
 * against the image's size) and its note; its spectra and display transform are not for this writer and must be
 * NULL. G_OK, G_ERR_IO or G_ERR_NOMEM. */
GENERIC_NODISCARD int gimage_exr_write(const char *path, const GImage *img, const GImageWriteOptions *opt,
                                       double scale, GError *err);

#endif
