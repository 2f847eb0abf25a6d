/* material_fixture.h - what the material tests share (test_materials.c, test_dielectric.c): a colour model
 * named by the test's state with a surface point on the plane z = 0, colours made in it, hemisphere
 * integration and sample extremes, and BOTH(f), which runs a case in the rgb and the spectrum model.
 * Include after <cmocka.h>. */
#ifndef GENERIC_TESTS_MATERIAL_FIXTURE_H
#define GENERIC_TESTS_MATERIAL_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/material.h"
#include "generic/materials.h"
#include "generic/reader.h"
#include "generic/registry.h"
#include "generic/surfpoint.h"
#include "test_util.h"

#define DEG (M_PI / 180.0)

typedef struct Fix {
    GColorModel *model;
    GScratch *scratch;
    GSurfPoint sp;
} Fix;

/* Creates the model named by the test's state (skips when it is not registered) and a surface point on the
 * plane z = 0 with the normal +z, seen from outside. */
static inline void fix_open(Fix *f, void **state)
{
    const char *name = *state;
    GError err;
    if (gcolormodel_create(name, NULL, &f->model, &err) != G_OK) {
        print_message("colour model '%s' not available: %s\n", name, err.message);
        skip();
    }
    f->scratch = gscratch_create(0);
    assert_non_null(f->scratch);
    gsurfpoint_init(&f->sp, f->model, f->scratch);
    f->sp.geometric_normal = gvec3(0, 0, 1);
}

static inline void fix_close(Fix *f)
{
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
}

static inline GColor new_color(Fix *f)
{
    GColor c;
    assert_int_equal(gcolor_scratch(&c, f->model, f->scratch), G_OK);
    return c;
}

/* A constant value v in every sample (exact in every model). */
static inline GColor grey(Fix *f, double v)
{
    GColor c = new_color(f);
    if (f->model->nsamples == 0) {
        double rgb[3] = {v, v, v};
        assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
    } else {
        GSpectrumNM s;
        for (int i = 0; i < GNM_COUNT; i++)
            s.v[i] = (float)v;
        assert_int_equal(gcolor_from_nm(&c, &s, GCOLOR_REFLECTANCE), G_OK);
    }
    for (int i = 0; i < f->model->nvalues; i++)
        assert_near(c.v[i], v, 1e-6);
    return c;
}

static inline GColor rgb_color(Fix *f, double r, double g, double b, GColorRole role)
{
    GColor c = new_color(f);
    double rgb[3] = {r, g, b};
    assert_int_equal(gcolor_from_rgb(&c, rgb, role), G_OK);
    return c;
}

static inline void assert_color_near(const GColor *a, const GColor *b, double tol)
{
    for (int i = 0; i < a->model->nvalues; i++)
        if (fabs(a->v[i] - b->v[i]) > tol * (1.0 + fabs(b->v[i])))
            fail_msg("sample %d: %.8g, expected %.8g (tolerance %g)", i, a->v[i], b->v[i], tol);
}

static inline void assert_black(const GColor *c)
{
    for (int i = 0; i < c->model->nvalues; i++)
        if (c->v[i] != 0.0f)
            fail_msg("sample %d is %g, expected black", i, c->v[i]);
}

static inline GVec3 dir_at(double theta, double phi)
{
    return gvec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

/* Directional-hemispherical reflectance for light from `in`: the integral over out of
 * f_r cos(theta_out) d(omega) = reflection(in, 1, out) / cos(theta_in) cos(theta_out) d(omega), midpoint rule
 * on an nt x np grid in (theta, phi). Written into acc, one value per sample. */
static inline void albedo(Fix *f, const GMaterial *m, GVec3 in, int nt, int np, GColor *acc)
{
    GScratchMark mark = gscratch_mark(f->scratch);
    GColor one = grey(f, 1.0), r = new_color(f);
    gcolor_black(acc);
    double dt = 0.5 * M_PI / nt, dp = 2.0 * M_PI / np, cos_in = in.z;
    for (int i = 0; i < nt; i++) {
        double th = (i + 0.5) * dt, w = cos(th) * sin(th) * dt * dp / cos_in;
        for (int j = 0; j < np; j++) {
            GVec3 out = dir_at(th, (j + 0.5) * dp);
            assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, out, &r), G_OK);
            assert_int_equal(gcolor_add_scaled(acc, &r, w), G_OK);
        }
    }
    gscratch_release(f->scratch, mark);
}

static inline double max_sample(const GColor *c)
{
    double mx = -INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        mx = fmax(mx, c->v[i]);
    return mx;
}

static inline double min_sample(const GColor *c)
{
    double mn = INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        mn = fmin(mn, c->v[i]);
    return mn;
}

#define BOTH(f)                                                                                                 \
    {#f " (rgb)", f, NULL, NULL, (void *)"rgb"}, { #f " (spectrum)", f, NULL, NULL, (void *)"spectrum" }

#endif
