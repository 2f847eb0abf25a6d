/* test_metals.c - the table of measured metals (generic/kit/metals.h) and the rule by which each colour model reduces
 * a unitless spectral quantity (GCOLOR_UNITLESS, color.h): the table's names, ranges and values; n and k at the
 * spectral models' own wavelengths; and the measurement behind the rule: the colour of a smooth conductor's Fresnel
 * reflectance at 19 angles, from n and k reduced by each candidate rule, against the spectral result at 1 nm (CIELAB
 * delta E 1976 under D65). The figures printed are those of docs/reference/colour.md ("Unitless quantities"). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/kit/fresnel.h"
#include "generic/kit/metals.h"
#include "generic/vec.h"
#include "test_util.h"

#include <string.h>

static void test_table(void **state)
{
    (void)state;
    int n = gmetal_count();
    assert_true(n >= 30);
    GMetalInfo prev = {0};
    for (int i = 0; i < n; i++) {
        GMetalInfo m;
        assert_int_equal(gmetal_info(i, &m), G_OK);
        assert_true(m.name && m.description && m.source && strstr(m.source, "refractiveindex.info"));
        if (i)
            assert_true(strcmp(prev.name, m.name) < 0);
        assert_true(m.min_nm <= 380.0 && m.max_nm >= 780.0);
        assert_int_equal(gmetal_find(m.name), i);
        for (double nm = 300; nm <= 900; nm += 1) {
            assert_true(gmetal_eta_at(i, nm) > 0.0 && gmetal_k_at(i, nm) >= 0.0);
            assert_true(isfinite(gmetal_eta_at(i, nm)) && isfinite(gmetal_k_at(i, nm)));
        }
        assert_near(gmetal_eta_at(i, 200.0), gmetal_eta_at(i, 360.0), 0.0); /* held beyond the grid */
        assert_near(gmetal_k_at(i, 1e4), gmetal_k_at(i, 830.0), 0.0);
        prev = m;
    }
    GMetalInfo none;
    assert_int_equal(gmetal_info(n, &none), G_ERR_INVALID);
    assert_null(none.name);
    assert_true(isnan(gmetal_eta_at(-1, 500.0)));
    for (const char *const *s = (const char *const[]){"Ag", "Al", "Au", "Cu", "Cr", "Fe", "Ni", "Pt", "Ti", "W",
                                                       "CuZn", NULL};
         *s; s++)
        assert_true(gmetal_find(*s) >= 0);
    assert_int_equal(gmetal_find("au"), gmetal_find("Au"));
    assert_int_equal(gmetal_find("unobtainium"), -1);
    assert_int_equal(gmetal_find(NULL), -1);
    /* Johnson and Christy's gold at 550.0 nm (0.5486 um: 0.43, 2.455; 0.5821 um: 0.29, 2.863), interpolated */
    int au = gmetal_find("Au");
    double t = (550.0 - 548.6) / (582.1 - 548.6);
    assert_near(gmetal_eta_at(au, 550.0), 0.43 + t * (0.29 - 0.43), 1e-5);
    assert_near(gmetal_k_at(au, 550.0), 2.455 + t * (2.863 - 2.455), 1e-5);
    char buf[1024];
    size_t len = gmetal_names(buf, sizeof buf);
    assert_int_equal(len, strlen(buf));
    assert_true(strncmp(buf, "Ag, Al, Au, ", 12) == 0 && strstr(buf, ", steel"));
    char small[8];
    assert_int_equal(gmetal_names(small, sizeof small), len);
    assert_string_equal(small, "Ag, Al,");
}

/* In the spectral models n and k are the table's at the model's own wavelengths. */
static void test_at_wavelengths(void **state)
{
    (void)state;
    assert_int_equal(generic_register_builtins(NULL), G_OK);
    const double steps[] = {1.0, 5.0, 10.0};
    for (int s = 0; s < 3; s++) {
        GColorModelOptions opt = {.step_nm = steps[s]};
        GColorModel *m;
        GError err;
        assert_int_equal(gcolormodel_create(s == 2 ? "bispectral" : "spectrum", &opt, &m, &err), G_OK);
        GColor eta, k;
        assert_int_equal(gcolor_alloc(&eta, m), G_OK);
        assert_int_equal(gcolor_alloc(&k, m), G_OK);
        for (int i = 0; i < gmetal_count(); i++) {
            assert_int_equal(gmetal_colors(i, &eta, &k), G_OK);
            for (int j = 0; j < m->nsamples; j++) {
                double nm = m->lambda_min + j * m->lambda_step;
                assert_near(eta.v[j], gmetal_eta_at(i, nm), 1e-6 * gmetal_eta_at(i, nm));
                assert_near(k.v[j], gmetal_k_at(i, nm), 1e-6 * gmetal_k_at(i, nm));
            }
        }
        assert_int_equal(gmetal_colors(gmetal_count(), &eta, &k), G_ERR_INVALID);
        gcolor_free(&eta);
        gcolor_free(&k);
        gcolormodel_destroy(m);
    }
}

/* ---- the measurement of the rules ---- */

static void lab_of(const double xyz[3], const double white[3], double lab[3])
{
    double f[3];
    for (int i = 0; i < 3; i++) {
        double t = xyz[i] / white[i];
        f[i] = t > 216.0 / 24389.0 ? cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
    }
    lab[0] = 116.0 * f[1] - 16.0;
    lab[1] = 500.0 * (f[0] - f[1]);
    lab[2] = 200.0 * (f[1] - f[2]);
}

static double delta_e(const double a[3], const double b[3], const double white[3])
{
    double la[3], lb[3];
    lab_of(a, white, la);
    lab_of(b, white, lb);
    return sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                (la[2] - lb[2]) * (la[2] - lb[2]));
}

