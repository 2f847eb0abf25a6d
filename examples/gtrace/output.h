/* output.h - writing the rendered image (output.c). */
#ifndef GTRACE_OUTPUT_H
#define GTRACE_OUTPUT_H

#include "render.h"

#include <generic/error.h>

/** Writes the framebuffer by extension: .exr linear float; .png/.jpg/.jpeg sRGB-encoded after
 * 2^exposure scaling, clamped to [0,1]. Writes a temporary file and renames it, so a failed write
 * leaves no partial file. */
int output_write(const char *path, const Framebuffer *fb, double exposure, GError *err);

/** Checks before the render that path can be written: its directory exists and is writable, it is not a
 * directory or a device, and OpenImageIO has a writer for its extension (gimage_check_output). */
int output_check(const char *path, GError *err);

#endif
