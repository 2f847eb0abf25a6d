/* test_bfc.c - the Labsphere BFC-450 reader: the four measured matrices of ../shared/data/bispectral (skipped
 * when the data is absent) read with their grid and known values, and malformed files refused with the line
 * and column of the fault. */
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
#include "generic/color.h"

static const char *data_file(const char *name)
{
    static char buf[4096];
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(buf, sizeof buf, "%s/../shared/data/bispectral/%s", src ? src : ".", name);
    if (access(buf, R_OK) != 0)
        snprintf(buf, sizeof buf, "/work/shared/data/bispectral/%s", name);
    return buf;
}

static float at(const GBfcData *d, double out_nm, double in_nm)
{
    int o = (int)lround((out_nm - d->rerad.out_min) / d->rerad.out_step);
    int i = (int)lround((in_nm - d->rerad.in_min) / d->rerad.in_step);
    return d->rerad.data[o * d->rerad.n_in + i];
}

static void test_real_files(void **state)
{
    (void)state;
    if (access(data_file("CIBA12.BFC"), R_OK) != 0)
        skip();
    static const char *const names[] = {"CIBA12.BFC", "HERPIORA.BFC", "POLGREE.BFC", "TEXTYELL.BFC"};
    for (int f = 0; f < 4; f++) {
        GBfcData d;
        GError err;
        int rc = gbfc_read(data_file(names[f]), &d, &err);
        if (rc != G_OK)
            print_error("%s\n", err.message);
        assert_int_equal(rc, G_OK);
        assert_int_equal(d.rerad.n_in, 49);
        assert_int_equal(d.rerad.n_out, 41);
        assert_true(d.rerad.in_min == 300.0 && d.rerad.in_step == 10.0);
        assert_true(d.rerad.out_min == 380.0 && d.rerad.out_step == 10.0);
        assert_ptr_equal(d.rerad.data, d.values);
        /* a reflectance: the diagonal lies in (0, 1.2) over the visible range */
        for (int nm = 400; nm <= 700; nm += 10) {
            float v = at(&d, nm, nm);
            assert_true(v > 0.0f && v < 1.2f);
        }
        gbfc_free(&d);
        assert_null(d.values);
    }
    GBfcData d;
    GError err;
    assert_int_equal(gbfc_read(data_file("CIBA12.BFC"), &d, &err), G_OK);
    assert_string_equal(d.description, "Ciba plastic white # 12");
    assert_true(fabsf(at(&d, 380, 300) - 0.000401615f) < 1e-9f); /* first value of the first row */
    assert_true(fabsf(at(&d, 390, 390) - 0.106772f) < 1e-7f);
    assert_true(fabsf(at(&d, 780, 300) - 0.00176521f) < 1e-9f); /* first value of the last row */
    /* the optical brightener: UV excitation (350 nm) re-radiated in the blue (440 nm) */
    assert_true(at(&d, 440, 350) > 0.01f);
    gbfc_free(&d);
}

static const char header[] = "VEC_01\t5\nBFC-450 Matrix File\n;t.BFC\n;test\n;\n;\n;\n;\n;\n;\n";

static void parse_fails(const char *body, const char *message)
{
    char text[2048];
    snprintf(text, sizeof text, "%s%s", header, body);
    GBfcData d;
    GError err;
    assert_int_equal(gbfc_parse(text, strlen(text), "t.BFC", &d, &err), G_ERR_PARSE);
    assert_string_equal(err.message, message);
    assert_null(d.values);
}

static void test_small_and_malformed(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text, "%s%s", header,
             "400 420 10 2 400 20\r\nr:c:\t400\t420\r\n400\t0.5\t0\r\n410\t0.1\t0\r\n420\t0.2\t0.3\r\nEOD\r\n");
    GBfcData d;
    GError err;
    assert_int_equal(gbfc_parse(text, strlen(text), "t.BFC", &d, &err), G_OK);
    assert_int_equal(d.rerad.n_out, 3);
    assert_int_equal(d.rerad.n_in, 2);
    assert_true(d.rerad.in_step == 20.0);
    assert_true(at(&d, 420, 420) == 0.3f && at(&d, 410, 400) == 0.1f);
    assert_string_equal(d.description, "test");
    gbfc_free(&d);
    gbfc_free(&d); /* a cleared struct is a no-op */

    parse_fails("400 420 10 2 400\n", "t.BFC:11:17: expected the excitation step, found the end of the line");
    parse_fails("400 420 7 2 400 10\n",
                "t.BFC:11:1: invalid grid line (expected: out_min out_max out_step n_in in_min in_step)");
    parse_fails("400 410 10 2 400 10\nlabels 400 410\n",
                "t.BFC:12:1: expected the column label row starting with 'r:c:'");
    parse_fails("400 410 10 2 400 10\nr:c: 400 420\n",
                "t.BFC:12:10: column label 420 does not match the grid (expected 410)");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1 0.2\n420 0.1 0.2\n",
                "t.BFC:14:1: row wavelength 420 does not match the grid (expected 410)");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1\n",
                "t.BFC:13:8: expected a matrix value, found the end of the line");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1 x\n", "t.BFC:13:9: expected a matrix value, found 'x'");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1 nan\n", "t.BFC:13:9: expected a matrix value, found 'nan'");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1 0.2 0.3\n",
                "t.BFC:13:13: more values on the row than the grid line announces");
    parse_fails("400 410 10 2 400 10\nr:c: 400 410\n400 0.1 0.2\n410 0.1 0.2\n",
                "t.BFC:15:1: expected 'EOD' after the last row");
    char shortfile[] = "VEC_01\nBFC\n";
    assert_int_equal(gbfc_parse(shortfile, strlen(shortfile), "s.BFC", &d, &err), G_ERR_PARSE);
    assert_string_equal(err.message, "s.BFC:3:1: file ends inside the 10 header lines");
    assert_int_equal(gbfc_read("/nonexistent/x.BFC", &d, &err), G_ERR_IO);
    assert_string_equal(err.message, "cannot open \"/nonexistent/x.BFC\": No such file or directory");
}

