/* test_color_ops.c - colour storage and the operations materials use instead of touching samples, in every
 * registered colour model (taken from the registry, not listed here): gcolor_free is harmless for arena and
 * caller colours, gcolor_wrap refuses a short buffer, fill / exp / axpy / add_scaled give the analytic values
 * for vectors and (bispectral) matrices. copy, fill, axpy and the finiteness tests answer alike at every position of
 * a value, on the grid lengths the library takes as constants and on others. The library's matrix default for a
 * model larger than any built-in one: test_color_big_model.c. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/registry.h"
#include "test_util.h"

enum { MAX_MODELS = 64 };

/* Every registered colour model with its default options; returns how many. */
static int all_models(GColorModel **out)
{
    const GTypeInfo *types[MAX_MODELS];
    int n = gregistry_list(GKIND_COLORMODEL, types, MAX_MODELS);
    assert_true(n > 0 && n <= MAX_MODELS);
    for (int i = 0; i < n; i++) {
        GError err;
        int rc = gcolormodel_create(types[i]->name, NULL, &out[i], &err);
        if (rc != G_OK)
            print_error("%s: %s\n", types[i]->name, err.message);
        assert_int_equal(rc, G_OK);
    }
    return n;
}

static void destroy_all(GColorModel **m, int n)
{
    for (int i = 0; i < n; i++)
        gcolormodel_destroy(m[i]);
}

static void assert_cleared(const GColor *c)
{
    assert_null(c->model);
    assert_null(c->v);
    assert_int_equal(c->storage, GCOLOR_STORAGE_NONE);
    assert_int_equal(c->capacity, 0);
}

/* ---- storage ---- */

static void test_free_is_harmless_for_arena_and_caller(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models);
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratch *s = gscratch_create(0);
        assert_non_null(s);
        static TuAlloc counter;
        /* arena: nothing is freed, the handle is cleared, the arena keeps working */
        GColor a;
        assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
        assert_int_equal(a.storage, GCOLOR_STORAGE_ARENA);
        assert_int_equal(a.capacity, m->capacity);
        tu_alloc_install(&counter);
        gcolor_free(&a);
        gcolor_free(&a); /* a cleared handle: a no-op */
        gmem_set_allocator(NULL);
        assert_int_equal(counter.frees, 0);
        assert_cleared(&a);
        GColor b;
        assert_int_equal(gcolor_scratch(&b, m, s), G_OK);
        assert_int_equal(gcolor_fill(&b, 0.25), G_OK);
        assert_near(gcolor_brightness(&b), 0.25, 1e-6);
        /* caller storage on the stack (a free of it would be fatal under ASan) */
        float stack[8];
        float *buf = (size_t)m->capacity <= tu_floats(stack) ? stack : calloc((size_t)m->capacity, sizeof *buf);
        GColor c;
        assert_int_equal(gcolor_wrap(&c, m, buf, (size_t)m->capacity), G_OK);
        assert_int_equal(c.storage, GCOLOR_STORAGE_CALLER);
        tu_alloc_install(&counter);
        gcolor_free(&c);
        gmem_set_allocator(NULL);
        assert_int_equal(counter.frees, 0);
        assert_cleared(&c);
        buf[m->capacity - 1] = 1.0f; /* still the caller's */
        if (buf != stack)
            free(buf);
        /* heap: exactly one free */
        GColor h;
        tu_alloc_install(&counter);
        assert_int_equal(gcolor_alloc(&h, m), G_OK);
        assert_int_equal(h.storage, GCOLOR_STORAGE_HEAP);
        assert_int_equal(h.capacity, m->capacity);
        gcolor_free(&h);
        gcolor_free(&h);
        gmem_set_allocator(NULL);
        assert_int_equal(counter.calls, 1);
        assert_int_equal(counter.frees, 1);
        assert_cleared(&h);
        gcolor_free(NULL);
        print_message("%-12s capacity %5d: free of arena and caller colours frees nothing, of a heap colour once\n",
                      gcolormodel_name(m), m->capacity);
        gscratch_destroy(s);
    }
    destroy_all(models, nm);
}

