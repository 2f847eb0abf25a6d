/* trace.h - what the integrators (integrators/) and the lights (lights/) share: the per-thread tracing context,
 * the stack of media a ray travels through and the surface point at a hit (trace.c). */
#ifndef GTRACE_TRACE_H
#define GTRACE_TRACE_H

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "camera/rng.h"
#include "scene/scene.h"

#include <generic/color.h>
#include <generic/material.h>
#include <generic/memory.h>
#include <generic/surfpoint.h>
#include <generic/vec.h>

#include <math.h>
#include <stdint.h>

/** The colours a TraceCtx owns (TraceCtx.tmp), each for one job that holds it without tracing another ray meanwhile,
 * so that no two users can meet: light shading (lighting.h's LightTmp), the shadow ray's walk through glass
 * (lights.c), the refraction indices on both sides of a surface (trace_relative_index), a shading point's
 * ambient and absorbed light (whitted.c), and what a material passes on of a secondary ray's light (whitted.c's
 * trace_secondary, before and after the ray, not across it). */
enum {
    TRACE_TMP_ILLUM, TRACE_TMP_REFL, TRACE_TMP_LIGHT, TRACE_TMP_GATHER, /* LightTmp */
    TRACE_TMP_WALK, TRACE_TMP_WALK_RI, TRACE_TMP_WALK_NF, TRACE_TMP_WALK_NT, /* light_transmit */
    TRACE_TMP_N_FROM, TRACE_TMP_N_TO,                             /* trace_relative_index */
    TRACE_TMP_SHADE, TRACE_TMP_PASS,                              /* shade, trace_secondary */
    TRACE_TMP_COUNT
};

/** The relative indices a TraceCtx keeps (TraceCtx.ri_cache): n(from) / n(to) for the first pairs of materials with
 * GMAT_CONSTANT_INDEX (material.h) it meets, whose ratio is the same colour at every point between them. */
#define TRACE_RI_SLOTS 8

/** One kept relative index: the pair (NULL: vacuum) and its colour, of the context's arena. Filled once and never
 * replaced, so a handle to it stays valid and its values unchanged for the context's life: a caller holds it across
 * the deeper hits of a recursion, and a surface point refers to it (gsurfpoint_set_relative_index). */
typedef struct TraceRelIndex {
    const GMaterial *from, *to;
    GColor ri;
    double scalar; /**< gsurfpoint_scalar_index(&ri), taken once: what a point set with it reads */
} TraceRelIndex;

/** Per-thread tracing state. */
typedef struct TraceCtx {
    const Scene *scene;
    GScratch *scratch;
    Rng rng;
    int max_depth;
    double cutoff;  /**< smallest path weight still traced (0: trace to max_depth) */
    double weight;  /**< weight of the current path in its pixel (product of the branches' brightness) */
    GColor unit;    /**< 1 in every sample (the vacuum's refraction index): probes a branch's weight */
    uint64_t rays;  /**< rays cast through Embree */
    int rays_left;  /**< secondary rays the current camera sample may still spawn */
    int capped;     /**< the current camera sample ran out of rays_left */
    int status;     /**< first error (G_OK while fine) */
    const char *culprit; /**< type of the material whose call failed first (NULL: none or not a material) */
    const struct Bands *bands; /**< the wavelength groups a dispersive refraction splits into (integrators/bands.h;
                                * NULL: none) */
    int band;            /**< the group the current path carries (-1: all light; set by a dispersive split) */
    const struct EmissiveSet *emissive; /**< the glowing geometry sampled as light (lights/emissive.h; NULL: none) */
    const struct LightPick *pick; /**< every light source chosen by power (lights/light_pick.h; NULL: no light is
                                   * drawn at random) */
    int volumes;         /**< the integrator renders participating media (the path tracer, in a scene with media):
                          * shadow rays are attenuated by them (lights.c); 0: only materials' absorption */
    int equiangular;     /**< the path tracer also samples the single scattering of point, spot and IES lights in
                          * homogeneous media equiangularly (integrators/medium_light.h); 0: free flight alone */
    GColor tmp[TRACE_TMP_COUNT]; /**< temporaries made once with the context (trace_ctx_temps); cleared in a
                                  * context built without them, whose users then take arena storage (trace_tmp) */
    TraceRelIndex ri_cache[TRACE_RI_SLOTS]; /**< relative indices kept (trace_cached_index); their storage is made
                                             * with the temporaries, none in a context built without them */
    int ri_filled;       /**< entries of ri_cache filled, the first ones */
} TraceCtx;

/** Gives c its own temporaries (c->tmp, of the scene's model) and the storage of its kept relative indices
 * (c->ri_cache, empty) from c's arena, made before any mark its users take and kept for its life (a worker's own
 * arena: two threads' colours never share a cache line); G_ERR_NOMEM when the arena cannot grow. */
