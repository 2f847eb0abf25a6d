/* test_materials.c - the built-in materials: energy conservation by numeric integration, reciprocity,
 * Fresnel, total internal reflection, dispersion (BK7), Beer-Lambert absorption, the ideal-direction
 * checks, emission sides and parameter checks. Every case runs in the rgb model and again in the
 * "spectrum" model (skipped while that model is not registered). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

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
static void fix_open(Fix *f, void **state)
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

static void fix_close(Fix *f)
{
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
}

static GColor new_color(Fix *f)
{
    GColor c;
    assert_int_equal(gcolor_scratch(&c, f->model, f->scratch), G_OK);
    return c;
}

/* A constant value v in every sample (exact in every model). */
static GColor grey(Fix *f, double v)
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

static GColor rgb_color(Fix *f, double r, double g, double b, GColorRole role)
{
    GColor c = new_color(f);
    double rgb[3] = {r, g, b};
    assert_int_equal(gcolor_from_rgb(&c, rgb, role), G_OK);
    return c;
}

static void assert_color_near(const GColor *a, const GColor *b, double tol)
{
    for (int i = 0; i < a->model->nvalues; i++)
        if (fabs(a->v[i] - b->v[i]) > tol * (1.0 + fabs(b->v[i])))
            fail_msg("sample %d: %.8g, expected %.8g (tolerance %g)", i, a->v[i], b->v[i], tol);
}

static void assert_black(const GColor *c)
{
    for (int i = 0; i < c->model->nvalues; i++)
        if (c->v[i] != 0.0f)
            fail_msg("sample %d is %g, expected black", i, c->v[i]);
}

static GVec3 dir_at(double theta, double phi)
{
    return gvec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

/* Directional-hemispherical reflectance for light from `in`: the integral over out of
 * f_r cos(theta_out) d(omega) = reflection(in, 1, out) / cos(theta_in) cos(theta_out) d(omega), midpoint rule
 * on an nt x np grid in (theta, phi). Written into acc, one value per sample. */
static void albedo(Fix *f, const GMaterial *m, GVec3 in, int nt, int np, GColor *acc)
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

static double max_sample(const GColor *c)
{
    double mx = -INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        mx = fmax(mx, c->v[i]);
    return mx;
}

static double min_sample(const GColor *c)
{
    double mn = INFINITY;
    for (int i = 0; i < c->model->nvalues; i++)
        mn = fmin(mn, c->v[i]);
    return mn;
}

/* ---- lambert ---- */

static void test_lambert_albedo(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor rho = grey(&f, 0.5), acc = new_color(&f);
    assert_int_equal(glambert_create(f.model, &rho, &m, &err), G_OK);
    const double angles[] = {0, 30, 60, 80};
    for (int k = 0; k < 4; k++) {
        albedo(&f, m, dir_at(angles[k] * DEG, 0.3), 200, 400, &acc);
        print_message("lambert rho 0.5, in %2.0f deg: albedo %.6f\n", angles[k], gcolor_brightness(&acc));
        assert_color_near(&acc, &rho, 1e-3);
    }
    /* light from below the surface, or a viewer below it, gets nothing */
    GColor one = grey(&f, 1.0), r = new_color(&f);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0, 0.6, -0.8), &one, gvec3(0, 0, 1), &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0, 0, 1), &one, gvec3(0, 0.6, -0.8), &r), G_OK);
    assert_black(&r);
    /* reflection = rho / pi cos(theta_in) illum, computed into the illum operand itself */
    GColor illum = rgb_color(&f, 2.0, 1.0, 0.5, GCOLOR_LIGHT), expect = new_color(&f);
    assert_int_equal(gcolor_mul(&expect, &rho, &illum), G_OK);
    assert_int_equal(gcolor_scale(&expect, &expect, 0.8 / M_PI), G_OK);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0.6, 0, 0.8), &illum, gvec3(0, 0, 1), &illum), G_OK);
    assert_color_near(&illum, &expect, 1e-6);
    /* diffuse, ambient, opaque */
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    assert_color_near(&r, &rho, 0);
    GColor amb = grey(&f, 0.25);
    assert_int_equal(gmaterial_ambient(m, &f.sp, &amb, &r), G_OK);
    GColor eighth = grey(&f, 0.125);
    assert_color_near(&r, &eighth, 1e-7);
    assert_int_equal(gmaterial_opaque(m, &f.sp), 1);
    GVec3 d;
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3(0, 0, -1), &d), 0);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- phong ---- */

