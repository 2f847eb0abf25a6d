/* shapes.c - the analytic shapes in their own space: intersection in double precision, bounds, and the
 * surface at a hit ((u,v), tangents with dpdu x dpdv along the outward normal, surface index).
 *
 * Surface indices: box faces 0..5 = -x, +x, -y, +y, -z, +z; cylinder 0 side, 1 base cap, 2 top cap;
 * every other shape 0. (u,v): sphere longitude/latitude in [0,1] (v = 1 at the +y pole); plane: distance
 * along its frame; box faces, disc and caps: [0,1] across; cylinder side: angle and height in [0,1]; quad:
 * corner + u edge1 + v edge2; triangle: the barycentrics of b and c. The full table with orientations is in
 * examples/gtrace/README.md ("Surface parameters and surface indices"). hit_geom takes a hit inside an
 * instance through the placement's transform. */
#include "geometry.h"

#include <math.h>

static int hit_disc_at(GVec3 c, GVec3 n, double r, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t)
{
    double dn = gvec3_dot(rd, n);
    if (dn == 0.0)
        return 0;
    double th = gvec3_dot(gvec3_sub(c, ro), n) / dn;
    if (!(th > tmin && th < tmax))
        return 0;
    GVec3 d = gvec3_sub(gvec3_madd(ro, rd, th), c);
    if (gvec3_dot(d, d) > r * r)
        return 0;
    *t = th;
    return 1;
}

static int hit_box(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t, int *surface)
{
    const double rov[3] = {ro.x, ro.y, ro.z}, rdv[3] = {rd.x, rd.y, rd.z};
    const double lo[3] = {o->lo.x, o->lo.y, o->lo.z}, hi[3] = {o->hi.x, o->hi.y, o->hi.z};
    double tn = -INFINITY, tf = INFINITY;
    int fn = -1, ff = -1;
    for (int a = 0; a < 3; a++) {
        if (rdv[a] == 0.0) {
            if (rov[a] < lo[a] || rov[a] > hi[a])
                return 0;
            continue;
        }
        double inv = 1.0 / rdv[a];
        double ta = (lo[a] - rov[a]) * inv, tb = (hi[a] - rov[a]) * inv;
        int fa = 2 * a, fb = 2 * a + 1;
        if (ta > tb) {
            double s = ta;
            ta = tb;
            tb = s;
            fa = 2 * a + 1;
            fb = 2 * a;
        }
        if (ta > tn) {
            tn = ta;
            fn = fa;
        }
        if (tb < tf) {
            tf = tb;
            ff = fb;
        }
    }
    if (tn > tf)
        return 0;
    if (tn > tmin && tn < tmax && fn >= 0) {
        *t = tn;
        *surface = fn;
        return 1;
    }
    if (tf > tmin && tf < tmax && ff >= 0) {
        *t = tf;
        *surface = ff;
        return 1;
    }
    return 0;
}

static int hit_cylinder(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t, int *surface)
{
    GVec3 oc = gvec3_sub(ro, o->center);
    /* local coordinates: x along t1, y along t2, z along the axis */
    double ox = gvec3_dot(oc, o->t1), oy = gvec3_dot(oc, o->t2), oz = gvec3_dot(oc, o->normal);
    double dx = gvec3_dot(rd, o->t1), dy = gvec3_dot(rd, o->t2), dz = gvec3_dot(rd, o->normal);
    int found = 0;
    double best = tmax, t0, t1;
    if (shape_solve_quadratic(dx * dx + dy * dy, ox * dx + oy * dy, ox * ox + oy * oy - o->radius * o->radius, &t0,
                              &t1)) {
        const double cand[2] = {t0, t1};
        for (int i = 0; i < 2; i++) {
            double z = oz + dz * cand[i];
            if (cand[i] > tmin && cand[i] < best && z >= 0.0 && z <= o->height) {
                best = cand[i];
                *surface = 0;
                found = 1;
                break;
            }
        }
    }
    if (!o->open) {
        double tc;
        if (hit_disc_at(o->center, o->normal, o->radius, ro, rd, tmin, best, &tc)) {
            best = tc;
            *surface = 1;
            found = 1;
        }
        if (hit_disc_at(gvec3_madd(o->center, o->normal, o->height), o->normal, o->radius, ro, rd, tmin, best, &tc)) {
            best = tc;
            *surface = 2;
            found = 1;
        }
    }
    if (found)
        *t = best;
    return found;
}

