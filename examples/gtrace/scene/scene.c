/* scene.c - the scene: colour model, objects with their materials and transforms, lights, camera,
 * background and ambient light. */
#include "scene.h"
#include "accel.h"
#include "ies.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

int scene_create(const GColorModel *model, Scene **out, GError *err)
{
    *out = NULL;
    Scene *s = gmem_calloc(1, sizeof *s);
    if (!s)
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating the scene");
    s->model = model;
    camera_defaults(&s->camera);
    if (gcolor_alloc(&s->background, model) != G_OK || gcolor_alloc(&s->ambient, model) != G_OK) {
        scene_destroy(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory creating the scene");
    }
    *out = s;
    return G_OK;
}

void scene_destroy(Scene *s)
{
    if (!s)
        return;
    accel_release(s);
    if (!s->lib) {
        for (int i = 0; i < s->nobjects; i++)
            object_free(s->objects[i]);
        for (int i = 0; i < s->nlights; i++)
            light_free(s->lights[i]);
    }
    gmem_free(s->objects);
    gmem_free(s->lights);
    gmem_free(s->interiors);
    gcolor_free(&s->background);
    gcolor_free(&s->ambient);
    gmaterial_unref(s->medium);
    glibrary_destroy(s->lib);
    gcolormodel_destroy(s->owned_model);
    gmem_free(s);
}

static int grow_array(void ***items, int *cap, int n)
{
    if (n < *cap)
        return G_OK;
    int nc = *cap ? *cap * 2 : 16;
    void **ni = gmem_realloc(*items, (size_t)nc * sizeof *ni);
    if (!ni)
        return G_ERR_NOMEM;
    *items = ni;
    *cap = nc;
    return G_OK;
}

int scene_add_object(Scene *s, Object *o, GError *err)
{
    if (!o)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    if (grow_array((void ***)&s->objects, &s->cap_objects, s->nobjects) != G_OK) {
        if (!s->lib)
            object_free(o);
        return gerror_set(err, G_ERR_NOMEM, "out of memory adding an object");
    }
    s->objects[s->nobjects++] = o;
    return G_OK;
}

int scene_add_light(Scene *s, Light *l, GError *err)
{
    if (!l)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    if (grow_array((void ***)&s->lights, &s->cap_lights, s->nlights) != G_OK) {
        if (!s->lib)
            light_free(l);
        return gerror_set(err, G_ERR_NOMEM, "out of memory adding a light");
    }
    s->lights[s->nlights++] = l;
    return G_OK;
}

Object *object_new(ShapeKind kind, GMaterial *material)
{
    Object *o = gmem_calloc(1, sizeof *o);
    if (!o)
        return NULL;
    o->kind = kind;
    o->material = gmaterial_ref(material);
    xform_identity(&o->xf);
    o->expansion = 1.0;
    o->proto_index = -1;
    return o;
}

void object_free(Object *o)
{
    if (!o)
        return;
    if (o->charged)
        gmem_budget_release(object_is_shape(o) ? OBJECT_SHAPE_ACCEL_BYTES : o->placement_bytes);
    gmaterial_unref(o->material);
    if (o->kind == SHAPE_MESH)
        mesh_free(o->mesh);
    if (o->kind == SHAPE_GROUP)
        gmem_free(o->members);
    gmem_free(o);
}

Object *object_compact(Object *o)
{
    if (!o || o->kind != SHAPE_SPHERE || o->has_xf)
        return o;
    Object *c = gmem_alloc(OBJECT_HEAD_BYTES);
    if (!c) {
        object_free(o);
        return NULL;
    }
    memcpy(c, o, OBJECT_HEAD_BYTES);
    gmem_free(o); /* its material reference is c's now */
    return c;
}

/* Hands the placements a member or prototype reserved over to the object that places it. */
static void take_placements(Object *m)
{
    if (object_is_shape(m) || !m->charged)
        return;
    gmem_budget_release(m->placement_bytes);
    m->placement_bytes = 0;
}

int object_charge(Object *o, GError *err)
{
    if (o->charged || o->kind == SHAPE_MESH || o->kind == SHAPE_QUAD || o->kind == SHAPE_TRIANGLE)
        return G_OK; /* a mesh reserves its own; a quad or a triangle is a few floats in Embree */
    char what[96];
    size_t bytes = OBJECT_SHAPE_ACCEL_BYTES;
    if (!object_is_shape(o)) {
        double b = o->expansion * OBJECT_PLACEMENT_BYTES;
        bytes = b < (double)SIZE_MAX ? (size_t)b : SIZE_MAX;
        snprintf(what, sizeof what, "%s of %.6g placements", o->kind == SHAPE_GROUP ? "a group" : "an instance",
                 o->expansion);
    } else {
        snprintf(what, sizeof what, "an analytic shape's share of the acceleration structure");
    }
    int rc = gmem_budget_reserve(bytes, what, err);
    if (rc != G_OK)
        return rc;
    o->charged = 1;
    if (object_is_shape(o))
        return G_OK;
    o->placement_bytes = bytes;
    if (o->kind == SHAPE_GROUP)
        for (int i = 0; i < o->nmembers; i++)
            take_placements(o->members[i]);
    else
        take_placements(o->proto);
    return G_OK;
}

double object_expansion(const Object *o) { return object_is_shape(o) ? 1.0 : o->expansion; }

int object_nesting(const Object *o) { return object_is_shape(o) ? 0 : o->nesting; }

Light *light_new(const GColorModel *model, LightKind kind)
{
    Light *l = gmem_calloc(1, sizeof *l);
    if (!l)
        return NULL;
    if (gcolor_alloc(&l->color, model) != G_OK) {
        gmem_free(l);
        return NULL;
    }
    l->kind = kind;
    l->direction = gvec3(0, -1, 0);
    l->cos_inner = cos(20.0 * M_PI / 180.0);
    l->cos_outer = cos(30.0 * M_PI / 180.0);
    l->samples = 16;
    return l;
}

void light_free(Light *l)
{
    if (!l)
        return;
    gcolor_free(&l->color);
    if (l->ies)
        ies_free(l->ies);
    gmem_free(l->ies);
    gmem_free(l);
}

static int finite3(GVec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

int object_sphere(Object *o, GVec3 center, double radius, GError *err)
{
    if (!finite3(center) || !(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "sphere: the radius must be positive and finite");
    o->kind = SHAPE_SPHERE;
    o->center = center;
    o->radius = radius;
    return G_OK;
}

int object_plane(Object *o, GVec3 point, GVec3 normal, GError *err)
{
    if (!finite3(point) || !finite3(normal) || gvec3_length(normal) == 0.0)
        return gerror_set(err, G_ERR_INVALID, "plane: the normal must be a finite non-zero vector");
    o->kind = SHAPE_PLANE;
    o->center = point;
    o->normal = gvec3_normalize(normal);
    frame_from_normal(o->normal, &o->t1, &o->t2);
    return G_OK;
}

int object_box(Object *o, GVec3 lo, GVec3 hi, GError *err)
{
    if (!finite3(lo) || !finite3(hi) || !(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
        return gerror_set(err, G_ERR_INVALID, "box: the second corner must be above the first in x, y and z");
    o->kind = SHAPE_BOX;
    o->lo = lo;
    o->hi = hi;
    return G_OK;
}

int object_disc(Object *o, GVec3 center, GVec3 normal, double radius, GError *err)
{
    if (!finite3(center) || !finite3(normal) || gvec3_length(normal) == 0.0 || !(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "disc: needs a non-zero normal and a positive radius");
    o->kind = SHAPE_DISC;
    o->center = center;
    o->normal = gvec3_normalize(normal);
    o->radius = radius;
    frame_from_normal(o->normal, &o->t1, &o->t2);
    return G_OK;
}

int object_cylinder(Object *o, GVec3 base, GVec3 top, double radius, int open, GError *err)
{
    GVec3 axis = gvec3_sub(top, base);
    double h = gvec3_length(axis);
    if (!finite3(base) || !finite3(top) || !(h > 0.0) || !(radius > 0.0) || !isfinite(radius))
        return gerror_set(err, G_ERR_INVALID, "cylinder: needs distinct end points and a positive radius");
    o->kind = SHAPE_CYLINDER;
    o->center = base;
    o->normal = gvec3_scale(axis, 1.0 / h);
    o->height = h;
    o->radius = radius;
    o->open = open;
    frame_from_normal(o->normal, &o->t1, &o->t2);
    return G_OK;
}

int object_quad(Object *o, GVec3 corner, GVec3 edge1, GVec3 edge2, GError *err)
{
    GVec3 n = gvec3_cross(edge1, edge2);
    if (!finite3(corner) || !finite3(edge1) || !finite3(edge2) || !(gvec3_length(n) > 0.0) ||
        !isfinite(gvec3_length(n)))
        return gerror_set(err, G_ERR_INVALID, "quad: the edges must be finite and not parallel");
    o->kind = SHAPE_QUAD;
    o->center = corner;
    o->t1 = edge1;
    o->t2 = edge2;
    o->normal = gvec3_normalize(n);
    return G_OK;
}

int object_triangle(Object *o, GVec3 a, GVec3 b, GVec3 c, GError *err)
{
    GVec3 e1 = gvec3_sub(b, a), e2 = gvec3_sub(c, a), n = gvec3_cross(e1, e2);
    if (!finite3(a) || !finite3(b) || !finite3(c) || !(gvec3_length(n) > 0.0) || !isfinite(gvec3_length(n)))
        return gerror_set(err, G_ERR_INVALID, "triangle: the corners must be finite and not on one line");
    o->kind = SHAPE_TRIANGLE;
    o->center = a;
    o->t1 = e1;
    o->t2 = e2;
    o->normal = gvec3_normalize(n);
    return G_OK;
}

int object_is_shape(const Object *o) { return o->kind != SHAPE_GROUP && o->kind != SHAPE_INSTANCE; }

/* grows [lo, hi] by the world bounds of a member (cached for groups and instances, so this is O(1)) */
static void grow_by(GVec3 *lo, GVec3 *hi, const Object *m)
{
    GVec3 a, b;
    object_world_bounds(m, &a, &b);
    *lo = gvec3(fmin(lo->x, a.x), fmin(lo->y, a.y), fmin(lo->z, a.z));
    *hi = gvec3(fmax(hi->x, b.x), fmax(hi->y, b.y), fmax(hi->z, b.z));
}

int object_group(Object *o, Object *const *members, int n, GError *err)
{
    if (n < 1)
        return gerror_set(err, G_ERR_INVALID, "group: needs at least one object");
    o->members = gmem_calloc((size_t)n, sizeof *o->members);
    if (!o->members)
        return gerror_set(err, G_ERR_NOMEM, "group: out of memory for %d members", n);
    o->kind = SHAPE_GROUP;
    o->nmembers = n;
    o->lo = gvec3(INFINITY, INFINITY, INFINITY);
    o->hi = gvec3(-INFINITY, -INFINITY, -INFINITY);
    int shapes = 0, nesting = 0;
    double expansion = 0.0;
    for (int i = 0; i < n; i++) {
        Object *m = members[i];
        o->members[i] = m;
        m->is_part = 1;
        grow_by(&o->lo, &o->hi, m);
        if (object_is_shape(m)) {
            shapes = 1;
        } else {
            expansion += m->expansion;
            nesting = m->nesting > nesting ? m->nesting : nesting;
        }
    }
    o->nesting = nesting + 1;
    o->expansion = expansion + shapes;
    return G_OK;
}

int object_instance(Object *o, Object *proto, GError *err)
{
    (void)err;
    o->kind = SHAPE_INSTANCE;
    o->proto = proto;
    proto->is_part = 1;
    o->lo = gvec3(INFINITY, INFINITY, INFINITY);
    o->hi = gvec3(-INFINITY, -INFINITY, -INFINITY);
    grow_by(&o->lo, &o->hi, proto);
    o->nesting = object_nesting(proto) + 1;
    o->expansion = object_expansion(proto);
    return G_OK;
}
