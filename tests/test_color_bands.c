/* test_color_bands.c - the colour interface's wavelength bands (color.h: band_count, band_mask, band_value):
 * every built-in model's bands partition its samples (the masks are disjoint unit masks summing to white),
 * the value of a dielectric's index in a band is the dispersion formula at the band's wavelength, and a model
 * that gives no band slots has one band that is everything. A class is asked its band count once, when its model is
 * created, and the kit's band value is the sample itself. gcolor_band_peak gives what a loop over gcolor_band_value
 * gives. */
#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/kit/spectral.h"
#include "generic/materials.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <cmocka.h>

static GColorModel *model(const char *name)
{
    GColorModel *m = NULL;
    GError err;
    if (gcolormodel_create(name, NULL, &m, &err) != G_OK)
        fail_msg("%s: %s", name, err.message);
    return m;
}

static void check_partition(const char *name, int want)
{
    GColorModel *m = model(name);
    int n = gcolormodel_band_count(m);
    assert_int_equal(n, want);
    GColor mask, sum, white;
    assert_int_equal(gcolor_alloc(&mask, m), G_OK);
    assert_int_equal(gcolor_alloc(&sum, m), G_OK);
    assert_int_equal(gcolor_alloc(&white, m), G_OK);
    assert_int_equal(gcolor_fill(&white, 1.0), G_OK);
    for (int k = 0; k < n; k++) {
        assert_int_equal(gcolor_band_mask(&mask, k), G_OK);
        /* the mask is 1 in its own band and 0 in every other */
        for (int j = 0; j < n; j++)
            assert_true(fabs(gcolor_band_value(&mask, j) - (j == k)) < 1e-6);
        assert_int_equal(gcolor_add(&sum, &sum, &mask), G_OK);
    }
    for (int j = 0; j < n; j++)
        assert_true(fabs(gcolor_band_value(&sum, j) - 1.0) < 1e-6);
    assert_true(fabs(gcolor_brightness(&sum) - gcolor_brightness(&white)) < 1e-5);
    /* out of range */
    assert_int_equal(gcolor_band_mask(&mask, n), G_ERR_INVALID);
    assert_int_equal(gcolor_band_mask(&mask, -1), G_ERR_INVALID);
    assert_true(isnan(gcolor_band_value(&mask, n)));
    gcolor_free(&mask);
    gcolor_free(&sum);
    gcolor_free(&white);
    gcolormodel_destroy(m);
}

static void test_builtin_partitions(void **state)
{
    (void)state;
    check_partition("rgb", 3);
    check_partition("spectrum9", 9);
    check_partition("spectrum", 81);
    check_partition("bispectral", 41);
}

/* The index of a Sellmeier glass in band k of a sampled model is n at the band's wavelength (the model's
 * sample: its hat-weighted average over one step, within 5e-4 for BK7, the one-sided hat of the end samples
 * being the largest part); in rgb, n at 610, 550
 * and 465 nm. */
static void test_index_per_band(void **state)
{
    (void)state;
    const double b[3] = {1.03961212, 0.231792344, 1.01046945}, c[3] = {0.00600069867, 0.0200179144, 103.560653};
    GDispersion d = gdispersion_sellmeier(b, c);
    const char *names[] = {"spectrum", "spectrum9", "bispectral", "rgb"};
    for (int i = 0; i < 4; i++) {
        GColorModel *m = model(names[i]);
        GDielectricParams p = {d, NULL, NULL};
        GMaterial *glass = NULL;
        GError err;
        assert_int_equal(gdielectric_create(m, &p, &glass, &err), G_OK);
        GColor n;
        assert_int_equal(gcolor_alloc(&n, m), G_OK);
        assert_int_equal(gmaterial_refraction_index(glass, NULL, &n), G_OK);
        const double rgb_nm[3] = {610.0, 550.0, 465.0};
        double worst = 0.0;
        for (int k = 0; k < gcolormodel_band_count(m); k++) {
            double nm = m->nsamples > 0 ? m->lambda_min + k * m->lambda_step : rgb_nm[k];
            worst = fmax(worst, fabs(gcolor_band_value(&n, k) - gdispersion_index(&d, nm)));
        }
        print_message("%s: band indices within %.2g of Sellmeier\n", names[i], worst);
        /* spectrum9's 50 nm hat averages the curve at the ends (the index rises steeply below 400 nm) */
        assert_true(worst < (m->lambda_step > 20.0 ? 5e-3 : 5e-4));
        gcolor_free(&n);
        gmaterial_unref(glass);
        gcolormodel_destroy(m);
    }
}

