/* texture_fixtures.h - test doubles shared by the texture tests: a material that counts its method calls
 * and answers with fixed values, a generator that counts its evaluations, and surface point set-up. */
#ifndef TEXTURE_FIXTURES_H
#define TEXTURE_FIXTURES_H

#include <generic/color.h>
#include <generic/material.h>
#include <generic/surfpoint.h>
#include <generic/texture.h>
#include <generic/textures.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ---- a material that counts calls ---- */

typedef struct CountMat {
    GMaterial base;
    double rgb[3];   /* diffuse, emission, refraction_index; times illum for the light methods */
    GVec3 normal;    /* returned by normal() */
    GVec3 refl_dir;  /* returned by reflection_dir() when refl_valid */
    int refl_valid;
    int opaque;
    int calls[GNODE_METHOD_COUNT];
} CountMat;

#define COUNT(self, m) (((CountMat *)(uintptr_t)(self))->calls[m]++)

static int cm_const(const GMaterial *self, GColor *result)
{
    const CountMat *c = (const CountMat *)self;
    return gcolor_from_rgb(result, c->rgb, GCOLOR_REFLECTANCE);
}

static int cm_times(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    GScratchMark mk = gscratch_mark(sp->scratch);
    GColor c;
    int rc = gcolor_scratch(&c, result->model, sp->scratch);
    if (rc == G_OK)
        rc = cm_const(self, &c);
    if (rc == G_OK)
        rc = gcolor_mul(result, &c, illum);
    gscratch_release(sp->scratch, mk);
    return rc;
}

static void cm_destroy(GMaterial *self) { free(self); }
static int cm_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out, GColor *r)
{
    (void)in;
    (void)out;
    COUNT(self, GNODE_REFLECTION);
    return cm_times(self, sp, illum, r);
}
static int cm_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *ri,
                         GVec3 out, GColor *r)
{
    (void)in;
    (void)out;
    (void)ri;
    COUNT(self, GNODE_REFRACTION);
    return cm_times(self, sp, illum, r);
}
static int cm_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *r)
{
    (void)sp;
    COUNT(self, GNODE_REFRACTION_INDEX);
    return cm_const(self, r);
}
static int cm_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)sp;
    (void)view;
    COUNT(self, GNODE_REFLECTION_DIR);
    const CountMat *c = (const CountMat *)self;
    if (c->refl_valid)
        *dir = c->refl_dir;
    return c->refl_valid;
}
static int cm_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *ri, GVec3 *dir)
{
    (void)sp;
    (void)view;
    (void)ri;
    (void)dir;
    COUNT(self, GNODE_REFRACTION_DIR);
    return 0;
}
static int cm_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *r)
{
    (void)sp;
    (void)out;
    COUNT(self, GNODE_EMISSION);
    return cm_const(self, r);
}
static int cm_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *r)
{
    COUNT(self, GNODE_AMBIENT);
    return cm_times(self, sp, illum, r);
}
static int cm_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double len, GColor *r)
{
    (void)len;
    COUNT(self, GNODE_ABSORPTION);
    if (!sp)
        return gcolor_copy(r, illum);
    return cm_times(self, sp, illum, r);
}
static int cm_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    (void)sp;
    COUNT(self, GNODE_NORMAL);
    *n = ((const CountMat *)self)->normal;
    return G_OK;
}
static int cm_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *r)
{
    (void)sp;
    COUNT(self, GNODE_DIFFUSE);
    return cm_const(self, r);
}
static int cm_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)sp;
    COUNT(self, GNODE_OPAQUE);
    return ((const CountMat *)self)->opaque;
}

static const GMaterialClass countmat_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "countmat",
    .description = "test material that counts its calls",
    .destroy = cm_destroy,
    .reflection = cm_reflection,
    .refraction = cm_refraction,
    .refraction_index = cm_refraction_index,
    .reflection_dir = cm_reflection_dir,
    .refraction_dir = cm_refraction_dir,
    .emission = cm_emission,
    .ambient = cm_ambient,
    .absorption = cm_absorption,
    .normal = cm_normal,
    .diffuse = cm_diffuse,
    .opaque = cm_opaque,
};

/* A counting material of a grey or coloured value with normal +z, opaque. */
static inline CountMat *countmat_new(const GColorModel *m, double r, double g, double b)
{
    CountMat *c = calloc(1, sizeof *c);
    if (!c || gmaterial_init(&c->base, &countmat_class, m, NULL) != G_OK) {
        free(c);
        return NULL;
    }
    c->rgb[0] = r;
    c->rgb[1] = g;
    c->rgb[2] = b;
    c->normal = gvec3(0, 0, 1);
    c->opaque = 1;
    return c;
}

static inline int countmat_total(const CountMat *c)
{
    int n = 0;
    for (int i = 0; i < GNODE_METHOD_COUNT; i++)
        n += c->calls[i];
    return n;
}

/* ---- a generator that counts evaluations ---- */

typedef struct CountGen {
    GGenerator base;
    double value;
    int calls;
    double u, v, axis1[2], axis2[2]; /* the (u, v) and footprint axes of the last point evaluated */
} CountGen;

static void cg_destroy(GGenerator *self) { free(self); }
static double cg_value(const GGenerator *self, GSurfPoint *sp)
{
    CountGen *g = (CountGen *)(uintptr_t)self;
    g->calls++;
    g->u = sp->u;
    g->v = sp->v;
    memcpy(g->axis1, sp->uv_axis1, sizeof g->axis1);
    memcpy(g->axis2, sp->uv_axis2, sizeof g->axis2);
    return ((const CountGen *)self)->value;
}

static const GGeneratorClass countgen_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "countgen",
    .description = "test generator that counts evaluations",
    .destroy = cg_destroy,
    .value = cg_value,
};

static inline CountGen *countgen_new(double value)
{
    CountGen *g = calloc(1, sizeof *g);
    if (!g || ggenerator_init(&g->base, &countgen_class, GGENERATOR_SPACE_NONE, NULL) != G_OK) {
        free(g);
        return NULL;
    }
    g->value = value;
    return g;
}

/* ---- surface points ---- */

/* A point on the plane z = 0 at (u, v) with unit tangents along x and y and normal +z. */
static inline void plane_point(GSurfPoint *sp, const GColorModel *m, GScratch *s, double u, double v)
{
    gsurfpoint_init(sp, m, s);
    sp->u = u;
    sp->v = v;
    sp->point = sp->object_point = gvec3(u, v, 0.0);
    sp->geometric_normal = gvec3(0, 0, 1);
    sp->dpdu = gvec3(1, 0, 0);
    sp->dpdv = gvec3(0, 1, 0);
}

/* The first channel of a colour as linear RGB (reflectance). */
static inline double color_r(const GColor *c)
{
    double rgb[3];
    assert_int_equal(gcolor_to_rgb(c, GCOLOR_REFLECTANCE, rgb), G_OK);
    return rgb[0];
}

#endif
