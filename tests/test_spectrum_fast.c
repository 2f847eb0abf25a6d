/* test_spectrum_fast.c - the kit's per-ray kernels (spectral_kernels.h, spectral_kernels8.h) give their scalar
 * definitions' results bit for bit (memcmp), on every length from 1 to 140 and on 255, 256, 257, 401, 531, 1024 and
 * 1681 samples: element-wise add, mul, scale, div, fill, axpy, copy and mul then scale (out apart from the
 * operands, out in place of either operand, at every alignment, nothing written before the start or past the end;
 * in the 8-float versions the last n % 8 samples are pieces of 4, 2 and 1 floats), the finiteness and sign test,
 * and the sums (magnitudes, dot products, weighted magnitudes, brightness, colour matching) in their documented
 * order: 8 float lanes over the whole blocks of 8, the lanes folded in pairs, the last samples one by one. Both
 * the 4-float versions and, where the processor has AVX2, the 8-float ones (whole blocks as straight-line code
 * entered by one jump), with zeros of both signs, NaN, infinities, huge and denormal samples, zero divisors. Then
 * the spectrum model's operations (through gcolor_*, whichever body the loader picked) against the 4-float kernels
 * on grids of 9, 41, 81, 401 and 531 samples and on grids whose last block has 1 to 7 samples (5, 17, 19 to 23,
 * 26): the same results, in place too.
 *
 * Every NaN in the inputs is x86's default NaN (sign set, no payload), the one an invalid operation makes: which
 * of two NaN operands an operation passes on is the compiler's choice of operand order, not the kernel's order of
 * work, and with one kind of NaN there is nothing to choose. A NaN with a payload is tested in one operand only.
 * A sum may still meet two kinds (the magnitude of the default NaN is a positive NaN), so sums that are NaN are
 * only checked to be NaN; the rounds with finite samples compare them bit for bit (and check they are numbers). */
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
#include "generic/kit/spectral.h"
#include "generic/kit/spectral_kernels.h"
#include "test_util.h"

enum { MAX_N = 1681, SMALL_N = 140, ROUNDS = 6, GUARD = 8 };

static const int large_n[] = {255, 256, 257, 401, 531, 1024, 1681};

static float from_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

static uint32_t rng = 12345u;

static uint32_t next(void)
{
    rng = rng * 1664525u + 1013904223u;
    return rng >> 8;
}

/* What the edge cases among the samples are: */
enum {
    ANY,     /* zeros of both signs, the default NaN, infinities, huge and denormal values */
    PAYLOAD, /* FINITE's and a NaN with a payload (no infinity, no overflow: no other NaN forms) */
    FINITE   /* zeros, denormal values, and values 2^60 apart, which the order of a sum, in float and in double,
              * changes (no product of two reaches infinity) */
};

/* A sample: mostly ordinary values of either sign, one in five an edge case of the kind asked for. */
static float sample(int kind)
{
    const float any[] = {0.0f, -0.0f, from_bits(0xffc00000u), INFINITY, -INFINITY, 3.0e38f, -3.0e38f, 1e-40f,
                         -1e-40f, 1.17549435e-38f, from_bits(1u), 1.0f};
    const float payload[] = {0.0f, -0.0f, from_bits(0x7fc01234u), 1e-40f, -1e-40f, 1e18f, -1e18f, 3e-18f};
    uint32_t r = next();
    if (r % 5 == 0) {
        r /= 5;
        if (kind == ANY)
            return any[r % tu_floats(any)];
        float v = payload[r % tu_floats(payload)];
        return kind == FINITE && isnan(v) ? 1.0f : v;
    }
    return ((float)(r % 20000) - 10000.0f) / 997.0f;
}

static void fill_random(float *v, int n, int kind)
{
    for (int i = 0; i < n; i++)
        v[i] = sample(kind);
}

/* What is being compared, for the message of a failure. */
static char what[96];

/* got and want the same bytes; a failure names what differs (what) and the first byte that does. */
#define assert_same(got, want, bytes) same_bytes((got), (want), (bytes), __FILE__, __LINE__)

