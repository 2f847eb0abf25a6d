/* test_color_big_model.c - the library's defaults for a colour model whose capacity is larger than any built-in
 * one (a test fixture of BIG_N samples and BIG_N x BIG_N matrices, with no axpy of its own): add_scaled and axpy
 * compose add and scale exactly on its matrices and vectors, without allocating after the first use, in the main
 * thread and in others (the library's temporary is per thread); exp refuses a matrix it cannot read, fill gives the
 * vector. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <string.h>

#include "generic/color.h"
#include "test_util.h"

enum { BIG_N = 160 /* BIG_N * BIG_N = 25600 floats > 128 * 128 */ };

static float sample_a(int i, int n) { return 0.05f + 0.9f * (float)i / (float)n; }

/* ---- a model larger than any built-in: vectors of BIG_N samples, BIG_N x BIG_N matrices, no axpy slot ---- *
 * A test fixture: add and scale know matrices (what the library's axpy default composes); mul, div and pow
 * take vectors only; a vector reads as a grey of its mean. */

static int big_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)opt;
    (void)err;
    self->nvalues = BIG_N;
    self->capacity = BIG_N * BIG_N;
    return G_OK;
}

static int floats_of(const GColor *c) { return c->kind == GCOLOR_MATRIX ? BIG_N * BIG_N : BIG_N; }

static void big_black(const GColorModel *m, GColor *out)
{
    (void)m;
    out->kind = GCOLOR_VECTOR;
    memset(out->v, 0, BIG_N * sizeof *out->v);
}

static int big_add(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    if (a->kind == b->kind) {
        for (int i = 0; i < floats_of(a); i++)
            out->v[i] = a->v[i] + b->v[i];
        out->kind = a->kind;
        return G_OK;
    }
    const GColor *mat = a->kind == GCOLOR_MATRIX ? a : b, *vec = mat == a ? b : a;
    static _Thread_local float d[BIG_N];
    memcpy(d, vec->v, sizeof d);
    if (out->v != mat->v)
        memcpy(out->v, mat->v, BIG_N * BIG_N * sizeof *out->v);
    for (int k = 0; k < BIG_N; k++)
        out->v[k * BIG_N + k] += d[k];
    out->kind = GCOLOR_MATRIX;
    return G_OK;
}

static int big_scale(const GColorModel *m, GColor *out, const GColor *a, double s)
{
    (void)m;
    for (int i = 0; i < floats_of(a); i++)
        out->v[i] = (float)(a->v[i] * s);
    out->kind = a->kind;
    return G_OK;
}

