/* test_cie.c - CIE colorimetry (lib/color/cie.c): white points of the illuminants, the colour matching
 * functions and D65 against Debian's colord-data, the blackbody, the sRGB matrices and the RGB basis. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"

static void xy_of(const double xyz[3], double *x, double *y)
{
    double s = xyz[0] + xyz[1] + xyz[2];
    *x = xyz[0] / s;
    *y = xyz[1] / s;
}

static void test_d65_white_point(void **state)
{
    (void)state;
    GSpectrumNM d65;
    double xyz[3];
    assert_int_equal(gcie_illuminant_nm("D65", &d65), G_OK);
    gcie_nm_to_xyz(&d65, GCOLOR_LIGHT, xyz);
    printf("D65 as a light: XYZ = %.5f %.5f %.5f\n", xyz[0], xyz[1], xyz[2]);
    assert_true(fabs(xyz[0] - 0.95047) < 3e-4);
    assert_true(fabs(xyz[1] - 1.0) < 1e-6);
    /* the 1 nm tables come from the 5 nm ones by Sprague interpolation (CIE 15); linear interpolation
     * would give Z = 1.08845, outside this bound */
    assert_true(fabs(xyz[2] - 1.08883) < 3e-4);
    /* the same white as the sRGB matrix's: rgb (1,1,1) */
    double rgb[3];
    gcie_xyz_to_rgb(xyz, rgb);
    for (int i = 0; i < 3; i++)
        assert_true(fabs(rgb[i] - 1.0) < 5e-4);
}

static void test_equal_energy_and_a(void **state)
{
    (void)state;
    GSpectrumNM s;
    double xyz[3];
    assert_int_equal(gcie_illuminant_nm("E", &s), G_OK);
    for (int i = 0; i < GNM_COUNT; i++)
        assert_true(s.v[i] == 1.0f);
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    printf("E as a light: XYZ = %.6f %.6f %.6f\n", xyz[0], xyz[1], xyz[2]);
    assert_true(fabs(xyz[0] - 1.0) < 1e-4);
    assert_true(fabs(xyz[1] - 1.0) < 1e-9);
    /* Z is the closest to the bound (0.99990): the share of zbar below 380 nm is outside the exchange grid */
    assert_true(fabs(xyz[2] - 1.0) < 1e-4);
    /* illuminant A: CIE white point x = 0.44757, y = 0.40745 */
    assert_int_equal(gcie_illuminant_nm("A", &s), G_OK);
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    double x, y;
    xy_of(xyz, &x, &y);
    printf("A: xy = %.5f %.5f\n", x, y);
    assert_true(fabs(xyz[1] - 1.0) < 1e-6);
    assert_true(fabs(x - 0.44757) < 5e-4 && fabs(y - 0.40745) < 5e-4);
    assert_int_equal(gcie_illuminant_nm("F99", &s), G_ERR_NOTFOUND);
    assert_true(gcie_illuminant("nope", 500.0) < 0.0);
}

/* Every named illuminant is a light of Y = 1 on the 1 nm grid, the listed names and only they are known, and the
 * chromaticities of a few are the CIE's published ones (CIE 15:2004, 5 nm sums over 380..780 nm). */
static void test_named_illuminants(void **state)
{
    (void)state;
    static GSpectrumNM s;
    double xyz[3], x, y;
    int n = 0;
    for (; gcie_illuminant_name(n); n++) {
        assert_int_equal(gcie_illuminant_nm(gcie_illuminant_name(n), &s), G_OK);
        gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
        assert_true(fabs(xyz[1] - 1.0) < 1e-6);
    }
    assert_int_equal(n, 29);
    assert_null(gcie_illuminant_name(-1));
    static const struct {
        const char *name;
        double x, y;
    } cie[] = {{"F2", 0.37210, 0.37510}, {"F11", 0.38050, 0.37690}, {"D50", 0.34570, 0.35850},
               {"C", 0.31006, 0.31616},  {"F7", 0.31290, 0.32920},  {"LED-B3", 0.37560, 0.37230}};
    for (size_t i = 0; i < sizeof cie / sizeof *cie; i++) {
        assert_int_equal(gcie_illuminant_nm(cie[i].name, &s), G_OK);
        gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
        xy_of(xyz, &x, &y);
        printf("%s: xy = %.5f %.5f\n", cie[i].name, x, y);
        assert_true(fabs(x - cie[i].x) < 1e-4 && fabs(y - cie[i].y) < 1e-4);
    }
    assert_int_equal(gcie_illuminant_nm("F13", &s), G_ERR_NOTFOUND);
    assert_int_equal(gcie_illuminant_nm("led-b1", &s), G_ERR_NOTFOUND);
    assert_int_equal(gcie_illuminant_nm(NULL, &s), G_ERR_NOTFOUND);
    assert_true(gcie_illuminant("F13", 500.0) < 0.0);
    assert_true(gcie_illuminant("F2", 300.0) == 0.0 && gcie_illuminant("F2", 546.0) > 0.0);
}

