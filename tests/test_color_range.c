/* test_color_range.c - the range of colours after conversion: every model's own conversion error
 * (gcolormodel_rgb_range) measured and checked against the RGB cube, the whole 11x11x11 grid of in-gamut
 * reflectances accepted by lambert in every model with its albedo inside [0, 1] and its colour kept within the
 * model's error, out-of-range, out-of-gamut and non-finite values refused with a message that says what was
 * checked, and out-of-gamut lights mapped (gcolor_clip_to_gamut). */
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
#include "generic/kit/material_params.h"
#include "generic/materials.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"

static const char *const models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
enum { NMODELS = 4, GRID = 11 };

/* The measured conversion error of each model (reflectance), rounded outwards: docs/reference/colour.md ("Range
 * after conversion") states these. */
static const double expect_lo[NMODELS] = {0.0, -0.13, -0.0001, -0.0031};
static const double expect_hi[NMODELS] = {1.0, 1.13, 1.0002, 1.0031};

/* The models with the basis uplift, whose exact correction gives the conversion error this file measures (the
 * sigmoid uplift, the default, keeps reflectances of the cube within [0, 1]: tests/test_uplift.c). */
static GColorModel *make(const char *name)
{
    GColorModel *m = NULL;
    GError err;
    GColorModelOptions basis = {.uplift = GCOLOR_UPLIFT_BASIS};
    assert_int_equal(gcolormodel_create(name, &basis, &m, &err), G_OK);
    return m;
}

/* The range is exact: every sample of the 11^3 grid lies inside it and the grid's corners reach both ends. */
static void test_range_is_the_cube_extremes(void **state)
{
    (void)state;
    for (int mi = 0; mi < NMODELS; mi++) {
        GColorModel *m = make(models[mi]);
        double lo, hi;
        assert_int_equal(gcolormodel_rgb_range(m, GCOLOR_REFLECTANCE, &lo, &hi), G_OK);
        printf("%-10s reflectance range %.5f .. %.5f\n", models[mi], lo, hi);
        assert_true(lo >= expect_lo[mi] && lo <= 0.0);
        assert_true(hi <= expect_hi[mi] && hi >= 1.0 - 1e-6);
        if (mi == 0) {
            assert_true(lo == 0.0);
            assert_true(fabs(hi - 1.0) < 1e-7);
        } else {
            assert_true(lo < -1e-5); /* the spectral models do dip below 0: the reason for the rule */
        }
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        double gmin = INFINITY, gmax = -INFINITY;
        for (int i = 0; i < GRID * GRID * GRID; i++) {
            double rgb[3] = {(i % GRID) / 10.0, (i / GRID % GRID) / 10.0, (i / (GRID * GRID)) / 10.0};
            assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
            for (int k = 0; k < m->nvalues; k++) {
                gmin = fmin(gmin, c.v[k]);
                gmax = fmax(gmax, c.v[k]);
            }
        }
        assert_true(gmin >= lo - 1e-6 && gmin <= lo + 1e-5);
        assert_true(gmax <= hi + 1e-6 && gmax >= hi - 1e-5);
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
}

/* Every colour of the grid is a lambert reflectance in every model; the albedo stays in [0, 1] and its RGB is
 * the input's within the model's conversion error (what clamping may take away). */
static void test_grid_accepted_by_lambert(void **state)
{
    (void)state;
    for (int mi = 0; mi < NMODELS; mi++) {
        GColorModel *m = make(models[mi]);
        double lo, hi;
        assert_int_equal(gcolormodel_rgb_range(m, GCOLOR_REFLECTANCE, &lo, &hi), G_OK);
        double err_bound = 2.0 * fmax(-lo, hi - 1.0) + 1e-5;
        GColor c, albedo;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        assert_int_equal(gcolor_alloc(&albedo, m), G_OK);
        GScratch *scratch = gscratch_create(1 << 16);
        assert_non_null(scratch);
        int refused = 0;
        double worst = 0.0;
        for (int i = 0; i < GRID * GRID * GRID; i++) {
            double rgb[3] = {(i % GRID) / 10.0, (i / GRID % GRID) / 10.0, (i / (GRID * GRID)) / 10.0};
            assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE), G_OK);
            GMaterial *l = NULL;
            GError err;
            if (glambert_create(m, &c, &l, &err) != G_OK) {
                if (refused++ == 0)
                    printf("%s refuses rgb %g %g %g: %s\n", models[mi], rgb[0], rgb[1], rgb[2], err.message);
                continue;
            }
            GSurfPoint sp;
            gsurfpoint_init(&sp, m, scratch);
            assert_int_equal(gmaterial_diffuse(l, &sp, &albedo), G_OK);
            for (int k = 0; k < m->nvalues; k++)
                assert_true(albedo.v[k] >= 0.0f && albedo.v[k] <= 1.0f);
            double back[3];
            assert_int_equal(gcolor_to_rgb(&albedo, GCOLOR_REFLECTANCE, back), G_OK);
            for (int j = 0; j < 3; j++)
                worst = fmax(worst, fabs(back[j] - rgb[j]));
            gmaterial_unref(l);
        }
        printf("%-10s grid: %d of %d refused, albedo RGB within %.2g of the input (bound %.2g)\n", models[mi],
               refused, GRID * GRID * GRID, worst, err_bound);
        assert_int_equal(refused, 0);
        assert_true(worst <= err_bound);
        gscratch_destroy(scratch);
        gcolor_free(&c);
        gcolor_free(&albedo);
        gcolormodel_destroy(m);
    }
}

