/* dist.c - the distributed render (dist.h). The image (or its crop) is cut into blocks of DistSettings.block
 * pixels, taken in render_tile_order's shuffled order. Rank 0 keeps every other rank two blocks ahead (one to
 * render, one waiting), so a rank never idles while its result travels, and sends the next block whenever a
 * result arrives: a fast rank simply asks more often. Rank 0 renders blocks too, one row of 16-pixel tiles at a
 * time, looking at its messages between rows. A block's pixels travel packed by framebuffer_pack, so every
 * per-pixel array of the framebuffer comes along. Every wait is bounded by the timeout (the other ranks wait twice
 * as long for rank 0, which may itself be waiting a timeout for someone else: so rank 0, which sees the whole
 * job, names the culprit); a rank that exceeds it is named, and the job ends.
 *
 * Messages (native layout: every rank runs the same gtrace build): HELLO (status, digest, message) from each
 * rank once its scene is loaded; WORK (a block index, or STOP, or QUIT) from rank 0; RESULT (the block index,
 * then its packed pixels), FAIL (a message) and STATS (rays, non-finite, capped) to rank 0. */
#include "dist.h"
#include "mpi_load.h"

#include <generic/memory.h>

#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { TAG_HELLO = 1, TAG_WORK, TAG_RESULT, TAG_FAIL, TAG_STATS };
enum { WORK_STOP = -1, WORK_QUIT = -2 };
/* Blocks a rank holds: the one it renders and the one it will render next. */
enum { CREDIT = 2 };
/* Rows of a block rendered between two looks at the messages. */
enum { SLICE = 16 };

typedef struct Hello {
    int32_t status;
    uint64_t digest;
    char message[400];
} Hello;

typedef struct Totals {
    uint64_t rays, nonfinite, capped;
} Totals;

struct Dist {
    const GtMpiOps *ops;
    int rank, size;
    struct sigaction old_term; /* rank 0: SIGTERM's action before dist_start */
};

/* The state of one distributed render on one rank. */
typedef struct Job {
    Dist *d;
    const DistSettings *ds;
    Renderer *r;
    Framebuffer *fb;
    int nbx, nblocks;
    int *order;           /* the blocks in the order they are handed out */
    unsigned char *buf;   /* one block's message: its index, then the packed pixels */
    size_t buf_cap;
    char msg[512];        /* the transport's last message */
} Job;

/* Rank 0's SIGTERM from MPI's start to the end of dist_render: the launcher ends the job because another rank died. Says so (the launcher's
 * own message names the rank) and exits; no image has been written. */
static void terminated(int sig)
{
    static const char text[] = "gtrace: the MPI job was ended by its launcher (another rank died?) before the "
                               "image was complete; no image written\n";
    (void)sig;
    ssize_t n = write(STDERR_FILENO, text, sizeof text - 1);
    (void)n;
    _exit(1);
}

int dist_start(Dist **out, GError *err)
{
    *out = NULL;
    const GtMpiOps *ops = mpi_load(err);
    if (!ops)
        return G_ERR_IO;
    Dist *d = gmem_calloc(1, sizeof *d);
    if (!d)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    d->ops = ops;
    char msg[512];
    if (ops->init(&d->rank, &d->size, msg, sizeof msg) != 0) {
        gmem_free(d);
        return gerror_set(err, G_ERR_IO, "MPI could not start: %s", msg);
    }
    if (d->rank == 0) {
        struct sigaction term = {.sa_handler = terminated};
        sigaction(SIGTERM, &term, &d->old_term);
    }
    *out = d;
    return G_OK;
}

int dist_rank(const Dist *d)
{
    return d->rank;
}

int dist_size(const Dist *d)
{
    return d->size;
}

void dist_finish(Dist *d)
{
    if (!d)
        return;
    d->ops->finalize();
    gmem_free(d);
}

