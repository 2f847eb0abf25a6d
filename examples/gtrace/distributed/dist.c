/* dist.c - the distributed render (dist.h). The image (or its crop) is cut into blocks of DistSettings.block
 * pixels, taken in render_tile_order's shuffled order. Rank 0 keeps every other rank two blocks ahead (one to
 * render, one waiting), so a rank never idles while its result travels, and sends the next block whenever a
 * result arrives: a fast rank simply asks more often. Rank 0 renders blocks too, one row of 16-pixel tiles at a
 * time, looking at its messages between rows. A block's pixels travel packed by framebuffer_pack, so every
 * per-pixel array of the framebuffer comes along. Every wait is bounded by the timeout (the other ranks wait twice
 * as long for rank 0, which may itself be waiting a timeout for someone else: so rank 0, which sees the whole
 * job, names the culprit); a rank that exceeds it is named, and the job ends: every failure of the job returns its
 * message up to dist_render, which marks the job failed, and dist_finish ends every rank (MPI_Abort) once the
 * caller has printed it.
 *
 * The particle integrators (sppm, light) render the whole image at once and share each batch of particle paths
 * instead (PhotonShare, photons.h; dist_particles.c): every rank traces its range of the batch's paths and sends
 * them to rank 0 (PHOTONS), which completes the batch and sends it back whole (sppm: every rank gathers it at the
 * visible points of its band of rows) or only says GO (light: rank 0 alone sums the contributions); at the end
 * every other rank sends its totals and its band of rows (BAND). The batches are cut as in a single process and
 * every sum is made in a single process's order, so the image is the same bits for any number of ranks.
 *
 * Messages (native layout: every rank runs the same gtrace build): HELLO (status, digest, message) from each
 * rank once its scene is loaded; WORK (a block index, or STOP, or QUIT) from rank 0; RESULT (the block index,
 * then its packed pixels), FAIL (a message) and STATS (rays, non-finite, capped) to rank 0; PHOTONS (a range of a
 * batch's paths, photon_batch_pack) both ways, GO from rank 0 and BAND (totals, then packed pixels) to rank 0. */
#include "dist.h"
#include "dist_job.h"
#include "integrators/light.h"
#include "integrators/sppm.h"
#include "mpi_load.h"

#include <generic/memory.h>

#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

/* Rank 0's SIGTERM from MPI's start to the end of dist_render (to dist_finish when the job failed): the launcher
 * ends the job because another rank died. Says so (the launcher's own message names the rank) and exits; no image
 * has been written. */
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
    if (d->failed) {
        d->ops->abort(1);
        abort(); /* MPI_Abort does not return */
    }
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
               rs->crop[0], rs->crop[1], rs->crop[2], rs->crop[3], rs->waves, rs->sampler, rs->sppm_passes,
               rs->no_equiangular};
    h = fnv(h, v, sizeof v);
    double f[] = {rs->cutoff, (double)rs->sppm_photons, rs->sppm_radius, rs->sppm_alpha};
    return fnv(h, f, sizeof f);
}

int job_fail(Job *j, const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    j->d->failed = 1;
    if (j->d->rank == 0)
        return gerror_set(j->err, G_ERR_IO, "%s; the job is ended and no image written", text);
    return gerror_set(j->err, G_ERR_IO, "rank %d: %s; the job is ended", j->d->rank, text);
}

int job_send(Job *j, int dest, int tag, const void *buf, size_t len)
{
    const GtMpiOps *ops = j->d->ops;
    int h, rc = ops->isend(dest, tag, buf, len, &h, j->msg, sizeof j->msg);
    if (rc == 0 && (rc = ops->wait(h, j->ds->timeout, j->msg, sizeof j->msg)) == 1)
        return job_fail(j, "rank %d took no message for %g s (stopped or dead?)", dest, j->ds->timeout);
    if (rc != 0)
        return job_fail(j, "sending to rank %d failed: %s", dest, j->msg);
    return G_OK;
}

int job_next_message(Job *j, double timeout, int *from, int *tag, size_t *len)
{
    int rc = j->d->ops->probe(timeout, from, tag, len, j->msg, sizeof j->msg);
    if (rc < 0)
        return job_fail(j, "waiting for a message failed: %s", j->msg);
    return rc == 0;
}