static GMaterial *make_phong(Fix *f, double kd, double ks, double n, double mirror)
{
    GError err;
    GMaterial *m;
    GColor ckd = grey(f, kd), cks = grey(f, ks), cm = grey(f, mirror);
    GPhongParams p = {&ckd, &cks, n, mirror > 0 ? &cm : NULL};
    if (gphong_create(f->model, &p, &m, &err) != G_OK)
        fail_msg("gphong_create: %s", err.message);
    return m;
}

static void test_phong_albedo(void **state)
{
    Fix f;
    fix_open(&f, state);
    GColor acc = new_color(&f);
    const double ns[] = {1, 10, 100, 1000};
    const double angles[] = {0, 30, 60, 85};
    for (int a = 0; a < 4; a++) {
        GMaterial *m = make_phong(&f, 0.3, 0.6, ns[a], 0);
        for (int k = 0; k < 4; k++) {
            albedo(&f, m, dir_at(angles[k] * DEG, 1.1), ns[a] >= 1000 ? 400 : 200, 200, &acc);
            double lo = min_sample(&acc), hi = max_sample(&acc);
            print_message("phong kd 0.3 ks 0.6 n %4.0f, in %2.0f deg: albedo %.6f\n", ns[a], angles[k], hi);
            assert_true(hi <= 1.0);
            assert_true(hi <= 0.9 + 2e-3);
            assert_true(hi - lo < 1e-5); /* constant parameters give a constant result */
            if (angles[k] == 0)          /* the whole lobe is above the horizon: exactly kd + ks */
                assert_near(hi, 0.9, 2e-3);
        }
        gmaterial_unref(m);
    }
    /* a narrow lobe off the normal reflects ks cos(theta_r) (the projected lobe) */
    GMaterial *m = make_phong(&f, 0.0, 1.0, 1000, 0);
    albedo(&f, m, dir_at(30 * DEG, 0.0), 400, 200, &acc);
    print_message("phong ks 1 n 1000, in 30 deg: albedo %.6f (cos 30 = %.6f)\n", max_sample(&acc), cos(30 * DEG));
    assert_near(max_sample(&acc), cos(30 * DEG), 3e-3);
    gmaterial_unref(m);
    fix_close(&f);
}

/* f_r(in, out) = reflection(in, 1, out) / cos(theta_in) must equal f_r(out, in). */
static void check_reciprocity(Fix *f, const GMaterial *m)
{
    GColor one = grey(f, 1.0), a = new_color(f), b = new_color(f);
    uint64_t seed = 12345;
    int nonzero = 0;
    for (int k = 0; k < 500; k++) {
        double u[4];
        for (int i = 0; i < 4; i++) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            u[i] = (double)(seed >> 11) / 9007199254740992.0;
        }
        GVec3 in = dir_at(acos(0.02 + 0.97 * u[0]), 2 * M_PI * u[1]);
        GVec3 out = dir_at(acos(0.02 + 0.97 * u[2]), 2 * M_PI * u[3]);
        assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, out, &a), G_OK);
        assert_int_equal(gmaterial_reflection(m, &f->sp, out, &one, in, &b), G_OK);
        assert_int_equal(gcolor_scale(&a, &a, 1.0 / in.z), G_OK);
        assert_int_equal(gcolor_scale(&b, &b, 1.0 / out.z), G_OK);
        assert_color_near(&a, &b, 2e-5);
        nonzero += gcolor_brightness(&a) > 0.0;
    }
    assert_int_equal(nonzero, 500);
}

