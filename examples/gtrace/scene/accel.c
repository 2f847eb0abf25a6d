/* accel.c - ray-scene intersection through Embree 3.
 *
 * The analytic shapes are user geometries: Embree's BVH finds candidates and our callbacks intersect the
 * exact shape in double precision in the object's own space (spheres stay spheres, so refraction and
 * normals are exact and no tessellation level has to be chosen). The double-precision ray travels to the
 * callbacks in an extended intersect context; the callback also keeps the exact t of the closest analytic
 * hit. Meshes, quads and triangles are Embree's own triangles and quads.
 *
 * Groups and instances: every group's shapes (and every shape an instance places directly) form one
 * prototype, an Embree scene built once; each placement of a prototype is an Embree instance of it in the
 * top-level scene. Embree 3 as Debian builds it has one instance level (RTC_MAX_INSTANCE_LEVEL_COUNT 1), so
 * nested groups and instances are flattened: their transforms are composed and each path to a prototype is
 * one instance (the prototypes' BVHs are still shared). The shapes' callbacks take the double-precision ray
 * through the placement's own transform, not Embree's float one.
 *
 * A scene of a few analytic shapes is traced without Embree, through the direct list of accel_direct.c; Embree's
 * device is then not made at all (its thread pool and arenas: 1.9 MB of the bench scene's 15.7 MB peak RSS), and
 * s->rtc stays NULL. */
#include "accel.h"
#include "accel_direct.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* scene.h names Embree's handles without Embree's header; they must stay the types Embree hands out */
_Static_assert(_Generic(((Scene *)0)->device, RTCDevice: 1, default: 0) &&
                   _Generic(((Scene *)0)->rtc, RTCScene: 1, default: 0),
               "Scene.device and Scene.rtc are not RTCDevice and RTCScene");

typedef struct Context {
    struct RTCIntersectContext rtc; /* first: Embree hands this pointer back to the callbacks */
    const Scene *scene;
    const Ray *ray;
    double best_t;
    unsigned best_geom, best_prim, best_inst;
    int stopped;  /* occlusion: a surface that blocks all light ended the query */
    int passable; /* occlusion: a surface that may let light through ended it (the walk of lights.c decides) */
} Context;

/* 1 when a surface of material m may let light through somewhere (a shadow ray must then walk its hits). */
static int may_pass_light(const GMaterial *m) { return !gmaterial_opaque_everywhere(m); }

/* A prototype: the Embree scene of a group's shapes (or of one instanced shape), built once however often
 * it is placed, and its geometry id -> object table. */
typedef struct AccelProto {
    RTCScene rtc;
    Object **by_geom;
    unsigned nby_geom;
    ShapeBatch user; /* its analytic shapes: one user geometry */
} AccelProto;

/* The placement of the instance Embree is inside (NULL: the top-level scene). */
static const Instance *context_instance(const Context *cx)
{
    unsigned id = cx->rtc.instID[0];
    if (id == RTC_INVALID_GEOMETRY_ID || id >= cx->scene->nby_geom)
        return NULL;
    return &cx->scene->inst_by_geom[id];
}

/* The ray in o's own space: through the placement (prototype space), then the object's transform. */
static void to_object(const Object *o, const Instance *in, const Ray *r, GVec3 *ro, GVec3 *rd)
{
    *ro = r->o;
    *rd = r->d;
    if (in) {
        *ro = xform_inv_point(&in->xf, *ro);
        *rd = xform_inv_vector(&in->xf, *rd);
    }
    if (o->has_xf) {
        *ro = xform_inv_point(&o->xf, *ro);
        *rd = xform_inv_vector(&o->xf, *rd);
    }
}

/* The analytic shape of primitive `prim` of a user geometry (its user data is the batch's array of shapes). */
static const Object *user_shape(void *user, unsigned prim) { return ((Object *const *)user)[prim]; }

static void user_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const Object *o = user_shape(args->geometryUserPtr, args->primID);
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
    const Object *o = user_shape(args->geometryUserPtr, args->primID);
    Context *cx = (Context *)args->context;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    GVec3 ro, rd;
    to_object(o, context_instance(cx), cx->ray, &ro, &rd);
    double tmax = gfmin((double)rh->ray.tfar, cx->best_t);
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
    cx->best_prim = args->primID;
    cx->best_inst = args->context->instID[0];
}

