/* test_thinfilm.c - the thin film: the kit's Airy sum against the textbook closed form of a non-absorbing film
 * (air / n 1.33 / air, thickness 0 to 1000 nm, angles 0 to 80 degrees, every nm from 380 to 780) within 1e-9, its
 * R + T = 1 within 1e-9; the thinfilm material in `spectrum` at 1 nm giving that R along its mirror ray and T along
 * its refracted ray at every sample (float colours: within 2e-6); the film's colour in rgb against spectrum over
 * the sweep, mean CIEDE2000 difference at most 1; an absorbing film's R + T below 1; its parameters' bounds. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "colour_difference.h"
#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/kit/thinfilm.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"
#include "test_util.h"

#define DEG (M_PI / 180.0)

/* The closed form of a film between two equal non-absorbing media at wavelength nm (Born and Wolf 1.6 (58)): per
 * polarisation R = (r01^2 + r12^2 + 2 r01 r12 cos phi) / (1 + r01^2 r12^2 + 2 r01 r12 cos phi), phi = 4 pi n d
 * cos(theta_1) / lambda, r12 = -r01 for a film in one medium; the mean of s and p. */
static double airy_closed(double n, double d, double theta, double nm)
{
    double s = sin(theta), c0 = cos(theta), c1 = sqrt(1.0 - s * s / (n * n));
    double rs = (c0 - n * c1) / (c0 + n * c1), rp = (n * c0 - c1) / (n * c0 + c1);
    double phi = 4.0 * M_PI * n * d * c1 / nm, sum = 0.0;
    double r01[2] = {rs, rp};
    for (int p = 0; p < 2; p++) {
        double a = r01[p], b = -r01[p];
        sum += (a * a + b * b + 2.0 * a * b * cos(phi)) / (1.0 + a * a * b * b + 2.0 * a * b * cos(phi));
    }
    return 0.5 * sum;
}

static void test_airy_closed_form(void **state)
{
    (void)state;
    double worst_r = 0.0, worst_sum = 0.0;
    for (double d = 0.0; d <= 1000.0; d += 25.0)
        for (int a = 0; a <= 80; a += 5)
            for (int nm = 380; nm <= 780; nm++) {
                GThinFilm f = {d, 1.33, 0.0, 1.0, 1.0};
                double r, t;
                gthinfilm_airy(&f, nm, cos(a * DEG), &r, &t);
                worst_r = fmax(worst_r, fabs(r - airy_closed(1.33, d, a * DEG, nm)));
                worst_sum = fmax(worst_sum, fabs(r + t - 1.0));
            }
    print_message("air / 1.33 / air, 0-1000 nm, 0-80 deg, 380-780 nm: |R - closed form| <= %.3g, |R + T - 1| <= %.3g\n",
                  worst_r, worst_sum);
    assert_true(worst_r <= 1e-9);
    assert_true(worst_sum <= 1e-9);
    /* a film of thickness 0 is the bare interface of air and air: nothing reflected */
    GThinFilm none = {0.0, 1.33, 0.0, 1.0, 1.0};
    double r, t;
    gthinfilm_airy(&none, 550.0, 1.0, &r, &t);
    assert_true(fabs(r) < 1e-15 && fabs(t - 1.0) < 1e-15);
    /* a quarter-wave coating of index sqrt(1.5) on glass 1.5 cancels the reflection at its wavelength */
    GThinFilm ar = {550.0 / (4.0 * sqrt(1.5)), sqrt(1.5), 0.0, 1.0, 1.5};
    gthinfilm_airy(&ar, 550.0, 1.0, &r, &t);
    assert_true(r < 1e-15);
    assert_true(fabs(t - 1.0) < 1e-12);
    /* an absorbing film passes on less than arrives; total internal reflection at the substrate passes nothing */
    GThinFilm metal = {30.0, 0.2, 3.0, 1.0, 1.5};
    gthinfilm_airy(&metal, 550.0, 0.8, &r, &t);
    assert_true(r > 0.0 && t > 0.0 && r + t < 0.99);
    GThinFilm tir = {200.0, 1.4, 0.0, 1.5, 1.0};
    gthinfilm_airy(&tir, 550.0, cos(60.0 * DEG), &r, &t);
    assert_true(t == 0.0 && fabs(r - 1.0) < 1e-9);
}

