/* test_dielectric.c - the smooth dielectric: Fresnel reflectance and total internal reflection, dispersion
 * (BK7 by Sellmeier), Beer-Lambert absorption, ideal rays about a tilted shading normal; each case in the rgb and
 * the spectrum model. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "material_fixture.h"

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

/* One ideal ray of the glass at f->sp for light leaving towards out (k 0: reflected, 1: refracted, with ri):
 * checks that it passes on nothing when it points back across the geometric surface (reflected into it, refracted
 * out of it) and something otherwise, and that the sample drawn along it (u1 picks the lobe) weighs the same.
 * Returns 1 when it crossed. */
static int tilted_ray(Fix *f, const GMaterial *glass, GVec3 out, const GColor *ri, int k, GVec3 dir)
{
    GColor one = grey(f, 1.0), r = new_color(f), w = new_color(f);
    int across = (dir.z < 0.0) != k;
    assert_int_equal(k ? gmaterial_refraction(glass, &f->sp, dir, &one, ri, out, &r)
                       : gmaterial_reflection(glass, &f->sp, dir, &one, out, &r), G_OK);
    if (across)
        assert_black(&r);
    else
        assert_true(max_sample(&r) > 0.0);
    GMaterialSample s;
    assert_int_equal(gmaterial_sample(glass, &f->sp, out, ri, k ? 0x1.fffffffffffffp-1 : 0.0, 0.5, &s, &w), 1);
    assert_int_equal(s.flags, GSAMPLE_DELTA | (k ? GSAMPLE_TRANSMIT : GSAMPLE_REFLECT));
    assert_true(gvec3_length(gvec3_sub(gvec3_normalize(s.in), gvec3_normalize(dir))) < 1e-9);
    assert_true(across ? max_sample(&w) == 0.0 : max_sample(&w) > 0.0);
    return across;
}

/* A shading normal tilted as a bump tilts it (40 and 75 degrees), seen from outside and from inside: an ideal ray
 * about it that points back across the geometric surface (reflected into the body, or refracted back into it from
 * inside) passes nothing on, as a mirror's does, where it leaked F or 1 - F of the light through the surface; the
 * rays on their own side pass on what they did. Each kind of crossing must occur. */
static void test_tilted_normal(void **state)
{
    Fix f;
    fix_open(&f, state);
    GMaterial *glass = make_glass(&f, 1.5);
    f.sp.material = glass;
    int crossed[2][2] = {{0, 0}, {0, 0}}, kept[2][2] = {{0, 0}, {0, 0}};
    for (int inside = 0; inside < 2; inside++) {
        f.sp.from = inside ? glass : NULL;
        f.sp.to = inside ? NULL : glass;
        f.sp.entering = !inside;
        GColor ri = rel_index(&f, f.sp.from, f.sp.to);
        for (double tilt = 40; tilt < 80; tilt += 35)
            for (double th = 5; th < 90; th += 5)
                for (double ph = 0; ph < 360; ph += 30) {
                    GVec3 out = dir_at(th * DEG, ph * DEG), ns = dir_at(tilt * DEG, 0), dir[2];
                    gsurfpoint_invalidate(&f.sp);
                    gsurfpoint_set_normal(&f.sp, ns);
                    if (gvec3_dot(out, ns) <= 0.01)
                        continue; /* the back of the facet */
                    assert_int_equal(gmaterial_reflection_dir(glass, &f.sp, gvec3_neg(out), &dir[0]), 1);
                    int refracts = gmaterial_refraction_dir(glass, &f.sp, gvec3_neg(out), &ri, &dir[1]);
                    for (int k = 0; k < 1 + refracts; k++) {
                        int c = tilted_ray(&f, glass, out, &ri, k, dir[k]);
                        crossed[inside][k] += c;
                        kept[inside][k] += !c;
                    }
                }
    }
    print_message("reflected rays crossing / kept: outside %d / %d, inside %d / %d; refracted: outside %d / %d, "
                  "inside %d / %d\n", crossed[0][0], kept[0][0], crossed[1][0], kept[1][0], crossed[0][1], kept[0][1],
                  crossed[1][1], kept[1][1]);
    assert_true(crossed[0][0] > 0 && crossed[1][0] > 0 && crossed[1][1] > 0);
    assert_int_equal(crossed[0][1], 0); /* entering the denser side, the refracted ray never turns back */
    assert_true(kept[0][0] > 0 && kept[1][0] > 0 && kept[0][1] > 0 && kept[1][1] > 0);
    gmaterial_unref(glass);
    fix_close(&f);
}

/* ---- emitter ---- */

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        BOTH(test_fresnel),
        BOTH(test_dispersion_bk7),
        BOTH(test_beer_lambert),
        BOTH(test_tilted_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
