/* image_display.h - finding the OpenColorIO config of a display transform (image_display.c). */
#ifndef GENERIC_IMAGE_DISPLAY_H
#define GENERIC_IMAGE_DISPLAY_H

#include "generic/services/image.h"

/** The config a display transform uses (GImageDisplay): d->config, else $OCIO, else the shipped config found
 * beside the library or the program (DIR/../share/generic/ocio/config.ocio) or installed
 * (GENERIC_DATADIR/generic/ocio/config.ocio). Writes its path into path (size bytes); G_OK, or G_ERR_IO saying
 * where it was looked for. */
int gimage_display_config(const GImageDisplay *d, char *path, size_t size, GError *err);

#endif
