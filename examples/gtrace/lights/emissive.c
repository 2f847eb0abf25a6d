/* emissive.c - glowing geometry as light: the emissive primitives of a scene, chosen by power through an alias
 * table (Walker 1977, Vose 1991: constant time per choice), and sampled by area (triangles, quads, discs) or by
 * the solid angle a sphere subtends (Shirley, Wang and Zimmerman 1996).
 *
 * The radiance of a drawn point is the material's own emission there, asked at a surface point filled as a ray
 * from the shading point would fill it (trace.c's surfpoint_fill), so a textured or one-sided emission, a blend
 * or a plug-in's emission is what the light carries. The power that sets the choice is only a guide (the
 * emission at the primitive's centre on both sides, times its area): every choice is unbiased, a guide that misses
 * the emission's variation across a primitive only adds noise. A primitive whose guide is black is left out; a
 * material sampling path then counts its emission in full, as for the shapes left out (planes, boxes, cylinders,
 * spheres under a shear or an unequal scale, the parts of groups and instances). */
#include "emissive.h"
#include "alias_table.h"
#include "lighting.h"

#include <generic/material.h>
#include <generic/memory.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

typedef enum EmissiveKind { EMIT_TRIANGLE, EMIT_PARALLELOGRAM, EMIT_DISC, EMIT_SPHERE } EmissiveKind;

/** One primitive, in world space. */
typedef struct EmissivePrim {
    const Object *obj;
    unsigned prim;   /**< the mesh triangle (0 for the other shapes) */
    int kind;        /**< an EmissiveKind */
    GVec3 p0;        /**< triangle, parallelogram: the corner; disc, sphere: the centre */
    GVec3 e1, e2;    /**< triangle, parallelogram: the edges; disc: the two semi-axes */
    GVec3 n;         /**< flat kinds: the unit normal */
    double area;     /**< flat kinds: the area; sphere: the radius */
} EmissivePrim;

/** An object's primitives: prims[first .. first + count). */
typedef struct EmissiveObject {
    const Object *obj;
    int first, count;
} EmissiveObject;

struct EmissiveSet {
    EmissivePrim *prims;
    double *prob;  /**< the probability of choosing each primitive */
    double *q;     /**< alias table: keep slot i with probability q[i], else take alias[i] */
    int *alias;
    int n;
    double total; /**< the sum of the primitives' guides to their power (prim_power) */
    EmissiveObject *objs; /**< sorted by the object's address */
    int nobjs;
};

static const Media NO_MEDIA = {.n = 0};

/* The emission of o's material towards the origin of the ray from origin along dir that meets the primitive at
 * distance t (barycentrics bu, bv for meshes, quads and triangles), into L. */
static int emission_at(TraceCtx *c, const Object *o, unsigned prim, double bu, double bv, GVec3 origin, GVec3 dir,
                       double t, GColor *L)
{
    Ray r = {origin, dir, 0.0, INFINITY, 0.0, 0.0};
    Hit h = {.obj = o, .inst = NULL, .material = o->material, .t = t, .prim = prim, .bu = bu, .bv = bv};
    GSurfPoint sp;
    GVec3 facing;
    GScratchMark mark = gscratch_mark(c->scratch);
    surfpoint_fill(c, &r, &h, &NO_MEDIA, &sp, &facing);
    int rc = gmaterial_emission(o->material, &sp, gvec3_neg(dir), L);
    gscratch_release(c->scratch, mark);
    return rc;
}

/* The centre of a primitive (with its barycentrics) and a unit direction off its surface there. */
static void prim_centre(const EmissivePrim *p, GVec3 *centre, GVec3 *normal, double *bu, double *bv)
{
    *bu = *bv = 0.0;
    switch (p->kind) {
    case EMIT_TRIANGLE:
        *bu = *bv = 1.0 / 3.0;
        *centre = gvec3_add(p->p0, gvec3_scale(gvec3_add(p->e1, p->e2), 1.0 / 3.0));
        *normal = p->n;
        break;
    case EMIT_PARALLELOGRAM:
        *bu = *bv = 0.5;
        *centre = gvec3_add(p->p0, gvec3_scale(gvec3_add(p->e1, p->e2), 0.5));
        *normal = p->n;
        break;
    case EMIT_DISC:
        *centre = p->p0;
        *normal = p->n;
        break;
    default: /* a sphere: its top */
        *normal = gvec3(0, 1, 0);
        *centre = gvec3_madd(p->p0, *normal, p->area);
        break;
    }
}

