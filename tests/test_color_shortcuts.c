/* test_color_shortcuts.c - lib/color/color_shortcuts.c in every registered colour model (taken from the registry):
 * gcolor_is_black on black, each single non-zero sample (in the vector blocks and in the tail), -0.0, NaN and
 * infinities, tiny values, all agreeing with gcolor_brightness(c) == 0.0; gcolor_mul_scaled equal bit for bit to
 * gcolor_mul then gcolor_scale, also in place; the bispectral model's matrices; and a plug-in model whose vectors
 * are not plain samples (its own fill), for which both take the model's own operations, not its floats; and the
 * spectrum model on grids of 3 to 531 samples (no whole 8-sample block, one, many, more than 16). */
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
#include "generic/registry.h"
#include "test_util.h"

enum { MAX_MODELS = 64 };

static int all_models(GColorModel **out)
{
    const GTypeInfo *types[MAX_MODELS];
    int n = gregistry_list(GKIND_COLORMODEL, types, MAX_MODELS);
    assert_true(n > 0 && n <= MAX_MODELS);
    for (int i = 0; i < n; i++) {
        GError err;
        assert_int_equal(gcolormodel_create(types[i]->name, NULL, &out[i], &err), G_OK);
    }
    return n;
}

/* is_black against the brightness, and the expected answer */
static void assert_black(const GColor *c, int want)
{
    double b = gcolor_brightness(c);
    assert_int_equal(gcolor_is_black(c), want);
    assert_int_equal(b == 0.0, want);
}

static void test_vectors_in_every_model(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models);
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    const float odd[] = {1.0f, -0.25f, 1e-30f, -1e-30f, INFINITY, -INFINITY, NAN};
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratchMark mark = gscratch_mark(s);
        GColor c;
        assert_int_equal(gcolor_scratch(&c, m, s), G_OK);
        assert_black(&c, 1); /* gcolor_scratch gives black */
        assert_int_equal(gcolor_fill(&c, 0.0), G_OK);
        assert_black(&c, 1);
        assert_int_equal(gcolor_fill(&c, 0.5), G_OK);
        assert_black(&c, 0);
        assert_int_equal(gcolor_scale(&c, &c, 0.0), G_OK);
        assert_black(&c, 1);
        /* every sample negative zero: black */
        for (int i = 0; i < m->nvalues; i++)
            c.v[i] = -0.0f;
        assert_black(&c, 1);
        /* one non-zero sample at every position, in every block and the tail */
        for (int i = 0; i < m->nvalues; i++)
            for (size_t j = 0; j < sizeof odd / sizeof *odd; j++) {
                gcolor_black(&c);
                c.v[i] = odd[j];
                assert_int_equal(gcolor_is_black(&c), 0);
                double b = gcolor_brightness(&c);
                assert_false(b == 0.0); /* NaN for NaN, > 0 otherwise */
                assert_true(isnan(odd[j]) ? isnan(b) : b > 0.0);
            }
        /* a light from RGB and its negative */
        const double rgb[3] = {0.2, 0.4, 0.6};
        assert_int_equal(gcolor_from_rgb(&c, rgb, GCOLOR_LIGHT), G_OK);
        assert_black(&c, 0);
        assert_int_equal(gcolor_scale(&c, &c, -1.0), G_OK);
        assert_black(&c, 0);
        gscratch_release(s, mark);
    }
    gscratch_destroy(s);
    for (int k = 0; k < nm; k++)
        gcolormodel_destroy(models[k]);
}

static void test_matrices(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models), with_matrices = 0;
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratchMark mark = gscratch_mark(s);
        GColor a;
        assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
        if (!tu_diagonal_matrix(m, &a)) {
            gscratch_release(s, mark);
            continue;
        }
        with_matrices++;
        int n = m->nsamples;
        assert_black(&a, 0);
        assert_int_equal(gcolor_scale(&a, &a, 0.0), G_OK); /* the zero matrix */
        assert_int_equal(a.kind, GCOLOR_MATRIX);
        assert_black(&a, 1);
        for (int e = 0; e < n * n; e++)
            a.v[e] = -0.0f;
        assert_black(&a, 1);
        /* one entry off the diagonal (re-radiation only), then one NaN */
        a.v[n - 1] = 0.25f;
        assert_black(&a, 0);
        a.v[n - 1] = 0.0f;
        a.v[(n - 1) * n] = NAN;
        assert_int_equal(gcolor_is_black(&a), 0);
        assert_true(isnan(gcolor_brightness(&a)));
        gscratch_release(s, mark);
    }
    assert_true(with_matrices > 0); /* bispectral */
    gscratch_destroy(s);
    for (int k = 0; k < nm; k++)
        gcolormodel_destroy(models[k]);
}

