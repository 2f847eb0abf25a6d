/* test_optics.c - the geometric helpers of lib/core/optics.c: the ideal-mirror and ideal-refraction tests against
 * their definitions (the cosine between the given direction and the ideal one above 1 - 1e-6), the orthonormal
 * frame, and the moments of the cosine and uniform hemisphere samplers. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "generic/material.h"

#include <math.h>
#include <stdlib.h>

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

static GVec3 rnd_vec(unsigned *s, double scale)
{
    return gvec3(scale * (2 * rnd(s) - 1), scale * (2 * rnd(s) - 1), scale * (2 * rnd(s) - 1));
}

/* The definition, with square roots. */
static int mirror_pair_reference(GVec3 in, GVec3 n, GVec3 out)
{
    GVec3 ideal = gvec3_sub(gvec3_scale(n, 2.0 * gvec3_dot(in, n)), in);
    double li = gvec3_length(ideal), lo = gvec3_length(out);
    if (li == 0.0 || lo == 0.0)
        return 0;
    return gvec3_dot(ideal, out) / (li * lo) > 1.0 - 1e-6;
}

static void test_mirror_pair(void **state)
{
    (void)state;
    unsigned s = 7;
    int agree = 0, pairs = 0;
    for (int i = 0; i < 200000; i++) {
        GVec3 n = gvec3_normalize(rnd_vec(&s, 1.0)), in = rnd_vec(&s, i % 3 ? 1.0 : 1e3);
        GVec3 out = gvec3_sub(gvec3_scale(n, 2.0 * gvec3_dot(in, n)), in);
        /* half of the cases near the ideal direction, at angles around the 1e-6 threshold in cosine */
        if (i % 2)
            out = gvec3_add(out, gvec3_scale(rnd_vec(&s, 1.0), gvec3_length(out) * 3e-3 * rnd(&s)));
        else
            out = rnd_vec(&s, 2.0);
        int want = mirror_pair_reference(in, n, out);
        pairs += want;
        agree += gmaterial_is_mirror_pair(in, n, out) == want;
    }
    assert_int_equal(agree, 200000);
    assert_true(pairs > 1000 && pairs < 99000); /* both answers occur */
    GVec3 n = gvec3(0, 0, 1);
    assert_false(gmaterial_is_mirror_pair(gvec3(0, 0, 0), n, n));
    assert_false(gmaterial_is_mirror_pair(n, n, gvec3(0, 0, 0)));
    assert_true(gmaterial_is_mirror_pair(gvec3(1, 0, 1), n, gvec3(-2, 0, 2)));
    assert_false(gmaterial_is_mirror_pair(gvec3(1, 0, 1), n, gvec3(2, 0, -2)));
}

/* The definition: the normalised refraction direction, then the cosine with the square root of |in|. */
static int refraction_pair_reference(GVec3 view, GVec3 n, double eta, GVec3 in)
{
    GVec3 t;
    double li = gvec3_length(in);
    if (!goptics_refract(view, n, eta, &t) || li == 0.0)
        return 0;
    return gvec3_dot(t, in) > (1.0 - 1e-6) * li;
}

static void test_refraction_pair(void **state)
{
    (void)state;
    unsigned s = 13;
    int agree = 0, pairs = 0, tir = 0;
    for (int i = 0; i < 200000; i++) {
        GVec3 n = gvec3_normalize(rnd_vec(&s, 1.0)), view = gvec3_normalize(rnd_vec(&s, 1.0)), t;
        if (gvec3_dot(view, n) > 0.0)
            view = gvec3_neg(view); /* arriving against the normal */
        double eta = i % 4 == 0 ? 1.5 : i % 4 == 1 ? 1.0 / 1.5 : 0.3 + 2.0 * rnd(&s);
        GVec3 in;
        if (goptics_refract(view, n, eta, &t)) {
            in = gvec3_scale(t, i % 3 ? 1.0 : 1e3 * rnd(&s) + 1e-3);
            /* half of the cases near the ideal direction, at angles around the 1e-6 threshold in cosine */
            if (i % 2)
                in = gvec3_add(in, gvec3_scale(rnd_vec(&s, 1.0), gvec3_length(in) * 3e-3 * rnd(&s)));
            else
                in = rnd_vec(&s, 2.0);
        } else {
            tir++;
            in = rnd_vec(&s, 1.0);
        }
        int want = refraction_pair_reference(view, n, eta, in);
        pairs += want;
        agree += goptics_is_refraction_pair(view, n, eta, in) == want;
    }
    assert_int_equal(agree, 200000);
    assert_true(pairs > 1000 && pairs < 99000 && tir > 1000); /* both answers and total reflection occur */
    GVec3 n = gvec3(0, 0, 1), v = gvec3(0, 0, -1);
    assert_true(goptics_is_refraction_pair(v, n, 1.5, v));              /* normal incidence goes straight on */
    assert_false(goptics_is_refraction_pair(v, n, 1.5, gvec3(0, 0, 0))); /* no direction */
    assert_false(goptics_is_refraction_pair(v, n, 1.5, gvec3(0, 0, 1))); /* backwards */
    GVec3 grazing = gvec3_normalize(gvec3(1, 0, -0.1));
    assert_false(goptics_is_refraction_pair(grazing, n, 1.5, grazing)); /* past the critical angle */
}

static void test_frame(void **state)
{
    (void)state;
    unsigned s = 11;
    for (int i = 0; i < 10000; i++) {
        GVec3 n = gvec3_normalize(rnd_vec(&s, 1.0)), t, b;
        if (i == 0)
            n = gvec3(0, 0, -1); /* the branch point of the construction */
        goptics_frame(n, &t, &b);
        assert_true(fabs(gvec3_dot(t, t) - 1.0) < 1e-12 && fabs(gvec3_dot(b, b) - 1.0) < 1e-12);
        assert_true(fabs(gvec3_dot(t, b)) < 1e-12 && fabs(gvec3_dot(t, n)) < 1e-12 && fabs(gvec3_dot(b, n)) < 1e-12);
        assert_true(gvec3_dot(gvec3_cross(t, b), n) > 0.999999); /* right-handed */
    }
}

/* E[cos] = 2/3 under the cosine density, 1/2 under the uniform one; E[cos^2] = 1/2 and 1/3; all above the
 * plane. 4 standard errors at 1e5 samples. */
static void test_hemisphere_moments(void **state)
{
    (void)state;
    unsigned s = 3;
    GVec3 n = gvec3_normalize(gvec3(0.3, -0.5, 0.8));
    const int N = 100000;
    for (int kind = 0; kind < 2; kind++) {
        double m1 = 0.0, m2 = 0.0;
        for (int i = 0; i < N; i++) {
            GVec3 d =
                kind ? goptics_sample_hemisphere(n, rnd(&s), rnd(&s)) : goptics_sample_cosine(n, rnd(&s), rnd(&s));
            assert_true(fabs(gvec3_length(d) - 1.0) < 1e-12);
            double c = gvec3_dot(d, n);
            assert_true(c >= 0.0);
            m1 += c;
            m2 += c * c;
        }
        m1 /= N;
        m2 /= N;
        double want1 = kind ? 0.5 : 2.0 / 3.0, want2 = kind ? 1.0 / 3.0 : 0.5;
        double se = sqrt((want2 - want1 * want1) / N);
        assert_true(fabs(m1 - want1) < 4 * se);
        assert_true(fabs(m2 - want2) < 0.01);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mirror_pair),
        cmocka_unit_test(test_refraction_pair),
        cmocka_unit_test(test_frame),
        cmocka_unit_test(test_hemisphere_moments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