static void same_bytes(const void *got, const void *want, size_t bytes, const char *file, int line)
{
    if (memcmp(got, want, bytes) == 0)
        return;
    size_t k = 0;
    while (((const char *)got)[k] == ((const char *)want)[k])
        k++;
    print_error("%s:%d: %s: byte %zu of %zu differs\n", file, line, what, k, bytes);
    _fail(file, line);
}

/* ---- the scalar definitions ---- */

static float term(GSpectralTerm t, float a, float b)
{
    return t == GSPECTRAL_ABS ? fabsf(a) : t == GSPECTRAL_DOT ? a * b : a * fabsf(b);
}

/* The whole blocks' terms in 8 float lanes, block after block, folded to lanes j + (j + 4); returns the samples
 * in whole blocks. */
static int lanes(GSpectralTerm t, const float *a, const float *b, int n, float f[4])
{
    float l[8] = {0};
    int i = 0;
    for (; i + 8 <= n; i += 8)
        for (int j = 0; j < 8; j++)
            l[j] += term(t, a[i + j], b[i + j]);
    for (int j = 0; j < 4; j++)
        f[j] = l[j] + l[j + 4];
    return i;
}

static float ref_sum(GSpectralTerm t, const float *a, const float *b, int n)
{
    float f[4];
    int i = lanes(t, a, b, n, f);
    float s = (f[0] + f[1]) + (f[2] + f[3]);
    for (; i < n; i++)
        s += term(t, a[i], b[i]);
    return s;
}

static double ref_bright(const float *w, const float *a, int n)
{
    float f[4];
    int i = lanes(GSPECTRAL_WABS, w, a, n, f);
    double s = (double)f[0] + f[1] + f[2] + f[3];
    for (; i < n; i++)
        s += w[i] * fabsf(a[i]);
    return s;
}

/* t: per block of 8 samples 8 x, 8 y and 8 z weights */
static void ref_xyz(const float *t, const float *a, int n, double xyz[3])
{
    for (int c = 0; c < 3; c++) {
        float l[8] = {0}, tail = 0.0f;
        int i = 0;
        for (; i + 8 <= n; i += 8)
            for (int j = 0; j < 8; j++)
                l[j] += a[i + j] * t[i * 3 + c * 8 + j];
        for (; i < n; i++)
            tail += a[i] * t[(i / 8) * 24 + c * 8 + i % 8];
        float f[4];
        for (int j = 0; j < 4; j++)
            f[j] = l[j] + l[j + 4];
        xyz[c] = (((double)f[0] + f[1]) + ((double)f[2] + f[3])) + tail;
    }
}

static int ref_finite(const float *a, int n, int nonneg)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(a[i]) || (nonneg && a[i] < 0.0f))
            return 0;
    return 1;
}

/* The element-wise operations: 0 add, 1 mul, 2 scale (b unused), 3 div, 4 fill (a, b unused), 5 axpy, 6 copy
 * (b unused; the 4-float side is memmove, what gcolor_copy does without AVX2), 7 mul then scale (gcolor_mul_scaled:
 * the product rounded to float, then scaled). */
enum { ADD, MUL, SCALE, DIV, FILL, AXPY, COPY, MUL_SCALED, NOPS };

static float ref_elem(int op, float a, float b, double s)
{
    switch (op) {
    case ADD: return a + b;
    case MUL: return a * b;
    case SCALE: return a * (float)s;
    case DIV: return b != 0.0f ? a / b : 0.0f;
    case FILL: return (float)s;
    case COPY: return a;
    case MUL_SCALED: {
        float x = a * b;
        return x * (float)s;
    }
    default: return b + (float)(a * s);
    }
}

/* ---- the kernels under test, one body per width ---- */

typedef void (*ElemFn)(int op, float *o, const float *a, const float *b, double s, int n);

static void elem4(int op, float *o, const float *a, const float *b, double s, int n)
{
    switch (op) {
    case ADD: gspectral_kadd(o, a, b, n); break;
    case MUL: gspectral_kmul(o, a, b, n); break;
    case SCALE: gspectral_kscale(o, a, (float)s, n); break;
    case DIV: gspectral_kdiv(o, a, b, n); break;
    case FILL: gspectral_kfill(o, (float)s, n); break;
    case COPY: memmove(o, a, (size_t)n * sizeof(float)); break;
    case MUL_SCALED: gspectral_kmul_scaled(o, a, b, (float)s, n); break;
    default: gspectral_kaxpyd(o, s, a, b, n); break;
    }
}

