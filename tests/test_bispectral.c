/* test_bispectral.c - the bispectral colour model: re-radiation matrices against plain reflectances,
 * energy moved by single entries, composition, folding, and resampling measured matrices between grids
 * (energy preserved, diagonal kept, noise clamped, out-of-range excitation dropped). Synthetic matrices
 * only: every expected value is known in closed form. */
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
#include "test_util.h"

enum { CAP = 128 * 128 };
static float buf[8][CAP];

static GColorModel *model(double step, double lo, double hi)
{
    GColorModelOptions o = {step, lo, hi, 0};
    GColorModel *m = NULL;
    GError err;
    int rc = gcolormodel_create("bispectral", &o, &m, &err);
    if (rc != G_OK)
        printf("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return m;
}

static int at(const GColorModel *m, double nm) { return (int)floor((nm - m->lambda_min) / m->lambda_step + 0.5); }

/* A matrix given on the model's own grid. */
static void matrix(const GColorModel *m, const float *data, GColor *out)
{
    int n = m->nsamples;
    GReradiation r = {m->lambda_min, m->lambda_step, n, m->lambda_min, m->lambda_step, n, data};
    GError err;
    assert_int_equal(gcolor_from_reradiation(out, &r, &err), G_OK);
    assert_int_equal(out->kind, GCOLOR_MATRIX);
}

static unsigned rng = 12345u;
static float frand(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (float)((rng >> 8) / 16777216.0);
}

static double max_rel_diff(const float *a, const float *b, int n)
{
    double d = 0.0, s = 0.0;
    for (int i = 0; i < n; i++) {
        d = fmax(d, fabs((double)a[i] - b[i]));
        s = fmax(s, fabs((double)a[i]));
    }
    return s > 0 ? d / s : d;
}

static void test_diagonal_matrix_is_a_reflectance(void **state)
{
    (void)state;
    GColorModel *m = model(0, 0, 0);
    int n = m->nsamples;
    GColor r, d, light, o1, o2;
    assert_int_equal(gcolor_wrap(&r, m, buf[0], tu_floats(buf[0])), G_OK);
    assert_int_equal(gcolor_wrap(&d, m, buf[1], tu_floats(buf[1])), G_OK);
    assert_int_equal(gcolor_wrap(&light, m, buf[2], tu_floats(buf[2])), G_OK);
    assert_int_equal(gcolor_wrap(&o1, m, buf[3], tu_floats(buf[3])), G_OK);
    assert_int_equal(gcolor_wrap(&o2, m, buf[4], tu_floats(buf[4])), G_OK);
    double refl[3] = {0.2, 0.7, 0.4}, lrgb[3] = {0.9, 0.8, 0.6};
    assert_int_equal(gcolor_from_rgb(&r, refl, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_from_rgb(&light, lrgb, GCOLOR_LIGHT), G_OK);
    static float data[CAP];
    memset(data, 0, sizeof data);
    for (int k = 0; k < n; k++)
        data[k * n + k] = r.v[k];
    matrix(m, data, &d);
    assert_memory_equal(d.v, data, (size_t)n * n * sizeof(float)); /* same grid: an exact copy */
    /* reflection */
    assert_int_equal(gcolor_mul(&o1, &d, &light), G_OK);
    assert_int_equal(gcolor_mul(&o2, &r, &light), G_OK);
    assert_int_equal(o1.kind, GCOLOR_VECTOR);
    assert_true(max_rel_diff(o1.v, o2.v, n) < 1e-6);
    /* conversions, brightness */
    double x1[3], x2[3];
    for (int role = 0; role < 2; role++) {
        assert_int_equal(gcolor_to_xyz(&d, (GColorRole)role, x1), G_OK);
        assert_int_equal(gcolor_to_xyz(&r, (GColorRole)role, x2), G_OK);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(x1[i] - x2[i]) < 1e-6);
        GSpectrumNM s1, s2;
        assert_int_equal(gcolor_to_nm(&d, (GColorRole)role, &s1), G_OK);
        assert_int_equal(gcolor_to_nm(&r, (GColorRole)role, &s2), G_OK);
        assert_true(max_rel_diff(s1.v, s2.v, GNM_COUNT) < 1e-6);
    }
    assert_true(fabs(gcolor_brightness(&d) - gcolor_brightness(&r)) < 1e-6);
    /* pow and div act on the diagonal and give vectors */
    assert_int_equal(gcolor_pow(&o1, &d, 2.0), G_OK);
    assert_int_equal(gcolor_mul(&o2, &r, &r), G_OK);
    assert_int_equal(o1.kind, GCOLOR_VECTOR);
    assert_true(max_rel_diff(o1.v, o2.v, n) < 1e-6);
    assert_int_equal(gcolor_div(&o1, &d, &r), G_OK);
    for (int k = 0; k < n; k++)
        assert_true(r.v[k] == 0.0f ? o1.v[k] == 0.0f : fabsf(o1.v[k] - 1.0f) < 1e-6f);
    /* D * D is diag(r^2), D + r is diag(2 r) */
    assert_int_equal(gcolor_mul(&o1, &d, &d), G_OK);
    assert_int_equal(o1.kind, GCOLOR_MATRIX);
    assert_int_equal(gcolor_add(&o2, &d, &r), G_OK);
    assert_int_equal(o2.kind, GCOLOR_MATRIX);
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++) {
            float want1 = o == i ? r.v[o] * r.v[o] : 0.0f, want2 = o == i ? 2.0f * r.v[o] : 0.0f;
            assert_true(fabsf(o1.v[o * n + i] - want1) < 1e-6f && fabsf(o2.v[o * n + i] - want2) < 1e-6f);
        }
    gcolormodel_destroy(m);
}