static void test_reciprocity(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor rho = rgb_color(&f, 0.8, 0.5, 0.2, GCOLOR_REFLECTANCE);
    assert_int_equal(glambert_create(f.model, &rho, &m, &err), G_OK);
    check_reciprocity(&f, m);
    gmaterial_unref(m);
    const double ns[] = {0, 3, 40};
    for (int i = 0; i < 3; i++) {
        m = make_phong(&f, 0.2, 0.7, ns[i], 0);
        check_reciprocity(&f, m);
        gmaterial_unref(m);
    }
    fix_close(&f);
}

static void test_phong_lobe_and_mirror(void **state)
{
    Fix f;
    fix_open(&f, state);
    GColor one = grey(&f, 1.0), r = new_color(&f);
    GVec3 in = dir_at(40 * DEG, 0.0), mir = dir_at(40 * DEG, M_PI), d;
    /* the lobe's peak value: (kd / pi + ks (n + 2) / (2 pi)) cos(theta_in) */
    GMaterial *m = make_phong(&f, 0.25, 0.5, 20, 0);
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3_neg(mir), &d), 0);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &one, mir, &r), G_OK);
    assert_near(max_sample(&r), (0.25 / M_PI + 0.5 * 22 / (2 * M_PI)) * cos(40 * DEG), 1e-5);
    /* 10 degrees off the mirror direction in the plane of incidence: cos^20(10 deg) */
    GVec3 off = dir_at(50 * DEG, M_PI);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &one, off, &r), G_OK);
    assert_near(max_sample(&r), (0.25 / M_PI + 0.5 * 22 / (2 * M_PI) * pow(cos(10 * DEG), 20)) * cos(40 * DEG),
                       1e-5);
    gmaterial_unref(m);
    /* with a mirror reflectance: a reflection ray, and the aligned pair returns mirror * illum */
    m = make_phong(&f, 0.25, 0.5, 20, 0.2);
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3_neg(in), &d), 1);
    assert_near(gvec3_dot(d, mir), 1.0, 1e-12);
    GColor illum = rgb_color(&f, 3.0, 2.0, 1.0, GCOLOR_LIGHT), expect = new_color(&f), cm = grey(&f, 0.2);
    assert_int_equal(gcolor_mul(&expect, &cm, &illum), G_OK);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &illum, mir, &r), G_OK);
    assert_color_near(&r, &expect, 1e-6);
    /* ambient reflects the albedo kd + ks + mirror */
    assert_int_equal(gmaterial_ambient(m, &f.sp, &one, &r), G_OK);
    GColor sum = grey(&f, 0.95);
    assert_color_near(&r, &sum, 1e-6);
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    GColor kd = grey(&f, 0.25);
    assert_color_near(&r, &kd, 0);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- mirror ---- */

static void test_mirror(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor R = rgb_color(&f, 0.9, 0.6, 0.3, GCOLOR_REFLECTANCE), illum = rgb_color(&f, 1.0, 2.0, 4.0, GCOLOR_LIGHT);
    GColor r = new_color(&f), expect = new_color(&f);
    assert_int_equal(gmirror_create(f.model, &R, &m, &err), G_OK);
    GColor Rm = new_color(&f), white = grey(&f, 1.0);
    assert_int_equal(gmaterial_ambient(m, &f.sp, &white, &Rm), G_OK); /* R itself */
    assert_int_equal(gcolor_mul(&expect, &Rm, &illum), G_OK);
    GVec3 view = gvec3_normalize(gvec3(0.3, -0.4, -0.7)), d;
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, view, &d), 1);
    assert_near(gvec3_length(d), 1.0, 1e-12);
    assert_near(d.z, -view.z, 1e-12);
    /* as the tracer calls it: in = the reflected ray, out = towards the viewer */
    assert_int_equal(gmaterial_reflection(m, &f.sp, d, &illum, gvec3_neg(view), &r), G_OK);
    assert_color_near(&r, &expect, 1e-6);
    /* a few degrees off: nothing */
    double theta = acos(d.z), phi = atan2(d.y, d.x);
    const double offs[] = {0.5, 2.0, 5.0};
    for (int k = 0; k < 3; k++) {
        assert_int_equal(gmaterial_reflection(m, &f.sp, dir_at(theta + offs[k] * DEG, phi), &illum,
                                              gvec3_neg(view), &r), G_OK);
        assert_black(&r);
        assert_int_equal(gmaterial_reflection(m, &f.sp, dir_at(theta, phi + offs[k] * DEG), &illum,
                                              gvec3_neg(view), &r), G_OK);
        assert_black(&r);
    }
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_opaque(m, &f.sp), 1);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- dielectric ---- */

