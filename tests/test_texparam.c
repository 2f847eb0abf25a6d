/* test_texparam.c - textured parameters (kit/texparam.h): `range LO HI` on generators, numbers and colours driven
 * per surface point (exact values in each checker cell, memoised on the point, no allocation per evaluation), the
 * energy rule at a texture's extremes, and bad input refused at file:line:col naming the parameter. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/kit/texparam.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "generic/texture.h"
#include "reader_fixture.h"
#include "test_alloc.h"
#include "test_util.h"

/* The message a load of text gives, which must contain want. */
static void load_fails_with(const char *text, const char *want)
{
    GLibrary *lib = NULL;
    GError err;
    assert_true(greader_load_string(text, "t.mat", NULL, &lib, &err) < 0);
    assert_null(lib);
    if (!strstr(err.message, want))
        print_error("got:  %s\nwant: ...%s...\n", err.message, want);
    assert_non_null(strstr(err.message, want));
}

/* A point of m at (u, v) where the light enters m from vacuum (the relative index n(vacuum) / n(m)). */
static GSurfPoint *entering(const GMaterial *m, GScratch *s, double u, double v)
{
    GSurfPoint *sp = plane_point(m->model, s, u, v);
    sp->material = m;
    sp->from = NULL;
    sp->to = m;
    return sp;
}

/* Evaluating m (reflection, refraction, sample, pdf) at 100 points, each a new hit (caches cleared), allocates
 * nothing. */
static void assert_no_allocation(const GMaterial *m, GScratch *s)
{
    GSurfPoint *sp = entering(m, s, 0.3, 0.6);
    GColor white, got;
    assert_int_equal(gtexparam_unit_color(m->model, &white), G_OK);
    assert_int_equal(gcolor_alloc(&got, m->model), G_OK);
    GVec3 in = gvec3_normalize(gvec3(0.3, 0.2, 1.0)), out = gvec3_normalize(gvec3(-0.3, -0.1, 1.0));
    static TuAlloc counter;
    counter = (TuAlloc){0};
    tu_alloc_install(&counter);
    int failed = 0;
    for (int i = 0; i < 100 && !failed; i++) {
        sp->u = 0.037 * i;
        sp->v = 0.61 + 0.013 * i;
        sp->point = gvec3(sp->u, sp->v, 0.0);
        gsurfpoint_invalidate(sp);
        int rc = gmaterial_reflection(m, sp, in, &white, out, &got);
        if (rc == G_OK)
            rc = gmaterial_refraction(m, sp, gvec3(-in.x, -in.y, -in.z), &white, NULL, out, &got);
        GMaterialSample smp;
        int drawn = gmaterial_sample(m, sp, out, NULL, 0.37, 0.61, &smp, &got);
        double pdf = gmaterial_pdf(m, sp, in, out, NULL);
        failed = rc != G_OK || drawn < 0 || !(pdf >= 0.0);
    }
    long calls = counter.calls;
    gmem_set_allocator(NULL);
    assert_false(failed);
    assert_int_equal(calls, 0);
    gsurfpoint_free(sp);
    gcolor_free(&white);
    gcolor_free(&got);
}

/* reflection, pdf, diffuse and a sample of material t at (u, v) equal, float for float, those of material c at the
 * same point (a textured parameter whose value there is c's constant). */