static void user_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    if (args->N != 1 || !args->valid[0])
        return;
    const Object *o = user_shape(args->geometryUserPtr, args->primID);
    Context *cx = (Context *)args->context;
    struct RTCRay *ray = (struct RTCRay *)args->ray;
    GVec3 ro, rd;
    const Instance *in = context_instance(cx);
    to_object(o, in, cx->ray, &ro, &rd);
    double t;
    int surface;
    if (!shape_intersect(o, ro, rd, cx->ray->tmin, cx->ray->tmax, &t, &surface))
        return;
    /* either ends the query: past a surface that may let light through, the walk of lights.c decides (going on
     * to look for an opaque one behind it would cost every glass surface on the way twice) */
    if (may_pass_light(in && in->material ? in->material : o->material))
        cx->passable = 1;
    else
        cx->stopped = 1;
    ray->tfar = -INFINITY;
}

/* Attaches a new geometry to the Embree scene `into` and returns its id through *id. */
static int attach(RTCGeometry g, RTCScene into, unsigned *id)
{
    rtcCommitGeometry(g);
    *id = rtcAttachGeometry(into, g);
    rtcReleaseGeometry(g);
    return G_OK;
}

/* A point of o in the space of the scene it is attached to (its own transform applied). */
static void put_vertex(const Object *o, GVec3 p, float *v)
{
    if (o->has_xf)
        p = xform_point(&o->xf, p);
    v[0] = (float)p.x;
    v[1] = (float)p.y;
    v[2] = (float)p.z;
}

static int add_mesh(Scene *s, RTCScene into, Object *o, unsigned *id, GError *err)
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
    for (int i = 0; i < m->nverts; i++)
        put_vertex(o, gvec3(m->pos[3 * i], m->pos[3 * i + 1], m->pos[3 * i + 2]), v + 3 * i);
    memcpy(idx, m->tri, (size_t)m->ntris * 3 * sizeof(unsigned));
    return attach(g, into, id);
}

/* A quad or a triangle as one primitive of Embree's own type: corners center, +t1, (+t1+t2,) +t2, so that
 * Embree's hit (u, v) are the shape's parameters along t1 and t2. */
static int add_flat(Scene *s, RTCScene into, Object *o, unsigned *id, GError *err)
{
    int quad = o->kind == SHAPE_QUAD, nv = quad ? 4 : 3;
    RTCGeometry g = rtcNewGeometry(s->device, quad ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a %s geometry", quad ? "quad" : "triangle");
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), (size_t)nv);
    unsigned *idx = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, quad ? RTC_FORMAT_UINT4 : RTC_FORMAT_UINT3,
                                            (size_t)nv * sizeof(unsigned), 1);
    if (!v || !idx) {
        rtcReleaseGeometry(g);
        return gerror_set(err, G_ERR_NOMEM, "embree: out of memory");
    }
    GVec3 c = o->center, a = gvec3_add(c, o->t1), b = gvec3_add(c, o->t2);
    put_vertex(o, c, v);
    put_vertex(o, a, v + 3);
    if (quad) {
        put_vertex(o, gvec3_add(a, o->t2), v + 6);
        put_vertex(o, b, v + 9);
    } else {
        put_vertex(o, b, v + 6);
    }
    for (int i = 0; i < nv; i++)
        idx[i] = (unsigned)i;
    return attach(g, into, id);
}

/* Adds an analytic shape to the batch of the Embree scene being filled (its primitive number is its index). */
static int batch_add(ShapeBatch *b, Object *o, GError *err)
{
    if (b->n == b->cap) {
        unsigned nc = b->cap ? 2 * b->cap : 16;
        Object **ns = gmem_realloc(b->shapes, (size_t)nc * sizeof *ns);
        if (!ns)
            return gerror_set(err, G_ERR_NOMEM, "out of memory for %u analytic shapes", b->n + 1);
        b->shapes = ns;
        b->cap = nc;
    }
    b->shapes[b->n++] = o;
    return G_OK;
}

/* Attaches the batch's shapes to `into` as one user geometry (none when the batch is empty); the batch's array is
 * Embree's user data from here on and must not move. */
