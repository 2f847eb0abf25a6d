/* test_colorparse.c - colour literals converted into every colour model: a monochromatic line keeps its energy
 * and its wavelength in 1, 5 and 10 nm models (and in spectrum9), its XYZ in rgb is the colour matching
 * function at its wavelength; tabulated spectra interpolate; blackbody and illuminants have Y = 1 as lights;
 * one named colour serves as reflectance and as light; a BFC matrix becomes a matrix in the bispectral model
 * and a folded reflectance elsewhere, with its physically impossible (anti-Stokes) and negative entries
 * removed, and cannot be a light. */
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
#include "generic/memory.h"
#include "generic/reader.h"

#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __LINE__)
static void near_(double a, double b, double tol, const char *what, int line)
{
    if (!(fabs(a - b) <= tol)) {
        print_error("line %d: %s = %.10g, expected %.10g within %g\n", line, what, a, b, tol);
        fail();
    }
}

static GLibrary *load_in(const char *model, double step, const char *text)
{
    if (!gregistry_find(GKIND_COLORMODEL, model))
        skip();
    GColorModelOptions mo = {.step_nm = step};
    GReaderOptions opt = {.colormodel = model, .colormodel_options = &mo};
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "c.mat", &opt, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return lib;
}

/* Energy (sum over the 1 nm grid) and centroid of a named colour read as a light. */
static void energy(GLibrary *lib, const char *name, double *e, double *centre)
{
    GColor c = {0};
    assert_int_equal(gcolor_alloc(&c, glibrary_colormodel(lib)), G_OK);
    GError err;
    assert_int_equal(glibrary_color(lib, name, GCOLOR_LIGHT, &c, &err), G_OK);
    GSpectrumNM s;
    assert_int_equal(gcolor_to_nm(&c, GCOLOR_LIGHT, &s), G_OK);
    double sum = 0, moment = 0;
    for (int i = 0; i < GNM_COUNT; i++) {
        sum += s.v[i];
        moment += s.v[i] * (GNM_MIN + i);
    }
    *e = sum;
    *centre = sum != 0 ? moment / sum : 0;
    gcolor_free(&c);
}

static void test_line_energy_in_spectral_models(void **state)
{
    (void)state;
    static const double steps[] = {1, 5, 10};
    for (int k = 0; k < 3; k++) {
        GLibrary *lib = load_in("spectrum", steps[k], "color laser line 532 2\ncolor off line 537.3 0.5\n");
        double e, c;
        energy(lib, "laser", &e, &c);
        assert_near(e, 2.0, 2e-3);
        assert_near(c, 532.0, 0.05);
        energy(lib, "off", &e, &c);
        assert_near(e, 0.5, 1e-3);
        assert_near(c, 537.3, 0.05);
        glibrary_destroy(lib);
    }
    GLibrary *lib = load_in("bispectral", 0, "color laser line 532 2\n");
    double e, c;
    energy(lib, "laser", &e, &c);
    assert_near(e, 2.0, 2e-3);
    assert_near(c, 532.0, 0.05);
    glibrary_destroy(lib);
    /* nine samples 50 nm apart keep the line's colour and luminance instead of its radiant power
     * (tests/test_spectrum9.c): the centre of their spline moves by 6.4 nm */
    lib = load_in("spectrum9", 0, "color laser line 532 2\n");
    energy(lib, "laser", &e, &c);
    assert_near(c, 532.0, 10.0);
    glibrary_destroy(lib);
}

static void test_line_in_rgb_is_the_cmf(void **state)
{
    (void)state;
    GLibrary *lib = load_in("rgb", 0, "color laser line 532 2\ncolor e illuminant E\n");
    const GColorModel *m = glibrary_colormodel(lib);
    float v[9], ve[9]; /* rgb's capacity: a value may be a 3 x 3 re-radiation matrix */
    GColor c, ce;
    assert_int_equal(gcolor_wrap(&c, m, v, sizeof v / sizeof v[0]), G_OK);
    assert_int_equal(gcolor_wrap(&ce, m, ve, sizeof ve / sizeof ve[0]), G_OK);
    GError err;
    assert_int_equal(glibrary_color(lib, "laser", GCOLOR_LIGHT, &c, &err), G_OK);
    double xyz[3], cmf[3], sum_y = 0;
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
    gcie_cmf(532.0, cmf);
    for (int i = 0; i < GNM_COUNT; i++) {
        double t[3];
        gcie_cmf(GNM_MIN + i, t);
        sum_y += t[1];
    }
    for (int k = 0; k < 3; k++)
        assert_near(xyz[k], 2.0 * cmf[k] / sum_y, 2e-5);
    /* a 532 nm laser is far outside the sRGB gamut: red goes negative */
    assert_true(v[0] < 0.0f && v[1] > 0.0f);
    /* equal energy has Y = 1 */
    assert_int_equal(glibrary_color(lib, "e", GCOLOR_LIGHT, &ce, &err), G_OK);
    assert_int_equal(gcolor_to_xyz(&ce, GCOLOR_LIGHT, xyz), G_OK);
    assert_near(xyz[1], 1.0, 1e-4);
    glibrary_destroy(lib);
}