static void assert_same_at(const GMaterial *t, const GMaterial *c, GScratch *s, double u, double v)
{
    const GColorModel *m = t->model;
    GSurfPoint *sp = entering(t, s, u, v), *sq = entering(c, s, u, v);
    GColor white, a, b;
    assert_int_equal(gtexparam_unit_color(m, &white), G_OK);
    assert_int_equal(gcolor_alloc(&a, m), G_OK);
    assert_int_equal(gcolor_alloc(&b, m), G_OK);
    for (int k = 0; k < 6; k++) {
        GVec3 in = gvec3_normalize(gvec3(0.3 - 0.2 * k, 0.2, 1.0 - 0.15 * k));
        GVec3 out = gvec3_normalize(gvec3(-0.2 + 0.1 * k, 0.1 * k, 1.0 - 0.1 * k));
        assert_int_equal(gmaterial_reflection(t, sp, in, &white, out, &a), G_OK);
        assert_int_equal(gmaterial_reflection(c, sq, in, &white, out, &b), G_OK);
        assert_memory_equal(a.v, b.v, sizeof(float) * (size_t)m->nvalues);
        GVec3 below = gvec3(-in.x, -in.y, -in.z);
        assert_int_equal(gmaterial_refraction(t, sp, below, &white, NULL, out, &a), G_OK);
        assert_int_equal(gmaterial_refraction(c, sq, below, &white, NULL, out, &b), G_OK);
        assert_memory_equal(a.v, b.v, sizeof(float) * (size_t)m->nvalues);
        assert_true(gmaterial_pdf(t, sp, in, out, NULL) == gmaterial_pdf(c, sq, in, out, NULL));
        assert_true(gmaterial_pdf(t, sp, below, out, NULL) == gmaterial_pdf(c, sq, below, out, NULL));
        GMaterialSample x, y;
        double u1 = 0.1 + 0.15 * k, u2 = 0.77 - 0.1 * k;
        int dx = gmaterial_sample(t, sp, out, NULL, u1, u2, &x, &a), dy = gmaterial_sample(c, sq, out, NULL, u1, u2,
                                                                                           &y, &b);
        assert_int_equal(dx, dy);
        if (dx > 0) {
            assert_true(x.pdf == y.pdf && x.in.x == y.in.x && x.in.y == y.in.y && x.in.z == y.in.z);
            assert_memory_equal(a.v, b.v, sizeof(float) * (size_t)m->nvalues);
        }
    }
    assert_int_equal(gmaterial_diffuse(t, sp, &a), G_OK);
    assert_int_equal(gmaterial_diffuse(c, sq, &b), G_OK);
    assert_memory_equal(a.v, b.v, sizeof(float) * (size_t)m->nvalues);
    gsurfpoint_free(sp);
    gsurfpoint_free(sq);
    gcolor_free(&white);
    gcolor_free(&a);
    gcolor_free(&b);
}

/* The largest relative difference of t's and c's reflection and refraction at (u, v) over a few pairs of
 * directions. */
static double worst_relative(const GMaterial *t, const GMaterial *c, GScratch *s, double u, double v)
{
    const GColorModel *m = t->model;
    GSurfPoint *sp = entering(t, s, u, v), *sq = entering(c, s, u, v);
    GColor white, a, b;
    assert_int_equal(gtexparam_unit_color(m, &white), G_OK);
    assert_int_equal(gcolor_alloc(&a, m), G_OK);
    assert_int_equal(gcolor_alloc(&b, m), G_OK);
    double worst = 0.0;
    for (int k = 0; k < 8; k++) {
        GVec3 in = gvec3_normalize(gvec3(0.4 - 0.1 * k, 0.1, 1.0 - 0.1 * k));
        GVec3 out = gvec3_normalize(gvec3(-0.3 + 0.05 * k, 0.05 * k, 1.0 - 0.11 * k));
        for (int side = 0; side < 2; side++) {
            GVec3 from = side ? gvec3(-in.x, -in.y, -in.z) : in;
            assert_int_equal(side ? gmaterial_refraction(t, sp, from, &white, NULL, out, &a)
                                  : gmaterial_reflection(t, sp, from, &white, out, &a), G_OK);
            assert_int_equal(side ? gmaterial_refraction(c, sq, from, &white, NULL, out, &b)
                                  : gmaterial_reflection(c, sq, from, &white, out, &b), G_OK);
            for (int i = 0; i < m->nvalues; i++) {
                double d = fabs((double)a.v[i] - b.v[i]) / fmax(1e-6, fabs((double)b.v[i]));
                worst = d > worst ? d : worst;
            }
        }
    }
    gsurfpoint_free(sp);
    gsurfpoint_free(sq);
    gcolor_free(&white);
    gcolor_free(&a);
    gcolor_free(&b);
    return worst;
}