static int batch_attach(Scene *s, RTCScene into, ShapeBatch *b, GError *err)
{
    b->geom_id = RTC_INVALID_GEOMETRY_ID;
    if (!b->n)
        return G_OK;
    RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_USER);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a user geometry");
    rtcSetGeometryUserPrimitiveCount(g, b->n);
    rtcSetGeometryUserData(g, b->shapes);
    rtcSetGeometryBoundsFunction(g, user_bounds, NULL);
    rtcSetGeometryIntersectFunction(g, user_intersect);
    rtcSetGeometryOccludedFunction(g, user_occluded);
    return attach(g, into, &b->geom_id);
}

/* A shape of the batch b by its Embree ids, or NULL when they name none. */
static const Object *batch_shape(const ShapeBatch *b, unsigned geom, unsigned prim)
{
    return geom == b->geom_id && prim < b->n ? b->shapes[prim] : NULL;
}

static void batch_free(ShapeBatch *b)
{
    gmem_free(b->shapes);
    memset(b, 0, sizeof *b);
    b->geom_id = RTC_INVALID_GEOMETRY_ID;
}

/* 1 for the shapes Embree intersects itself (meshes, quads, triangles); the others are the user geometry's. */
static int native_shape(const Object *o)
{
    return o->kind == SHAPE_MESH || o->kind == SHAPE_QUAD || o->kind == SHAPE_TRIANGLE;
}

/* Adds one of Embree's own shapes (native_shape) to `into` as a geometry of its own. */
static int add_native(Scene *s, RTCScene into, Object *o, unsigned *id, GError *err)
{
    /* Embree ends an occlusion query on these itself, whatever their material */
    s->native_may_pass |= may_pass_light(o->material);
    return o->kind == SHAPE_MESH ? add_mesh(s, into, o, id, err) : add_flat(s, into, o, id, err);
}

/* Makes room for geometry id `id` in a table of objects (and placements when inst is not NULL). */
static int table_fit(Object ***objs, Instance **inst, unsigned *n, unsigned id)
{
    if (id < *n)
        return G_OK;
    unsigned nn = *n ? *n : 16;
    while (nn <= id)
        nn *= 2;
    Object **no = gmem_realloc(*objs, (size_t)nn * sizeof *no);
    if (!no)
        return G_ERR_NOMEM;
    *objs = no;
    if (inst) {
        Instance *ni = gmem_realloc(*inst, (size_t)nn * sizeof *ni);
        if (!ni)
            return G_ERR_NOMEM;
        *inst = ni;
    }
    for (unsigned i = *n; i < nn; i++) {
        no[i] = NULL;
        if (inst)
            (*inst)[i].proto = -1;
    }
    *n = nn;
    return G_OK;
}