/* The guide to a primitive's power: its area times the brightness of its emission at the centre, front and back. */
static int prim_power(TraceCtx *c, const EmissivePrim *p, GColor *L, double *power)
{
    GVec3 centre, normal;
    double bu, bv, b = 0.0;
    prim_centre(p, &centre, &normal, &bu, &bv);
    double scale = 1.0;
    for (int side = 0; side < 2; side++) {
        GVec3 off = gvec3_scale(normal, side ? -1.0 : 1.0);
        int rc = emission_at(c, p->obj, p->prim, bu, bv, gvec3_add(centre, off), gvec3_neg(off), 1.0, L);
        if (rc < 0)
            return rc;
        b += gcolor_brightness_as(L, GCOLOR_LIGHT);
        if (p->kind == EMIT_SPHERE) /* a sphere is seen from outside only */
            break;
    }
    if (p->kind == EMIT_SPHERE)
        scale = 4.0 * M_PI * p->area * p->area;
    else
        scale = p->area;
    *power = isfinite(b) && b > 0.0 ? b * scale : 0.0;
    return G_OK;
}

/* The world-space radius of a sphere under o's transform when that is a rotation, a uniform scale and a
 * translation; 0 otherwise. */
static double sphere_world_radius(const Object *o)
{
    if (!o->has_xf)
        return o->radius;
    GVec3 a = xform_vector(&o->xf, gvec3(1, 0, 0)), b = xform_vector(&o->xf, gvec3(0, 1, 0));
    GVec3 z = xform_vector(&o->xf, gvec3(0, 0, 1));
    double la = gvec3_length(a), lb = gvec3_length(b), lz = gvec3_length(z), tol = 1e-9 * la;
    if (!(la > 0.0) || fabs(la - lb) > tol || fabs(la - lz) > tol || fabs(gvec3_dot(a, b)) > tol * la ||
        fabs(gvec3_dot(a, z)) > tol * la || fabs(gvec3_dot(b, z)) > tol * la)
        return 0.0;
    return o->radius * la;
}

static GVec3 world_point(const Object *o, GVec3 p) { return o->has_xf ? xform_point(&o->xf, p) : p; }

static void set_flat(EmissivePrim *p, int kind, GVec3 p0, GVec3 e1, GVec3 e2)
{
    p->kind = kind;
    p->p0 = p0;
    p->e1 = e1;
    p->e2 = e2;
    GVec3 cr = gvec3_cross(e1, e2);
    double l = gvec3_length(cr);
    p->n = l > 0.0 ? gvec3_scale(cr, 1.0 / l) : gvec3(0, 0, 1);
    p->area = kind == EMIT_TRIANGLE ? 0.5 * l : kind == EMIT_DISC ? M_PI * l : l;
}

/* The primitives of o into prims (NULL: only counted); their number. */
static int object_prims(const Object *o, EmissivePrim *prims)
{
    switch (o->kind) {
    case SHAPE_SPHERE: {
        double r = sphere_world_radius(o);
        if (!(r > 0.0))
            return 0;
        if (prims)
            *prims = (EmissivePrim){.obj = o, .kind = EMIT_SPHERE, .p0 = world_point(o, o->center), .area = r};
        return 1;
    }
    case SHAPE_DISC:
    case SHAPE_QUAD:
    case SHAPE_TRIANGLE:
        if (prims) {
            *prims = (EmissivePrim){.obj = o};
            GVec3 p0 = world_point(o, o->center), e1 = o->t1, e2 = o->t2;
            if (o->kind == SHAPE_DISC)
                e1 = gvec3_scale(e1, o->radius), e2 = gvec3_scale(e2, o->radius);
            if (o->has_xf)
                e1 = xform_vector(&o->xf, e1), e2 = xform_vector(&o->xf, e2);
            int kind = o->kind == SHAPE_DISC ? EMIT_DISC : o->kind == SHAPE_QUAD ? EMIT_PARALLELOGRAM : EMIT_TRIANGLE;
            set_flat(prims, kind, p0, e1, e2);
        }
        return 1;
    case SHAPE_MESH:
        for (int k = 0; prims && k < o->mesh->ntris; k++) {
            const unsigned *t = o->mesh->tri + 3 * k;
            const double *pos = o->mesh->pos;
            GVec3 v[3];
            for (int j = 0; j < 3; j++)
                v[j] = world_point(o, gvec3(pos[3 * t[j]], pos[3 * t[j] + 1], pos[3 * t[j] + 2]));
            prims[k] = (EmissivePrim){.obj = o, .prim = (unsigned)k};
            set_flat(&prims[k], EMIT_TRIANGLE, v[0], gvec3_sub(v[1], v[0]), gvec3_sub(v[2], v[0]));
        }
        return o->mesh->ntris;
    default:
        return 0;
    }
}

