/* test_fluorescent_rgb.c - re-radiation matrices in rgb and spectrum9: the non-orthogonal reduction
 * (gcolormodel_reduce_reradiation) and the models' 3 x 3 and 9 x 9 matrices.
 *   - a plain reflectance (a diagonal matrix) reduces to the identity for white 1 and, in general, to a matrix whose
 *     response to white is the rgb reflectance of the diagonal;
 *   - every reduced matrix has entries >= 0 and column sums <= 1 (energy, material_params.h);
 *   - the colour of a fluorescent patch under D65, A and F2 (CIE FL2) against the bispectral model's: for the
 *     measured matrices of ../shared/data/bispectral (skipped when absent) and the parametric day-glo orange, the
 *     mean CIEDE2000 of the reduction is below the equal-energy fold's (the reflectance rgb had before matrices)
 *     under each illuminant, and the reduction is within 0.1 of the bispectral colour under D65 wherever no
 *     column needed scaling; the same in spectrum9 against its own fold (the reflectance it had before matrices);
 *   - the matrix operations against hand-computed products, in both models. */
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
#include "generic/fluorescent.h"
#include "generic/services/bfc.h"
#include "colour_difference.h"
#include "test_util.h"

static GColorModel *model(const char *name)
{
    GColorModel *m;
    GError err;
    assert_int_equal(generic_register_builtins(&err), G_OK);
    assert_int_equal(gcolormodel_create(name, NULL, &m, &err), G_OK);
    return m;
}

/* The path of a shared BFC file, or NULL when the data is not there. */
static const char *bfc_path(const char *name)
{
    static char path[1024];
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/../shared/data/bispectral/%s", src ? src : ".", name);
    if (access(path, R_OK) != 0)
        snprintf(path, sizeof path, "/work/shared/data/bispectral/%s", name);
    return access(path, R_OK) == 0 ? path : NULL;
}

/* A diagonal matrix on 380..780 nm every 10 nm with the reflectance refl(nm). */
static float *diagonal_matrix(double (*refl)(double), GReradiation *r)
{
    float *v = calloc(41 * 41, sizeof *v);
    assert_non_null(v);
    for (int k = 0; k < 41; k++)
        v[k * 41 + k] = (float)refl(380.0 + 10.0 * k);
    *r = (GReradiation){
        .in_min = 380, .in_step = 10, .n_in = 41, .out_min = 380, .out_step = 10, .n_out = 41, .data = v};
    return v;
}

static double white(double nm) { return (void)nm, 1.0; }
static double reddish(double nm) { return 0.1 + 0.8 / (1.0 + exp(-(nm - 600.0) / 15.0)); }

/* A diagonal matrix of 1 reduces to the identity in the model named; a coloured one to a matrix whose response to
 * white is the reflectance: in rgb its rgb reflectance (rgb's white is D65), in spectrum9 the reflectance's colour
 * under equal energy (the sum of its unit lights is the constant 1), both exactly. */
static void plain_reflectance(const char *name)
{
    GColorModel *m = model(name);
    int n = m->nvalues;
    GError err;
    GReradiation r;
    float *v = diagonal_matrix(white, &r);
    GColor c, d;
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gcolor_alloc(&d, m), G_OK);
    assert_int_equal(gcolor_from_reradiation(&c, &r, &err), G_OK);
    assert_int_equal(c.kind, GCOLOR_MATRIX);
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++)
            assert_true(fabs(c.v[o * n + i] - (o == i ? 1.0 : 0.0)) < 1e-4);
    free(v);
    v = diagonal_matrix(reddish, &r);
    assert_int_equal(gcolor_from_reradiation(&c, &r, &err), G_OK);
    GSpectrumNM s; /* the diagonal is linear between its samples */
    for (int k = 0; k < GNM_COUNT; k++) {
        int q = k / 10 < 40 ? k / 10 : 39;
        double t = (k - 10.0 * q) / 10.0;
        s.v[k] = (float)((1.0 - t) * reddish(380.0 + 10.0 * q) + t * reddish(390.0 + 10.0 * q));
    }
    double fold[3], want[3];
    if (n == 3) {
        assert_int_equal(gcolor_from_nm(&d, &s, GCOLOR_REFLECTANCE), G_OK);
        assert_int_equal(gcolor_to_rgb(&c, GCOLOR_REFLECTANCE, fold), G_OK);
        assert_int_equal(gcolor_to_rgb(&d, GCOLOR_REFLECTANCE, want), G_OK);
    } else {
        assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, fold), G_OK);
        gcie_nm_to_xyz(&s, GCOLOR_LIGHT, want);
    }
    for (int k = 0; k < 3; k++)
        assert_true(fabs(fold[k] - want[k]) < 1e-4);
    free(v);
    gcolor_free(&c);
    gcolor_free(&d);
    gcolormodel_destroy(m);
}

