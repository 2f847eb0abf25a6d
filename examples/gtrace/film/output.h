/* output.h - writing the rendered image (output.c). */
#ifndef GTRACE_OUTPUT_H
#define GTRACE_OUTPUT_H

#include "framebuffer.h"

#include <generic/error.h>
#include <generic/services/image.h>

/** Writes the framebuffer by extension: .exr linear float (and, with fb->waves, the values at wavelengths as
 * emissive channels S0.<nm>nm in the layout of generic/services/image.h); .png/.jpg/.jpeg sRGB-encoded after 2^exposure
 * scaling, clamped to [0,1], or through the OpenColorIO display transform display (NULL: none; 8-bit formats
 * only, generic/services/image.h). Writes a temporary file and renames it, so a failed write
 * leaves no partial file. */
int output_write(const char *path, const Framebuffer *fb, double exposure, const GImageDisplay *display, GError *err);
/** output_write recording note (NULL: none) with a crop (GImageWriteOptions.note: OpenEXR keeps it), which
 * `gtrace merge` compares between pieces. */
int output_write_piece(const char *path, const Framebuffer *fb, double exposure, const GImageDisplay *display,
                       const char *note, GError *err);

/** 1 when path names a linear float format (.exr, .hdr, .pfm): no exposure and no display transform. */
int output_is_float(const char *path);

/** 1 when path names an OpenEXR file (.exr, any case): the one format that stores the values at wavelengths. */
int output_is_exr(const char *path);

/** Checks before the render that path can be written: its directory exists and is writable, it is not a
 * directory or a device, and OpenImageIO has a writer for its extension (gimage_check_output). */
int output_check(const char *path, GError *err);

#endif