static GMaterial *make_glass(Fix *f, double n)
{
    GError err;
    GMaterial *m;
    GDielectricParams p = {gdispersion_constant(n), NULL, NULL};
    if (gdielectric_create(f->model, &p, &m, &err) != G_OK)
        fail_msg("gdielectric_create: %s", err.message);
    return m;
}

/* The tracer's relative index n(from) / n(to) as a colour. */
static GColor rel_index(Fix *f, const GMaterial *from, const GMaterial *to)
{
    GColor a = new_color(f), b = new_color(f);
    assert_int_equal(gmaterial_refraction_index(from, NULL, &a), G_OK);
    assert_int_equal(gmaterial_refraction_index(to, NULL, &b), G_OK);
    assert_int_equal(gcolor_div(&a, &a, &b), G_OK);
    return a;
}

/* Reflected and refracted fractions for a viewer at angle theta, as the tracer of Fig. 4 computes them. */
static int split(Fix *f, const GMaterial *m, double theta, double *refl, double *trans)
{
    GColor one = grey(f, 1.0), r = new_color(f);
    GColor ri = rel_index(f, f->sp.from, f->sp.to);
    GVec3 view = gvec3_neg(dir_at(theta, 0.7)), rd, td;
    gsurfpoint_invalidate(&f->sp);
    assert_int_equal(gmaterial_reflection_dir(m, &f->sp, view, &rd), 1);
    assert_int_equal(gmaterial_reflection(m, &f->sp, rd, &one, gvec3_neg(view), &r), G_OK);
    *refl = gcolor_brightness(&r);
    int valid = gmaterial_refraction_dir(m, &f->sp, view, &ri, &td);
    *trans = 0.0;
    if (valid) {
        /* Snell: n_from sin(theta) = n_to sin(theta_t) */
        double eta = gcolor_brightness(&ri);
        assert_near(hypot(td.x, td.y), eta * sin(theta), 1e-9);
        assert_true(td.z < 0);
        assert_int_equal(gmaterial_refraction(m, &f->sp, td, &one, &ri, gvec3_neg(view), &r), G_OK);
        *trans = gcolor_brightness(&r);
        /* not aligned: nothing */
        assert_int_equal(gmaterial_refraction(m, &f->sp, gvec3_normalize(gvec3(td.x + 0.05, td.y, td.z)), &one, &ri,
                                              gvec3_neg(view), &r), G_OK);
        assert_black(&r);
    }
    return valid;
}

