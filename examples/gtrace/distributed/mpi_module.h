/* mpi_module.h - the interface between gtrace and its MPI module, gtrace_mpi.so (mpi/transport.c).
 * Open MPI maps a few dozen libraries and takes tens of milliseconds to start, so gtrace does not link it: the
 * module is opened (mpi_load.c) only when gtrace runs under mpirun. It holds MPI's few calls that gtrace needs,
 * each bounded by a timeout where it waits, and reports failures as text; the scheduling is gtrace's (dist.c). */
#ifndef GTRACE_MPI_MODULE_H
#define GTRACE_MPI_MODULE_H

#include <stddef.h>

/** Raised whenever the table changes; a module of another version is refused. */
#define GTMPI_ABI 1
/** The module's file name and the one symbol it exports (a GtMpiEntry). */
#define GTMPI_MODULE_FILE "gtrace_mpi.so"
#define GTMPI_ENTRY "gtrace_mpi_module"

/** MPI's operations as gtrace uses them. Every one that can fail returns 0, or -1 with a one-line reason in
 * msg (cap bytes); those that wait return 1 when their timeout (seconds) ran out first. */
typedef struct GtMpiOps {
    /** MPI_Init_thread (only the main thread calls MPI), errors returned rather than fatal; this process's rank
     * and the number of ranks. */
    int (*init)(int *rank, int *size, char *msg, size_t cap);
    /** Starts sending len bytes to rank dest with tag; *handle names the send for wait. buf must stay unchanged
     * until the send is complete. */
    int (*isend)(int dest, int tag, const void *buf, size_t len, int *handle, char *msg, size_t cap);
    /** Waits up to timeout seconds (0: looks once) for the send handle to complete. */
    int (*wait)(int handle, double timeout, char *msg, size_t cap);
    /** Waits up to timeout seconds (0: looks once) for a message from any rank: its sender, tag and length. */
    int (*probe)(double timeout, int *from, int *tag, size_t *len, char *msg, size_t cap);
    /** Receives the message probe found (from, tag, len as it gave them) into buf, waiting up to timeout seconds
     * for the rest of it to arrive. */
    int (*recv)(int from, int tag, void *buf, size_t len, double timeout, char *msg, size_t cap);
    /** Ends every rank of the job with status (MPI_Abort); does not return. */
    void (*abort)(int status);
    /** MPI_Finalize. */
    void (*finalize)(void);
    /** The MPI library's version line. */
    const char *(*version)(void);
} GtMpiOps;

/** The module's entry: checks abi, fills ops. 0, or -1 for another ABI. */
typedef int (*GtMpiEntry)(unsigned abi, GtMpiOps *ops);

#endif