static int big_mul(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    if (a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)
        return G_ERR_UNSUPPORTED;
    for (int i = 0; i < BIG_N; i++)
        out->v[i] = a->v[i] * b->v[i];
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int big_div(const GColorModel *m, GColor *out, const GColor *a, const GColor *b)
{
    (void)m;
    if (a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)
        return G_ERR_UNSUPPORTED;
    for (int i = 0; i < BIG_N; i++)
        out->v[i] = b->v[i] != 0.0f ? a->v[i] / b->v[i] : 0.0f;
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static int big_pow(const GColorModel *m, GColor *out, const GColor *a, double e)
{
    (void)m;
    if (a->kind != GCOLOR_VECTOR)
        return G_ERR_UNSUPPORTED;
    for (int i = 0; i < BIG_N; i++)
        out->v[i] = a->v[i] > 0.0f ? (float)pow(a->v[i], e) : (e == 0.0 ? 1.0f : 0.0f);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

/* mean magnitude; a matrix: of its response to equal-energy light */
static double big_brightness(const GColorModel *m, const GColor *a)
{
    (void)m;
    double s = 0.0;
    for (int i = 0; i < floats_of(a); i++)
        s += fabs(a->v[i]);
    return s / BIG_N;
}

static int big_to_nm(const GColorModel *m, const GColor *a, GColorRole role, GSpectrumNM *out)
{
    (void)role;
    float grey = (float)big_brightness(m, a);
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = grey;
    return G_OK;
}

static int big_from_nm(const GColorModel *m, const GSpectrumNM *in, GColorRole role, GColor *out)
{
    (void)m;
    (void)role;
    double s = 0.0;
    for (int i = 0; i < GNM_COUNT; i++)
        s += in->v[i];
    for (int i = 0; i < BIG_N; i++)
        out->v[i] = (float)(s / GNM_COUNT);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}

static const GColorModelClass big_class = {
    .abi_version = GCOLOR_ABI_VERSION,
    .name = "big",
    .description = "test fixture: 160 samples, 160 x 160 matrices, no axpy of its own",
    .init = big_init,
    .black = big_black,
    .add = big_add,
    .mul = big_mul,
    .scale = big_scale,
    .div = big_div,
    .pow = big_pow,
    .brightness = big_brightness,
    .to_nm = big_to_nm,
    .from_nm = big_from_nm,
};

static float big_entry(int o, int i) { return 0.001f * (float)((o * 13 + i * 5) % 97); }
static float big_entry2(int o, int i) { return 0.5f - 0.0001f * (float)((o + 3 * i) % 401); }

static void big_matrix(GColor *c, float (*f)(int, int))
{
    for (int o = 0; o < BIG_N; o++)
        for (int i = 0; i < BIG_N; i++)
            c->v[o * BIG_N + i] = f(o, i);
    c->kind = GCOLOR_MATRIX;
}

/* add_scaled and axpy on the big model's matrices and vectors, checked entry by entry; 0 on success */
static int big_round(const GColorModel *m, GScratch *s)
{
    GScratchMark mark = gscratch_mark(s);
    GColor A, M, v, o;
    int rc = gcolor_scratch(&A, m, s) | gcolor_scratch(&M, m, s) | gcolor_scratch(&v, m, s) |
             gcolor_scratch(&o, m, s);
    double worst = 0.0;
    if (rc == G_OK) {
        const double sc = -0.35;
        big_matrix(&A, big_entry);
        big_matrix(&M, big_entry2);
        rc |= gcolor_add_scaled(&M, &A, sc); /* M += sc A: the composed default through its temporary */
        for (int o2 = 0; o2 < BIG_N; o2++)
            for (int i = 0; i < BIG_N; i++)
                worst = fmax(worst, fabs(M.v[o2 * BIG_N + i] - (big_entry2(o2, i) + sc * big_entry(o2, i))));
        for (int i = 0; i < BIG_N; i++)
            v.v[i] = sample_a(i, BIG_N);
        v.kind = GCOLOR_VECTOR;
        rc |= gcolor_add_scaled(&v, &A, 2.0); /* a vector's storage becomes diag(v) + 2 A */
        rc |= gcolor_axpy(&o, 2.0, &A, &M);   /* out aliases neither: scale, then add */
        for (int o2 = 0; o2 < BIG_N; o2++)
            for (int i = 0; i < BIG_N; i++) {
                double d = o2 == i ? sample_a(i, BIG_N) : 0.0, a = big_entry(o2, i);
                worst = fmax(worst, fabs(v.v[o2 * BIG_N + i] - (d + 2.0 * a)));
                worst = fmax(worst, fabs(o.v[o2 * BIG_N + i] - (2.0 * a + M.v[o2 * BIG_N + i])));
            }
        if (v.kind != GCOLOR_MATRIX || o.kind != GCOLOR_MATRIX)
            rc = G_ERR_INVALID;
    }
    gscratch_release(s, mark);
    return rc != G_OK || worst > 1e-6;
}

static void test_add_scaled_beyond_builtin_capacity(void **state)
{
    (void)state;
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create_class(&big_class, NULL, &m, &err), G_OK);
    assert_true(m->capacity > 128 * 128);
    GScratch *s = gscratch_create(4 * (size_t)m->capacity * sizeof(float) + 1024);
    assert_non_null(s);
    assert_int_equal(big_round(m, s), 0); /* the first use may set up the library's temporary */
    static TuAlloc counter;
    tu_alloc_install(&counter);
    int bad = 0;
    for (int i = 0; i < 20; i++)
        bad |= big_round(m, s);
    gmem_set_allocator(NULL);
    assert_int_equal(bad, 0);
    print_message("capacity %d floats: add_scaled and axpy exact, %ld allocations in 20 rounds after the first\n",
                  m->capacity, counter.calls);
    assert_int_equal(counter.calls, 0);
    /* the defaults of the other slots: exp refuses a matrix it cannot read, fill gives the vector */
    GColor a, o;
    assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
    assert_int_equal(gcolor_scratch(&o, m, s), G_OK);
    big_matrix(&a, big_entry);
    assert_int_equal(gcolor_exp(&o, &a, -1.0), G_ERR_UNSUPPORTED);
    assert_int_equal(gcolor_fill(&a, 0.5), G_OK);
    assert_int_equal(a.kind, GCOLOR_VECTOR);
    assert_near(gcolor_brightness(&a), 0.5, 1e-6);
    assert_int_equal(gcolor_exp(&o, &a, -2.0), G_OK);
    assert_near(o.v[BIG_N - 1], exp(-1.0), 1e-7);
    gscratch_destroy(s);
    gcolormodel_destroy(m);
}

/* The library's temporary is per thread and is freed when the thread ends (LeakSanitizer would report it). */
static void *big_in_thread(void *model)
{
    GScratch *s = gscratch_create(0);
    int bad = s ? big_round(model, s) : 1;
    gscratch_destroy(s);
    return bad ? model : NULL;
}

static void test_add_scaled_in_other_threads(void **state)
{
    (void)state;
    GColorModel *m;
    GError err;
    assert_int_equal(gcolormodel_create_class(&big_class, NULL, &m, &err), G_OK);
    pthread_t t[2];
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_create(&t[i], NULL, big_in_thread, m), 0);
    for (int i = 0; i < 2; i++) {
        void *res = m;
        assert_int_equal(pthread_join(t[i], &res), 0);
        assert_null(res);
    }
    gcolormodel_destroy(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_add_scaled_beyond_builtin_capacity),
        cmocka_unit_test(test_add_scaled_in_other_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
