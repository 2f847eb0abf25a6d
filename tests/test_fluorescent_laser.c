/* test_fluorescent_laser.c - the laser experiment (gfluor_laser_split, gfluor_laser_pattern) on the measured
 * day-glo orange HERPIORA.BFC (skipped when the shared data is absent) and on the parametric matrix (always):
 * the varnish's unshifted share grows towards grazing incidence, fluorescent-phong's does not, energy stays
 * within what the matrix returns, the integrator reproduces the Lambertian limit exactly, and the green
 * lobe of the varnish is elongated while Phong's is round. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/bfc.h"
#include "generic/fluorescent.h"
#include "examples/gmat/laser_experiment.h"
#include "test_util.h"

/* Fixture: the bispectral model, an arena, and the matrix under test (state: "HERPIORA.BFC" or NULL for
 * the parametric one). */
typedef struct Fix {
    GColorModel *model;
    GScratch *scratch;
    GReradiation r;
    GBfcData bfc;
    int from_file;
    const char *name;
} Fix;

static int fix_setup(void **state, const char *file)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    if (gcolormodel_create("bispectral", NULL, &f->model, &err) != G_OK)
        return -1;
    f->scratch = gscratch_create(0);
    f->name = file ? file : "parametric";
    if (file) {
        char path[1024];
        const char *src = getenv("GENERIC_SOURCE_DIR");
        snprintf(path, sizeof path, "%s/../shared/data/bispectral/%s", src ? src : ".", file);
        if (access(path, R_OK) != 0)
            snprintf(path, sizeof path, "/work/shared/data/bispectral/%s", file);
        if (access(path, R_OK) == 0 && gbfc_read(path, &f->bfc, &err) == G_OK) {
            f->r = f->bfc.rerad;
            f->from_file = 1;
        }
    } else {
        GFluorBands b;
        gfluor_bands_default(&b);
        if (gfluor_matrix_create(&b, 380, 10, 41, &f->r, &err) != G_OK)
            return -1;
    }
    *state = f;
    return 0;
}
static int setup_file(void **state) { return fix_setup(state, "HERPIORA.BFC"); }
static int setup_param(void **state) { return fix_setup(state, NULL); }

static int fix_teardown(void **state)
{
    Fix *f = *state;
    if (f->from_file)
        gbfc_free(&f->bfc);
    else
        gfluor_matrix_free(&f->r);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->model);
    free(f);
    return 0;
}

static Fix *fix(void **state)
{
    Fix *f = *state;
    if (!f->r.data) {
        print_message("HERPIORA.BFC not found: skipped\n");
        skip();
    }
    return f;
}

static GMaterial *varnish(Fix *f, double ior)
{
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    p.ior = ior;
    GMaterial *m;
    GError err;
    if (gfluor_varnish_create(f->model, &f->r, &p, &m, &err) != G_OK)
        fail_msg("%s", err.message);
    return m;
}

static GMaterial *phong(Fix *f, double ks)
{
    GFluorPhongParams p;
    gfluor_phong_default(&p);
    p.ks = ks;
    GMaterial *m;
    GError err;
    if (gfluor_phong_create(f->model, &f->r, &p, &m, &err) != G_OK)
        fail_msg("%s", err.message);
    return m;
}

/* n: rings and steps of the integration (0: the default 192) */
static GFluorLaserSplit split_n(Fix *f, const GMaterial *m, double nm, double elevation, int n)
{
    GFluorLaserSplit s;
    GError err;
    GFluorLaserOptions opt = {n, n};
    if (gfluor_laser_split(m, f->scratch, nm, elevation, &opt, &s, &err) != G_OK)
        fail_msg("%s", err.message);
    return s;
}

static GFluorLaserSplit split(Fix *f, const GMaterial *m, double nm, double elevation)
{
    return split_n(f, m, nm, elevation, 0);
}

/* Entry of the matrix at emission o nm, excitation i nm (negatives clamped). */
static double entry(const GReradiation *r, double o_nm, double i_nm)
{
    int o = (int)lround((o_nm - r->out_min) / r->out_step), i = (int)lround((i_nm - r->in_min) / r->in_step);
    float v = r->data[o * r->n_in + i];
    return v > 0 ? v : 0;
}