/* Adds a shape to a prototype's Embree scene (one of Embree's own) or its batch (an analytic one). */
static int proto_add(Scene *s, AccelProto *p, Object *o, GError *err)
{
    if (!native_shape(o))
        return batch_add(&p->user, o, err);
    unsigned id;
    int rc = add_native(s, p->rtc, o, &id, err);
    if (rc == G_OK && table_fit(&p->by_geom, NULL, &p->nby_geom, id) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
    if (rc == G_OK)
        p->by_geom[id] = o;
    return rc;
}

/* The prototype of a group (its shapes) or of an instanced shape, built on first use. */
static int proto_of(Scene *s, Object *o, GError *err)
{
    if (o->proto_index >= 0)
        return o->proto_index;
    if (s->nprotos == s->cap_protos) {
        int nc = s->cap_protos ? 2 * s->cap_protos : 8;
        AccelProto *np = gmem_realloc(s->protos, (size_t)nc * sizeof *np);
        if (!np)
            return gerror_set(err, G_ERR_NOMEM, "out of memory");
        s->protos = np;
        s->cap_protos = nc;
    }
    AccelProto *p = &s->protos[s->nprotos];
    memset(p, 0, sizeof *p);
    batch_free(&p->user);
    p->rtc = rtcNewScene(s->device);
    if (!p->rtc)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a scene");
    s->nprotos++;
    rtcSetSceneBuildQuality(p->rtc, RTC_BUILD_QUALITY_HIGH);
    int rc = G_OK;
    if (o->kind == SHAPE_GROUP) {
        for (int i = 0; i < o->nmembers && rc == G_OK; i++)
            if (object_is_shape(o->members[i]))
                rc = proto_add(s, p, o->members[i], err);
    } else {
        rc = proto_add(s, p, o, err);
    }
    if (rc == G_OK)
        rc = batch_attach(s, p->rtc, &p->user, err);
    if (rc < 0)
        return rc;
    rtcCommitScene(p->rtc);
    o->proto_index = s->nprotos - 1;
    return o->proto_index;
}

/* Places prototype `proto` at xf in the top-level scene. */
static int place(Scene *s, int proto, const Xform *xf, const GMaterial *material, GError *err)
{
    if (s->ninstances >= GTRACE_MAX_INSTANCES)
        return gerror_set(err, G_ERR_INVALID, "the scene expands to more than %d instances", GTRACE_MAX_INSTANCES);
    s->ninstances++;
    /* Embree takes the placement in single precision and inverts it: refuse what a float cannot carry */
    float m[12];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            if (!(fabs(xf->m[i][j]) <= 1e30))
                return gerror_set(err, G_ERR_INVALID, "a placement's transform has an entry of %g, beyond 1e30 "
                                  "(Embree's instances are single precision)", xf->m[i][j]);
            m[4 * i + j] = (float)xf->m[i][j];
        }
    double det = (double)m[0] * ((double)m[5] * m[10] - (double)m[6] * m[9]) -
                 (double)m[1] * ((double)m[4] * m[10] - (double)m[6] * m[8]) +
                 (double)m[2] * ((double)m[4] * m[9] - (double)m[5] * m[8]);
    if (!(fabs(det) > 1e-36))
        return gerror_set(err, G_ERR_INVALID, "a placement's transform is singular in single precision "
                          "(determinant %g; Embree's instances are single precision)", det);
    RTCGeometry g = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_INSTANCE);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create an instance");
    rtcSetGeometryInstancedScene(g, s->protos[proto].rtc);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
    unsigned id;
    attach(g, s->rtc, &id);
    if (table_fit(&s->by_geom, &s->inst_by_geom, &s->nby_geom, id) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    if (material && may_pass_light(material))
        s->native_may_pass = 1; /* an override that may reach Embree's own shapes of the prototype */
    Instance *in = &s->inst_by_geom[id];
    in->xf = *xf;
    in->material = material;
    in->proto = proto;
    return G_OK;
}

/* Places a group or an instance (and everything nested in it) under the transform `parent`. */
static int flatten(Scene *s, Object *o, const Xform *parent, const GMaterial *override, int depth, GError *err)
{
    if (depth > GTRACE_MAX_NESTING)
        return gerror_set(err, G_ERR_INVALID, "groups and instances nest deeper than %d", GTRACE_MAX_NESTING);
    Xform xf = *parent;
    if (o->has_xf)
        xform_compose(parent, &o->xf, &xf);
    if (o->kind == SHAPE_INSTANCE) {
        const GMaterial *m = override ? override : o->material;
        Object *p = o->proto;
        if (!object_is_shape(p))
            return flatten(s, p, &xf, m, depth + 1, err);
        int k = proto_of(s, p, err);
        return k < 0 ? k : place(s, k, &xf, m, err);
    }
    int shapes = 0, rc = G_OK;
    for (int i = 0; i < o->nmembers && rc == G_OK; i++) {
        if (object_is_shape(o->members[i]))
            shapes = 1;
        else
            rc = flatten(s, o->members[i], &xf, override, depth + 1, err);
    }
    if (rc == G_OK && shapes) {
        int k = proto_of(s, o, err);
        rc = k < 0 ? k : place(s, k, &xf, override, err);
    }
    return rc;
}

