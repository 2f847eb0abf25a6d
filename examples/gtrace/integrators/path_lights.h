/* path_lights.h - the path tracer's state (PathCtx), shared by path.c (the path) and path_lights.c (next-event
 * estimation at a surface vertex): what each of a vertex's sample dimensions is for, the path's random numbers, and
 * the two NEE estimators. Internal to the path tracer. */
#ifndef GTRACE_PATH_LIGHTS_H
#define GTRACE_PATH_LIGHTS_H

#include "lights/lighting.h"
#include "trace/sampler.h"
#include "trace/trace.h"
#include "check.h"

#include <generic/color.h>

/* The state of one path (path_trace fills it for a camera sample). */
typedef struct PathCtx {
    TraceCtx *c;
    const Light *env_light; /**< the reference probe light that samples the background probe (NULL: none) */
    double env_pick;        /**< the probability that next-event estimation chooses env_light */
    int env_in_lights;      /**< the background probe's light is carried by its technique's directional lights */
    int scattered;          /**< the current path has had a non-delta bounce (it sees the ambient light) */
    int from_medium;        /**< set for the ray a medium vertex traces next (read and cleared by path_radiance):
                             * the probe was not sampled there, so the background it meets counts fully */
    int sobol;              /**< the path's own numbers come from the sample point (SAMPLER_SOBOL) */
    int point_lights;       /**< the scene has point, spot or IES lights (equiangular sampling in media serves them) */
    SamplePoint point;      /**< the camera sample's point in the pixel's sequence */
    SampleGroup group;      /**< its group used last (group 0, the camera's, is never used here: none yet) */
} PathCtx;

/* What each of a vertex's sample dimensions is for: two groups of four a vertex, after the camera's group (the pixel
 * position and the lens). The pairs that matter most lie in a group's first two dimensions, whose points are
 * stratified in 2D (a (0,m,2)-net); picks and Russian roulette take the others. */
enum {
    SLOT_LIGHT_U,    /**< the light sample's point on an area light or glowing primitive, or a probe's direction */
    SLOT_LIGHT_V,
    SLOT_LIGHT_PICK, /**< the light chosen by power (light_pick.h), then the glowing primitive */
    SLOT_DELTA_PICK, /**< the delta light kept among the candidates (path_lights.c's delta_choice) */
    SLOT_BSDF_U, /**< the material's sampled direction */
    SLOT_BSDF_V,
    SLOT_ROULETTE, /**< drawn after the material's sample: the same group (PathCtx.group keeps one) */
    SLOT_BAND,     /**< the wavelength group of a dispersive refraction */
    SLOTS_PER_VERTEX
};

/* The path's random numbers: the thread's generator, seeded for this camera sample by path_trace. */
static inline double path_uniform(PathCtx *p) { return rng_next(&p->c->rng); }

/* The number for `slot` of the vertex at `depth` (0: the camera ray's hit): the sample point's dimension with the
 * Sobol sampler, else the generator's next number. */
static inline double path_vertex_uniform(PathCtx *p, int depth, int slot)
{
    if (!p->sobol)
        return path_uniform(p);
    uint32_t dim = (uint32_t)(SAMPLER_GROUP_DIMS + depth * SLOTS_PER_VERTEX + slot);
    if (p->group.group != dim / SAMPLER_GROUP_DIMS)
        p->group = sample_group(&p->point, dim / SAMPLER_GROUP_DIMS);
    return sample_group_value(&p->group, (int)(dim % SAMPLER_GROUP_DIMS));
}

/** Adds to out the direct light at sp, the vertex at `depth`, from every light source, reflected towards to_viewer
 * (NEE, when the table holds few entries: light_pick_nee_every). The first sphere or rectangle light (else the glowing
 * geometry) takes the vertex's light dimensions, the others the generator's numbers. *unset: out holds nothing yet
 * and stands for black (LightTmp.unset): the first light is written to it, and *unset cleared. */
int path_direct_light_every(PathCtx *p, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 to_viewer,
                            int opaque, const GColor *ri, int depth, GColor *out, int *unset);

/** Adds to out the direct light at sp, the vertex at `depth`, reflected towards to_viewer (NEE, when the table holds
 * many entries): one light source chosen by power from the scene's table (lights/light_pick.h), its estimate divided
 * by the probability of the choice. The choice takes the vertex's pick dimension (none when the table has one entry),
 * a sphere or rectangle light or the glowing geometry its point dimensions, the glowing geometry's primitive what is
 * left of the pick's number; a delta light draws nothing, a probe the generator's numbers. */
int path_direct_light(PathCtx *p, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 to_viewer, int opaque,
                      const GColor *ri, int depth, GColor *out, int *unset);

#endif
