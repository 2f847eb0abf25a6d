/* test_batch.c - the batch API (generic/batch.h) against the dispatch called row by row on gbatch_surface_point's
 * points: every material method, generator values and colour conversions equal bit for bit, in rgb, spectrum and
 * bispectral, on one thread and on several; bad rows refused naming the row and the argument. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "generic/batch.h"
#include "generic/builtins.h"
#include "generic/reader.h"
#include "test_util.h"

enum { N = 3000 };

static const char *const text =
    "material glossy phong { diffuse rgb 0.6 0.08 0.05 specular rgb 0.25 0.25 0.25 exponent 60 }\n"
    "material matte lambert { reflectance rgb 0.7 0.5 0.2 }\n"
    "material glass dielectric { index cauchy 1.3199 0.006878 -0.000132 }\n"
    "material lamp emitter { radiance rgb 2 1.5 1 }\n"
    "generator noise turbulence { space object frequency 3 }\n"
    "material tiles interpolate { a lambert { reflectance rgb 0.8 0.8 0.8 } b phong { diffuse rgb 0.1 0.2 0.5 "
    "specular rgb 0.3 0.3 0.3 exponent 60 } t checker { dims 2 frequency 4 } }\n";

/* The inputs of N rows: unit normals about +z, points, (u, v), tangents, in and out directions on the normal's side
 * (a few below it, for refraction), random numbers. */
typedef struct Rows {
    double normal[N * 3], point[N * 3], uv[N * 2], dpdu[N * 3], dpdv[N * 3], in[N * 3], out[N * 3], u[N * 2];
} Rows;

static GVec3 random_dir(unsigned long long *s, double zmin)
{
    for (;;) {
        GVec3 d = gvec3(2 * tu_uniform(s) - 1, 2 * tu_uniform(s) - 1, 2 * tu_uniform(s) - 1);
        double l = gvec3_length(d);
        if (l > 0.1 && l <= 1.0 && d.z / l >= zmin)
            return gvec3_scale(d, 1.0 / l);
    }
}

static void put(double *a, int i, GVec3 v)
{
    a[3 * i] = v.x;
    a[3 * i + 1] = v.y;
    a[3 * i + 2] = v.z;
}

static Rows *make_rows(void)
{
    Rows *r = calloc(1, sizeof *r);
    assert_non_null(r);
    unsigned long long s = 42;
    for (int i = 0; i < N; i++) {
        put(r->normal, i, random_dir(&s, 0.8));
        put(r->point, i, gvec3(4 * tu_uniform(&s) - 2, 4 * tu_uniform(&s) - 2, tu_uniform(&s)));
        r->uv[2 * i] = tu_uniform(&s);
        r->uv[2 * i + 1] = tu_uniform(&s);
        put(r->dpdu, i, gvec3(1, 0, 0));
        put(r->dpdv, i, gvec3(0, 1, 0));
        put(r->in, i, random_dir(&s, i % 5 == 0 ? -1.0 : 0.05));
        put(r->out, i, random_dir(&s, 0.05));
        r->u[2 * i] = tu_uniform(&s);
        r->u[2 * i + 1] = tu_uniform(&s);
    }
    return r;
}

static GLibrary *load(const char *model)
{
    GReaderOptions opt = {.colormodel = model};
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "batch.mat", &opt, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return lib;
}

static GBatchPoints points_of(const Rows *r, int threads)
{
    return (GBatchPoints){.n = N, .normal = r->normal, .point = r->point, .uv = r->uv, .dpdu = r->dpdu,
                          .dpdv = r->dpdv, .threads = threads};
}

/* Bit-for-bit equality of two arrays of doubles (NaN equal to the same NaN). */
static void assert_same(const double *a, const double *b, size_t n, const char *what)
{
    if (memcmp(a, b, n * sizeof *a) != 0) {
        for (size_t i = 0; i < n; i++)
            if (memcmp(a + i, b + i, sizeof *a) != 0) {
                print_error("%s: element %zu: %.17g != %.17g\n", what, i, a[i], b[i]);
                break;
            }
        fail();
    }
}

enum { M_REFLECTION, M_REFRACTION, M_EMISSION, M_PDF, M_SAMPLE };