int shape_intersect(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t, int *surface)
{
    *surface = 0;
    switch (o->kind) {
    case SHAPE_SPHERE:
        return shape_hit_sphere(o, ro, rd, tmin, tmax, t);
    case SHAPE_PLANE:
        return shape_hit_plane(o, ro, rd, tmin, tmax, t);
    case SHAPE_BOX:
        return hit_box(o, ro, rd, tmin, tmax, t, surface);
    case SHAPE_DISC:
        return hit_disc_at(o->center, o->normal, o->radius, ro, rd, tmin, tmax, t);
    case SHAPE_CYLINDER:
        return hit_cylinder(o, ro, rd, tmin, tmax, t, surface);
    case SHAPE_MESH:
    case SHAPE_QUAD:
    case SHAPE_TRIANGLE:
    case SHAPE_GROUP:
    case SHAPE_INSTANCE:
        break; /* Embree's own geometry and instances */
    }
    return 0;
}

static void bounds_grow(GVec3 *lo, GVec3 *hi, GVec3 p)
{
    *lo = gvec3(fmin(lo->x, p.x), fmin(lo->y, p.y), fmin(lo->z, p.z));
    *hi = gvec3(fmax(hi->x, p.x), fmax(hi->y, p.y), fmax(hi->z, p.z));
}

/* bounds of a disc of radius r around c in the plane spanned by a, b */
static void disc_bounds(GVec3 c, GVec3 a, GVec3 b, double r, GVec3 *lo, GVec3 *hi)
{
    for (int i = 0; i < 4; i++) {
        double sa = (i & 1) ? r : -r, sb = (i & 2) ? r : -r;
        bounds_grow(lo, hi, gvec3_madd(gvec3_madd(c, a, sa), b, sb));
    }
}

void shape_bounds(const Object *o, GVec3 *lo, GVec3 *hi)
{
    *lo = gvec3(INFINITY, INFINITY, INFINITY);
    *hi = gvec3(-INFINITY, -INFINITY, -INFINITY);
    switch (o->kind) {
    case SHAPE_SPHERE: {
        GVec3 r = gvec3(o->radius, o->radius, o->radius);
        *lo = gvec3_sub(o->center, r);
        *hi = gvec3_add(o->center, r);
        break;
    }
    case SHAPE_PLANE:
        disc_bounds(o->center, o->t1, o->t2, SHAPE_PLANE_EXTENT, lo, hi);
        break;
    case SHAPE_BOX:
        *lo = o->lo;
        *hi = o->hi;
        break;
    case SHAPE_DISC:
        disc_bounds(o->center, o->t1, o->t2, o->radius, lo, hi);
        break;
    case SHAPE_CYLINDER:
        disc_bounds(o->center, o->t1, o->t2, o->radius, lo, hi);
        disc_bounds(gvec3_madd(o->center, o->normal, o->height), o->t1, o->t2, o->radius, lo, hi);
        break;
    case SHAPE_MESH:
        for (int i = 0; i < o->mesh->nverts; i++)
            bounds_grow(lo, hi, gvec3(o->mesh->pos[3 * i], o->mesh->pos[3 * i + 1], o->mesh->pos[3 * i + 2]));
        break;
    case SHAPE_QUAD:
        bounds_grow(lo, hi, gvec3_add(gvec3_add(o->center, o->t1), o->t2));
        /* fall through */
    case SHAPE_TRIANGLE:
        bounds_grow(lo, hi, o->center);
        bounds_grow(lo, hi, gvec3_add(o->center, o->t1));
        bounds_grow(lo, hi, gvec3_add(o->center, o->t2));
        break;
    case SHAPE_GROUP:
    case SHAPE_INSTANCE:
        *lo = o->lo; /* cached by the constructor */
        *hi = o->hi;
        break;
    }
}