/* range LO HI maps 0 to exactly LO and 1 to exactly HI, and every value linearly (its gradient too). */
static void test_range_maps_linearly(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("generator c checker { dims 2 frequency 1 range 10 200 }\n"
                         "generator p perlin { frequency 2 }\n"
                         "generator q perlin { frequency 2 range -1 3 }\n"
                         "generator d checker { dims 2 range 0 1 }\n");
    GScratch *s = gscratch_create(1 << 14);
    const GGenerator *c = glibrary_find(lib, GKIND_GENERATOR, "c"), *p = glibrary_find(lib, GKIND_GENERATOR, "p"),
                     *q = glibrary_find(lib, GKIND_GENERATOR, "q"), *d = glibrary_find(lib, GKIND_GENERATOR, "d");
    GSurfPoint *even = plane_point(glibrary_colormodel(lib), s, 0.5, 0.5);
    GSurfPoint *odd = plane_point(glibrary_colormodel(lib), s, 1.5, 0.5);
    assert_true(ggenerator_value(c, even) == 10.0);
    assert_true(ggenerator_value(c, odd) == 200.0);
    double lo, hi;
    ggenerator_declared_range(c, &lo, &hi);
    assert_true(lo == 10.0 && hi == 200.0);
    ggenerator_declared_range(p, &lo, &hi);
    assert_true(lo == 0.0 && hi == 1.0);
    assert_string_equal(ggenerator_name(d), "checker"); /* the default range makes no range generator */
    for (int i = 0; i < 20; i++) {
        GSurfPoint *sp = plane_point(glibrary_colormodel(lib), s, 0.137 * i, 0.291 * i);
        double v = ggenerator_value(p, sp), w = ggenerator_value(q, sp);
        assert_true(w == -1.0 * (1.0 - v) + 3.0 * v);
        GVec3 gp, gq;
        assert_int_equal(ggenerator_gradient(p, sp, &gp), G_OK);
        assert_int_equal(ggenerator_gradient(q, sp, &gq), G_OK);
        assert_true(fabs(gq.x - 4.0 * gp.x) <= 1e-9 * (1.0 + fabs(gq.x)));
        assert_true(fabs(gq.y - 4.0 * gp.y) <= 1e-9 * (1.0 + fabs(gq.y)));
        gsurfpoint_free(sp);
    }
    gsurfpoint_free(even);
    gsurfpoint_free(odd);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* A mix by a checker is exactly a in the cells where the checker is 0 and b where it is 1; a lambert of that
 * reflectance reflects there exactly what the lambert of that constant reflects. */
static void test_mix_is_exact_in_cells(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("colormodel spectrum\n"
                         "material t lambert { reflectance mix { by checker { dims 2 frequency 1 } a rgb 0.2 0.3 0.4 "
                         "b rgb 0.6 0.5 0.1 } }\n"
                         "material a lambert { reflectance rgb 0.2 0.3 0.4 }\n"
                         "material b lambert { reflectance rgb 0.6 0.5 0.1 }\n");
    const GColorModel *m = glibrary_colormodel(lib);
    GScratch *s = gscratch_create(1 << 16);
    GColor white, got, want;
    assert_int_equal(gtexparam_unit_color(m, &white), G_OK);
    assert_int_equal(gcolor_alloc(&got, m), G_OK);
    assert_int_equal(gcolor_alloc(&want, m), G_OK);
    GVec3 in = gvec3_normalize(gvec3(0.3, 0.2, 1.0)), out = gvec3_normalize(gvec3(-0.2, 0.1, 1.0));
    for (int cell = 0; cell < 2; cell++) {
        GSurfPoint *sp = plane_point(m, s, cell ? 1.25 : 0.25, 0.75);
        GSurfPoint *sq = plane_point(m, s, cell ? 1.25 : 0.25, 0.75);
        assert_int_equal(gmaterial_reflection(glibrary_material(lib, "t"), sp, in, &white, out, &got), G_OK);
        assert_int_equal(gmaterial_reflection(glibrary_material(lib, cell ? "b" : "a"), sq, in, &white, out, &want),
                         G_OK);
        assert_memory_equal(got.v, want.v, sizeof(float) * (size_t)m->nvalues);
        assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "t"), sp, &got), G_OK);
        assert_int_equal(gmaterial_diffuse(glibrary_material(lib, cell ? "b" : "a"), sq, &want), G_OK);
        assert_memory_equal(got.v, want.v, sizeof(float) * (size_t)m->nvalues);
        gsurfpoint_free(sp);
        gsurfpoint_free(sq);
    }
    gcolor_free(&white);
    gcolor_free(&got);
    gcolor_free(&want);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* A textured exponent is evaluated once per point (its generator's value is in the point's cache after the
 * first call), and evaluating textured parameters at a point allocates nothing. */
