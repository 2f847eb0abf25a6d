/* test_glasses.c - the named glasses of the dispersion kit: each glass's index at 450, 550 and 650 nm against the
 * published formula written out here (the SCHOTT catalogue's, Malitson's and Peter's Sellmeier forms, Daimon and
 * Masumura's four-term water), the catalogue's n_d, lookup by name, and the text format: `glass NAME`, `index glass
 * NAME`, an unknown name refused at file:line:col with the known names listed. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "material_fixture.h"
#include "generic/kit/dispersion.h"

/* n from a published Sellmeier formula: n^2 = 1 + sum b_i l^2 / (l^2 - c_i), l in um; squared: c_i given as
 * sqrt (Malitson, Peter). */
static double published(const double *b, const double *c, int terms, int squared, double nm)
{
    double l2 = nm * nm * 1e-6, n2 = 1.0;
    for (int i = 0; i < terms; i++)
        n2 += b[i] * l2 / (l2 - (squared ? c[i] * c[i] : c[i]));
    return sqrt(n2);
}

typedef struct Published {
    const char *name;
    double b[4], c[4];
    int terms, squared;
    double nd; /* the catalogue's n_d (0: none given) */
} Published;

static const Published table[] = {
    {"BK7", {1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}, 3, 0, 1.5168},
    {"BAF10", {1.5851495, 0.143559385, 1.08521269}, {0.00926681282, 0.0424489805, 105.613573}, 3, 0, 1.67003},
    {"F5", {1.3104463, 0.19603426, 0.96612977}, {0.00958633048, 0.0457627627, 115.011883}, 3, 0, 1.60342},
    {"F10", {1.62153902, 0.256287842, 1.64447552}, {0.0122241457, 0.0595736775, 147.468793}, 3, 0, 1.72828},
    {"F11", {1.73759695, 0.313747346, 1.89878101}, {0.013188707, 0.0623068142, 155.23629}, 3, 0, 1.78472},
    {"FK51A", {0.971247817, 0.216901417, 0.904651666}, {0.00472301995, 0.0153575612, 168.68133}, 3, 0, 1.48656},
    {"LASF9", {2.00029547, 0.298926886, 1.80691843}, {0.0121426017, 0.0538736236, 156.530829}, 3, 0, 1.85025},
    {"SF5", {1.46141885, 0.247713019, 0.949995832}, {0.0111826126, 0.0508594669, 112.041888}, 3, 0, 1.6727},
    {"SF10", {1.62153902, 0.256287842, 1.64447552}, {0.0122241457, 0.0595736775, 147.468793}, 3, 0, 1.72828},
    {"SF11", {1.73759695, 0.313747346, 1.89878101}, {0.013188707, 0.0623068142, 155.23629}, 3, 0, 1.78472},
    {"fused silica", {0.6961663, 0.4079426, 0.8974794}, {0.0684043, 0.1162414, 9.896161}, 3, 1, 1.4585},
    {"water", {5.684027565E-1, 1.726177391E-1, 2.086189578E-2, 1.130748688E-1},
     {5.101829712E-3, 1.821153936E-2, 2.620722293E-2, 1.069792721E1}, 4, 0, 0.0},
    {"diamond", {0.3306, 4.3356}, {0.1750, 0.1060}, 2, 1, 2.4175},
};

static void indices_match_the_sources(void **state)
{
    (void)state;
    assert_int_equal(gdispersion_glass_count(), (int)(sizeof table / sizeof table[0]));
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++) {
        const Published *p = &table[i];
        const GGlass *g = gdispersion_glass_find(p->name);
        assert_non_null(g);
        assert_int_equal(gdispersion_check(&g->formula, NULL), G_OK);
        /* water: three terms for Daimon's four, within the fit's 4e-6 */
        double tol = p->terms == 4 ? 5e-6 : 1e-12;
        const double nms[3] = {450, 550, 650};
        for (int k = 0; k < 3; k++) {
            double want = published(p->b, p->c, p->terms, p->squared, nms[k]);
            double got = gdispersion_index(&g->formula, nms[k]);
            if (fabs(got - want) > tol)
                fail_msg("%s at %g nm: %.9f, the source says %.9f", p->name, nms[k], got, want);
        }
        if (p->nd > 0) /* the catalogue's n_d (587.56 nm), to its printed digits */
            assert_near(gdispersion_index(&g->formula, 587.56), p->nd, 2e-4);
        print_message("%-13s n(450) %.6f n(550) %.6f n(650) %.6f\n", g->name, gdispersion_index(&g->formula, 450),
                      gdispersion_index(&g->formula, 550), gdispersion_index(&g->formula, 650));
    }
    /* water over the whole visible range against the four-term formula */
    const Published *w = &table[11];
    const GGlass *water = gdispersion_glass_find("water");
    double worst = 0.0;
    for (int nm = 360; nm <= 830; nm++)
        worst = fmax(worst, fabs(gdispersion_index(&water->formula, nm) - published(w->b, w->c, 4, 0, nm)));
    print_message("water: three-term formula within %.2e of Daimon and Masumura's, 360..830 nm\n", worst);
    assert_true(worst < 5e-6);
}