/* ---- a plug-in model whose vectors are not plain samples: value x is stored as x + 1 (black is all ones) ---- */

enum { OFF_N = 11 }; /* more than one block of eight */

static int off_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)opt;
    (void)err;
    self->nvalues = self->capacity = OFF_N;
    return G_OK;
}

static void off_black(const GColorModel *m, GColor *out)
{
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < m->nvalues; i++)
        out->v[i] = 1.0f;
}

static int off_fill(const GColorModel *m, GColor *out, double value)
{
    out->kind = GCOLOR_VECTOR;
    for (int i = 0; i < m->nvalues; i++)
        out->v[i] = (float)(value + 1.0);
    return G_OK;
}

static int off_unsupported(void) { return G_ERR_UNSUPPORTED; }

static int off_add(const GColorModel *m, GColor *o, const GColor *a, const GColor *b)
{
    (void)m, (void)o, (void)a, (void)b;
    return off_unsupported();
}

static int off_scale(const GColorModel *m, GColor *o, const GColor *a, double s)
{
    (void)m, (void)o, (void)a, (void)s;
    return off_unsupported();
}

static int off_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)m, (void)a, (void)role, (void)out;
    return off_unsupported();
}

static int off_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    (void)m, (void)in, (void)role, (void)out;
    return off_unsupported();
}

static double off_brightness(const GColorModel *m, const GColor *a)
{
    double s = 0.0;
    for (int i = 0; i < m->nvalues; i++)
        s += fabs(a->v[i] - 1.0);
    return s / m->nvalues;
}

static const GColorModelClass off_class = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "offset",
    .description = "a test model storing x + 1",
    .init = off_init,
    .black = off_black,
    .add = off_add,
    .mul = off_add,
    .scale = off_scale,
    .div = off_add,
    .pow = off_scale,
    .brightness = off_brightness,
    .to_nm = off_nm,
    .from_nm = off_from_nm,
    .fill = off_fill,
};

/* gcolor_mul_scaled(out, a, b, s) against gcolor_mul then gcolor_scale, bit for bit (memcmp) */
static void assert_mul_scaled(const GColorModel *m, GScratch *s, const GColor *a, const GColor *b, double k)
{
    GScratchMark mark = gscratch_mark(s);
    GColor want, got, inplace;
    assert_int_equal(gcolor_scratch(&want, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&got, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&inplace, m, s), G_OK);
    assert_int_equal(gcolor_mul(&want, a, b), G_OK);
    assert_int_equal(gcolor_scale(&want, &want, k), G_OK);
    assert_int_equal(gcolor_mul_scaled(&got, a, b, k), G_OK);
    assert_int_equal(got.kind, want.kind);
    size_t bytes = (size_t)(want.kind == GCOLOR_MATRIX ? m->capacity : m->nvalues) * sizeof(float);
    assert_memory_equal(got.v, want.v, bytes);
    assert_int_equal(gcolor_copy(&inplace, b), G_OK); /* out aliases b */
    assert_int_equal(gcolor_mul_scaled(&inplace, a, &inplace, k), G_OK);
    assert_memory_equal(inplace.v, want.v, bytes);
    gscratch_release(s, mark);
}

static void test_mul_scaled_is_mul_then_scale(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models);
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    const double scales[] = {1.0 / M_PI, 0.123456789, -2.5, 0.0, 1e-40};
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratchMark mark = gscratch_mark(s);
        GColor a, b, mat;
        assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&b, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&mat, m, s), G_OK);
        for (int i = 0; i < m->nvalues; i++) { /* awkward values, so that any other rounding shows */
            a.v[i] = 0.1f + 0.7f * (float)i / (float)(i + 3);
            b.v[i] = 3.3f - 0.31f * (float)i;
        }
        b.v[m->nvalues - 1] = -0.0f;
        for (size_t j = 0; j < sizeof scales / sizeof *scales; j++)
            assert_mul_scaled(m, s, &a, &b, scales[j]);
        if (tu_diagonal_matrix(m, &mat)) { /* matrix times light, and matrix times matrix: the model's own */
            mat.v[m->nsamples - 1] = 0.25f;
            assert_mul_scaled(m, s, &mat, &b, 0.3);
            assert_mul_scaled(m, s, &mat, &mat, 0.3);
        }
        gscratch_release(s, mark);
    }
    /* colours of two models */
    if (nm > 1) {
        GColor a, b;
        assert_int_equal(gcolor_scratch(&a, models[0], s), G_OK);
        assert_int_equal(gcolor_scratch(&b, models[1], s), G_OK);
        assert_int_equal(gcolor_mul_scaled(&a, &a, &b, 1.0), G_ERR_MISMATCH);
    }
    gscratch_destroy(s);
    for (int k = 0; k < nm; k++)
        gcolormodel_destroy(models[k]);
}