static void test_cmf_values(void **state)
{
    (void)state;
    double c[3], d[3];
    gcie_cmf(555.0, c);
    assert_true(fabs(c[1] - 1.0) < 1e-6);
    /* tabulated 1931 values at 5 nm points: xbar(600) = 1.0622, zbar(450) = 1.77211 */
    gcie_cmf(600.0, c);
    assert_true(fabs(c[0] - 1.0622) < 1e-5);
    gcie_cmf(450.0, c);
    assert_true(fabs(c[2] - 1.77211) < 1e-5);
    /* linear between 1 nm values, 0 outside the exchange range */
    gcie_cmf(555.5, c);
    gcie_cmf(555.0, d);
    double e[3];
    gcie_cmf(556.0, e);
    for (int i = 0; i < 3; i++)
        assert_true(fabs(c[i] - 0.5 * (d[i] + e[i])) < 1e-7);
    gcie_cmf(370.0, c);
    assert_true(c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0);
    /* luminance weights are ybar / sum(ybar): sum 1, peak at 555 nm */
    double sum = 0.0;
    int peak = 0;
    for (int i = 0; i < GNM_COUNT; i++) {
        sum += gcie_luminance_weight(i);
        if (gcie_luminance_weight(i) > gcie_luminance_weight(peak))
            peak = i;
    }
    assert_true(fabs(sum - 1.0) < 1e-9);
    assert_int_equal(GNM_MIN + peak, 555);
}

/* ---- colord-data: a small reader for its CGATS-like spectral files ---- */

typedef struct CdData {
    double start, end;
    int bands, sets;
    double v[3][128];
} CdData;

static int read_colord(const char *path, CdData *d)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    memset(d, 0, sizeof *d);
    char line[8192];
    int in_data = 0;
    while (fgets(line, sizeof line, f)) {
        char key[64];
        if (sscanf(line, "%63s", key) != 1)
            continue;
        if (strcmp(key, "SPECTRAL_START_NM") == 0)
            d->start = atof(line + strlen(key) + 1);
        else if (strcmp(key, "SPECTRAL_END_NM") == 0)
            d->end = atof(line + strlen(key) + 1);
        else if (strcmp(key, "SPECTRAL_BANDS") == 0)
            d->bands = atoi(line + strlen(key) + 1);
        else if (strcmp(key, "BEGIN_DATA") == 0)
            in_data = 1;
        else if (strcmp(key, "END_DATA") == 0)
            in_data = 0;
        else if (in_data && d->sets < 3) {
            char *p = line;
            for (int i = 0; i < d->bands && i < 128; i++)
                d->v[d->sets][i] = strtod(p, &p);
            d->sets++;
        }
    }
    fclose(f);
    return d->bands > 1 && d->bands <= 128 && d->sets > 0 ? 0 : -1;
}

static double cd_at(const CdData *d, int set, double nm)
{
    double step = (d->end - d->start) / (d->bands - 1);
    int i = (int)floor((nm - d->start) / step + 0.5);
    return d->v[set][i];
}

static void test_tables_match_colord(void **state)
{
    (void)state;
    CdData cmf, d65;
    if (read_colord("/usr/share/colord/cmf/CIE1931-2deg-XYZ.cmf", &cmf) != 0 ||
        read_colord("/usr/share/colord/illuminant/CIE-D65.sp", &d65) != 0) {
        printf("colord-data not installed: skipped\n");
        skip();
    }
    assert_int_equal(cmf.sets, 3);
    double worst_cmf = 0.0, worst_d65 = 0.0;
    double d560 = gcie_illuminant("D65", 560.0), f560 = cd_at(&d65, 0, 560.0);
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm += 5) {
        double c[3];
        gcie_cmf(nm, c);
        for (int k = 0; k < 3; k++) {
            double ref = cd_at(&cmf, k, nm);
            worst_cmf = fmax(worst_cmf, fabs(c[k] - ref) / fmax(1.0, fabs(ref)));
        }
        /* the library normalises D65 to Y = 1: compare the shape, relative to 560 nm */
        double a = gcie_illuminant("D65", nm) / d560, b = cd_at(&d65, 0, nm) / f560;
        worst_d65 = fmax(worst_d65, fabs(a - b));
    }
    printf("largest difference to colord-data: cmf %.2g, D65 %.2g\n", worst_cmf, worst_d65);
    assert_true(worst_cmf < 1e-6);
    assert_true(worst_d65 < 1e-5);
}