/* The reference: row by row through the dispatch, on gbatch_surface_point's point, written as the batch writes. */
static void reference(int method, const GMaterial *m, const GBatchPoints *pts, const Rows *r, GBatchOutput output,
                      double *result, double *pdf, double *dirs, int *flags)
{
    const GColorModel *model = m->model;
    int w = gbatch_output_width(model, output);
    GScratch *s = gscratch_create(0);
    GColor white, c, ri;
    assert_int_equal(gcolor_alloc(&white, model), G_OK);
    assert_int_equal(gbatch_white_light(model, &white), G_OK);
    GError err;
    for (int i = 0; i < N; i++) {
        GScratchMark mark = gscratch_mark(s);
        GSurfPoint sp;
        assert_int_equal(gbatch_surface_point(pts, (size_t)i, m, model, s, &sp, &err), G_OK);
        assert_int_equal(gcolor_scratch(&c, model, s), G_OK);
        assert_int_equal(gcolor_scratch(&ri, model, s), G_OK);
        assert_int_equal(gbatch_relative_index(&sp, &ri), G_OK);
        GVec3 in = gvec3(r->in[3 * i], r->in[3 * i + 1], r->in[3 * i + 2]);
        GVec3 out = gvec3(r->out[3 * i], r->out[3 * i + 1], r->out[3 * i + 2]);
        int rc = G_OK;
        if (method == M_REFLECTION)
            rc = gmaterial_reflection(m, &sp, in, &white, out, &c);
        else if (method == M_REFRACTION)
            rc = gmaterial_refraction(m, &sp, in, &white, &ri, out, &c);
        else if (method == M_EMISSION)
            rc = gmaterial_emission(m, &sp, out, &c);
        else if (method == M_PDF)
            pdf[i] = gmaterial_pdf(m, &sp, in, out, &ri);
        else {
            GMaterialSample smp = {{0, 0, 0}, 0, 0};
            rc = gmaterial_sample(m, &sp, out, &ri, r->u[2 * i], r->u[2 * i + 1], &smp, &c);
            assert_true(rc >= 0);
            if (rc == 0) {
                smp = (GMaterialSample){{0, 0, 0}, 0, 0};
                gcolor_black(&c);
            }
            put(dirs, i, smp.in);
            pdf[i] = smp.pdf;
            flags[i] = smp.flags;
            rc = G_OK;
        }
        assert_int_equal(rc, G_OK);
        if (method != M_PDF) {
            double *dst = result + (size_t)w * i;
            if (output == GBATCH_SAMPLES)
                for (int k = 0; k < model->nvalues; k++)
                    dst[k] = c.v[k];
            else if (output == GBATCH_XYZ)
                assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, dst), G_OK);
            else
                assert_int_equal(gcolor_to_rgb(&c, GCOLOR_LIGHT, dst), G_OK);
        }
        gscratch_release(s, mark);
    }
    gcolor_free(&white);
    gscratch_destroy(s);
}

/* One material, every method and output, on 1 and 3 threads, against the reference. */
static void check_material(GLibrary *lib, const char *name, const Rows *r)
{
    const GMaterial *m = glibrary_material(lib, name);
    assert_non_null(m);
    int nv = m->model->nvalues;
    size_t big = (size_t)N * (size_t)(nv > 3 ? nv : 3);
    double *want = calloc(big, sizeof(double)), *got = calloc(big, sizeof(double));
    double *want_pdf = calloc(N, sizeof(double)), *got_pdf = calloc(N, sizeof(double));
    double *want_dir = calloc(3 * N, sizeof(double)), *got_dir = calloc(3 * N, sizeof(double));
    int *want_flags = calloc(N, sizeof(int)), *got_flags = calloc(N, sizeof(int));
    assert_true(want && got && want_pdf && got_pdf && want_dir && got_dir && want_flags && got_flags);
    GError err;
    for (int threads = 1; threads <= 3; threads += 2) {
        GBatchPoints pts = points_of(r, threads);
        for (int o = GBATCH_SAMPLES; o <= GBATCH_RGB; o++) {
            GBatchOutput out = (GBatchOutput)o;
            size_t len = (size_t)N * (size_t)gbatch_output_width(m->model, out);
            reference(M_REFLECTION, m, &pts, r, out, want, NULL, NULL, NULL);
            assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, out, got, &err), G_OK);
            assert_same(want, got, len, "reflection");
            reference(M_REFRACTION, m, &pts, r, out, want, NULL, NULL, NULL);
            assert_int_equal(gbatch_refraction(m, &pts, r->in, r->out, out, got, &err), G_OK);
            assert_same(want, got, len, "refraction");
            reference(M_EMISSION, m, &pts, r, out, want, NULL, NULL, NULL);
            assert_int_equal(gbatch_emission(m, &pts, r->out, out, got, &err), G_OK);
            assert_same(want, got, len, "emission");
            reference(M_SAMPLE, m, &pts, r, out, want, want_pdf, want_dir, want_flags);
            assert_int_equal(gbatch_sample(m, &pts, r->out, r->u, out, got_dir, got_pdf, got_flags, got, &err), G_OK);
            assert_same(want, got, len, "sample weight");
            assert_same(want_pdf, got_pdf, N, "sample pdf");
            assert_same(want_dir, got_dir, 3 * N, "sample direction");
            assert_memory_equal(want_flags, got_flags, N * sizeof(int));
        }
        reference(M_PDF, m, &pts, r, GBATCH_RGB, NULL, want_pdf, NULL, NULL);
        assert_int_equal(gbatch_pdf(m, &pts, r->in, r->out, got_pdf, &err), G_OK);
        assert_same(want_pdf, got_pdf, N, "pdf");
    }
    free(want);
    free(got);
    free(want_pdf);
    free(got_pdf);
    free(want_dir);
    free(got_dir);
    free(want_flags);
    free(got_flags);
}

