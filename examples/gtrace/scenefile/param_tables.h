/* param_tables.h - the parameter tables of gtrace's scene types (param_tables.c), in the order parse.c registers
 * the types. */
#ifndef GTRACE_PARAM_TABLES_H
#define GTRACE_PARAM_TABLES_H

#include <generic/registry.h>

enum { SCENE_SHAPE_TYPES = 10, SCENE_LIGHT_TYPES = 8, SCENE_CAMERA_TYPES = 3 };

/** sphere, plane, box, disc, cylinder, mesh, quad, triangle, group, instance */
extern const GParamInfo *const scene_shape_tables[SCENE_SHAPE_TYPES];
/** point, directional, spot, sphere, rectangle, ambient, background (the probe's is probe_light.c's) */
extern const GParamInfo *const scene_light_tables[SCENE_LIGHT_TYPES];
/** pinhole, thinlens, orthographic */
extern const GParamInfo *const scene_camera_tables[SCENE_CAMERA_TYPES];

#endif