/* Expects glambert_create to refuse c, with a message containing what. */
static void expect_refused(const GColorModel *m, const GColor *c, const char *what)
{
    GMaterial *l = NULL;
    GError err;
    assert_int_equal(glambert_create(m, c, &l, &err), G_ERR_INVALID);
    assert_null(l);
    if (!strstr(err.message, what))
        fail_msg("%s: '%s' does not say '%s'", gcolormodel_name(m), err.message, what);
}

/* Beyond the model's error: out of gamut (a negative component), above 1, NaN, a sample pushed just past the
 * tolerance; each refused, saying the value, the sample and the bound. */
static void test_out_of_range_refused(void **state)
{
    (void)state;
    for (int mi = 0; mi < NMODELS; mi++) {
        GColorModel *m = make(models[mi]);
        double lo, hi;
        assert_int_equal(gcolormodel_rgb_range(m, GCOLOR_REFLECTANCE, &lo, &hi), G_OK);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        double neg[3] = {-0.3, -0.3, -0.3}, over[3] = {1.3, 1.3, 1.3};
        assert_int_equal(gcolor_from_rgb(&c, neg, GCOLOR_REFLECTANCE), G_OK);
        expect_refused(m, &c, "must be finite and >= 0");
        assert_int_equal(gcolor_from_rgb(&c, over, GCOLOR_REFLECTANCE), G_OK);
        expect_refused(m, &c, "(must be <= 1");
        assert_int_equal(gcolor_fill(&c, 0.5), G_OK);
        c.v[m->nvalues - 1] = NAN;
        expect_refused(m, &c, "must be finite");
        /* just past the error on either side */
        assert_int_equal(gcolor_fill(&c, 0.5), G_OK);
        c.v[0] = (float)(lo - 0.01);
        expect_refused(m, &c, "at sample 0");
        assert_int_equal(gcolor_fill(&c, hi + 0.01), G_OK); /* above in every band: no fold either */
        expect_refused(m, &c, "at sample 0");
        if (m->nsamples > 0)
            expect_refused(m, &c, "380 nm");
        if (mi > 0) {
            expect_refused(m, &c, "conversion error of model");
            /* inside the error: accepted and clamped */
            assert_int_equal(gcolor_fill(&c, 0.5), G_OK);
            c.v[0] = (float)(lo * 0.5);
            c.v[1] = (float)(1.0 + (hi - 1.0) * 0.5);
            GMaterial *l = NULL;
            GError err;
            assert_int_equal(glambert_create(m, &c, &l, &err), G_OK);
            GScratch *scratch = gscratch_create(1 << 16);
            GSurfPoint sp;
            gsurfpoint_init(&sp, m, scratch);
            GColor a;
            assert_int_equal(gcolor_alloc(&a, m), G_OK);
            assert_int_equal(gmaterial_diffuse(l, &sp, &a), G_OK);
            assert_true(a.v[0] == 0.0f && a.v[1] == 1.0f);
            gcolor_free(&a);
            gmaterial_unref(l);
            gscratch_destroy(scratch);
        }
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
}

/* The primaries the issue found refused, through the reader, in every model. */
static void test_primaries_through_the_reader(void **state)
{
    (void)state;
    static const char *const text =
        "material r lambert { reflectance rgb 1 0 0 }\nmaterial g lambert { reflectance rgb 0 1 0 }\n"
        "material b lambert { reflectance rgb 0 0 1 }\nmaterial m phong { diffuse rgb 0 0.5 0 specular rgb 0 0.5 0 }\n";
    for (int mi = 0; mi < NMODELS; mi++) {
        GReaderOptions opt;
        memset(&opt, 0, sizeof opt);
        opt.colormodel = models[mi];
        GLibrary *lib = NULL;
        GError err;
        int rc = greader_load_string(text, "p.mat", &opt, &lib, &err);
        if (rc != G_OK)
            fail_msg("%s: %s", models[mi], err.message);
        glibrary_destroy(lib);
    }
}

/* A re-radiation matrix whose brightness is above 1 is refused naming the brightness, not a sample. */
static void test_matrix_message(void **state)
{
    (void)state;
    GColorModel *m = make("bispectral");
    GColor c;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    int n = m->nsamples;
    for (int k = 0; k < n * n; k++)
        c.v[k] = (k % (n + 1) == 0) ? 1.5f : 0.0f;
    c.kind = GCOLOR_MATRIX;
    expect_refused(m, &c, "re-radiation matrix that sends out 1.5 of the light arriving at excitation sample 0");
    c.v[3] = -1.0f;
    expect_refused(m, &c, "excitation sample 3");
    gcolor_free(&c);
    gcolormodel_destroy(m);
}

/* A light of unit power at nm alone, converted into model m (c allocated). */
static void line_light(GColorModel *m, int nm, GColor *c)
{
    assert_int_equal(gcolor_alloc(c, m), G_OK);
    GSpectrumNM line;
    memset(&line, 0, sizeof line);
    line.v[nm - GNM_MIN] = 1.0f;
    assert_int_equal(gcolor_from_nm(c, &line, GCOLOR_LIGHT), G_OK);
}

/* A line light is out of the rgb gamut: mapped (no negative, luminance kept) and reported; an in-gamut light
 * converted into a spectral model is only clamped, not reported. */
static void test_clip_to_gamut(void **state)
{
    (void)state;
    GColorModel *rgb = make("rgb");
    GColor c;
    line_light(rgb, 546, &c);
    assert_true(c.v[0] < 0.0f); /* green 546 nm has a negative red in sRGB */
    double xyz0[3], xyz1[3];
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz0), G_OK);
    int mapped = -1;
    assert_int_equal(gcolor_clip_to_gamut(&c, GCOLOR_LIGHT, &mapped), G_OK);
    assert_int_equal(mapped, 1);
    assert_true(gcolor_is_nonnegative(&c));
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz1), G_OK);
    assert_true(fabs(xyz1[1] - xyz0[1]) < 1e-6 * xyz0[1]);
    c.v[1] = INFINITY;
    assert_int_equal(gcolor_clip_to_gamut(&c, GCOLOR_LIGHT, &mapped), G_ERR_INVALID);
    gcolor_free(&c);
    gcolormodel_destroy(rgb);
    for (int mi = 1; mi < NMODELS; mi++) {
        GColorModel *m = make(models[mi]);
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        double green[3] = {0, 1, 0};
        assert_int_equal(gcolor_from_rgb(&c, green, GCOLOR_LIGHT), G_OK);
        int negative = !gcolor_is_nonnegative(&c);
        assert_int_equal(gcolor_clip_to_gamut(&c, GCOLOR_LIGHT, &mapped), G_OK);
        assert_int_equal(mapped, 0);
        assert_true(gcolor_is_nonnegative(&c));
        printf("%-10s light rgb 0 1 0: %s\n", models[mi], negative ? "dipped below 0, clamped" : "non-negative");
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
}