int job_receive(Job *j, int from, int tag, size_t len, void *buf, size_t cap)
{
    if (len > cap)
        return job_fail(j, "rank %d sent a message of %zu bytes where at most %zu were expected", from, len, cap);
    int rc = j->d->ops->recv(from, tag, buf, len, j->ds->timeout, j->msg, sizeof j->msg);
    if (rc == 1)
        return job_fail(j, "a message from rank %d did not arrive in %g s", from, j->ds->timeout);
    if (rc != 0)
        return job_fail(j, "receiving from rank %d failed: %s", from, j->msg);
    return G_OK;
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

/* Renders rows [slice * SLICE, + SLICE) of block b: 1 when that was its last row, 0 when not, or job_fail's
 * status (another rank than 0 first tells rank 0, which ends the job, and waits for it). */
static int render_slice(Job *j, int b, int slice, Progress *prog)
{
    int block[4], region[4];
    block_region(j, b, block);
    memcpy(region, block, sizeof region);
    region[1] = block[1] + slice * SLICE;
    region[3] = region[1] + SLICE < block[3] ? region[1] + SLICE : block[3];
    GError err;
    if (renderer_region(j->r, region, prog, &err) != G_OK) {
        if (j->d->rank != 0) { /* tells rank 0 (j->buf may still be on its way), which ends the job meanwhile */
            int from, tag, rc;
            size_t len;
            if ((rc = job_send(j, 0, TAG_FAIL, err.message, strlen(err.message) + 1)) < 0 ||
                (rc = job_next_message(j, j->ds->timeout, &from, &tag, &len)) < 0)
                return rc;
        }
        return job_fail(j, "%s", err.message);
    }
    return region[3] == block[3];
}

/* Rank 0: every rank's HELLO. G_OK when all loaded the same scene; else the failures in j->err (every other rank
 * told to quit), or job_fail's status. */
static int gather_hellos(Job *j, int load_status, const char *load_msg, uint64_t digest)
{
    Dist *d = j->d;
    char report[2048] = "";
    size_t used = 0;
    int bad = load_status != G_OK, rc = G_OK;
    if (bad)
        used += (size_t)snprintf(report, sizeof report, "%s", load_msg);
    int *seen = gmem_calloc((size_t)d->size, sizeof(int));
    if (!seen)
        return job_fail(j, "out of memory");
    for (int got = 1; got < d->size && rc == G_OK; got++) {
        int from, tag;
        size_t len;
        Hello h;
        int heard = job_next_message(j, j->ds->timeout, &from, &tag, &len);
        if (heard == 0) {
            int n = 0;
            for (int k = 1; k < d->size; k++)
                n += !seen[k];
            char missing[256] = "";
            for (int k = 1, u = 0; k < d->size && u < (int)sizeof missing - 16; k++)
                if (!seen[k])
                    u += snprintf(missing + u, sizeof missing - (size_t)u, "%s%d", u ? ", " : "", k);
            rc = job_fail(j, "%d rank%s (%s) did not report within %g s of start (stopped, dead or still loading?)",
                          n, n > 1 ? "s" : "", missing, j->ds->timeout);
        } else if (heard < 0) {
            rc = heard;
        } else if (tag != TAG_HELLO || len != sizeof h) {
            rc = job_fail(j, "rank %d sent an unexpected message (tag %d) before reporting its scene", from, tag);
        } else if ((rc = job_receive(j, from, tag, len, &h, sizeof h)) == G_OK) {
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
                    used += (size_t)snprintf(report + used, sizeof report - used, "%srank %d: %s",
                                             used ? "\n  " : "", from, why);
            }
        }
    }
    gmem_free(seen);
    if (rc < 0 || !bad)
        return rc;
    int32_t quit = WORK_QUIT;
    for (int k = 1; k < d->size; k++)
        if ((rc = job_send(j, k, TAG_WORK, &quit, sizeof quit)) < 0)
            return rc;
    return gerror_set(j->err, load_status != G_OK ? load_status : G_ERR_IO, "%s", report);
}

/* Rank 0's results and failures that have come in, and a new block for each rank that sent one back (waiting up
 * to timeout seconds for the first message). G_OK or job_fail's status. */