static void test_fresnel(void **state)
{
    Fix f;
    fix_open(&f, state);
    /* the helper itself: normal incidence ((n-1)/(n+1))^2 and Brewster's angle ((n^2-1)/(n^2+1))^2 / 2 */
    assert_near(goptics_fresnel(1.0, 1.0 / 1.5), 0.04, 1e-12);
    assert_near(goptics_fresnel(cos(atan(1.5)), 1.0 / 1.5), pow(1.25 / 3.25, 2) / 2, 1e-12);
    assert_near(goptics_fresnel(0.0, 1.0 / 1.5), 1.0, 1e-12);
    GMaterial *glass = make_glass(&f, 1.5);
    f.sp.material = glass;
    f.sp.from = NULL;
    f.sp.to = glass;
    assert_near(gsurfpoint_relative_index(&f.sp), 1.0 / 1.5, 1e-7);
    double R, T;
    assert_int_equal(split(&f, glass, 0.0, &R, &T), 1);
    print_message("dielectric n 1.5 normal incidence: R %.8f T %.8f\n", R, T);
    assert_near(R, 0.04, 1e-6);
    assert_near(T, 0.96, 1e-6);
    assert_int_equal(split(&f, glass, atan(1.5), &R, &T), 1);
    print_message("dielectric n 1.5 Brewster %.3f deg: R %.8f\n", atan(1.5) / DEG, R);
    assert_near(R, pow(1.25 / 3.25, 2) / 2, 1e-6);
    /* R + T = 1 from outside at every angle */
    for (double th = 0; th < 89.5; th += 10) {
        assert_int_equal(split(&f, glass, th * DEG, &R, &T), 1);
        print_message("  outside %2.0f deg: R %.6f T %.6f\n", th, R, T);
        assert_near(R + T, 1.0, 1e-6);
    }
    /* from inside: R + T = 1 below the critical angle, total internal reflection above it */
    f.sp.from = glass;
    f.sp.to = NULL;
    f.sp.entering = 0;
    double crit = asin(1.0 / 1.5);
    const double inside[] = {0, 20, 40, 41.5};
    for (int k = 0; k < 4; k++) {
        assert_int_equal(split(&f, glass, inside[k] * DEG, &R, &T), 1);
        print_message("  inside %4.1f deg: R %.6f T %.6f\n", inside[k], R, T);
        assert_near(R + T, 1.0, 1e-6);
    }
    const double beyond[] = {crit / DEG + 0.1, 42, 60, 85};
    for (int k = 0; k < 4; k++) {
        assert_int_equal(split(&f, glass, beyond[k] * DEG, &R, &T), 0);
        assert_near(R, 1.0, 1e-6);
    }
    print_message("critical angle %.4f deg: TIR from %.4f deg on\n", crit / DEG, crit / DEG + 0.1);
    assert_int_equal(gmaterial_opaque(glass, &f.sp), 0);
    gmaterial_unref(glass);
    fix_close(&f);
}

static void test_dispersion_bk7(void **state)
{
    Fix f;
    fix_open(&f, state);
    const double B[3] = {1.03961212, 0.231792344, 1.01046945};
    const double C[3] = {0.00600069867, 0.0200179144, 103.560653};
    GDispersion bk7 = gdispersion_sellmeier(B, C);
    double nd = gdispersion_index(&bk7, 589.3), nF = gdispersion_index(&bk7, 486.1),
           nC = gdispersion_index(&bk7, 656.3);
    double abbe = (nd - 1) / (nF - nC);
    print_message("BK7 Sellmeier: n_d %.6f, n_F %.6f, n_C %.6f, Abbe %.2f\n", nd, nF, nC, abbe);
    assert_near(nd, 1.5168, 2e-4);
    assert_near(abbe, 64.17, 0.2); /* Schott's catalogue value */
    /* the catalogue's Cauchy fit of the same glass */
    GDispersion cauchy = gdispersion_cauchy(1.5046, 0.00420, 0.0);
    double worst = 0;
    for (int nm = 400; nm <= 700; nm += 5)
        worst = fmax(worst, fabs(gdispersion_index(&cauchy, nm) - gdispersion_index(&bk7, nm)));
    print_message("Cauchy (1.5046, 0.00420) vs Sellmeier, 400..700 nm: max difference %.2e\n", worst);
    assert_true(worst < 2e-4);
    for (int nm = 400; nm < 700; nm += 10) /* normal dispersion: n falls with the wavelength */
        assert_true(gdispersion_index(&bk7, nm) > gdispersion_index(&bk7, nm + 10));

    GError err;
    GMaterial *m;
    GDielectricParams p = {bk7, NULL, NULL};
    assert_int_equal(gdielectric_create(f.model, &p, &m, &err), G_OK);
    GColor n = new_color(&f);
    assert_int_equal(gmaterial_refraction_index(m, NULL, &n), G_OK);
    if (f.model->nsamples == 0) {
        assert_near(n.v[0], gdispersion_index(&bk7, 610), 1e-6);
        assert_near(n.v[1], gdispersion_index(&bk7, 550), 1e-6);
        assert_near(n.v[2], gdispersion_index(&bk7, 465), 1e-6);
    } else {
        int k = (int)lround((589.3 - f.model->lambda_min) / f.model->lambda_step);
        double lk = f.model->lambda_min + k * f.model->lambda_step;
        print_message("spectrum sample %d at %.1f nm: n %.6f (formula %.6f)\n", k, lk, n.v[k],
                      gdispersion_index(&bk7, lk));
        assert_near(n.v[k], gdispersion_index(&bk7, lk), 1e-4);
        assert_near(n.v[k], 1.5168, 2e-4 + 5e-5 * fabs(lk - 589.3));
        for (int i = 0; i + 1 < f.model->nsamples; i++)
            assert_true(n.v[i] >= n.v[i + 1]);
    }
    double b = gcolor_brightness(&n);
    assert_true(b > gdispersion_index(&bk7, 650) && b < gdispersion_index(&bk7, 450));
    gmaterial_unref(m);
    fix_close(&f);
}

