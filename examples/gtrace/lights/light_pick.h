/* light_pick.h - one table that chooses among all the light sources of a scene by power (light_pick.c), for every
 * integrator that draws lights at random: the path tracer's next-event estimation (one light a vertex), the particle
 * integrators' emission and SPPM's direct light. */
#ifndef GTRACE_LIGHT_PICK_H
#define GTRACE_LIGHT_PICK_H

#include "emissive.h"
#include "emit.h"

#include <generic/error.h>

/** The most entries a table may hold for next-event estimation to take a sample of every light source at each vertex
 * rather than one chosen by power (light_pick_nee_every). Measured by `make bench-lights` (point lights over a floor,
 * time to equal RMSE, one thread): sampling every light reaches it in 0.1 to 0.7 of the time of one chosen light from 2
 * to 150 lights, 0.9 at 200, the same at 300, and 4.2 times the time at 1000. */
#ifndef LIGHT_PICK_EVERY_MAX /* a build may set another, e.g. to measure either estimator on any scene */
#define LIGHT_PICK_EVERY_MAX 256
#endif

/** The scene's light sources that send light (emit_supported lights of some power, and the glowing geometry as one
 * entry with its own table), each chosen with a probability proportional to its power through an alias table. */
typedef struct LightPick {
    int n;                       /**< entries (0: the scene has nothing that sends light) */
    const Light **lights;        /**< entry i's light; NULL: the glowing geometry (emissive) */
    double *prob;                /**< entry i's probability (they sum to 1) */
    double *q;                   /**< alias table: keep entry i with probability q[i], else take alias[i] */
    int *alias;
    double *scene_prob;          /**< the probability of the scene's light i (s->lights[i]); 0 when not an entry */
    double emissive_prob;        /**< the probability of the glowing geometry's entry (0: none) */
    const EmissiveSet *emissive; /**< the glowing geometry (NULL: none or no power) */
    int *area;                   /**< the indices in s->lights of the sphere and rectangle lights, in order */
    int narea;
    double *bright;              /**< entry i's colour's brightness as a light (0 for the glowing geometry) */
    int *delta;                  /**< the entries that are delta lights (point, spot, directional, IES), in order */
    int ndelta;
    double delta_prob;           /**< the probability of choosing one of them (the sum of theirs) */
    double *delta_q;             /**< alias table over them by power: choice i of ndelta is entry delta[i] */
    int *delta_alias;
    EmitBounds bounds;           /**< the scene's bounds, which a directional light's or a probe's power uses */
    int every;                   /**< next-event estimation samples every light (n <= LIGHT_PICK_EVERY_MAX) */
} LightPick;

/** Builds the table of s and its glowing geometry e (NULL: none): every light emit_supported accepts whose emit_power
 * is positive and finite, and e when emissive_power(e) is; a table of no entries when there is none (not an error).
 * G_ERR_NOMEM (with err) when the tables cannot be had. */
int light_pick_build(LightPick *lp, const Scene *s, const EmissiveSet *e, GError *err);
/** Frees the tables; a zeroed table is a no-op. */
void light_pick_free(LightPick *lp);
/** Chooses an entry with one uniform number u in [0, 1): its index (-1 when the table has no entry), its probability
 * into *prob, and into *u_rest (may be NULL) a number uniform in [0, 1) and independent of the choice, from what is
 * left of u (u itself when the table has one entry). Constant time. */
int light_pick_sample(const LightPick *lp, double u, double *prob, double *u_rest);
/** The probability that light_pick_sample chooses the scene's light i (s->lights[i]): 0 when it is not an entry. */
double light_pick_pmf(const LightPick *lp, int i);
/** A delta light's entry drawn by power among the delta lights only (lp->ndelta >= 1) with one uniform number u: the
 * choice among them that light_pick_sample makes once it has chosen a delta light. */
int light_pick_delta(const LightPick *lp, double u);
/** 1 when next-event estimation takes one sample of every light source of the scene (and of the glowing geometry) at
 * each vertex, the table holding at most LIGHT_PICK_EVERY_MAX entries; 0 when it takes one chosen by the table. */
int light_pick_nee_every(const LightPick *lp);
/** The probability with which next-event estimation samples the scene's light i at a vertex: 1 when it samples every
 * light (light_pick_nee_every), else light_pick_pmf. */
double light_pick_nee_pmf(const LightPick *lp, int i);
/** The same for the glowing geometry: 1 when every light is sampled, else the probability of its entry. */
double light_pick_nee_emissive_pmf(const LightPick *lp);
/** 1 when entry k is a delta light (point, spot, directional, IES: material sampling never meets it). */
int light_pick_is_delta(const LightPick *lp, int k);

#endif
