/* medium_light.h - next-event estimation at a scattering event in a participating medium (medium_light.c), for the
 * path tracer's medium vertices. */
#ifndef GTRACE_MEDIUM_LIGHT_H
#define GTRACE_MEDIUM_LIGHT_H

#include "media/medium.h"
#include "trace/trace.h"

/** A ray's way through a homogeneous medium that scatters, o + t d for t in (0, tmax) (tmax may be INFINITY), and
 * the distance t of the scattering event free-flight sampling drew on it: the light of point, spot and IES lights
 * at that event is weighted by the balance heuristic against equiangular sampling on the same way
 * (medium_equiangular_light). */
typedef struct MediumWay {
    GVec3 o, d;
    double tmax, t;
} MediumWay;

/** Adds to out the light scattered at x (in the medium vol, which media describes) from the ray direction d towards
 * -d: when c->pick (not NULL; light_pick.h) holds few entries (light_pick_nee_every) one sample of every light source
 * of the scene and one of the glowing geometry; else one light source chosen by power from it with c->rng (no number
 * when it has one entry), one sample of it divided by the probability of the choice; each through light_transmit
 * (absorption and media along the way; a sphere or rectangle light or the glowing geometry, which phase sampling also
 * reaches, blocked by any surface and weighted by the power heuristic against the phase function's density, theirs
 * including the choice). A light probe chosen adds nothing (phase sampling reaches it). way: x is the free-flight
 * event on it, and point-like lights are weighted against their equiangular samples (NULL: they count fully). */
int medium_direct_light(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, const MediumWay *way,
                        GColor *out);

/** Adds to out the single scattering along way (its t unused) from each point, spot and IES light, sampled by
 * equiangular sampling (media/equiangular.h): at a distance t drawn towards the light, the transmittance to t times
 * sigma_s times the light's phase-weighted sample there (through light_transmit), over the sum of the equiangular
 * density and free flight's (medium_distance_pdf): the balance heuristic, whose other half medium_direct_light
 * weights with way. vol must be homogeneous and scatter; the numbers come from c->rng. */
int medium_equiangular_light(TraceCtx *c, const Medium *vol, const Media *media, const MediumWay *way, GColor *out);

#endif