/* The spectrum model on grids of 3 to 531 samples (no whole 8-sample block up to more than 16 of them, tails of
 * 1, 3 and 5 samples): is_black with one non-zero sample anywhere, and mul_scaled against mul then scale. */
static void test_every_length(void **state)
{
    (void)state;
    const GColorModelOptions grids[] = {
        {.min_nm = 380, .max_nm = 580, .step_nm = 100}, {.min_nm = 380, .max_nm = 780, .step_nm = 100},
        {.min_nm = 380, .max_nm = 780, .step_nm = 50}, {.min_nm = 380, .max_nm = 780, .step_nm = 25},
        {.min_nm = 380, .max_nm = 780, .step_nm = 20}, {.min_nm = 380, .max_nm = 780, .step_nm = 10},
        {.min_nm = 380, .max_nm = 780, .step_nm = 5},  {.min_nm = 380, .max_nm = 780, .step_nm = 4},
        {.min_nm = 380, .max_nm = 700, .step_nm = 5},  {.min_nm = 380, .max_nm = 780, .step_nm = 2},
        {.min_nm = 300, .max_nm = 830, .step_nm = 1},
    };
    const float odd[] = {1e-30f, -2.0f, NAN, INFINITY};
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    for (size_t g = 0; g < sizeof grids / sizeof *grids; g++) {
        GColorModel *m;
        GError err;
        if (gcolormodel_create("spectrum", &grids[g], &m, &err) != G_OK)
            fail_msg("grid %zu: %s", g, err.message);
        GScratchMark mark = gscratch_mark(s);
        GColor a, b;
        assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&b, m, s), G_OK);
        assert_black(&a, 1);
        for (int i = 0; i < m->nvalues; i++)
            for (size_t j = 0; j < sizeof odd / sizeof *odd; j++) {
                gcolor_black(&a);
                a.v[i] = odd[j];
                assert_int_equal(gcolor_is_black(&a), 0);
                a.v[i] = -0.0f;
                assert_black(&a, 1);
            }
        for (int i = 0; i < m->nvalues; i++) {
            a.v[i] = 0.1f + 0.7f * (float)i / (float)(i + 3);
            b.v[i] = 3.3f - 0.31f * (float)i;
        }
        assert_mul_scaled(m, s, &a, &b, 1.0 / M_PI);
        assert_mul_scaled(m, s, &a, &b, -0.0);
        gscratch_release(s, mark);
        gcolormodel_destroy(m);
    }
    gscratch_destroy(s);
}

static void test_own_fill_takes_its_operations(void **state)
{
    (void)state;
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create_class(&off_class, NULL, &m, &err), G_OK);
    float store[OFF_N];
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, store, OFF_N), G_OK);
    assert_black(&c, 1); /* all ones, which is black here */
    assert_int_equal(gcolor_fill(&c, 0.0), G_OK);
    assert_black(&c, 1);
    assert_int_equal(gcolor_fill(&c, -1.0), G_OK); /* all zeros: not black in this model */
    assert_black(&c, 0);
    gcolor_black(&c);
    c.v[OFF_N - 1] = 1.5f;
    assert_black(&c, 0);
    c.v[OFF_N - 1] = NAN;
    assert_int_equal(gcolor_is_black(&c), 0);
    /* mul_scaled takes the model's mul (which this model does not have) rather than multiplying its floats */
    assert_int_equal(gcolor_mul_scaled(&c, &c, &c, 2.0), G_ERR_UNSUPPORTED);
    gcolormodel_destroy(m);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vectors_in_every_model),
        cmocka_unit_test(test_matrices),
        cmocka_unit_test(test_mul_scaled_is_mul_then_scale),
        cmocka_unit_test(test_every_length),
        cmocka_unit_test(test_own_fill_takes_its_operations),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
