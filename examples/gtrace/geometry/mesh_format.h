/* mesh_format.h - which reader a mesh file goes to (mesh_format.c), the checks a PLY or STL file passes before
 * assimp reads it (mesh_ply.c, mesh_stl.c) and the assimp reader (mesh_assimp.c). */
#ifndef GTRACE_MESH_FORMAT_H
#define GTRACE_MESH_FORMAT_H

#include "object.h"

#include <stddef.h>

/** Most vertices or triangles of a mesh: the OBJ reader's arrays hold at most 2^30 ints, 3 per triangle or vertex. */
#define MESH_MAX_COUNT (0x40000000 / 3)
/** Largest PLY or STL file in bytes (4 GiB less 16): assimp reads the checked bytes from memory, with a 32-bit
 * length. */
#define MESH_MAX_FILE_BYTES 0xfffffff0ull
/** Deepest nesting of a mesh file's nodes (assimp's node import and post-processing recurse over them). */
#define MESH_MAX_NODE_DEPTH 256
/** Most files (besides the mesh) a mesh file may name and assimp may open for it. */
#define MESH_MAX_FILES 64
/** Most nodes a glTF file's node tree expands to (a node named by n parents counts n times, with its subtree):
 * assimp copies each, about 1 KB apiece. */
#define GLTF_MAX_PLACEMENTS 100000
/** The mesh formats gtrace reads, for messages. */
#define MESH_FORMATS_READ "Wavefront OBJ (.obj), PLY (.ply), STL (.stl) and glTF 2.0 (.gltf, .glb)"

/** The reader of a mesh file. */
typedef enum MeshFormat {
    MESH_FORMAT_OBJ,        /**< mesh.c */
    MESH_FORMAT_PLY,        /**< mesh_ply.c's check, then assimp */
    MESH_FORMAT_STL,        /**< mesh_stl.c's check, then assimp */
    MESH_FORMAT_GLTF,       /**< mesh_gltf.c's check, then assimp (a .gltf may name buffer files beside it) */
    MESH_FORMAT_UNSUPPORTED /**< a format gtrace does not read */
} MeshFormat;

/** The reader for a file whose first n bytes are head, of size bytes in all, named path. The content decides: a
 * "ply" first line is PLY, a binary STL (84 + 50 bytes per triangle its header counts) or "solid" at the start (an
 * ASCII STL) is STL, the "glTF" magic (.glb) or a '{' as the first character besides white space (glTF's JSON) is
 * glTF, a 3DS main chunk is unsupported. Else the name decides: .ply, .stl, .gltf and .glb go to that format's check
 * (mesh_ply_check, mesh_stl_check, mesh_gltf_check), which refuses what its content is not, before assimp reads a
 * byte; .3ds and the other extensions assimp knows (mesh_assimp_reads_extension) are unsupported, and so is a file
 * with a NUL byte in its first line (binary data); any other is OBJ, which
 * gtrace reads itself. For an unsupported
 * file, what (of what_size bytes) names what it is ("a 3DS (3D Studio) file", "a .fbx file"). */
MeshFormat mesh_format_detect(const unsigned char *head, size_t n, unsigned long long size, const char *path,
                              char *what, size_t what_size);
/** mesh_format_detect on the first bytes of the regular file open as fd (its offset is left where it was). */
MeshFormat mesh_format_of(int fd, const char *path, char *what, size_t what_size);

/** 1 when the word w (len bytes, no NUL needed) is a decimal number that assimp's number readers and strtod read
 * whole and alike: a sign, digits with a point among or after them or a point and digits, an exponent with digits
 * (no hexadecimal, no "nan" or "inf", no comma). */
int mesh_decimal_number(const char *w, size_t len);
/** 1 when assimp has a reader for files named with the extension ext (with its dot, any case). */
int mesh_assimp_reads_extension(const char *ext);
/** Reads a PLY, STL or glTF 2.0 file through assimp (mesh_assimp.c): positions, normals and the first (u,v) set per
 * vertex, node transforms baked in, each assimp mesh's material index as the surface index. fd is the file, open,
 * and is closed. The file is read whole (at most MESH_MAX_FILE_BYTES; a glTF file of JSON at most JSON_MAX_BYTES)
 * and checked (mesh_ply_check, mesh_stl_check, mesh_gltf_check), and assimp reads those bytes; the other files a
 * glTF file names are opened only where files allows (NULL: everywhere), as regular files (mesh_assimp_io.h); more
 * than MESH_MAX_COUNT vertices or triangles are refused before they are copied. Errors name the file. */
