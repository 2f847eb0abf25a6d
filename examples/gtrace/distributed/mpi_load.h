/* mpi_load.h - whether gtrace runs under mpirun, and its MPI module (mpi_load.c). */
#ifndef GTRACE_MPI_LOAD_H
#define GTRACE_MPI_LOAD_H

#include "mpi_module.h"

#include <generic/error.h>

/** 1 when the process was started by an MPI launcher (mpirun, srun with PMIx: its environment names a rank). */
int mpi_launched(void);

/** The MPI module's operations, loading it once: $GTRACE_MPI_MODULE (a path, then nowhere else), else
 * generic/ and ../lib/generic/ beside the executable, else the installed GTRACE_MPI_LIBDIR. NULL with G_ERR_IO
 * naming the module and the reason when it cannot be loaded. Not thread safe (the main thread calls it once). */
const GtMpiOps *mpi_load(GError *err);

/** What --version says about distributed rendering: the module's file as built, or that it was not built. */
const char *mpi_build_note(void);

#endif
