/* decode_protocol.h - what the image decoder process (lib/image/decoder/generic_decode.c) and the library
 * (lib/image/decode_isolated.c) say to each other over the socket that is the decoder's standard input and output.
 *
 * The library starts `generic-decode BASE_BYTES MAX_BYTES` once and sends it requests, one at a time. The decoder
 * limits its address space to BASE_BYTES (at most MAX_BYTES later), forbids core files and file writes, and for each
 * request (a GDecodeRequest and request.path_length bytes of path) reads the header and sends a record of phase
 * HEADER; for an "info" request, or a header refused, the request ends there. Otherwise it waits for a GDecodeGo:
 * 'g' (the library reserved the decode against its memory budget) with the address space and the CPU seconds the
 * decode may take, or 'n' (refused: the request ends). It then decodes and sends a record of phase PIXELS followed,
 * for "read" with status G_OK, by width x height x channels floats in the machine's order, and lowers its address
 * space limit back to BASE_BYTES. A record whose status is not G_OK is followed by message_length bytes of message.
 * The decoder ends at the end of its input. It is built from the same tree as the library: no versioning beyond the
 * magic number. */
#ifndef GENERIC_DECODE_PROTOCOL_H
#define GENERIC_DECODE_PROTOCOL_H

#include <stdint.h>

#define GDECODE_MAGIC 0x47444332u /* "GDC2" */
#define GDECODE_PROGRAM "generic-decode"
/** The longest message a record carries, and the longest path a request carries. */
#define GDECODE_MESSAGE_MAX 512
#define GDECODE_PATH_MAX 4096

enum { GDECODE_HEADER = 1, GDECODE_PIXELS = 2 };
/** Request modes: the pixels, a full decode whose pixels are dropped, the header only. */
enum { GDECODE_MODE_READ = 1, GDECODE_MODE_CHECK = 2, GDECODE_MODE_INFO = 3 };

/** A request: mode, gimage_read flags and the length of the path that follows. */
typedef struct GDecodeRequest {
    uint32_t magic;
    int32_t mode;
    uint32_t flags;
    uint32_t path_length; /**< 1..GDECODE_PATH_MAX */
} GDecodeRequest;

/** The answer to a HEADER record: go on ('g') within these limits, or stop ('n'). */
typedef struct GDecodeGo {
    uint32_t magic;
    int32_t go;
    uint64_t address_space; /**< bytes */
    uint64_t cpu_seconds;   /**< beyond what the decoder used before this decode */
} GDecodeGo;

/** One record. HEADER: width, height and the file's channels (1..n). PIXELS: width, height and the channels sent. */
typedef struct GDecodeRecord {
    uint32_t magic;
    int32_t phase;
    int32_t status; /**< G_OK or a negative G_ERR_ code */
    int32_t width, height, channels;
    uint32_t message_length; /**< 0..GDECODE_MESSAGE_MAX */
} GDecodeRecord;

#endif