static void test_plain_reflectance(void **state)
{
    (void)state;
    plain_reflectance("rgb");
    plain_reflectance("spectrum9");
}

/* The equal-energy fold of r as an rgb reflectance, clipped into the gamut keeping its luminance: what rgb made of
 * a re-radiation matrix before it had matrices. */
static void naive_fold(const GReradiation *r, GColor *out)
{
    GSpectrumNM s;
    for (int k = 0; k < GNM_COUNT; k++) {
        double f = (GNM_MIN + k - r->out_min) / r->out_step, v = 0.0;
        int o = (int)floor(f);
        double t = f - o;
        for (int q = 0; q < 2; q++) {
            int row = o + q;
            double w = q ? t : 1.0 - t;
            if (row < 0 || row >= r->n_out || w == 0.0)
                continue;
            for (int i = 0; i < r->n_in; i++) {
                double nm = r->in_min + i * r->in_step;
                if (nm >= GNM_MIN && nm <= GNM_MAX)
                    v += w * r->data[row * r->n_in + i];
            }
        }
        s.v[k] = (float)v;
    }
    assert_int_equal(gcolor_from_nm(out, &s, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_clip_to_gamut(out, GCOLOR_REFLECTANCE, NULL), G_OK);
}

/* XYZ of the light the matrix colour a (of its own model) sends back under the illuminant */
static void patch_xyz(const GColor *a, const GSpectrumNM *light, double xyz[3])
{
    GColor l, o;
    assert_int_equal(gcolor_alloc(&l, a->model), G_OK);
    assert_int_equal(gcolor_alloc(&o, a->model), G_OK);
    assert_int_equal(gcolor_from_nm(&l, light, GCOLOR_LIGHT), G_OK);
    assert_int_equal(gcolor_mul(&o, a, &l), G_OK);
    assert_int_equal(gcolor_to_xyz(&o, GCOLOR_LIGHT, xyz), G_OK);
    gcolor_free(&l);
    gcolor_free(&o);
}

enum { NILLUM = 3 };
static const char *const illuminants[NILLUM] = {"D65", "A", "F2"};

typedef struct Totals {
    double naive[NILLUM], reduced[NILLUM];
    int count;
} Totals;

/* Adds the CIEDE2000 of the naive fold and of the reduction to the bispectral colour under each illuminant. */
static void compare(const char *name, const GReradiation *r, GColorModel *rgb, GColorModel *bi, Totals *t)
{
    GError err;
    GColor reduced, naive, mat;
    assert_int_equal(gcolor_alloc(&reduced, rgb), G_OK);
    assert_int_equal(gcolor_alloc(&naive, rgb), G_OK);
    assert_int_equal(gcolor_alloc(&mat, bi), G_OK);
    assert_int_equal(gcolor_from_reradiation(&reduced, r, &err), G_OK);
    assert_int_equal(gcolor_from_reradiation(&mat, r, &err), G_OK);
    naive_fold(r, &naive);
    /* non-negative, and energy: every column sums to at most 1 */
    int n = rgb->nvalues;
    const char *model_name = gcolormodel_name(rgb);
    assert_int_equal(reduced.kind, GCOLOR_MATRIX);
    for (int i = 0; i < n; i++) {
        double sum = 0.0;
        for (int o = 0; o < n; o++) {
            assert_true(reduced.v[o * n + i] >= 0.0f);
            sum += reduced.v[o * n + i];
        }
        assert_true(sum <= 1.0 + 1e-6);
    }
    for (int l = 0; l < NILLUM; l++) {
        GSpectrumNM light;
        assert_int_equal(gcie_illuminant_nm(illuminants[l], &light), G_OK);
        double w[3], ref[3], a[3], b[3], lw[3], lr[3], la[3], lb[3];
        gcie_nm_to_xyz(&light, GCOLOR_LIGHT, w);
        patch_xyz(&mat, &light, ref);
        patch_xyz(&naive, &light, a);
        patch_xyz(&reduced, &light, b);
        cd_xyz_to_lab_white(w, w, lw);
        cd_xyz_to_lab_white(ref, w, lr);
        cd_xyz_to_lab_white(a, w, la);
        cd_xyz_to_lab_white(b, w, lb);
        double dn = cd_delta_e2000(lr, la), dr = cd_delta_e2000(lr, lb);
        /* under D65 (rgb's white) the reduction is exact unless the colour leaves the rgb gamut (a negative
         * component is 0) or its components sum above white's 3 (scaled to 3: energy) */
        double rgb[3];
        gcie_xyz_to_rgb(ref, rgb);
        int exact = n == 3 && l == 0 && fmin(rgb[0], fmin(rgb[1], rgb[2])) >= 0.0 && rgb[0] + rgb[1] + rgb[2] <= 3.0;
        print_message("%-9s %-12s %-3s  CIEDE2000 to bispectral: fold %6.3f  reduced %6.3f%s\n", model_name, name,
                      illuminants[l], dn, dr, n == 3 && l == 0 && !exact ? "  (outside the gamut or above white)" : "");
        if (exact)
            assert_true(dr < 0.1);
        t->naive[l] += dn;
        t->reduced[l] += dr;
    }
    t->count++;
    gcolor_free(&reduced);
    gcolor_free(&naive);
    gcolor_free(&mat);
}

/* The reduction in the model named against its fold, under each illuminant. */
static void reduction_against_bispectral(const char *name)
{
    GColorModel *rgb = model(name), *bi = model("bispectral");
    Totals t = {0};
    GError err;
    GFluorBands bands;
    gfluor_bands_default(&bands);
    GReradiation par;
    assert_int_equal(gfluor_matrix_create(&bands, 300, 10, 49, &par, &err), G_OK);
    compare("day-glo", &par, rgb, bi, &t);
    gfluor_matrix_free(&par);
    static const char *const names[] = {"CIBA12.BFC", "HERPIORA.BFC", "POLGREE.BFC", "TEXTYELL.BFC"};
    int measured = 0;
    for (int f = 0; f < 4; f++) {
        const char *path = bfc_path(names[f]);
        if (!path)
            continue;
        GBfcData d;
        assert_int_equal(gbfc_read(path, &d, &err), G_OK);
        compare(names[f], &d.rerad, rgb, bi, &t);
        gbfc_free(&d);
        measured++;
    }
    if (!measured)
        print_message("no measured matrices (../shared/data/bispectral): the parametric one alone\n");
    for (int l = 0; l < NILLUM; l++) {
        double n = t.naive[l] / t.count, r = t.reduced[l] / t.count;
        print_message("%s: mean of %d under %-3s: fold %.3f  reduced %.3f\n", name, t.count, illuminants[l], n, r);
        assert_true(r < n);
    }
    gcolormodel_destroy(rgb);
    gcolormodel_destroy(bi);
}

static void test_reduction_against_bispectral(void **state)
{
    (void)state;
    reduction_against_bispectral("rgb");
}

static void test_reduction_spectrum9(void **state)
{
    (void)state;
    reduction_against_bispectral("spectrum9");
}

static void set9(GColor *c, const float v[9])
{
    memcpy(c->v, v, 9 * sizeof *v);
    c->kind = GCOLOR_MATRIX;
}

static void test_matrix_operations(void **state)
{
    (void)state;
    GColorModel *m = model("rgb");
    assert_int_equal(m->nvalues, 3);
    assert_int_equal(m->capacity, 9);
    GColor a, b, v, out;
    assert_int_equal(gcolor_alloc(&a, m), G_OK);
    assert_int_equal(gcolor_alloc(&b, m), G_OK);
    assert_int_equal(gcolor_alloc(&v, m), G_OK);
    assert_int_equal(gcolor_alloc(&out, m), G_OK);
    const float am[9] = {0.5f, 0.25f, 0.125f, 0.0f, 0.5f, 0.25f, 0.0f, 0.0f, 0.5f};
    const float bm[9] = {0.2f, 0.0f, 0.0f, 0.1f, 0.3f, 0.0f, 0.0f, 0.2f, 0.4f};
    set9(&a, am);
    set9(&b, bm);
    v.v[0] = 1.0f, v.v[1] = 2.0f, v.v[2] = 4.0f;
    /* the light A v */
    assert_int_equal(gcolor_mul(&out, &a, &v), G_OK);
    assert_int_equal(out.kind, GCOLOR_VECTOR);
    assert_true(fabs(out.v[0] - 1.5) < 1e-6 && fabs(out.v[1] - 2.0) < 1e-6 && fabs(out.v[2] - 2.0) < 1e-6);
    /* A B, B applied first; out aliasing an operand */
    assert_int_equal(gcolor_copy(&out, &a), G_OK);
    assert_int_equal(gcolor_mul(&out, &out, &b), G_OK);
    assert_int_equal(out.kind, GCOLOR_MATRIX);
    for (int o = 0; o < 3; o++)
        for (int i = 0; i < 3; i++) {
            double p = 0.0;
            for (int k = 0; k < 3; k++)
                p += am[o * 3 + k] * bm[k * 3 + i];
            assert_true(fabs(out.v[o * 3 + i] - p) < 1e-6);
        }
    /* diag(v) B scales B's rows; A + diag(v) */
    assert_int_equal(gcolor_mul(&out, &v, &b), G_OK);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(out.v[k] - v.v[k / 3] * bm[k]) < 1e-6);
    assert_int_equal(gcolor_add(&out, &a, &v), G_OK);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(out.v[k] - (am[k] + (k % 4 == 0 ? v.v[k / 4] : 0.0f))) < 1e-6);
    /* axpy through the model's scale and add */
    assert_int_equal(gcolor_axpy(&out, 2.0, &a, &b), G_OK);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(out.v[k] - (2.0f * am[k] + bm[k])) < 1e-6);
    /* brightness, XYZ: the response to white, A (1, 1, 1) */
    double rows[3] = {0.875, 0.75, 0.5}, xyz[3], want[3];
    gcie_rgb_to_xyz(rows, want);
    assert_int_equal(gcolor_to_xyz(&a, GCOLOR_REFLECTANCE, xyz), G_OK);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(xyz[k] - want[k]) < 1e-6);
    assert_true(fabs(gcolor_brightness(&a) - (0.2126729 * 0.875 + 0.7151522 * 0.75 + 0.0721750 * 0.5)) < 1e-6);
    assert_false(gcolor_is_black(&a));
    /* div and pow read the diagonal: a medium absorbs, it does not fluoresce */
    assert_int_equal(gcolor_pow(&out, &a, 2.0), G_OK);
    assert_int_equal(out.kind, GCOLOR_VECTOR);
    assert_true(fabs(out.v[0] - 0.25) < 1e-6 && fabs(out.v[2] - 0.25) < 1e-6);
    gcolor_free(&a);
    gcolor_free(&b);
    gcolor_free(&v);
    gcolor_free(&out);
    gcolormodel_destroy(m);
}