/* FNV-1a over n bytes, continuing from h. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ULL;
    return h;
}

uint64_t dist_digest(const char *scene_path, const char *model, const RenderSettings *rs)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    h = fnv(h, scene_path, strlen(scene_path) + 1);
    h = fnv(h, model ? model : "", strlen(model ? model : "") + 1);
    int v[] = {rs->width, rs->height, rs->spp, rs->depth, rs->max_rays, rs->bands, rs->integrator,
               rs->crop[0], rs->crop[1], rs->crop[2], rs->crop[3], rs->waves};
    h = fnv(h, v, sizeof v);
    return fnv(h, &rs->cutoff, sizeof rs->cutoff);
}

/* Prints the message and ends every rank of the job; never returns. */
__attribute__((noreturn, format(printf, 2, 3))) static void fatal(const Dist *d, const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (d->rank == 0)
        fprintf(stderr, "gtrace: %s; the job is ended and no image written\n", text);
    else
        fprintf(stderr, "gtrace: rank %d: %s; the job is ended\n", d->rank, text);
    fflush(stderr);
    d->ops->abort(1);
    abort(); /* MPI_Abort does not return */
}

/* Sends len bytes to dest and waits (bounded) until they are gone. */
static void send_now(Job *j, int dest, int tag, const void *buf, size_t len)
{
    const GtMpiOps *ops = j->d->ops;
    int h, rc = ops->isend(dest, tag, buf, len, &h, j->msg, sizeof j->msg);
    if (rc == 0 && (rc = ops->wait(h, j->ds->timeout, j->msg, sizeof j->msg)) == 1)
        fatal(j->d, "rank %d took no message for %g s (stopped or dead?)", dest, j->ds->timeout);
    if (rc != 0)
        fatal(j->d, "sending to rank %d failed: %s", dest, j->msg);
}

/* Waits up to timeout seconds for a message: 1 with its sender, tag and length, 0 when none came. */
static int next_message(Job *j, double timeout, int *from, int *tag, size_t *len)
{
    int rc = j->d->ops->probe(timeout, from, tag, len, j->msg, sizeof j->msg);
    if (rc < 0)
        fatal(j->d, "waiting for a message failed: %s", j->msg);
    return rc == 0;
}

/* Receives the message next_message announced into buf (cap bytes; a longer message is an error). */
static void receive(Job *j, int from, int tag, size_t len, void *buf, size_t cap)
{
    if (len > cap)
        fatal(j->d, "rank %d sent a message of %zu bytes where at most %zu were expected", from, len, cap);
    int rc = j->d->ops->recv(from, tag, buf, len, j->ds->timeout, j->msg, sizeof j->msg);
    if (rc == 1)
        fatal(j->d, "a message from rank %d did not arrive in %g s", from, j->ds->timeout);
    if (rc != 0)
        fatal(j->d, "receiving from rank %d failed: %s", from, j->msg);
}

/* Block b's pixels in full-image coordinates. */
static void block_region(const Job *j, int b, int region[4])
{
    int bs = j->ds->block;
    region[0] = j->fb->x + (b % j->nbx) * bs;
    region[1] = j->fb->y + (b / j->nbx) * bs;
    region[2] = region[0] + bs < j->fb->x + j->fb->width ? region[0] + bs : j->fb->x + j->fb->width;
    region[3] = region[1] + bs < j->fb->y + j->fb->height ? region[1] + bs : j->fb->y + j->fb->height;
}

/* Renders rows [slice * SLICE, + SLICE) of block b; 1 when that was its last row. */
static int render_slice(Job *j, int b, int slice, Progress *prog)
{
    int block[4], region[4];
    block_region(j, b, block);
    memcpy(region, block, sizeof region);
    region[1] = block[1] + slice * SLICE;
    region[3] = region[1] + SLICE < block[3] ? region[1] + SLICE : block[3];
    GError err;
    if (renderer_region(j->r, region, prog, &err) != G_OK) {
        if (j->d->rank == 0)
            fatal(j->d, "%s", err.message);
        send_now(j, 0, TAG_FAIL, err.message, strlen(err.message) + 1); /* j->buf may still be on its way */
        int from, tag;
        size_t len;
        next_message(j, j->ds->timeout, &from, &tag, &len); /* rank 0 ends the job meanwhile */
        fatal(j->d, "%s", err.message);
    }
    return region[3] == block[3];
}

