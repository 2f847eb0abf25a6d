/* probe_env.h - the `light probe` entry: its settings, the probe, and the lights it gives the scene
 * (probe_light.c). */
#ifndef GTRACE_PROBE_ENV_H
#define GTRACE_PROBE_ENV_H

#include "scene/light.h"
#include "probe_dist.h"
#include "scene/scene.h"

#include <generic/color.h>
#include <generic/error.h>
#include <generic/services/probe.h>
#include <generic/reader.h>
#include <generic/vec.h>

#include <stdio.h>

/** The technique value of the reference mode (next to the library's GProbeTechnique values). */
#define PROBE_REFERENCE GPROBE_TECHNIQUE_COUNT
/** The technique value of a basis (GProbeBasisKind k) used as an ambient term, and the test for one. */
#define PROBE_BASIS(k) (GPROBE_TECHNIQUE_COUNT + 1 + (int)(k))
#define PROBE_IS_BASIS(t) ((t) > PROBE_REFERENCE)

/** A `light probe` entry: its settings, the probe once loaded, and the lights made from it. */
typedef struct ProbeEnv {
    /* settings: the scene file's, then the command line's */
    char *file;          /**< the probe image (resolved against the scene file's directory) */
    int technique;       /**< a GProbeTechnique, PROBE_REFERENCE or PROBE_BASIS(kind) */
    int count;           /**< technique: number of lights; basis: coefficients or lobes */
    int samples;         /**< reference: samples per shading point */
    int fit_normals;     /**< irradiance: normals the fit uses (0: the library's default) */
    GVec3 rotate;        /**< degrees about x, then y, then z (gprobe_rotation_xyz) */
    double scale;        /**< multiplies the probe's radiance */
    int background;      /**< the probe is what rays leaving the scene see */
    int shadows;         /**< reference: cast shadow rays */
    GProbeFormat format; /**< how the image maps to directions */
    char where[256];     /**< "file:line:col" of the entry, for messages */
    /* made by probe_attach */
    GProbe *probe;
    double R[9];         /**< probe space -> world, row-major */
    Light **lights;      /**< the lights it gave the scene (owned) */
    int nlights;
    ProbeDist dist;      /**< reference: the sampling distribution */
    ProbeDist nee_dist;  /**< reference: the path tracer's, compensated (probe_dist_build), MIS-weighted */
    GProbeBasis basis;   /**< basis: the fitted approximation, its irradiance the ambient term */
    double seconds;      /**< loading and approximating */
    double error_mean;   /**< technique: mean irradiance error of the lights in percent (the paper's measure) */
} ProbeEnv;

/** Command-line replacements for the settings of the scene's `light probe` entries (NULL, 0 or -1: keep). */
typedef struct ProbeOverride {
    const char *file;      /**< probe image, relative to the current directory */
    const char *technique; /**< a library technique or basis keyword, or reference */
    int count;             /**< number of lights */
    int samples;           /**< reference: samples per shading point */
    double scale;          /**< radiance scale */
    int shadows;           /**< reference: 1 on, 0 off, -1 keep */
} ProbeOverride;

/** The parse routine and destructor of `light probe` (registered by gtrace_register_types). */
int probe_light_parse(GReader *r, const void *vtable, void **object, GError *err);
void probe_light_destroy(void *object);
/** The parameters probe_light_parse reads (GParamInfo rows ended by {NULL}; generic/registry.h). */
extern const GParamInfo probe_light_params[];
/** Applies command-line replacements to every probe entry of a loaded library (before scene_from_library);
 * G_ERR_INVALID when the library has none or a value does not fit. */
int probe_override_apply(GLibrary *lib, const ProbeOverride *ov, GError *err);
/** Loads the probe of an entry, makes its lights (directional lights of a technique, or one LIGHT_PROBE light
 * for the reference) and adds them to the scene; the probe becomes the scene's background unless the entry
 * says `background off`. Called by scene_from_library; the entry keeps owning what it made. */
int probe_attach(Scene *s, ProbeEnv *env, GError *err);
/** A direction of the probe in world space (turned by the entry's rotation). */
GVec3 probe_to_world(const ProbeEnv *env, GVec3 d);
/** A world direction in the probe's own frame (the inverse of probe_to_world). */
GVec3 probe_from_world(const ProbeEnv *env, GVec3 d);
/** Radiance seen along direction d leaving the scene (d in world space), bilinear between pixel centres. */
int probe_background(const ProbeEnv *env, GVec3 d, GColor *out);
/** Radiance of the probe as a light along world direction d: the pixel d falls in, scaled (piecewise constant,
 * as its sampling distribution; probe_sample.c). */
int probe_pixel_radiance(const ProbeEnv *env, GVec3 d, GColor *out);
/** Prints one line per probe entry of the scene (file, size, technique, lights, time, irradiance error). */
void probe_describe(const Scene *s, FILE *f);

#endif
