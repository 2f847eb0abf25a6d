/* decode_isolated.h - decoding untrusted images in a separate process (lib/image/decode_isolated.c): the library
 * side of lib/image/decode_protocol.h, and the switch between it and decoding in this process. */
#ifndef GENERIC_DECODE_ISOLATED_H
#define GENERIC_DECODE_ISOLATED_H

#include "generic/error.h"
#include "generic/services/image.h"

/** What the decoder does: the pixels, a full decode whose pixels are dropped (a check before OpenImageIO's texture
 * system opens the file in this process), or the header only. */
typedef enum { GDECODE_READ, GDECODE_CHECK, GDECODE_INFO } GDecodeMode;

/** Decodes path in a decoder process. READ fills img (zeroed on failure); READ and CHECK reserve the decode against
 * the memory budget from the header before the decode starts, and release it on return; INFO and CHECK give the
 * file's width, height and channels (any may be NULL). G_OK, or the reader's status and message, or G_ERR_IO when
 * the decoder cannot be started or ends without an answer (a crash, a time or memory limit: the message says which). */
int gdecode_run(const char *path, GDecodeMode mode, unsigned flags, GImage *img, int *width, int *height, int *channels,
                GError *err);

/** Before a file is read in this process (OpenImageIO's texture system, the spectral channels): decodes it whole in
 * a decoder process (gdecode_run, GDECODE_CHECK) when images are decoded apart (gspawn_isolated,
 * services/spawn.h), so that a file that crashes, hangs or blows up a reader is refused before. G_OK, or
 * gdecode_run's status. */
int gdecode_check_whole(const char *path, GError *err);

/** gimage_read_spectra_layer without its gdecode_check_whole, for a caller that ran it on path already (one check
 * for several reads). */
int gdecode_read_spectra_checked(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err);

/** The bytes a decode of a width x height image of channels channels charges in one process: the file's channels and
 * the 4-channel result, as floats. */
double gdecode_charge(int width, int height, int channels);

#endif