/* Reflectances above 1: a plain vector is refused where the model has matrices (rgb, bispectral) and accepted as a
 * fold, unclamped, where it has none when its energy is <= 1; above that energy it is refused everywhere. A
 * matrix that piles light from every excitation into one emission sample (fold 0.9 n there) but sends out 0.9
 * per excitation sample conserves energy and is accepted. */
static void test_above_one_is_a_fold(void **state)
{
    (void)state;
    for (int mi = 0; mi < NMODELS; mi++) {
        GColorModel *m = make(models[mi]);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        assert_int_equal(gcolor_fill(&c, 0.3), G_OK);
        c.v[0] = 1.6f;
        double e = gmaterial_param_energy(&c, NULL);
        assert_true(e < 1.0);
        GMaterial *l = NULL;
        GError err;
        int rc = glambert_create(m, &c, &l, &err);
        int matrices = m->cls->from_reradiation != NULL;
        if (matrices) {
            assert_int_equal(rc, G_ERR_INVALID);
            assert_null(strstr(err.message, "only as the fold")); /* a plain vector: no fold here */
        } else {
            if (rc != G_OK)
                fail_msg("%s: a fold of energy %g refused: %s", models[mi], e, err.message);
            GScratch *scratch = gscratch_create(1 << 16);
            GSurfPoint sp;
            gsurfpoint_init(&sp, m, scratch);
            GColor a;
            assert_int_equal(gcolor_alloc(&a, m), G_OK);
            assert_int_equal(gmaterial_diffuse(l, &sp, &a), G_OK);
            assert_true(fabsf(a.v[0] - 1.6f) < 1e-6f); /* unclamped */
            gcolor_free(&a);
            gscratch_destroy(scratch);
            gmaterial_unref(l);
        }
        assert_int_equal(gcolor_fill(&c, 1.2), G_OK); /* energy 1.2: refused in every model */
        expect_refused(m, &c, "(must be <= 1");
        if (matrices) {
            int n = m->nvalues;
            memset(c.v, 0, sizeof(float) * (size_t)n * n);
            for (int i = 0; i < n; i++)
                c.v[(n - 1) * n + i] = 0.9f;
            c.kind = GCOLOR_MATRIX;
            assert_int_equal(glambert_create(m, &c, &l, &err), G_OK);
            gmaterial_unref(l);
            c.v[(n - 1) * n + 2] = 1.5f;
            expect_refused(m, &c, "excitation sample 2");
        }
        gcolor_free(&c);
        gcolormodel_destroy(m);
    }
}