static int take_results(Job *j, double timeout, int *held, double *heard, int *next, int *done, Progress *prog)
{
    int from, tag, rc;
    size_t len;
    while ((rc = job_next_message(j, timeout, &from, &tag, &len)) == 1) {
        timeout = 0.0;
        heard[from] = now_seconds();
        if (tag == TAG_FAIL) {
            if ((rc = job_receive(j, from, tag, len, j->buf, j->buf_cap)) < 0)
                return rc;
            j->buf[j->buf_cap - 1] = 0;
            return job_fail(j, "rank %d: %s", from, (char *)j->buf);
        }
        if (tag != TAG_RESULT || held[from] <= 0 || len < sizeof(int32_t))
            return job_fail(j, "rank %d sent an unexpected message (tag %d, %zu bytes)", from, tag, len);
        if ((rc = job_receive(j, from, tag, len, j->buf, j->buf_cap)) < 0)
            return rc;
        int32_t b;
        memcpy(&b, j->buf, sizeof b);
        int region[4];
        if (b < 0 || b >= j->nblocks)
            return job_fail(j, "rank %d sent block %d of %d", from, (int)b, j->nblocks);
        block_region(j, b, region);
        if (len != sizeof(int64_t) + framebuffer_region_bytes(j->fb, region))
            return job_fail(j, "rank %d sent %zu bytes for block %d", from, len, (int)b);
        framebuffer_unpack(j->fb, region, j->buf + sizeof(int64_t));
        progress_add(prog, (long)(region[2] - region[0]) * (region[3] - region[1]));
        (*done)++;
        held[from]--;
        if (*next < j->nblocks) {
            int32_t nb = j->order[(*next)++];
            if ((rc = job_send(j, from, TAG_WORK, &nb, sizeof nb)) < 0)
                return rc;
            held[from]++;
        }
    }
    return rc < 0 ? rc : G_OK;
}

/* Rank 0 at the end: every other rank's totals added to st. G_OK or job_fail's status. */
static int gather_totals(Job *j, RenderStats *st)
{
    for (int got = 1; got < j->d->size; got++) {
        int from, tag, rc;
        size_t len;
        Totals t;
        if ((rc = job_next_message(j, j->ds->timeout, &from, &tag, &len)) <= 0)
            return rc < 0 ? rc : job_fail(j, "a rank did not send its totals within %g s", j->ds->timeout);
        if (tag != TAG_STATS || len != sizeof t)
            return job_fail(j, "rank %d sent an unexpected message (tag %d) instead of its totals", from, tag);
        if ((rc = job_receive(j, from, tag, len, &t, sizeof t)) < 0)
            return rc;
        st->rays += t.rays;
        st->nonfinite += t.nonfinite;
        st->capped += t.capped;
    }
    return G_OK;
}

/* Rank 0's part after the HELLOs: hands out, renders, gathers. G_OK or job_fail's status. */
static int lead(Job *j, RenderStats *st, int quiet)
{
    Dist *d = j->d;
    int n = j->nblocks, next = 0, done = 0, rc = G_OK;
    int *held = gmem_calloc((size_t)d->size, sizeof(int));        /* blocks handed to each rank, not yet back */
    double *heard = gmem_calloc((size_t)d->size, sizeof(double)); /* when each rank last sent something */
    if (!held || !heard) {
        gmem_free(held);
        gmem_free(heard);
        return job_fail(j, "out of memory");
    }
    Progress prog;
    progress_start(&prog, (long)j->fb->width * j->fb->height, quiet);
    double t0 = now_seconds();
    for (int k = 1; k < d->size && rc == G_OK; k++) {
        heard[k] = t0;
        for (int c = 0; c < CREDIT && next < n && rc == G_OK; c++, held[k]++) {
            int32_t b = j->order[next++];
            rc = job_send(j, k, TAG_WORK, &b, sizeof b);
        }
    }
    int mine = -1, slice = 0;
    while (rc == G_OK && done < n) {
        int idle = mine < 0 && (j->ds->dedicated || next >= n);
        if ((rc = take_results(j, idle ? 0.05 : 0.0, held, heard, &next, &done, &prog)) < 0)
            break;
        double now = now_seconds();
        for (int k = 1; k < d->size && rc == G_OK; k++)
            if (held[k] > 0 && now - heard[k] > j->ds->timeout)
                rc = job_fail(j, "rank %d sent nothing for %g s while it held %d block%s (stopped or dead?)", k,
                              j->ds->timeout, held[k], held[k] > 1 ? "s" : "");
        if (rc == G_OK && mine < 0 && !j->ds->dedicated && next < n) {
            mine = j->order[next++];
            slice = 0;
        }
        int last = rc == G_OK && mine >= 0 ? render_slice(j, mine, slice++, &prog) : 0;
        if (last < 0)
            rc = last;
        else if (last) {
            mine = -1;
            done++;
        }
    }
    int32_t stop = WORK_STOP;
    for (int k = 1; k < d->size && rc == G_OK; k++)
        rc = job_send(j, k, TAG_WORK, &stop, sizeof stop);
    if (rc == G_OK) {
        renderer_stats(j->r, st);
        rc = gather_totals(j, st);
    }
    progress_finish(&prog);
    st->seconds = now_seconds() - t0;
    gmem_free(held);
    gmem_free(heard);
    return rc;
}