static void test_wrap_refuses_short_buffer(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models);
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        size_t cap = (size_t)m->capacity, total = cap + 8;
        float *buf = malloc(total * sizeof *buf);
        assert_non_null(buf);
        for (size_t i = 0; i < total; i++)
            buf[i] = -7.0f;
        GColor c = {.model = m, .v = buf, .storage = GCOLOR_STORAGE_HEAP, .capacity = 5}; /* stale contents */
        assert_int_equal(gcolor_wrap(&c, m, buf, cap - 1), G_ERR_INVALID);
        assert_cleared(&c);
        assert_int_equal(gcolor_wrap(&c, m, buf, 0), G_ERR_INVALID);
        assert_cleared(&c);
        assert_int_equal(gcolor_wrap(&c, m, NULL, cap), G_ERR_INVALID);
        assert_cleared(&c);
        for (size_t i = 0; i < total; i++) /* a refused wrap writes nothing */
            assert_true(buf[i] == -7.0f);
        assert_int_equal(gcolor_wrap(&c, m, buf, cap), G_OK);
        assert_ptr_equal(c.model, m);
        assert_int_equal(c.storage, GCOLOR_STORAGE_CALLER);
        assert_int_equal(c.capacity, m->capacity);
        assert_true(gcolor_brightness(&c) == 0.0); /* black */
        for (size_t i = cap; i < total; i++) /* nothing beyond the size given */
            assert_true(buf[i] == -7.0f);
        assert_int_equal(gcolor_wrap(&c, m, buf, total), G_OK);
        assert_int_equal(c.capacity, (int)total);
        print_message("%-12s wrap of %zu floats refused, of %zu accepted\n", gcolormodel_name(m), cap - 1, cap);
        free(buf);
    }
    destroy_all(models, nm);
}

/* ---- fill, exp, axpy on vectors ---- */

static float sample_a(int i, int n) { return 0.05f + 0.9f * (float)i / (float)n; }
static float sample_b(int i, int n) { return 0.7f - 0.5f * (float)i / (float)n; }

static void set_vector(GColor *c, float (*f)(int, int))
{
    gcolor_black(c);
    for (int i = 0; i < c->model->nvalues; i++)
        c->v[i] = f(i, c->model->nvalues);
}

/* every sample of c against want(i), relative tolerance */
static void assert_samples(const GColor *c, double (*want)(int, int, double), double s, double tol)
{
    assert_int_equal(c->kind, GCOLOR_VECTOR);
    int n = c->model->nvalues;
    for (int i = 0; i < n; i++) {
        double w = want(i, n, s);
        assert_near(c->v[i], w, tol * fmax(1.0, fabs(w)));
    }
}

static double want_exp(int i, int n, double s) { return exp(s * sample_a(i, n)); }
static double want_axpy(int i, int n, double s) { return s * sample_a(i, n) + sample_b(i, n); }
static double want_add_scaled(int i, int n, double s) { return sample_b(i, n) + s * sample_a(i, n); }

