/* scene.h - the scene: objects, lights, camera, background, ambient light and the camera's medium
 * (scene.c; built from a scene file by parse.c). */
#ifndef GTRACE_SCENE_H
#define GTRACE_SCENE_H

#include "camera/camera.h"
#include "geometry/geometry.h"
#include "light.h"
#include "geometry/object.h"

#include <generic/color.h>
#include <generic/error.h>
#include <generic/material.h>
#include <generic/reader.h>

struct ProbeEnv;
struct Medium;

/** A material whose objects bound a participating medium (an object's `interior`, media/medium.h). */
typedef struct MediumBinding {
    const GMaterial *material;
    const struct Medium *medium;
} MediumBinding;
/* Embree's handle types: RTCDevice and RTCScene are pointers to these, so the scene holds them without
 * including Embree (only accel.c does). */
struct RTCDeviceTy;
struct RTCSceneTy;

/** The analytic shapes of one Embree scene (the top-level one or a prototype's), traced as the primitives of one
 * user geometry: primitive i is shapes[i] (accel.c). */
typedef struct ShapeBatch {
    Object **shapes; /**< borrowed objects, n of them (the array is the geometry's user data once attached) */
    unsigned n, cap;
    unsigned geom_id; /**< the user geometry's id (RTC_INVALID_GEOMETRY_ID: none) */
} ShapeBatch;

typedef struct Scene {
    const GColorModel *model; /**< colour model of every colour in the scene */
    GColorModel *owned_model; /**< destroyed with the scene (NULL: the model belongs to someone else) */
    Object **objects;
    int nobjects, cap_objects;
    Light **lights;
    int nlights, cap_lights;
    Camera camera;
    int have_camera;
    GColor background;     /**< radiance of rays that leave the scene */
    GColor ambient;        /**< ambient light handed to material.ambient */
    int have_ambient;
    GMaterial *medium;     /**< the medium the camera is in (NULL: vacuum; a reference) */
    GLibrary *lib;         /**< when loaded from text: owns the objects and lights (and the model) */
    /* acceleration (accel.c) */
    struct RTCDeviceTy *device; /**< an RTCDevice */
    struct RTCSceneTy *rtc;     /**< an RTCScene (NULL: accel_build has not run) */
    Object **by_geom;      /**< geometry id -> object of the top-level scene (NULL for an instance) */
    Instance *inst_by_geom; /**< geometry id -> placement (proto -1 for a shape of the top-level scene) */
    unsigned nby_geom;
    ShapeBatch user;        /**< the analytic shapes of the top-level scene */
    struct AccelProto *protos; /**< prototype scenes of groups and instanced shapes */
    int nprotos, cap_protos;
    unsigned ninstances;    /**< Embree instances in the top-level scene */
    int native_may_pass;    /**< a mesh, quad or triangle (or an override reaching one) may let light through */
    struct AccelDirect *direct; /**< a small scene of analytic shapes tested one by one (accel_direct.c; NULL:
                                 * Embree traces every ray) */
    int ndirect;            /**< entries of direct */
    int accel_embree_only;  /**< set before accel_build: trace through Embree even when the direct list would do */
    int accel_threads;      /**< set before accel_build: threads Embree may build with (0: all processors) */
    const struct ProbeEnv *env; /**< light probe seen by rays that leave the scene (NULL: background) */
    const struct Medium *atmosphere; /**< the participating medium outside every object (NULL: none; borrowed) */
    MediumBinding *interiors;        /**< the materials that bound a medium (heap), ninteriors of them */
    int ninteriors;
    int has_media;                   /**< an atmosphere or an interior: the integrators look for media */
} Scene;

/** An empty scene in the given colour model (not owned; set owned_model to hand one over). */
int scene_create(const GColorModel *model, Scene **out, GError *err);
/** Frees everything (NULL: no-op). */
void scene_destroy(Scene *s);
/** Takes ownership of o (freed with the scene also when this fails). */
int scene_add_object(Scene *s, Object *o, GError *err);
/** Takes ownership of l. */
int scene_add_light(Scene *s, Light *l, GError *err);

#endif
