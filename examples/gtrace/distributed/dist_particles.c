/* dist_particles.c - the particle integrators (sppm, light) across ranks (dist.h): every rank traces its range of
 * each batch's paths and sends them to rank 0 (PHOTONS), which completes the batch and sends it back whole (sppm:
 * every rank gathers it at the visible points of its band of rows) or only says GO (light: rank 0 alone sums the
 * contributions); at the end every other rank sends its totals and its band of rows (BAND). */
#include "dist_job.h"
#include "integrators/light.h"
#include "integrators/sppm.h"

#include <generic/memory.h>

#include <stdio.h>
#include <string.h>

/* j->pbuf holds at least cap bytes. G_OK or job_fail's status. */
static int pbuf_reserve(Job *j, size_t cap)
{
    if (cap <= j->pbuf_cap)
        return G_OK;
    gmem_free(j->pbuf);
    j->pbuf_cap = 0;
    if (!(j->pbuf = gmem_alloc(cap)))
        return job_fail(j, "out of memory for %zu bytes of photons", cap);
    j->pbuf_cap = cap;
    return G_OK;
}

/* Rank 0: the FAIL of a rank, or an unexpected message, as the job's failure. */
static int unexpected(Job *j, int from, int tag, size_t len, const char *what)
{
    int rc;
    if (tag == TAG_FAIL && (rc = pbuf_reserve(j, len + 1)) == G_OK &&
        (rc = job_receive(j, from, tag, len, j->pbuf, j->pbuf_cap)) == G_OK) {
        j->pbuf[len] = 0;
        return job_fail(j, "rank %d: %s", from, (char *)j->pbuf);
    }
    return j->d->failed ? G_ERR_IO : job_fail(j, "rank %d sent an unexpected message (tag %d, %zu bytes) %s", from,
                                              tag, len, what);
}

/* PhotonShare.batch: every rank's range of b's paths to rank 0, and the whole batch (to_all) or a GO back. */
static int share_batch(void *user, PhotonBatch *b, int to_all, GError *err)
{
    (void)err; /* job_fail writes j->err, the render's own */
    Job *j = user;
    Dist *d = j->d;
    int n = b->paths, lo, hi, from, tag, rc;
    size_t len;
    if ((rc = pbuf_reserve(j, photon_batch_pack_bytes(b, j->model, 0, n))) < 0)
        return rc;
    if (d->rank != 0) {
        photon_share_range(n, d->rank, d->size, &lo, &hi);
        if ((rc = job_send(j, 0, TAG_PHOTONS, j->pbuf, photon_batch_pack(b, lo, hi, j->pbuf))) < 0)
            return rc;
        if ((rc = job_next_message(j, 2 * j->ds->timeout, &from, &tag, &len)) <= 0)
            return rc < 0 ? rc : job_fail(j, "no word from rank 0 for %g s (stopped or dead?)", 2 * j->ds->timeout);
        if (tag == TAG_GO && !to_all && len == sizeof(int32_t))
            return job_receive(j, from, tag, len, j->pbuf, j->pbuf_cap);
        if (tag != TAG_PHOTONS || !to_all)
            return job_fail(j, "rank %d sent an unexpected message (tag %d) during a photon batch", from, tag);
        if ((rc = job_receive(j, from, tag, len, j->pbuf, j->pbuf_cap)) < 0)
            return rc;
        if (photon_batch_unpack(b, 0, n, j->pbuf, len) != G_OK)
            return job_fail(j, "rank 0 sent a malformed photon batch (%zu bytes)", len);
        return G_OK;
    }
    for (int got = 1; got < d->size; got++) {
        if ((rc = job_next_message(j, j->ds->timeout, &from, &tag, &len)) <= 0)
            return rc < 0 ? rc : job_fail(j, "a rank sent no photons for %g s (stopped or dead?)", j->ds->timeout);
        if (tag != TAG_PHOTONS)
            return unexpected(j, from, tag, len, "during a photon batch");
        photon_share_range(n, from, d->size, &lo, &hi);
        if ((rc = job_receive(j, from, tag, len, j->pbuf, j->pbuf_cap)) < 0)
            return rc;
        if (photon_batch_unpack(b, lo, hi, j->pbuf, len) != G_OK)
            return job_fail(j, "rank %d sent a malformed photon batch (%zu bytes for paths %d..%d)", from, len, lo, hi);
    }
    int32_t go = 1;
    size_t whole = to_all ? photon_batch_pack(b, 0, n, j->pbuf) : 0;
    for (int k = 1; k < d->size; k++)
        if ((rc = to_all ? job_send(j, k, TAG_PHOTONS, j->pbuf, whole) : job_send(j, k, TAG_GO, &go, sizeof go)) < 0)
            return rc;
    return G_OK;
}