static void check_models(const char *model)
{
    Rows *r = make_rows();
    GLibrary *lib = load(model);
    static const char *const names[] = {"glossy", "matte", "glass", "lamp", "tiles"};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++)
        check_material(lib, names[k], r);
    glibrary_destroy(lib);
    free(r);
}

static void test_materials_rgb(void **state)
{
    (void)state;
    check_models("rgb");
}

static void test_materials_spectrum(void **state)
{
    (void)state;
    check_models("spectrum");
}

static void test_materials_bispectral(void **state)
{
    (void)state;
    check_models("bispectral");
}

/* The phong lobe is not black: the comparison above compares numbers, not zeros. */
static void test_values_are_not_trivial(void **state)
{
    (void)state;
    Rows *r = make_rows();
    GLibrary *lib = load("rgb");
    const GMaterial *m = glibrary_material(lib, "matte");
    GBatchPoints pts = points_of(r, 0);
    double *rgb = calloc(3 * N, sizeof(double));
    GError err;
    assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, GBATCH_SAMPLES, rgb, &err), G_OK);
    /* lambert in rgb: reflectance / pi * cos(in) for in above the surface, black below */
    for (int i = 0; i < N; i++) {
        GVec3 n = gvec3_normalize(gvec3(r->normal[3 * i], r->normal[3 * i + 1], r->normal[3 * i + 2]));
        double c = gvec3_dot(n, gvec3(r->in[3 * i], r->in[3 * i + 1], r->in[3 * i + 2]));
        double o = gvec3_dot(n, gvec3(r->out[3 * i], r->out[3 * i + 1], r->out[3 * i + 2]));
        double want = c > 0 && o > 0 ? 0.7 / M_PI * c : 0.0;
        assert_near(rgb[3 * i], want, 1e-6);
    }
    free(rgb);
    glibrary_destroy(lib);
    free(r);
}

static void test_generator(void **state)
{
    (void)state;
    Rows *r = make_rows();
    GLibrary *lib = load("spectrum");
    const GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "noise");
    assert_non_null(g);
    const GColorModel *model = glibrary_colormodel(lib);
    double *want = calloc(N, sizeof(double)), *got = calloc(N, sizeof(double));
    GScratch *s = gscratch_create(0);
    GError err;
    GBatchPoints pts = points_of(r, 2);
    double lo = 1e9, hi = -1e9;
    for (int i = 0; i < N; i++) {
        GSurfPoint sp;
        assert_int_equal(gbatch_surface_point(&pts, (size_t)i, NULL, model, s, &sp, &err), G_OK);
        want[i] = ggenerator_value(g, &sp);
        lo = want[i] < lo ? want[i] : lo;
        hi = want[i] > hi ? want[i] : hi;
    }
    assert_true(hi - lo > 0.1); /* the noise varies over the points */
    assert_int_equal(gbatch_generator_value(g, model, &pts, got, &err), G_OK);
    assert_same(want, got, N, "generator");
    gscratch_destroy(s);
    free(want);
    free(got);
    glibrary_destroy(lib);
    free(r);
}

