/* test_materials.c - the built-in materials: energy conservation by numeric integration, reciprocity, the
 * ideal-direction checks, emission sides and parameter checks (the dielectric: test_dielectric.c). Every case
 * runs in the rgb model and again in the "spectrum" model (skipped while that model is not registered). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "material_fixture.h"

/* ---- lambert ---- */

static void test_lambert_albedo(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor rho = grey(&f, 0.5), acc = new_color(&f);
    assert_int_equal(glambert_create(f.model, &rho, &m, &err), G_OK);
    const double angles[] = {0, 30, 60, 80};
    for (int k = 0; k < 4; k++) {
        albedo(&f, m, dir_at(angles[k] * DEG, 0.3), 200, 400, &acc);
        print_message("lambert rho 0.5, in %2.0f deg: albedo %.6f\n", angles[k], gcolor_brightness(&acc));
        assert_color_near(&acc, &rho, 1e-3);
    }
    /* light from below the surface, or a viewer below it, gets nothing */
    GColor one = grey(&f, 1.0), r = new_color(&f);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0, 0.6, -0.8), &one, gvec3(0, 0, 1), &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0, 0, 1), &one, gvec3(0, 0.6, -0.8), &r), G_OK);
    assert_black(&r);
    /* reflection = rho / pi cos(theta_in) illum, computed into the illum operand itself */
    GColor illum = rgb_color(&f, 2.0, 1.0, 0.5, GCOLOR_LIGHT), expect = new_color(&f);
    assert_int_equal(gcolor_mul(&expect, &rho, &illum), G_OK);
    assert_int_equal(gcolor_scale(&expect, &expect, 0.8 / M_PI), G_OK);
    assert_int_equal(gmaterial_reflection(m, &f.sp, gvec3(0.6, 0, 0.8), &illum, gvec3(0, 0, 1), &illum), G_OK);
    assert_color_near(&illum, &expect, 1e-6);
    /* diffuse, ambient, opaque */
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    assert_color_near(&r, &rho, 0);
    GColor amb = grey(&f, 0.25);
    assert_int_equal(gmaterial_ambient(m, &f.sp, &amb, &r), G_OK);
    GColor eighth = grey(&f, 0.125);
    assert_color_near(&r, &eighth, 1e-7);
    assert_int_equal(gmaterial_opaque(m, &f.sp), 1);
    GVec3 d;
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3(0, 0, -1), &d), 0);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- phong ---- */

static GMaterial *make_phong(Fix *f, double kd, double ks, double n, double mirror)
{
    GError err;
    GMaterial *m;
    GColor ckd = grey(f, kd), cks = grey(f, ks), cm = grey(f, mirror);
    GPhongParams p = {&ckd, &cks, n, mirror > 0 ? &cm : NULL};
    if (gphong_create(f->model, &p, &m, &err) != G_OK)
        fail_msg("gphong_create: %s", err.message);
    return m;
}

static void test_phong_albedo(void **state)
{
    Fix f;
    fix_open(&f, state);
    GColor acc = new_color(&f);
    const double ns[] = {1, 10, 100, 1000};
    const double angles[] = {0, 30, 60, 85};
    for (int a = 0; a < 4; a++) {
        GMaterial *m = make_phong(&f, 0.3, 0.6, ns[a], 0);
        for (int k = 0; k < 4; k++) {
            albedo(&f, m, dir_at(angles[k] * DEG, 1.1), ns[a] >= 1000 ? 400 : 200, 200, &acc);
            double lo = min_sample(&acc), hi = max_sample(&acc);
            print_message("phong kd 0.3 ks 0.6 n %4.0f, in %2.0f deg: albedo %.6f\n", ns[a], angles[k], hi);
            assert_true(hi <= 1.0);
            assert_true(hi <= 0.9 + 2e-3);
            assert_true(hi - lo < 1e-5); /* constant parameters give a constant result */
            if (angles[k] == 0)          /* the whole lobe is above the horizon: exactly kd + ks */
                assert_near(hi, 0.9, 2e-3);
        }
        gmaterial_unref(m);
    }
    /* a narrow lobe off the normal reflects ks cos(theta_r) (the projected lobe) */
    GMaterial *m = make_phong(&f, 0.0, 1.0, 1000, 0);
    albedo(&f, m, dir_at(30 * DEG, 0.0), 400, 200, &acc);
    print_message("phong ks 1 n 1000, in 30 deg: albedo %.6f (cos 30 = %.6f)\n", max_sample(&acc), cos(30 * DEG));
    assert_near(max_sample(&acc), cos(30 * DEG), 3e-3);
    gmaterial_unref(m);
    fix_close(&f);
}