/* A model class without band slots: one band, its mask white, its value the brightness. */
static void test_defaults(void **state)
{
    (void)state;
    GColorModel *rgb = model("rgb");
    GColorModelClass plain = *rgb->cls;
    plain.band_count = NULL;
    plain.band_mask = NULL;
    plain.band_value = NULL;
    GColorModel *m = NULL;
    GError err;
    assert_int_equal(gcolormodel_create_class(&plain, NULL, &m, &err), G_OK);
    assert_int_equal(gcolormodel_band_count(m), 1);
    GColor mask, c;
    assert_int_equal(gcolor_alloc(&mask, m), G_OK);
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gcolor_band_mask(&mask, 0), G_OK);
    assert_true(fabs(gcolor_brightness(&mask) - 1.0) < 1e-6);
    double v[3] = {0.2, 0.5, 0.9};
    assert_int_equal(gcolor_from_rgb(&c, v, GCOLOR_REFLECTANCE), G_OK);
    assert_true(fabs(gcolor_band_value(&c, 0) - gcolor_brightness(&c)) < 1e-9);
    assert_int_equal(gcolor_band_mask(&mask, 1), G_ERR_INVALID);
    /* a model with masks but no band_value: the luminance-weighted mean over the mask */
    plain.band_count = rgb->cls->band_count;
    plain.band_mask = rgb->cls->band_mask;
    GColorModel *m2 = NULL;
    assert_int_equal(gcolormodel_create_class(&plain, NULL, &m2, &err), G_OK);
    GColor c2;
    assert_int_equal(gcolor_alloc(&c2, m2), G_OK);
    assert_int_equal(gcolor_from_rgb(&c2, v, GCOLOR_REFLECTANCE), G_OK);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(gcolor_band_value(&c2, k) - v[k]) < 1e-6);
    gcolor_free(&c2);
    gcolormodel_destroy(m2);
    gcolor_free(&mask);
    gcolor_free(&c);
    gcolormodel_destroy(m);
    gcolormodel_destroy(rgb);
}

static int band_count_calls;

static int counting_band_count(const GColorModel *m)
{
    band_count_calls++;
    return gspectral_band_count(m);
}

/* The library asks a class for its band count once, when the model is created; the kit's band_value (every sample a
 * band) reads the sample itself: exactly the sample, and NaN outside the bands or for a matrix. */
static void test_band_count_asked_once(void **state)
{
    (void)state;
    GColorModel *spectrum = model("spectrum");
    GColorModelClass counted = *spectrum->cls;
    counted.band_count = counting_band_count;
    GColorModel *m = NULL;
    GError err;
    band_count_calls = 0;
    assert_int_equal(gcolormodel_create_class(&counted, NULL, &m, &err), G_OK);
    assert_int_equal(band_count_calls, 1);
    GColor c;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    const int n = gcolormodel_band_count(m);
    assert_int_equal(n, m->nvalues);
    for (int k = 0; k < n; k++)
        c.v[k] = 0.3f + 0.001f * (float)k;
    for (int k = 0; k < n; k++)
        assert_true(gcolor_band_value(&c, k) == (double)c.v[k]);
    assert_true(isnan(gcolor_band_value(&c, -1)) && isnan(gcolor_band_value(&c, n)));
    assert_int_equal(band_count_calls, 1);
    gcolor_free(&c);
    gcolormodel_destroy(m);
    gcolormodel_destroy(spectrum);
    GColorModel *bi = model("bispectral");
    GColor a;
    assert_int_equal(gcolor_alloc(&a, bi), G_OK);
    assert_int_equal(gcolor_fill(&a, 0.5), G_OK);
    assert_true(gcolor_band_value(&a, 3) == 0.5);
    a.kind = GCOLOR_MATRIX;
    assert_true(isnan(gcolor_band_value(&a, 3)));
    gcolor_free(&a);
    gcolormodel_destroy(bi);
}