static int cmp_objs(const void *a, const void *b)
{
    uintptr_t x = (uintptr_t)((const EmissiveObject *)a)->obj, y = (uintptr_t)((const EmissiveObject *)b)->obj;
    return x < y ? -1 : x > y;
}

void emissive_free(EmissiveSet *e)
{
    if (!e)
        return;
    gmem_free(e->prims);
    gmem_free(e->prob);
    gmem_free(e->q);
    gmem_free(e->alias);
    gmem_free(e->objs);
    gmem_free(e);
}

int emissive_count(const EmissiveSet *e) { return e ? e->n : 0; }

int emissive_build(const Scene *s, TraceCtx *c, EmissiveSet **out, GError *err)
{
    *out = NULL;
    size_t total = 0;
    int nobjs = 0;
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (o->is_part || !o->material || (o->material->flags & GMAT_NO_EMISSION))
            continue;
        int k = object_prims(o, NULL);
        total += (size_t)k;
        nobjs += k > 0;
    }
    if (total == 0)
        return G_OK;
    if (total > (size_t)INT32_MAX / 2)
        return gerror_set(err, G_ERR_INVALID, "%zu emissive primitives: more than a light table holds", total);
    EmissiveSet *e = gmem_calloc(1, sizeof *e);
    double *power = gmem_alloc(sizeof *power * total);
    GColor L = {0};
    int rc = e && power ? gcolor_alloc(&L, s->model) : G_ERR_NOMEM;
    if (rc == G_OK) {
        e->prims = gmem_alloc(sizeof *e->prims * total);
        e->objs = gmem_alloc(sizeof *e->objs * (size_t)nobjs);
        if (!e->prims || !e->objs)
            rc = G_ERR_NOMEM;
    }
    double sum = 0.0;
    int n = 0;
    for (int i = 0; rc == G_OK && i < s->nobjects; i++) { /* every primitive, then only those that glow */
        const Object *o = s->objects[i];
        if (o->is_part || !o->material || (o->material->flags & GMAT_NO_EMISSION))
            continue;
        int k = object_prims(o, e->prims + n), first = n;
        for (int j = 0; rc == G_OK && j < k; j++) {
            double pw = 0.0;
            rc = prim_power(c, &e->prims[first + j], &L, &pw);
            if (rc == G_OK && pw > 0.0) {
                e->prims[n] = e->prims[first + j];
                power[n++] = pw;
                sum += pw;
            }
        }
        if (n > first)
            e->objs[e->nobjs++] = (EmissiveObject){o, first, n - first};
    }
    gcolor_free(&L);
    if (rc == G_OK && n > 0 && isfinite(sum)) {
        e->n = n;
        e->total = sum;
        e->prob = gmem_alloc(sizeof *e->prob * (size_t)n);
        e->q = gmem_alloc(sizeof *e->q * (size_t)n);
        e->alias = gmem_alloc(sizeof *e->alias * (size_t)n);
        if (!e->prob || !e->q || !e->alias)
            rc = G_ERR_NOMEM;
        for (int i = 0; rc == G_OK && i < n; i++)
            e->prob[i] = power[i] / sum;
        if (rc == G_OK)
            rc = alias_table_build(e->prob, n, e->q, e->alias);
        qsort(e->objs, (size_t)e->nobjs, sizeof *e->objs, cmp_objs);
    }
    gmem_free(power);
    if (rc != G_OK) {
        emissive_free(e);
        if (rc == G_ERR_NOMEM)
            return gerror_set(err, rc, "out of memory for %zu emissive primitives", total);
        return gerror_set(err, rc, "the emission of a glowing object failed: %s", gstatus_string(rc));
    }
    if (e->n == 0) { /* nothing glows after all (or the powers overflow: left to material sampling) */
        emissive_free(e);
        return G_OK;
    }
    *out = e;
    return G_OK;
}

