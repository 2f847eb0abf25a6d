/* transport.c - gtrace's MPI module, gtrace_mpi.so (mpi_module.h): point-to-point messages on MPI_COMM_WORLD with
 * every wait bounded. MPI's own calls block without limit, so a wait here polls (MPI_Iprobe, MPI_Test) with a
 * back-off of up to a millisecond until the deadline: a rank that died or stopped turns into a timeout the caller
 * reports, never a hang. Built against Open MPI alone; it uses nothing of libgeneric. */
#include "../mpi_module.h"

#include <mpi.h>

#include <limits.h>
#include <stdio.h>
#include <time.h>

/* Sends in flight; a handle is an index here. gtrace keeps at most two per rank pair. */
enum { MAX_SENDS = 64 };
static MPI_Request sends[MAX_SENDS];
static int sends_init;

static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Sleeps between two polls: nothing for the first few, then doubling up to 1 ms. */
static void back_off(int *round)
{
    if (++*round < 16)
        return;
    long ns = 1000L << (*round - 16 < 10 ? *round - 16 : 10);
    struct timespec ts = {0, ns < 1000000L ? ns : 1000000L};
    nanosleep(&ts, NULL);
}

/* The message of an MPI error code, as "what: reason"; returns -1. */
static int fail(int code, const char *what, char *msg, size_t cap)
{
    char text[MPI_MAX_ERROR_STRING];
    int len = 0;
    if (MPI_Error_string(code, text, &len) != MPI_SUCCESS)
        snprintf(text, sizeof text, "MPI error %d", code);
    snprintf(msg, cap, "%s: %s", what, text);
    return -1;
}

static int init(int *rank, int *size, char *msg, size_t cap)
{
    int provided = 0, rc = MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided);
    if (rc != MPI_SUCCESS)
        return fail(rc, "MPI_Init_thread", msg, cap);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    if ((rc = MPI_Comm_rank(MPI_COMM_WORLD, rank)) != MPI_SUCCESS || (rc = MPI_Comm_size(MPI_COMM_WORLD, size)))
        return fail(rc, "MPI_Comm_rank", msg, cap);
    if (!sends_init) {
        for (int i = 0; i < MAX_SENDS; i++)
            sends[i] = MPI_REQUEST_NULL;
        sends_init = 1;
    }
    return 0;
}

static int isend(int dest, int tag, const void *buf, size_t len, int *handle, char *msg, size_t cap)
{
    if (len > INT_MAX) {
        snprintf(msg, cap, "a message of %zu bytes is too long for MPI (at most %d)", len, INT_MAX);
        return -1;
    }
    int slot = 0;
    while (slot < MAX_SENDS && sends[slot] != MPI_REQUEST_NULL)
        slot++;
    if (slot == MAX_SENDS) {
        snprintf(msg, cap, "more than %d sends in flight", MAX_SENDS);
        return -1;
    }
    int rc = MPI_Isend(buf, (int)len, MPI_BYTE, dest, tag, MPI_COMM_WORLD, &sends[slot]);
    if (rc != MPI_SUCCESS)
        return fail(rc, "MPI_Isend", msg, cap);
    *handle = slot;
    return 0;
}

static int wait_send(int handle, double timeout, char *msg, size_t cap)
{
    if (handle < 0 || handle >= MAX_SENDS) {
        snprintf(msg, cap, "no send %d", handle);
        return -1;
    }
    double deadline = seconds() + timeout;
    for (int round = 0;; back_off(&round)) {
        int done = 0, rc = MPI_Test(&sends[handle], &done, MPI_STATUS_IGNORE);
        if (rc != MPI_SUCCESS)
            return fail(rc, "MPI_Test", msg, cap);
        if (done)
            return 0;
        if (seconds() >= deadline)
            return 1;
    }
}

static int probe(double timeout, int *from, int *tag, size_t *len, char *msg, size_t cap)
{
    double deadline = seconds() + timeout;
    for (int round = 0;; back_off(&round)) {
        int flag = 0, count = 0;
        MPI_Status st;
        int rc = MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        if (rc != MPI_SUCCESS)
            return fail(rc, "MPI_Iprobe", msg, cap);
        if (flag) {
            if ((rc = MPI_Get_count(&st, MPI_BYTE, &count)) != MPI_SUCCESS)
                return fail(rc, "MPI_Get_count", msg, cap);
            *from = st.MPI_SOURCE;
            *tag = st.MPI_TAG;
            *len = (size_t)count;
            return 0;
        }
        if (seconds() >= deadline)
            return 1;
    }
}

static int recv(int from, int tag, void *buf, size_t len, double timeout, char *msg, size_t cap)
{
    MPI_Request req;
    int rc = MPI_Irecv(buf, (int)len, MPI_BYTE, from, tag, MPI_COMM_WORLD, &req);
    if (rc != MPI_SUCCESS)
        return fail(rc, "MPI_Irecv", msg, cap);
    double deadline = seconds() + timeout;
    for (int round = 0;; back_off(&round)) {
        int done = 0;
        if ((rc = MPI_Test(&req, &done, MPI_STATUS_IGNORE)) != MPI_SUCCESS)
            return fail(rc, "MPI_Test", msg, cap);
        if (done)
            return 0;
        if (seconds() >= deadline)
            return 1; /* the request stays posted: the caller ends the job */
    }
}

static void abort_all(int status)
{
    MPI_Abort(MPI_COMM_WORLD, status);
}

static void finalize(void)
{
    MPI_Finalize();
}

static const char *version(void)
{
    static char text[MPI_MAX_LIBRARY_VERSION_STRING];
    int len = 0;
    if (MPI_Get_library_version(text, &len) != MPI_SUCCESS)
        return "unknown MPI";
    for (int i = 0; text[i]; i++)
        if (text[i] == ',' || text[i] == '\n') {
            text[i] = 0;
            break;
        }
    return text;
}

__attribute__((visibility("default"))) int gtrace_mpi_module(unsigned abi, GtMpiOps *ops)
{
    if (abi != GTMPI_ABI)
        return -1;
    *ops = (GtMpiOps){init, isend, wait_send, probe, recv, abort_all, finalize, version};
    return 0;
}
