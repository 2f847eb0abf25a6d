/* test_gtrace_sampler.c - the path tracer's sample values (examples/gtrace/trace/sampler.c): the Sobol direction
 * numbers against their recurrence from Joe and Kuo's polynomials, the stratification of the first 2^m points (each
 * dimension a (0,m,1)-net, the first two dimensions of a group a (0,m,2)-net) before and after the per-pixel shuffle
 * and scrambling, the scramble a bijection that keeps the leading bits' order, and every value uniform over pixels
 * (chi-square), with groups independent of each other. */
#include "trace/sampler.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

/* The direction numbers v_1 .. v_32 of a dimension of primitive polynomial degree s with coefficient bits a and
 * initial numbers m (Bratley and Fox's recurrence); s = 0: the van der Corput sequence. */
static void direction_numbers(int s, unsigned a, const unsigned *m, uint32_t v[33])
{
    for (int k = 1; k <= 32; k++) {
        if (s == 0) {
            v[k] = 1u << (32 - k);
        } else if (k <= s) {
            v[k] = (uint32_t)m[k - 1] << (32 - k);
        } else {
            uint32_t x = v[k - s] ^ (v[k - s] >> s);
            for (int i = 1; i < s; i++)
                if ((a >> (s - 1 - i)) & 1u)
                    x ^= v[k - i];
            v[k] = x;
        }
    }
}

static void test_direction_numbers(void **state)
{
    (void)state;
    /* Joe and Kuo (new-joe-kuo-6.21201): dimension 2: s 1, a 0, m 1; 3: s 2, a 1, m 1 3; 4: s 3, a 1, m 1 3 1 */
    static const unsigned m2[] = {1}, m3[] = {1, 3}, m4[] = {1, 3, 1};
    const int s[4] = {0, 1, 2, 3};
    const unsigned a[4] = {0, 0, 1, 1};
    const unsigned *m[4] = {NULL, m2, m3, m4};
    for (int d = 0; d < 4; d++) {
        uint32_t v[33];
        direction_numbers(s[d], a[d], m[d], v);
        for (int k = 1; k <= 32; k++)
            assert_int_equal(sobol_bits(1u << (k - 1), d), v[k]);
        /* and linearity: point i xor j is the xor of the points */
        for (uint32_t i = 0; i < 300; i += 7)
            assert_int_equal(sobol_bits(i ^ 0x35u, d), sobol_bits(i, d) ^ sobol_bits(0x35u, d));
    }
    /* the published sequence's first points */
    static const double first[5][4] = {
        {0, 0, 0, 0}, {0.5, 0.5, 0.5, 0.5}, {0.25, 0.75, 0.75, 0.75}, {0.75, 0.25, 0.25, 0.25},
        {0.125, 0.625, 0.375, 0.125}};
    for (uint32_t i = 0; i < 5; i++)
        for (int d = 0; d < 4; d++)
            assert_true(sobol_bits(i, d) * (1.0 / 4294967296.0) == first[i][d]);
}

/* 1 when the n = 2^m values x[i] (and y[i] when y is given) are stratified: one in each of the 2^m intervals (1D),
 * or one in each elementary box of 2^k by 2^(m-k) for every k (2D, a (0,m,2)-net). */
static int is_net(const double *x, const double *y, int m)
{
    int n = 1 << m;
    unsigned char *seen = calloc((size_t)n, 1);
    int ok = 1;
    for (int k = 0; k <= (y ? m : 0) && ok; k++) {
        memset(seen, 0, (size_t)n);
        for (int i = 0; i < n && ok; i++) {
            int cx = y ? (int)(x[i] * (1 << k)) : (int)(x[i] * n);
            int cy = y ? (int)(y[i] * (1 << (m - k))) : 0;
            int cell = y ? (cx << (m - k)) | cy : cx;
            ok = !seen[cell]++;
        }
    }
    free(seen);
    return ok;
}

