/* dist_job.h - what the distributed render's two parts share (dist.c: the job, its messages and the block
 * renderers; dist_particles.c: the particle integrators): the message tags, a rank's state and the bounded
 * messaging, each failure going through job_fail. Private to distributed/. */
#ifndef GTRACE_DIST_JOB_H
#define GTRACE_DIST_JOB_H

#include "dist.h"
#include "mpi_module.h"

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

enum { TAG_HELLO = 1, TAG_WORK, TAG_RESULT, TAG_FAIL, TAG_STATS, TAG_PHOTONS, TAG_GO, TAG_BAND };
typedef struct Totals {
    uint64_t rays, nonfinite, capped;
} Totals;

struct Dist {
    const GtMpiOps *ops;
    int rank, size;
    int failed;                /* the job failed (job_fail): dist_finish ends every rank */
    struct sigaction old_term; /* rank 0: SIGTERM's action before dist_start */
};

/* The state of one distributed render on one rank. */
typedef struct Job {
    Dist *d;
    const DistSettings *ds;
    GError *err;          /* where job_fail puts the message */
    Renderer *r;
    Framebuffer *fb;
    int nbx, nblocks;
    int *order;           /* the blocks in the order they are handed out */
    unsigned char *buf;   /* one block's message: its index, then the packed pixels */
    size_t buf_cap;
    const GColorModel *model; /* the particle integrators: the scene's colour model */
    unsigned char *pbuf;  /* the particle integrators: a batch's paths, packed */
    size_t pbuf_cap;
    char msg[512];        /* the transport's last message */
} Job;


/* The job has failed: the message into j->err (on rank 0 "TEXT; the job is ended and no image written", on
 * another "rank R: TEXT; the job is ended"), and the job marked for dist_finish to end. Returns G_ERR_IO. */
__attribute__((format(printf, 2, 3))) int job_fail(Job *j, const char *fmt, ...);
/* Sends len bytes to dest and waits (bounded) until they are gone. G_OK or job_fail's status. */
int job_send(Job *j, int dest, int tag, const void *buf, size_t len);
/* Waits up to timeout seconds for a message: 1 with its sender, tag and length, 0 when none came, or job_fail's
 * status. */
int job_next_message(Job *j, double timeout, int *from, int *tag, size_t *len);
/* Receives the message job_next_message announced into buf (cap bytes; a longer message is an error). G_OK or
 * job_fail's status. */
int job_receive(Job *j, int from, int tag, size_t len, void *buf, size_t cap);

/* The particle integrators' part after the HELLOs: every rank renders with a PhotonShare, then rank 0 gathers the
 * bands. Rank 0: G_OK or the failure; another: 1 once its band is sent, or the failure. */
int job_particles(Job *j, const Scene *s, const RenderSettings *rs, RenderStats *st);

#endif