/* The measured day-glo pigment (shared data, skipped without it) as a lambert reflectance: accepted in every
 * model, as a fold whose energy is <= 1 (spectrum9, spectrum) or as a matrix (rgb's reduction, bispectral). */
static void test_measured_fold(void **state)
{
    (void)state;
    static const char *const path = "/work/shared/data/bispectral/HERPIORA.BFC";
    FILE *f = fopen(path, "r");
    if (!f) {
        printf("%s not found: skipped\n", path);
        return;
    }
    fclose(f);
    char text[256];
    snprintf(text, sizeof text, "color h bfc \"%s\"\nmaterial m lambert { reflectance h }\n", path);
    for (int mi = 0; mi < NMODELS; mi++) {
        GReaderOptions opt;
        memset(&opt, 0, sizeof opt);
        opt.colormodel = models[mi];
        GLibrary *lib = NULL;
        GError err;
        int rc = greader_load_string(text, "h.mat", &opt, &lib, &err);
        printf("%-10s HERPIORA as lambert: %s\n", models[mi], rc == G_OK ? "accepted" : err.message);
        assert_int_equal(rc, G_OK);
        glibrary_destroy(lib);
    }
}

/* A line light out of the rgb gamut mapped as a light: its negative components 0, the others unchanged (its
 * luminance not restored), reported; within a model's conversion error the luminance is kept, as
 * gcolor_clip_to_gamut keeps it. */
static void test_clip_light_to_gamut(void **state)
{
    (void)state;
    GColorModel *rgb = make("rgb");
    GColor c;
    line_light(rgb, 450, &c);
    float before[3] = {c.v[0], c.v[1], c.v[2]};
    assert_true(before[1] < 0.0f && before[0] > 0.0f && before[2] > 0.0f); /* 450 nm: a negative green */
    int mapped = -1;
    assert_int_equal(gcolor_clip_light_to_gamut(&c, &mapped), G_OK);
    assert_int_equal(mapped, 1);
    assert_true(c.v[0] == before[0] && c.v[1] == 0.0f && c.v[2] == before[2]);
    c.v[0] = NAN;
    assert_int_equal(gcolor_clip_light_to_gamut(&c, &mapped), G_ERR_INVALID);
    gcolor_free(&c);
    gcolormodel_destroy(rgb);
    GColorModel *sp = make("spectrum");
    assert_int_equal(gcolor_alloc(&c, sp), G_OK);
    double green[3] = {0, 1, 0}, xyz0[3], xyz1[3];
    assert_int_equal(gcolor_from_rgb(&c, green, GCOLOR_LIGHT), G_OK);
    c.v[0] = -1e-7f; /* within the conversion error */
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz0), G_OK);
    assert_int_equal(gcolor_clip_light_to_gamut(&c, &mapped), G_OK);
    assert_int_equal(mapped, 0);
    assert_true(gcolor_is_nonnegative(&c));
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz1), G_OK);
    assert_true(fabs(xyz1[1] - xyz0[1]) < 1e-6 * xyz0[1]);
    gcolor_free(&c);
    gcolormodel_destroy(sp);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_range_is_the_cube_extremes),
        cmocka_unit_test(test_grid_accepted_by_lambert),
        cmocka_unit_test(test_out_of_range_refused),
        cmocka_unit_test(test_primaries_through_the_reader),
        cmocka_unit_test(test_matrix_message),
        cmocka_unit_test(test_clip_to_gamut),
        cmocka_unit_test(test_clip_light_to_gamut),
        cmocka_unit_test(test_above_one_is_a_fold),
        cmocka_unit_test(test_measured_fold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