static void test_single_entry_moves_energy(void **state)
{
    (void)state;
    GColorModel *m = model(0, 0, 0);
    int n = m->nsamples, i450 = at(m, 450), i600 = at(m, 600);
    const float k = 0.3f;
    GColor mat, light, out;
    assert_int_equal(gcolor_wrap(&mat, m, buf[0], tu_floats(buf[0])), G_OK);
    assert_int_equal(gcolor_wrap(&light, m, buf[1], tu_floats(buf[1])), G_OK);
    assert_int_equal(gcolor_wrap(&out, m, buf[2], tu_floats(buf[2])), G_OK);
    GSpectrumNM d65;
    assert_int_equal(gcie_illuminant_nm("D65", &d65), G_OK);
    assert_int_equal(gcolor_from_nm(&light, &d65, GCOLOR_LIGHT), G_OK);
    const float *l = light.v;
    static float data[CAP];
    /* only the entry: exactly k of the light at 450 nm appears at 600 nm, nothing anywhere else */
    memset(data, 0, sizeof data);
    data[i600 * n + i450] = k;
    matrix(m, data, &mat);
    assert_int_equal(gcolor_mul(&out, &mat, &light), G_OK);
    for (int s = 0; s < n; s++)
        assert_true(out.v[s] == (s == i600 ? k * l[i450] : 0.0f));
    /* a conserving matrix: white except that k of 450 nm leaves its diagonal for 600 nm */
    for (int s = 0; s < n; s++)
        data[s * n + s] = 1.0f;
    data[i450 * n + i450] = 1.0f - k;
    matrix(m, data, &mat);
    assert_int_equal(gcolor_mul(&out, &mat, &light), G_OK);
    double e_in = 0.0, e_out = 0.0;
    for (int s = 0; s < n; s++) {
        e_in += l[s];
        e_out += out.v[s];
        if (s == i450)
            assert_true(fabsf(out.v[s] - (1.0f - k) * l[s]) < 1e-6f * l[s]);
        else if (s == i600)
            assert_true(fabsf(out.v[s] - (l[s] + k * l[i450])) < 1e-6f * l[s]);
        else
            assert_true(out.v[s] == l[s]);
    }
    assert_true(fabs(e_out - e_in) < 1e-6 * e_in); /* energy moved, not made */
    /* a monochromatic 450 nm light comes back as 1 - k at 450 nm and k at 600 nm */
    gcolor_black(&light);
    light.v[i450] = 1.0f;
    assert_int_equal(gcolor_mul(&out, &mat, &light), G_OK);
    for (int s = 0; s < n; s++)
        assert_true(out.v[s] == (s == i450 ? 1.0f - k : s == i600 ? k : 0.0f));
    gcolormodel_destroy(m);
}