void object_world_bounds(const Object *o, GVec3 *lo, GVec3 *hi)
{
    GVec3 slo, shi;
    shape_bounds(o, &slo, &shi);
    if (!o->has_xf) { /* the eight corners' minimum and maximum, per axis */
        *lo = gvec3(fmin(slo.x, shi.x), fmin(slo.y, shi.y), fmin(slo.z, shi.z));
        *hi = gvec3(fmax(slo.x, shi.x), fmax(slo.y, shi.y), fmax(slo.z, shi.z));
        return;
    }
    *lo = gvec3(INFINITY, INFINITY, INFINITY);
    *hi = gvec3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < 8; i++) {
        GVec3 c = gvec3((i & 1) ? shi.x : slo.x, (i & 2) ? shi.y : slo.y, (i & 4) ? shi.z : slo.z);
        if (o->has_xf)
            c = xform_point(&o->xf, c);
        bounds_grow(lo, hi, c);
    }
}

int scene_coord_ok(GVec3 v)
{
    return fabs(v.x) <= SCENE_MAX_COORD && fabs(v.y) <= SCENE_MAX_COORD && fabs(v.z) <= SCENE_MAX_COORD;
}

double object_extent_check(const Object *o)
{
    GVec3 slo, shi;
    shape_bounds(o, &slo, &shi);
    double worst = 0.0;
    for (int i = 0; i < 8; i++) {
        GVec3 c = gvec3((i & 1) ? shi.x : slo.x, (i & 2) ? shi.y : slo.y, (i & 4) ? shi.z : slo.z);
        if (o->has_xf)
            c = xform_point(&o->xf, c);
        if (!scene_coord_ok(c)) {
            double m = fmax(fabs(c.x), fmax(fabs(c.y), fabs(c.z)));
            if (!(m == m) || !isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z))
                return INFINITY;
            worst = fmax(worst, m);
        }
    }
    return worst;
}

static double wrap01(double x) { return x - floor(x); }