static void test_stratified(void **state)
{
    (void)state;
    enum { M = 10, N = 1 << M };
    static double v[4][N];
    /* the unscrambled points */
    for (int i = 0; i < N; i++)
        for (int d = 0; d < 4; d++)
            v[d][i] = sobol_bits((uint32_t)i, d) * (1.0 / 4294967296.0);
    for (int m = 1; m <= M; m++) {
        for (int d = 0; d < 4; d++)
            assert_true(is_net(v[d], NULL, m));
        assert_true(is_net(v[0], v[1], m));
    }
    /* dimensions 0 and 2 are not a (0,m,2)-net (t = 1): the check sees it */
    int all = 1;
    for (int m = 1; m <= M; m++)
        all &= is_net(v[0], v[2], m);
    assert_false(all);
    /* a pixel's shuffled, scrambled samples, in several pixels and groups */
    const uint64_t pixels[] = {0, 1, 4711, 65535ULL * 65536ULL};
    for (int p = 0; p < 4; p++) {
        for (uint32_t g = 0; g < 40; g += 13) {
            for (int i = 0; i < N; i++) {
                SamplePoint pt = sample_point(pixels[p], (uint32_t)i);
                for (int d = 0; d < 4; d++)
                    v[d][i] = sample_value(&pt, 4 * g + (uint32_t)d);
            }
            for (int m = 1; m <= M; m++) {
                for (int d = 0; d < 4; d++)
                    assert_true(is_net(v[d], NULL, m));
                assert_true(is_net(v[0], v[1], m));
            }
            for (int i = 0; i < N; i++)
                for (int d = 0; d < 4; d++)
                    assert_true(v[d][i] >= 0.0 && v[d][i] < 1.0);
        }
    }
}

static void test_scramble(void **state)
{
    (void)state;
    /* a bijection that maps each interval of 2^(32-k) values into one such interval (nested: the leading k bits of
     * the result depend on the leading k bits of the input only) */
    for (uint32_t seed = 1; seed < 2000000000u; seed += 411111111u) {
        for (int k = 1; k <= 12; k++) {
            uint32_t mask = ~0u << (32 - k);
            for (uint32_t x = 0; x < 4000; x++) {
                uint32_t a = x * 2654435761u, b = (a & mask) | (~a & ~mask);
                assert_int_equal(owen_scramble(a, seed) & mask, owen_scramble(b, seed) & mask);
            }
        }
        /* a permutation of the 16 leading-bit patterns, and different seeds give different permutations */
        unsigned seen = 0;
        for (uint32_t x = 0; x < 16; x++)
            seen |= 1u << (owen_scramble(x << 28, seed) >> 28);
        assert_int_equal(seen, 0xffffu);
    }
    int differ = 0;
    for (uint32_t x = 0; x < 64; x++)
        differ += owen_scramble(x << 26, 1u) != owen_scramble(x << 26, 2u);
    assert_true(differ > 32);
}

/* Pearson's chi-square of the counts in k bins, n samples in all, against equal expectations. */
static double chi_square(const int *count, int k, int n)
{
    double e = (double)n / k, x = 0.0;
    for (int i = 0; i < k; i++)
        x += (count[i] - e) * (count[i] - e) / e;
    return x;
}

static void test_uniform_over_pixels(void **state)
{
    (void)state;
    /* a fixed sample and dimension over 65536 pixels: 64 bins (63 degrees of freedom: the 99.9th percentile is
     * 103.4); and two dimensions of different groups jointly in 8 x 8 bins (independent groups) */
    enum { NPIX = 65536, K = 64 };
    const uint32_t dims[][2] = {{0, 4}, {1, 9}, {5, 6}, {4, 12}, {7, 100}, {2, 3}};
    for (int s = 0; s < 3; s++) {
        uint32_t index = (uint32_t[]){0, 5, 1000}[s];
        for (int t = 0; t < 6; t++) {
            int c1[K] = {0}, c2[K] = {0};
            for (int p = 0; p < NPIX; p++) {
                SamplePoint pt = sample_point((uint64_t)p, index);
                double a = sample_value(&pt, dims[t][0]), b = sample_value(&pt, dims[t][1]);
                c1[(int)(a * K)]++;
                c2[(int)(a * 8) * 8 + (int)(b * 8)]++;
            }
            double x1 = chi_square(c1, K, NPIX), x2 = chi_square(c2, K, NPIX);
            print_message("sample %u dims %u, %u: chi-square 1D %.1f, 2D %.1f (63 dof)\n", index, dims[t][0],
                          dims[t][1], x1, x2);
            assert_true(x1 < 103.4);
            assert_true(x2 < 103.4);
        }
    }
    /* the check sees a dependence: a dimension against itself */
    int c[K] = {0};
    for (int p = 0; p < NPIX; p++) {
        SamplePoint pt = sample_point((uint64_t)p, 3);
        double a = sample_value(&pt, 8);
        c[(int)(a * 8) * 8 + (int)(a * 8)]++;
    }
    assert_true(chi_square(c, K, NPIX) > 1000.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_direction_numbers),
        cmocka_unit_test(test_stratified),
        cmocka_unit_test(test_scramble),
        cmocka_unit_test(test_uniform_over_pixels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
