/* test_material_alloc.c - the per-ray path of the built-in materials makes no allocation (colour
 * arithmetic and material calls on a scratch arena), and their constructors fail cleanly (status,
 * message, nothing leaked) when any allocation fails. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/material.h"
#include "generic/materials.h"
#include "generic/surfpoint.h"
#include "test_alloc.h"

typedef struct Set {
    GMaterial *lambert, *phong, *mirror, *glass, *emitter;
} Set;

static void make_set(const GColorModel *m, GScratch *s, Set *set)
{
    GError err;
    GColor kd, ks, mir, a, L;
    double half[3] = {0.5, 0.4, 0.3}, low[3] = {0.2, 0.2, 0.2}, tenth[3] = {0.1, 0.1, 0.1};
    double coef[3] = {0.3, 0.1, 0.05}, light[3] = {4, 4, 4};
    assert_int_equal(gcolor_scratch(&kd, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&ks, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&mir, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&L, m, s), G_OK);
    assert_int_equal(gcolor_from_rgb(&kd, half, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_from_rgb(&ks, low, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_from_rgb(&mir, tenth, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_from_rgb(&a, coef, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_from_rgb(&L, light, GCOLOR_LIGHT), G_OK);
    for (int i = 0; i < m->nvalues; i++) {
        a.v[i] = fmaxf(a.v[i], 0.0f);
        L.v[i] = fmaxf(L.v[i], 0.0f);
    }
    assert_int_equal(glambert_create(m, &kd, &set->lambert, &err), G_OK);
    GPhongParams pp = {&kd, &ks, 30.0, &mir};
    assert_int_equal(gphong_create(m, &pp, &set->phong, &err), G_OK);
    assert_int_equal(gmirror_create(m, &kd, &set->mirror, &err), G_OK);
    GDielectricParams dp = {gdispersion_cauchy(1.5046, 0.0042, 0.0), &a, NULL};
    assert_int_equal(gdielectric_create(m, &dp, &set->glass, &err), G_OK);
    assert_int_equal(gemitter_create(m, &L, 0, &set->emitter, &err), G_OK);
}

static void free_set(Set *set)
{
    gmaterial_unref(set->lambert);
    gmaterial_unref(set->phong);
    gmaterial_unref(set->mirror);
    gmaterial_unref(set->glass);
    gmaterial_unref(set->emitter);
}

static void zero_alloc_case(const char *model_name)
{
    GError err;
    GColorModel *m;
    if (gcolormodel_create(model_name, NULL, &m, &err) != G_OK) {
        print_message("colour model '%s' not available: %s\n", model_name, err.message);
        skip();
    }
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    Set set;
    make_set(m, s, &set);
    GSurfPoint sp;
    gsurfpoint_init(&sp, m, s);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.from = NULL;
    sp.to = set.glass;

    static TuAlloc c;
    tu_alloc_install(&c);
    double sum = 0.0;
    for (int k = 0; k < 1000; k++) {
        GScratchMark mark = gscratch_mark(s);
        gsurfpoint_invalidate(&sp);
        GColor illum, r, ri, n1;
        int rc = gcolor_scratch(&illum, m, s) | gcolor_scratch(&r, m, s) | gcolor_scratch(&ri, m, s) |
                 gcolor_scratch(&n1, m, s);
        double th = 0.001 * k, one[3] = {1.0, 0.8, 0.6};
        rc |= gcolor_from_rgb(&illum, one, GCOLOR_LIGHT);
        GVec3 in = gvec3(sin(th), 0, cos(th)), out = gvec3(-sin(th), 0, cos(th)), view = gvec3_neg(out), d;
        GVec3 other = gvec3_normalize(gvec3(0.2, 0.3, 0.9));
        const GMaterial *all[5] = {set.lambert, set.phong, set.mirror, set.glass, set.emitter};
        for (int i = 0; i < 5; i++) {
            sp.material = all[i];
            rc |= gmaterial_reflection(all[i], &sp, in, &illum, out, &r);
            sum += gcolor_brightness(&r);
            rc |= gmaterial_reflection(all[i], &sp, other, &illum, out, &r);
            sum += gcolor_brightness(&r);
            assert_true(gmaterial_reflection_dir(all[i], &sp, view, &d) >= 0); /* 1: valid, 0: none */
            rc |= gmaterial_refraction_index(sp.from, &sp, &ri);
            rc |= gmaterial_refraction_index(all[i], &sp, &n1);
            rc |= gcolor_div(&ri, &ri, &n1);
            if (gmaterial_refraction_dir(all[i], &sp, view, &ri, &d) == 1)
                rc |= gmaterial_refraction(all[i], &sp, d, &illum, &ri, out, &r);
            sum += gcolor_brightness(&r);
            rc |= gmaterial_absorption(all[i], &sp, &illum, 0.5 + 0.001 * k, &r);
            rc |= gmaterial_absorption(all[i], &sp, &r, 0.25, &r); /* in place */
            sum += gcolor_brightness(&r);
            rc |= gmaterial_emission(all[i], &sp, out, &r);
            rc |= gmaterial_ambient(all[i], &sp, &illum, &r);
            rc |= gmaterial_diffuse(all[i], &sp, &r);
            /* colour arithmetic */
            rc |= gcolor_add(&r, &r, &illum);
            rc |= gcolor_mul(&r, &r, &illum);
            rc |= gcolor_scale(&r, &r, 0.5);
            rc |= gcolor_pow(&r, &r, 1.5);
            rc |= gcolor_add_scaled(&r, &illum, 0.25);
            sum += gcolor_brightness(&r);
        }
        assert_int_equal(rc, G_OK);
        gscratch_release(s, mark);
    }
    gmem_set_allocator(NULL);
    print_message("%s: 1000 rounds of every material method: %ld allocations, %ld frees (sum %.3f)\n", model_name,
                  c.calls, c.frees, sum);
    assert_int_equal(c.calls, 0);
    assert_int_equal(c.frees, 0);
    assert_true(sum > 0.0 && isfinite(sum));
    free_set(&set);
    gscratch_destroy(s);
    gcolormodel_destroy(m);
}

