/* measure.c - gmat's measurements: one reflection, the ideal specular ray, the directional-hemispherical
 * reflectance by numeric integration, and printing colours. */
#include "gmat.h"

#include <math.h>
#include <stdio.h>

GVec3 gmat_direction(double theta_deg, double phi_deg)
{
    double t = theta_deg * M_PI / 180.0, p = phi_deg * M_PI / 180.0;
    return gvec3(sin(t) * cos(p), sin(t) * sin(p), cos(t));
}

void gmat_surface_point(GmatContext *ctx, GSurfPoint *sp, int below)
{
    gsurfpoint_init(sp, ctx->model, ctx->scratch);
    sp->geometric_normal = gvec3(0, 0, below ? -1 : 1);
    sp->dpdu = gvec3(1, 0, 0);
    sp->dpdv = gvec3(0, 1, 0);
    sp->u = sp->v = 0.5;
    if (ctx->place) {
        sp->u = ctx->place->u;
        sp->v = ctx->place->v;
        sp->point = sp->object_point = ctx->place->point;
        sp->surface = ctx->place->surface;
    }
    sp->entering = !below;
    sp->material = ctx->material;
    sp->from = below ? ctx->material : NULL;
    sp->to = below ? NULL : ctx->material;
}

double gmat_uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

int gmat_random_light(const GColorModel *m, unsigned long long *s, GColor *light)
{
    if (!m->cls->fill) { /* the library reads its values as plain samples: each one drawn on its own */
        for (int j = 0; j < m->nvalues; j++)
            light->v[j] = (float)(0.25 + 0.75 * gmat_uniform(s));
        light->kind = GCOLOR_VECTOR;
        return G_OK;
    }
    /* a model with its own representation: a random spectrum (a value every 10 nm, linear between) through its own
     * conversion, 41 degrees of freedom */
    enum { KNOTS = (GNM_COUNT - 1) / 10 + 1 };
    double knot[KNOTS];
    for (int k = 0; k < KNOTS; k++)
        knot[k] = 0.25 + 0.75 * gmat_uniform(s);
    GSpectrumNM nm;
    for (int i = 0; i < GNM_COUNT; i++) {
        int k = i / 10;
        double f = (i % 10) / 10.0;
        nm.v[i] = (float)(k + 1 < KNOTS ? knot[k] + f * (knot[k + 1] - knot[k]) : knot[k]);
    }
    return gcolor_from_nm(light, &nm, GCOLOR_LIGHT);
}

static const GColor *light(const GmatContext *ctx) { return ctx->light ? ctx->light : &ctx->white; }

int gmat_reflect(GmatContext *ctx, GVec3 in, GVec3 out)
{
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, 0);
    GScratchMark mark = gscratch_mark(ctx->scratch);
    int rc = gmaterial_reflection(ctx->material, &sp, in, light(ctx), out, &ctx->result);
    gscratch_release(ctx->scratch, mark);
    return rc;
}

/* The relative index n(from) / n(to) of the point as a colour (as a renderer hands it to refraction()). */
int gmat_relative_index(GSurfPoint *sp, GColor *out)
{
    GColor to;
    int rc = gcolor_scratch(&to, sp->model, sp->scratch);
    if (rc == G_OK)
        rc = gmaterial_refraction_index(sp->from, sp, out);
    if (rc == G_OK)
        rc = gmaterial_refraction_index(sp->to, sp, &to);
    return rc == G_OK ? gcolor_div(out, out, &to) : rc;
}

/* The relative index at sp into ri, a colour on sp's arena (released with the caller's mark). */
static int scratch_relative_index(GSurfPoint *sp, GColor *ri)
{
    int rc = gcolor_scratch(ri, sp->model, sp->scratch);
    return rc == G_OK ? gmat_relative_index(sp, ri) : rc;
}

double gmat_relative_eta(GSurfPoint *sp)
{
    GScratchMark mark = gscratch_mark(sp->scratch);
    GColor ri;
    double eta = NAN;
    if (scratch_relative_index(sp, &ri) == G_OK)
        eta = gsurfpoint_scalar_index(&ri);
    gscratch_release(sp->scratch, mark);
    return eta;
}

/* Light from in (upper hemisphere) refracted towards out (lower hemisphere), into ctx->result. */
static int transmit(GmatContext *ctx, GVec3 in, GVec3 out)
{
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, 1);
    GScratchMark mark = gscratch_mark(ctx->scratch);
    GColor ri;
    int rc = scratch_relative_index(&sp, &ri);
    if (rc == G_OK)
        rc = gmaterial_refraction(ctx->material, &sp, in, light(ctx), &ri, out, &ctx->result);
    gscratch_release(ctx->scratch, mark);
    return rc;
}

int gmat_specular(GmatContext *ctx, GVec3 in, GVec3 *dir)
{
    GSurfPoint sp;
    gmat_surface_point(ctx, &sp, 0);
    if (gmaterial_reflection_dir(ctx->material, &sp, gvec3_neg(in), dir) != 1)
        return 0;
    if (dir->z <= 0.0)
        return 0;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    int rc = gmaterial_reflection(ctx->material, &sp, in, light(ctx), *dir, &ctx->result);
    gscratch_release(ctx->scratch, mark);
    return rc == G_OK ? 1 : rc;
}

/* rho = 1/cos(theta_in) * integral of f(in, out) cos(theta_out) d(omega) over the upper (below = 0: reflection)
 * or lower (below = 1: refraction) hemisphere; with u = sin^2(theta_out): cos(theta) d(omega) = 1/2 du dphi
 * over [0,1] x [0, 2 pi]. Adds into total. */
