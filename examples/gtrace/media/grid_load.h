/* grid_load.h - reading a grid medium's density from an OpenVDB file (grid_load.c) through the reader program
 * gtrace-vdb (vdb/vdb_read.cpp, vdb/vdb_protocol.h), started for each file in a process of its own. */
#ifndef GTRACE_GRID_LOAD_H
#define GTRACE_GRID_LOAD_H

#include "grid.h"

#include <generic/error.h>

/** Densest grid accepted: the dense copy holds at most this many voxels, whatever the memory budget allows. */
#define GRID_MAX_VOXELS (1LL << 30)

/** Reads the float grid `name` of the OpenVDB file at path into g (zeroed first; its index space placed by the
 * file's transform). The dense copy is bounded before anything is allocated: by GRID_MAX_VOXELS and by what the
 * memory budget has left, checked on the file's stated extent and again on its voxels (a file that understates
 * its grid is refused); the copy and its majorants are then reserved against the budget. Every density must be
 * finite and >= 0. G_OK, or G_ERR_IO with the reason (the file is missing, not an OpenVDB file, truncated, lies
 * about its grid, is too large, has no such grid or not float values; the reader is missing or ended without an
 * answer: a crash, its time or memory limit). */
int grid_load(const char *path, const char *name, Grid *g, GError *err);

#endif
