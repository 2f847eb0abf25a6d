/* test_spectral_kernels.c - the vector kernels of spectral_kernels.h that have a scalar definition in their
 * comment (division with zero where the divisor is zero, axpy with the product in double, the finiteness and
 * sign test) give bit for bit the scalar definition's results, for every length from 0 to 90 (the vector part
 * and the tail), with operands that alias the output, and with zeros, negative zeros, infinities and NaNs among
 * the samples. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "generic/spectral_kernels.h"

enum { N = 90 };

static uint32_t rng_state = 12345u;
static float rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    uint32_t r = rng_state >> 8;
    switch (r % 11) {
    case 0: return 0.0f;
    case 1: return -0.0f;
    default: return ((float)(r % 20000) - 10000.0f) / 997.0f;
    }
}

static void fill(float *v, int n)
{
    for (int i = 0; i < n; i++)
        v[i] = rnd();
}

static int same_bits(const float *a, const float *b, int n) { return memcmp(a, b, (size_t)n * sizeof *a) == 0; }

static void test_div_equals_scalar(void **state)
{
    (void)state;
    for (int round = 0; round < 20; round++)
        for (int n = 0; n <= N; n++) {
            float a[N], b[N], o[N], ref[N];
            fill(a, n);
            fill(b, n);
            for (int i = 0; i < n; i++)
                ref[i] = b[i] != 0.0f ? a[i] / b[i] : 0.0f;
            gspectral_kdiv(o, a, b, n);
            assert_true(same_bits(o, ref, n));
            gspectral_kdiv(a, a, b, n); /* out aliases a */
            assert_true(same_bits(a, ref, n));
        }
}

static void test_axpyd_equals_scalar(void **state)
{
    (void)state;
    const double scales[] = {0.0, 1.0, -0.3, 1.0 / 3.0, 1e-30, 7.123456789012345};
    for (int k = 0; k < (int)(sizeof scales / sizeof *scales); k++)
        for (int n = 0; n <= N; n++) {
            float a[N], b[N], o[N], ref[N];
            fill(a, n);
            fill(b, n);
            for (int i = 0; i < n; i++)
                ref[i] = b[i] + (float)(a[i] * scales[k]);
            gspectral_kaxpyd(o, scales[k], a, b, n);
            assert_true(same_bits(o, ref, n));
            gspectral_kaxpyd(b, scales[k], a, b, n); /* out aliases b, as gcolor_add_scaled does */
            assert_true(same_bits(b, ref, n));
        }
}

static void test_finite_equals_scalar(void **state)
{
    (void)state;
    const float odd[] = {INFINITY, -INFINITY, NAN, -1.0f, -0.0f, 0.0f, 1e38f, -1e-40f};
    for (int n = 1; n <= N; n++)
        for (int pos = 0; pos < n; pos += 7)
            for (int k = 0; k < (int)(sizeof odd / sizeof *odd); k++) {
                float a[N];
                for (int i = 0; i < n; i++)
                    a[i] = (float)(i % 5) * 0.25f; /* finite, not negative */
                a[pos] = odd[k];
                for (int nonneg = 0; nonneg <= 1; nonneg++) {
                    int ref = 1;
                    for (int i = 0; i < n; i++)
                        if (!isfinite(a[i]) || (nonneg && a[i] < 0.0f))
                            ref = 0;
                    assert_int_equal(gspectral_kfinite(a, n, nonneg), ref);
                }
            }
    assert_int_equal(gspectral_kfinite(NULL, 0, 1), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_div_equals_scalar),
        cmocka_unit_test(test_axpyd_equals_scalar),
        cmocka_unit_test(test_finite_equals_scalar),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
