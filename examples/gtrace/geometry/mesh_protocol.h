/* mesh_protocol.h - what the mesh reader process (geometry/mesh_reader/gtrace_mesh.c) and gtrace
 * (geometry/mesh_isolated.c) say to each other.
 *
 * gtrace starts one reader per mesh file: `gtrace-mesh VERSION FORMAT PATH LIMIT USED ADDRESS_SPACE CPU ASK`, with
 * the file, open for reading, as descriptor 3 (the reader opens the mesh by no name), one end of a socket pair as
 * its standard input and output and /dev/null as its standard error. VERSION is MESH_PROTOCOL_VERSION (a reader
 * of another version exits with status MESH_EXIT_VERSION); FORMAT the MeshFormat gtrace detected; LIMIT and USED
 * gtrace's memory budget's limit and the bytes reserved in it (the reader charges its own reservations against the
 * same figures); ADDRESS_SPACE (bytes) and CPU (seconds) its limits; ASK 1 when the reader must ask before it opens
 * any other file (a glTF's buffer file), 0 when every file may be opened by the library's rules.
 *
 * The reader sends MeshMessage records: ASK (text: the path it wants to open), answered by a MeshAnswer and its
 * message (gtrace's --confine check), any number of times; then one RESULT. A RESULT whose status is not G_OK
 * carries the error (position, parameter and text); a RESULT with G_OK is followed by the mesh's arrays in the
 * machine's order: pos (3 nverts doubles), normal (3 nnormals doubles), uv (2 nuvs doubles), tri (3 ntris uint32),
 * tri_uv and tri_normal (3 ntris int32 each), tri_surface (ntris int32). The reader then exits. */
#ifndef GTRACE_MESH_PROTOCOL_H
#define GTRACE_MESH_PROTOCOL_H

#include <generic/error.h>

#include <stdint.h>

#define MESH_READER_PROGRAM "gtrace-mesh"
#define MESH_PROTOCOL_MAGIC 0x474d5348u /* "GMSH" */
#define MESH_PROTOCOL_VERSION 1
/** The reader's exit status when gtrace speaks another version of the protocol. */
#define MESH_EXIT_VERSION 3
/** The longest text a message carries (a path, or an error's message). */
#define MESH_TEXT_MAX 4096
/** The descriptor the mesh file is open on in the reader. */
#define MESH_READER_FD 3

enum { MESH_MSG_ASK = 1, MESH_MSG_RESULT = 2 };

/** From the reader: a question (ASK) or the answer to the request (RESULT), then text_length bytes of text. */
typedef struct MeshMessage {
    uint32_t magic;
    int32_t kind;
    int32_t status;                 /**< RESULT: G_OK or a negative G_ERR_ code */
    int32_t line, col;              /**< RESULT with an error: its position in the file, 0 for none */
    int32_t nverts, ntris, nuvs, nnormals;
    uint32_t text_length;           /**< 0..MESH_TEXT_MAX */
    char param[GERROR_PARAM_MAX];   /**< RESULT with an error: the parameter complained about, NUL-terminated */
} MeshMessage;

/** From gtrace, for an ASK: G_OK (open it), or the refusal and message_length bytes of its message. */
typedef struct MeshAnswer {
    uint32_t magic;
    int32_t status;
    uint32_t message_length; /**< 0..MESH_TEXT_MAX */
} MeshAnswer;

#endif