static void test_lights_have_unit_luminance(void **state)
{
    (void)state;
    static const char *const models[] = {"rgb", "spectrum", "spectrum9", "bispectral"};
    for (int k = 0; k < 4; k++) {
        if (!gregistry_find(GKIND_COLORMODEL, models[k]))
            continue;
        GLibrary *lib = load_in(models[k], 0, "color a blackbody 3000\ncolor b blackbody 9000\n"
                                              "color c illuminant A\ncolor d illuminant D65\ncolor w rgb 1 1 1\n");
        const GColorModel *m = glibrary_colormodel(lib);
        GColor c = {0};
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        GError err;
        const char *names[] = {"a", "b", "c", "d", "w"};
        for (int i = 0; i < 5; i++) {
            double xyz[3];
            assert_int_equal(glibrary_color(lib, names[i], GCOLOR_LIGHT, &c, &err), G_OK);
            assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
            assert_near(xyz[1], 1.0, m->nsamples == 9 ? 0.03 : 5e-3);
        }
        /* rgb 1 1 1 as a light is D65: the chromaticity of D65 (0.3127, 0.3290) */
        double xyz[3];
        assert_int_equal(glibrary_color(lib, "w", GCOLOR_LIGHT, &c, &err), G_OK);
        assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
        assert_near(xyz[0] / (xyz[0] + xyz[1] + xyz[2]), 0.3127, 3e-3);
        assert_near(xyz[1] / (xyz[0] + xyz[1] + xyz[2]), 0.3290, 3e-3);
        /* and as a reflectance it is a perfect white: flat 1 */
        assert_int_equal(glibrary_color(lib, "w", GCOLOR_REFLECTANCE, &c, &err), G_OK);
        GSpectrumNM s;
        assert_int_equal(gcolor_to_nm(&c, GCOLOR_REFLECTANCE, &s), G_OK);
        assert_near(s.v[550 - GNM_MIN], 1.0, 0.05);
        gcolor_free(&c);
        glibrary_destroy(lib);
    }
}

static void test_spectrum_literal_in_5nm(void **state)
{
    (void)state;
    GLibrary *lib = load_in("spectrum", 5, "color s scale 0.5 spectrum { 400 0.2 600 0.6 }\n");
    GColor c = {0};
    assert_int_equal(gcolor_alloc(&c, glibrary_colormodel(lib)), G_OK);
    GError err;
    assert_int_equal(glibrary_color(lib, "s", GCOLOR_REFLECTANCE, &c, &err), G_OK);
    GSpectrumNM s;
    assert_int_equal(gcolor_to_nm(&c, GCOLOR_REFLECTANCE, &s), G_OK);
    assert_near(s.v[500 - GNM_MIN], 0.5 * 0.4, 1e-5);
    assert_near(s.v[450 - GNM_MIN], 0.5 * 0.3, 1e-5);
    assert_near(s.v[390 - GNM_MIN], 0.5 * 0.2, 1e-5);
    assert_near(s.v[700 - GNM_MIN], 0.5 * 0.6, 1e-5);
    gcolor_free(&c);
    glibrary_destroy(lib);
}

/* A matrix with an anti-Stokes entry (emission 400 from excitation 410) and negative noise. */
static const char noisy_bfc[] = "VEC_01\t3\nBFC-450 Matrix File\n;n.BFC\n;noisy\n;\n;\n;\n;\n;\n;\n"
                                "400 420 10 3 400 10\nr:c: 400 410 420\n"
                                "400 0.5 0.3 -0.01\n410 0.1 0.4 0.0\n420 0.2 -0.02 0.3\nEOD\n";