static void random_matrix(const GColorModel *m, GColor *out, float scale)
{
    int n = m->nsamples;
    static float data[CAP];
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++)
            data[o * n + i] = o == i ? 0.5f + 0.5f * frand() : (o > i ? scale * frand() : 0.0f);
    matrix(m, data, out);
}

/* The default model with a random matrix in a (off-diagonal entries up to 0.05) and v, o beside it. */
static GColorModel *random_fixture(GColor *a, GColor *v, GColor *o)
{
    GColorModel *m = model(0, 0, 0);
    assert_int_equal(gcolor_wrap(a, m, buf[0], tu_floats(buf[0])), G_OK);
    assert_int_equal(gcolor_wrap(v, m, buf[1], tu_floats(buf[1])), G_OK);
    assert_int_equal(gcolor_wrap(o, m, buf[2], tu_floats(buf[2])), G_OK);
    random_matrix(m, a, 0.05f);
    return m;
}

static void test_composition(void **state)
{
    (void)state;
    GColorModel *m = model(0, 0, 0);
    int n = m->nsamples, nn = n * n;
    GColor a, b, ab, light, x1, x2, t, c;
    assert_int_equal(gcolor_wrap(&a, m, buf[0], tu_floats(buf[0])), G_OK);
    assert_int_equal(gcolor_wrap(&b, m, buf[1], tu_floats(buf[1])), G_OK);
    assert_int_equal(gcolor_wrap(&ab, m, buf[2], tu_floats(buf[2])), G_OK);
    assert_int_equal(gcolor_wrap(&light, m, buf[3], tu_floats(buf[3])), G_OK);
    assert_int_equal(gcolor_wrap(&x1, m, buf[4], tu_floats(buf[4])), G_OK);
    assert_int_equal(gcolor_wrap(&x2, m, buf[5], tu_floats(buf[5])), G_OK);
    assert_int_equal(gcolor_wrap(&t, m, buf[6], tu_floats(buf[6])), G_OK);
    assert_int_equal(gcolor_wrap(&c, m, buf[7], tu_floats(buf[7])), G_OK);
    random_matrix(m, &a, 0.02f);
    random_matrix(m, &b, 0.02f);
    double lrgb[3] = {0.7, 0.9, 1.1};
    assert_int_equal(gcolor_from_rgb(&light, lrgb, GCOLOR_LIGHT), G_OK);
    /* (A B) L = A (B L) */
    assert_int_equal(gcolor_mul(&ab, &a, &b), G_OK);
    assert_int_equal(ab.kind, GCOLOR_MATRIX);
    assert_int_equal(gcolor_mul(&x1, &ab, &light), G_OK);
    assert_int_equal(gcolor_mul(&t, &b, &light), G_OK);
    assert_int_equal(gcolor_mul(&x2, &a, &t), G_OK);
    assert_true(max_rel_diff(x1.v, x2.v, n) < 1e-5);
    /* in place: out aliasing either operand or both */
    assert_int_equal(gcolor_copy(&c, &a), G_OK);
    assert_int_equal(gcolor_mul(&c, &c, &b), G_OK);
    assert_true(max_rel_diff(c.v, ab.v, nn) < 1e-6);
    assert_int_equal(gcolor_copy(&c, &b), G_OK);
    assert_int_equal(gcolor_mul(&c, &a, &c), G_OK);
    assert_true(max_rel_diff(c.v, ab.v, nn) < 1e-6);
    assert_int_equal(gcolor_mul(&x1, &a, &a), G_OK); /* A^2 */
    assert_int_equal(gcolor_copy(&c, &a), G_OK);
    assert_int_equal(gcolor_mul(&c, &c, &c), G_OK);
    assert_true(max_rel_diff(c.v, x1.v, nn) < 1e-6);
    /* M * V in place on the light */
    assert_int_equal(gcolor_mul(&x1, &a, &light), G_OK);
    assert_int_equal(gcolor_copy(&t, &light), G_OK);
    assert_int_equal(gcolor_mul(&t, &a, &t), G_OK);
    assert_true(max_rel_diff(t.v, x1.v, n) < 1e-7);
    /* V * M = diag(v) M: a filter after the fluorescent layer, exact on any light */
    GColor r;
    float rv[CAP];
    assert_int_equal(gcolor_wrap(&r, m, rv, tu_floats(rv)), G_OK);
    double refl[3] = {0.9, 0.3, 0.5};
    assert_int_equal(gcolor_from_rgb(&r, refl, GCOLOR_REFLECTANCE), G_OK);
    assert_int_equal(gcolor_mul(&c, &r, &a), G_OK);
    assert_int_equal(c.kind, GCOLOR_MATRIX);
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++)
            assert_true(fabsf(c.v[o * n + i] - rv[o] * a.v[o * n + i]) <= 1e-7f);
    assert_int_equal(gcolor_mul(&x1, &c, &light), G_OK);
    assert_int_equal(gcolor_mul(&t, &a, &light), G_OK);
    assert_int_equal(gcolor_mul(&x2, &r, &t), G_OK);
    assert_true(max_rel_diff(x1.v, x2.v, n) < 1e-6);
    gcolormodel_destroy(m);
}