/* The paper's observation: the varnish keeps much more of the green at grazing incidence. */
static void test_varnish_angle_dependence(void **state)
{
    Fix *f = fix(state);
    GMaterial *m = varnish(f, 1.5);
    GFluorLaserSplit s5 = split(f, m, 532, 5), s20 = split(f, m, 532, 20), s60 = split(f, m, 532, 60);
    print_message("%s varnish 532 nm: kept %.4f %.4f %.4f, shifted %.4f %.4f %.4f at 5/20/60 degrees, "
                  "shifted dominant %.0f nm (peak %.0f nm)\n", f->name, s5.kept, s20.kept, s60.kept, s5.shifted,
                  s20.shifted, s60.shifted, s60.dominant_nm, s60.peak_nm);
    assert_near(s5.wavelength, 530, 0);
    assert_true(s5.kept >= 3.0 * s60.kept);
    assert_true(s5.kept > s20.kept && s20.kept > s60.kept);
    assert_true(s60.shifted > s5.shifted); /* what the facets do not keep goes into the base */
    assert_true(s60.dominant_nm > 580 && s60.dominant_nm < 620); /* orange */
    gmaterial_unref(m);
}

/* ... and fluorescent-phong does not follow the angle (the paper's criticism). */
static void test_phong_angle_independence(void **state)
{
    Fix *f = fix(state);
    GMaterial *m = phong(f, 0.04);
    GFluorLaserSplit s20 = split(f, m, 532, 20), s60 = split(f, m, 532, 60);
    print_message("%s phong 532 nm: kept %.4f / %.4f at 20 / 60 degrees (change %.2f%%)\n", f->name, s20.kept,
                  s60.kept, 100 * fabs(s20.kept - s60.kept) / s60.kept);
    assert_true(fabs(s20.kept - s60.kept) < 0.2 * s60.kept);
    /* the lobes' own share: kept = (1 - ks) M_kk + ks d_k A with A about 1 away from the horizon */
    double mkk = entry(&f->r, 530, 530);
    for (int k = 0; k < 2; k++) {
        double kept = k ? s60.kept : s20.kept, a = (kept - 0.96 * mkk) / (0.04 * mkk);
        assert_true(a > 0.9 && a <= 1.0 + 1e-3);
    }
    gmaterial_unref(m);
}

/* With ior 1 the varnish is a Lambertian with M: the split is M's column at the beam's sample. */
static void test_lambert_limit(void **state)
{
    Fix *f = fix(state);
    GMaterial *m = varnish(f, 1.0);
    const double nms[] = {450, 532, 589};
    for (int k = 0; k < 3; k++) {
        double lam = 10 * lround(nms[k] / 10), col = 0;
        for (int o = 0; o < f->r.n_out; o++)
            col += o == lround((lam - f->r.out_min) / f->r.out_step) ? 0 : entry(&f->r, f->r.out_min + 10 * o, lam);
        for (double el = 10; el <= 90; el += 40) {
            GFluorLaserSplit s = split_n(f, m, nms[k], el, 96);
            assert_near(s.kept, entry(&f->r, lam, lam), 2e-3 * (1 + entry(&f->r, lam, lam)));
            assert_near(s.shifted, col, 2e-3 * (1 + col));
        }
    }
    gmaterial_unref(m);
}

/* Energy out <= energy in, or what the matrix itself returns when measured data exceeds it. */
static void test_energy(void **state)
{
    Fix *f = fix(state);
    GMaterial *mats[2] = {varnish(f, 1.5), phong(f, 0.04)};
    double cmax = gfluor_matrix_max_column_sum(&f->r, 380, 780);
    const double nms[] = {450, 532, 633};
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 3; k++)
            for (double el = 5; el <= 90; el += 42.5) {
                GFluorLaserSplit s = split_n(f, mats[j], nms[k], el, 96);
                assert_true(s.kept >= 0 && s.shifted >= 0);
                assert_true(s.kept + s.shifted <= fmax(1.0, cmax) + 2e-3);
            }
    gmaterial_unref(mats[0]);
    gmaterial_unref(mats[1]);
}

/* The varnish's green lobe is long along the plane of incidence; Phong's is round. The pattern is
 * two-coloured: green at the lobe, orange elsewhere. */