static void test_fill_exp_axpy_vectors(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models);
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratchMark mark = gscratch_mark(s);
        GColor a, b, o;
        assert_int_equal(gcolor_scratch(&a, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&b, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&o, m, s), G_OK);
        /* fill: the constant in every sample, brightness c, and 1 as a reflectance is white */
        const double cs[] = {0.0, 0.37, 1.0, 2.5};
        for (int j = 0; j < 4; j++) {
            assert_int_equal(gcolor_fill(&o, cs[j]), G_OK);
            assert_int_equal(o.kind, GCOLOR_VECTOR);
            for (int i = 0; i < m->nvalues; i++)
                assert_true(o.v[i] == (float)cs[j]);
            assert_near(gcolor_brightness(&o), cs[j], 1e-6 * fmax(1.0, cs[j]));
        }
        double rgb[3];
        assert_int_equal(gcolor_fill(&o, 1.0), G_OK);
        assert_int_equal(gcolor_to_rgb(&o, GCOLOR_REFLECTANCE, rgb), G_OK);
        for (int c = 0; c < 3; c++)
            assert_near(rgb[c], 1.0, 2e-3);
        assert_int_equal(gcolor_fill(&o, NAN), G_ERR_INVALID);
        assert_int_equal(gcolor_fill(&o, INFINITY), G_ERR_INVALID);
        /* exp(s a), also in place */
        set_vector(&a, sample_a);
        assert_int_equal(gcolor_exp(&o, &a, -2.5), G_OK);
        assert_samples(&o, want_exp, -2.5, 1e-6);
        assert_int_equal(gcolor_exp(&a, &a, 0.8), G_OK);
        assert_samples(&a, want_exp, 0.8, 1e-6);
        assert_int_equal(gcolor_exp(&o, &b, 0.0), G_OK); /* exp(0) = 1 */
        for (int i = 0; i < m->nvalues; i++)
            assert_true(o.v[i] == 1.0f);
        /* axpy: separate, out = a, out = b */
        const double ss[] = {0.0, 0.75, -1.5};
        for (int j = 0; j < 3; j++) {
            set_vector(&a, sample_a);
            set_vector(&b, sample_b);
            assert_int_equal(gcolor_axpy(&o, ss[j], &a, &b), G_OK);
            assert_samples(&o, want_axpy, ss[j], 1e-6);
            assert_int_equal(gcolor_axpy(&a, ss[j], &a, &b), G_OK);
            assert_samples(&a, want_axpy, ss[j], 1e-6);
            set_vector(&a, sample_a);
            assert_int_equal(gcolor_axpy(&b, ss[j], &a, &b), G_OK);
            assert_samples(&b, want_axpy, ss[j], 1e-6);
            set_vector(&b, sample_b);
            assert_int_equal(gcolor_add_scaled(&b, &a, ss[j]), G_OK);
            assert_samples(&b, want_add_scaled, ss[j], 1e-6);
        }
        /* a + a * 1 = 2 a: out aliasing both operands */
        set_vector(&a, sample_a);
        assert_int_equal(gcolor_axpy(&a, 1.0, &a, &a), G_OK);
        for (int i = 0; i < m->nvalues; i++)
            assert_near(a.v[i], 2.0 * sample_a(i, m->nvalues), 1e-6);
        /* operands of another model */
        const GColorModel *other = models[(k + 1) % nm];
        if (other != m && other->cls != m->cls) {
            GColor x;
            assert_int_equal(gcolor_scratch(&x, other, s), G_OK);
            assert_int_equal(gcolor_axpy(&o, 1.0, &x, &b), G_ERR_MISMATCH);
            assert_int_equal(gcolor_axpy(&o, 1.0, &a, &x), G_ERR_MISMATCH);
            assert_int_equal(gcolor_axpy(&x, 1.0, &a, &b), G_ERR_MISMATCH);
            assert_int_equal(gcolor_exp(&x, &a, 1.0), G_ERR_MISMATCH);
        }
        print_message("%-12s fill, exp, axpy and add_scaled give the analytic samples\n", gcolormodel_name(m));
        gscratch_release(s, mark);
    }
    gscratch_destroy(s);
    destroy_all(models, nm);
}

/* ---- matrices (the bispectral layout: A[o * n + i], row o = emission) ---- */

static float entry_a(int o, int i) { return o >= i ? 0.01f * (float)(1 + (o * 7 + i * 3) % 11) : 0.0f; }
static float entry_b(int o, int i) { return 0.3f + 0.002f * (float)o - 0.001f * (float)i; }

/* A matrix of model m, made through from_reradiation and then given the entries f. 0 when the model turns
 * a re-radiation matrix into a vector (it has no matrices). */
static int make_matrix(const GColorModel *m, float (*f)(int, int), GColor *out)
{
    if (!tu_diagonal_matrix(m, out))
        return 0;
    int n = m->nsamples;
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++)
            out->v[o * n + i] = f(o, i);
    return 1;
}

/* c's entries against s * A + B, where A and B are matrices or vectors (va, vb: the vector's samples, put on
 * the diagonal) */
static void assert_entries(const GColor *c, double s, float (*fa)(int, int), float (*va)(int, int),
                           float (*fb)(int, int), float (*vb)(int, int))
{
    int n = c->model->nsamples;
    assert_int_equal(c->kind, GCOLOR_MATRIX);
    double worst = 0.0;
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++) {
            double a = fa ? fa(o, i) : (o == i ? va(o, n) : 0.0);
            double b = fb ? fb(o, i) : (o == i ? vb(o, n) : 0.0);
            double w = s * a + b;
            worst = fmax(worst, fabs(c->v[o * n + i] - w));
        }
    assert_true(worst <= 1e-6);
}