/* gcolor_band_peak's definition: the largest of 0 and the bands read one gcolor_band_value at a time, NAN at the
 * first NAN read. */
static double peak_by_loop(const GColor *c, int first, int step)
{
    double peak = 0.0;
    for (int i = first; i < gcolormodel_band_count(c->model); i += step) {
        double v = gcolor_band_value(c, i);
        if (isnan(v))
            return NAN;
        peak = fmax(peak, v);
    }
    return peak;
}

/* A step of a 64-bit linear congruential generator: a number in [0, 1). */
static double next_uniform(unsigned long long *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 9007199254740992.0;
}

/* Generated vectors of every built-in model (values in [-1, 2), some all negative, some with a NaN sample) and of a
 * model whose bands are read through its masks: gcolor_band_peak equals the loop over every first band and step. */
static void test_band_peak(void **state)
{
    (void)state;
    const char *names[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    unsigned long long rng = 12345;
    for (int mi = 0; mi < 5; mi++) {
        GColorModel *base = model(mi < 4 ? names[mi] : "rgb"), *m = base;
        GColorModelClass masks_only = *base->cls;
        masks_only.band_value = NULL; /* bands read through the masks (gcolor_band_value's general path) */
        GError err;
        if (mi == 4)
            assert_int_equal(gcolormodel_create_class(&masks_only, NULL, &m, &err), G_OK);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        int n = gcolormodel_band_count(m), compared = 0;
        for (int trial = 0; trial < 40; trial++) {
            double lo = trial % 5 == 1 ? -1.0 : -0.2; /* every fifth one all negative: a peak of 0 */
            for (int k = 0; k < m->nvalues; k++)
                c.v[k] = (float)(lo + (trial % 5 == 1 ? 0.9 : 2.2) * next_uniform(&rng));
            if (trial % 7 == 3) /* a NaN sample somewhere */
                c.v[(int)(next_uniform(&rng) * m->nvalues)] = NAN;
            for (int first = 0; first <= n; first++)
                for (int step = 1; step <= n + 1; step++) {
                    double want = peak_by_loop(&c, first, step), got = gcolor_band_peak(&c, first, step);
                    if (isnan(want))
                        assert_true(isnan(got));
                    else
                        assert_true(got == want);
                    compared += !isnan(want) && want > 0.0;
                }
        }
        assert_true(compared > 0);
        assert_true(gcolor_band_peak(&c, n, 1) == 0.0); /* no band read */
        assert_true(isnan(gcolor_band_peak(&c, -1, 1)) && isnan(gcolor_band_peak(&c, 0, 0)));
        assert_true(gcolor_band_peak(&c, 0, 2147483647) == peak_by_loop(&c, 0, n + 1)); /* one band: no overflow */
        c.kind = GCOLOR_MATRIX;
        assert_true(isnan(gcolor_band_peak(&c, 0, 1)));
        gcolor_free(&c);
        if (m != base)
            gcolormodel_destroy(m);
        gcolormodel_destroy(base);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_builtin_partitions),
        cmocka_unit_test(test_index_per_band),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_band_count_asked_once),
        cmocka_unit_test(test_band_peak),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
