/* test_fluorescent.c - the parametric re-radiation matrix, the normalised Blinn distribution, and the
 * fluorescent-phong and fluorescent-varnish materials: energy (white furnace, albedo <= 1, energy out <= in
 * plus what the matrix itself returns), reciprocity, the limits that reduce them to a Lambertian, the same
 * code in the rgb, spectrum9, spectrum and bispectral models, parameter checks and allocation failures.
 * The measured matrices of ../shared/data/bispectral are used when present (skipped otherwise). */
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
#include "generic/reader.h"
#include "test_util.h"

#define DEG (M_PI / 180.0)

/* Reads a shared BFC file, or skips the test when the data is not there. */
static void load_bfc(const char *name, GBfcData *d)
{
    char path[1024];
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/../shared/data/bispectral/%s", src ? src : ".", name);
    if (access(path, R_OK) != 0)
        snprintf(path, sizeof path, "/work/shared/data/bispectral/%s", name);
    if (access(path, R_OK) != 0) {
        print_message("%s not found: skipped\n", name);
        skip();
    }
    GError err;
    if (gbfc_read(path, d, &err) != G_OK)
        fail_msg("%s", err.message);
}

static GColorModel *model(const char *name)
{
    GColorModel *m;
    GError err;
    if (gcolormodel_create(name, NULL, &m, &err) != G_OK)
        fail_msg("%s", err.message);
    return m;
}

static GReradiation default_matrix(void)
{
    GFluorBands b;
    gfluor_bands_default(&b);
    GReradiation r;
    GError err;
    assert_int_equal(gfluor_matrix_create(&b, 380, 10, 41, &r, &err), G_OK);
    return r;
}

/* ---- the parametric matrix ---- */

static void test_matrix_energy(void **state)
{
    (void)state;
    GFluorBands b;
    gfluor_bands_default(&b);
    GReradiation r;
    GError err;
    assert_int_equal(gfluor_matrix_create(&b, 380, 5, 81, &r, &err), G_OK);
    for (int i = 0; i < r.n_in; i++) {
        double li = 380 + 5 * i, d = fabs(li - b.absorb_peak) / b.absorb_width;
        double a = b.absorb_max * exp(-0.5 * pow(d, b.absorb_shape));
        assert_near(r.data[i * r.n_in + i], b.reflectance * (1 - a), 1e-6);
        /* emission at longer wavelengths only; the column sum is reflectance (1 - a) + a Q <li / lo> */
        double sum = 0, photons = 0;
        for (int o = 0; o < r.n_out; o++) {
            double v = r.data[o * r.n_in + i];
            assert_true(v >= 0);
            if (o < i)
                assert_true(v == 0);
            sum += v;
            if (o > i)
                photons += v * (380 + 5 * o) / li;
        }
        assert_true(sum <= 1.0 + 1e-6);
        if (i < r.n_in - 1) /* photons re-emitted = quantum yield * photons absorbed */
            assert_near(photons, a * b.quantum_yield, 1e-5);
    }
    assert_true(gfluor_matrix_max_column_sum(&r, 380, 780) <= 1.0 + 1e-6);
    gfluor_matrix_free(&r);
    gfluor_matrix_free(&r); /* cleared: a no-op */
}

static void test_matrix_emission_peak(void **state)
{
    (void)state;
    GReradiation r = default_matrix();
    /* the response to blue light at 450 nm peaks near absorb_peak + stokes_shift = 605 nm */
    int i = (450 - 380) / 10, best = 0;
    for (int o = 0; o < r.n_out; o++)
        if (r.data[o * r.n_in + i] > r.data[best * r.n_in + i] && o != i)
            best = o;
    assert_near(380 + 10 * best, 605, 10);
    gfluor_matrix_free(&r);
}

