/* light.h - the scene's light sources (constructors in scene.c; their shading is lighting.h). */
#ifndef GTRACE_LIGHT_H
#define GTRACE_LIGHT_H

#include <generic/color.h>
#include <generic/vec.h>

struct ProbeEnv;
struct IesData;

typedef enum LightKind {
    LIGHT_POINT,       /**< intensity I: illum = I / d^2 */
    LIGHT_DIRECTIONAL, /**< irradiance E perpendicular to the direction: illum = E */
    LIGHT_SPOT,        /**< point light with a smooth cone */
    LIGHT_SPHERE,      /**< sphere of uniform radiance, sampled by solid angle */
    LIGHT_RECT,        /**< one-sided rectangle of uniform radiance, stratified samples */
    LIGHT_AMBIENT,     /**< (text only) ambient light: summed into Scene.ambient */
    LIGHT_BACKGROUND,  /**< (text only) radiance of rays that leave the scene: Scene.background */
    LIGHT_PROBE,       /**< a whole light probe, Monte Carlo with importance sampling (probe_sample.c) */
    LIGHT_IES          /**< a point light whose intensity follows an IES LM-63 candela table (scene/ies.h) */
} LightKind;

typedef struct Light {
    LightKind kind;
    GColor color;            /**< intensity, irradiance or radiance (heap storage, owned) */
    GVec3 position;          /**< point, spot, sphere centre, rectangle corner */
    GVec3 direction;         /**< directional, spot: unit direction the light travels */
    GVec3 edge1, edge2;      /**< rectangle edges; the lit side is edge1 x edge2 */
    double radius;           /**< sphere */
    double cos_inner, cos_outer; /**< spot cone (full intensity inside inner, none outside outer) */
    int samples;             /**< area lights, probe: shadow samples per shading point */
    int visible;             /**< sphere, rectangle: seen by camera rays as their radiance (default 0) */
    const struct ProbeEnv *env; /**< LIGHT_PROBE: the probe it samples (owned by the probe entry) */
    struct IesData *ies;     /**< LIGHT_IES: its candela table (owned); color is then the light per candela */
    GVec3 along, third;      /**< LIGHT_IES: with direction (the photometric axis), the luminaire's frame: along is
                              * the direction of horizontal angle 0 (type C) or the polar axis (type B), third =
                              * direction x along */
} Light;

/** A light with defaults whose colour has heap storage in the model (black). */
Light *light_new(const GColorModel *model, LightKind kind);
/** Frees the light and its colour (NULL: no-op). */
void light_free(Light *l);

#endif