/* f_r(in, out) = reflection(in, 1, out) / cos(theta_in) must equal f_r(out, in). */
static void check_reciprocity(Fix *f, const GMaterial *m)
{
    GColor one = grey(f, 1.0), a = new_color(f), b = new_color(f);
    uint64_t seed = 12345;
    int nonzero = 0;
    for (int k = 0; k < 500; k++) {
        double u[4];
        for (int i = 0; i < 4; i++) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            u[i] = (double)(seed >> 11) / 9007199254740992.0;
        }
        GVec3 in = dir_at(acos(0.02 + 0.97 * u[0]), 2 * M_PI * u[1]);
        GVec3 out = dir_at(acos(0.02 + 0.97 * u[2]), 2 * M_PI * u[3]);
        assert_int_equal(gmaterial_reflection(m, &f->sp, in, &one, out, &a), G_OK);
        assert_int_equal(gmaterial_reflection(m, &f->sp, out, &one, in, &b), G_OK);
        assert_int_equal(gcolor_scale(&a, &a, 1.0 / in.z), G_OK);
        assert_int_equal(gcolor_scale(&b, &b, 1.0 / out.z), G_OK);
        assert_color_near(&a, &b, 2e-5);
        nonzero += gcolor_brightness(&a) > 0.0;
    }
    assert_int_equal(nonzero, 500);
}

static void test_reciprocity(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor rho = rgb_color(&f, 0.8, 0.5, 0.2, GCOLOR_REFLECTANCE);
    assert_int_equal(glambert_create(f.model, &rho, &m, &err), G_OK);
    check_reciprocity(&f, m);
    gmaterial_unref(m);
    const double ns[] = {0, 3, 40};
    for (int i = 0; i < 3; i++) {
        m = make_phong(&f, 0.2, 0.7, ns[i], 0);
        check_reciprocity(&f, m);
        gmaterial_unref(m);
    }
    fix_close(&f);
}

static void test_phong_lobe_and_mirror(void **state)
{
    Fix f;
    fix_open(&f, state);
    GColor one = grey(&f, 1.0), r = new_color(&f);
    GVec3 in = dir_at(40 * DEG, 0.0), mir = dir_at(40 * DEG, M_PI), d;
    /* the lobe's peak value: (kd / pi + ks (n + 2) / (2 pi)) cos(theta_in) */
    GMaterial *m = make_phong(&f, 0.25, 0.5, 20, 0);
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3_neg(mir), &d), 0);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &one, mir, &r), G_OK);
    assert_near(max_sample(&r), (0.25 / M_PI + 0.5 * 22 / (2 * M_PI)) * cos(40 * DEG), 1e-5);
    /* 10 degrees off the mirror direction in the plane of incidence: cos^20(10 deg) */
    GVec3 off = dir_at(50 * DEG, M_PI);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &one, off, &r), G_OK);
    assert_near(max_sample(&r), (0.25 / M_PI + 0.5 * 22 / (2 * M_PI) * pow(cos(10 * DEG), 20)) * cos(40 * DEG),
                       1e-5);
    gmaterial_unref(m);
    /* with a mirror reflectance: a reflection ray, and the aligned pair returns mirror * illum */
    m = make_phong(&f, 0.25, 0.5, 20, 0.2);
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, gvec3_neg(in), &d), 1);
    assert_near(gvec3_dot(d, mir), 1.0, 1e-12);
    GColor illum = rgb_color(&f, 3.0, 2.0, 1.0, GCOLOR_LIGHT), expect = new_color(&f), cm = grey(&f, 0.2);
    assert_int_equal(gcolor_mul(&expect, &cm, &illum), G_OK);
    assert_int_equal(gmaterial_reflection(m, &f.sp, in, &illum, mir, &r), G_OK);
    assert_color_near(&r, &expect, 1e-6);
    /* ambient reflects the albedo kd + ks + mirror */
    assert_int_equal(gmaterial_ambient(m, &f.sp, &one, &r), G_OK);
    GColor sum = grey(&f, 0.95);
    assert_color_near(&r, &sum, 1e-6);
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    GColor kd = grey(&f, 0.25);
    assert_color_near(&r, &kd, 0);
    gmaterial_unref(m);
    fix_close(&f);
}

