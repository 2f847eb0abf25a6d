/* test_thindielectric.c - the thin dielectric pane: R + T = 1 at every angle (lossless), R at normal incidence
 * 2 R0 / (1 + R0) with R0 = ((n - 1) / (n + 1))^2, the sum of the inner reflections against a direct sum of the
 * series, straight transmission (no offset), its delta lobes drawn with probability R and 1 - R, pdf 0; each case
 * in the rgb and the spectrum model. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "material_fixture.h"

static GMaterial *make_pane(Fix *f, double n)
{
    GError err;
    GMaterial *m;
    GDispersion d = gdispersion_constant(n);
    if (gthindielectric_create(f->model, &d, &m, &err) != G_OK)
        fail_msg("gthindielectric_create: %s", err.message);
    return m;
}

/* What the pane reflects and transmits of white light seen at theta. */
static void split(Fix *f, const GMaterial *m, double theta, double *refl, double *trans)
{
    GColor one = grey(f, 1.0), r = new_color(f);
    GVec3 out = dir_at(theta, 0.4), view = gvec3_neg(out), rd, td;
    assert_int_equal(gmaterial_reflection_dir(m, &f->sp, view, &rd), 1);
    assert_int_equal(gmaterial_reflection(m, &f->sp, rd, &one, out, &r), G_OK);
    *refl = gcolor_brightness(&r);
    assert_int_equal(gmaterial_refraction_dir(m, &f->sp, view, NULL, &td), 1);
    assert_true(gvec3_dot(td, view) > 1.0 - 1e-15); /* straight on */
    assert_int_equal(gmaterial_refraction(m, &f->sp, td, &one, NULL, out, &r), G_OK);
    *trans = gcolor_brightness(&r);
    /* a refracted pair of a real glass is no pair of the pane */
    GVec3 bent;
    assert_int_equal(goptics_refract(view, gvec3(0, 0, 1), 1.0 / 1.5, &bent), 1);
    if (theta > 1e-3) {
        assert_int_equal(gmaterial_refraction(m, &f->sp, bent, &one, NULL, out, &r), G_OK);
        assert_black(&r);
    }
}

static void lossless_and_normal_incidence(void **state)
{
    Fix f;
    fix_open(&f, state);
    const double ns[3] = {1.33, 1.5, 2.4};
    for (int k = 0; k < 3; k++) {
        GMaterial *m = make_pane(&f, ns[k]);
        double n = ns[k], r0 = (n - 1) * (n - 1) / ((n + 1) * (n + 1)), R, T;
        split(&f, m, 0.0, &R, &T);
        print_message("n %.2f: R0 %.6f, pane R %.6f (2 R0 / (1 + R0) = %.6f), T %.6f\n", n, r0, R,
                      2 * r0 / (1 + r0), T);
        assert_near(R, 2 * r0 / (1 + r0), 1e-6);
        for (int a = 0; a <= 89; a += 3) {
            double theta = a * DEG;
            split(&f, m, theta, &R, &T);
            assert_near(R + T, 1.0, 1e-6);
            /* the series F + (1 - F)^2 F (1 + F^2 + F^4 + ...), summed term by term */
            double F = goptics_fresnel(cos(theta), 1.0 / n), series = F, term = (1 - F) * (1 - F) * F;
            for (int i = 0; i < 200; i++, term *= F * F)
                series += term;
            assert_near(R, series, 1e-6);
            assert_true(R >= F - 1e-12); /* the pane reflects more than one face */
        }
        assert_int_equal(gmaterial_is_delta(m, &f.sp), 1);
        assert_int_equal(gmaterial_opaque(m, &f.sp), 0);
        assert_true(gmaterial_diagonal(m));
        gmaterial_unref(m);
    }
    fix_close(&f);
}

static void delta_lobes(void **state)
{
    Fix f;
    fix_open(&f, state);
    GMaterial *m = make_pane(&f, 1.5);
    GVec3 out = dir_at(60 * DEG, 1.1);
    double R, T;
    split(&f, m, 60 * DEG, &R, &T);
    GColor w = new_color(&f);
    int reflected = 0, n = 4000;
    for (int i = 0; i < n; i++) {
        GMaterialSample s;
        double u1 = (i + 0.5) / n;
        assert_int_equal(gmaterial_sample(m, &f.sp, out, NULL, u1, 0.5, &s, &w), 1);
        assert_true(s.flags & GSAMPLE_DELTA);
        if (s.flags & GSAMPLE_REFLECT) {
            reflected++;
            assert_true(gmaterial_is_mirror_pair(s.in, gvec3(0, 0, 1), out));
            assert_near(s.pdf, R, 1e-6);
        } else {
            assert_true(s.flags & GSAMPLE_TRANSMIT);
            assert_true(gvec3_dot(s.in, out) < -1.0 + 1e-15);
            assert_near(s.pdf, T, 1e-6);
        }
        assert_near(gcolor_brightness(&w), 1.0, 1e-6); /* value / probability: each lobe carries all */
        assert_true(gmaterial_pdf(m, &f.sp, s.in, out, NULL) == 0.0);
    }
    assert_near((double)reflected / n, R, 1.0 / n);
    gmaterial_unref(m);
    fix_close(&f);
}

static void text_format(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GLibrary *lib;
    GReaderOptions ro = {.model = f.model};
    assert_int_equal(greader_load_string("material pane thindielectric { glass BK7 }\n"
                                         "material plain thindielectric\n",
                                         "pane.mat", &ro, &lib, &err), G_OK);
    double R, T, Rb, Tb;
    split(&f, glibrary_material(lib, "pane"), 0.0, &R, &T);
    split(&f, glibrary_material(lib, "plain"), 0.0, &Rb, &Tb);
    assert_near(Rb, 2 * 0.04 / 1.04, 1e-6); /* index 1.5 when not given */
    assert_true(R > Rb);                     /* BK7's 1.52 reflects a little more */
    glibrary_destroy(lib);
    fix_close(&f);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        BOTH(lossless_and_normal_incidence),
        BOTH(delta_lobes),
        BOTH(text_format),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