/* Numbers of every length up to past the limit: each is read whole (exact value) or refused naming its length,
 * never split into two numbers - a row short of one value stays an error. */
static void test_long_numbers(void **state)
{
    (void)state;
    static char text[4096], num[600];
    GBfcData d;
    GError err;
    for (int len = 3; len <= 520; len += len < 250 ? 31 : 1) {
        /* "0.5" padded with trailing zeros to len characters: the value is exactly 0.5 */
        memset(num, '0', (size_t)len);
        memcpy(num, "0.5", 3);
        num[len] = '\0';
        snprintf(text, sizeof text, "%s400 410 10 2 400 10\nr:c: 400 410\n400 0.25 %s\n410 0.1 0.2\nEOD\n", header,
                 num);
        int rc = gbfc_parse(text, strlen(text), "t.BFC", &d, &err);
        if (len <= 255) {
            assert_int_equal(rc, G_OK);
            assert_true(at(&d, 400, 410) == 0.5f && at(&d, 400, 400) == 0.25f);
            gbfc_free(&d);
        } else {
            char want[200];
            snprintf(want, sizeof want,
                     "t.BFC:13:10: expected a matrix value, found a token of %d characters (at most 255)", len);
            assert_int_equal(rc, G_ERR_PARSE);
            assert_string_equal(err.message, want);
            assert_null(d.values);
        }
        /* the same number as the only value of a two-column row: one value is missing */
        snprintf(text, sizeof text, "%s400 410 10 2 400 10\nr:c: 400 410\n400 %s\n410 0.1 0.2\nEOD\n", header, num);
        assert_int_equal(gbfc_parse(text, strlen(text), "t.BFC", &d, &err), G_ERR_PARSE);
        assert_null(d.values);
        assert_non_null(strstr(err.message, len <= 255 ? "t.BFC:13:" : "found a token of"));
    }
}

/* Nothing of a file is quoted before its grid line shows it to be a BFC file (a password file says only that
 * it is not one); after it, a bad token is quoted. */
static void test_foreign_file_not_quoted(void **state)
{
    (void)state;
    char text[2048];
    snprintf(text, sizeof text, "%s%s", header, "secret:x:0:0:secret:/root:/bin/sh\n");
    GBfcData d;
    GError err;
    assert_int_equal(gbfc_parse(text, strlen(text), "t.BFC", &d, &err), G_ERR_PARSE);
    assert_string_equal(err.message, "t.BFC:11:1: expected the first emission wavelength: not a BFC-450 matrix file");
    assert_null(strstr(err.message, "secret"));
    parse_fails("400 secret\n", "t.BFC:11:5: expected the last emission wavelength: not a BFC-450 matrix file");
}

/* A matrix whose grid lies beside a model's range is refused with both ranges; shifted across the range, every
 * conversion is either refused or gives a colour that is not black. */
static void test_grid_outside_model(void **state)
{
    (void)state;
    static const char *const models[] = {"rgb", "spectrum", "bispectral"};
    float data[3 * 3];
    for (int i = 0; i < 9; i++)
        data[i] = i % 4 == 0 ? 0.5f : 0.0f; /* a plain 0.5 reflectance on the diagonal */
    for (int m = 0; m < 3; m++) {
        GColorModel *model;
        GError err;
        assert_int_equal(gcolormodel_create(models[m], NULL, &model, &err), G_OK);
        GColor c = {0};
        assert_int_equal(gcolor_alloc(&c, model), G_OK);
        GReradiation far = {100000, 10, 3, 100000, 10, 3, data};
        assert_int_equal(gcolor_from_reradiation(&c, &far, &err), G_ERR_INVALID);
        assert_non_null(strstr(err.message, "emission wavelengths 100000..100020 nm lie outside the range"));
        int refused = 0, converted = 0;
        for (double shift = -1000; shift <= 1000; shift += 10) {
            GReradiation r = {400 + shift, 10, 3, 400 + shift, 10, 3, data};
            int rc = gcolor_from_reradiation(&c, &r, &err);
            if (rc != G_OK) {
                assert_int_equal(rc, G_ERR_INVALID);
                assert_non_null(strstr(err.message, "lie outside the range of the colour model"));
                refused++;
                continue;
            }
            converted++;
            assert_true(gcolor_brightness(&c) > 0.0);
        }
        assert_true(refused > 100 && converted >= 40);
        gcolor_free(&c);
        gcolormodel_destroy(model);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_real_files),
        cmocka_unit_test(test_small_and_malformed),
        cmocka_unit_test(test_long_numbers),
        cmocka_unit_test(test_foreign_file_not_quoted),
        cmocka_unit_test(test_grid_outside_model),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
