/* lighting.h - the light sources' shade routine (lights.c; the probe's reference mode in probe_sample.c). */
#ifndef GTRACE_LIGHTING_H
#define GTRACE_LIGHTING_H

#include "light.h"
#include "trace.h"

#include <generic/color.h>
#include <generic/surfpoint.h>
#include <generic/vec.h>

/** Scratch colours for light_shade, allocated once per shading point and shared by all lights. */
typedef struct LightTmp {
    GColor illum, refl, tmp;
} LightTmp;
/** Allocates the temporaries on the thread's arena. */
int light_temps(TraceCtx *c, LightTmp *t);
/** Adds to result the light reflected towards out_dir by sp from one light source, shadowed and absorbed
 * (Fig. 4, light.shade); opaque: the material's opaque() at sp (culls lights behind the surface). */
int light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                int opaque, LightTmp *t, GColor *result);
/** Adds the light of one sample (lights.c): color * scale arrives from direction `in` over dist (INFINITY
 * for distant light), reflected by the material towards out_dir and shadowed. */
int sample_light(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 in, double dist,
                 const GColor *color, double scale, GVec3 out_dir, LightTmp *t, GColor *result);
/** The reference mode of a probe (probe_sample.c): its direct light at sp estimated from l->samples directions
 * drawn from the distribution (stratified), each shadowed and reflected through the material like any light. */
int probe_light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media,
                      GVec3 out_dir, int opaque, LightTmp *t, GColor *result);

/** Visible area lights (light_seen.c): 1 with out = the radiance of the nearest sphere or rectangle light
 * marked visible that r meets before tmax (a rectangle from its lit side only), 0 when it meets none. */
int light_seen(const Scene *s, const Ray *r, double tmax, GColor *out, int *status);

#endif
