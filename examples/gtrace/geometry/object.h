/* object.h - the scene's objects: a shape in its own space, a transform to world space and a material
 * (constructors in scene.c, OBJ meshes in mesh.c, PLY, STL and glTF in mesh_assimp.c). */
#ifndef GTRACE_OBJECT_H
#define GTRACE_OBJECT_H

#include "transform.h"

#include <generic/error.h>
#include <generic/material.h>
#include <generic/vec.h>

#include <stddef.h>

typedef enum ShapeKind {
    SHAPE_SPHERE,
    SHAPE_PLANE,
    SHAPE_BOX,
    SHAPE_DISC,
    SHAPE_CYLINDER,
    SHAPE_MESH,
    SHAPE_QUAD,     /**< parallelogram center + u t1 + v t2, (u,v) in [0,1]^2: an Embree quad */
    SHAPE_TRIANGLE, /**< center + u t1 + v t2 with u, v >= 0, u + v <= 1: an Embree triangle */
    SHAPE_GROUP,    /**< a list of objects (borrowed): one Embree scene for its shapes */
    SHAPE_INSTANCE  /**< another object or group placed by a transform, optionally in another material */
} ShapeKind;

/** Largest nesting of groups and instances in one object. */
#define GTRACE_MAX_NESTING 64
/** Largest number of Embree instances a scene may expand to (every path through groups and instances). */
#define GTRACE_MAX_INSTANCES 100000

/** A triangle mesh read from an OBJ, PLY, STL or glTF file. Positions are kept in object space (double) and world space
 * (the float buffer Embree reads); normals and (u,v) per corner, -1 where the file gave none. */
typedef struct Mesh {
    int nverts, ntris, nuvs, nnormals;
    double *pos;        /**< object space, 3 per vertex */
    double *uv;         /**< 2 per uv */
    double *normal;     /**< object space, 3 per normal */
    unsigned *tri;      /**< 3 vertex indices per triangle */
    int *tri_uv;        /**< 3 uv indices per triangle or -1 */
    int *tri_normal;    /**< 3 normal indices per triangle or -1 */
    int *tri_surface;   /**< group (usemtl/g) index per triangle: the surface index */
    size_t budget;      /**< bytes reserved for it against the memory budget (its arrays and the accelerator's copy
                             and hierarchy, mesh_budget_bytes), released by mesh_free */
} Mesh;

/** The bytes a mesh of nverts vertices and ntris triangles is charged against the memory budget when it is read,
 * before its arrays are allocated: its vertex and triangle arrays (with a normal and a (u,v) per vertex) and what
 * the accelerator builds from it (Embree's vertex and index copies and its hierarchy, about 64 bytes a triangle). */
size_t mesh_budget_bytes(size_t nverts, size_t ntris);

/** One object: a shape in its own space, a transform to world space and a material. The head (kind to interior) is
 * all that a sphere without a transform uses: object_compact stores such a sphere without the rest (the tail), so no
 * code reads a field of the tail of a sphere whose has_xf is 0. */
typedef struct Object {
    ShapeKind kind : 8;
    unsigned has_xf : 1;  /**< xf applies (0: object space is world space, xf is not read) */
    unsigned is_part : 1; /**< a member of a group or an instance's prototype: rendered only through them */
    unsigned charged : 1; /**< object_charge reserved its share against the memory budget (object_free returns it) */
    int proto_index;  /**< accel: the prototype scene of a group or instanced shape (-1: none) */
    GMaterial *material; /**< owned reference */
    GVec3 center;     /**< sphere, disc: centre; plane: a point; cylinder: base centre; quad, triangle: corner */
    double radius;    /**< sphere, disc, cylinder */
    const struct Medium *interior; /**< the participating medium inside (media/medium.h; NULL: none; borrowed) */
    /* the tail */
    Xform xf;
    GVec3 normal;     /**< plane, disc, quad, triangle: unit normal; cylinder: unit axis */
    GVec3 t1, t2;     /**< plane, disc, cylinder: frame with t1 x t2 = normal; quad, triangle: the edges */
    double height;    /**< cylinder */
    int open;         /**< cylinder without caps */
    GVec3 lo, hi;     /**< box corners; group, instance: the bounds of what they hold, in their own space */
    Mesh *mesh;       /**< SHAPE_MESH */
    struct Object **members;     /**< SHAPE_GROUP: the members (borrowed from the library), nmembers of them */
    int nmembers;
    struct Object *proto;        /**< SHAPE_INSTANCE: what it places (borrowed); material is the override or NULL */
    int nesting;      /**< groups and instances nested in this object (0 for a shape) */
    double expansion; /**< Embree instances this object expands to when placed (a shape placed alone: 1) */
    size_t placement_bytes; /**< group, instance: its placements' bytes reserved by object_charge (0 once a group
                                 or an instance that places it has taken them over) */
} Object;

