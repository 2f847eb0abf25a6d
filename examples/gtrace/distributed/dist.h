/* dist.h - rendering one image on the ranks of an MPI job (dist.c): rank 0 hands out blocks of the image on
 * demand, renders some itself, gathers the others and returns the whole image; every rank renders with its
 * OpenMP threads. The pixels equal a single-process render's (each is seeded from its own index). The particle
 * integrators (sppm, light) share each batch of photon paths over the ranks instead of blocks (PhotonShare,
 * integrators/photons.h), summed in a single process's order: their pixels equal a single process's too. */
#ifndef GTRACE_DIST_H
#define GTRACE_DIST_H

#include "render/render.h"

#include <generic/error.h>

#include <stdint.h>

/** Defaults of --mpi-block and --mpi-timeout. */
#define DIST_DEFAULT_BLOCK 64
#define DIST_DEFAULT_TIMEOUT 600.0

/** How the ranks share the work. */
typedef struct DistSettings {
    int block;        /**< blocks are block x block pixels (the unit a rank asks for and sends back; not used by
                           the particle integrators, nor is dedicated) */
    double timeout;   /**< seconds rank 0 waits for another rank (the others wait twice as long for rank 0) before
                           it declares it dead and ends the job */
    int dedicated;    /**< 1: rank 0 only hands out and gathers blocks; 0: it renders blocks too */
} DistSettings;

/** What dist_render returns on a rank other than 0: its part is sent (exit 0), or the job failed elsewhere and
 * rank 0 reported it (exit 1, nothing to print). */
enum { DIST_SENT = 1, DIST_QUIT = 2 };

/** An MPI job as gtrace sees it. */
typedef struct Dist Dist;

/** Loads the MPI module (mpi_load.h) and initialises MPI. G_ERR_IO with the reason when either fails. On rank
 * 0, until dist_render returns (until dist_finish when it failed), a SIGTERM (the launcher ending the job because a
 * rank died) prints that the job was ended before the image was complete and exits with status 1. */
int dist_start(Dist **out, GError *err);

/** This process's rank and the number of ranks. */
int dist_rank(const Dist *d);
int dist_size(const Dist *d);

/** A fingerprint of what decides the pixels (scene file name, colour model, the render settings but the thread
 * count and quietness): ranks started with other arguments are refused rather than merged. */
uint64_t dist_digest(const char *scene_path, const char *model, const RenderSettings *rs);

/** The render, called by every rank once it has loaded the scene (load_status G_OK, s and rs set) or failed to
 * (load_status < 0, load_msg its message). First every rank reports its status to rank 0: if any failed, rank 0
 * returns an error with every failing rank's message and the others DIST_QUIT; so does a rank
 * with another digest (the particle integrators' own checks, sppm_check and light_check, count as the load).
 * Then the blocks (or the photon batches) are rendered. Rank 0 returns G_OK with the whole image (or crop) in fb
 * and the job's totals in st; the others return DIST_SENT once their part is sent. A rank that falls silent for
 * ds->timeout seconds, a failed render or a lost message fails the whole job: G_ERR_IO with the message in err
 * (rank 0: "...; the job is ended and no image written", another: "rank R: ...; the job is ended"), and
 * dist_finish then ends every rank. */
int dist_render(Dist *d, const DistSettings *ds, int load_status, const char *load_msg, uint64_t digest,
                const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err);

/** Ends this rank's part of the job and frees d (NULL: no-op): MPI_Finalize, or, after dist_render failed the job
 * (its message printed by the caller), MPI_Abort of every rank with exit status 1, which does not return. */
void dist_finish(Dist *d);

#endif
