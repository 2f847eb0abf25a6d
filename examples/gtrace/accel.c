/* accel.c - ray-scene intersection through Embree 3.
 *
 * The analytic shapes are user geometries: Embree's BVH finds candidates and our callbacks intersect the
 * exact shape in double precision in the object's own space (spheres stay spheres, so refraction and
 * normals are exact and no tessellation level has to be chosen). The double-precision ray travels to the
 * callbacks in an extended intersect context; the callback also keeps the exact t of the closest analytic
 * hit. Meshes are native Embree triangles with world-space vertices. */
#include "accel.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <string.h>

/* scene.h names Embree's handles without Embree's header; they must stay the types Embree hands out */
_Static_assert(_Generic(((Scene *)0)->device, RTCDevice: 1, default: 0) &&
                   _Generic(((Scene *)0)->rtc, RTCScene: 1, default: 0),
               "Scene.device and Scene.rtc are not RTCDevice and RTCScene");

typedef struct Context {
    struct RTCIntersectContext rtc; /* first: Embree hands this pointer back to the callbacks */
    const Ray *ray;
    double best_t;
    unsigned best_geom;
} Context;

static void to_object(const Object *o, const Ray *r, GVec3 *ro, GVec3 *rd)
{
    if (o->has_xf) {
        *ro = xform_inv_point(&o->xf, r->o);
        *rd = xform_inv_vector(&o->xf, r->d);
    } else {
        *ro = r->o;
        *rd = r->d;
    }
}

static void user_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const Object *o = args->geometryUserPtr;
    GVec3 wlo, whi;
    object_world_bounds(o, &wlo, &whi);
    /* pad by a relative epsilon so flat shapes and float rounding do not lose hits */
    double pad = 1e-6 * (1.0 + fmax(fmax(fabs(wlo.x), fabs(whi.x)), fmax(fmax(fabs(wlo.y), fabs(whi.y)),
                                                                      fmax(fabs(wlo.z), fabs(whi.z)))));
    struct RTCBounds *b = args->bounds_o;
    b->lower_x = (float)(wlo.x - pad);
    b->lower_y = (float)(wlo.y - pad);
    b->lower_z = (float)(wlo.z - pad);
    b->upper_x = (float)(whi.x + pad);
    b->upper_y = (float)(whi.y + pad);
    b->upper_z = (float)(whi.z + pad);
}

static void user_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    if (args->N != 1 || !args->valid[0])
        return;
    const Object *o = args->geometryUserPtr;
    Context *cx = (Context *)args->context;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    GVec3 ro, rd;
    to_object(o, cx->ray, &ro, &rd);
    double tmax = fmin((double)rh->ray.tfar, cx->best_t);
    double t;
    int surface;
    if (!shape_intersect(o, ro, rd, cx->ray->tmin, tmax, &t, &surface))
        return;
    rh->ray.tfar = (float)t;
    rh->hit.u = (float)surface;
    rh->hit.v = 0.0f;
    rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0.0f;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
    cx->best_t = t;
    cx->best_geom = args->geomID;
}

static void user_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    if (args->N != 1 || !args->valid[0])
        return;
    const Object *o = args->geometryUserPtr;
    Context *cx = (Context *)args->context;
    struct RTCRay *ray = (struct RTCRay *)args->ray;
    GVec3 ro, rd;
    to_object(o, cx->ray, &ro, &rd);
    double t;
    int surface;
    if (shape_intersect(o, ro, rd, cx->ray->tmin, cx->ray->tmax, &t, &surface))
        ray->tfar = -INFINITY;
}

static int add_mesh(Scene *s, Object *o, GError *err)
{
    const Mesh *m = o->mesh;
    RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a triangle geometry");
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                       (size_t)m->nverts);
    unsigned *idx = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                            (size_t)m->ntris);
    if (!v || !idx) {
        rtcReleaseGeometry(g);
        return gerror_set(err, G_ERR_NOMEM, "embree: out of memory for a mesh of %d triangles", m->ntris);
    }
    for (int i = 0; i < m->nverts; i++) {
        GVec3 p = gvec3(m->pos[3 * i], m->pos[3 * i + 1], m->pos[3 * i + 2]);
        if (o->has_xf)
            p = xform_point(&o->xf, p);
        v[3 * i] = (float)p.x;
        v[3 * i + 1] = (float)p.y;
        v[3 * i + 2] = (float)p.z;
    }
    memcpy(idx, m->tri, (size_t)m->ntris * 3 * sizeof(unsigned));
    rtcCommitGeometry(g);
    o->geom_id = rtcAttachGeometry(s->rtc, g);
    rtcReleaseGeometry(g);
    return G_OK;
}