typedef struct Sums {
    float sum[3]; /* per GSpectralTerm */
    double bright, xyz[3];
    int finite[2]; /* nonnegative 0, 1 */
} Sums;

static void sums4(const float *a, const float *b, const float *t, int n, Sums *r)
{
    for (int k = 0; k < 3; k++)
        r->sum[k] = gspectral_ksum((GSpectralTerm)k, a, b, n);
    r->bright = gspectral_kbright(b, a, n);
    gspectral_kxyz(t, a, n, r->xyz);
    for (int k = 0; k < 2; k++)
        r->finite[k] = gspectral_kfinite(a, n, k);
}

#ifdef GSPECTRAL_AVX2
/* Each operation with its constants, as the library's bodies instantiate them. */
static GSPECTRAL_TARGET_AVX2 void elem8(int op, float *o, const float *a, const float *b, double s, int n)
{
    switch (op) {
    case ADD: gspectral_kmap8(GSPECTRAL_ADD, o, a, b, n); break;
    case MUL: gspectral_kmap8(GSPECTRAL_MUL, o, a, b, n); break;
    case SCALE: gspectral_kscale8(o, a, (float)s, n); break;
    case DIV: gspectral_kdiv8(o, a, b, n); break;
    case FILL: gspectral_kfill8(o, (float)s, n); break;
    case COPY: gspectral_kcopy8(o, a, n); break;
    case MUL_SCALED: gspectral_kmul_scaled8(o, a, b, (float)s, n); break;
    default: gspectral_kaxpyd8(o, s, a, b, n); break;
    }
}

static GSPECTRAL_TARGET_AVX2 void sums8(const float *a, const float *b, const float *t, int n, Sums *r)
{
    r->sum[GSPECTRAL_ABS] = gspectral_ksum8(GSPECTRAL_ABS, a, b, n);
    r->sum[GSPECTRAL_DOT] = gspectral_ksum8(GSPECTRAL_DOT, a, b, n);
    r->sum[GSPECTRAL_WABS] = gspectral_ksum8(GSPECTRAL_WABS, a, b, n);
    r->bright = gspectral_kbright8(b, a, n);
    gspectral_kxyz8(t, a, n, r->xyz);
    r->finite[0] = gspectral_kfinite8(a, n, 0);
    r->finite[1] = gspectral_kfinite8(a, n, 1);
}
#endif

/* ---- the comparisons ---- */

/* The operands a and b and the result o start off floats (0 to 7) into their allocations, so that the kernels meet
 * every alignment; o has GUARD floats before and after its n. */
typedef struct Bufs {
    float *a, *b, *t, *want, *o;
    float *a_block, *b_block, *o_block; /* the allocations */
} Bufs;

/* The GUARD floats before o and after its n hold sentinel. */
static void check_guards(const float *o, int n, float sentinel)
{
    for (int i = -GUARD; i < 0; i++)
        assert_same(&o[i], &sentinel, sizeof sentinel);
    for (int i = n; i < n + GUARD; i++)
        assert_same(&o[i], &sentinel, sizeof sentinel);
}

/* One element-wise operation of one width on a and b against the definition: apart, in place of a, in place of b
 * (axpy's usual form), nothing written before o or past its n. */
static void check_elem(ElemFn fn, int op, const Bufs *m, double s, int n)
{
    size_t len = strlen(what);
    snprintf(what + len, sizeof what - len, ", operation %d", op);
    const float sentinel = from_bits(0x7f812345u);
    size_t bytes = (size_t)n * sizeof(float);
    for (int i = 0; i < n; i++)
        m->want[i] = ref_elem(op, m->a[i], m->b[i], s);
    for (int i = -GUARD; i < n + GUARD; i++)
        m->o[i] = sentinel;
    fn(op, m->o, m->a, m->b, s, n);
    assert_same(m->o, m->want, bytes);
    check_guards(m->o, n, sentinel);
    memcpy(m->o, m->a, bytes);
    fn(op, m->o, m->o, m->b, s, n);
    assert_same(m->o, m->want, bytes);
    check_guards(m->o, n, sentinel);
    memcpy(m->o, m->b, bytes);
    fn(op, m->o, m->a, m->o, s, n);
    assert_same(m->o, m->want, bytes);
    check_guards(m->o, n, sentinel);
    what[len] = '\0';
}

