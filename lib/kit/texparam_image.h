/* texparam_image.h - the image lookup of textured colours (texparam.h), for lib/kit/texparam.c. */
#ifndef GENERIC_KIT_TEXPARAM_IMAGE_H
#define GENERIC_KIT_TEXPARAM_IMAGE_H

#include "generic/kit/texparam.h"

/** Reads `{ file PATH  wrap W  swrap W  twrap W  colorspace C  blur B }` after `image` and opens the image
 * (gtexparam_image_open) in model m; an image that cannot be read is reported at its file name. */
GENERIC_NODISCARD int gtexparam_image_read(GReader *r, const GColorModel *m, GColorRole role, GTexImage **out,
                                           GError *err);
/** The largest value of each channel uplifted in role, into new storage of the image's model. */
GENERIC_NODISCARD int gtexparam_image_max(GTexImage *im, GColorRole role, GColor *out, GError *err);

#endif