static int add_user(Scene *s, Object *o, GError *err)
{
    RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_USER);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a user geometry");
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryUserData(g, o);
    rtcSetGeometryBoundsFunction(g, user_bounds, NULL);
    rtcSetGeometryIntersectFunction(g, user_intersect);
    rtcSetGeometryOccludedFunction(g, user_occluded);
    rtcCommitGeometry(g);
    o->geom_id = rtcAttachGeometry(s->rtc, g);
    rtcReleaseGeometry(g);
    return G_OK;
}

int accel_build(Scene *s, GError *err)
{
    accel_release(s);
    s->device = rtcNewDevice(NULL);
    if (!s->device)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a device (error %d)", (int)rtcGetDeviceError(NULL));
    s->rtc = rtcNewScene(s->device);
    rtcSetSceneBuildQuality(s->rtc, RTC_BUILD_QUALITY_HIGH);
    unsigned maxid = 0;
    for (int i = 0; i < s->nobjects; i++) {
        Object *o = s->objects[i];
        int rc = o->kind == SHAPE_MESH ? add_mesh(s, o, err) : add_user(s, o, err);
        if (rc != G_OK) {
            accel_release(s);
            return rc;
        }
        if (o->geom_id + 1 > maxid)
            maxid = o->geom_id + 1;
    }
    rtcCommitScene(s->rtc);
    enum RTCError e = rtcGetDeviceError(s->device);
    if (e != RTC_ERROR_NONE) {
        accel_release(s);
        return gerror_set(err, G_ERR_INVALID, "embree: scene build failed (error %d)", (int)e);
    }
    s->by_geom = gmem_calloc(maxid ? maxid : 1, sizeof *s->by_geom);
    if (!s->by_geom) {
        accel_release(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    s->nby_geom = maxid;
    for (int i = 0; i < s->nobjects; i++)
        s->by_geom[s->objects[i]->geom_id] = s->objects[i];
    return G_OK;
}

void accel_release(Scene *s)
{
    if (s->rtc)
        rtcReleaseScene(s->rtc);
    if (s->device)
        rtcReleaseDevice(s->device);
    s->rtc = NULL;
    s->device = NULL;
    gmem_free(s->by_geom);
    s->by_geom = NULL;
    s->nby_geom = 0;
}

static void make_ray(const Ray *r, struct RTCRay *ray)
{
    ray->org_x = (float)r->o.x;
    ray->org_y = (float)r->o.y;
    ray->org_z = (float)r->o.z;
    ray->dir_x = (float)r->d.x;
    ray->dir_y = (float)r->d.y;
    ray->dir_z = (float)r->d.z;
    ray->tnear = (float)r->tmin;
    ray->tfar = r->tmax < 3.0e38 ? (float)r->tmax : INFINITY;
    ray->time = 0.0f;
    ray->mask = 0xffffffffu;
    ray->id = 0;
    ray->flags = 0;
}

/* Embree asserts (and ends the process) on a ray it cannot trace: an origin or direction that is not finite
 * or beyond about 1.8e18. Scenes are refused beyond SCENE_MAX_COORD when they are read; a ray that still gets
 * here so (a NaN from a material's direction) hits nothing. */
static int traceable(const Ray *r)
{
    const double big = 1.0e18;
    return fabs(r->o.x) < big && fabs(r->o.y) < big && fabs(r->o.z) < big && fabs(r->d.x) < big &&
           fabs(r->d.y) < big && fabs(r->d.z) < big && r->tmin >= 0.0 && r->tmin < 3.0e38 && !(r->tmax < r->tmin);
}

int accel_intersect(const Scene *s, const Ray *r, Hit *h)
{
    if (!traceable(r))
        return 0;
    Context cx;
    rtcInitIntersectContext(&cx.rtc);
    cx.ray = r;
    cx.best_t = INFINITY;
    cx.best_geom = RTC_INVALID_GEOMETRY_ID;
    struct RTCRayHit rh;
    make_ray(r, &rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s->rtc, &cx.rtc, &rh);
    unsigned id = rh.hit.geomID;
    if (id == RTC_INVALID_GEOMETRY_ID || id >= s->nby_geom)
        return 0;
    h->obj = s->by_geom[id];
    h->prim = rh.hit.primID;
    if (h->obj->kind == SHAPE_MESH) {
        h->t = rh.ray.tfar;
        h->bu = rh.hit.u;
        h->bv = rh.hit.v;
        h->surface = 0;
    } else {
        h->t = id == cx.best_geom ? cx.best_t : rh.ray.tfar;
        h->bu = h->bv = 0.0;
        h->surface = (int)rh.hit.u;
    }
    return 1;
}

int accel_occluded(const Scene *s, const Ray *r)
{
    if (!traceable(r))
        return 0;
    Context cx;
    rtcInitIntersectContext(&cx.rtc);
    cx.ray = r;
    cx.best_t = INFINITY;
    cx.best_geom = RTC_INVALID_GEOMETRY_ID;
    struct RTCRay ray;
    make_ray(r, &ray);
    rtcOccluded1(s->rtc, &cx.rtc, &ray);
    return ray.tfar < 0.0f;
}