/* A sum: the same bits, or both NaN. A magnitude's term makes the default NaN a positive one, so that two NaNs
 * may meet in a sum, and which one an addition passes on is the compiler's choice of operand order. */
#define assert_same_sum(got, want)                                                                             \
    do {                                                                                                       \
        if (!isnan(got) || !isnan(want))                                                                       \
            assert_same(&(got), &(want), sizeof(want));                                                        \
    } while (0)

/* finite: the operands and the table are finite, so that the sums are numbers, compared bit for bit */
static void check_sums(const Sums *got, const float *a, const float *b, const float *t, int n, int finite)
{
    strcat(what, ", sums");
    for (int k = 0; k < 3; k++) {
        float want = ref_sum((GSpectralTerm)k, a, b, n);
        assert_same_sum(got->sum[k], want);
    }
    double bright = ref_bright(b, a, n), xyz[3];
    assert_same_sum(got->bright, bright);
    ref_xyz(t, a, n, xyz);
    for (int c = 0; c < 3; c++)
        assert_same_sum(got->xyz[c], xyz[c]);
    for (int k = 0; k < 2; k++)
        assert_int_equal(got->finite[k], ref_finite(a, n, k));
    if (finite)
        assert_false(isnan(bright) || isnan(xyz[0]) || isnan(ref_sum(GSPECTRAL_DOT, a, b, n)));
}

/* Operands that end with their allocations (the sanitizers see any read past them), off floats in; the table of
 * (n + 7) / 8 blocks. */
static Bufs bufs_alloc(int n, int off)
{
    Bufs m = {.a_block = malloc((size_t)(off + n) * sizeof(float)),
              .b_block = malloc((size_t)(off + n) * sizeof(float)),
              .t = malloc((size_t)(n + 7) / 8 * 24 * sizeof(float)),
              .want = malloc((size_t)n * sizeof(float)),
              .o_block = malloc((size_t)(GUARD + off + n + GUARD) * sizeof(float))};
    assert_true(m.a_block && m.b_block && m.t && m.want && m.o_block);
    m.a = m.a_block + off;
    m.b = m.b_block + off;
    m.o = m.o_block + GUARD + off;
    return m;
}

static void bufs_free(Bufs *m)
{
    free(m->a_block);
    free(m->b_block);
    free(m->t);
    free(m->want);
    free(m->o_block);
}

static int have_avx2(void)
{
#ifdef GSPECTRAL_AVX2
    return gspectral_have_avx2();
#else
    return 0;
#endif
}

/* Every kernel of both widths on n samples, ROUNDS random operands: two with every kind of edge case (where the
 * sums are mostly NaN), one with NaNs with a payload in a and finite b and table, then finite ones only (where the
 * sums are not NaN): a positive a, which the finiteness and sign test passes, zero divisors only, any. */
static void check_length(int n, int off)
{
    const double scales[] = {0.5, -0.0, 0.0, 1e300, -3.25, 1e-45, INFINITY, 7.123456789012345};
    Bufs m = bufs_alloc(n, off);
    for (int r = 0; r < ROUNDS; r++) {
        fill_random(m.a, n, r < 2 ? ANY : r == 2 ? PAYLOAD : FINITE);
        fill_random(m.b, n, r < 2 ? ANY : FINITE);
        fill_random(m.t, (n + 7) / 8 * 24, r < 2 ? ANY : FINITE);
        if (r == 3)
            for (int i = 0; i < n; i++)
                m.a[i] = (float)(i % 7) * 0.25f;
        if (r == 4) /* whole zero divisors */
            memset(m.b, 0, (size_t)n * sizeof(float));
        double s = r >= 2 ? 0.5 + r : scales[(n + r) % tu_floats(scales)];
        Sums got;
        snprintf(what, sizeof what, "4-float kernels, %d samples at float %d, round %d", n, off, r);
        for (int op = 0; op < NOPS; op++)
            check_elem(elem4, op, &m, s, n);
        sums4(m.a, m.b, m.t, n, &got);
        check_sums(&got, m.a, m.b, m.t, n, r >= 3);
#ifdef GSPECTRAL_AVX2
        if (have_avx2()) {
            snprintf(what, sizeof what, "8-float kernels, %d samples at float %d, round %d", n, off, r);
            for (int op = 0; op < NOPS; op++)
                check_elem(elem8, op, &m, s, n);
            sums8(m.a, m.b, m.t, n, &got);
            check_sums(&got, m.a, m.b, m.t, n, r >= 3);
        }
#endif
    }
    bufs_free(&m);
}