/* spectrum9's 9 x 9 matrices: products, sums and the reading of a matrix by its response to white, against the
 * same computed by hand; a vector's operations unchanged. */
static void test_matrix_operations_spectrum9(void **state)
{
    (void)state;
    GColorModel *m = model("spectrum9");
    assert_int_equal(m->nvalues, 9);
    assert_int_equal(m->capacity, 81);
    GColor a, b, v, out, rows;
    assert_int_equal(gcolor_alloc(&a, m), G_OK);
    assert_int_equal(gcolor_alloc(&b, m), G_OK);
    assert_int_equal(gcolor_alloc(&v, m), G_OK);
    assert_int_equal(gcolor_alloc(&out, m), G_OK);
    assert_int_equal(gcolor_alloc(&rows, m), G_OK);
    float am[81], bm[81];
    for (int k = 0; k < 81; k++) {
        am[k] = k / 9 <= k % 9 ? 0.01f * (float)(1 + (k * 7) % 11) : 0.0f; /* upper triangle: re-radiation to red */
        bm[k] = 0.02f * (float)((k * 5) % 7);
    }
    memcpy(a.v, am, sizeof am), a.kind = GCOLOR_MATRIX;
    memcpy(b.v, bm, sizeof bm), b.kind = GCOLOR_MATRIX;
    for (int k = 0; k < 9; k++)
        v.v[k] = 0.5f + 0.25f * (float)k;
    assert_int_equal(gcolor_mul(&out, &a, &v), G_OK); /* the light A v */
    assert_int_equal(out.kind, GCOLOR_VECTOR);
    for (int o = 0; o < 9; o++) {
        double p = 0.0, r = 0.0;
        for (int i = 0; i < 9; i++)
            p += am[o * 9 + i] * v.v[i], r += am[o * 9 + i];
        assert_true(fabs(out.v[o] - p) < 1e-6);
        rows.v[o] = (float)r;
    }
    assert_int_equal(gcolor_copy(&out, &a), G_OK); /* A B, out aliasing A */
    assert_int_equal(gcolor_mul(&out, &out, &b), G_OK);
    assert_int_equal(out.kind, GCOLOR_MATRIX);
    for (int o = 0; o < 9; o++)
        for (int i = 0; i < 9; i++) {
            double p = 0.0;
            for (int k = 0; k < 9; k++)
                p += am[o * 9 + k] * bm[k * 9 + i];
            assert_true(fabs(out.v[o * 9 + i] - p) < 1e-6);
        }
    assert_int_equal(gcolor_mul(&out, &v, &b), G_OK); /* diag(v) B */
    for (int k = 0; k < 81; k++)
        assert_true(fabs(out.v[k] - v.v[k / 9] * bm[k]) < 1e-6);
    assert_int_equal(gcolor_add(&out, &a, &v), G_OK); /* A + diag(v) */
    for (int k = 0; k < 81; k++)
        assert_true(fabs(out.v[k] - (am[k] + (k % 10 == 0 ? v.v[k / 10] : 0.0f))) < 1e-6);
    assert_int_equal(gcolor_axpy(&out, 2.0, &a, &b), G_OK);
    for (int k = 0; k < 81; k++)
        assert_true(fabs(out.v[k] - (2.0f * am[k] + bm[k])) < 1e-6);
    assert_int_equal(gcolor_scale(&out, &a, 0.5), G_OK);
    assert_int_equal(out.kind, GCOLOR_MATRIX);
    assert_true(fabs(out.v[80] - 0.5f * am[80]) < 1e-7);
    /* XYZ, the nm spectrum and brightness read the response to white, the row sums (entries >= 0 here) */
    double xyz[3], want[3];
    assert_int_equal(gcolor_to_xyz(&a, GCOLOR_LIGHT, xyz), G_OK);
    assert_int_equal(gcolor_to_xyz(&rows, GCOLOR_LIGHT, want), G_OK);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(xyz[k] - want[k]) < 1e-6 * fmax(1.0, fabs(want[k])));
    GSpectrumNM sa, sr;
    assert_int_equal(gcolor_to_nm(&a, GCOLOR_REFLECTANCE, &sa), G_OK);
    assert_int_equal(gcolor_to_nm(&rows, GCOLOR_REFLECTANCE, &sr), G_OK);
    for (int k = 0; k < GNM_COUNT; k++)
        assert_true(fabs(sa.v[k] - sr.v[k]) < 1e-6);
    assert_true(fabs(gcolor_brightness(&a) - gcolor_brightness(&rows)) < 1e-6);
    /* pow, div and exp read the diagonal */
    assert_int_equal(gcolor_pow(&out, &a, 2.0), G_OK);
    assert_int_equal(out.kind, GCOLOR_VECTOR);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(out.v[k] - am[k * 10] * am[k * 10]) < 1e-6);
    assert_int_equal(gcolor_exp(&out, &a, -1.0), G_OK);
    assert_true(out.kind == GCOLOR_VECTOR && fabs(out.v[4] - exp(-am[40])) < 1e-6);
    assert_int_equal(gcolor_div(&out, &a, &v), G_OK);
    assert_true(out.kind == GCOLOR_VECTOR && fabs(out.v[8] - am[80] / v.v[8]) < 1e-6);
    /* two vectors: sample by sample */
    assert_int_equal(gcolor_mul(&out, &v, &rows), G_OK);
    for (int k = 0; k < 9; k++)
        assert_true(fabs(out.v[k] - v.v[k] * rows.v[k]) < 1e-6);
    gcolor_free(&a);
    gcolor_free(&b);
    gcolor_free(&v);
    gcolor_free(&out);
    gcolor_free(&rows);
    gcolormodel_destroy(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plain_reflectance),
        cmocka_unit_test(test_reduction_against_bispectral),
        cmocka_unit_test(test_reduction_spectrum9),
        cmocka_unit_test(test_matrix_operations),
        cmocka_unit_test(test_matrix_operations_spectrum9),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