static void test_fold_and_brightness(void **state)
{
    (void)state;
    GColor a, v, o;
    GColorModel *m = random_fixture(&a, &v, &o);
    int n = m->nsamples;
    for (int r = 0; r < n; r++) {
        double s = 0.0;
        for (int i = 0; i < n; i++)
            s += a.v[r * n + i];
        v.v[r] = (float)s;
    }
    for (int role = 0; role < 2; role++) {
        GSpectrumNM s;
        assert_int_equal(gcolor_to_nm(&a, (GColorRole)role, &s), G_OK);
        for (int r = 0; r < n; r++) /* grid wavelengths are whole nm: the folded value is the row sum */
            assert_true(fabsf(s.v[(int)(m->lambda_min + r * m->lambda_step) - GNM_MIN] - v.v[r]) < 1e-6f * v.v[r]);
        double x1[3], x2[3];
        assert_int_equal(gcolor_to_xyz(&a, (GColorRole)role, x1), G_OK);
        assert_int_equal(gcolor_to_xyz(&v, (GColorRole)role, x2), G_OK);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(x1[i] - x2[i]) < 1e-6 * fabs(x2[i]) + 1e-9);
    }
    /* brightness of a matrix is that of its response to equal-energy light */
    assert_true(fabs(gcolor_brightness(&a) - gcolor_brightness(&v)) < 1e-6 * gcolor_brightness(&v));
    /* c I has brightness c */
    static float data[CAP];
    memset(data, 0, sizeof data);
    for (int k = 0; k < n; k++)
        data[k * n + k] = 0.75f;
    matrix(m, data, &o);
    assert_true(fabs(gcolor_brightness(&o) - 0.75) < 1e-6);
    /* 0 only for black: a zero matrix is 0, a single entry anywhere is not */
    assert_int_equal(gcolor_scale(&o, &a, 0.0), G_OK);
    assert_int_equal(o.kind, GCOLOR_MATRIX);
    assert_true(gcolor_brightness(&o) == 0.0);
    for (int e = 0; e < n * n; e += 37) {
        o.v[e] = 1e-4f;
        assert_true(gcolor_brightness(&o) > 0.0);
        o.v[e] = -1e-4f;
        assert_true(gcolor_brightness(&o) > 0.0);
        o.v[e] = 0.0f;
    }
    gcolormodel_destroy(m);
}