static void test_beer_lambert(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor a = rgb_color(&f, 0.1, 0.5, 2.0, GCOLOR_REFLECTANCE);
    for (int i = 0; i < f.model->nvalues; i++) /* a coefficient may be anything >= 0 */
        a.v[i] = fmaxf(a.v[i], 0.0f);
    GDielectricParams p = {gdispersion_constant(1.33), &a, NULL};
    assert_int_equal(gdielectric_create(f.model, &p, &m, &err), G_OK);
    GColor illum = rgb_color(&f, 1.0, 3.0, 0.5, GCOLOR_LIGHT), r = new_color(&f), copy = new_color(&f);
    for (int i = 0; i < f.model->nvalues; i++)
        illum.v[i] = fmaxf(illum.v[i], 0.01f);
    const double ds[] = {0.0, 0.3, 1.0, 2.5, 10.0};
    for (int k = 0; k < 5; k++) {
        assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, ds[k], &r), G_OK);
        for (int i = 0; i < f.model->nvalues; i++)
            assert_near(r.v[i] / illum.v[i], exp(-a.v[i] * ds[k]), 1e-5);
        /* in place, with and without an arena */
        assert_int_equal(gcolor_copy(&copy, &illum), G_OK);
        assert_int_equal(gmaterial_absorption(m, &f.sp, &copy, ds[k], &copy), G_OK);
        assert_color_near(&copy, &r, 1e-6);
        assert_int_equal(gcolor_copy(&copy, &illum), G_OK);
        assert_int_equal(gmaterial_absorption(m, NULL, &copy, ds[k], &copy), G_OK);
        assert_color_near(&copy, &r, 1e-6);
    }
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, 2.5, &r), G_OK);
    print_message("transmittance after 2.5 units, first sample: %.7f (exp(-a d) = %.7f)\n", r.v[0] / illum.v[0],
                  exp(-a.v[0] * 2.5));
    /* T(d1) T(d2) = T(d1 + d2) */
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, 0.7, &r), G_OK);
    assert_int_equal(gmaterial_absorption(m, &f.sp, &r, 1.3, &r), G_OK);
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, 2.0, &copy), G_OK);
    assert_color_near(&r, &copy, 1e-5);
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, -1.0, &r), G_ERR_INVALID);
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, NAN, &r), G_ERR_INVALID);
    gmaterial_unref(m);
    /* clear glass and vacuum absorb nothing */
    m = make_glass(&f, 1.5);
    assert_int_equal(gmaterial_absorption(m, &f.sp, &illum, 100.0, &r), G_OK);
    assert_color_near(&r, &illum, 0);
    assert_int_equal(gmaterial_absorption(NULL, &f.sp, &illum, 100.0, &r), G_OK);
    assert_color_near(&r, &illum, 0);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- emitter ---- */