static void test_pattern(void **state)
{
    Fix *f = fix(state);
    GMaterial *v = varnish(f, 1.5), *p = phong(f, 0.04);
    GError err;
    GFluorPattern pat;
    const double els[] = {5, 20, 60};
    for (int k = 0; k < 3; k++) {
        assert_int_equal(gfluor_laser_pattern(v, f->scratch, 532, els[k], 128, 128, 1.5, &pat, &err), G_OK);
        print_message("%s varnish %2.0f degrees: green lobe %.3f wide, %.3f long: aspect %.2f\n", f->name, els[k],
                      pat.kept_fwhm_h, pat.kept_fwhm_v, pat.aspect);
        if (els[k] <= 20)
            assert_true(pat.aspect > 1.4);
        if (k == 0) {
            /* the lobe's brightest point is green, a point away from it orange */
            long best = 0;
            for (long i = 1; i < 128L * 128; i++)
                if (pat.kept[i] > pat.kept[best])
                    best = i;
            const float *g = pat.rgb + best * 3, *o = pat.rgb + (14L * 128 + 14) * 3;
            assert_true(g[1] > g[0] && g[1] > g[2]);
            assert_true(o[0] > o[1] && o[1] > o[2]);
        }
        gfluor_pattern_free(&pat);
        assert_int_equal(gfluor_laser_pattern(p, f->scratch, 532, els[k], 128, 128, 1.5, &pat, &err), G_OK);
        print_message("%s phong   %2.0f degrees: green lobe %.3f wide, %.3f long: aspect %.2f\n", f->name, els[k],
                      pat.kept_fwhm_h, pat.kept_fwhm_v, pat.aspect);
        if (els[k] >= 20)
            assert_true(pat.aspect > 0.85 && pat.aspect < 1.15);
        gfluor_pattern_free(&pat);
        gfluor_pattern_free(&pat); /* freed: a no-op */
    }
    gmaterial_unref(v);
    gmaterial_unref(p);
}

static void test_other_models(void **state)
{
    Fix *f = fix(state);
    /* rgb: nothing can shift; kept is the whole reflected share of a white beam */
    GColorModel *rgb;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &rgb, &err), G_OK);
    GMaterial *m;
    assert_int_equal(gfluor_varnish_create(rgb, &f->r, NULL, &m, &err), G_OK);
    GFluorLaserSplit s;
    assert_int_equal(gfluor_laser_split(m, f->scratch, 532, 30, NULL, &s, &err), G_OK);
    assert_true(s.shifted == 0 && s.wavelength == 0);
    assert_true(s.kept > 0.1 && s.kept < 1.0);
    gmaterial_unref(m);
    gcolormodel_destroy(rgb);
}

static void test_errors(void **state)
{
    Fix *f = fix(state);
    GMaterial *m = varnish(f, 1.5);
    GFluorLaserSplit s;
    GFluorPattern p;
    GError err;
    assert_int_equal(gfluor_laser_split(m, f->scratch, 532, 0, NULL, &s, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "elevation"));
    assert_int_equal(gfluor_laser_split(m, f->scratch, 532, 95, NULL, &s, &err), G_ERR_INVALID);
    assert_int_equal(gfluor_laser_split(m, f->scratch, 900, 30, NULL, &s, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "range"));
    assert_int_equal(gfluor_laser_pattern(m, f->scratch, 532, 30, 4, 4, 1, &p, &err), G_ERR_INVALID);
    assert_null(p.rgb);
    gmaterial_unref(m);
}

static void test_dominant_wavelength(void **state)
{
    (void)state;
    for (int nm = 450; nm <= 650; nm += 50) {
        double c[3];
        gcie_cmf(nm, c);
        double s = c[0] + c[1] + c[2];
        assert_near(gfluor_dominant_wavelength(c[0] / s, c[1] / s), nm, 1.0);
        /* mixed with white it keeps its dominant wavelength */
        double x = 0.5 * c[0] / s + 0.5 / 3, y = 0.5 * c[1] / s + 0.5 / 3;
        assert_near(gfluor_dominant_wavelength(x, y), nm, 1.0);
    }
    assert_true(gfluor_dominant_wavelength(1.0 / 3, 1.0 / 3) == 0.0);
    double a[3], b[3];
    gcie_cmf(420, a);
    gcie_cmf(680, b);
    double X = a[0] / (a[0] + a[1] + a[2]) + b[0] / (b[0] + b[1] + b[2]);
    double Y = a[1] / (a[0] + a[1] + a[2]) + b[1] / (b[0] + b[1] + b[2]);
    double d = gfluor_dominant_wavelength(X / 2, Y / 2); /* a purple: complementary green */
    assert_true(d < -490 && d > -580);
}