static int build_objects(Scene *s, GError *err)
{
    double expansion = 0.0;
    for (int i = 0; i < s->nobjects; i++) {
        s->objects[i]->proto_index = -1;
        if (!s->objects[i]->is_part && !object_is_shape(s->objects[i]))
            expansion += s->objects[i]->expansion;
    }
    if (expansion > GTRACE_MAX_INSTANCES)
        return gerror_set(err, G_ERR_INVALID, "the scene's groups and instances expand to %.6g placements, more than "
                          "the limit of %d", expansion, GTRACE_MAX_INSTANCES);
    Xform id;
    xform_identity(&id);
    for (int i = 0; i < s->nobjects; i++) {
        Object *o = s->objects[i];
        if (o->is_part)
            continue;
        int rc;
        if (object_is_shape(o) && !native_shape(o)) {
            rc = batch_add(&s->user, o, err);
        } else if (object_is_shape(o)) {
            unsigned gid;
            rc = add_native(s, s->rtc, o, &gid, err);
            if (rc == G_OK && table_fit(&s->by_geom, &s->inst_by_geom, &s->nby_geom, gid) != G_OK)
                rc = gerror_set(err, G_ERR_NOMEM, "out of memory");
            if (rc == G_OK)
                s->by_geom[gid] = o;
        } else {
            rc = flatten(s, o, &id, NULL, 1, err);
        }
        if (rc < 0)
            return rc;
    }
    return batch_attach(s, s->rtc, &s->user, err);
}

/* The top-level BVH's quality. Embree's high-quality build (spatial splits) costs about 1.4 us of CPU per
 * triangle more than the medium one and saves some 10% of the tracing: for the 1M-triangle mesh of bench-pov at
 * 800x600 and 1 sample per pixel the medium build halves the process's CPU (2.9 to 1.4 s) and leaves the render
 * time within noise. So the high build is chosen when the image's camera samples (width x height x spp of the
 * whole image, a crop's or an MPI rank's share aside, so that every piece builds alike) are at least 10 per
 * primitive of the top-level scene, the low one (Embree's Morton-code build) when they are fewer than 1 per 10
 * primitives, the medium one between. For 1M spheres rendered at 1x1 (bench/scale.sh) the low build takes the
 * process's CPU from 2.2 to 1.9 s and its peak RSS from 286 to 223 MB; the hits are the same (the user geometry's
 * callbacks decide them exactly), only the order in which Embree visits candidates differs. */
static enum RTCBuildQuality top_quality(const Scene *s, double samples)
{
    double prims = 0.0;
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (!o->is_part && object_is_shape(o))
            prims += o->kind == SHAPE_MESH ? o->mesh->ntris : 1;
    }
    if (samples >= 10.0 * prims)
        return RTC_BUILD_QUALITY_HIGH;
    return 10.0 * samples >= prims ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_LOW;
}

int accel_build(Scene *s, GError *err)
{
    return accel_build_for(s, (double)s->camera.width * s->camera.height * s->camera.spp, err);
}