/* ---- mirror ---- */

static void test_mirror(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m;
    GColor R = rgb_color(&f, 0.9, 0.6, 0.3, GCOLOR_REFLECTANCE), illum = rgb_color(&f, 1.0, 2.0, 4.0, GCOLOR_LIGHT);
    GColor r = new_color(&f), expect = new_color(&f);
    assert_int_equal(gmirror_create(f.model, &R, &m, &err), G_OK);
    GColor Rm = new_color(&f), white = grey(&f, 1.0);
    assert_int_equal(gmaterial_ambient(m, &f.sp, &white, &Rm), G_OK); /* R itself */
    assert_int_equal(gcolor_mul(&expect, &Rm, &illum), G_OK);
    GVec3 view = gvec3_normalize(gvec3(0.3, -0.4, -0.7)), d;
    assert_int_equal(gmaterial_reflection_dir(m, &f.sp, view, &d), 1);
    assert_near(gvec3_length(d), 1.0, 1e-12);
    assert_near(d.z, -view.z, 1e-12);
    /* as the tracer calls it: in = the reflected ray, out = towards the viewer */
    assert_int_equal(gmaterial_reflection(m, &f.sp, d, &illum, gvec3_neg(view), &r), G_OK);
    assert_color_near(&r, &expect, 1e-6);
    /* a few degrees off: nothing */
    double theta = acos(d.z), phi = atan2(d.y, d.x);
    const double offs[] = {0.5, 2.0, 5.0};
    for (int k = 0; k < 3; k++) {
        assert_int_equal(gmaterial_reflection(m, &f.sp, dir_at(theta + offs[k] * DEG, phi), &illum,
                                              gvec3_neg(view), &r), G_OK);
        assert_black(&r);
        assert_int_equal(gmaterial_reflection(m, &f.sp, dir_at(theta, phi + offs[k] * DEG), &illum,
                                              gvec3_neg(view), &r), G_OK);
        assert_black(&r);
    }
    assert_int_equal(gmaterial_diffuse(m, &f.sp, &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_opaque(m, &f.sp), 1);
    gmaterial_unref(m);
    fix_close(&f);
}

static void test_emitter(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *one_side, *two_side;
    GColor L = rgb_color(&f, 5.0, 4.0, 3.0, GCOLOR_LIGHT), r = new_color(&f), one = grey(&f, 1.0);
    for (int i = 0; i < f.model->nvalues; i++)
        L.v[i] = fmaxf(L.v[i], 0.0f);
    assert_int_equal(gemitter_create(f.model, &L, 0, &one_side, &err), G_OK);
    assert_int_equal(gemitter_create(f.model, &L, 1, &two_side, &err), G_OK);
    GVec3 out = dir_at(50 * DEG, 2.0);
    /* seen from outside (the normal faces the viewer and is the outward normal) */
    f.sp.entering = 1;
    assert_int_equal(gmaterial_emission(one_side, &f.sp, out, &r), G_OK);
    assert_color_near(&r, &L, 0);
    assert_int_equal(gmaterial_emission(one_side, &f.sp, gvec3_neg(out), &r), G_OK);
    assert_black(&r);
    /* seen from inside: the normal faces inwards, so out along it is the back */
    f.sp.entering = 0;
    assert_int_equal(gmaterial_emission(one_side, &f.sp, out, &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_emission(two_side, &f.sp, out, &r), G_OK);
    assert_color_near(&r, &L, 0);
    /* no reflection, no diffuse colour */
    assert_int_equal(gmaterial_reflection(one_side, &f.sp, out, &one, gvec3(0, 0, 1), &r), G_OK);
    assert_black(&r);
    assert_int_equal(gmaterial_diffuse(one_side, &f.sp, &r), G_OK);
    assert_black(&r);
    gmaterial_unref(one_side);
    gmaterial_unref(two_side);
    fix_close(&f);
}

/* ---- parameter checks ---- */

static void expect_error_(int rc, GMaterial **m, const GError *err, const char *a, const char *b)
{
    assert_int_equal(rc, G_ERR_INVALID);
    assert_null(*m);
    *m = (GMaterial *)err; /* a non-NULL sentinel for the next call */
    print_message("refused: %s\n", err->message);
    if (!strstr(err->message, a) || (b && !strstr(err->message, b)))
        fail_msg("message '%s' should mention '%s' and '%s'", err->message, a, b ? b : "");
}

/* rc is evaluated before m is looked at */
#define expect_error(call, m, err, a, b)                                                                        \
    do {                                                                                                        \
        int rc_ = (call);                                                                                       \
        expect_error_(rc_, &(m), (err), (a), (b));                                                              \
    } while (0)

static void test_bad_parameters(void **state)
{
    Fix f;
    fix_open(&f, state);
    GError err;
    GMaterial *m = (GMaterial *)&f;
    GColor bad = grey(&f, 0.5), good = grey(&f, 0.4), big = grey(&f, 0.7);
    bad.v[1] = NAN;
    expect_error(glambert_create(f.model, &bad, &m, &err), m, &err, "reflectance", "nan");
    bad.v[1] = -0.25f;
    expect_error(gmirror_create(f.model, &bad, &m, &err), m, &err, "reflectance", "-0.25");
    expect_error(gemitter_create(f.model, &bad, 0, &m, &err), m, &err, "radiance", "-0.25");
    /* above 1 in every band: 1.5 in one band alone would be a fold of energy below 1 in the models without
     * matrices (material_params.h), accepted there */
    assert_int_equal(gcolor_fill(&bad, 1.5), G_OK);
    expect_error(glambert_create(f.model, &bad, &m, &err), m, &err, "reflectance", "1.5");
    expect_error(glambert_create(f.model, NULL, &m, &err), m, &err, "reflectance", "missing");

    GPhongParams pp = {&good, &good, -2.0, NULL};
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "exponent", "-2");
    pp.exponent = NAN;
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "exponent", "nan");
    pp.exponent = 10;
    pp.ks = &big; /* 0.4 + 0.7 */
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "kd + ks", "1.1");
    pp.ks = &good;
    pp.mirror = &good; /* 0.4 + 0.4 + 0.4 */
    expect_error(gphong_create(f.model, &pp, &m, &err), m, &err, "kd + ks + mirror", "1.2");

    double B[3] = {1.03961212, NAN, 1.01046945}, C[3] = {0.00600069867, 0.0200179144, 103.560653};
    GDielectricParams dp = {gdispersion_sellmeier(B, C), NULL, NULL};
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Sellmeier", "B2");
    B[1] = 0.231792344;
    C[2] = 0.36; /* a pole at 600 nm */
    dp.index = gdispersion_sellmeier(B, C);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Sellmeier", "nm");
    dp.index = gdispersion_constant(-1.5);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "index", "-1.5");
    dp.index = gdispersion_cauchy(1.5, INFINITY, 0);
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "Cauchy", "B");
    dp.index = gdispersion_constant(1.5);
    assert_int_equal(gcolor_fill(&bad, 0.5), G_OK);
    bad.v[1] = -1.0f;
    dp.absorption = &bad;
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "absorption", "-1");
    dp.absorption = NULL;
    dp.tint = &bad;
    expect_error(gdielectric_create(f.model, &dp, &m, &err), m, &err, "tint", "-1");
    fix_close(&f);
}