static void test_bfc_literal(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/test_colorparse_noisy.BFC", build ? build : "/tmp");
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(noisy_bfc, f);
    fclose(f);
    char text[4300];
    snprintf(text, sizeof text, "color m bfc \"%s\"\n", path);
    /* the expected matrix: only emission >= excitation, negatives clipped */
    float clean[9] = {0.5f, 0, 0, 0.1f, 0.4f, 0, 0.2f, 0, 0.3f};
    GReradiation r = {400, 10, 3, 400, 10, 3, clean};
    static const char *const models[] = {"bispectral", "rgb", "spectrum"};
    for (int k = 0; k < 3; k++) {
        if (!gregistry_find(GKIND_COLORMODEL, models[k]))
            continue;
        GLibrary *lib = load_in(models[k], 0, text);
        const GColorModel *m = glibrary_colormodel(lib);
        GColor got = {0}, want = {0};
        assert_int_equal(gcolor_alloc(&got, m), G_OK);
        assert_int_equal(gcolor_alloc(&want, m), G_OK);
        GError err;
        assert_int_equal(glibrary_color(lib, "m", GCOLOR_REFLECTANCE, &got, &err), G_OK);
        assert_int_equal(gcolor_from_reradiation(&want, &r, &err), G_OK);
        assert_int_equal(got.kind, want.kind);
        if (strcmp(models[k], "bispectral") == 0)
            assert_int_equal(got.kind, GCOLOR_MATRIX);
        int n = got.kind == GCOLOR_MATRIX ? m->capacity : m->nvalues;
        for (int i = 0; i < n; i++)
            assert_near(got.v[i], want.v[i], 1e-6);
        /* a matrix is no light */
        assert_int_equal(glibrary_color(lib, "m", GCOLOR_LIGHT, &got, &err), G_ERR_INVALID);
        assert_non_null(strstr(err.message, "cannot be a light"));
        gcolor_free(&got);
        gcolor_free(&want);
        glibrary_destroy(lib);
    }
    unlink(path);
}

static void test_spec_copy(void **state)
{
    (void)state;
    GColorSpec *s = gcolorspec_create(), *copy = NULL;
    assert_non_null(s);
    float *data = gmem_calloc(4, sizeof(float));
    data[3] = 0.25f;
    const GReradiation m = {400, 10, 2, 400, 10, 2, NULL};
    GError err;
    const size_t used = gmem_budget_used();
    assert_int_equal(gcolorspec_own_matrix(s, &m, data, "a test matrix", &err), G_OK);
    assert_int_equal(s->form, GCOLORSPEC_RERADIATION);
    assert_ptr_equal(s->rerad.data, data);
    assert_int_equal(gmem_budget_used(), used + 4 * sizeof(float)); /* held while the spec lives */
    assert_int_equal(gcolorspec_copy(s, &copy, &err), G_OK);
    assert_int_equal(gmem_budget_used(), used + 8 * sizeof(float));
    assert_ptr_not_equal(copy->owned_data, s->owned_data);
    assert_ptr_equal(copy->rerad.data, copy->owned_data);
    assert_true(copy->owned_data[3] == 0.25f);
    gcolorspec_destroy(s);
    assert_true(copy->rerad.data[3] == 0.25f);
    gcolorspec_destroy(copy);
    assert_int_equal(gmem_budget_used(), used);
    gcolorspec_destroy(NULL);
    /* a matrix over the budget is refused, freed, and the spec left as it was */
    GColorSpec *t = gcolorspec_create();
    gmem_budget_set_limit(used + (1u << 20) - 1); /* one byte short */
    float *big = gmem_calloc(1u << 18, sizeof(float)); /* 1 MiB */
    const GReradiation mb = {400, 1, 512, 400, 1, 512, NULL};
    assert_int_equal(gcolorspec_own_matrix(t, &mb, big, "a 512x512 matrix", &err), G_ERR_NOMEM);
    assert_non_null(strstr(err.message, "a 512x512 matrix"));
    assert_null(t->owned_data);
    assert_int_equal(gmem_budget_used(), used);
    gmem_budget_set_limit(0);
    gcolorspec_destroy(t);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_line_energy_in_spectral_models),
        cmocka_unit_test(test_line_in_rgb_is_the_cmf),
        cmocka_unit_test(test_lights_have_unit_luminance),
        cmocka_unit_test(test_spectrum_literal_in_5nm),
        cmocka_unit_test(test_bfc_literal),
        cmocka_unit_test(test_spec_copy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