static void test_emitter(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *one_side, *two_side;
    GColor L = rgb_color(&f, 5.0, 4.0, 3.0, GCOLOR_LIGHT), r = new_color(&f), one = grey(&f, 1.0);
    for (int i = 0; i < f.model->nvalues; i++)
        L.v[i] = fmaxf(L.v[i], 0.0f);
    assert_int_equal(gemitter_create(f.model, &L, 0, &one_side, &err), G_OK);
    assert_int_equal(gemitter_create(f.model, &L, 1, &two_side, &err), G_OK);
    GVec3 out = dir_at(50 * DEG, 2.0);
    /* seen from outside (the normal faces the viewer and is the outward normal) */
    f.sp.entering = 1;
    assert_int_equal(gmaterial_emission(one_side, &f.sp, out, &r), G_OK);
    assert_color_near(&r, &L, 0);
    assert_int_equal(gmaterial_emission(one_side, &f.sp, gvec3_neg(out), &r), G_OK);
    assert_black(&r);
    /* seen from inside: the normal faces inwards, so out along it is the back */
    f.sp.entering = 0;
    assert_int_equal(gmaterial_emission(one_side, &f.sp, out, &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_emission(two_side, &f.sp, out, &r), G_OK);
    assert_color_near(&r, &L, 0);
    /* no reflection, no diffuse colour */
    assert_int_equal(gmaterial_reflection(one_side, &f.sp, out, &one, gvec3(0, 0, 1), &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_diffuse(one_side, &f.sp, &r), G_OK);
    assert_black(&r);
    gmaterial_unref(one_side);
    gmaterial_unref(two_side);
    fix_close(&f);
}

/* ---- parameter checks ---- */

static void expect_error_(int rc, GMaterial **m, const GError *err, const char *a, const char *b)
{
    assert_int_equal(rc, G_ERR_INVALID);
    assert_null(*m);
    *m = (GMaterial *)err; /* a non-NULL sentinel for the next call */
    print_message("refused: %s\n", err->message);
    if (!strstr(err->message, a) || (b && !strstr(err->message, b)))
        fail_msg("message '%s' should mention '%s' and '%s'", err->message, a, b ? b : "");
}

/* rc is evaluated before m is looked at */
#define expect_error(call, m, err, a, b)                                                                        \
    do {                                                                                                        \
        int rc_ = (call);                                                                                       \
        expect_error_(rc_, &(m), (err), (a), (b));                                                              \
    } while (0)

static void test_bad_parameters(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m = (GMaterial *)&f;
    GColor bad = grey(&f, 0.5), good = grey(&f, 0.4), big = grey(&f, 0.7);
    bad.v[1] = NAN;
    expect_error(glambert_create(f.model, &bad, &m, &err), m, &err, "reflectance", "nan");
    bad.v[1] = -0.25f;
    expect_error(gmirror_create(f.model, &bad, &m, &err), m, &err, "reflectance", "-0.25");
    expect_error(gemitter_create(f.model, &bad, 0, &m, &err), m, &err, "radiance", "-0.25");
    bad.v[1] = 1.5f;
    expect_error(glambert_create(f.model, &bad, &m, &err), m, &err, "reflectance", "1.5");
    expect_error(glambert_create(f.model, NULL, &m, &err), m, &err, "reflectance", "missing");

    GPhongParams pp = {&good, &good, -2.0, NULL};
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "exponent", "-2");
    pp.exponent = NAN;
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "exponent", "nan");
    pp.exponent = 10;
    pp.ks = &big; /* 0.4 + 0.7 */
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "kd + ks", "1.1");
    pp.ks = &good;
    pp.mirror = &good; /* 0.4 + 0.4 + 0.4 */
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "kd + ks + mirror", "1.2");

    double B[3] = {1.03961212, NAN, 1.01046945}, C[3] = {0.00600069867, 0.0200179144, 103.560653};
    GDielectricParams dp = {gdispersion_sellmeier(B, C), NULL, NULL};
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Sellmeier", "B2");
    B[1] = 0.231792344;
    C[2] = 0.36; /* a pole at 600 nm */
    dp.index = gdispersion_sellmeier(B, C);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Sellmeier", "nm");
    dp.index = gdispersion_constant(-1.5);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "index", "-1.5");
    dp.index = gdispersion_cauchy(1.5, INFINITY, 0);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Cauchy", "B");
    dp.index = gdispersion_constant(1.5);
    bad.v[1] = -1.0f;
    dp.absorption = &bad;
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "absorption", "-1");
    dp.absorption = NULL;
    dp.tint = &bad;
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "tint", "-1");
    fix_close(&f);
}