/** The bytes of an object's head (object_compact). */
#define OBJECT_HEAD_BYTES offsetof(Object, xf)

/** A zeroed object of a kind with an identity transform holding a new reference to material. */
Object *object_new(ShapeKind kind, GMaterial *material);
/** Frees the object, its mesh and its material reference (NULL: no-op). */
void object_free(Object *o);
/** An object's storage made as small as its shape allows: a sphere without a transform is moved into a block of its
 * head alone (OBJECT_HEAD_BYTES), o freed; any other object is returned as it is. NULL (o freed with its material
 * reference) when out of memory. */
Object *object_compact(Object *o);
/** Bytes an analytic shape is charged against the memory budget for its share of the acceleration structure: its
 * primitive in the user geometry's hierarchy (Embree's medium or high build, with the build's primitive
 * reference) and its slot in the batch. A mesh's share is in mesh_budget_bytes. */
#define OBJECT_SHAPE_ACCEL_BYTES 128
/** Bytes each placement of a group or an instance is charged: its Embree instance (the geometry, its primitive in
 * the top-level hierarchy) and its Instance record in the geometry-id table. */
#define OBJECT_PLACEMENT_BYTES 1024
/** Reserves against the memory budget what o adds to the scene once its entry is read: an analytic shape its share
 * of the acceleration structure (OBJECT_SHAPE_ACCEL_BYTES), a group or an instance its placements (expansion x
 * OBJECT_PLACEMENT_BYTES), taking over the placements its members or prototype had reserved (it places them). A
 * mesh reserves its own as it is read. G_OK, or G_ERR_NOMEM with the budget's message naming what was asked (the
 * caller puts the entry's position in front; nothing is reserved then). object_free returns the reservation. */
int object_charge(Object *o, GError *err);
/** The expansion (placements when placed) and nesting of an object: a shape's are 1 and 0. */
double object_expansion(const Object *o);
int object_nesting(const Object *o);
/** Shape constructors in object space (they fill the frames); return G_ERR_INVALID for bad parameters. */
int object_sphere(Object *o, GVec3 center, double radius, GError *err);
int object_plane(Object *o, GVec3 point, GVec3 normal, GError *err);
int object_box(Object *o, GVec3 lo, GVec3 hi, GError *err);
int object_disc(Object *o, GVec3 center, GVec3 normal, double radius, GError *err);
int object_cylinder(Object *o, GVec3 base, GVec3 top, double radius, int open, GError *err);
int object_quad(Object *o, GVec3 corner, GVec3 edge1, GVec3 edge2, GError *err);
int object_triangle(Object *o, GVec3 a, GVec3 b, GVec3 c, GError *err);
/** A group of members (copied array; the members are borrowed and marked as parts). */
int object_group(Object *o, Object *const *members, int n, GError *err);
/** An instance of proto (borrowed, marked as a part) with o's transform and o->material as the override. */
int object_instance(Object *o, Object *proto, GError *err);
/** 1 for the kinds that are geometry themselves (not groups or instances). */
int object_is_shape(const Object *o);
/** Reads a mesh file into o: Wavefront OBJ (v, vt, vn, f with polygons as fans; usemtl/g start new surface
 * indices) here, PLY, STL and glTF 2.0 through assimp (mesh_format.h picks the reader by content; a
 * name decides only for OBJ, which has no signature).
 * A format gtrace does not read (3DS, FBX, ...) fails with G_ERR_UNSUPPORTED. Errors name the file and the
 * parameter "file" (GError.param), where a scene file's reader places them. */
int object_mesh_load(Object *o, const char *path, GError *err);
/** Where a mesh's reader may open files other than the mesh itself (a glTF's buffer files): allowed(ctx, path, err)
 * is asked before each is opened (a scene's reader answers with greader_path_allowed, for --confine) and returns
 * G_OK or a negative status with err filled; NULL allows every path. Every such file is also a regular file. */
typedef struct MeshFiles {
    int (*allowed)(void *ctx, const char *path, GError *err);
    void *ctx;
} MeshFiles;
/** object_mesh_load with the files the mesh names opened only where files allows (NULL: everywhere). */
int object_mesh_load_from(Object *o, const char *path, const MeshFiles *files, GError *err);
/** Frees a mesh and releases its budget (NULL: no-op). */
void mesh_free(Mesh *m);

#endif