/* The primitive of the set hit h is on, or -1. */
static int prim_of_hit(const EmissiveSet *e, const Hit *h)
{
    if (h->inst)
        return -1;
    int lo = 0, hi = e->nobjs - 1;
    uintptr_t key = (uintptr_t)h->obj;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        uintptr_t k = (uintptr_t)e->objs[mid].obj;
        if (k == key) {
            const EmissiveObject *eo = &e->objs[mid]; /* a mesh's glowing triangles, in increasing order */
            int a = eo->first, z = eo->first + eo->count - 1;
            while (a <= z) {
                int m = (a + z) / 2;
                if (e->prims[m].prim == h->prim)
                    return m;
                if (e->prims[m].prim < h->prim)
                    a = m + 1;
                else
                    z = m - 1;
            }
            return -1;
        }
        if (k < key)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

/* The solid angle density of primitive i's sampling from x for direction dir meeting it at distance t. */
static double prim_pdf(const EmissiveSet *e, int i, GVec3 x, GVec3 dir, double t)
{
    const EmissivePrim *p = &e->prims[i];
    if (p->kind == EMIT_SPHERE) {
        GVec3 oc = gvec3_sub(p->p0, x);
        double dc2 = gvec3_dot(oc, oc), r2 = p->area * p->area;
        if (!(dc2 > r2))
            return 0.0;
        double omega = 2.0 * M_PI * (1.0 - sqrt(fmax(0.0, 1.0 - r2 / dc2)));
        return omega > 0.0 ? e->prob[i] / omega : 0.0;
    }
    double cos_l = fabs(gvec3_dot(dir, p->n));
    return cos_l > 0.0 ? e->prob[i] * t * t / (p->area * cos_l) : 0.0;
}

double emissive_pdf(const EmissiveSet *e, const Hit *h, GVec3 x, GVec3 dir, double t)
{
    int i = e ? prim_of_hit(e, h) : -1;
    return i < 0 ? 0.0 : prim_pdf(e, i, x, dir, t);
}

int emissive_sample(TraceCtx *c, const EmissiveSet *e, GVec3 x, double u0, double u1, double u2, GVec3 *in,
                    double *dist, GVec3 *normal, double *pdf, GColor *L)
{
    int i = alias_table_pick(e->q, e->alias, e->n, u0, NULL);
    const EmissivePrim *p = &e->prims[i];
    double bu = 0.0, bv = 0.0;
    GVec3 y;
    if (p->kind == EMIT_SPHERE) {
        GVec3 axis = gvec3_sub(p->p0, x);
        double dc = gvec3_length(axis), r = p->area;
        if (!(dc > r))
            return 0;
        axis = gvec3_scale(axis, 1.0 / dc);
        double sin_max = r / dc, cos_max = sqrt(fmax(0.0, 1.0 - sin_max * sin_max));
        GVec3 t1, t2;
        frame_from_normal(axis, &t1, &t2);
        double ct = 1.0 - u1 * (1.0 - cos_max), st = sqrt(fmax(0.0, 1.0 - ct * ct)), ph = 2.0 * M_PI * u2;
        *in = gvec3_add(gvec3_scale(axis, ct), gvec3_add(gvec3_scale(t1, st * cos(ph)), gvec3_scale(t2, st * sin(ph))));
        double b = dc * ct, disc = b * b - (dc * dc - r * r);
        *dist = b - sqrt(fmax(0.0, disc));
        *normal = gvec3_scale(gvec3_sub(gvec3_madd(x, *in, *dist), p->p0), 1.0 / r);
    } else {
        if (p->kind == EMIT_TRIANGLE) {
            double su = sqrt(u1);
            bu = u2 * su;
            bv = 1.0 - su;
        } else if (p->kind == EMIT_PARALLELOGRAM) {
            bu = u1;
            bv = u2;
        } else { /* a disc: uniform in the ellipse its semi-axes span */
            double rr = sqrt(u1), ph = 2.0 * M_PI * u2;
            bu = rr * cos(ph);
            bv = rr * sin(ph);
        }
        y = gvec3_add(p->p0, gvec3_add(gvec3_scale(p->e1, bu), gvec3_scale(p->e2, bv)));
        GVec3 w = gvec3_sub(y, x);
        double d = gvec3_length(w);
        if (!(d > 0.0))
            return 0;
        *in = gvec3_scale(w, 1.0 / d);
        *dist = d;
        *normal = p->n;
        if (p->kind == EMIT_DISC)
            bu = bv = 0.0;
    }
    *pdf = prim_pdf(e, i, x, *in, *dist);
    if (!(*pdf > 0.0) || !isfinite(*pdf))
        return 0;
    int rc = emission_at(c, p->obj, p->prim, bu, bv, x, *in, *dist, L);
    return rc < 0 ? rc : 1;
}

int emissive_shade(TraceCtx *c, const EmissiveSet *e, GSurfPoint *sp, GVec3 facing, const Media *media,
                   GVec3 out_dir, int opaque, LightTmp *t, GColor *result)
{
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor L;
    int rc = gcolor_scratch_uncleared(&L, c->scene->model, c->scratch);
    int n = EMISSIVE_WHITTED_SAMPLES;
    for (int k = 0; rc >= 0 && k < n; k++) {
        GVec3 in, normal;
        double dist, pdf;
        double u0 = (k + rng_next(&c->rng)) / n, u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
        int got = emissive_sample(c, e, sp->point, u0, u1, u2, &in, &dist, &normal, &pdf, &L);
        if (got <= 0) {
            rc = got;
            continue;
        }
        if (opaque && gvec3_dot(in, facing) <= 0.0)
            continue;
        rc = sample_light(c, sp, facing, media, in, emissive_shadow_reach(sp->point, facing, in, dist, normal), &L,
                          1.0 / (pdf * n), out_dir, t, result);
    }
    gscratch_release(c->scratch, mark);
    return rc < 0 ? rc : G_OK;
}

double emissive_shadow_reach(GVec3 x, GVec3 facing, GVec3 in, double dist, GVec3 normal)
{
    return shadow_reach(offset_origin(x, facing, in), in, gvec3_madd(x, in, dist), normal);
}

double emissive_power(const EmissiveSet *e) { return e ? M_PI * e->total : 0.0; }

int emissive_emit(TraceCtx *c, const EmissiveSet *e, const double u[5], GVec3 *origin, GVec3 *dir, GColor *power)
{
    int i = alias_table_pick(e->q, e->alias, e->n, u[0], NULL);
    const EmissivePrim *p = &e->prims[i];
    double bu = 0.0, bv = 0.0, area, sides = 1.0, v = u[3];
    GVec3 y, n;
    if (p->kind == EMIT_SPHERE) {
        double z = 1.0 - 2.0 * u[1], r = sqrt(fmax(0.0, 1.0 - z * z)), ph = 2.0 * M_PI * u[2];
        n = gvec3(r * cos(ph), r * sin(ph), z);
        y = gvec3_madd(p->p0, n, p->area);
        area = 4.0 * M_PI * p->area * p->area;
    } else {
        if (p->kind == EMIT_TRIANGLE) {
            double su = sqrt(u[1]);
            bu = u[2] * su;
            bv = 1.0 - su;
        } else if (p->kind == EMIT_PARALLELOGRAM) {
            bu = u[1];
            bv = u[2];
        } else {
            double rr = sqrt(u[1]), ph = 2.0 * M_PI * u[2];
            bu = rr * cos(ph);
            bv = rr * sin(ph);
        }
        y = gvec3_add(p->p0, gvec3_add(gvec3_scale(p->e1, bu), gvec3_scale(p->e2, bv)));
        if (p->kind == EMIT_DISC)
            bu = bv = 0.0;
        area = p->area;
        sides = 2.0; /* u[3] picks the side, then is reused for the direction */
        n = v < 0.5 ? p->n : gvec3_neg(p->n);
        v = v < 0.5 ? 2.0 * v : 2.0 * v - 1.0;
    }
    *dir = goptics_sample_cosine(n, v, u[4]);
    *origin = y;
    double cos_l = gvec3_dot(*dir, n);
    if (!(cos_l > 0.0) || !(e->prob[i] > 0.0))
        return gcolor_fill(power, 0.0);
    /* seen from a point one unit out along the direction */
    int rc = emission_at(c, p->obj, p->prim, bu, bv, gvec3_add(y, *dir), gvec3_neg(*dir), 1.0, power);
    if (rc < 0)
        return rc;
    return gcolor_scale(power, power, M_PI * area * sides / e->prob[i]);
}