enum { RULE_REFLECTANCE, RULE_POINT, RULE_MATCH_R0, RULE_LIBRARY, RULES };
static const char *const rule_names[RULES] = {"as a reflectance", "GCOLOR_UNITLESS", "matching R(0)", "gmetal_colors"};

/* n and k of metal i in out's model by a rule: each curve reduced as a reflectance; each curve's values at the model's
 * wavelengths (GCOLOR_UNITLESS in a model with wavelengths, as a reflectance otherwise); n so and k such that the
 * normal-incidence reflectance is the model's reduction of the spectral one (a reflectance); the library's. */
static void reduce(int rule, int metal, GColor *eta, GColor *k)
{
    if (rule == RULE_LIBRARY) {
        assert_int_equal(gmetal_colors(metal, eta, k), G_OK);
        return;
    }
    GSpectrumNM n_nm, k_nm, r_nm;
    for (int j = 0; j < GNM_COUNT; j++) {
        double n = gmetal_eta_at(metal, GNM_MIN + j), kk = gmetal_k_at(metal, GNM_MIN + j);
        n_nm.v[j] = (float)n;
        k_nm.v[j] = (float)kk;
        r_nm.v[j] = (float)goptics_fresnel_conductor(1.0, n, kk);
    }
    GColorRole role = rule == RULE_REFLECTANCE ? GCOLOR_REFLECTANCE : GCOLOR_UNITLESS;
    assert_int_equal(gcolor_from_nm(eta, &n_nm, role), G_OK);
    assert_int_equal(gcolor_from_nm(k, &k_nm, role), G_OK);
    if (rule != RULE_MATCH_R0)
        return;
    assert_int_equal(gcolor_from_nm(k, &r_nm, GCOLOR_REFLECTANCE), G_OK); /* k holds R(0) for a moment */
    for (int s = 0; s < eta->model->nvalues; s++) {
        double n = eta->v[s], r = gfmin(gfmax(k->v[s], 0.0), 0.999);
        double k2 = (r * (n + 1) * (n + 1) - (n - 1) * (n - 1)) / (1.0 - r);
        k->v[s] = (float)sqrt(gfmax(k2, 0.0));
    }
}

/* Mean delta E over 19 angles (0..85 every 5 degrees, and 89) of metal i's Fresnel colour by a rule in model m. */
static double rule_error(const GColorModel *m, int rule, int metal, const double white[3])
{
    GColor eta, k, f;
    assert_int_equal(gcolor_alloc(&eta, m), G_OK);
    assert_int_equal(gcolor_alloc(&k, m), G_OK);
    assert_int_equal(gcolor_alloc(&f, m), G_OK);
    reduce(rule, metal, &eta, &k);
    double sum = 0.0;
    int count = 0;
    for (int a = 0; a <= 90; a += 5) {
        double c = cos((a == 90 ? 89 : a) * M_PI / 180.0);
        GSpectrumNM ref;
        for (int j = 0; j < GNM_COUNT; j++)
            ref.v[j] = (float)goptics_fresnel_conductor(c, gmetal_eta_at(metal, GNM_MIN + j),
                                                        gmetal_k_at(metal, GNM_MIN + j));
        double want[3], got[3];
        gcie_nm_to_xyz(&ref, GCOLOR_REFLECTANCE, want);
        assert_int_equal(gmaterial_fresnel_conductor(&f, c, &eta, &k), G_OK);
        assert_int_equal(gcolor_to_xyz(&f, GCOLOR_REFLECTANCE, got), G_OK);
        sum += delta_e(want, got, white);
        count++;
    }
    gcolor_free(&eta);
    gcolor_free(&k);
    gcolor_free(&f);
    return sum / count;
}

/* The library's reduction (gmetal_colors) is the best of the candidates for gold, copper and silver together, in rgb
 * and spectrum9; in spectrum at 5 nm every rule is within 0.05 of it. */
static void test_rules(void **state)
{
    (void)state;
    assert_int_equal(generic_register_builtins(NULL), G_OK);
    GSpectrumNM one;
    for (int j = 0; j < GNM_COUNT; j++)
        one.v[j] = 1.0f;
    double white[3];
    gcie_nm_to_xyz(&one, GCOLOR_REFLECTANCE, white);
    const char *models[] = {"rgb", "spectrum9", "spectrum"};
    const char *metals[] = {"Au", "Cu", "Ag", "Al", "CuZn", "Cr", "Fe", "Ni", "Pt", "Ti", "W", "TiN"};
    const int nmetals = sizeof metals / sizeof metals[0], assessed = 3;
    print_message("mean CIELAB delta E 1976 of a smooth conductor's reflectance over 19 angles, against 1 nm:\n");
    for (int mi = 0; mi < 3; mi++) {
        GColorModel *m;
        GError err;
        assert_int_equal(gcolormodel_create(models[mi], NULL, &m, &err), G_OK);
        double total[RULES] = {0};
        for (int r = 0; r < RULES; r++) {
            char line[512];
            int len = snprintf(line, sizeof line, "  %-9s %-19s", models[mi], rule_names[r]);
            for (int i = 0; i < nmetals; i++) {
                double e = rule_error(m, r, gmetal_find(metals[i]), white);
                if (i < assessed)
                    total[r] += e;
                len += snprintf(line + len, sizeof line - len, " %s %.2f", metals[i], e);
            }
            print_message("%s\n", line);
        }
        for (int r = 0; r < RULES; r++)
            assert_true(total[RULE_LIBRARY] <= total[r] + 1e-9);
        if (mi == 2)
            for (int r = 0; r < RULES; r++)
                assert_true(total[r] / assessed < total[RULE_LIBRARY] / assessed + 0.05);
        gcolormodel_destroy(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_at_wavelengths),
        cmocka_unit_test(test_rules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