int accel_build_for(Scene *s, double samples, GError *err)
{
    accel_release(s);
    int rc = accel_direct_build(s, err);
    if (rc < 0 || s->direct) /* traced through the direct list: no Embree */
        return rc;
    char config[32] = ""; /* Embree's own thread pool obeys --threads too (its BVH build is parallel) */
    if (s->accel_threads > 0)
        snprintf(config, sizeof config, "threads=%d", s->accel_threads);
    s->device = rtcNewDevice(config[0] ? config : NULL);
    if (!s->device)
        return gerror_set(err, G_ERR_NOMEM, "embree: cannot create a device (error %d)", (int)rtcGetDeviceError(NULL));
    s->rtc = rtcNewScene(s->device);
    rtcSetSceneBuildQuality(s->rtc, top_quality(s, samples));
    rc = build_objects(s, err);
    if (rc < 0) {
        accel_release(s);
        return rc;
    }
    rtcCommitScene(s->rtc);
    enum RTCError e = rtcGetDeviceError(s->device);
    if (e != RTC_ERROR_NONE) {
        accel_release(s);
        return gerror_set(err, G_ERR_INVALID, "embree: scene build failed (error %d)", (int)e);
    }
    if (!s->by_geom && table_fit(&s->by_geom, &s->inst_by_geom, &s->nby_geom, 0) != G_OK) {
        accel_release(s);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    return G_OK;
}

void accel_release(Scene *s)
{
    accel_direct_release(s);
    for (int i = 0; i < s->nprotos; i++) {
        rtcReleaseScene(s->protos[i].rtc);
        gmem_free(s->protos[i].by_geom);
        batch_free(&s->protos[i].user);
    }
    gmem_free(s->protos);
    s->protos = NULL;
    s->nprotos = s->cap_protos = 0;
    s->ninstances = 0;
    s->native_may_pass = 0;
    if (s->rtc)
        rtcReleaseScene(s->rtc);
    if (s->device)
        rtcReleaseDevice(s->device);
    s->rtc = NULL;
    s->device = NULL;
    batch_free(&s->user);
    gmem_free(s->by_geom);
    gmem_free(s->inst_by_geom);
    s->by_geom = NULL;
    s->inst_by_geom = NULL;
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
 * here so (a NaN from a material's direction) hits nothing. One sum of the six magnitudes, in scalars: it is
 * below 1e18 only when each is (a NaN or an infinity makes it fail). Loading the fields two at a time read
 * across the separate 8-byte stores that had just written them (a store-forwarding stall: 8% of the time samples
 * sat on it; about 1% of a render's time came back). Inlined into both queries: a call of its own cost a third of
 * its instructions. */
static inline __attribute__((always_inline)) int traceable(const Ray *r)
{
    double m = fabs(r->o.x) + fabs(r->o.y) + fabs(r->o.z) + fabs(r->d.x) + fabs(r->d.y) + fabs(r->d.z);
    return m < 1.0e18 && r->tmin >= 0.0 && r->tmin < 3.0e38 && !(r->tmax < r->tmin);
}

int accel_intersect(const Scene *s, const Ray *r, Hit *h)
{
    if (!traceable(r))
        return 0;
    if (s->direct)
        return accel_direct_intersect(s, r, h);
    Context cx;
    rtcInitIntersectContext(&cx.rtc);
    cx.scene = s;
    cx.ray = r;
    cx.best_t = INFINITY;
    cx.best_geom = cx.best_prim = cx.best_inst = RTC_INVALID_GEOMETRY_ID;
    struct RTCRayHit rh;
    make_ray(r, &rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s->rtc, &cx.rtc, &rh);
    unsigned id = rh.hit.geomID, inst = rh.hit.instID[0];
    if (id == RTC_INVALID_GEOMETRY_ID)
        return 0;
    h->inst = NULL;
    unsigned prim = rh.hit.primID;
    if (inst != RTC_INVALID_GEOMETRY_ID) {
        if (inst >= s->nby_geom || s->inst_by_geom[inst].proto < 0)
            return 0;
        h->inst = &s->inst_by_geom[inst];
        const AccelProto *p = &s->protos[h->inst->proto];
        h->obj = batch_shape(&p->user, id, prim);
        if (!h->obj && id < p->nby_geom)
            h->obj = p->by_geom[id];
    } else {
        h->obj = batch_shape(&s->user, id, prim);
        if (!h->obj && id < s->nby_geom)
            h->obj = s->by_geom[id];
    }
    if (!h->obj)
        return 0;
    h->material = h->inst && h->inst->material ? h->inst->material : h->obj->material;
    if (native_shape(h->obj)) {
        h->prim = prim;
        h->t = rh.ray.tfar;
        h->bu = rh.hit.u;
        h->bv = rh.hit.v;
        h->surface = 0;
    } else {
        h->prim = 0; /* an analytic shape is one primitive of its own */
        h->t = id == cx.best_geom && prim == cx.best_prim && inst == cx.best_inst ? cx.best_t : rh.ray.tfar;
        h->bu = h->bv = 0.0;
        h->surface = (int)rh.hit.u;
    }
    return 1;
}

int accel_occluded(const Scene *s, const Ray *r)
{
    if (!traceable(r))
        return 0;
    if (s->direct)
        return accel_direct_occluded(s, r);
    Context cx;
    rtcInitIntersectContext(&cx.rtc);
    cx.scene = s;
    cx.ray = r;
    cx.best_t = INFINITY;
    cx.best_geom = cx.best_prim = cx.best_inst = RTC_INVALID_GEOMETRY_ID;
    cx.stopped = cx.passable = 0;
    struct RTCRay ray;
    make_ray(r, &ray);
    rtcOccluded1(s->rtc, &cx.rtc, &ray);
    if (!(ray.tfar < 0.0f))
        return OCCLUDED_CLEAR;
    if (cx.stopped) /* an analytic shape that blocks all light */
        return OCCLUDED_OPAQUE;
    if (cx.passable) /* an analytic shape that may let light through */
        return OCCLUDED_PASSABLE;
    return s->native_may_pass ? OCCLUDED_PASSABLE : OCCLUDED_OPAQUE; /* one of Embree's own shapes */
}
