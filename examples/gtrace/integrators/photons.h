/* photons.h - particles of light traced from the light sources (photons.c), shared by the particle integrators:
 * the lights chosen by power, one particle path per index (its random numbers seeded by the index alone), the
 * points where it met non-ideal surfaces stored in a batch of fixed size, and a hashed grid over a batch. */
#ifndef GTRACE_PHOTONS_H
#define GTRACE_PHOTONS_H

#include "lights/emissive.h"
#include "lights/emit.h"
#include "lights/light_pick.h"
#include "trace/trace.h"

#include <generic/color.h>
#include <generic/error.h>
#include <generic/memory.h>

#include <stdint.h>

/** Bounces after which Russian roulette may end a particle path. */
#define PHOTON_RR_START 3

/** The lights that send particles, with the probabilities of choosing each (proportional to its power): the scene's
 * light table (light_pick.h), of at least one entry. */
typedef struct PhotonSource {
    LightPick pick;
    EmitBounds bounds; /**< the scene's bounds (pick.bounds), which directional lights' and probes' particles cross */
} PhotonSource;

/** The emitting lights of s, and the glowing geometry of emissive (NULL: none) as one more (light_pick_build);
 * G_ERR_INVALID naming the kinds that do emit when s has nothing that sends particles (or all of it is black),
 * G_ERR_NOMEM. */
int photon_source_init(PhotonSource *src, const Scene *s, const EmissiveSet *emissive, GError *err);
/** Frees the tables; a zeroed source is a no-op. */
void photon_source_free(PhotonSource *src);

/** One stored particle: where it met a non-ideal surface, the direction it came from and its power. */
typedef struct Photon {
    GVec3 p, wi;
    GColor power;
    long pixel; /**< a visitor's use (light.c: the pixel it lights, -1: none) */
} Photon;

/** What a particle path does at a stored surface point instead of storing its power (photon_trace): fills slot
 * (its power and pixel) from the surface point sp (facing, media as trace.h gives them), the direction wi the
 * particle came from and its power; G_OK or a status. */
typedef int (*PhotonVisit)(void *user, TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 wi,
                           const GColor *power, Photon *slot);

/** A batch of particle paths: path i keeps up to per_path stored particles at photons[i * per_path ..], count[i]
 * of them; then a hashed grid (photon_batch_index) over all of them. */
typedef struct PhotonBatch {
    int paths, per_path;
    Photon *photons;
    int *count;
    GScratch *arena; /**< the particles' colours */
    /* the grid: cells of side `cell`, hashed into `buckets` lists */
    double cell;
    int buckets;
    int *bucket_start; /**< buckets + 1 entries */
    int *order;        /**< photon slots, bucket by bucket, each bucket's in slot order */
    int stored;        /**< particles in the grid */
} PhotonBatch;

/** A batch of `paths` paths of at most per_path stored particles each, in model m. */
int photon_batch_init(PhotonBatch *b, const GColorModel *m, int paths, int per_path, GError *err);
/** Frees the batch; a zeroed batch is a no-op. */
void photon_batch_free(PhotonBatch *b);
/** Traces particle path `index` (its random numbers seeded by index alone) into slot `slot` of the batch: the
 * light chosen by power, each bounce drawn by gmaterial_sample from the direction it came from (its power through
 * the material's weight, or through reflection/refraction for a material that re-radiates), dispersion by one
 * wavelength group as the path tracer does it, Russian roulette after PHOTON_RR_START bounces, at most c->max_depth
 * bounces. It keeps at most per_path of the non-ideal surfaces it meets, from the first (direct: 1) or the second
 * (direct: 0: the first one's light is direct light, which SPPM estimates by light samples): their power and
 * position, or what visit (not NULL) makes of them. media0: the camera's medium. */
int photon_trace(TraceCtx *c, const PhotonSource *src, const Media *media0, uint64_t index, PhotonBatch *b, int slot,
                 int direct, PhotonVisit visit, void *user);
/** Builds the batch's grid with cells of side `cell` (> 0): the order of the particles in a bucket does not depend
 * on anything but the slots. */
int photon_batch_index(PhotonBatch *b, double cell, GError *err);
/** The grid cell of a point. */
void photon_cell(const PhotonBatch *b, GVec3 p, int64_t cell[3]);
/** The bucket of a cell. */
int photon_bucket(const PhotonBatch *b, const int64_t cell[3]);

/** How the processes of a distributed job share a particle render (distributed/dist.c fills it; NULL: one
 * process renders alone). Every batch's paths are split into `size` consecutive ranges (photon_share_range), of
 * which this process traces range `rank`; batch() then brings every range's particles into b, in their slots:
 * onto rank 0 only, or (to_all) onto every rank. It returns G_OK, or a status with the job's failure in err (the
 * job is then ended: return it at once). */
typedef struct PhotonShare {
    int rank, size;
    int (*batch)(void *user, PhotonBatch *b, int to_all, GError *err);
    void *user;
} PhotonShare;

/** Part `part` of `parts` of n items: [lo, hi), consecutive parts, sizes differing by at most one. */
void photon_share_range(int n, int part, int parts, int *lo, int *hi);

/** The bytes photon_batch_pack writes for paths [lo, hi) of b in model m (every slot counted at its largest). */
size_t photon_batch_pack_bytes(const PhotonBatch *b, const GColorModel *m, int lo, int hi);
/** Writes paths [lo, hi) of b (each path's count, then its particles: position, direction, pixel, colour kind and
 * values, native layout) into buf; returns the bytes written. */
size_t photon_batch_pack(const PhotonBatch *b, int lo, int hi, unsigned char *buf);
/** The inverse of photon_batch_pack for paths [lo, hi) from len bytes: G_OK, or G_ERR_INVALID when the bytes are
 * not such a pack (a count beyond per_path, a wrong length or colour kind) with b's paths then undefined. */
int photon_batch_unpack(PhotonBatch *b, int lo, int hi, const unsigned char *buf, size_t len);

#endif