static void test_fill_exp_axpy_matrices(void **state)
{
    (void)state;
    GColorModel *models[MAX_MODELS];
    int nm = all_models(models), with_matrices = 0;
    GScratch *s = gscratch_create(0);
    assert_non_null(s);
    for (int k = 0; k < nm; k++) {
        const GColorModel *m = models[k];
        GScratchMark mark = gscratch_mark(s);
        GColor A, B, v, o;
        assert_int_equal(gcolor_scratch(&A, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&B, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&v, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&o, m, s), G_OK);
        if (!make_matrix(m, entry_a, &A)) {
            gscratch_release(s, mark);
            continue;
        }
        with_matrices++;
        int n = m->nsamples;
        const double sc = 0.6;
        /* matrix + matrix: separate, out = B, out = A */
        make_matrix(m, entry_b, &B);
        assert_int_equal(gcolor_axpy(&o, sc, &A, &B), G_OK);
        assert_entries(&o, sc, entry_a, NULL, entry_b, NULL);
        assert_int_equal(gcolor_add_scaled(&B, &A, sc), G_OK);
        assert_entries(&B, sc, entry_a, NULL, entry_b, NULL);
        make_matrix(m, entry_b, &B);
        assert_int_equal(gcolor_axpy(&A, sc, &A, &B), G_OK);
        assert_entries(&A, sc, entry_a, NULL, entry_b, NULL);
        /* s A + diag(v): separate, out = v (the vector becomes the matrix), out = A */
        make_matrix(m, entry_a, &A);
        set_vector(&v, sample_b);
        assert_int_equal(gcolor_axpy(&o, sc, &A, &v), G_OK);
        assert_entries(&o, sc, entry_a, NULL, NULL, sample_b);
        assert_int_equal(gcolor_axpy(&v, sc, &A, &v), G_OK);
        assert_entries(&v, sc, entry_a, NULL, NULL, sample_b);
        set_vector(&v, sample_b);
        assert_int_equal(gcolor_axpy(&A, sc, &A, &v), G_OK);
        assert_entries(&A, sc, entry_a, NULL, NULL, sample_b);
        /* diag(s v) + B: separate, out = v, out = B (add_scaled) */
        make_matrix(m, entry_b, &B);
        set_vector(&v, sample_a);
        assert_int_equal(gcolor_axpy(&o, sc, &v, &B), G_OK);
        assert_entries(&o, sc, NULL, sample_a, entry_b, NULL);
        assert_int_equal(gcolor_axpy(&v, sc, &v, &B), G_OK);
        assert_entries(&v, sc, NULL, sample_a, entry_b, NULL);
        set_vector(&v, sample_a);
        assert_int_equal(gcolor_add_scaled(&B, &v, sc), G_OK);
        assert_entries(&B, sc, NULL, sample_a, entry_b, NULL);
        /* vector + s matrix into the vector's storage (add_scaled of a matrix into a light) */
        make_matrix(m, entry_a, &A);
        set_vector(&v, sample_b);
        assert_int_equal(gcolor_add_scaled(&v, &A, sc), G_OK);
        assert_entries(&v, sc, entry_a, NULL, NULL, sample_b);
        /* exp of a matrix: exp(s d) of its diagonal, a vector (a medium absorbs, it does not re-radiate) */
        make_matrix(m, entry_b, &B);
        assert_int_equal(gcolor_exp(&o, &B, -1.5), G_OK);
        assert_int_equal(o.kind, GCOLOR_VECTOR);
        for (int i = 0; i < n; i++)
            assert_near(o.v[i], exp(-1.5 * entry_b(i, i)), 1e-6);
        assert_int_equal(gcolor_exp(&B, &B, -1.5), G_OK); /* in place */
        for (int i = 0; i < n; i++)
            assert_near(B.v[i], exp(-1.5 * entry_b(i, i)), 1e-6);
        /* fill over a matrix: the constant vector c (the operator c I) */
        make_matrix(m, entry_b, &B);
        assert_int_equal(gcolor_fill(&B, 0.4), G_OK);
        assert_int_equal(B.kind, GCOLOR_VECTOR);
        for (int i = 0; i < n; i++)
            assert_true(B.v[i] == 0.4f);
        assert_near(gcolor_brightness(&B), 0.4, 1e-6);
        print_message("%-12s %d x %d matrices: axpy, add_scaled, exp and fill give the analytic entries\n",
                      gcolormodel_name(m), n, n);
        gscratch_release(s, mark);
    }
    assert_true(with_matrices >= 1); /* the bispectral model is built in */
    gscratch_destroy(s);
    destroy_all(models, nm);
}

/* copy, fill and the finiteness tests on every position of a value, on grids of the lengths the library takes as
 * constants (9, 41, 81) and of others (3, 51, 401), vectors and matrices: the same answers as a test of each sample,
 * every float copied bit for bit, a fill that writes the vector's samples and nothing past them, and axpy against
 * its definition (the product in double, rounded to float, then the float sum). */