static void test_kernels_every_length(void **state)
{
    (void)state;
    /* every alignment of the operands and the result modulo 32 bytes (fewer under the sanitizers) */
    const int offsets[] = {0, 1, 2, 3, 4, 5, 6, 7};
    const int noffsets = TU_SANITIZED ? 3 : (int)tu_floats(offsets);
    for (int k = 0; k < noffsets; k++)
        for (int n = 1; n <= SMALL_N; n++)
            check_length(n, offsets[k * (TU_SANITIZED ? 3 : 1)]);
    for (size_t k = 0; k < tu_floats(large_n); k++)
        check_length(large_n[k], (int)k % 8);
    print_message("kernels equal their definitions bit for bit, 1 to %d samples at %d offsets and up to %d (%s)\n",
                  SMALL_N, noffsets, MAX_N,
                  have_avx2() ? "4-float and 8-float versions" : "4-float versions: no AVX2 here");
}

#ifdef GSPECTRAL_AVX2
static GSPECTRAL_TARGET_AVX2 int finite8(const float *a, int n, int nonneg) { return gspectral_kfinite8(a, n, nonneg); }
#endif

/* The finiteness and sign test with one odd sample at every position (in the blocks the jump enters, the
 * samples after the whole blocks and the loop's rounds). */
static void test_finite_every_position(void **state)
{
    (void)state;
    const float odd[] = {INFINITY, -INFINITY, from_bits(0xffc00000u), from_bits(0x7fc01234u), -1.0f, -1e-45f};
    const int lengths[] = {1, 7, 8, 9, 15, 16, 17, 41, 81, 127, 128, 129, 136, 401};
    float *a = malloc(401 * sizeof *a);
    assert_non_null(a);
    for (size_t l = 0; l < tu_floats(lengths); l++) {
        int n = lengths[l];
        for (int pos = 0; pos < n; pos++)
            for (size_t k = 0; k < tu_floats(odd); k++) {
                for (int i = 0; i < n; i++)
                    a[i] = i % 3 ? 0.5f : -0.0f; /* -0 is not below 0 */
                a[pos] = odd[k];
                for (int nonneg = 0; nonneg < 2; nonneg++) {
                    int want = ref_finite(a, n, nonneg);
                    assert_int_equal(want, !(k < 4 || nonneg)); /* the odd sample decides */
                    assert_int_equal(gspectral_kfinite(a, n, nonneg), want);
#ifdef GSPECTRAL_AVX2
                    if (have_avx2())
                        assert_int_equal(finite8(a, n, nonneg), want);
#endif
                }
            }
    }
    free(a);
}

/* ---- the spectrum model's operations against the 4-float kernels ---- */

/* want and got: the same floats, bit for bit, and the same kind */
static void assert_same_color(const GColor *got, const GColor *want)
{
    assert_int_equal(got->kind, want->kind);
    assert_same(got->v, want->v, (size_t)got->model->nvalues * sizeof(float));
}