/* rgb -> model -> rgb round trip through the batch equals the per-value calls, and reflectances come back. */
static void test_colors(void **state)
{
    (void)state;
    static const char *const models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    GError err;
    for (size_t k = 0; k < sizeof models / sizeof *models; k++) {
        GColorModel *m;
        assert_int_equal(gcolormodel_create(models[k], NULL, &m, &err), G_OK);
        unsigned long long s = 7;
        double *rgb = calloc(3 * N, sizeof(double)), *back = calloc(3 * N, sizeof(double));
        double *want = calloc(3 * N, sizeof(double));
        float *samples = calloc((size_t)N * m->nvalues, sizeof(float));
        for (int i = 0; i < 3 * N; i++)
            rgb[i] = 0.05 + 0.9 * tu_uniform(&s);
        assert_int_equal(gbatch_color_from_rgb(m, N, rgb, GCOLOR_REFLECTANCE, samples, 2, &err), G_OK);
        assert_int_equal(gbatch_color_to(m, N, samples, GCOLOR_REFLECTANCE, GBATCH_RGB, back, 2, &err), G_OK);
        GColor c;
        assert_int_equal(gcolor_alloc(&c, m), G_OK);
        for (int i = 0; i < N; i++) {
            assert_int_equal(gcolor_from_rgb(&c, rgb + 3 * i, GCOLOR_REFLECTANCE), G_OK);
            assert_memory_equal(c.v, samples + (size_t)m->nvalues * i, (size_t)m->nvalues * sizeof(float));
            assert_int_equal(gcolor_to_rgb(&c, GCOLOR_REFLECTANCE, want + 3 * i), G_OK);
            for (int j = 0; j < 3; j++)
                assert_near(back[3 * i + j], rgb[3 * i + j], 2e-3);
        }
        assert_same(want, back, 3 * N, models[k]);
        gcolor_free(&c);
        free(rgb);
        free(back);
        free(want);
        free(samples);
        gcolormodel_destroy(m);
    }
}

/* A NaN, a zero normal or a random number out of range: refused at the lowest bad row, named in the message. */
static void test_bad_rows(void **state)
{
    (void)state;
    Rows *r = make_rows();
    GLibrary *lib = load("rgb");
    const GMaterial *m = glibrary_material(lib, "glossy");
    double *res = calloc(3 * N, sizeof(double)), *pdf = calloc(N, sizeof(double)), *dir = calloc(3 * N, sizeof(double));
    int *flags = calloc(N, sizeof(int));
    GError err;
    GBatchPoints pts = points_of(r, 3);
    r->in[3 * 2001 + 1] = NAN;
    r->normal[3 * 1500] = r->normal[3 * 1500 + 1] = r->normal[3 * 1500 + 2] = 0.0;
    assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, GBATCH_RGB, res, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "gbatch_reflection: row 1500: normal"));
    r->normal[3 * 1500 + 2] = 1.0;
    assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, GBATCH_RGB, res, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "row 2001: in is not finite"));
    r->u[2 * 17] = 1.0;
    assert_int_equal(gbatch_sample(m, &pts, r->out, r->u, GBATCH_RGB, dir, pdf, flags, res, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "row 17: u is outside [0, 1)"));
    assert_int_equal(gbatch_reflection(m, &pts, NULL, r->out, GBATCH_RGB, res, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "no in array"));
    assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, (GBatchOutput)7, res, &err), G_ERR_INVALID);
    assert_int_equal(gbatch_reflection(NULL, &pts, r->in, r->out, GBATCH_RGB, res, &err), G_ERR_INVALID);
    /* no rows: nothing to do */
    pts.n = 0;
    assert_int_equal(gbatch_reflection(m, &pts, r->in, r->out, GBATCH_RGB, res, &err), G_OK);
    free(res);
    free(pdf);
    free(dir);
    free(flags);
    glibrary_destroy(lib);
    free(r);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_materials_rgb),        cmocka_unit_test(test_materials_spectrum),
        cmocka_unit_test(test_materials_bispectral), cmocka_unit_test(test_values_are_not_trivial),
        cmocka_unit_test(test_generator),            cmocka_unit_test(test_colors),
        cmocka_unit_test(test_bad_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