/* Surface in object space: point (refined onto the shape), outward normal, tangents, (u,v). */
static void local_geom(const Object *o, int surface, int want_uv, GVec3 *p, GVec3 *n, GVec3 *dpdu, GVec3 *dpdv,
                       double *u, double *v)
{
    switch (o->kind) {
    case SHAPE_SPHERE: {
        GVec3 l = gvec3_normalize(gvec3_sub(*p, o->center));
        *p = gvec3_madd(o->center, l, o->radius);
        *n = l;
        if (!want_uv) /* an acos and an atan2 saved: the tangents stay as the caller set them */
            break;
        /* theta = acos(cy) from the pole, phi = atan2(-l.z, l.x) around y; sin(theta) = sqrt(1 - cy^2), and
         * sin(theta) cos(phi) = l.x, sin(theta) sin(phi) = -l.z: no sin, and no division for dp/du */
        double cy = gfmax(-1.0, gfmin(1.0, l.y)), theta = acos(cy), st = sqrt(gfmax(0.0, 1.0 - cy * cy));
        double phi = atan2(-l.z, l.x);
        *u = wrap01(phi / (2.0 * M_PI));
        *v = 1.0 - theta / M_PI;
        double r = o->radius;
        if (st < 1e-9) { /* at a pole: any tangent frame */
            frame_from_normal(l, dpdu, dpdv);
            *dpdu = gvec3_scale(*dpdu, 2.0 * M_PI * r);
            *dpdv = gvec3_scale(*dpdv, M_PI * r);
        } else {
            double k = M_PI * r * cy / st;
            *dpdu = gvec3(2.0 * M_PI * r * l.z, 0.0, -2.0 * M_PI * r * l.x);
            *dpdv = gvec3(-k * l.x, M_PI * r * st, -k * l.z);
        }
        break;
    }
    case SHAPE_PLANE: {
        GVec3 d = gvec3_sub(*p, o->center);
        *p = gvec3_madd(*p, o->normal, -gvec3_dot(d, o->normal));
        *n = o->normal;
        *u = gvec3_dot(d, o->t1);
        *v = gvec3_dot(d, o->t2);
        *dpdu = o->t1;
        *dpdv = o->t2;
        break;
    }
    case SHAPE_DISC: {
        GVec3 d = gvec3_sub(*p, o->center);
        *p = gvec3_madd(*p, o->normal, -gvec3_dot(d, o->normal));
        *n = o->normal;
        double w = 2.0 * o->radius;
        *u = 0.5 + gvec3_dot(d, o->t1) / w;
        *v = 0.5 + gvec3_dot(d, o->t2) / w;
        *dpdu = gvec3_scale(o->t1, w);
        *dpdv = gvec3_scale(o->t2, w);
        break;
    }
    case SHAPE_BOX: {
        GVec3 s = gvec3_sub(o->hi, o->lo), q = *p;
        int axis = surface / 2, positive = surface & 1;
        double face = positive ? (&o->hi.x)[axis] : (&o->lo.x)[axis];
        (&q.x)[axis] = face;
        *p = q;
        *n = gvec3(0, 0, 0);
        (&n->x)[axis] = positive ? 1.0 : -1.0;
        double fx = (q.x - o->lo.x) / s.x, fy = (q.y - o->lo.y) / s.y, fz = (q.z - o->lo.z) / s.z;
        switch (surface) {
        case 0: *u = fz; *v = fy; *dpdu = gvec3(0, 0, s.z); *dpdv = gvec3(0, s.y, 0); break;
        case 1: *u = 1 - fz; *v = fy; *dpdu = gvec3(0, 0, -s.z); *dpdv = gvec3(0, s.y, 0); break;
        case 2: *u = fx; *v = fz; *dpdu = gvec3(s.x, 0, 0); *dpdv = gvec3(0, 0, s.z); break;
        case 3: *u = fx; *v = 1 - fz; *dpdu = gvec3(s.x, 0, 0); *dpdv = gvec3(0, 0, -s.z); break;
        case 4: *u = 1 - fx; *v = fy; *dpdu = gvec3(-s.x, 0, 0); *dpdv = gvec3(0, s.y, 0); break;
        default: *u = fx; *v = fy; *dpdu = gvec3(s.x, 0, 0); *dpdv = gvec3(0, s.y, 0); break;
        }
        break;
    }
    case SHAPE_CYLINDER: {
        GVec3 d = gvec3_sub(*p, o->center);
        double x = gvec3_dot(d, o->t1), y = gvec3_dot(d, o->t2), z = gvec3_dot(d, o->normal);
        double r = o->radius, w = 2.0 * r;
        if (surface == 0) {
            double l = hypot(x, y);
            if (l > 0.0) {
                x *= r / l;
                y *= r / l;
            }
            *p = gvec3_madd(gvec3_madd(gvec3_madd(o->center, o->t1, x), o->t2, y), o->normal, z);
            *n = gvec3_normalize(gvec3_add(gvec3_scale(o->t1, x), gvec3_scale(o->t2, y)));
            *u = wrap01(atan2(y, x) / (2.0 * M_PI));
            *v = o->height > 0.0 ? z / o->height : 0.0;
            *dpdu = gvec3_scale(gvec3_sub(gvec3_scale(o->t2, x), gvec3_scale(o->t1, y)), 2.0 * M_PI);
            *dpdv = gvec3_scale(o->normal, o->height);
        } else {
            double zc = surface == 2 ? o->height : 0.0;
            *p = gvec3_madd(gvec3_madd(gvec3_madd(o->center, o->t1, x), o->t2, y), o->normal, zc);
            double sgn = surface == 2 ? 1.0 : -1.0;
            *n = gvec3_scale(o->normal, sgn);
            *u = 0.5 + sgn * x / w;
            *v = 0.5 + y / w;
            *dpdu = gvec3_scale(o->t1, sgn * w);
            *dpdv = gvec3_scale(o->t2, w);
        }
        break;
    }
    case SHAPE_MESH:
    case SHAPE_QUAD:
    case SHAPE_TRIANGLE:
    case SHAPE_GROUP:
    case SHAPE_INSTANCE:
        break;
    }
}