/* A constructor's complaint names its parameter (gerror_set_param); the reader places it there: the message's
 * position and the GError fields agree, and a parameter the file did not write is placed at the last token. */
static void test_error_at_parameter(void **state)
{
    (void)state;
    GError err;
    assert_int_equal(gerror_set_param(&err, G_ERR_INVALID, "reflectance", "x: %d", 7), G_ERR_INVALID);
    assert_string_equal(err.param, "reflectance");
    assert_string_equal(err.message, "x: 7");
    assert_int_equal(err.line, 0);
    gerror_set(&err, G_ERR_INVALID, "y");
    assert_string_equal(err.param, "");

    GLibrary *lib = NULL;
    /* "reflectance" starts at line 3, column 5; the bad value is read after it */
    assert_int_equal(greader_load_string("\nmaterial w lambert {\n    reflectance rgb 0.5 -2 0.5 }\n", "t.mat", NULL,
                                         &lib, &err),
                     G_ERR_INVALID);
    assert_null(lib);
    assert_int_equal(err.line, 3);
    assert_int_equal(err.col, 5);
    assert_string_equal(err.param, "reflectance");
    assert_string_equal(err.message,
                        "t.mat:3:5: lambert: reflectance has the value -2 at sample 1 (must be finite and >= 0)");
    /* phong names kd + ks + mirror, which is no parameter of the file: the last token read, the closing brace */
    assert_int_equal(greader_load_string("material m phong { diffuse rgb 0.6 0.6 0.6\n"
                                         "  specular rgb 0.3 0.3 0.3 mirror rgb 0.3 0.3 0.3 }\n",
                                         "p.mat", NULL, &lib, &err),
                     G_ERR_INVALID);
    assert_int_equal(err.line, 2);
    assert_int_equal(err.col, 51);
    assert_string_equal(err.param, "");
    assert_non_null(strstr(err.message, "p.mat:2:51: phong: kd + ks + mirror is"));
}

static void test_registered(void **state)
{
    (void)state;
    static const char *const names[] = {"lambert", "phong", "mirror", "dielectric", "emitter"};
    for (int i = 0; i < 5; i++) {
        const GTypeInfo *t = gregistry_find(GKIND_MATERIAL, names[i]);
        assert_non_null(t);
        const GMaterialClass *cls = t->vtable;
        assert_non_null(cls);
        assert_string_equal(cls->name, names[i]);
        assert_int_equal(cls->abi_version, GMATERIAL_ABI_VERSION);
        assert_non_null(t->parse);
    }
}

#define BOTH(f)                                                                                                 \
    {#f " (rgb)", f, NULL, NULL, (void *)"rgb"}, { #f " (spectrum)", f, NULL, NULL, (void *)"spectrum" }

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        BOTH(test_lambert_albedo),
        BOTH(test_phong_albedo),
        BOTH(test_reciprocity),
        BOTH(test_phong_lobe_and_mirror),
        BOTH(test_mirror),
        BOTH(test_fresnel),
        BOTH(test_dispersion_bk7),
        BOTH(test_beer_lambert),
        BOTH(test_emitter),
        BOTH(test_bad_parameters),
        cmocka_unit_test(test_registered),
        cmocka_unit_test(test_error_at_parameter),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
