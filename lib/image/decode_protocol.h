/* decode_protocol.h - what the image decoder process (lib/image/decoder/generic_decode.c) and the library
 * (lib/image/decode_isolated.c) say to each other over the socket that is the decoder's standard input and output.
 *
 * The library starts `generic-decode MODE FLAGS AS_BYTES CPU:CPU_MAX PATH` (MODE "read": the pixels, "check": a
 * full decode whose pixels are dropped, "info": the header only). The decoder limits itself (address space AS_BYTES,
 * CPU time CPU seconds, at most CPU_MAX later, no core file, no file written), reads the header and sends a record of phase HEADER; for
 * "info" it ends there. Otherwise it waits for 'g' and two uint64_t (the library reserved the decode against its
 * memory budget; the numbers are the address space to lower its limit to and its CPU time in seconds) and goes on; anything else or the end of the socket
 * ends it. It then decodes and sends a record of phase
 * PIXELS followed, for "read" with status G_OK, by width x height x channels floats in the machine's order.
 * A record whose status is not G_OK is followed by message_length bytes of message. The decoder is built from the
 * same tree as the library: no versioning beyond the magic number. */
#ifndef GENERIC_DECODE_PROTOCOL_H
#define GENERIC_DECODE_PROTOCOL_H

#include <stdint.h>

#define GDECODE_MAGIC 0x47444331u /* "GDC1" */
#define GDECODE_PROGRAM "generic-decode"
/** The longest message a record carries. */
#define GDECODE_MESSAGE_MAX 512

enum { GDECODE_HEADER = 1, GDECODE_PIXELS = 2 };

/** One record. HEADER: width, height and the file's channels (1..n). PIXELS: width, height and the channels sent. */
typedef struct GDecodeRecord {
    uint32_t magic;
    int32_t phase;
    int32_t status; /**< G_OK or a negative G_ERR_ code */
    int32_t width, height, channels;
    uint32_t message_length; /**< 0..GDECODE_MESSAGE_MAX */
} GDecodeRecord;

#endif