void hit_geom_transform(const Object *o, HitGeom *g)
{
    g->odpdu = g->dpdu;
    g->odpdv = g->dpdv;
    g->p = xform_point(&o->xf, g->op);
    g->n_out = gvec3_normalize(xform_normal(&o->xf, g->n_out));
    g->n_smooth = gvec3_normalize(xform_normal(&o->xf, g->n_smooth));
    if (g->want_uv) {
        g->dpdu = xform_vector(&o->xf, g->dpdu);
        g->dpdv = xform_vector(&o->xf, g->dpdv);
    }
}

/* quads and triangles: Embree's (u, v) are the parameters of center + u t1 + v t2 */
static void flat_hit_geom(const Object *o, const Hit *h, HitGeom *g)
{
    g->op = gvec3_madd(gvec3_madd(o->center, o->t1, h->bu), o->t2, h->bv);
    g->n_out = g->n_smooth = o->normal;
    g->dpdu = o->t1;
    g->dpdv = o->t2;
    g->surface = 0;
    g->u = h->bu;
    g->v = h->bv;
    hit_geom_to_world(o, g);
}

void shape_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g)
{
    if (o->kind == SHAPE_QUAD || o->kind == SHAPE_TRIANGLE) {
        flat_hit_geom(o, h, g);
        return;
    }
    GVec3 pw = gvec3_madd(r->o, r->d, h->t);
    g->op = o->has_xf ? xform_inv_point(&o->xf, pw) : pw;
    g->n_out = gvec3(0, 0, 1);
    g->dpdu = gvec3(1, 0, 0);
    g->dpdv = gvec3(0, 1, 0);
    g->u = g->v = 0.0;
    /* in place: the fields, not copies passed by value (24-byte vectors go through the stack, and a 16-byte load
     * of two 8-byte stores just made stalls) */
    local_geom(o, h->surface, g->want_uv, &g->op, &g->n_out, &g->dpdu, &g->dpdv, &g->u, &g->v);
    g->n_smooth = g->n_out;
    g->surface = h->surface;
    hit_geom_to_world(o, g);
}

void hit_geom(const Ray *r, const Hit *h, int want_uv, HitGeom *g)
{
    g->want_uv = want_uv;
    const Instance *in = h->inst;
    const Ray *pr = r; /* a copy only for an instance */
    Ray moved;
    if (in) { /* the ray in the prototype's space: affine, so t is unchanged */
        moved = *r;
        moved.o = xform_inv_point(&in->xf, r->o);
        moved.d = xform_inv_vector(&in->xf, r->d);
        pr = &moved;
    }
    if (h->obj->kind == SHAPE_MESH)
        mesh_hit_geom(h->obj, pr, h, g);
    else
        shape_hit_geom(h->obj, pr, h, g);
    if (in) {
        if (!g->object_tangents) { /* the prototype's space is the object's */
            g->odpdu = g->dpdu;
            g->odpdv = g->dpdv;
            g->object_tangents = 1;
        }
        g->p = xform_point(&in->xf, g->p);
        g->n_out = gvec3_normalize(xform_normal(&in->xf, g->n_out));
        g->n_smooth = gvec3_normalize(xform_normal(&in->xf, g->n_smooth));
        if (want_uv) {
            g->dpdu = xform_vector(&in->xf, g->dpdu);
            g->dpdv = xform_vector(&in->xf, g->dpdv);
        }
    }
}
