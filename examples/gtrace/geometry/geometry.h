/* geometry.h - intersection with a shape and the surface at a hit (shapes.c, mesh.c). */
#ifndef GTRACE_GEOMETRY_H
#define GTRACE_GEOMETRY_H

#include "object.h"
#include "ray.h"

#include <generic/vec.h>

#include <math.h>

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
    GVec3 odpdu, odpdv; /**< tangents in object space, set only with object_tangents */
    int object_tangents; /**< 1 when the object's space is not world space (a transform, an instance): odpdu and
                              odpdv are then the tangents there; 0: they equal dpdu and dpdv and are not set */
    double u, v;
    int surface;
    int want_uv; /**< set by hit_geom: 0 when (u, v) and the tangents are not wanted (GMAT_NO_UV) and may be left
                      zero (a shape whose (u, v) cost a call skips them; the others fill them anyway) */
} HitGeom;

/** Half size of a plane's bounded extent in its own units. */
#define SHAPE_PLANE_EXTENT 1.0e5
/** Largest coordinate a scene may reach, in world space after transforms: every object's extent, every
 * light's position and the camera lie within [-SCENE_MAX_COORD, SCENE_MAX_COORD] in x, y and z. Embree traces
 * single-precision rays and stops the process on an origin beyond about 1.8e18; 1e15 keeps a margin, and
 * float positions there are already 1e8 units apart. */
#define SCENE_MAX_COORD 1.0e15

/** a t^2 + 2 b t + c = 0: 1 with the roots in ascending order (computed without cancellation), 0 for none. */
static inline int shape_solve_quadratic(double a, double b, double c, double *t0, double *t1)
{
    double disc = b * b - a * c;
    if (disc < 0.0 || a == 0.0)
        return 0;
    double q = -(b + copysign(sqrt(disc), b));
    double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
    *t0 = gfmin(r0, r1);
    *t1 = gfmax(r0, r1);
    return 1;
}

/** The first of t0 <= t1 inside (tmin, tmax) into *t: 1, or 0 for neither. */
static inline int shape_pick(double t0, double t1, double tmin, double tmax, double *t)
{
    if (t0 > tmin && t0 < tmax) {
        *t = t0;
        return 1;
    }
    if (t1 > tmin && t1 < tmax) {
        *t = t1;
        return 1;
    }
    return 0;
}

/** A sphere in its own space (shape_intersect's case, inline for the direct list of accel_direct.c); tmin >= 0.
 * A ray leaving the sphere's centre from outside it (b > 0, c >= 0: a ray from a point of its surface, as its
 * shadow and reflected rays are) is a miss without the square root and the divisions: both roots are then <= 0
 * (q < 0, so q / a <= 0 and c / q <= 0; no NaN, as b and c are finite), neither beyond tmin. */
static inline int shape_hit_sphere(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t)
{
    GVec3 oc = gvec3_sub(ro, o->center);
    double b = gvec3_dot(oc, rd), c = gvec3_dot(oc, oc) - o->radius * o->radius, t0, t1;
    if ((b > 0.0 && c >= 0.0) || !shape_solve_quadratic(gvec3_dot(rd, rd), b, c, &t0, &t1))
        return 0;
    return shape_pick(t0, t1, tmin, tmax, t);
}

/** A plane (bounded at SHAPE_PLANE_EXTENT) in its own space (as shape_hit_sphere). */
static inline int shape_hit_plane(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t)
{
    double dn = gvec3_dot(rd, o->normal);
    if (dn == 0.0)
        return 0;
    double th = gvec3_dot(gvec3_sub(o->center, ro), o->normal) / dn;
    if (!(th > tmin && th < tmax))
        return 0;
    GVec3 d = gvec3_sub(gvec3_madd(ro, rd, th), o->center);
    if (fabs(gvec3_dot(d, o->t1)) > SHAPE_PLANE_EXTENT || fabs(gvec3_dot(d, o->t2)) > SHAPE_PLANE_EXTENT)
        return 0;
    *t = th;
    return 1;
}

/** Object-space ray-shape intersection in (tmin, tmax), tmin >= 0 (a traceable ray's: accel.c); 1 with *t and
 * *surface when hit. */
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
/** Surface details of an analytic shape at a hit (g->want_uv as hit_geom set it). */
void shape_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);
/** Surface details at any hit in world space (through its instance, if any); without want_uv, (u, v) and the
 * tangents may be left zero. */
void hit_geom(const Ray *r, const Hit *h, int want_uv, HitGeom *g);
/** Surface details of a mesh triangle at a hit (g->want_uv as hit_geom set it). */
void mesh_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);
/** hit_geom_to_world's part for an object with a transform: g->p and the normals, and (when g->want_uv) the
 * tangents, from the object's space to world space. */
void hit_geom_transform(const Object *o, HitGeom *g);

/** Brings g from the object's space to world space in place: g->op, n_out, n_smooth, dpdu and dpdv hold the
 * object-space point, outward normal, shading normal and tangents; sets g->p and, for a transformed object, keeps
 * the tangents in odpdu and odpdv (object_tangents) and turns the normals and (when g->want_uv) the tangents to
 * world space; u, v and the surface are the caller's. Inline: called, it reloaded the vectors its caller had just
 * stored (a store-forwarding stall, 2.5% of the samples of bench-pov's render); and an untransformed object's
 * tangents are not copied to odpdu, for the same reason (surface points leave object_dpdu zero for them, which
 * surfpoint.h defines as equal to dpdu). */
static inline void hit_geom_to_world(const Object *o, HitGeom *g)
{
    g->object_tangents = o->has_xf;
    if (o->has_xf)
        hit_geom_transform(o, g);
    else
        g->p = g->op;
}

#endif