static void test_matrix_vector_operations(void **state)
{
    (void)state;
    GColor a, v, o;
    GColorModel *m = random_fixture(&a, &v, &o);
    int n = m->nsamples;
    double rgb[3] = {0.4, 0.5, 0.6};
    assert_int_equal(gcolor_from_rgb(&v, rgb, GCOLOR_REFLECTANCE), G_OK);
    /* add: A + diag(v) in both orders, and into the vector's own storage */
    assert_int_equal(gcolor_add(&o, &a, &v), G_OK);
    for (int r = 0; r < n; r++)
        for (int i = 0; i < n; i++)
            assert_true(o.v[r * n + i] == a.v[r * n + i] + (r == i ? v.v[r] : 0.0f));
    static float keep[CAP];
    memcpy(keep, o.v, (size_t)n * n * sizeof *keep);
    assert_int_equal(gcolor_add(&o, &v, &a), G_OK);
    assert_memory_equal(o.v, keep, (size_t)n * n * sizeof *keep);
    GColor v2;
    assert_int_equal(gcolor_wrap(&v2, m, buf[3], tu_floats(buf[3])), G_OK);
    assert_int_equal(gcolor_copy(&v2, &v), G_OK);
    assert_int_equal(gcolor_add(&v2, &v2, &a), G_OK);
    assert_int_equal(v2.kind, GCOLOR_MATRIX);
    assert_memory_equal(v2.v, keep, (size_t)n * n * sizeof *keep);
    /* scale keeps the kind, per entry */
    assert_int_equal(gcolor_scale(&o, &a, 2.0), G_OK);
    assert_int_equal(o.kind, GCOLOR_MATRIX);
    for (int e = 0; e < n * n; e++)
        assert_true(o.v[e] == 2.0f * a.v[e]);
    /* div: diagonals, a vector */
    assert_int_equal(gcolor_div(&o, &a, &v), G_OK);
    assert_int_equal(o.kind, GCOLOR_VECTOR);
    for (int k = 0; k < n; k++)
        assert_true(fabsf(o.v[k] - a.v[k * n + k] / v.v[k]) < 1e-6f * o.v[k]);
    assert_int_equal(gcolor_copy(&o, &a), G_OK);
    assert_int_equal(gcolor_div(&o, &o, &a), G_OK); /* in place */
    for (int k = 0; k < n; k++)
        assert_true(fabsf(o.v[k] - 1.0f) < 1e-6f);
    /* pow: the diagonal only (absorption does not fluoresce) */
    assert_int_equal(gcolor_pow(&o, &a, 0.5), G_OK);
    assert_int_equal(o.kind, GCOLOR_VECTOR);
    for (int k = 0; k < n; k++)
        assert_true(fabsf(o.v[k] - sqrtf(a.v[k * n + k])) < 1e-6f);
    gcolormodel_destroy(m);
}

/* A fluorescent band on any grid: absorbed around 470 nm, emitted around 600 nm, zero diagonal (both well
 * inside 380..780 nm: the grid edges, where the hat is cut in half, are not what is measured here). The
 * density per nm of excitation times the excitation step is the share per bin. */
static float *band(double in_min, double in_step, int n_in, double out_min, double out_step, int n_out)
{
    float *d = calloc((size_t)n_in * n_out, sizeof *d);
    for (int o = 0; o < n_out; o++)
        for (int i = 0; i < n_in; i++) {
            double li = in_min + i * in_step, lo = out_min + o * out_step;
            if (fabs(li - lo) < 1e-9)
                continue;
            double g = 0.004 * exp(-0.5 * pow((li - 470.0) / 20.0, 2)) * exp(-0.5 * pow((lo - 600.0) / 25.0, 2));
            d[(size_t)o * n_in + i] = (float)(g * in_step);
        }
    return d;
}