/* Rank 0: every rank's HELLO. G_OK when all loaded the same scene; else the failures, in err. */
static int gather_hellos(Job *j, int load_status, const char *load_msg, uint64_t digest, GError *err)
{
    Dist *d = j->d;
    char report[2048] = "";
    size_t used = 0;
    int bad = load_status != G_OK;
    if (bad)
        used += (size_t)snprintf(report, sizeof report, "%s", load_msg);
    int *seen = gmem_calloc((size_t)d->size, sizeof(int));
    if (!seen)
        fatal(d, "out of memory");
    for (int got = 1; got < d->size; got++) {
        int from, tag;
        size_t len;
        if (!next_message(j, j->ds->timeout, &from, &tag, &len)) {
            int n = 0;
            for (int k = 1; k < d->size; k++)
                n += !seen[k];
            char missing[256] = "";
            for (int k = 1, u = 0; k < d->size && u < (int)sizeof missing - 16; k++)
                if (!seen[k])
                    u += snprintf(missing + u, sizeof missing - (size_t)u, "%s%d", u ? ", " : "", k);
            fatal(d, "%d rank%s (%s) did not report within %g s of start (stopped, dead or still loading?)", n,
                  n > 1 ? "s" : "", missing, j->ds->timeout);
        }
        Hello h;
        if (tag != TAG_HELLO || len != sizeof h)
            fatal(d, "rank %d sent an unexpected message (tag %d) before reporting its scene", from, tag);
        receive(j, from, tag, len, &h, sizeof h);
        seen[from] = 1;
        h.message[sizeof h.message - 1] = 0;
        const char *why = h.status != G_OK ? h.message
                          : load_status == G_OK && h.digest != digest
                              ? "it was started with other arguments than rank 0 (scene, colour model, size or "
                                "render options): every rank needs the same command line"
                              : NULL;
        if (why) {
            bad = 1;
            if (used < sizeof report)
                used += (size_t)snprintf(report + used, sizeof report - used, "%srank %d: %s", used ? "\n  " : "",
                                         from, why);
        }
    }
    gmem_free(seen);
    if (!bad)
        return G_OK;
    int32_t quit = WORK_QUIT;
    for (int k = 1; k < d->size; k++)
        send_now(j, k, TAG_WORK, &quit, sizeof quit);
    return gerror_set(err, load_status != G_OK ? load_status : G_ERR_IO, "%s", report);
}