static void check_model_ops(const GColorModel *m, const GColor *a, const GColor *b, GColor *x, GColor *want,
                            double s)
{
    const GSpectral *sp = m->priv;
    int n = m->nvalues;
    want->kind = GCOLOR_VECTOR;
    int (*api[])(GColor *, const GColor *, const GColor *) = {gcolor_add, gcolor_mul, gcolor_div};
    void (*kern[])(float *, const float *, const float *, int) = {gspectral_kadd, gspectral_kmul, gspectral_kdiv};
    for (int op = 0; op < 3; op++) {
        kern[op](want->v, a->v, b->v, n);
        assert_int_equal(api[op](x, a, b), G_OK);
        assert_same_color(x, want);
        for (int side = 0; side < 2; side++) { /* in place of a, then of b */
            assert_int_equal(gcolor_copy(x, side ? b : a), G_OK);
            assert_int_equal(side ? api[op](x, a, x) : api[op](x, x, b), G_OK);
            assert_same_color(x, want);
        }
    }
    gspectral_kscale(want->v, a->v, (float)s, n);
    assert_int_equal(gcolor_copy(x, a), G_OK);
    assert_int_equal(gcolor_scale(x, x, s), G_OK);
    assert_same_color(x, want);
    gspectral_kaxpyd(want->v, s, a->v, b->v, n);
    assert_int_equal(gcolor_copy(x, b), G_OK);
    assert_int_equal(gcolor_axpy(x, s, a, x), G_OK);
    assert_same_color(x, want);
    gspectral_kmul_scaled(want->v, a->v, b->v, (float)s, n);
    assert_int_equal(gcolor_mul_scaled(x, a, b, s), G_OK);
    assert_same_color(x, want);
    assert_int_equal(gcolor_copy(x, a), G_OK);
    assert_int_equal(gcolor_mul_scaled(x, x, b, s), G_OK);
    assert_same_color(x, want);
    double bright = gspectral_kbright(sp->lum, a->v, n), got_bright = gcolor_brightness(a);
    assert_same(&got_bright, &bright, sizeof bright);
    for (int role = 0; role < 2; role++) {
        double wx[3], gx[3];
        gspectral_kxyz(gspectral_xyz_floats(sp, (GColorRole)role), a->v, n, wx);
        assert_int_equal(gcolor_to_xyz(a, (GColorRole)role, gx), G_OK);
        assert_same(gx, wx, sizeof wx);
    }
    assert_int_equal(gcolor_is_finite(a), gspectral_kfinite(a->v, n, 0));
    assert_int_equal(gcolor_is_nonnegative(a), gspectral_kfinite(a->v, n, 1));
    memset(want->v, 0, (size_t)n * sizeof(float));
    memset(x->v, 0xff, (size_t)n * sizeof(float)); /* NaNs the black must overwrite */
    gcolor_black(x);
    assert_same_color(x, want);
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
    const double scales[] = {0.0, -0.0, 1.0, -2.5, 1e-3, 1e30, 1e300, INFINITY, 0.1};
    for (int r = 0; r < 40; r++) {
        fill_random(a.v, m->nvalues, 0);
        fill_random(b.v, m->nvalues, 0);
        if (r % 10 == 1) /* whole zero divisors and a zero last sample */
            gcolor_black(&b);
        if (r % 10 == 2)
            a.v[m->nvalues - 1] = b.v[m->nvalues - 1] = 0.0f;
        check_model_ops(m, &a, &b, &x, &want, scales[r % tu_floats(scales)]);
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
    if (!opt || opt->max_nm == 0.0 || opt->max_nm >= 780.0) /* a grid over the visible range */
        assert_near(xyz[1], 0.5, 1e-3); /* a reflectance of 0.5 under the white point: Y = 0.5 */
    gscratch_destroy(arena);
    gcolormodel_destroy(m);
}

static void test_model_default_grid(void **state)
{
    (void)state;
    check_model(NULL, 81);
}

static void test_model_other_grids(void **state)
{
    (void)state;
    /* and grids whose last block has 1 to 7 samples, or whose only one does */
    const GColorModelOptions opts[] = {{10.0, 0, 0, 0},       {50.0, 0, 0, 0},       {1.0, 0, 0, 0},
                                       {1.0, 300.0, 830.0, 0}, {20.0, 0, 0, 0},       {25.0, 0, 0, 0},
                                       {16.0, 0, 0, 0},       {10.0, 380.0, 560.0, 0}, {10.0, 380.0, 570.0, 0},
                                       {10.0, 380.0, 590.0, 0}, {10.0, 380.0, 600.0, 0}, {100.0, 0, 0, 0}};
    const int n[] = {41, 9, 401, 531, 21, 17, 26, 19, 20, 22, 23, 5};
    for (size_t k = 0; k < tu_floats(opts); k++)
        check_model(&opts[k], n[k]);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kernels_every_length),
        cmocka_unit_test(test_finite_every_position),
        cmocka_unit_test(test_model_default_grid),
        cmocka_unit_test(test_model_other_grids),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
