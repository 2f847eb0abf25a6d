/* medium.h - participating media (medium.c at render time, medium_parse.c for the entries): the kind `medium`, its type
 * homogeneous, where a ray is inside one (an object's `interior`, the camera's `atmosphere`), and what the integrators
 * ask of one: transmittance and free-flight sampling with one-sample MIS over the bands, so that a medium whose
 * coefficients differ between the colour model's bands converges in every model. */
#ifndef GTRACE_MEDIUM_H
#define GTRACE_MEDIUM_H

#include "grid.h"
#include "phase.h"

#include <generic/color.h>
#include <generic/error.h>
#include <generic/memory.h>
#include <generic/reader.h>
#include <generic/registry.h>

struct Scene;
struct Media;

/** Largest extinction coefficient accepted (per scene unit, after `scale`): beyond it a medium is a surface. */
#define MEDIUM_MAX_SIGMA 1e9

/** A medium: coefficients in the scene's colour model (vectors, >= 0 in every band), a phase function (borrowed from
 * the library that loaded it). A homogeneous medium has grid NULL; a grid medium's coefficients are per unit of its
 * grid's density (they vary along a ray as the density does). */
typedef struct Medium {
    GColor sigma_a, sigma_s, sigma_t; /**< absorption, scattering, extinction = their sum (scaled) */
    const Phase *phase;
    int bands;                        /**< the model's bands */
    int scatters;                     /**< sigma_s is not black */
    const Grid *grid;                 /**< the density of a grid medium (owned by it), else NULL */
    double sigma_t_max;               /**< grid media: the largest band value of sigma_t (ratio tracking's rate) */
} Medium;

/** The kind `medium`, numbered by media_register (GKIND_MAX before). */
extern GKind gtrace_kind_medium;
/** Registers the kinds `phase` and `medium` (idempotent). */
int media_register_kinds(GError *err);
/** Registers the kinds and their types: phase isotropic and hg, medium homogeneous (idempotent). */
int media_register_types(GError *err);

/** Registers the medium type grid in the kind given (media_register_types calls it; idempotent). */
int media_register_grid(GKind medium_kind, GError *err);
/** For the parse routines of the medium types: reads the value of key when it is one of the parameters every medium
 * has (sigma_a, sigma_s, phase, scale: 1), else reads nothing (0); negative on an error at its position, which
 * names the type. */
int medium_read_param(GReader *r, const char *type, const char *key, Medium *m, double *scale, GError *err);
/** Completes m after its parameters: coefficients not given are black, both are multiplied by scale, sigma_t is
 * their sum, bands and scatters are set; sigma_t out of [0, MEDIUM_MAX_SIGMA] in a band is refused. */
int medium_complete(GReader *r, const char *type, Medium *m, double scale, GError *err);
/** Frees a medium of any type (its colours, its grid) and m itself; NULL is ignored. */
void medium_free(Medium *m);

/** The medium a ray with this stack of materials travels in: the interior of the top material when an object of
 * that material declared one, the scene's atmosphere when the stack is empty or holds only the camera's medium
 * material, else none (NULL). */
const Medium *medium_current(const struct Scene *s, const struct Media *media);

/** Fills the scene's media from its objects' interiors and its atmosphere (set from the camera): the bindings of
 * materials to media, has_media. G_ERR_INVALID (naming the scene) when one material bounds two different media. */
int media_bind_scene(struct Scene *s, const char *name, GError *err);

/** light *= the medium's transmittance exp(-sigma_t d) over d (INFINITY: zero where sigma_t > 0), in place; a
 * temporary from scratch, released before it returns. */
int medium_attenuate(const Medium *m, double d, GColor *light, GScratch *scratch);

/** Free-flight sampling along a ray within (0, tmax) (tmax may be INFINITY): a band is chosen uniformly with
 * u_band and a distance drawn from its exponential with u_dist; the density is the mean of every band's
 * (one-sample MIS with the balance heuristic). Returns 1 for a scattering event at *t, with weight = the
 * transmittance to it times sigma_s over that density; 0 when the ray reaches tmax, with weight = the
 * transmittance over the probability of passing; weight must have storage of the model. A medium that does not
 * scatter draws nothing: 0 with weight = the transmittance to tmax. */
int medium_sample_distance(const Medium *m, double tmax, double u_band, double u_dist, double *t, GColor *weight);

/** The density with which medium_sample_distance draws a scattering event at t > 0 in a homogeneous medium that
 * scatters: the mean over the bands of sigma_t exp(-sigma_t t) (for multiple importance sampling against another
 * strategy for the same distance). */
double medium_distance_pdf(const Medium *m, double t);

/** Free flight through a grid medium along o + t d within (0, tmax) (d a unit vector; tmax may be INFINITY), with
 * the same contract as medium_sample_distance: delta tracking against the grid's majorant bricks in a band chosen
 * uniformly, weighted by one-sample MIS (balance heuristic) over the bands' tracking densities, so that a grid of
 * constant density samples as the homogeneous medium does. A grid that does not scatter: 0 with weight a ratio
 * tracking estimate of the transmittance to tmax. Random numbers from rng; temporaries from scratch. */
int medium_grid_flight(const Medium *m, GVec3 o, GVec3 d, double tmax, Rng *rng, double *t, GColor *weight,
                       GScratch *scratch);

/** light *= the transmittance along o + t d over (0, dist) (dist may be INFINITY): exactly medium_attenuate for a
 * homogeneous medium (no random numbers drawn), an unbiased ratio tracking estimate for a grid medium. */
int medium_transmit(const Medium *m, GVec3 o, GVec3 d, double dist, Rng *rng, GColor *light, GScratch *scratch);

#endif
