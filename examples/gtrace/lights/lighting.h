/* lighting.h - the light sources' shade routine (lights.c; the probe's reference mode in probe_sample.c, shared
 * by the Whitted and the path integrator). */
#ifndef GTRACE_LIGHTING_H
#define GTRACE_LIGHTING_H

#include "scene/light.h"
#include "trace/trace.h"

#include <generic/color.h>
#include <generic/surfpoint.h>
#include <generic/vec.h>

/** Scratch colours for light_shade, shared by all lights at a shading point (light shading traces no rays
 * but shadow rays, so the context's own temporaries serve every shading point), the shadow rule of
 * sample_light, and the light gathered for a Lambertian material (light_gather). */
typedef struct LightTmp {
    GColor illum, refl, tmp;
    GColor gathered; /**< with `gather`: the sum of each sample's light (shadowed) times its gmaterial_cos_in */
    int gathered_any; /**< with `gather`: 1 once a sample's light was added to `gathered` (0: it stands for black and
                       * is not written: the first sample writes it) */
    int blocked; /**< 1: a shadow ray stops at any surface (the path tracer's rule for lights that material
                  * sampling also reaches: light through glass arrives there as a caustic); 0 (light_temps'
                  * default): it passes non-opaque surfaces along the straight line */
    int gather;  /**< 1 (light_gather): sample_light adds to `gathered` instead of asking the material per sample;
                  * 0 (light_temps' default): it adds the material's reflection of each sample to the result */
    int unset;   /**< 1: the result holds nothing yet and stands for black (a caller that has not written it): the first
                  * light is written to it instead of added (light_add), and unset is then 0; until then the result may
                  * be written as a temporary (its values mean nothing while unset is 1); 0 (light_temps' default): the
                  * result is written and light is added to it */
} LightTmp;
/** The temporaries: the context's own (trace_tmp; from the thread's arena when it has none), not black; blocked,
 * gather and unset are 0. */
int light_temps(TraceCtx *c, LightTmp *t);
/** Starts gathering the light of the samples at sp when its material has GMAT_LAMBERTIAN (material.h): its
 * reflection of a sample is diffuse(sp) times the light times gmaterial_cos_in / pi, so sample_light sums light times
 * cosine into t->gathered and light_gather_finish reflects the sum once. Nothing for another material (each
 * sample asks its reflection). Call it after light_temps, before the first light. */
void light_gather(GSurfPoint *sp, LightTmp *t);
/** Ends light_gather: adds diffuse(sp) times t->gathered / pi to result (nothing when none was gathered; written to
 * it with t->unset) and turns gathering off. A no-op without light_gather. */
int light_gather_finish(GSurfPoint *sp, LightTmp *t, GColor *result);
/** Adds light x to result: result = result + x, or with t->unset result = x (x may be result itself) and t->unset
 * = 0. */
int light_add(LightTmp *t, GColor *result, const GColor *x);
/** Adds to result the light reflected towards out_dir by sp from one light source, shadowed and absorbed
 * (Fig. 4, light.shade); opaque: the material's opaque() at sp (culls lights behind the surface). */
int light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                int opaque, LightTmp *t, GColor *result);
/** The light of one sample arriving at sp from `dir` over `dist` (INFINITY: a distant light) after the surfaces in
 * between, in place in light (lights.c): blocked by an opaque surface (*visible = 0), passed through the others
 * along the straight line (their refraction at each interface, the media's absorption); G_OK or a status. */
int light_transmit(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 dir, double dist,
                   GColor *light, int *visible);
/** Adds the light of one sample (lights.c): color * scale arrives from direction `in` over dist (INFINITY
 * for distant light), reflected by the material towards out_dir and shadowed (t->blocked says how); with
 * t->gather, the shadowed light times its cosine goes to t->gathered instead (light_gather_finish reflects it),
 * except where the medium's absorption acts on the reflected light (a finite distance in a medium): that sample
 * is reflected on its own. */
int sample_light(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 in, double dist,
                 const GColor *color, double scale, GVec3 out_dir, LightTmp *t, GColor *result);
/** The spot light l's share of its intensity in the direction -in (in: from a point towards the light): 1 within
 * the inner cone, 0 beyond the outer, smooth between. */
double light_spot_factor(const Light *l, GVec3 in);
/** The power heuristic (beta 2, lights.c): the multiple-importance weight of a strategy that drew a direction
 * with density a against one that would have drawn it with density b. */
double mis_power(double a, double b);
/** A probe light in the Whitted tracer (probe_sample.c): a basis's ambient term, or for technique reference
 * probe_light_nee with l->samples directions and no MIS. */
int probe_light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media,
                      GVec3 out_dir, int opaque, LightTmp *t, GColor *result);
/** The direct light of a reference probe l at sp towards out_dir, for both integrators (probe_sample.c): n
 * directions drawn from the probe's distribution with c->rng (stratified when n > 1; with n = 1 and u given, the one
 * direction u[0], u[1] map to, the caller's numbers in [0, 1)), each carrying the
 * probe's pixel as a light through sample_light (shadows by t->blocked; `shadows off` skips them unless
 * mis_ri is given). mis_ri (the path tracer, whose material sampling also reaches the probe): each direction
 * is weighted against the material's pdf for the relative index mis_ri by mis_power, the direction's density taken
 * as its density in the probe's distribution times pick (the probability with which the caller chose this light among
 * others; 1: always); NULL: weight 1. The estimate itself is not divided by pick. */
int probe_light_nee(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                    int opaque, int n, const double *u, const GColor *mis_ri, double pick, LightTmp *t,
                    GColor *result);

/** Visible area lights (light_seen.c): 1 with out = the radiance of the nearest sphere or rectangle light
 * marked visible that r meets before tmax (a rectangle from its lit side only), 0 when it meets none. */
int light_seen(const Scene *s, const Ray *r, double tmax, GColor *out, int *status);

#endif
