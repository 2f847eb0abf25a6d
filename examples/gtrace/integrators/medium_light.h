/* medium_light.h - next-event estimation at a scattering event in a participating medium (medium_light.c), for the
 * path tracer's medium vertices. */
#ifndef GTRACE_MEDIUM_LIGHT_H
#define GTRACE_MEDIUM_LIGHT_H

#include "media/medium.h"
#include "trace/trace.h"

/** Adds to out the light scattered at x (in the medium vol, which media describes) from the ray direction d towards
 * -d: when c->pick (not NULL; light_pick.h) holds few entries (light_pick_nee_every) one sample of every light source
 * of the scene and one of the glowing geometry; else one light source chosen by power from it with c->rng (no number
 * when it has one entry), one sample of it divided by the probability of the choice; each through light_transmit
 * (absorption and media along the way; a sphere or rectangle light or the glowing geometry, which phase sampling also
 * reaches, blocked by any surface and weighted by the power heuristic against the phase function's density, theirs
 * including the choice). A light probe chosen adds nothing (phase sampling reaches it). */
int medium_direct_light(TraceCtx *c, const Medium *vol, const Media *media, GVec3 x, GVec3 d, GColor *out);

#endif