/* A matrix on the bispectral model's grid: `diag` on the diagonal and `shift` of each sample's light re-radiated
 * one sample up, so every excitation sample but the last sends out diag + shift. */
static void shift_matrix(GColorModel *m, float diag, float shift, float *data, GColor *out)
{
    int n = m->nsamples;
    memset(data, 0, (size_t)n * n * sizeof *data);
    for (int i = 0; i < n; i++) {
        data[i * n + i] = diag;
        if (i + 1 < n)
            data[(i + 1) * n + i] = shift; /* row: emission, column: excitation */
    }
    GReradiation r = {m->lambda_min, m->lambda_step, n, m->lambda_min, m->lambda_step, n, data};
    GError err;
    assert_int_equal(gcolor_alloc(out, m), G_OK);
    assert_int_equal(gcolor_from_reradiation(out, &r, &err), G_OK);
    assert_int_equal(out->kind, GCOLOR_MATRIX);
}

/* Re-radiation matrices are held to what they send out per excitation sample, their column sums (light moved to
 * other samples counts): alone as a parameter of lambert, mirror, phong or a dielectric's tint, and in phong's
 * kd + ks + mirror, where a plain colour beside the matrix adds to its diagonal. */
static void test_matrix_energy(void **state)
{
    (void)state;
    GColorModel *model;
    GError err;
    assert_int_equal(gcolormodel_create("bispectral", NULL, &model, &err), G_OK);
    float *data = malloc((size_t)model->nsamples * model->nsamples * sizeof *data);
    assert_non_null(data);
    GColor keeps, makes, kd, small;
    shift_matrix(model, 0.6f, 0.3f, data, &keeps); /* sends out 0.9: accepted alone */
    shift_matrix(model, 0.6f, 0.5f, data, &makes); /* sends out 1.1: its diagonal alone is 0.6 */
    assert_int_equal(gcolor_alloc(&kd, model), G_OK);
    assert_int_equal(gcolor_fill(&kd, 0.2), G_OK);
    assert_int_equal(gcolor_alloc(&small, model), G_OK);
    assert_int_equal(gcolor_fill(&small, 0.05), G_OK);
    GMaterial *m = NULL;
    assert_int_equal(gmirror_create(model, &keeps, &m, &err), G_OK);
    gmaterial_unref(m);
    m = NULL;
    expect_error(gmirror_create(model, &makes, &m, &err), m, &err, "reflectance is a re-radiation matrix that sends "
                 "out 1.1", "energy is conserved");
    assert_string_equal(err.param, "reflectance");
    expect_error(glambert_create(model, &makes, &m, &err), m, &err, "sends out 1.1", NULL);
    GPhongParams pp = {&small, NULL, 20.0, &makes};
    expect_error(gphong_create(model, &pp, &m, &err), m, &err, "phong: mirror is a re-radiation matrix", "1.1");
    GDielectricParams dp = {gdispersion_constant(1.5), NULL, &makes};
    expect_error(gdielectric_create(model, &dp, &m, &err), m, &err, "tint is a re-radiation matrix", "1.1");
    /* kd 0.2 + mirror 0.9 per excitation sample: 1.1, though no parameter exceeds 1 and the sum's diagonal is 0.8 */
    pp.kd = &kd;
    pp.mirror = &keeps;
    expect_error(gphong_create(model, &pp, &m, &err), m, &err,
                 "phong: kd + ks + mirror is a re-radiation matrix that sends out 1.1", "excitation sample 0");
    assert_string_equal(err.param, "mirror");
    pp.mirror = NULL;
    pp.ks = &keeps; /* the glossy lobe's matrix, named so */
    expect_error(gphong_create(model, &pp, &m, &err), m, &err, "sends out 1.1", NULL);
    assert_string_equal(err.param, "specular");
    pp.ks = NULL;
    pp.kd = &small; /* 0.05 + 0.9 */
    pp.mirror = &keeps;
    assert_int_equal(gphong_create(model, &pp, &m, &err), G_OK);
    gmaterial_unref(m);
    /* from a file: placed at the parameter that re-radiates */
    GLibrary *lib = NULL;
    GReaderOptions ro = {.model = model};
    assert_int_equal(greader_load_string("color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 "
                                         "absorb_max 0.97\n    emit_width 20 stokes_shift 135 quantum_yield 0.65 "
                                         "reflectance 0.92 }\n"
                                         "material p phong { diffuse rgb 0.1 0.1 0.1 mirror dayglo }\n",
                                         "t.mat", &ro, &lib, &err),
                     G_ERR_INVALID);
    assert_null(lib);
    print_message("refused: %s\n", err.message);
    assert_int_equal(err.line, 3);
    assert_int_equal(err.col, 44); /* "mirror" */
    assert_string_equal(err.param, "mirror");
    assert_non_null(strstr(err.message, "t.mat:3:44: phong: kd + ks + mirror is a re-radiation matrix that sends out "
                                        "1.02"));
    gcolor_free(&keeps);
    gcolor_free(&makes);
    gcolor_free(&kd);
    gcolor_free(&small);
    free(data);
    gcolormodel_destroy(model);
}