static void test_matrix_bad_params(void **state)
{
    (void)state;
    GFluorBands b;
    GReradiation r;
    GError err;
    struct { double *field; double value; const char *name; } cases[] = {
        {&b.quantum_yield, 1.5, "quantum_yield"}, {&b.absorb_width, 0.0, "absorb_width"},
        {&b.absorb_max, NAN, "absorb_max"},       {&b.reflectance, -0.1, "reflectance"},
        {&b.stokes_shift, -5, "stokes_shift"},    {&b.absorb_shape, 0.5, "absorb_shape"},
        {&b.emit_width, INFINITY, "emit_width"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        gfluor_bands_default(&b);
        *cases[k].field = cases[k].value;
        assert_int_equal(gfluor_matrix_create(&b, 380, 10, 41, &r, &err), G_ERR_INVALID);
        assert_non_null(strstr(err.message, cases[k].name));
        assert_null(r.data);
    }
    gfluor_bands_default(&b);
    assert_int_equal(gfluor_matrix_create(&b, 380, 0, 41, &r, &err), G_ERR_INVALID);
    assert_int_equal(gfluor_matrix_create(&b, 380, 10, 0, &r, &err), G_ERR_INVALID);
}

static void test_matrix_diagonal(void **state)
{
    (void)state;
    GBfcData d;
    load_bfc("HERPIORA.BFC", &d);
    GReradiation diag;
    GError err;
    assert_int_equal(gfluor_matrix_diagonal(&d.rerad, &diag, &err), G_OK);
    int negatives = 0;
    for (int o = 0; o < diag.n_out; o++)
        for (int i = 0; i < diag.n_in; i++) {
            float src = d.rerad.data[o * d.rerad.n_in + i], v = diag.data[o * diag.n_in + i];
            double lo = diag.out_min + o * diag.out_step, li = diag.in_min + i * diag.in_step;
            negatives += src < 0;
            if (fabs(lo - li) < 1e-9)
                assert_near(v, src > 0 ? src : 0, 0);
            else
                assert_true(v == 0.0f);
        }
    assert_true(negatives > 0); /* the measured file does carry negative noise */
    GSpectrumNM nm;
    assert_int_equal(gfluor_matrix_diagonal_nm(&d.rerad, &nm, &err), G_OK);
    /* at 600 nm (a sample) the diagonal entry, between samples linear */
    int o600 = (600 - 380) / 10, i600 = (600 - 300) / 10, i610 = i600 + 1;
    assert_near(nm.v[600 - GNM_MIN], d.rerad.data[o600 * 49 + i600], 1e-6);
    double mid = 0.5 * (d.rerad.data[o600 * 49 + i600] + d.rerad.data[(o600 + 1) * 49 + i610]);
    assert_near(nm.v[605 - GNM_MIN], mid, 1e-6);
    gfluor_matrix_free(&diag);
    gbfc_free(&d);
}

/* ---- Blinn ---- */

static void test_blinn_normalised(void **state)
{
    (void)state;
    const double ms[] = {0, 1, 5, 15.336, 100, 1000, 10000};
    for (size_t k = 0; k < sizeof ms / sizeof ms[0]; k++) {
        /* int D(h) (h.n) dw = 2 pi int D cos sin dtheta; Simpson in u = 1 - cos theta, crowded near 0 */
        const int n = 20000;
        double s = 0;
        for (int j = 0; j <= n; j++) {
            double t = (double)j / n, u = t * t * t, du = 3 * t * t / n; /* cos theta = 1 - u */
            double c = 1 - u, f = gfluor_blinn_d(ms[k], c) * c * du;
            s += f * (j == 0 || j == n ? 1 : (j & 1) ? 4 : 2);
        }
        assert_near(2 * M_PI * s / 3, 1.0, 1e-3);
    }
    assert_true(gfluor_blinn_d(10, -0.1) == 0.0);
}

static void test_blinn_slope(void **state)
{
    (void)state;
    assert_near(gfluor_blinn_mean_slope(0), 45.0, 1e-6);
    double m = gfluor_blinn_exponent(17.0);
    assert_near(gfluor_blinn_mean_slope(m), 17.0, 1e-6);
    assert_near(m, 15.34, 0.01);
    /* large m: the tilt is Rayleigh distributed with sigma^2 = 1 / (m + 1), mean sigma sqrt(pi / 2) */
    assert_near(gfluor_blinn_mean_slope(2000) * DEG, sqrt(M_PI / (2 * 2001.0)), 1e-3 * sqrt(M_PI / 4002.0) * 5);
    assert_true(isnan(gfluor_blinn_exponent(45.0)));
    assert_true(isnan(gfluor_blinn_exponent(0.0)));
}

/* ---- materials ---- */

typedef struct Hemi {
    GScratch *s;
    GSurfPoint sp;
} Hemi;

static void hemi_init(Hemi *h, const GMaterial *m)
{
    h->s = gscratch_create(0);
    gsurfpoint_init(&h->sp, m->model, h->s);
    h->sp.geometric_normal = gvec3(0, 0, 1);
    h->sp.material = m;
}

static GVec3 dir(double theta, double phi)
{
    return gvec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}

/* Directional albedo per value of the model for light from theta_i: the integral of reflection(in, 1, o)
 * cos_o over the hemisphere divided by cos_i, into alb (nvalues doubles), by an n x n midpoint rule in
 * (cos^2 theta, phi) (fine enough for the varnish's facets; not for narrow Phong lobes). */
static void albedo(const GMaterial *m, double theta_i, const GColor *light, int n, double *alb)
{
    Hemi h;
    hemi_init(&h, m);
    const GColorModel *md = m->model;
    GColor r;
    assert_int_equal(gcolor_scratch(&r, md, h.s), G_OK);
    for (int k = 0; k < md->nvalues; k++)
        alb[k] = 0;
    GVec3 in = dir(theta_i, M_PI);
    const int nt = n, np = n;
    for (int a = 0; a < nt; a++) {
        double t = (a + 0.5) / nt, ct = sqrt(t); /* cos^2 uniform: dw cos = pi dt dphi / ... */
        double st = sqrt(1 - t);
        for (int b = 0; b < np; b++) {
            double phi = 2 * M_PI * (b + 0.5) / np;
            GVec3 o = gvec3(st * cos(phi), st * sin(phi), ct);
            assert_int_equal(gmaterial_reflection(m, &h.sp, in, light, o, &r), G_OK);
            /* cos_o dw = 0.5 d(cos^2) dphi */
            double w = 0.5 * (1.0 / nt) * (2 * M_PI / np) / cos(theta_i);
            for (int k = 0; k < md->nvalues; k++)
                alb[k] += r.v[k] * w;
        }
    }
    gscratch_destroy(h.s);
}

static void flat_light(const GColorModel *m, float *store, size_t nfloats, GColor *c)
{
    assert_int_equal(gcolor_wrap(c, m, store, nfloats), G_OK);
    assert_int_equal(gcolor_fill(c, 1.0), G_OK);
}

static void test_varnish_white_furnace(void **state)
{
    (void)state;
    /* over a white non-fluorescent base (identity matrix) nothing is absorbed: albedo 1 at every angle */
    GColorModel *md = model("bispectral");
    float *ident = calloc(41 * 41, sizeof(float));
    for (int k = 0; k < 41; k++)
        ident[k * 41 + k] = 1.0f;
    GReradiation r = {380, 10, 41, 380, 10, 41, ident};
    GMaterial *m;
    GError err;
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    assert_int_equal(gfluor_varnish_create(md, &r, &p, &m, &err), G_OK);
    float store[41 * 41];
    GColor light;
    flat_light(md, store, tu_floats(store), &light);
    double alb[41];
    for (int deg = 0; deg <= 80; deg += 20) {
        albedo(m, deg * DEG, &light, 160, alb);
        for (int k = 0; k < 41; k++)
            assert_near(alb[k], 1.0, 2e-3);
    }
    gmaterial_unref(m);
    free(ident);
    gcolormodel_destroy(md);
}

static void diag_only_varnish(const GReradiation *src, const char *model_name)
{
    GColorModel *md = model(model_name);
    GReradiation diag;
    GError err;
    assert_int_equal(gfluor_matrix_diagonal(src, &diag, &err), G_OK);
    GMaterial *m;
    assert_int_equal(gfluor_varnish_create(md, &diag, NULL, &m, &err), G_OK);
    float store[41 * 41];
    GColor light;
    flat_light(md, store, tu_floats(store), &light);
    double alb[41], lo = 1, hi = 0;
    const int degs[] = {0, 30, 60, 75, 85, 89};
    for (int j = 0; j < 6; j++) {
        albedo(m, degs[j] * DEG, &light, 128, alb);
        for (int k = 0; k < md->nvalues; k++) {
            assert_true(alb[k] <= 1.0 + 2e-3);
            lo = fmin(lo, alb[k]);
            hi = fmax(hi, alb[k]);
        }
    }
    print_message("%s: diagonal-only varnish albedo in [%.4f, %.4f] over 0..89 degrees\n", model_name, lo, hi);
    /* reciprocity: f(i, o) = f(o, i) sample by sample */
    Hemi h;
    hemi_init(&h, m);
    GColor a, b;
    assert_int_equal(gcolor_scratch(&a, md, h.s), G_OK);
    assert_int_equal(gcolor_scratch(&b, md, h.s), G_OK);
    srand(5);
    for (int t = 0; t < 200; t++) {
        GVec3 i = dir(acos(0.02 + 0.98 * rand() / (double)RAND_MAX), 2 * M_PI * rand() / (double)RAND_MAX);
        GVec3 o = dir(acos(0.02 + 0.98 * rand() / (double)RAND_MAX), 2 * M_PI * rand() / (double)RAND_MAX);
        assert_int_equal(gmaterial_reflection(m, &h.sp, i, &light, o, &a), G_OK);
        assert_int_equal(gmaterial_reflection(m, &h.sp, o, &light, i, &b), G_OK);
        for (int k = 0; k < md->nvalues; k++) {
            double fa = a.v[k] / i.z, fb = b.v[k] / o.z;
            assert_near(fa, fb, 1e-5 * fmax(1.0, fabs(fa)));
        }
    }
    gscratch_destroy(h.s);
    gmaterial_unref(m);
    gfluor_matrix_free(&diag);
    gcolormodel_destroy(md);
}

static void test_varnish_diagonal_parametric(void **state)
{
    (void)state;
    GReradiation r = default_matrix();
    diag_only_varnish(&r, "bispectral");
    diag_only_varnish(&r, "rgb");
    gfluor_matrix_free(&r);
}

static void test_varnish_diagonal_measured(void **state)
{
    (void)state;
    GBfcData d;
    load_bfc("HERPIORA.BFC", &d);
    diag_only_varnish(&d.rerad, "bispectral");
    gbfc_free(&d);
}

/* The same material code in every model: with ior 1 the varnish is Lambertian with M, and fluorescent-phong
 * with ks = 0 too; under equal-energy light the bispectral result equals the folded one of the spectrum
 * model on the same grid. */
static void test_models_agree(void **state)
{
    (void)state;
    GReradiation r = default_matrix();
    const char *names[] = {"bispectral", "spectrum", "spectrum9", "rgb"};
    GColorModelOptions ten = {10, 380, 780, 0};
    float results[4][2][64];
    for (int k = 0; k < 4; k++) {
        GColorModel *md;
        GError err;
        assert_int_equal(gcolormodel_create(names[k], k == 1 ? &ten : NULL, &md, &err), G_OK);
        GFluorVarnishParams vp;
        gfluor_varnish_default(&vp);
        vp.ior = 1.0;
        GFluorPhongParams pp;
        gfluor_phong_default(&pp);
        pp.ks = 0.0;
        GMaterial *mats[2];
        assert_int_equal(gfluor_varnish_create(md, &r, &vp, &mats[0], &err), G_OK);
        assert_int_equal(gfluor_phong_create(md, &r, &pp, &mats[1], &err), G_OK);
        GColor fold, light, out;
        float fs[41 * 41], ls[41 * 41], os[41 * 41];
        assert_int_equal(gcolor_wrap(&fold, md, fs, tu_floats(fs)), G_OK);
        assert_int_equal(gcolor_from_reradiation(&fold, &r, &err), G_OK);
        assert_int_equal(fold.kind, k == 1 ? GCOLOR_VECTOR : GCOLOR_MATRIX); /* spectrum folds it */
        if (k == 3) { /* rgb: the reduced matrix; its response to white is outside the gamut in blue (about -0.06):
                       * 0, red on top; entries >= 0 */
            double white_rgb[3];
            assert_int_equal(gcolor_to_rgb(&fold, GCOLOR_REFLECTANCE, white_rgb), G_OK);
            for (int s = 0; s < 9; s++)
                assert_true(fold.v[s] >= 0.0f);
            assert_true(fabs(white_rgb[2]) < 1e-6);
            assert_true(white_rgb[0] > 4.0 * white_rgb[1]);
        }
        flat_light(md, ls, tu_floats(ls), &light);
        assert_int_equal(gcolor_wrap(&out, md, os, tu_floats(os)), G_OK);
        for (int j = 0; j < 2; j++) {
            Hemi h;
            hemi_init(&h, mats[j]);
            GVec3 in = dir(30 * DEG, 0), o = dir(50 * DEG, 2.0);
            assert_int_equal(gmaterial_reflection(mats[j], &h.sp, in, &light, o, &out), G_OK);
            assert_int_equal(out.kind, GCOLOR_VECTOR);
            assert_true(gcolor_is_finite(&out));
            GColor expect;
            float es[41 * 41];
            assert_int_equal(gcolor_wrap(&expect, md, es, tu_floats(es)), G_OK);
            assert_int_equal(gcolor_mul(&expect, &fold, &light), G_OK);
            for (int s = 0; s < md->nvalues; s++) {
                assert_near(out.v[s], expect.v[s] * cos(30 * DEG) / M_PI, 1e-5);
                results[k][j][s] = out.v[s];
            }
            gscratch_destroy(h.s);
            gmaterial_unref(mats[j]);
        }
        gcolormodel_destroy(md);
    }
    /* under flat light the bispectral result (matrix applied) and the spectrum model's (folded by
     * gcolor_from_reradiation through the 1 nm grid, whose hat-weighted resampling smooths the emission
     * peak a little) carry the same energy */
    double e_bi = 0, e_sp = 0, peak = 0;
    for (int s = 0; s < 41; s++) {
        e_bi += results[0][0][s];
        e_sp += results[1][0][s];
        peak = fmax(peak, results[0][0][s]);
    }
    for (int s = 0; s < 41; s++)
        assert_near(results[0][0][s], results[1][0][s], 0.05 * peak);
    assert_near(e_sp, e_bi, 5e-3 * e_bi);
    gfluor_matrix_free(&r);
}

static void test_varnish_measured_energy(void **state)
{
    (void)state;
    /* all four shared matrices: the reflected share of a white beam never exceeds what the matrix returns */
    const char *files[] = {"HERPIORA.BFC", "CIBA12.BFC", "POLGREE.BFC", "TEXTYELL.BFC"};
    GColorModel *md = model("bispectral");
    for (int f = 0; f < 4; f++) {
        GBfcData d;
        load_bfc(files[f], &d);
        GMaterial *m;
        GError err;
        assert_int_equal(gfluor_varnish_create(md, &d.rerad, NULL, &m, &err), G_OK);
        double cmax = gfluor_matrix_max_column_sum(&d.rerad, 380, 780);
        for (int k = 5; k < 41; k += 10) {
            float ls[41 * 41];
            GColor light;
            assert_int_equal(gcolor_wrap(&light, md, ls, tu_floats(ls)), G_OK);
            light.v[k] = 1.0f;
            double alb[41], total = 0;
            albedo(m, 40 * DEG, &light, 96, alb);
            for (int s = 0; s < 41; s++)
                total += alb[s];
            assert_true(total <= fmax(1.0, cmax) + 2e-3);
            assert_true(total > 0.05);
        }
        gmaterial_unref(m);
        gbfc_free(&d);
    }
    gcolormodel_destroy(md);
}

static void test_bad_params(void **state)
{
    (void)state;
    GColorModel *md = model("bispectral");
    GReradiation r = default_matrix();
    GMaterial *m = (GMaterial *)&m;
    GError err;
    GFluorVarnishParams vp;
    gfluor_varnish_default(&vp);
    vp.ior = 0.5;
    assert_int_equal(gfluor_varnish_create(md, &r, &vp, &m, &err), G_ERR_INVALID);
    assert_null(m);
    assert_non_null(strstr(err.message, "ior"));
    gfluor_varnish_default(&vp);
    vp.slope_deg = 50;
    assert_int_equal(gfluor_varnish_create(md, &r, &vp, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "slope"));
    vp.exponent = NAN;
    assert_int_equal(gfluor_varnish_create(md, &r, &vp, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "exponent"));
    GFluorPhongParams pp;
    gfluor_phong_default(&pp);
    pp.weight[1] = 0.9;
    assert_int_equal(gfluor_phong_create(md, &r, &pp, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "sum"));
    gfluor_phong_default(&pp);
    pp.ks = 1.0;
    assert_int_equal(gfluor_phong_create(md, &r, &pp, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "ks"));
    GReradiation broken = r;
    broken.data = NULL;
    assert_int_equal(gfluor_phong_create(md, &broken, NULL, &m, &err), G_ERR_INVALID);
    float nanv[4] = {0.5f, NAN, 0, 0.5f};
    GReradiation withnan = {380, 10, 2, 380, 10, 2, nanv};
    assert_int_equal(gfluor_varnish_create(md, &withnan, NULL, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "non-finite"));
    gfluor_matrix_free(&r);
    gcolormodel_destroy(md);
}

/* ---- the text format ---- */

static void test_text_format(void **state)
{
    (void)state;
    const char *text =
        "colormodel bispectral\n"
        "color orange reradiation { quantum_yield 0.65 }\n"
        "material a fluorescent-varnish { matrix orange ior 1.5 slope 17 }\n"
        "material b fluorescent-phong { matrix orange ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
        "material c fluorescent-varnish\n"
        "material d fluorescent-varnish { matrix rgb 0.5 0.5 0.5 exponent 40 }\n";
    GLibrary *lib;
    GError err;
    if (greader_load_string(text, "fluor.mat", NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    const GColorModel *md = glibrary_colormodel(lib);
    assert_string_equal(gcolormodel_name(md), "bispectral");
    GReradiation r = default_matrix();
    GMaterial *code[2];
    assert_int_equal(gfluor_varnish_create(md, &r, NULL, &code[0], &err), G_OK);
    assert_int_equal(gfluor_phong_create(md, &r, NULL, &code[1], &err), G_OK);
    GMaterial *text_m[3] = {glibrary_material(lib, "a"), glibrary_material(lib, "b"), glibrary_material(lib, "c")};
    for (int k = 0; k < 3; k++) {
        assert_non_null(text_m[k]);
        const GMaterial *ref = code[k == 1];
        Hemi h;
        hemi_init(&h, ref);
        float s1[41 * 41], s2[41 * 41], s3[41 * 41];
        GColor light, a, b;
        flat_light(md, s1, tu_floats(s1), &light);
        assert_int_equal(gcolor_wrap(&a, md, s2, tu_floats(s2)), G_OK);
        assert_int_equal(gcolor_wrap(&b, md, s3, tu_floats(s3)), G_OK);
        GVec3 in = dir(70 * DEG, 0), o = dir(70 * DEG, M_PI + 0.05);
        assert_int_equal(gmaterial_reflection(text_m[k], &h.sp, in, &light, o, &a), G_OK);
        assert_int_equal(gmaterial_reflection(ref, &h.sp, in, &light, o, &b), G_OK);
        for (int s = 0; s < 41; s++)
            assert_near(a.v[s], b.v[s], 1e-6 + 1e-5 * b.v[s]);
        gscratch_destroy(h.s);
    }
    /* a plain reflectance as the matrix: nothing shifts */
    GFluorLaserSplit sp;
    GScratch *sc = gscratch_create(0);
    assert_int_equal(gfluor_laser_split(glibrary_material(lib, "d"), sc, 600, 30, NULL, &sp, &err), G_OK);
    assert_near(sp.shifted, 0.0, 1e-6);
    assert_true(sp.kept > 0.3);
    gscratch_destroy(sc);
    gmaterial_unref(code[0]);
    gmaterial_unref(code[1]);
    gfluor_matrix_free(&r);
    glibrary_destroy(lib);

    const struct { const char *text, *msg; } bad[] = {
        {"material x fluorescent-varnish { ior 0.5 }", "fluor.mat:1:38"},
        {"material x fluorescent-varnish { gloss 3 }", "ior, slope, exponent"},
        {"material x fluorescent-phong { matrix line 532 }", "light"},
        {"material x fluorescent-phong { weights 0.5 0.5 0.5 }", "sum"},
        {"color q reradiation { quantum_yield 2 }", "quantum_yield"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        assert_int_not_equal(greader_load_string(bad[k].text, "fluor.mat", NULL, &lib, &err), G_OK);
        assert_null(lib);
        if (!strstr(err.message, bad[k].msg))
            fail_msg("'%s' gave '%s', expected it to mention '%s'", bad[k].text, err.message, bad[k].msg);
    }
}

/* ---- allocation failures ---- */

static void test_alloc_failures(void **state)
{
    (void)state;
    GColorModel *md = model("bispectral");
    GReradiation r = default_matrix();
    static TuAlloc alloc;
    for (int which = 0; which < 3; which++) {
        int ok = 0;
        for (long n = 0; n < 64 && !ok; n++) {
            alloc = (TuAlloc){.fail_call = n + 1, .fail_after = 1}; /* n calls succeed */
            tu_alloc_install(&alloc);
            GMaterial *m = NULL;
            GReradiation g = {0};
            GError err;
            int rc = which == 0   ? gfluor_varnish_create(md, &r, NULL, &m, &err)
                     : which == 1 ? gfluor_phong_create(md, &r, NULL, &m, &err)
                                  : gfluor_matrix_create(&(GFluorBands){470, 115, 8, 0.97, 20, 135, 0.65, 0.92},
                                                         380, 10, 41, &g, &err);
            gmem_set_allocator(NULL);
            if (rc == G_OK) {
                ok = 1;
                gmaterial_unref(m);
                gfluor_matrix_free(&g);
            } else {
                assert_int_equal(rc, G_ERR_NOMEM);
                assert_null(m);
                assert_null(g.data);
            }
        }
        assert_true(ok);
    }
    gfluor_matrix_free(&r);
    gcolormodel_destroy(md);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_matrix_energy),
        cmocka_unit_test(test_matrix_emission_peak),
        cmocka_unit_test(test_matrix_bad_params),
        cmocka_unit_test(test_matrix_diagonal),
        cmocka_unit_test(test_blinn_normalised),
        cmocka_unit_test(test_blinn_slope),
        cmocka_unit_test(test_varnish_white_furnace),
        cmocka_unit_test(test_varnish_diagonal_parametric),
        cmocka_unit_test(test_varnish_diagonal_measured),
        cmocka_unit_test(test_models_agree),
        cmocka_unit_test(test_varnish_measured_energy),
        cmocka_unit_test(test_bad_params),
        cmocka_unit_test(test_text_format),
        cmocka_unit_test(test_alloc_failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
