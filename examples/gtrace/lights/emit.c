/* emit.c - particles leaving the light sources (emit.h). Each kind is drawn so that its weight is simple: point and
 * IES lights uniformly over the sphere, spots uniformly over their outer cone, directional lights uniformly over a
 * disc as wide as the scene's bounding sphere, sphere and rectangle lights uniformly over their area with a cosine
 * distribution about the outward normal (the rectangle from its lit side), probes (`technique reference`) by
 * their sampling distribution (probe_dist.h) through the same disc as a directional light. */
#include "emit.h"
#include "probe_env.h"
#include "scene/ies.h"

#include <generic/material.h>

#include <math.h>

void emit_bounds(const Scene *s, EmitBounds *b)
{
    GVec3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < s->nobjects; i++) {
        GVec3 a, z;
        object_world_bounds(s->objects[i], &a, &z);
        if (!(z.x - a.x < SHAPE_PLANE_EXTENT && z.y - a.y < SHAPE_PLANE_EXTENT && z.z - a.z < SHAPE_PLANE_EXTENT))
            continue; /* a plane: its bounded extent is no part of the scene's size */
        lo = (GVec3){fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z)};
        hi = (GVec3){fmax(hi.x, z.x), fmax(hi.y, z.y), fmax(hi.z, z.z)};
    }
    if (!(lo.x <= hi.x)) {
        *b = (EmitBounds){{0, 0, 0}, 1.0};
        return;
    }
    b->centre = gvec3_scale(gvec3_add(lo, hi), 0.5);
    b->radius = fmax(1e-6, 0.5 * gvec3_length(gvec3_sub(hi, lo)));
}

int emit_supported(const Light *l)
{
    switch (l->kind) {
    case LIGHT_POINT:
    case LIGHT_SPOT:
    case LIGHT_DIRECTIONAL:
    case LIGHT_SPHERE:
    case LIGHT_RECT:
        return 1;
    case LIGHT_IES:
        return l->ies != NULL;
    case LIGHT_PROBE:
        return l->env && l->env->probe && l->env->dist.row_cdf && l->env->dist.h > 0;
    default:
        return 0;
    }
}

/* The solid angle of the spot's outer cone. */
static double spot_solid_angle(const Light *l) { return 2.0 * M_PI * (1.0 - fmax(-1.0, fmin(1.0, l->cos_outer))); }

double emit_power_factor(const Light *l, const EmitBounds *b)
{
    switch (l->kind) {
    case LIGHT_POINT:
        return 4.0 * M_PI;
    case LIGHT_SPOT:
        return spot_solid_angle(l);
    case LIGHT_IES:
        return l->ies ? ies_flux(l->ies) : 0.0;
    case LIGHT_DIRECTIONAL:
        return M_PI * b->radius * b->radius;
    case LIGHT_SPHERE:
        return 4.0 * M_PI * M_PI * l->radius * l->radius;
    case LIGHT_RECT:
        return M_PI * gvec3_length(gvec3_cross(l->edge1, l->edge2));
    default:
        return 0.0;
    }
}

static double smoothstep01(double a, double b, double x)
{
    if (b <= a)
        return x >= b ? 1.0 : 0.0;
    double t = fmin(1.0, fmax(0.0, (x - a) / (b - a)));
    return t * t * (3.0 - 2.0 * t);
}

/* A unit vector uniform over the sphere. */
static GVec3 uniform_sphere(double u1, double u2)
{
    double z = 1.0 - 2.0 * u1, r = sqrt(fmax(0.0, 1.0 - z * z)), ph = 2.0 * M_PI * u2;
    return (GVec3){r * cos(ph), r * sin(ph), z};
}