/* Rank 0's part after the HELLOs: hands out, renders, gathers. */
static void lead(Job *j, RenderStats *st, int quiet)
{
    Dist *d = j->d;
    int n = j->nblocks, next = 0, done = 0;
    int *held = gmem_calloc((size_t)d->size, sizeof(int));        /* blocks handed to each rank, not yet back */
    double *heard = gmem_calloc((size_t)d->size, sizeof(double)); /* when each rank last sent something */
    if (!held || !heard)
        fatal(d, "out of memory");
    Progress prog;
    progress_start(&prog, (long)j->fb->width * j->fb->height, quiet);
    double t0 = now_seconds();
    for (int k = 1; k < d->size; k++) {
        heard[k] = t0;
        for (int c = 0; c < CREDIT && next < n; c++, held[k]++) {
            int32_t b = j->order[next++];
            send_now(j, k, TAG_WORK, &b, sizeof b);
        }
    }
    int mine = -1, slice = 0;
    while (done < n) {
        int from, tag;
        size_t len;
        int idle = mine < 0 && (j->ds->dedicated || next >= n);
        while (next_message(j, idle ? 0.05 : 0.0, &from, &tag, &len)) {
            heard[from] = now_seconds();
            if (tag == TAG_FAIL) {
                receive(j, from, tag, len, j->buf, j->buf_cap);
                j->buf[j->buf_cap - 1] = 0;
                fatal(d, "rank %d: %s", from, (char *)j->buf);
            }
            if (tag != TAG_RESULT || held[from] <= 0 || len < sizeof(int32_t))
                fatal(d, "rank %d sent an unexpected message (tag %d, %zu bytes)", from, tag, len);
            receive(j, from, tag, len, j->buf, j->buf_cap);
            int32_t b;
            memcpy(&b, j->buf, sizeof b);
            int region[4];
            if (b < 0 || b >= n)
                fatal(d, "rank %d sent block %d of %d", from, (int)b, n);
            block_region(j, b, region);
            if (len != sizeof(int64_t) + framebuffer_region_bytes(j->fb, region))
                fatal(d, "rank %d sent %zu bytes for block %d", from, len, (int)b);
            framebuffer_unpack(j->fb, region, j->buf + sizeof(int64_t));
            progress_add(&prog, (long)(region[2] - region[0]) * (region[3] - region[1]));
            done++;
            held[from]--;
            if (next < n) {
                int32_t nb = j->order[next++];
                send_now(j, from, TAG_WORK, &nb, sizeof nb);
                held[from]++;
            }
            idle = 0;
        }
        double now = now_seconds();
        for (int k = 1; k < d->size; k++)
            if (held[k] > 0 && now - heard[k] > j->ds->timeout)
                fatal(d, "rank %d sent nothing for %g s while it held %d block%s (stopped or dead?)", k,
                      j->ds->timeout, held[k], held[k] > 1 ? "s" : "");
        if (mine < 0 && !j->ds->dedicated && next < n) {
            mine = j->order[next++];
            slice = 0;
        }
        if (mine >= 0 && render_slice(j, mine, slice++, &prog)) {
            mine = -1;
            done++;
        }
    }
    int32_t stop = WORK_STOP;
    for (int k = 1; k < d->size; k++)
        send_now(j, k, TAG_WORK, &stop, sizeof stop);
    renderer_stats(j->r, st);
    for (int got = 1; got < d->size; got++) { /* every rank's totals */
        int from, tag;
        size_t len;
        Totals t;
        if (!next_message(j, j->ds->timeout, &from, &tag, &len))
            fatal(d, "a rank did not send its totals within %g s", j->ds->timeout);
        if (tag != TAG_STATS || len != sizeof t)
            fatal(d, "rank %d sent an unexpected message (tag %d) instead of its totals", from, tag);
        receive(j, from, tag, len, &t, sizeof t);
        st->rays += t.rays;
        st->nonfinite += t.nonfinite;
        st->capped += t.capped;
    }
    progress_finish(&prog);
    st->seconds = now_seconds() - t0;
    gmem_free(held);
    gmem_free(heard);
}

/* Appends block b to the ring of blocks a rank holds. */
static void hold(Job *j, int *ring, int *count, int *first, int b)
{
    if (*count >= 2 * CREDIT)
        fatal(j->d, "rank 0 handed out more blocks than agreed");
    ring[(*first + *count) % (2 * CREDIT)] = b;
    (*count)++;
}