int gmat_integrate(GmatContext *ctx, GVec3 in, int n, int below, GColor *total)
{
    double w = 0.5 * (1.0 / n) * (2.0 * M_PI / (2 * n)) / in.z;
    /* colours hold floats: sum each ring of directions on its own, then the rings, to keep rounding small */
    GColor ring = {0};
    if (gcolor_alloc(&ring, ctx->model) != G_OK)
        return G_ERR_NOMEM;
    int rc = G_OK;
    for (int i = 0; i < n && rc == G_OK; i++) {
        double u = (i + 0.5) / n, st = sqrt(u), ct = sqrt(1.0 - u);
        gcolor_black(&ring);
        for (int j = 0; j < 2 * n && rc == G_OK; j++) {
            double p = (j + 0.5) * 2.0 * M_PI / (2 * n);
            GVec3 out = gvec3(st * cos(p), st * sin(p), below ? -ct : ct);
            rc = below ? transmit(ctx, in, out) : gmat_reflect(ctx, in, out);
            if (rc == G_OK)
                rc = gcolor_add_scaled(&ring, &ctx->result, w);
        }
        if (rc == G_OK)
            rc = gcolor_add(total, total, &ring);
    }
    gcolor_free(&ring);
    return rc;
}

int gmat_albedo(GmatContext *ctx, GVec3 in, int n, GColor *total, double *y_total, double *y_specular)
{
    double xyz[3];
    gcolor_black(total);
    int rc = gmat_integrate(ctx, in, n, 0, total);
    if (rc != G_OK)
        return rc;
    *y_specular = 0.0;
    GVec3 dir;
    int spec = gmat_specular(ctx, in, &dir);
    if (spec < 0)
        return spec;
    if (spec == 1) { /* the aligned case returns the specular reflectance times the light: no cosines */
        rc = gcolor_to_xyz(&ctx->result, GCOLOR_LIGHT, xyz);
        if (rc != G_OK)
            return rc;
        *y_specular = xyz[1];
        rc = gcolor_add(total, total, &ctx->result);
        if (rc != G_OK)
            return rc;
    }
    rc = gcolor_to_xyz(total, GCOLOR_LIGHT, xyz);
    if (rc != G_OK)
        return rc;
    *y_total = xyz[1];
    return G_OK;
}

int gmat_ideal_refraction(GmatContext *ctx, GVec3 in, GVec3 *dir)
{
    /* the refraction direction of the light's ray seen from outside, evaluated from inside */
    GSurfPoint up;
    gmat_surface_point(ctx, &up, 0);
    GScratchMark mark = gscratch_mark(ctx->scratch);
    GColor ri;
    int rc = scratch_relative_index(&up, &ri);
    int valid = rc == G_OK ? gmaterial_refraction_dir(ctx->material, &up, gvec3_neg(in), &ri, dir) : rc;
    gscratch_release(ctx->scratch, mark);
    if (valid != 1 || dir->z >= 0.0)
        return valid < 0 ? valid : 0;
    *dir = gvec3_normalize(*dir);
    rc = transmit(ctx, in, *dir);
    return rc == G_OK ? 1 : rc;
}

int gmat_transmittance(GmatContext *ctx, GVec3 in, int n, GColor *total, double *y_ideal)
{
    int rc = gmat_integrate(ctx, in, n, 1, total);
    *y_ideal = 0.0;
    if (rc != G_OK)
        return rc;
    GVec3 dir;
    int ideal = gmat_ideal_refraction(ctx, in, &dir);
    if (ideal != 1)
        return ideal;
    double xyz[3];
    rc = gcolor_to_xyz(&ctx->result, GCOLOR_LIGHT, xyz);
    if (rc == G_OK) {
        *y_ideal = xyz[1];
        rc = gcolor_add(total, total, &ctx->result);
    }
    return rc;
}

void gmat_print_color(const char *label, const GColor *c, int spectrum)
{
    double xyz[3], rgb[3];
    if (gcolor_to_xyz(c, GCOLOR_LIGHT, xyz) != G_OK) {
        printf("%s (the colour cannot be converted to XYZ)\n", label);
        return;
    }
    gcie_xyz_to_rgb(xyz, rgb);
    printf("%s linear sRGB  %.6f %.6f %.6f\n", label, rgb[0], rgb[1], rgb[2]);
    printf("%s XYZ          %.6f %.6f %.6f\n", label, xyz[0], xyz[1], xyz[2]);
    if (!spectrum)
        return;
    GSpectrumNM s;
    if (gcolor_to_nm(c, GCOLOR_LIGHT, &s) != G_OK) {
        printf("%s spectrum     (not available in model %s)\n", label, gcolormodel_name(c->model));
        return;
    }
    const GColorModel *m = c->model;
    int native = m->nsamples > 0 && m->lambda_step >= 1.0;
    double start = native ? m->lambda_min : GNM_MIN, step = native ? m->lambda_step : 10.0;
    printf("%s spectrum     (nm, value per nm%s)\n", label, native ? ", the model's samples" : ", every 10 nm");
    for (double nm = start; nm <= GNM_MAX + 1e-9; nm += step) {
        int i = (int)lround(nm) - GNM_MIN;
        if (i >= 0 && i < GNM_COUNT)
            printf("  %6.1f %.6g\n", nm, s.v[i]);
    }
}