int mesh_load_assimp(Object *o, const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err);

/** The checks mesh_load_assimp makes before assimp reads a byte (mesh_ply_check, mesh_stl_check, mesh_gltf_check
 * on the file read whole, charged to the memory budget while it is held), alone: G_OK, or their refusal. fd stays
 * open. */
int mesh_assimp_check(const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err);
/** mesh_load_assimp in the reader process gtrace-mesh (mesh_isolated.c, mesh_protocol.h), under limits of address
 * space and CPU time, after mesh_assimp_check in this process: the same mesh, the same errors, and fd closed; the other
 * files a glTF file names are allowed by files here, in this process, before the reader opens them. The mesh's counts
 * are bounded and its arrays reserved against the memory budget before they are allocated, and its indices and
 * positions checked. A reader that crashes, runs out of its limits, gives no answer in time or breaks the protocol is
 * G_ERR_IO naming the file and how it ended; the reader is always reaped. */
int mesh_load_isolated(Object *o, const char *path, int fd, MeshFormat format, const MeshFiles *files, GError *err);

/** What a checked glTF file places: the nodes its node tree expands to, and the vertices and triangles of the meshes
 * summed over those placements (what the mesh baked from it holds, at most). */
typedef struct MeshGltfCounts {
    unsigned long long placements, verts, tris;
    unsigned long long buffer_bytes; /**< the byteLength of all its buffers */
} MeshGltfCounts;
/** Checks a whole glTF 2.0 file (data, size bytes: JSON, or a .glb by its "glTF" magic) before assimp reads it
 * (mesh_gltf.c): the .glb's header and chunk lengths against size; the JSON strict and nested at most JSON_MAX_DEPTH
 * deep (scanned without recursion); asset.version "2.x"; each buffer's byteLength held by its data: URI, the .glb's
 * BIN chunk or its file beside path (a relative name, allowed by files, a regular file of at least that many bytes);
 * buffer views within their buffers, accessors (with a buffer view, not sparse) within their views; every index in
 * range; nodes without cycles, at most MESH_MAX_NODE_DEPTH deep, expanding to at most GLTF_MAX_PLACEMENTS
 * placements and MESH_MAX_COUNT placed vertices and triangles, which *counts receives. Errors are
 * "PATH:LINE:COL: message" (a .glb's: in its JSON chunk) where there is a position. */
int mesh_gltf_check(const char *path, const unsigned char *data, size_t size, const MeshFiles *files,
                    MeshGltfCounts *counts, GError *err);

/** Checks a whole PLY file (data, size bytes, and one more byte that may be written) before assimp reads it: a
 * "ply" line, one format line, element and property lines it understands, other header lines (comment, obj_info, a
 * line such as Blender 2.4x's "Created by Blender3D 247 ...") skipped; element counts the file can hold, at most one
 * vertex and one face (or tristrips) element; a body with every value the header announces (ASCII: numbers as
 * assimp reads them), face lists of at least 3 indices within the vertex count. On success *header (gmem_alloc,
 * *header_len bytes) is the header to hand assimp instead of the file's own, written from what was checked, with the
 * vertex and face (tristrips) elements only, and the body to hand it is the *body_len bytes at offset *body of data,
 * where their entries were rewritten (ASCII: one entry a line). Errors name the file (and the header line). */
int mesh_ply_check(const char *path, char *data, size_t size, char **header, size_t *header_len, size_t *body,
                   size_t *body_len, GError *err);
/** Checks a whole STL file (data, size bytes) before assimp reads it: binary (an 80-byte header, a count of
 * triangles, 50 bytes each, exactly filling the file) or ASCII (solid NAME, facets of "facet normal X Y Z",
 * "outer loop", three "vertex X Y Z", "endloop", "endfacet", then "endsolid"; several solids may follow each
 * other), with finite numbers and 1 to MESH_MAX_COUNT / 3 triangles. Errors name the file (ASCII: FILE:LINE:COL). */
int mesh_stl_check(const char *path, const char *data, size_t size, GError *err);

#endif