double emit_sample(const Light *l, const EmitBounds *b, const double u[4], GVec3 *origin, GVec3 *dir)
{
    switch (l->kind) {
    case LIGHT_POINT:
        *origin = l->position;
        *dir = uniform_sphere(u[0], u[1]);
        return 4.0 * M_PI;
    case LIGHT_IES:
        *origin = l->position;
        *dir = uniform_sphere(u[0], u[1]);
        return 4.0 * M_PI * ies_candela_dir(l->ies, *dir, l->direction, l->along, l->third);
    case LIGHT_SPOT: {
        double cos_outer = fmax(-1.0, fmin(1.0, l->cos_outer));
        double ct = 1.0 - u[0] * (1.0 - cos_outer), st = sqrt(fmax(0.0, 1.0 - ct * ct)), ph = 2.0 * M_PI * u[1];
        GVec3 t1, t2;
        goptics_frame(l->direction, &t1, &t2);
        *origin = l->position;
        *dir = gvec3_add(gvec3_scale(l->direction, ct),
                         gvec3_add(gvec3_scale(t1, st * cos(ph)), gvec3_scale(t2, st * sin(ph))));
        return spot_solid_angle(l) * smoothstep01(l->cos_outer, l->cos_inner, ct);
    }
    case LIGHT_DIRECTIONAL: {
        GVec3 t1, t2;
        goptics_frame(l->direction, &t1, &t2);
        double r = b->radius * sqrt(u[0]), ph = 2.0 * M_PI * u[1];
        GVec3 on = gvec3_add(gvec3_scale(t1, r * cos(ph)), gvec3_scale(t2, r * sin(ph)));
        *origin = gvec3_add(gvec3_sub(b->centre, gvec3_scale(l->direction, 2.0 * b->radius)), on);
        *dir = l->direction;
        return M_PI * b->radius * b->radius;
    }
    case LIGHT_SPHERE: {
        GVec3 n = uniform_sphere(u[0], u[1]);
        *origin = gvec3_madd(l->position, n, l->radius * (1.0 + 1e-9));
        *dir = goptics_sample_cosine(n, u[2], u[3]);
        return 4.0 * M_PI * M_PI * l->radius * l->radius;
    }
    case LIGHT_RECT: {
        GVec3 nl = gvec3_cross(l->edge1, l->edge2);
        double area = gvec3_length(nl);
        if (!(area > 0.0))
            return 0.0;
        nl = gvec3_scale(nl, 1.0 / area);
        *origin = gvec3_add(l->position, gvec3_add(gvec3_scale(l->edge1, u[0]), gvec3_scale(l->edge2, u[1])));
        *dir = goptics_sample_cosine(nl, u[2], u[3]);
        return M_PI * area;
    }
    default:
        return 0.0;
    }
}

double emit_power(const Light *l, const EmitBounds *b)
{
    if (l->kind == LIGHT_PROBE) {
        if (!emit_supported(l))
            return 0.0;
        const ProbeDist *d = &l->env->dist;
        return M_PI * b->radius * b->radius * d->row_cdf[d->h] * l->env->scale;
    }
    return gcolor_brightness_as(&l->color, GCOLOR_LIGHT) * emit_power_factor(l, b);
}

int emit_particle(const Light *l, const EmitBounds *b, const double u[4], GVec3 *origin, GVec3 *dir, double *factor,
                  GColor *color)
{
    *factor = 0.0;
    if (l->kind != LIGHT_PROBE) {
        *factor = emit_sample(l, b, u, origin, dir);
        return gcolor_copy(color, &l->color);
    }
    if (!emit_supported(l))
        return G_OK;
    const ProbeEnv *env = l->env;
    int pu, pv;
    GVec3 local, t1, t2;
    double pdf = probe_dist_sample(&env->dist, env->probe, u[0], u[1], &pu, &pv, &local);
    if (!(pdf > 0.0) || !isfinite(pdf))
        return G_OK;
    GVec3 in = gvec3_normalize(probe_to_world(env, local)); /* towards the probe */
    goptics_frame(in, &t1, &t2);
    double r = b->radius * sqrt(u[2]), ph = 2.0 * M_PI * u[3];
    GVec3 on = gvec3_add(gvec3_scale(t1, r * cos(ph)), gvec3_scale(t2, r * sin(ph)));
    *origin = gvec3_add(gvec3_madd(b->centre, in, 2.0 * b->radius), on);
    *dir = gvec3_neg(in);
    int rc = gprobe_pixel_color(env->probe, pu, pv, color);
    if (rc < 0)
        return rc;
    *factor = M_PI * b->radius * b->radius * env->scale / pdf;
    return G_OK;
}