static void test_memoised_without_allocation(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("generator g perlin { frequency 3 range 5 300 }\n"
                         "material p phong { diffuse mix { by checker { dims 2 } a rgb 0.1 0.2 0.3 b rgb 0.5 0.4 "
                         "0.3 } specular rgb 0.2 0.2 0.2 exponent g }\n");
    const GColorModel *m = glibrary_colormodel(lib);
    const GMaterial *p = glibrary_material(lib, "p");
    const GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "g");
    GScratch *s = gscratch_create(1 << 16);
    GSurfPoint *sp = plane_point(m, s, 0.3, 0.6);
    GColor white, got;
    assert_int_equal(gtexparam_unit_color(m, &white), G_OK);
    assert_int_equal(gcolor_alloc(&got, m), G_OK);
    GVec3 in = gvec3_normalize(gvec3(0.3, 0.2, 1.0)), out = gvec3_normalize(gvec3(-0.3, -0.1, 1.0));
    double v;
    assert_false(gsurfpoint_cache_get(sp, g, &v, NULL));
    assert_int_equal(gmaterial_reflection(p, sp, in, &white, out, &got), G_OK);
    assert_true(gsurfpoint_cache_get(sp, g, &v, NULL));
    assert_true(v >= 5.0 && v <= 300.0);
    static TuAlloc counter;
    tu_alloc_install(&counter);
    for (int i = 0; i < 100; i++) {
        sp->u = 0.01 * i;
        gsurfpoint_invalidate(sp);
        int rc = gmaterial_reflection(p, sp, in, &white, out, &got);
        GMaterialSample smp;
        int drawn = gmaterial_sample(p, sp, out, NULL, 0.37, 0.61, &smp, &got);
        double pdf = gmaterial_pdf(p, sp, in, out, NULL);
        if (rc != G_OK || drawn < 0 || !(pdf >= 0.0))
            break;
    }
    long calls = counter.calls;
    gmem_set_allocator(NULL);
    assert_int_equal(calls, 0);
    gsurfpoint_free(sp);
    gcolor_free(&white);
    gcolor_free(&got);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* plastic: a checker-driven roughness (its range's ends are tabulated levels) and reflectance (a mix) give, in each
 * cell, exactly the constant plastic's reflection, pdf, sample and diffuse; between levels the interpolated tables
 * stay within 0.1% of the constant material's; nothing is allocated per evaluation. */
static void test_plastic_textured(void **state)
{
    (void)state;
    static const char *const models[] = {"rgb", "spectrum"};
    for (int mi = 0; mi < (TU_SANITIZED ? 1 : 2); mi++) { /* under the sanitizers one model: the same code paths */
        char text[2048];
        snprintf(text, sizeof text,
                 "colormodel %s\n"
                 "material r plastic { reflectance rgb 0.2 0.4 0.6 roughness checker { dims 2 range 0.05 0.5 } }\n"
                 "material r0 plastic { reflectance rgb 0.2 0.4 0.6 roughness 0.05 }\n"
                 "material r1 plastic { reflectance rgb 0.2 0.4 0.6 roughness 0.5 }\n"
                 "material c plastic { reflectance mix { by checker { dims 2 } a rgb 0.2 0.4 0.6 b rgb 0.7 0.1 0.1 }"
                 " roughness 0.2 }\n"
                 "material c0 plastic { reflectance rgb 0.2 0.4 0.6 roughness 0.2 }\n"
                 "material c1 plastic { reflectance rgb 0.7 0.1 0.1 roughness 0.2 }\n"
                 "material s plastic { reflectance mix { by checker { dims 2 } a rgb 0.2 0.4 0.6 b rgb 0.7 0.1 0.1 }"
                 " }\n"
                 "material s1 plastic { reflectance rgb 0.7 0.1 0.1 }\n"
                 "material mid plastic { reflectance rgb 0.2 0.4 0.6 roughness constant { value 0.45 range 0.05 0.5 }"
                 " }\n"
                 "material mid_c plastic { reflectance rgb 0.2 0.4 0.6 roughness 0.2525 }\n",
                 models[mi]);
        GLibrary *lib = load_ok(text);
        GScratch *s = gscratch_create(1 << 16);
        assert_same_at(glibrary_material(lib, "r"), glibrary_material(lib, "r0"), s, 0.25, 0.75);
        assert_same_at(glibrary_material(lib, "r"), glibrary_material(lib, "r1"), s, 1.25, 0.75);
        assert_same_at(glibrary_material(lib, "c"), glibrary_material(lib, "c0"), s, 0.25, 0.75);
        assert_same_at(glibrary_material(lib, "c"), glibrary_material(lib, "c1"), s, 1.25, 0.75);
        assert_same_at(glibrary_material(lib, "s"), glibrary_material(lib, "s1"), s, 1.25, 0.75);
        double worst = worst_relative(glibrary_material(lib, "mid"), glibrary_material(lib, "mid_c"), s, 0.3, 0.3);
        assert_true(worst > 0.0 && worst < 1e-3);
        assert_no_allocation(glibrary_material(lib, "r"), s);
        assert_no_allocation(glibrary_material(lib, "c"), s);
        gscratch_destroy(s);
        glibrary_destroy(lib);
    }
}

/* dielectric: a checker-driven roughness gives, in each cell (the range's ends, tabulated levels), exactly the
 * constant dielectric's reflection, refraction, pdf and sample; between levels the interpolated compensation keeps
 * the refraction within 0.3% of the constant material's; nothing is allocated per evaluation. */
static void test_dielectric_textured(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("colormodel spectrum\n"
                         "material r dielectric { glass BK7 roughness checker { dims 2 range 0.05 0.5 } }\n"
                         "material r0 dielectric { glass BK7 roughness 0.05 }\n"
                         "material r1 dielectric { glass BK7 roughness 0.5 }\n"
                         "material mid dielectric { glass BK7 roughness constant { value 0.4 range 0.05 0.5 } }\n"
                         "material mid_c dielectric { glass BK7 roughness 0.23 }\n");
    GScratch *s = gscratch_create(1 << 16);
    assert_same_at(glibrary_material(lib, "r"), glibrary_material(lib, "r0"), s, 0.25, 0.75);
    assert_same_at(glibrary_material(lib, "r"), glibrary_material(lib, "r1"), s, 1.25, 0.75);
    double worst = worst_relative(glibrary_material(lib, "mid"), glibrary_material(lib, "mid_c"), s, 0.3, 0.3);
    assert_true(worst > 0.0 && worst < 3e-3);
    assert_no_allocation(glibrary_material(lib, "r"), s);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* layer: a checker-driven thickness, a mix for the medium's albedo and a top whose roughness is textured give, in
 * each cell, exactly the constant layer's values (the walks draw the same numbers); nothing is allocated per
 * evaluation. */
static void test_layer_textured(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("material t layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 }"
                         " thickness checker { dims 2 range 0.2 2 } albedo mix { by checker { dims 2 } "
                         "a rgb 0.8 0.5 0.3 b rgb 0.2 0.6 0.9 } }\n"
                         "material t0 layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 }"
                         " thickness 0.2 albedo rgb 0.8 0.5 0.3 }\n"
                         "material t1 layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 }"
                         " thickness 2 albedo rgb 0.2 0.6 0.9 }\n"
                         "material r layer { top dielectric { index 1.5 roughness checker { dims 2 range 0.1 0.4 } }"
                         " bottom lambert { reflectance rgb 0.5 0.4 0.3 } thickness 0.5 }\n"
                         "material r1 layer { top dielectric { index 1.5 roughness 0.4 }"
                         " bottom lambert { reflectance rgb 0.5 0.4 0.3 } thickness 0.5 }\n");
    GScratch *s = gscratch_create(1 << 18);
    assert_same_at(glibrary_material(lib, "t"), glibrary_material(lib, "t0"), s, 0.25, 0.75);
    assert_same_at(glibrary_material(lib, "t"), glibrary_material(lib, "t1"), s, 1.25, 0.75);
    assert_same_at(glibrary_material(lib, "r"), glibrary_material(lib, "r1"), s, 1.25, 0.75);
    assert_no_allocation(glibrary_material(lib, "t"), s);
    assert_no_allocation(glibrary_material(lib, "r"), s);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* Where a number may be a generator, a defined constant is still a number, and a word that names no generator gets
 * the reader's own complaint about the number. */
static void test_numbers_stay_numbers(void **state)
{
    (void)state;
    GLibrary *lib = load_ok("define E 40\nmaterial p phong { exponent E }\n"
                         "material t thinfilm { thickness E }\n");
    glibrary_destroy(lib);
    load_fails("material m phong { exponent nan }\n", "t.mat:1:29: 'nan' is not allowed: numbers must be finite");
    load_fails_with("material m thinfilm { index nosuchgenerator }\n", "t.mat:1:29:");
}

/* Bad input is refused at file:line:col, naming the parameter. */
static void test_bad_input(void **state)
{
    (void)state;
    load_fails("generator g checker { dims 2 range 5 2 }\n",
               "t.mat:1:30: generator checker: range 5 2 has LO > HI (must be LO <= HI)");
    load_fails("material m dielectric { roughness_u checker { dims 2 } }\n",
               "t.mat:1:37: dielectric: roughness_u must be a constant number (it decides the anisotropic microfacet "
               "distribution and its albedo tables, made at creation), not a generator");
    load_fails("material m dielectric { roughness checker { dims 2 } }\n",
               "t.mat:1:35: dielectric: a textured roughness must stay >= 0.001, rough everywhere (the generator's "
               "range starts at 0; whether the interface is smooth is decided at creation)");
    load_fails_with("material m dielectric { roughness checker { dims 2 range 0.1 0.2 } roughness_u 0.3 }\n",
                    "dielectric: a textured roughness and roughness_u/roughness_v exclude each other");
    load_fails("material m dielectric { index checker { dims 2 range 1.2 1.6 } }\n",
               "t.mat:1:31: dielectric: index must be constant (it is the medium's index, which a renderer reads "
               "where a ray enters and keeps until the ray leaves), not a generator");
    load_fails("material m conductor { metal Au roughness checker { dims 2 } }\n",
               "t.mat:1:43: conductor: a textured roughness must stay >= 0.001, rough everywhere (the generator's "
               "range starts at 0; whether the surface is an ideal mirror is decided at creation)");
    load_fails("material m phong { exponent checker { dims 2 range -5 100 } }\n",
               "t.mat:1:29: phong: exponent takes values in [0, 1e+06]; the generator's range is [-5, 100] (set it "
               "with `range LO HI`)");
    load_fails_with("material m lambert { reflectance image { file \"/nonexistent/label.png\" } }\n",
                    "t.mat:1:47: image '/nonexistent/label.png'");
    load_fails_with("material m lambert { reflectance mix { by checker { dims 2 } a rgb 0.1 0.1 0.1 b rgb 1.5 1.5 "
                    "1.5 } }\n",
                    "t.mat:1:22: lambert: reflectance has the value 1.5");
    load_fails_with("material m phong { diffuse mix { by checker { dims 2 } a rgb 0.1 0.1 0.1 b rgb 0.8 0.8 0.8 } "
                    "specular rgb 0.3 0.3 0.3 }\n",
                    "phong: kd + ks + mirror is");
    load_fails_with("material m lambert { reflectance mix { by checker { dims 2 } a rgb 0.1 0.1 0.1 } }\n",
                    "mix: needs by, a and b");
    load_fails_with("material m lambert { reflectance mix { by checker { dims 2 } a rgb 0.1 0.1 0.1 c 1 } }\n",
                    "t.mat:1:80: mix: unknown parameter 'c' (expected one of: by, a, b)");
    load_fails_with("material m layer { top dielectric { } bottom lambert { } albedo mix { by checker { dims 2 } "
                    "a rgb 0.1 0.1 0.1 b rgb 1.5 1.5 1.5 } }\n",
                    "layer: albedo has the value 1.5");
    load_fails("material m layer { top dielectric { } bottom lambert { } thickness checker { dims 2 range 1 200 } }\n",
               "t.mat:1:68: layer: thickness takes values in [0, 100]; the generator's range is [1, 200] (set it with "
               "`range LO HI`)");
    load_fails_with("material m dielectric { tint mix { by checker { dims 2 } a rgb 0 0 0 b rgb 1 1 1 } }\n",
                    "t.mat:1:25: dielectric: tint cannot be textured");
    load_fails("material m plastic { roughness checker { dims 2 } }\n",
               "t.mat:1:32: plastic: a textured roughness must stay >= 0.001, rough everywhere (the generator's "
               "range starts at 0; whether the coat is smooth is decided at creation)");
    load_fails_with("material m plastic { reflectance mix { by checker { dims 2 } a rgb 0.1 0.1 0.1 b rgb 1.5 1.5 "
                    "1.5 } }\n",
                    "plastic: reflectance has the value 1.5");
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_range_maps_linearly),
        cmocka_unit_test(test_mix_is_exact_in_cells),
        cmocka_unit_test(test_memoised_without_allocation),
        cmocka_unit_test(test_plastic_textured),
        cmocka_unit_test(test_dielectric_textured),
        cmocka_unit_test(test_layer_textured),
        cmocka_unit_test(test_numbers_stay_numbers),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