/* A constructor's complaint names its parameter (gerror_set_param); the reader places it there: the message's
 * position and the GError fields agree, and a parameter the file did not write is placed at the last token. */
static void test_error_at_parameter(void **state)
{
    (void)state;
    GError err;
    assert_int_equal(gerror_set_param(&err, G_ERR_INVALID, "reflectance", "x: %d", 7), G_ERR_INVALID);
    assert_string_equal(err.param, "reflectance");
    assert_string_equal(err.message, "x: 7");
    assert_int_equal(err.line, 0);
    gerror_set(&err, G_ERR_INVALID, "y");
    assert_string_equal(err.param, "");

    GLibrary *lib = NULL;
    /* "reflectance" starts at line 3, column 5; the bad value is read after it */
    assert_int_equal(greader_load_string("\nmaterial w lambert {\n    reflectance rgb 0.5 -2 0.5 }\n", "t.mat", NULL,
                                         &lib, &err),
                     G_ERR_INVALID);
    assert_null(lib);
    assert_int_equal(err.line, 3);
    assert_int_equal(err.col, 5);
    assert_string_equal(err.param, "reflectance");
    assert_string_equal(err.message,
                        "t.mat:3:5: lambert: reflectance has the value -2 at sample 1 (must be finite and >= 0)");
    /* phong names kd + ks + mirror, which is no parameter of the file: the last token read, the closing brace */
    assert_int_equal(greader_load_string("material m phong { diffuse rgb 0.6 0.6 0.6\n"
                                         "  specular rgb 0.3 0.3 0.3 mirror rgb 0.3 0.3 0.3 }\n",
                                         "p.mat", NULL, &lib, &err),
                     G_ERR_INVALID);
    assert_int_equal(err.line, 2);
    assert_int_equal(err.col, 51);
    assert_string_equal(err.param, "");
    assert_non_null(strstr(err.message, "p.mat:2:51: phong: kd + ks + mirror is"));
}

static void test_registered(void **state)
{
    (void)state;
    static const char *const names[] = {"lambert", "phong", "mirror", "dielectric", "emitter"};
    for (int i = 0; i < 5; i++) {
        const GTypeInfo *t = gregistry_find(GKIND_MATERIAL, names[i]);
        assert_non_null(t);
        const GMaterialClass *cls = t->vtable;
        assert_non_null(cls);
        assert_string_equal(cls->name, names[i]);
        assert_int_equal(cls->abi_version, GMATERIAL_ABI_VERSION);
        assert_non_null(t->parse);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        BOTH(test_lambert_albedo),
        BOTH(test_phong_albedo),
        BOTH(test_reciprocity),
        BOTH(test_phong_lobe_and_mirror),
        BOTH(test_mirror),
        BOTH(test_emitter),
        BOTH(test_bad_parameters),
        cmocka_unit_test(test_registered),
        cmocka_unit_test(test_error_at_parameter),
        cmocka_unit_test(test_matrix_energy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