/* A rank other than 0 after its HELLO: renders the blocks it is given until STOP (returns 1) or QUIT (0). */
static int follow(Job *j)
{
    Dist *d = j->d;
    const GtMpiOps *ops = d->ops;
    int ring[2 * CREDIT], count = 0, first = 0, stopping = 0, cur = -1, slice = 0, pending = -1;
    for (;;) {
        int from, tag;
        size_t len;
        int idle = cur < 0 && count == 0;
        if (idle && stopping)
            break;
        while (next_message(j, idle ? 2 * j->ds->timeout : 0.0, &from, &tag, &len)) {
            int32_t b;
            if (tag != TAG_WORK || len != sizeof b)
                fatal(d, "rank %d sent an unexpected message (tag %d)", from, tag);
            receive(j, from, tag, len, &b, sizeof b);
            if (b == WORK_QUIT)
                return 0;
            if (b == WORK_STOP)
                stopping = 1;
            else if (b >= 0 && b < j->nblocks)
                hold(j, ring, &count, &first, b);
            else
                fatal(d, "rank 0 sent block %d of %d", (int)b, j->nblocks);
            idle = 0;
        }
        if (idle && !stopping)
            fatal(d, "no word from rank 0 for %g s (stopped or dead?)", 2 * j->ds->timeout);
        if (pending >= 0 && ops->wait(pending, 0.0, j->msg, sizeof j->msg) == 0)
            pending = -1; /* moves the result along while the next block renders */
        if (cur < 0 && count > 0) {
            cur = ring[first];
            first = (first + 1) % (2 * CREDIT);
            count--;
            slice = 0;
        }
        if (cur >= 0 && render_slice(j, cur, slice++, NULL)) {
            int rc = pending >= 0 ? ops->wait(pending, j->ds->timeout, j->msg, sizeof j->msg) : 0;
            if (rc != 0)
                fatal(d, rc == 1 ? "rank 0 took no result for %g s (stopped or dead?)" : "sending failed: %g %s",
                      j->ds->timeout, rc == 1 ? "" : j->msg);
            int region[4];
            block_region(j, cur, region);
            int32_t b = cur;
            memcpy(j->buf, &b, sizeof b);
            framebuffer_pack(j->fb, region, j->buf + sizeof(int64_t));
            size_t n = sizeof(int64_t) + framebuffer_region_bytes(j->fb, region);
            if (ops->isend(0, TAG_RESULT, j->buf, n, &pending, j->msg, sizeof j->msg) != 0)
                fatal(d, "sending a block failed: %s", j->msg);
            cur = -1;
        }
    }
    if (pending >= 0 && ops->wait(pending, j->ds->timeout, j->msg, sizeof j->msg) != 0)
        fatal(d, "rank 0 took no result for %g s (stopped or dead?)", j->ds->timeout);
    RenderStats rs;
    renderer_stats(j->r, &rs);
    Totals t = {rs.rays, rs.nonfinite, rs.capped};
    send_now(j, 0, TAG_STATS, &t, sizeof t);
    return 1;
}

int dist_render(Dist *d, const DistSettings *ds, int load_status, const char *load_msg, uint64_t digest,
                const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err)
{
    memset(st, 0, sizeof *st);
    Job j = {.d = d, .ds = ds, .fb = fb};
    int rc = load_status;
    if (rc == G_OK) /* a renderer that cannot start is this rank's failure to report like a load error */
        rc = renderer_create(&j.r, s, rs, fb, err);
    const char *why = load_status != G_OK ? load_msg : err->message;
    if (d->rank == 0) {
        rc = gather_hellos(&j, rc, why, digest, err);
    } else {
        Hello h;
        memset(&h, 0, sizeof h); /* no stray bytes in the padding */
        h.status = rc;
        h.digest = digest;
        if (rc != G_OK)
            snprintf(h.message, sizeof h.message, "%.*s", (int)sizeof h.message - 1, why);
        send_now(&j, 0, TAG_HELLO, &h, sizeof h);
        if (rc != G_OK) { /* wait for rank 0's QUIT, so that every rank finalises */
            int from, tag;
            size_t len;
            int32_t b;
            if (next_message(&j, 2 * ds->timeout, &from, &tag, &len) && tag == TAG_WORK && len == sizeof b)
                receive(&j, from, tag, len, &b, sizeof b);
            return DIST_QUIT;
        }
    }
    if (rc == G_OK) {
        j.nbx = (fb->width + ds->block - 1) / ds->block;
        j.nblocks = j.nbx * ((fb->height + ds->block - 1) / ds->block);
        j.order = gmem_alloc((size_t)j.nblocks * sizeof(int));
        int first[4] = {fb->x, fb->y, fb->x + ds->block, fb->y + ds->block}; /* the largest block */
        j.buf_cap = sizeof(int64_t) + framebuffer_region_bytes(fb, first);
        j.buf_cap = j.buf_cap < 1024 ? 1024 : j.buf_cap;
        j.buf = gmem_alloc(j.buf_cap);
        if (!j.order || !j.buf)
            fatal(d, "out of memory for the block list");
        render_tile_order(j.nblocks, j.order);
        if (d->rank == 0)
            lead(&j, st, rs->quiet);
        else
            rc = follow(&j) ? DIST_SENT : DIST_QUIT;
        gmem_free(j.order);
        gmem_free(j.buf);
    }
    if (d->rank == 0) /* the image may now be written */
        sigaction(SIGTERM, &d->old_term, NULL);
    renderer_destroy(j.r);
    if (d->rank != 0 || rc != G_OK)
        framebuffer_free(fb);
    return rc;
}