static void test_zero_alloc(void **state) { zero_alloc_case(*state); }

/* Every constructor, with allocation number k failing for every k until it succeeds: the status is
 * G_ERR_NOMEM with a message, *out is NULL, and everything allocated was freed again. */
static void test_constructors_out_of_memory(void **state)
{
    (void)state;
    GError err;
    GColorModel *m;
    assert_int_equal(gcolormodel_create("rgb", NULL, &m, &err), G_OK);
    GScratch *s = gscratch_create(4096);
    Set set;
    make_set(m, s, &set);
    free_set(&set);
    for (int which = 0; which < 5; which++) {
        int succeeded = 0;
        for (long k = 0; k < 50 && !succeeded; k++) {
            static TuAlloc c; /* fails from call k on */
            gscratch_reset(s);
            GColor kd, ks;
            double a[3] = {0.3, 0.2, 0.1};
            assert_int_equal(gcolor_scratch(&kd, m, s), G_OK);
            assert_int_equal(gcolor_scratch(&ks, m, s), G_OK);
            assert_int_equal(gcolor_from_rgb(&kd, a, GCOLOR_REFLECTANCE), G_OK);
            assert_int_equal(gcolor_from_rgb(&ks, a, GCOLOR_REFLECTANCE), G_OK);
            GPhongParams pp = {&kd, &ks, 10.0, &ks};
            GDielectricParams dp = {gdispersion_constant(1.5), &kd, &ks};
            GMaterial *out = (GMaterial *)&c;
            c = (TuAlloc){.fail_call = k + 1, .fail_after = 1};
            tu_alloc_install(&c);
            int rc = which == 0   ? glambert_create(m, &kd, &out, &err)
                     : which == 1 ? gphong_create(m, &pp, &out, &err)
                     : which == 2 ? gmirror_create(m, &kd, &out, &err)
                     : which == 3 ? gdielectric_create(m, &dp, &out, &err)
                                  : gemitter_create(m, &kd, 1, &out, &err);
            if (rc == G_OK) {
                succeeded = 1;
                assert_non_null(out);
                gmaterial_unref(out);
                assert_int_equal(c.calls, c.frees);
                assert_true(k >= 2); /* at least the instance and one colour */
            } else {
                assert_int_equal(rc, G_ERR_NOMEM);
                assert_null(out);
                assert_true(err.message[0] != '\0');
                assert_int_equal(c.frees, k); /* the k allocations that succeeded were all freed */
            }
            gmem_set_allocator(NULL);
        }
        assert_true(succeeded);
    }
    gscratch_destroy(s);
    gcolormodel_destroy(m);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        {"test_zero_alloc (rgb)", test_zero_alloc, NULL, NULL, (void *)"rgb"},
        {"test_zero_alloc (spectrum)", test_zero_alloc, NULL, NULL, (void *)"spectrum"},
        cmocka_unit_test(test_constructors_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
