/* parse.h - the tracer's entries in the text format (object, light, camera) and scenes from scene files
 * (parse.c). */
#ifndef GTRACE_PARSE_H
#define GTRACE_PARSE_H

#include "lights/probe_env.h"
#include "scene/scene.h"

#include <generic/error.h>
#include <generic/reader.h>

/** The tracer's kinds of entries (`object`, `light`, `camera`), numbered by gtrace_register_kinds. */
extern GKind gtrace_kind_object, gtrace_kind_light, gtrace_kind_camera;
/** The parse routines of gtrace's object, light and camera types (GParseFn, generic/registry.h); a loaded entry is
 * one of gtrace's when its type's parse routine is one of these. */
int scene_parse_object(GReader *r, const void *vtable, void **object, GError *err);
int scene_parse_light(GReader *r, const void *vtable, void **object, GError *err);
int scene_parse_camera(GReader *r, const void *vtable, void **object, GError *err);
/** Registers the kinds object, light and camera, and media/medium.h's medium and phase, with the registry
 * (idempotent). */
int gtrace_register_kinds(GError *err);
/** Registers the kinds and the object, light and camera types with the registry (idempotent). */
int gtrace_register_types(GError *err);
/** Reads a `{ translate <v> | rotate <v> | rotate_axis <axis> DEG | scale S | scale <v> ... }` block, applying each
 * operation after xf (the syntax of an object's transform). */
int scene_parse_transform(GReader *r, Xform *xf, GError *err);
/** Builds a scene from a loaded library (name: for messages), which the scene then owns (also on failure:
 * it is destroyed). */
int scene_from_library(GLibrary *lib, const char *name, Scene **out, GError *err);
/** Reads a scene file (registering the types first); colormodel overrides the file's model (NULL: keep). */
int scene_load(const char *path, const char *colormodel, Scene **out, GError *err);
/** Reads a scene file like scene_load, applying ov (NULL: nothing) to its light probes before they load. */
int scene_load_with(const char *path, const char *colormodel, const ProbeOverride *ov, Scene **out, GError *err);
/** scene_load_with starting from the reader options base (NULL: defaults; e.g. allow_plugins, confine_dir). */
int scene_load_opts(const char *path, const char *colormodel, const ProbeOverride *ov, const GReaderOptions *base,
                    Scene **out, GError *err);

#endif