/* Unpolarised Fresnel reflectance of a dielectric of index n at incidence cos_i (from air). */
static double fresnel(double n, double cos_i)
{
    double sin_t = sqrt(1.0 - cos_i * cos_i) / n, cos_t = sqrt(1.0 - sin_t * sin_t);
    double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t), rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

/* Over a black base the varnish keeps only its facets' reflection; with the smallest slope it accepts (0.01
 * degrees) that is a mirror's Fresnel reflectance. The default integration doubles its rings until it
 * converges to 1e-4 (a fixed 192 rings under-resolves the lobe by 3%), agrees with many more rings, and
 * stops early on a rough material. */
static void test_smooth_varnish_converges(void **state)
{
    Fix *f = *state;
    static const float zero[41 * 41];
    GReradiation black = {380, 10, 41, 380, 10, 41, zero};
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    p.slope_deg = 0.01;
    GMaterial *m;
    GError err;
    assert_int_equal(gfluor_varnish_create(f->model, &black, &p, &m, &err), G_OK);
    const double el[2] = {5.0, 30.0};
    for (int k = 0; k < (TU_SANITIZED ? 1 : 2); k++) { /* the sanitizers look at the code paths: 5 degrees */
        double F = fresnel(1.5, sin(el[k] * M_PI / 180.0));
        GFluorLaserSplit fixed = split_n(f, m, 532, el[k], 192), adaptive = split(f, m, 532, el[k]);
        /* the 4096-ring reference costs 4096^2 evaluations: the plain build's (the sanitizers keep Fresnel's) */
        GFluorLaserSplit fine = TU_SANITIZED ? adaptive : split_n(f, m, 532, el[k], 4096);
        print_message("slope 0.01, %2.0f degrees: kept %.6f with 192 rings, %.6f with %d (adaptive), %.6f with "
                      "4096; Fresnel %.6f\n", el[k], fixed.kept, adaptive.kept, adaptive.rings, fine.kept, F);
        assert_true(adaptive.rings > 192);
        assert_near(adaptive.kept, fine.kept, 1e-4);
        assert_near(adaptive.kept, F, 2e-4);
        assert_true(adaptive.shifted == 0.0);
    }
    assert_true(fabs(split_n(f, m, 532, 5.0, 192).kept - fresnel(1.5, sin(5.0 * M_PI / 180.0))) > 0.01);
    gmaterial_unref(m);
    /* the rough default varnish converges at the first doubling */
    GMaterial *rough = varnish(f, 1.5);
    GFluorLaserSplit s = split(f, rough, 532, 20), fine = split_n(f, rough, 532, 20, TU_SANITIZED ? 768 : 3072);
    assert_int_equal(s.rings, 384);
    assert_near(s.kept, fine.kept, 1e-4);
    assert_near(s.shifted, fine.shifted, 1e-4);
    gmaterial_unref(rough);
}

#define BOTH(t) cmocka_unit_test_setup_teardown(t, setup_file, fix_teardown), \
                cmocka_unit_test_setup_teardown(t, setup_param, fix_teardown)

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        BOTH(test_varnish_angle_dependence),
        BOTH(test_phong_angle_independence),
        BOTH(test_lambert_limit),
        BOTH(test_energy),
        BOTH(test_pattern),
        cmocka_unit_test_setup_teardown(test_other_models, setup_param, fix_teardown),
        cmocka_unit_test_setup_teardown(test_errors, setup_param, fix_teardown),
        cmocka_unit_test_setup_teardown(test_smooth_varnish_converges, setup_param, fix_teardown),
        cmocka_unit_test(test_dominant_wavelength),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