/* Appends block b to the ring of blocks a rank holds. G_OK or job_fail's status. */
static int hold(Job *j, int *ring, int *count, int *first, int b)
{
    if (*count >= 2 * CREDIT)
        return job_fail(j, "rank 0 handed out more blocks than agreed");
    ring[(*first + *count) % (2 * CREDIT)] = b;
    (*count)++;
    return G_OK;
}

/* A rank other than 0 after its HELLO: renders the blocks it is given until STOP (returns 1) or QUIT (0); or
 * job_fail's status. */
static int follow(Job *j)
{
    Dist *d = j->d;
    const GtMpiOps *ops = d->ops;
    int ring[2 * CREDIT], count = 0, first = 0, stopping = 0, cur = -1, slice = 0, pending = -1, rc;
    for (;;) {
        int from, tag;
        size_t len;
        int idle = cur < 0 && count == 0;
        if (idle && stopping)
            break;
        while ((rc = job_next_message(j, idle ? 2 * j->ds->timeout : 0.0, &from, &tag, &len)) == 1) {
            int32_t b;
            if (tag != TAG_WORK || len != sizeof b)
                return job_fail(j, "rank %d sent an unexpected message (tag %d)", from, tag);
            if ((rc = job_receive(j, from, tag, len, &b, sizeof b)) < 0)
                return rc;
            if (b == WORK_QUIT)
                return 0;
            if (b == WORK_STOP)
                stopping = 1;
            else if (b < 0 || b >= j->nblocks)
                return job_fail(j, "rank 0 sent block %d of %d", (int)b, j->nblocks);
            else if ((rc = hold(j, ring, &count, &first, b)) < 0)
                return rc;
            idle = 0;
        }
        if (rc < 0)
            return rc;
        if (idle && !stopping)
            return job_fail(j, "no word from rank 0 for %g s (stopped or dead?)", 2 * j->ds->timeout);
        if (pending >= 0 && ops->wait(pending, 0.0, j->msg, sizeof j->msg) == 0)
            pending = -1; /* moves the result along while the next block renders */
        if (cur < 0 && count > 0) {
            cur = ring[first];
            first = (first + 1) % (2 * CREDIT);
            count--;
            slice = 0;
        }
        int last = cur >= 0 ? render_slice(j, cur, slice++, NULL) : 0;
        if (last < 0)
            return last;
        if (last) {
            int sent = pending >= 0 ? ops->wait(pending, j->ds->timeout, j->msg, sizeof j->msg) : 0;
            if (sent == 1)
                return job_fail(j, "rank 0 took no result for %g s (stopped or dead?)", j->ds->timeout);
            if (sent != 0)
                return job_fail(j, "sending failed: %s", j->msg);
            int region[4];
            block_region(j, cur, region);
            int32_t b = cur;
            memcpy(j->buf, &b, sizeof b);
            framebuffer_pack(j->fb, region, j->buf + sizeof(int64_t));
            size_t n = sizeof(int64_t) + framebuffer_region_bytes(j->fb, region);
            if (ops->isend(0, TAG_RESULT, j->buf, n, &pending, j->msg, sizeof j->msg) != 0)
                return job_fail(j, "sending a block failed: %s", j->msg);
            cur = -1;
        }
    }
    if (pending >= 0 && ops->wait(pending, j->ds->timeout, j->msg, sizeof j->msg) != 0)
        return job_fail(j, "rank 0 took no result for %g s (stopped or dead?)", j->ds->timeout);
    RenderStats rs;
    renderer_stats(j->r, &rs);
    Totals t = {rs.rays, rs.nonfinite, rs.capped};
    return (rc = job_send(j, 0, TAG_STATS, &t, sizeof t)) < 0 ? rc : 1;
}

