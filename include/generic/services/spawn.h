/* spawn.h - the readers of untrusted files in processes of their own (lib/core/spawn.c): whether files are read so,
 * finding a reader program, and the socket it talks over. The image decoder (generic-decode), gtrace's mesh reader
 * (gtrace-mesh) and its OpenVDB reader (gtrace-vdb) are found and connected with these; each is started with
 * posix_spawn (never a fork of a process with threads) under limits of address space and CPU time. */
#ifndef GENERIC_SPAWN_H
#define GENERIC_SPAWN_H

#include "../export.h"
#include "../error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Whether untrusted images and meshes are read in processes of their own, from the environment variable
 * GENERIC_DECODE: unset, empty or "isolated" (the default): 1; "inprocess" (trusted files): 0; any other value:
 * G_ERR_INVALID in err naming the value and the two accepted. */
GENERIC_API int gspawn_isolated(GError *err);

/** Finds the reader program `name` into out (PATH_MAX bytes, its canonical path): the path in the environment
 * variable `env` when that is set and not empty (taken as it is, unless the process runs set-user-ID), else the
 * first executable `name` in the folder of the object holding `code` (a function's address: this library, or the
 * program), in its generic/ and in its ../lib/generic/, the same beside the running program, then in
 * libdir/generic (libdir may be NULL). 1 when found; 0 with out empty when not. */
GENERIC_API int gspawn_find(const char *name, const char *env, const void *code, const char *libdir, char *out);

/** A connected pair of AF_UNIX stream sockets, close-on-exec, both numbered above `lowest` (at least 2), so that
 * neither takes the place of a standard descriptor (or another descriptor a child is given) when this process runs
 * with one closed. 0, or -1 with errno set and nothing left open. */
GENERIC_API int gspawn_socketpair(int sv[2], int lowest);

#ifdef __cplusplus
}
#endif
#endif