int trace_ctx_temps(TraceCtx *c);
/** Clears the handles of trace_ctx_temps and empties the kept relative indices (their storage goes with the arena; a
 * no-op for a context without them). */
void trace_ctx_free_temps(TraceCtx *c);
/** The temporary `which` (a TRACE_TMP_ value) of c into *out: a copy of c's handle when c has its temporaries,
 * else storage from c's arena (given back by the caller's mark and release). Not black: the users write before
 * they read. */
int trace_tmp(TraceCtx *c, int which, GColor *out);

/** The media a ray travels through: bottom = the camera's medium, top = the current one. */
#define MEDIA_MAX 16
typedef struct Media {
    const GMaterial *m[MEDIA_MAX];
    int n;
} Media;

/** Fills sp for a hit of r: geometry, normal on the incident side, footprint from the ray cone, and the
 * materials on both sides from the media; *facing is the true face normal on the incident side (for
 * offsetting secondary rays; it differs from the geometric_normal field on meshes with vertex normals). */
void surfpoint_fill(TraceCtx *c, const Ray *r, const Hit *h, const Media *media, GSurfPoint *sp, GVec3 *facing);
/** The current medium (NULL: vacuum). */
const GMaterial *media_top(const Media *m);
/** Copies the stack in to out: its n entries only (a struct copy of the whole array is a `rep movs`, per shadow
 * ray; the stack is rarely more than two deep). */
void media_copy(Media *out, const Media *in);
/** The media after crossing the surface of mat: entering pushes it, leaving removes it. */
void media_cross(const Media *in, const GMaterial *mat, int entering, Media *out);
/** 1 when the medium m absorbs nothing (GMAT_CLEAR, material.h; NULL: vacuum): gmaterial_absorption gives the light
 * back bit for bit without calling the class, and the integrators skip even that call and the colour it writes (the
 * same answer). The bit read inline, as trace_relative_index reads the others (no call per hit). */
static inline int media_clear(const GMaterial *m) { return !m || (m->flags & GMAT_CLEAR); }
/** The relative index the material of sp is handed: *ri points to n(from) / n(to) at sp, made sp's relative index
 * (gsurfpoint_set_relative_index), and is read only (it may be shared, kept for the context's life). For a material
 * with GMAT_NO_REL_INDEX, whose methods read no index, c->unit (1 in every sample: no wavelength split) without the
 * two indices and the division, and the point's index is left unset (a method that asked would still get the true
 * one). When both sides have GMAT_CONSTANT_INDEX, the pair's kept colour (trace_cached_index: the same bits);
 * otherwise computed at sp into room (given storage from the thread's arena, released by the caller's mark). */
int trace_relative_index(TraceCtx *c, GSurfPoint *sp, GColor *room, const GColor **ri);
/** The kept relative index n(from) / n(to) of two materials with GMAT_CONSTANT_INDEX (NULL: vacuum) into *ri: found
 * among c->ri_cache, or computed at sp (refraction_index of both and gcolor_div, as trace_relative_index computes it
 * at a point, so the same bits) into the next free entry, and made sp's relative index with its kept scalar
 * (gsurfpoint_set_relative_index_scalar). *ri is NULL, with G_OK and sp unchanged, when a side may vary, c has no
 * kept indices (a context without temporaries) or every entry holds another pair: the caller computes it itself. */
int trace_cached_index(TraceCtx *c, const GMaterial *from, const GMaterial *to, GSurfPoint *sp, const GColor **ri);
/** The distance a point is moved off a surface (offset_origin) and the margin a shadow ray keeps from the surface of
 * its target (shadow_reach): a relative 2e-5 of the point's largest coordinate, far above the single precision of the
 * intersection tests. */
static inline double offset_eps(GVec3 p) { return 2e-5 * (1.0 + gfmax(fabs(p.x), gfmax(fabs(p.y), fabs(p.z)))); }
/** Offsets a point off a surface to the side `dir` leaves on, against self-intersection. Inline: called for every
 * secondary and shadow ray, it would pass its three vectors and its result through the stack. */
static inline GVec3 offset_origin(GVec3 p, GVec3 n, GVec3 dir)
{
    double eps = offset_eps(p);
    return gvec3_madd(p, n, gvec3_dot(dir, n) >= 0.0 ? eps : -eps);
}
/** The length of a shadow ray from origin along unit dir towards target, a point on a surface of unit normal `normal`
 * (either orientation) that the ray must not meet: the ray ends where it still lies the offset of a secondary ray's
 * origin at target (offset_origin's) in front of the surface's tangent plane at target, so that neither end of the
 * ray sees the surface it lies on whatever the scale and the distance; 0 when the origin lies closer to that plane
 * than the offset. A ray that runs along the plane ends where it passes target. */
double shadow_reach(GVec3 origin, GVec3 dir, GVec3 target, GVec3 normal);

#endif
