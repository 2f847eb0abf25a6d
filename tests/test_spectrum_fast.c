/* test_spectrum_fast.c - the spectrum model's own operations (colormodels/spectrum.c: black, add, mul, scale, div,
 * brightness and to_xyz, unrolled on the default grid of 81 samples) equal bit for bit (or NaN where the kit gives
 * NaN) to the kit's (gspectral_*, the generic loops): random values, zeros of both signs, NaN, infinities, huge and
 * denormal samples, zero divisors, the result in place of either operand; on the default grid and on another one
 * (41 samples, where the model takes the kit's operations). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/spectral.h"
#include "test_util.h"

enum { ROUNDS = 200 };

/* A sample: mostly ordinary values of either sign, sometimes one of the edge cases. */
static float sample(unsigned *seed)
{
    static const float odd[] = {0.0f, -0.0f, NAN, INFINITY, -INFINITY, 3.0e38f, -3.0e38f, 1e-40f, -1e-40f, 1.0f};
    unsigned r = (unsigned)rand_r(seed);
    if (r % 8 == 0)
        return odd[(r / 8) % tu_floats(odd)];
    return (float)rand_r(seed) / (float)RAND_MAX * 4.0f - 1.0f;
}

static void fill_random(GColor *c, unsigned *seed)
{
    for (int i = 0; i < c->model->nvalues; i++)
        c->v[i] = sample(seed);
}

/* The same float bit for bit, or both NaN: which of two NaN operands a sum passes on (its sign and payload) is
 * the compiler's choice of operand order, and a NaN is a NaN to every caller. */
static void assert_same_float(float a, float b)
{
    if (isnan(a) && isnan(b))
        return;
    assert_memory_equal(&a, &b, sizeof a);
}

static void assert_same_double(double a, double b)
{
    if (isnan(a) && isnan(b))
        return;
    assert_memory_equal(&a, &b, sizeof a);
}

/* the same floats and the same kind */
static void assert_same(const GColor *a, const GColor *b)
{
    assert_int_equal(a->kind, b->kind);
    for (int i = 0; i < a->model->nvalues; i++)
        assert_same_float(a->v[i], b->v[i]);
}

/* Every operation of the model against the kit's, on operands a and b (copied, so each call sees the same). */
static void compare_ops(const GColorModel *m, const GColor *a, const GColor *b, GColor *want, GColor *got, double s)
{
    assert_int_equal(gspectral_add(m, want, a, b), G_OK);
    assert_int_equal(gcolor_add(got, a, b), G_OK);
    assert_same(want, got);
    assert_int_equal(gspectral_mul(m, want, a, b), G_OK);
    assert_int_equal(gcolor_mul(got, a, b), G_OK);
    assert_same(want, got);
    assert_int_equal(gspectral_div(m, want, a, b), G_OK);
    assert_int_equal(gcolor_div(got, a, b), G_OK);
    assert_same(want, got);
    assert_int_equal(gspectral_scale(m, want, a, s), G_OK);
    assert_int_equal(gcolor_scale(got, a, s), G_OK);
    assert_same(want, got);
    assert_same_double(gspectral_brightness(m, a), gcolor_brightness(a));
    for (int role = 0; role < 2; role++) {
        double wx[3], gx[3];
        assert_int_equal(gspectral_to_xyz(m, a, (GColorRole)role, wx), G_OK);
        assert_int_equal(gcolor_to_xyz(a, (GColorRole)role, gx), G_OK);
        for (int c = 0; c < 3; c++)
            assert_same_double(wx[c], gx[c]);
    }
    gspectral_black(m, want);
    memset(got->v, 0xff, (size_t)m->nvalues * sizeof(float)); /* NaNs the black must overwrite */
    gcolor_black(got);
    assert_same(want, got);
}

/* The same with the result in place of a, then of b. */
static void compare_in_place(const GColorModel *m, const GColor *a, const GColor *b, GColor *x, GColor *want,
                             double s)
{
    int (*kit[])(const GColorModel *, GColor *, const GColor *, const GColor *) = {gspectral_add, gspectral_mul,
                                                                                   gspectral_div};
    int (*api[])(GColor *, const GColor *, const GColor *) = {gcolor_add, gcolor_mul, gcolor_div};
    for (int op = 0; op < 3; op++)
        for (int side = 0; side < 2; side++) {
            assert_int_equal(kit[op](m, want, a, b), G_OK);
            assert_int_equal(gcolor_copy(x, side ? b : a), G_OK);
            assert_int_equal(side ? api[op](x, a, x) : api[op](x, x, b), G_OK);
            assert_same(want, x);
        }
    assert_int_equal(gspectral_scale(m, want, a, s), G_OK);
    assert_int_equal(gcolor_copy(x, a), G_OK);
    assert_int_equal(gcolor_scale(x, x, s), G_OK);
    assert_same(want, x);
}

static void check_model(const GColorModelOptions *opt, int want_n)
{
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create("spectrum", opt, &m, &err), G_OK);
    assert_int_equal(m->nvalues, want_n);
    GScratch *arena = gscratch_create(0);
    assert_non_null(arena);
    GColor a, b, x, want, got;
    assert_int_equal(gcolor_scratch(&a, m, arena), G_OK);
    assert_int_equal(gcolor_scratch(&b, m, arena), G_OK);
    assert_int_equal(gcolor_scratch(&x, m, arena), G_OK);
    assert_int_equal(gcolor_scratch(&want, m, arena), G_OK);
    assert_int_equal(gcolor_scratch(&got, m, arena), G_OK);
    const double scales[] = {0.0, -0.0, 1.0, -2.5, 1e-3, 1e30, 1e300, INFINITY, NAN, 0.1};
    unsigned seed = 12345;
    for (int r = 0; r < ROUNDS; r++) {
        fill_random(&a, &seed);
        fill_random(&b, &seed);
        if (r % 10 == 1) /* whole zero divisors and a zero last sample */
            gcolor_black(&b);
        if (r % 10 == 2)
            a.v[m->nvalues - 1] = b.v[m->nvalues - 1] = 0.0f;
        double s = scales[r % tu_floats(scales)];
        compare_ops(m, &a, &b, &want, &got, s);
        compare_in_place(m, &a, &b, &x, &want, s);
    }
    /* ordinary numbers give ordinary results: the comparison above is not of NaNs alone */
    assert_int_equal(gcolor_fill(&a, 0.5), G_OK);
    assert_int_equal(gcolor_fill(&b, 0.25), G_OK);
    assert_int_equal(gcolor_div(&got, &a, &b), G_OK);
    for (int i = 0; i < m->nvalues; i++)
        assert_true(got.v[i] == 2.0f);
    assert_int_equal(gcolor_scale(&got, &a, 3.0), G_OK);
    assert_true(got.v[m->nvalues - 1] == 1.5f && got.v[0] == 1.5f);
    assert_near(gcolor_brightness(&a), 0.5, 1e-6);
    double xyz[3];
    assert_int_equal(gcolor_to_xyz(&a, GCOLOR_REFLECTANCE, xyz), G_OK);
    assert_near(xyz[1], 0.5, 1e-3); /* a reflectance of 0.5 under the white point: Y = 0.5 */
    gscratch_destroy(arena);
    gcolormodel_destroy(m);
}

static void test_default_grid(void **state)
{
    (void)state;
    check_model(NULL, 81);
}

static void test_other_grid(void **state)
{
    (void)state;
    GColorModelOptions opt = {.step_nm = 10.0};
    check_model(&opt, 41);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_grid),
        cmocka_unit_test(test_other_grid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