/* Rank `rank`'s band of rows of the image (the rows its sppm visible points cover; light: none but rank 0's, which
 * holds the whole image) as a region. 0 when it is empty. */
static int band_region(const Job *j, const RenderSettings *rs, int rank, int region[4])
{
    int lo = 0, hi = rank == 0 ? j->fb->height : 0;
    if (rs->integrator == RENDER_SPPM)
        photon_share_range(j->fb->height, rank, j->d->size, &lo, &hi);
    region[0] = j->fb->x;
    region[1] = j->fb->y + lo;
    region[2] = j->fb->x + j->fb->width;
    region[3] = j->fb->y + hi;
    return hi > lo;
}

/* Rank 0 after its own render: every other rank's BAND (totals and rows) into fb and st. G_OK or job_fail's
 * status. */
static int gather_bands(Job *j, const RenderSettings *rs, RenderStats *st)
{
    for (int got = 1; got < j->d->size; got++) {
        int from, tag, rc, region[4];
        size_t len;
        if ((rc = job_next_message(j, j->ds->timeout, &from, &tag, &len)) <= 0)
            return rc < 0 ? rc : job_fail(j, "a rank did not send its rows within %g s", j->ds->timeout);
        if (tag != TAG_BAND)
            return unexpected(j, from, tag, len, "instead of its rows");
        size_t pixels = band_region(j, rs, from, region) ? framebuffer_region_bytes(j->fb, region) : 0;
        if (len != sizeof(Totals) + pixels)
            return job_fail(j, "rank %d sent %zu bytes for its rows where %zu were expected", from, len,
                            sizeof(Totals) + pixels);
        if ((rc = pbuf_reserve(j, len)) < 0 || (rc = job_receive(j, from, tag, len, j->pbuf, j->pbuf_cap)) < 0)
            return rc;
        Totals t;
        memcpy(&t, j->pbuf, sizeof t);
        st->rays += t.rays;
        st->nonfinite += t.nonfinite;
        st->capped += t.capped;
        if (pixels)
            framebuffer_unpack(j->fb, region, j->pbuf + sizeof t);
    }
    return G_OK;
}

/* Another rank than 0 after its own render: its totals and band of rows to rank 0. G_OK or job_fail's status. */
static int send_band(Job *j, const RenderSettings *rs, const RenderStats *st)
{
    int region[4], rc;
    size_t pixels = band_region(j, rs, j->d->rank, region) ? framebuffer_region_bytes(j->fb, region) : 0;
    if ((rc = pbuf_reserve(j, sizeof(Totals) + pixels)) < 0)
        return rc;
    Totals t = {st->rays, st->nonfinite, st->capped};
    memcpy(j->pbuf, &t, sizeof t);
    if (pixels)
        framebuffer_pack(j->fb, region, j->pbuf + sizeof t);
    return job_send(j, 0, TAG_BAND, j->pbuf, sizeof t + pixels);
}

int job_particles(Job *j, const Scene *s, const RenderSettings *rs, RenderStats *st)
{
    Dist *d = j->d;
    PhotonShare share = {.rank = d->rank, .size = d->size, .batch = share_batch, .user = j};
    j->model = s->model;
    int rc = rs->integrator == RENDER_SPPM ? sppm_render(s, rs, j->fb, st, &share, j->err)
                                           : light_render(s, rs, j->fb, st, &share, j->err);
    if (rc != G_OK) {
        if (d->failed)
            return rc; /* the job's failure, already in j->err */
        if (d->rank != 0) { /* tells rank 0, which ends the job meanwhile */
            char text[sizeof j->err->message];
            snprintf(text, sizeof text, "%s", j->err->message);
            int from, tag;
            size_t len;
            if ((rc = job_send(j, 0, TAG_FAIL, text, strlen(text) + 1)) < 0 ||
                (rc = job_next_message(j, j->ds->timeout, &from, &tag, &len)) < 0)
                return rc;
            return job_fail(j, "%s", text);
        }
        return job_fail(j, "%s", j->err->message);
    }
    if (d->rank != 0)
        return (rc = send_band(j, rs, st)) < 0 ? rc : 1;
    return gather_bands(j, rs, st);
}