static void lookup_by_name(void **state)
{
    (void)state;
    assert_ptr_equal(gdispersion_glass_find("bk7"), gdispersion_glass_find("BK7"));
    assert_ptr_equal(gdispersion_glass_find("fused_silica"), gdispersion_glass_find("Fused Silica"));
    assert_null(gdispersion_glass_find("BK"));
    assert_null(gdispersion_glass_find("BK77"));
    assert_null(gdispersion_glass_find(""));
    assert_null(gdispersion_glass_find(NULL));
    assert_null(gdispersion_glass_at(-1));
    assert_null(gdispersion_glass_at(gdispersion_glass_count()));
    char names[512], tiny[8];
    gdispersion_glass_names(names, sizeof names);
    assert_non_null(strstr(names, "BK7, BAF10"));
    assert_non_null(strstr(names, "diamond"));
    gdispersion_glass_names(tiny, sizeof tiny); /* cut, terminated */
    assert_int_equal(strlen(tiny), sizeof tiny - 1);
}

/* The index a material file gives, as the material's refraction_index in the model (rgb: n at 610, 550, 465). */
static double index_at_550(Fix *f, const char *text)
{
    GError err;
    GLibrary *lib;
    GReaderOptions ro = {.model = f->model};
    if (greader_load_string(text, "glass.mat", &ro, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    GColor n = new_color(f);
    assert_int_equal(gmaterial_refraction_index(glibrary_material(lib, "g"), NULL, &n), G_OK);
    double v = n.v[1]; /* rgb: n(550 nm) as it is */
    if (f->model->nsamples > 0) {
        int k = (int)lround((550.0 - f->model->lambda_min) / f->model->lambda_step);
        assert_near(f->model->lambda_min + k * f->model->lambda_step, 550.0, 1e-9);
        v = n.v[k];
    }
    glibrary_destroy(lib);
    return v;
}

static void text_format(void **state)
{
    Fix f;
    fix_open(&f, state);
    const GGlass *sf11 = gdispersion_glass_find("SF11");
    double want = gdispersion_index(&sf11->formula, 550);
    assert_near(index_at_550(&f, "material g dielectric { glass SF11 }"), want, 1e-4);
    assert_near(index_at_550(&f, "material g dielectric { index glass sf11 }"), want, 1e-4);
    assert_near(index_at_550(&f, "material g dielectric { index glass \"fused silica\" }"),
                gdispersion_index(&gdispersion_glass_find("fused silica")->formula, 550), 1e-4);

    static const struct {
        const char *text, *want;
    } bad[] = {
        {"material g dielectric {\n  glass BK8 }", "bad.mat:2:9: unknown glass 'BK8' (known: BK7, BAF10, F5"},
        {"material g dielectric { index glass flint }", "bad.mat:1:37: unknown glass 'flint' (known: BK7,"},
        {"material g thindielectric { glass 7 }", "bad.mat:1:35: expected a glass name"},
        {"material g dielectric { index 0 }", "bad.mat:1:31: value 0 is out of range [0.01, 100]"},
        {"material g dielectric { index -1.5 }", "bad.mat:1:31: value -1.5 is out of range [0.01, 100]"},
        {"material g thindielectric { index 0.001 }", "bad.mat:1:35: value 0.001 is out of range [0.01, 100]"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GError err;
        GLibrary *lib = NULL;
        GReaderOptions ro = {.model = f.model};
        assert_int_not_equal(greader_load_string(bad[i].text, "bad.mat", &ro, &lib, &err), G_OK);
        if (!strstr(err.message, bad[i].want))
            fail_msg("'%s': '%s' lacks '%s'", bad[i].text, err.message, bad[i].want);
        assert_null(lib);
    }
    fix_close(&f);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(indices_match_the_sources),
        cmocka_unit_test(lookup_by_name),
        BOTH(text_format),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