static void test_copy_fill_finite_every_position(void **state)
{
    (void)state;
    const char *names[] = {"rgb", "spectrum9", "spectrum", "spectrum", "spectrum", "spectrum", "bispectral"};
    const GColorModelOptions opts[] = {{0, 0, 0, 0}, {0, 0, 0, 0},   {5, 0, 0, 0}, {10, 0, 0, 0},
                                       {1, 0, 0, 0}, {6, 400, 700, 0}, {0, 0, 0, 0}};
    const float odd[] = {NAN, INFINITY, -INFINITY, -0.5f};
    int cases = 0;
    for (int i = 0; i < 7; i++) {
        GColorModel *m;
        assert_int_equal(gcolormodel_create(names[i], &opts[i], &m, NULL), G_OK);
        const int cap = m->capacity, n = m->nvalues, matrices = cap == n * n && n > 1;
        float *av = malloc((size_t)(cap + 1) * sizeof *av), *bv = malloc((size_t)(cap + 1) * sizeof *bv);
        float *ov = malloc((size_t)(cap + 1) * sizeof *ov);
        assert_true(av && bv && ov);
        GColor a, b, o;
        assert_int_equal(gcolor_wrap(&a, m, av, (size_t)cap), G_OK);
        assert_int_equal(gcolor_wrap(&b, m, bv, (size_t)cap), G_OK);
        assert_int_equal(gcolor_wrap(&o, m, ov, (size_t)cap), G_OK);
        for (int kind = GCOLOR_VECTOR; kind <= (matrices ? GCOLOR_MATRIX : GCOLOR_VECTOR); kind++) {
            const int len = kind == GCOLOR_MATRIX ? cap : n;
            for (int k = 0; k < len; k++)
                for (int j = 0; j < 4; j++) {
                    for (int x = 0; x < len; x++)
                        av[x] = 0.25f + 0.125f * (float)(x % 5);
                    av[k] = odd[j];
                    a.kind = kind;
                    assert_int_equal(gcolor_is_finite(&a), j == 3);
                    assert_false(gcolor_is_nonnegative(&a));
                    av[k] = 1.0f;
                    assert_true(gcolor_is_finite(&a) && gcolor_is_nonnegative(&a));
                    av[k] = odd[j];
                    ov[len] = bv[len] = 7.0f; /* past the value: left alone */
                    for (int x = 0; x < len; x++)
                        ov[x] = -1.0f;
                    o.kind = 1 - kind;
                    assert_int_equal(gcolor_copy(&o, &a), G_OK);
                    assert_int_equal(o.kind, kind);
                    assert_memory_equal(ov, av, (size_t)len * sizeof *av);
                    assert_true(ov[len] == 7.0f);
                    if (kind == GCOLOR_VECTOR && j == 3) { /* axpy of two vectors: the library's or the model's */
                        for (int x = 0; x < n; x++)
                            bv[x] = 0.1f * (float)x - 1.0f;
                        b.kind = GCOLOR_VECTOR;
                        const double s = k % 2 ? 0.75 : 0.1;
                        assert_int_equal(gcolor_axpy(&o, s, &a, &b), G_OK);
                        for (int x = 0; x < n; x++)
                            assert_true(ov[x] == bv[x] + (float)(av[x] * s));
                    }
                    cases++;
                }
        }
        for (int j = 0; j < 3; j++) {
            const double c[] = {0.0, 0.3, -2.0};
            for (int x = 0; x <= cap; x++)
                ov[x] = 7.0f;
            o.kind = matrices ? GCOLOR_MATRIX : GCOLOR_VECTOR;
            assert_int_equal(gcolor_fill(&o, c[j]), G_OK);
            assert_int_equal(o.kind, GCOLOR_VECTOR);
            for (int x = 0; x < n; x++)
                assert_true(ov[x] == (float)c[j]);
            assert_true(ov[cap] == 7.0f);
        }
        print_message("%-10s %3d values (%s): copy, fill, finiteness and axpy at every position\n", names[i], n,
                      matrices ? "and matrices" : "vectors");
        free(av);
        free(bv);
        free(ov);
        gcolormodel_destroy(m);
    }
    print_message("%d positions\n", cases);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_is_harmless_for_arena_and_caller),
        cmocka_unit_test(test_wrap_refuses_short_buffer),
        cmocka_unit_test(test_fill_exp_axpy_vectors),
        cmocka_unit_test(test_fill_exp_axpy_matrices),
        cmocka_unit_test(test_copy_fill_finite_every_position),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
