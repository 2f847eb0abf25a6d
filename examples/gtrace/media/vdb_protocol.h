/* vdb_protocol.h - what the grid reader gtrace-vdb (vdb/vdb_read.cpp) writes on its standard output for gtrace's grid
 * media (media/grid_load.c), which start it per file with posix_spawn, so that OpenVDB never runs in gtrace's own
 * process and a hostile file can at worst end the reader.
 *
 * Invocation: gtrace-vdb FILE GRID MAX_VOXELS MAX_BYTES, where MAX_VOXELS bounds the dense copy (the bounding box of
 * the grid's active voxels) and MAX_BYTES the reader's address space. Output: a VdbReply; when its status is 0 the
 * dims[0] * dims[1] * dims[2] floats of the dense copy follow (x fastest, then y, then z), else message holds the
 * reason. Both sides are built on this machine: native byte order and layout. */
#ifndef GTRACE_VDB_PROTOCOL_H
#define GTRACE_VDB_PROTOCOL_H

#include <stdint.h>

/** The reader's program name, found beside gtrace (media/grid_load.c). */
#define VDB_READER_PROGRAM "gtrace-vdb"
/** The first bytes of every reply. */
#define VDB_REPLY_MAGIC 0x31424456u /* "VDB1" */

/** The reader's reply header. */
typedef struct VdbReply {
    uint32_t magic;            /**< VDB_REPLY_MAGIC */
    int32_t status;            /**< 0: a grid follows; 1: refused (message says why) */
    int32_t min[3];            /**< index of the first voxel of the dense copy */
    int32_t dims[3];           /**< voxels along x, y, z (>= 1 each when status is 0) */
    double index_to_world[12]; /**< rows of the 3x4 affine map from voxel index to the file's world space */
    uint64_t active_voxels;    /**< the grid's active voxel count */
    char message[400];         /**< the reason of a refusal, NUL-terminated */
} VdbReply;

#endif