static void test_blackbody(void **state)
{
    (void)state;
    GSpectrumNM s;
    double xyz[3], x, y;
    gcie_blackbody_nm(6504.0, &s);
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    xy_of(xyz, &x, &y);
    printf("blackbody 6504 K: xy = %.4f %.4f (D65 0.3127 0.3290)\n", x, y);
    assert_true(fabs(xyz[1] - 1.0) < 1e-5);
    assert_true(fabs(x - 0.3127) < 0.01 && fabs(y - 0.3290) < 0.01);
    /* 2856 K is illuminant A's temperature; the Planckian locus gives x = 0.4476, y = 0.4074 */
    gcie_blackbody_nm(2856.0, &s);
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    xy_of(xyz, &x, &y);
    assert_true(fabs(x - 0.4476) < 2e-3 && fabs(y - 0.4074) < 2e-3);
    /* hotter is bluer */
    double x2, y2;
    gcie_blackbody_nm(10000.0, &s);
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    xy_of(xyz, &x2, &y2);
    assert_true(x2 < 0.3127 && y2 < 0.3290);
}

static void test_srgb_matrices(void **state)
{
    (void)state;
    for (int c = 0; c < 3; c++) {
        double e[3] = {c == 0, c == 1, c == 2}, xyz[3], back[3];
        gcie_rgb_to_xyz(e, xyz);
        gcie_xyz_to_rgb(xyz, back);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(back[i] - e[i]) < 1e-9);
        gcie_xyz_to_rgb(e, back);
        gcie_rgb_to_xyz(back, xyz);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(xyz[i] - e[i]) < 1e-9);
    }
    double white[3] = {1, 1, 1}, xyz[3];
    gcie_rgb_to_xyz(white, xyz);
    assert_true(fabs(xyz[0] - 0.95047) < 1e-4 && fabs(xyz[1] - 1.0) < 1e-6 && fabs(xyz[2] - 1.08883) < 1e-4);
    /* primaries' chromaticities (Rec.709): red 0.64 0.33, green 0.30 0.60, blue 0.15 0.06 */
    const double prim[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    for (int c = 0; c < 3; c++) {
        double e[3] = {c == 0, c == 1, c == 2}, x, y;
        gcie_rgb_to_xyz(e, xyz);
        xy_of(xyz, &x, &y);
        assert_true(fabs(x - prim[c][0]) < 1e-3 && fabs(y - prim[c][1]) < 1e-3);
    }
}

static void test_rgb_basis(void **state)
{
    (void)state;
    double worst = 0.0;
    float lo = 1.0f, hi = 0.0f;
    for (int role = 0; role < 2; role++)
        for (int r = 0; r <= 4; r++)
            for (int g = 0; g <= 4; g++)
                for (int b = 0; b <= 4; b++) {
                    double rgb[3] = {r / 4.0, g / 4.0, b / 4.0}, xyz[3], back[3];
                    GSpectrumNM s;
                    gcie_rgb_to_nm(rgb, (GColorRole)role, &s);
                    gcie_nm_to_xyz(&s, (GColorRole)role, xyz);
                    gcie_xyz_to_rgb(xyz, back);
                    for (int i = 0; i < 3; i++)
                        worst = fmax(worst, fabs(back[i] - rgb[i]));
                    if (role == GCOLOR_REFLECTANCE)
                        for (int i = 0; i < GNM_COUNT; i++) {
                            lo = fminf(lo, s.v[i]);
                            hi = fmaxf(hi, s.v[i]);
                        }
                }
    printf("rgb -> nm -> rgb: max error %.2g; reflectances within [%.5f, %.5f]\n", worst, lo, hi);
    assert_true(worst < 1e-5);
    assert_true(lo > -1e-3 && hi < 1.001);
    /* white is the constant 1 as a reflectance and D65 (Y = 1) as a light */
    double white[3] = {1, 1, 1};
    GSpectrumNM s, d65;
    gcie_rgb_to_nm(white, GCOLOR_REFLECTANCE, &s);
    for (int i = 0; i < GNM_COUNT; i++)
        assert_true(fabsf(s.v[i] - 1.0f) < 1e-3f);
    gcie_rgb_to_nm(white, GCOLOR_LIGHT, &s);
    assert_int_equal(gcie_illuminant_nm("D65", &d65), G_OK);
    for (int i = 0; i < GNM_COUNT; i++)
        assert_true(fabsf(s.v[i] - d65.v[i]) < 2e-3f * d65.v[i]);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_d65_white_point), cmocka_unit_test(test_equal_energy_and_a),
        cmocka_unit_test(test_cmf_values),      cmocka_unit_test(test_tables_match_colord),
        cmocka_unit_test(test_blackbody),       cmocka_unit_test(test_srgb_matrices),
        cmocka_unit_test(test_rgb_basis),       cmocka_unit_test(test_named_illuminants),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