/* Energy re-radiated under equal-energy light, and where it goes (centroids of excitation and emission). */
static void energy(const float *d, double in_min, double in_step, int n_in, double out_min, double out_step,
                   int n_out, double *e, double *c_in, double *c_out)
{
    double s = 0.0, si = 0.0, so = 0.0;
    for (int o = 0; o < n_out; o++)
        for (int i = 0; i < n_in; i++) {
            double v = d[(size_t)o * n_in + i] * out_step;
            s += v;
            si += v * (in_min + i * in_step);
            so += v * (out_min + o * out_step);
        }
    *e = s;
    *c_in = si / s;
    *c_out = so / s;
}

static void test_resampling_preserves_energy(void **state)
{
    (void)state;
    const struct {
        double in_min, in_step;
        int n_in;
        double out_min, out_step;
        int n_out;
        double tol;
    } src[] = {
        {380, 5, 81, 380, 5, 81, 2e-5},   /* finer */
        {380, 20, 21, 380, 20, 21, 2e-5}, /* coarser */
        {380, 2, 201, 380, 2, 201, 2e-5}, /* much finer */
        {300, 5, 97, 380, 10, 41, 2e-5},  /* measured-style: UV excitation, different steps */
        {380, 8, 51, 380, 8, 51, 2e-4},   /* not aligned with the model's grid */
    };
    const double steps[] = {10, 5};
    for (int s = 0; s < 2; s++) {
        GColorModel *m = model(steps[s], 0, 0);
        int n = m->nsamples;
        GColor c;
        assert_int_equal(gcolor_wrap(&c, m, buf[0], tu_floats(buf[0])), G_OK);
        for (size_t k = 0; k < sizeof src / sizeof src[0]; k++) {
            float *d = band(src[k].in_min, src[k].in_step, src[k].n_in, src[k].out_min, src[k].out_step,
                            src[k].n_out);
            GReradiation r = {src[k].in_min, src[k].in_step, src[k].n_in, src[k].out_min, src[k].out_step,
                              src[k].n_out, d};
            GError err;
            assert_int_equal(gcolor_from_reradiation(&c, &r, &err), G_OK);
            double e0, i0, o0, e1, i1, o1;
            energy(d, r.in_min, r.in_step, r.n_in, r.out_min, r.out_step, r.n_out, &e0, &i0, &o0);
            energy(c.v, m->lambda_min, m->lambda_step, n, m->lambda_min, m->lambda_step, n, &e1, &i1, &o1);
            printf("model %g nm <- %g/%g nm: re-radiated energy %.6f -> %.6f (%.1e), centroids %.2f->%.2f, "
                   "%.2f->%.2f nm\n",
                   steps[s], src[k].in_step, src[k].out_step, e0, e1, fabs(e1 - e0) / e0, i0, i1, o0, o1);
            assert_true(fabs(e1 - e0) <= src[k].tol * e0);
            assert_true(fabs(i1 - i0) < 0.5 && fabs(o1 - o0) < 0.5);
            for (int e = 0; e < n * n; e++)
                assert_true(c.v[e] >= 0.0f);
            free(d);
        }
        gcolormodel_destroy(m);
    }
}

