/* geometry.h - intersection with a shape and the surface at a hit (shapes.c, mesh.c). */
#ifndef GTRACE_GEOMETRY_H
#define GTRACE_GEOMETRY_H

#include "object.h"
#include "ray.h"

#include <generic/vec.h>

/** One placement of a prototype (accel.c): a group's shapes or an instanced shape, in world space. */
typedef struct Instance {
    Xform xf;                  /**< prototype space -> world (the composition of the nested transforms) */
    const GMaterial *material; /**< the override of the outermost instance that gives one (NULL: none) */
    int proto;                 /**< the prototype's Embree scene */
} Instance;

/** What the acceleration structure reports for a hit. */
typedef struct Hit {
    const Object *obj;
    const Instance *inst;       /**< the placement the hit is in (NULL: a shape of the top-level scene) */
    const GMaterial *material;  /**< the material at the hit (the instance's override or the object's) */
    double t;
    unsigned prim;
    double bu, bv; /**< barycentrics (meshes) */
    int surface;   /**< surface index from the user geometry */
} Hit;

/** The geometry at a hit in world space: outward unit normal (of the object, before facing), shading
 * normal from mesh normals (equal to the outward normal otherwise), tangents, parameters. */
typedef struct HitGeom {
    GVec3 p, op, n_out, n_smooth, dpdu, dpdv;
    GVec3 odpdu, odpdv; /**< tangents in object space */
    double u, v;
    int surface;
} HitGeom;

/** Half size of a plane's bounded extent in its own units. */
#define SHAPE_PLANE_EXTENT 1.0e5
/** Largest coordinate a scene may reach, in world space after transforms: every object's extent, every
 * light's position and the camera lie within [-SCENE_MAX_COORD, SCENE_MAX_COORD] in x, y and z. Embree traces
 * single-precision rays and stops the process on an origin beyond about 1.8e18; 1e15 keeps a margin, and
 * float positions there are already 1e8 units apart. */
#define SCENE_MAX_COORD 1.0e15

/** Object-space ray-shape intersection in (tmin, tmax); 1 with *t and *surface when hit. */
int shape_intersect(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t, int *surface);
/** Object-space bounds of a shape (planes are bounded at SHAPE_PLANE_EXTENT). */
void shape_bounds(const Object *o, GVec3 *lo, GVec3 *hi);
/** World-space bounds of an object (its shape's bounds through its transform; not padded). */
void object_world_bounds(const Object *o, GVec3 *lo, GVec3 *hi);
/** 1 when every component of v is finite and within [-SCENE_MAX_COORD, SCENE_MAX_COORD]. */
int scene_coord_ok(GVec3 v);
/** 0 when the object's world extent lies within SCENE_MAX_COORD; otherwise the largest coordinate it reaches
 * (INFINITY when one overflows or is not a number). */
double object_extent_check(const Object *o);
/** Surface details of an analytic shape at a hit. */
void shape_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);
/** Surface details at any hit in world space (through its instance, if any). */
void hit_geom(const Ray *r, const Hit *h, HitGeom *g);
/** Surface details of a mesh triangle at a hit. */
void mesh_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);
/** Fills g's point, outward normal n, shading normal ns and tangents from object space (op, n, ns, dpdu, dpdv)
 * in world space, keeping the object-space point and tangents; u, v and the surface are left to the caller. */
void hit_geom_to_world(const Object *o, GVec3 op, GVec3 n, GVec3 ns, GVec3 dpdu, GVec3 dpdv, HitGeom *g);

#endif