/* Another rank than 0 that could not load the scene or start its renderer: reports it in its HELLO and waits for
 * rank 0's QUIT, so that every rank finalises. DIST_QUIT or job_fail's status. */
static int quit_after_hello(Job *j, Hello *h)
{
    int from, tag, rc;
    size_t len;
    int32_t b;
    if ((rc = job_send(j, 0, TAG_HELLO, h, sizeof *h)) < 0 ||
        (rc = job_next_message(j, 2 * j->ds->timeout, &from, &tag, &len)) < 0)
        return rc;
    if (rc == 1 && tag == TAG_WORK && len == sizeof b && (rc = job_receive(j, from, tag, len, &b, sizeof b)) < 0)
        return rc;
    return DIST_QUIT;
}

int dist_render(Dist *d, const DistSettings *ds, int load_status, const char *load_msg, uint64_t digest,
                const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err)
{
    memset(st, 0, sizeof *st);
    Job j = {.d = d, .ds = ds, .err = err, .fb = fb};
    int rc = load_status;
    int particle = rc == G_OK && (rs->integrator == RENDER_SPPM || rs->integrator == RENDER_LIGHT);
    if (particle) /* what the integrator would refuse is this rank's failure to report like a load error */
        rc = rs->integrator == RENDER_SPPM ? sppm_check(rs, err) : light_check(s, rs, err);
    else if (rc == G_OK) /* so is a renderer that cannot start */
        rc = renderer_create(&j.r, s, rs, fb, err);
    const char *why = load_status != G_OK ? load_msg : err->message;
    if (d->rank == 0) {
        rc = gather_hellos(&j, rc, why, digest);
    } else {
        Hello h;
        memset(&h, 0, sizeof h); /* no stray bytes in the padding */
        h.status = rc;
        h.digest = digest;
        if (rc != G_OK) {
            snprintf(h.message, sizeof h.message, "%.*s", (int)sizeof h.message - 1, why);
            return quit_after_hello(&j, &h);
        }
        rc = job_send(&j, 0, TAG_HELLO, &h, sizeof h);
    }
    if (rc == G_OK && particle) {
        rc = job_particles(&j, s, rs, st);
        if (d->rank != 0 && rc >= 0)
            rc = DIST_SENT;
        gmem_free(j.pbuf);
    } else if (rc == G_OK) {
        j.nbx = (fb->width + ds->block - 1) / ds->block;
        j.nblocks = j.nbx * ((fb->height + ds->block - 1) / ds->block);
        j.order = gmem_alloc((size_t)j.nblocks * sizeof(int));
        int first[4] = {fb->x, fb->y, fb->x + ds->block, fb->y + ds->block}; /* the largest block */
        j.buf_cap = sizeof(int64_t) + framebuffer_region_bytes(fb, first);
        j.buf_cap = j.buf_cap < 1024 ? 1024 : j.buf_cap;
        j.buf = gmem_alloc(j.buf_cap);
        if (!j.order || !j.buf)
            rc = job_fail(&j, "out of memory for the block list");
        else
            render_tile_order(j.nblocks, j.order);
        if (rc == G_OK && d->rank == 0)
            rc = lead(&j, st, rs->quiet);
        else if (rc == G_OK && (rc = follow(&j)) >= 0)
            rc = rc ? DIST_SENT : DIST_QUIT;
        gmem_free(j.order);
        gmem_free(j.buf);
    }
    if (d->rank == 0 && !d->failed) /* the image may now be written */
        sigaction(SIGTERM, &d->old_term, NULL);
    renderer_destroy(j.r);
    if (d->rank != 0 || rc != G_OK)
        framebuffer_free(fb);
    return rc;
}