static void test_resampling_diagonal_noise_range(void **state)
{
    (void)state;
    GColorModel *m = model(0, 0, 0);
    int n = m->nsamples;
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, buf[0], tu_floats(buf[0])), G_OK);
    /* a smooth reflectance on a 5 nm grid with negative noise off the diagonal */
    int ns = 81;
    float *d = calloc((size_t)ns * ns, sizeof *d);
    for (int o = 0; o < ns; o++)
        for (int i = 0; i < ns; i++)
            d[o * ns + i] = o == i ? (float)(0.5 + 0.3 * sin((380.0 + 5 * o) / 60.0)) : -1e-3f * frand();
    GReradiation r = {380, 5, ns, 380, 5, ns, d};
    GError err;
    assert_int_equal(gcolor_from_reradiation(&c, &r, &err), G_OK);
    for (int o = 0; o < n; o++)
        for (int i = 0; i < n; i++) {
            double x = 380.0 + 10 * o;
            if (o == i)
                assert_true(fabs(c.v[o * n + i] - (0.5 + 0.3 * sin(x / 60.0))) < 2e-3);
            else
                assert_true(c.v[o * n + i] == 0.0f); /* noise clamped, nothing invented */
        }
    free(d);
    /* excitation outside the model's range is dropped; a grid starting at 300 nm keeps it */
    int n_in = 49;
    d = calloc((size_t)n * n_in, sizeof *d);
    d[at(m, 600) * n_in + 4] = 0.2f; /* excitation 340 nm -> emission 600 nm */
    GReradiation uv = {300, 10, n_in, 380, 10, n, d};
    assert_int_equal(gcolor_from_reradiation(&c, &uv, &err), G_OK);
    assert_true(gcolor_brightness(&c) == 0.0);
    GColorModel *wide = model(10, 300, 780);
    GColor w;
    assert_int_equal(gcolor_wrap(&w, wide, buf[1], tu_floats(buf[1])), G_OK);
    assert_int_equal(gcolor_from_reradiation(&w, &uv, &err), G_OK);
    int nw = wide->nsamples;
    for (int e = 0; e < nw * nw; e++)
        assert_true(fabsf(w.v[e] - (e == at(wide, 600) * nw + at(wide, 340) ? 0.2f : 0.0f)) < 1e-7f);
    free(d);
    /* grids that never meet have no diagonal: refused */
    float z[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    GReradiation off = {385, 10, 2, 380, 10, 2, z};
    assert_int_equal(gcolor_from_reradiation(&c, &off, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "diagonal"));
    float nan_data[4] = {0.1f, NAN, 0.3f, 0.4f};
    GReradiation bad = {380, 10, 2, 380, 10, 2, nan_data};
    assert_int_equal(gcolor_from_reradiation(&c, &bad, &err), G_ERR_INVALID);
    GReradiation nan_grid = {NAN, 10, 2, 380, 10, 2, z}, inf_step = {380, INFINITY, 2, 380, 10, 2, z};
    assert_int_equal(gcolor_from_reradiation(&c, &nan_grid, &err), G_ERR_INVALID);
    assert_int_equal(gcolor_from_reradiation(&c, &inf_step, &err), G_ERR_INVALID);
    /* an emission step far wider than the excitation step: only the excitation column at the emission row's
     * own wavelength is its diagonal, never the neighbours within a tolerance scaled by the wide step */
    float one_row[3] = {0.5f, 0.8f, 0.0f};
    GReradiation coarse = {400, 10, 3, 400, 1e8, 1, one_row};
    assert_int_equal(gcolor_from_reradiation(&c, &coarse, &err), G_OK);
    for (int e = 0; e < n * n; e++) {
        float want = e == at(m, 400) * n + at(m, 400) ? 0.5f : e == at(m, 400) * n + at(m, 410) ? 0.8f : 0.0f;
        assert_true(fabsf(c.v[e] - want) < 1e-6f);
    }
    gcolormodel_destroy(wide);
    gcolormodel_destroy(m);
}

static void test_grid_limit(void **state)
{
    (void)state;
    GColorModel *m;
    GError err;
    GColorModelOptions big = {2, 300, 830, 0}; /* 266 samples: more than the 128 the stack buffers allow */
    assert_int_equal(gcolormodel_create("bispectral", &big, &m, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "128"));
    GColorModelOptions most = {5, 300, 830, 0}; /* 107 samples */
    assert_int_equal(gcolormodel_create("bispectral", &most, &m, &err), G_OK);
    assert_int_equal(m->capacity, 107 * 107);
    gcolormodel_destroy(m);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_diagonal_matrix_is_a_reflectance),
        cmocka_unit_test(test_single_entry_moves_energy),
        cmocka_unit_test(test_composition),
        cmocka_unit_test(test_fold_and_brightness),
        cmocka_unit_test(test_matrix_vector_operations),
        cmocka_unit_test(test_resampling_preserves_energy),
        cmocka_unit_test(test_resampling_diagonal_noise_range),
        cmocka_unit_test(test_grid_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