typedef struct Film {
    GLibrary *lib;
    const GColorModel *model;
    GScratch *scratch;
    GSurfPoint sp;
} Film;

/* A library of films of thickness 0, 50, ..., 1000 nm named t0, t50, ... in the model given (spectrum at 1 nm), with
 * the Airy sum's mode airy (exact or table). */
static void film_open_airy(Film *f, const char *model, double step, const char *airy)
{
    char text[4096];
    int len = 0;
    for (int d = 0; d <= 1000; d += 50)
        len += snprintf(text + len, sizeof text - len, "material t%d thinfilm { thickness %d index 1.33 airy %s }\n", d,
                        d, airy);
    GColorModelOptions mo = {.step_nm = step, .min_nm = 380, .max_nm = 780};
    GReaderOptions opt = {.colormodel = model, .colormodel_options = step > 0.0 ? &mo : NULL};
    GError err;
    if (greader_load_string(text, "films", &opt, &f->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    f->model = glibrary_colormodel(f->lib);
    f->scratch = gscratch_create(0);
    gsurfpoint_init(&f->sp, f->model, f->scratch);
    f->sp.geometric_normal = gvec3(0, 0, 1);
}

static void film_open(Film *f, const char *model, double step) { film_open_airy(f, model, step, "exact"); }

static void film_close(Film *f)
{
    gscratch_destroy(f->scratch);
    glibrary_destroy(f->lib);
}

/* The film of thickness d's reflection along the mirror ray and refraction along the straight ray (index 1) for
 * white light from theta, into r and t. */
static void film_rt(Film *f, int d, double theta, GColor *r, GColor *t)
{
    char name[16];
    snprintf(name, sizeof name, "t%d", d);
    GMaterial *m = glibrary_material(f->lib, name);
    assert_non_null(m);
    GColor one, ri;
    assert_int_equal(gcolor_scratch(&one, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&ri, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    assert_int_equal(gcolor_fill(&ri, 1.0), G_OK);
    f->sp.material = m, f->sp.from = NULL, f->sp.to = m;
    gsurfpoint_invalidate(&f->sp);
    GVec3 in = gvec3(sin(theta), 0, cos(theta)), out = gvec3(-sin(theta), 0, cos(theta)), dir;
    assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, out, r), G_OK);
    assert_int_equal(gmaterial_refraction_dir(m, &f->sp, gvec3_neg(out), &ri, &dir), 1);
    assert_true(gvec3_length(gvec3_sub(dir, gvec3_neg(out))) < 1e-5); /* index 1 on both sides: straight on */
    assert_int_equal(gmaterial_refraction(m, &f->sp, dir, &one, &ri, out, t), G_OK);
}

/* The films in spectrum at 1 nm against the closed form, their colours exact or tabulated (within bound). */
static void material_spectrum(const char *airy, double bound)
{
    Film f;
    film_open_airy(&f, "spectrum", 1.0, airy);
    double nm[401];
    assert_int_equal(gcolormodel_wavelengths(f.model, nm, 401), 401);
    double worst_r = 0.0, worst_sum = 0.0;
    for (int d = 0; d <= 1000; d += 50)
        for (int a = 0; a <= 80; a += 10) {
            GScratchMark mark = gscratch_mark(f.scratch);
            GColor r, t;
            assert_int_equal(gcolor_scratch(&r, f.model, f.scratch), G_OK);
            assert_int_equal(gcolor_scratch(&t, f.model, f.scratch), G_OK);
            film_rt(&f, d, a * DEG, &r, &t);
            for (int i = 0; i < 401; i++) {
                worst_r = fmax(worst_r, fabs(r.v[i] - airy_closed(1.33, d, a * DEG, nm[i])));
                worst_sum = fmax(worst_sum, fabs(r.v[i] + t.v[i] - 1.0));
            }
            gscratch_release(f.scratch, mark);
        }
    print_message("thinfilm (airy %s) in spectrum at 1 nm: |R - closed form| <= %.3g, |R + T - 1| <= %.3g (float "
                  "colours)\n", airy, worst_r, worst_sum);
    assert_true(worst_r <= bound);
    assert_true(worst_sum <= bound);
    film_close(&f);
}

static void test_material_spectrum(void **state)
{
    (void)state;
    material_spectrum("exact", 2e-6);
    material_spectrum("table", 2e-6); /* kit/thinfilm.h's bound for its tables */
}

/* The kit's table (gthinfilm_table_color) against the exact colours (gthinfilm_color) in spectrum over a fine grid
 * of cosines, denser towards grazing, for films in air and on glass, with and without extinction: within 2e-6 of R
 * and of T everywhere (exact below GTHINFILM_TABLE_COS_MIN); a film of index below the ambient's gets no table. */
static void test_table_grid(void **state)
{
    (void)state;
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create("spectrum", NULL, &m, &err), G_OK);
    const GThinFilm films[] = {{480, 1.33, 0, 1, 1}, {300, 1.9, 0, 1, 1.5}, {1000, 1.33, 0, 1, 1},
                               {180, 2.6, 0.2, 1, 1}};
    GColor r, t, re, te;
    assert_int_equal(gcolor_alloc(&r, m), G_OK);
    assert_int_equal(gcolor_alloc(&t, m), G_OK);
    assert_int_equal(gcolor_alloc(&re, m), G_OK);
    assert_int_equal(gcolor_alloc(&te, m), G_OK);
    const int steps = TU_SANITIZED ? 200 : 2000;
    for (int f = 0; f < 4; f++) {
        GThinFilmTable *tab;
        assert_int_equal(gthinfilm_table_create(&films[f], m, &tab), G_OK);
        assert_true(gthinfilm_table_matches(tab, &films[f]));
        double worst = 0.0;
        for (int i = 0; i <= steps; i++) {
            double u = (double)i / steps, c = u * u;
            assert_int_equal(gthinfilm_table_color(tab, c, &r, &t), G_OK);
            assert_int_equal(gthinfilm_color(&films[f], c, &re, &te), G_OK);
            for (int k = 0; k < m->nvalues; k++)
                worst = fmax(worst, fmax(fabs(r.v[k] - re.v[k]), fabs(t.v[k] - te.v[k])));
        }
        print_message("thinfilm table, %g nm index %g + %gi on %g: |table - exact| <= %.3g\n", films[f].thickness,
                      films[f].n, films[f].k, films[f].substrate, worst);
        assert_true(worst <= 2e-6);
        gthinfilm_table_destroy(tab);
    }
    GThinFilm low = {300, 0.8, 0, 1, 1.5};
    GThinFilmTable *none = NULL;
    assert_int_equal(gthinfilm_table_create(&low, m, &none), G_ERR_UNSUPPORTED);
    assert_null(none);
    GColor *all[] = {&r, &t, &re, &te};
    for (int i = 0; i < 4; i++)
        gcolor_free(all[i]);
    gcolormodel_destroy(m);
}

/* ---- CIEDE2000 (Sharma, Wu and Dalal 2005): tests/colour_difference.h ---- */

static void xyz_to_lab(const double xyz[3], const double white[3], double lab[3])
{
    cd_xyz_to_lab_white(xyz, white, lab);
}

static double ciede2000(const double l1[3], const double l2[3]) { return cd_delta_e2000(l1, l2); }

static void test_ciede2000_reference(void **state)
{
    (void)state;
    /* pairs 1, 7 and 17 of Sharma, Wu and Dalal's table 1 */
    const double pairs[3][7] = {{50.0, 2.6772, -79.7751, 50.0, 0.0, -82.7485, 2.0425},
                                {50.0, 0.0, 0.0, 50.0, -1.0, 2.0, 2.3669},
                                {50.0, 2.5, 0.0, 73.0, 25.0, -18.0, 27.1492}};
    for (int i = 0; i < 3; i++)
        assert_true(fabs(ciede2000(pairs[i], pairs[i] + 3) - pairs[i][6]) < 1e-4);
}

/* The film's reflected colour under white light in model as CIELAB (D65 white of the model). */
static void film_lab(Film *f, int d, double theta, double lab[3])
{
    GScratchMark mark = gscratch_mark(f->scratch);
    GColor r, t, w;
    assert_int_equal(gcolor_scratch(&r, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&t, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&w, f->model, f->scratch), G_OK);
    assert_int_equal(gcolor_fill(&w, 1.0), G_OK);
    film_rt(f, d, theta, &r, &t);
    double xyz[3], white[3];
    assert_int_equal(gcolor_to_xyz(&r, GCOLOR_REFLECTANCE, xyz), G_OK);
    assert_int_equal(gcolor_to_xyz(&w, GCOLOR_REFLECTANCE, white), G_OK);
    xyz_to_lab(xyz, white, lab);
    gscratch_release(f->scratch, mark);
}

static void test_rgb_against_spectrum(void **state)
{
    (void)state;
    Film rgb, spec;
    film_open(&rgb, "rgb", 0.0);
    film_open(&spec, "spectrum", 1.0);
    double sum = 0.0, worst = 0.0;
    int n = 0;
    for (int d = 0; d <= 1000; d += 50)
        for (int a = 0; a <= 80; a += 10) {
            double l1[3], l2[3];
            film_lab(&spec, d, a * DEG, l1);
            film_lab(&rgb, d, a * DEG, l2);
            double de = ciede2000(l1, l2);
            sum += de, worst = fmax(worst, de), n++;
        }
    print_message("thinfilm rgb against spectrum (1 nm), %d films and angles: mean dE2000 %.4f, worst %.4f\n", n,
                  sum / n, worst);
    assert_true(sum / n <= 1.0);
    film_close(&rgb);
    film_close(&spec);
}

/* Out-of-range parameters are refused at their place, naming the bound. */
static void test_bounds(void **state)
{
    (void)state;
    const char *bad[][2] = {
        {"material m thinfilm { thickness -1 }", "[0, 5000]"},
        {"material m thinfilm { thickness 6000 }", "[0, 5000]"},
        {"material m thinfilm { index 0 }", "[0.01, 10]"},
        {"material m thinfilm { extinction -0.5 }", "[0, 10]"},
        {"material m thinfilm { thickness nan }", "bad:1:"},
        {"material m thinfilm { base thinfilm { base thinfilm { base nothing } } }", "bad:1:"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GLibrary *lib = NULL;
        GError err;
        assert_int_not_equal(greader_load_string(bad[i][0], "bad", NULL, &lib, &err), G_OK);
        assert_null(lib);
        print_message("%s -> %s\n", bad[i][0], err.message);
        if (!strstr(err.message, bad[i][1]))
            fail_msg("'%s': message '%s' does not say %s", bad[i][0], err.message, bad[i][1]);
        assert_true(strncmp(err.message, "bad:1:", 6) == 0);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_airy_closed_form),
        cmocka_unit_test(test_table_grid),
        cmocka_unit_test(test_material_spectrum),
        cmocka_unit_test(test_ciede2000_reference),
        cmocka_unit_test(test_rgb_against_spectrum),
        cmocka_unit_test(test_bounds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
