/* sampling.c - the sampling checks of `gmat check` (material.h's sample, pdf, is_delta), for every material
 * and texture tree, built-in or plug-in. For light leaving towards `out` at a few incidences and places (from
 * outside, and from inside for a material that is not opaque) it draws NSAMPLES directions with
 * gmaterial_sample and measures:
 *   chi2          goodness of fit of the non-delta directions against gmaterial_pdf (the method of pbrt-v4's
 *                 and Mitsuba 3's chi2 tests): the sphere binned in (cos theta, phi), the expected count of a
 *                 bin N * the integral of pdf over it (adaptive cubature, bin_integral below, so that an
 *                 integrable singularity of a correct pdf is integrated, not sampled at midpoints), bins
 *                 expecting fewer than 5 pooled, Pearson's statistic and its p-value (the regularised
 *                 incomplete gamma function); the figure is -log10 of the smallest p-value, the tolerance
 *                 -log10 of ALPHA corrected for the number of tests (Sidak). A direction drawn where pdf() is
 *                 0 fails at once. A bin whose quadrature nodes all miss the pdf's support while it holds some
 *                 of it (the edge of a lobe about a tilted shading normal crosses the bins slantwise and may
 *                 clip a corner of one; a lobe narrower than the nodes' spacing) has expected count 0 by the
 *                 rule: a draw there is asked pdf() and, when it is positive, the bin is integrated again from
 *                 SPLIT_EDGE x SPLIT_EDGE cells; whatever it still misses counts with the pooled bins.
 *   pdf integral  the integral of pdf over the sphere against the share of draws that gave a non-delta
 *                 direction (1 - P(delta) - P(nothing drawn)); a material whose is_delta says every lobe is
 *                 ideal must draw no other direction.
 *   weight        for non-delta directions weight = value(in, white, out) / pdf(in, out) with value
 *                 reflection() or refraction() (directions on the ideal mirror ray excluded: reflection() is
 *                 the ideal part there) and the sample's pdf = pdf(); for a delta lobe weight * pdf does not
 *                 exceed the value along the ideal ray (other lobes of a blend may add to it). The value is
 *                 refraction() for a sample flagged GSAMPLE_TRANSMIT, else reflection(), as a renderer weighs it;
 *                 a sample on the other side of the geometric surface than its flag says (a ray about a tilted
 *                 shading normal that points into the surface) must carry no light. */
#include "gmat.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NSAMPLES 20000
#define NWEIGHT 2000  /* samples per test whose weight is checked */
#define BINS_COS 16
#define BINS_PHI 32
#define SPLIT_EDGE 8 /* first cells per side where a draw found the pdf positive in a bin whose nodes saw 0 */
#define MIN_EXPECTED 5.0
#define ALPHA 1e-3
#define TOL_INTEGRAL 0.02
#define TOL_WEIGHT 1e-3

static const double sample_incidences[] = {10, 50, 80};
#define NSINC ((int)(sizeof sample_incidences / sizeof sample_incidences[0]))
static const int sample_places[] = {0, 2};
#define NSPLACES ((int)(sizeof sample_places / sizeof sample_places[0]))

/* A small deterministic generator (splitmix64): the same numbers on every run. */
static double next_uniform(unsigned long long *s)
{
    unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* ln Gamma(x) for x > 0 (Lanczos, g = 7, 9 terms). */
static double log_gamma(double x)
{
    static const double c[9] = {0.99999999999980993, 676.5203681218851, -1259.1392167224028,
                                771.32342877765313, -176.61502916214059, 12.507343278686905,
                                -0.13857109526572012, 9.9843695780195716e-6, 1.5056327351493116e-7};
    if (x < 0.5)
        return log(M_PI / fabs(sin(M_PI * x))) - log_gamma(1.0 - x);
    x -= 1.0;
    double a = c[0], t = x + 7.5;
    for (int i = 1; i < 9; i++)
        a += c[i] / (x + i);
    return 0.5 * log(2.0 * M_PI) + (x + 0.5) * log(t) - t + log(a);
}

/* Q(a, x) = Gamma(a, x) / Gamma(a): the series of P below a + 1, the continued fraction of Q above. */
static double gamma_q(double a, double x)
{
    if (!(x > 0.0))
        return 1.0;
    double lg = a * log(x) - x - log_gamma(a);
    if (x < a + 1.0) {
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 1000; n++) {
            term *= x / (a + n);
            sum += term;
            if (fabs(term) < fabs(sum) * 1e-15)
                break;
        }
        return fmax(0.0, 1.0 - sum * exp(lg));
    }
    /* Lentz's method */
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; i++) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < 1e-300)
            d = 1e-300;
        c = b + an / c;
        if (fabs(c) < 1e-300)
            c = 1e-300;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (fabs(del - 1.0) < 1e-15)
            break;
    }
    return exp(lg) * h;
}

typedef struct SampleTest {
    GmatContext *ctx;
    GSurfPoint sp;
    GColor ri;     /* the relative index n(from) / n(to) */
    GColor weight; /* work colours */
    GColor value;
    GColor white;  /* gcolor_fill(1): the white sample() weighs with */
    GVec3 out;
    double ng; /* +1 or -1: the geometric normal's z */
} SampleTest;

/* pdf(in, out) at the test's point. */
static double pdf_at(SampleTest *t, GVec3 in)
{
    GScratchMark mark = gscratch_mark(t->ctx->scratch);
    double pdf = gmaterial_pdf(t->ctx->material, &t->sp, in, t->out, &t->ri);
    gscratch_release(t->ctx->scratch, mark);
    return pdf;
}

/* ---- the pdf's integral over a bin: globally adaptive cubature ----
 *
 * A bin is a rectangle in (theta, phi); the integrand pdf(theta, phi) sin(theta). Each cell is integrated by the
 * 3 x 3 Gauss-Legendre product rule, once whole and once as its four quarters; the quarters' sum is the cell's
 * value and the difference of the two its error. The cell of largest error is split into its quarters until the
 * errors sum below the bin's tolerance or the bin has CELLS_MAX cells (Genz and Malik's strategy, as the adaptive
 * integration of Mitsuba's chi2 test and SciPy's quad): an integrable singularity of the pdf (the 1/(o.h) peak of
 * half-vector sampling at grazing incidence) and a lobe's edge are resolved where they are, the smooth bins cost
 * 45 evaluations. The tolerance is an error in the expected count far below the count's own spread:
 * TOL_COUNT sqrt(max(1, expected)) draws. */

#define CELLS_MAX 256  /* cells of one bin: at most 45 + 144 (CELLS_MAX - 1) / 3 pdf evaluations */
#define TOL_COUNT 0.02 /* the error allowed in a bin's expected count, in units of its standard deviation */

typedef struct Cell {
    double t0, t1, p0, p1; /* the rectangle in theta and phi */
    double quarter[4];     /* the rule over each quarter */
    double value, err;     /* their sum, and its difference from the rule over the whole cell */
} Cell;

/* The 3 x 3 Gauss-Legendre rule of pdf(theta, phi) sin(theta) over [t0, t1] x [p0, p1]; NAN when pdf() is not
 * finite and >= 0 at a node. */
static double gauss3(SampleTest *t, double t0, double t1, double p0, double p1)
{
    static const double x[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static const double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double tm = 0.5 * (t0 + t1), th = 0.5 * (t1 - t0), pm = 0.5 * (p0 + p1), ph = 0.5 * (p1 - p0), sum = 0.0;
    for (int a = 0; a < 3; a++) {
        double theta = tm + th * x[a], st = sin(theta), ct = cos(theta);
        for (int b = 0; b < 3; b++) {
            double phi = pm + ph * x[b];
            double p = pdf_at(t, gvec3(st * cos(phi), st * sin(phi), ct));
            if (!isfinite(p) || p < 0.0)
                return NAN;
            sum += w[a] * w[b] * p * st;
        }
    }
    return sum * th * ph;
}

/* Fills cell c over its rectangle, given the rule over the whole of it: 0, or -1 when pdf() failed. */
static int cell_fill(SampleTest *t, Cell *c, double whole)
{
    double tm = 0.5 * (c->t0 + c->t1), pm = 0.5 * (c->p0 + c->p1);
    c->quarter[0] = gauss3(t, c->t0, tm, c->p0, pm);
    c->quarter[1] = gauss3(t, tm, c->t1, c->p0, pm);
    c->quarter[2] = gauss3(t, c->t0, tm, pm, c->p1);
    c->quarter[3] = gauss3(t, tm, c->t1, pm, c->p1);
    c->value = c->quarter[0] + c->quarter[1] + c->quarter[2] + c->quarter[3];
    c->err = fabs(c->value - whole);
    return isfinite(c->value) && isfinite(whole) ? 0 : -1;
}

/* The pdf integrated over bin (i, j) of the sphere (cos theta in [-1, 1] about +z, phi in [0, 2 pi)), starting
 * from split x split cells (1, or more for a bin whose first nodes all missed a lobe a draw found), for nsamples
 * draws; NAN when pdf() is not finite and >= 0. */
static double bin_integral(SampleTest *t, int i, int j, int split, int nsamples)
{
    static Cell cells[CELLS_MAX];
    double c0 = -1.0 + 2.0 * i / BINS_COS, c1 = -1.0 + 2.0 * (i + 1) / BINS_COS;
    double t0 = acos(c1), t1 = acos(c0); /* theta, to resolve lobes near the poles */
    double p0 = 2.0 * M_PI * j / BINS_PHI, p1 = 2.0 * M_PI * (j + 1) / BINS_PHI;
    int n = 0;
    if (split * split > CELLS_MAX)
        split = 1;
    for (int a = 0; a < split; a++)
        for (int b = 0; b < split; b++) {
            Cell *c = &cells[n++];
            c->t0 = t0 + (t1 - t0) * a / split, c->t1 = t0 + (t1 - t0) * (a + 1) / split;
            c->p0 = p0 + (p1 - p0) * b / split, c->p1 = p0 + (p1 - p0) * (b + 1) / split;
            if (cell_fill(t, c, gauss3(t, c->t0, c->t1, c->p0, c->p1)) != 0)
                return NAN;
        }
    for (;;) {
        double value = 0.0, err = 0.0;
        int worst = 0;
        for (int k = 0; k < n; k++) {
            value += cells[k].value, err += cells[k].err;
            if (cells[k].err > cells[worst].err)
                worst = k;
        }
        double tol = TOL_COUNT * sqrt(fmax(1.0, value * nsamples)) / nsamples;
        if (err <= tol || n + 3 > CELLS_MAX)
            return value;
        /* the worst cell's quarters become cells: the first in its place, the others appended */
        Cell parent = cells[worst];
        double tm = 0.5 * (parent.t0 + parent.t1), pm = 0.5 * (parent.p0 + parent.p1);
        double qt[4][2] = {{parent.t0, tm}, {tm, parent.t1}, {parent.t0, tm}, {tm, parent.t1}};
        double qp[4][2] = {{parent.p0, pm}, {parent.p0, pm}, {pm, parent.p1}, {pm, parent.p1}};
        for (int q = 0; q < 4; q++) {
            Cell *c = q == 0 ? &cells[worst] : &cells[n++];
            c->t0 = qt[q][0], c->t1 = qt[q][1], c->p0 = qp[q][0], c->p1 = qp[q][1];
            if (cell_fill(t, c, parent.quarter[q]) != 0)
                return NAN;
        }
    }
}

/* Relative difference of two colours (absolute below 1e-6). */
static double color_diff(const GColor *a, const GColor *b)
{
    double big = 1e-6, d = 0.0;
    for (int k = 0; k < a->model->nvalues; k++) {
        big = fmax(big, fmax(fabs(a->v[k]), fabs(b->v[k])));
        d = fmax(d, fabs((double)a->v[k] - b->v[k]));
    }
    return isfinite(d) ? d / big : INFINITY;
}

/* How far weight * pdf exceeds value (relative), 0 when it does not. */
static double color_excess(const GColor *w, double pdf, const GColor *value)
{
    double big = 1e-6, d = 0.0;
    for (int k = 0; k < w->model->nvalues; k++) {
        double x = w->v[k] * pdf, v = value->v[k];
        big = fmax(big, fmax(fabs(x), fabs(v)));
        d = fmax(d, x - v);
    }
    return isfinite(d) ? d / big : INFINITY;
}

/* The value of white light from in towards out: reflection() or refraction(). */
static int value_of(SampleTest *t, GVec3 in, int transmit, GColor *value)
{
    GmatContext *ctx = t->ctx;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    int rc = transmit ? gmaterial_refraction(ctx->material, &t->sp, in, &t->white, &t->ri, t->out, value)
                      : gmaterial_reflection(ctx->material, &t->sp, in, &t->white, t->out, value);
    gscratch_release(ctx->scratch, mark);
    return rc;
}

/* Results of one test. */
typedef struct SampleResult {
    double log_p;    /* -log10 of the chi2 p-value (0 without non-delta draws) */
    double integral_err;
    double weight_err;
    int nondelta, delta, failed;
    const char *why; /* of a failure to evaluate */
    const char *weight_why; /* of a weight error not measured by a difference */
} SampleResult;

/* Expected counts: N * the pdf's integral over each bin (bin_integral from split x split cells), only over the bins
 * marked in `only` unless it is NULL, added to *integral; 0 when the pdf is not finite and >= 0. */
static int expect(SampleTest *t, int nsamples, int split, const unsigned char *only, double *expected,
                  double *integral)
{
    for (int b = 0; b < BINS_COS * BINS_PHI; b++) {
        if (only && !only[b])
            continue;
        double v = bin_integral(t, b / BINS_PHI, b % BINS_PHI, split, nsamples);
        if (!isfinite(v))
            return 0;
        expected[b] = v * nsamples;
        *integral += v;
    }
    return 1;
}

/* The sphere's bins of one test: the counts expected from pdf() and those drawn. */
enum { NBINS = BINS_COS * BINS_PHI };
typedef struct Bins {
    double expected[NBINS];
    int observed[NBINS];
    unsigned char missed[NBINS]; /* the nodes saw 0, a draw found the pdf positive */
    int drawn_at_zero;           /* a direction drawn where pdf() is 0 */
} Bins;

/* A delta sample: weight * pdf must not exceed the value along the ideal ray (checked on the first NWEIGHT draws).
 * 0, or -1 when the material failed (r->failed). */
static int check_delta(SampleTest *t, int n, GVec3 in, int transmit, const GMaterialSample *s, SampleResult *r)
{
    r->delta++;
    if (n >= NWEIGHT)
        return 0;
    if (value_of(t, in, transmit, &t->value) != G_OK) {
        r->failed = 1, r->why = "reflection or refraction failed";
        return -1;
    }
    r->weight_err = fmax(r->weight_err, color_excess(&t->weight, s->pdf, &t->value));
    return 0;
}

/* Counts a non-delta direction in its bin; a draw into a bin expecting none is asked pdf() (every such draw: one
 * in a clipped corner must not excuse the others). */
static void bin_draw(SampleTest *t, GVec3 in, Bins *bins)
{
    double c = fmin(1.0, fmax(-1.0, in.z)), phi = atan2(in.y, in.x);
    if (phi < 0.0)
        phi += 2.0 * M_PI;
    int i = (int)((c + 1.0) * 0.5 * BINS_COS), j = (int)(phi / (2.0 * M_PI) * BINS_PHI);
    int b = (i < BINS_COS ? i : BINS_COS - 1) * BINS_PHI + (j < BINS_PHI ? j : BINS_PHI - 1);
    bins->observed[b]++;
    if (bins->expected[b] == 0.0) {
        double pdf = pdf_at(t, in);
        if (pdf > 0.0 && isfinite(pdf))
            bins->missed[b] = 1;
        else
            bins->drawn_at_zero = 1;
    }
}

/* A non-delta sample's weight against value / pdf() and its pdf against pdf() (directions on the ideal mirror ray
 * excluded: reflection() is the ideal part there). 0, or -1 when the material failed (r->failed). */
static int check_weight(SampleTest *t, GVec3 in, int transmit, const GMaterialSample *s, SampleResult *r)
{
    GVec3 n_s = gsurfpoint_normal(&t->sp);
    double pdf = pdf_at(t, in);
    double e = fabs(pdf - s->pdf) / fmax(pdf, s->pdf);
    if (!transmit && gmaterial_is_mirror_pair(in, n_s, t->out))
        return 0;
    if (value_of(t, in, transmit, &t->value) != G_OK) {
        r->failed = 1, r->why = "reflection or refraction failed";
        return -1;
    }
    if (pdf > 0.0 && gcolor_scale(&t->value, &t->value, 1.0 / pdf) == G_OK)
        e = fmax(e, color_diff(&t->weight, &t->value));
    else
        e = INFINITY;
    r->weight_err = fmax(r->weight_err, isfinite(e) ? e : INFINITY);
    return 0;
}

/* Draw n of a test: sample() with the next two numbers of *seed, checked and counted. 0, or -1 when the test
 * failed (r->failed and r->why set). */
static int draw(SampleTest *t, int n, unsigned long long *seed, int is_delta, Bins *bins, SampleResult *r)
{
    GmatContext *ctx = t->ctx;
    double u1 = next_uniform(seed), u2 = next_uniform(seed);
    GMaterialSample s;
    GScratchMark mark = gscratch_mark(ctx->scratch);
    int rc = gmaterial_sample(ctx->material, &t->sp, t->out, &t->ri, u1, u2, &s, &t->weight);
    gscratch_release(ctx->scratch, mark);
    if (rc < 0) {
        r->failed = 1, r->why = "sample returned an error";
        return -1;
    }
    if (rc == 0)
        return 0;
    double len = gvec3_length(s.in);
    if (!isfinite(len) || fabs(len - 1.0) > 1e-4 || !(s.pdf > 0.0) || !isfinite(s.pdf) ||
        !gcolor_is_finite(&t->weight)) {
        r->failed = 1, r->why = "a sample with a direction that is not a unit vector, or a pdf or weight that is "
                                "not finite and positive";
        return -1;
    }
    GVec3 in = gvec3_scale(s.in, 1.0 / len);
    /* the value a renderer weighs the sample with is the one its flag names (path.c); on the other side of the
     * geometric surface than the flag says (a mirror ray about a tilted shading normal that points into the
     * surface) the sample must carry no light (material.h), else it leaks light through the surface */
    int transmit = (s.flags & GSAMPLE_TRANSMIT) != 0;
    if ((in.z * t->ng < 0.0) != transmit && !gcolor_is_black(&t->weight)) {
        r->weight_err = INFINITY;
        r->weight_why = "a reflected sample below the geometric surface, or a transmitted one above it, "
                        "carries light";
    }
    if (s.flags & GSAMPLE_DELTA)
        return check_delta(t, n, in, transmit, &s, r);
    r->nondelta++;
    if (is_delta) {
        r->integral_err = INFINITY; /* is_delta said every lobe is ideal */
        r->why = "is_delta is 1 but a non-delta direction was drawn";
    }
    bin_draw(t, in, bins);
    return n < NWEIGHT ? check_weight(t, in, transmit, &s, r) : 0;
}

/* Pearson's chi2 over the bins, those expecting fewer than MIN_EXPECTED pooled, into r->log_p. */
static void pearson(const Bins *bins, SampleResult *r)
{
    double chi2 = 0.0, pool_e = 0.0;
    int pool_o = 0, dof = -1;
    for (int b = 0; b < NBINS; b++) {
        if (bins->expected[b] < MIN_EXPECTED) {
            pool_e += bins->expected[b];
            pool_o += bins->observed[b];
            continue;
        }
        double d = bins->observed[b] - bins->expected[b];
        chi2 += d * d / bins->expected[b];
        dof++;
    }
    if (pool_e >= MIN_EXPECTED) {
        double d = pool_o - pool_e;
        chi2 += d * d / pool_e;
        dof++;
    } else if (pool_o > 4.0 * MIN_EXPECTED + 4.0 * pool_e) {
        r->log_p = INFINITY; /* many draws where the pdf expects almost none */
        return;
    }
    if (dof < 1)
        return;
    double p = gamma_q(0.5 * dof, 0.5 * chi2);
    r->log_p = p > 0.0 ? -log10(p) : INFINITY;
}

static void run_test(SampleTest *t, int nsamples, unsigned long long seed, SampleResult *r)
{
    static Bins bins;
    memset(&bins, 0, sizeof bins);
    memset(r, 0, sizeof *r);
    int is_delta = gmaterial_is_delta(t->ctx->material, &t->sp);
    if (is_delta < 0) {
        r->failed = 1, r->why = "is_delta failed";
        return;
    }
    /* expected counts first, so that a draw into a bin expecting none is checked as it is drawn */
    double integral = 0.0;
    if (!expect(t, nsamples, 1, NULL, bins.expected, &integral)) {
        r->failed = 1, r->why = "pdf is not finite and >= 0";
        return;
    }
    for (int n = 0; n < nsamples; n++)
        if (draw(t, n, &seed, is_delta, &bins, r) != 0)
            return;
    if (!expect(t, nsamples, SPLIT_EDGE, bins.missed, bins.expected, &integral)) { /* the bins the nodes missed */
        r->failed = 1, r->why = "pdf is not finite and >= 0";
        return;
    }
    double share = (double)r->nondelta / nsamples;
    r->integral_err = fmax(r->integral_err, fabs(integral - share));
    if (r->nondelta == 0)
        return;
    if (bins.drawn_at_zero)
        r->log_p = INFINITY; /* drawn where the pdf says never */
    else
        pearson(&bins, r);
}

/* The worst of every test, where each was seen (the signed incidence theta_out), and the draws counted. */
typedef struct Summary {
    int failed, tests;
    double worst_p, worst_int, worst_w, at_p, at_int, at_w;
    const char *why, *weight_why;
    long delta, nondelta;
} Summary;

/* Adds a test's result at the signed incidence inc; 0, or -1 when the material failed (sum->failed). */
static int summarise(Summary *sum, const SampleResult *r, double inc)
{
    sum->tests++;
    if (r->failed) {
        sum->failed = 1, sum->why = r->why;
        return -1;
    }
    if (r->why && !sum->why)
        sum->why = r->why;
    if (r->weight_why && !sum->weight_why)
        sum->weight_why = r->weight_why;
    sum->delta += r->delta;
    sum->nondelta += r->nondelta;
    if (!(r->log_p <= sum->worst_p))
        sum->worst_p = r->log_p, sum->at_p = inc;
    if (!(r->integral_err <= sum->worst_int))
        sum->worst_int = r->integral_err, sum->at_int = inc;
    if (!(r->weight_err <= sum->worst_w))
        sum->worst_w = r->weight_err, sum->at_w = inc;
    return 0;
}

/* The tests at place number pi, from outside and (unless opaque there) from inside, one per incidence. */
static void test_place(SampleTest *t, int pi, int nsamples, Summary *sum)
{
    GmatContext *ctx = t->ctx;
    for (int below = 0; below < 2 && !sum->failed; below++) {
        gmat_surface_point(ctx, &t->sp, below);
        if (below && gmaterial_opaque(ctx->material, &t->sp))
            break;
        t->ng = below ? -1.0 : 1.0;
        GScratchMark mark = gscratch_mark(ctx->scratch);
        int rc = gmat_relative_index(&t->sp, &t->ri);
        gscratch_release(ctx->scratch, mark);
        if (rc != G_OK) {
            sum->failed = 1, sum->why = "refraction_index failed";
            break;
        }
        for (int a = 0; a < NSINC && !sum->failed; a++) {
            GVec3 d = gmat_direction(sample_incidences[a], 30.0 + 100.0 * pi);
            t->out = below ? gvec3(d.x, d.y, -d.z) : d;
            SampleResult r;
            run_test(t, nsamples, 0x5eed0000ULL + 977ULL * (unsigned long long)(sum->tests + 1), &r);
            summarise(sum, &r, below ? -sample_incidences[a] : sample_incidences[a]);
        }
    }
}

/* The three lines of the sampling checks. */
static void report_summary(const Summary *sum, int nsamples, GmatReportFn report, void *k)
{
    char detail[320];
    if (sum->failed) {
        snprintf(detail, sizeof detail, "(the material failed: %s)", sum->why ? sum->why : "?");
        report(k, "chi2", INFINITY, 0.0, detail);
        report(k, "pdf integral", INFINITY, TOL_INTEGRAL, detail);
        report(k, "weight", INFINITY, TOL_WEIGHT, detail);
        return;
    }
    double tol_p = -log10(1.0 - pow(1.0 - ALPHA, 1.0 / (sum->tests > 0 ? sum->tests : 1)));
    snprintf(detail, sizeof detail, "(-log10 p of sample() against pdf(), %d tests of %d draws, %dx%d bins in "
             "(cos theta, phi); worst at theta_out %g; %ld non-delta, %ld delta draws)", sum->tests, nsamples,
             BINS_COS, BINS_PHI, sum->at_p, sum->nondelta, sum->delta);
    report(k, "chi2", sum->worst_p, tol_p, detail);
    snprintf(detail, sizeof detail, "(|integral of pdf - share of non-delta draws|, worst at theta_out %g%s%s)",
             sum->at_int, sum->why ? "; " : "", sum->why ? sum->why : "");
    report(k, "pdf integral", sum->worst_int, TOL_INTEGRAL, detail);
    snprintf(detail, sizeof detail, "(weight vs value / pdf and the sample's pdf vs pdf(), relative; worst at "
             "theta_out %g%s%s)", sum->at_w, sum->weight_why ? "; " : "", sum->weight_why ? sum->weight_why : "");
    report(k, "weight", sum->worst_w, TOL_WEIGHT, detail);
}

void gmat_check_sampling(GmatContext *ctx, const GmatPlace *places, int nplaces, int nsamples, GmatReportFn report,
                         void *k)
{
    if (nsamples <= 0)
        nsamples = NSAMPLES;
    SampleTest t = {.ctx = ctx};
    Summary sum = {0};
    if (gcolor_alloc(&t.ri, ctx->model) || gcolor_alloc(&t.weight, ctx->model) || gcolor_alloc(&t.value, ctx->model) ||
        gcolor_alloc(&t.white, ctx->model) || gcolor_fill(&t.white, 1.0))
        sum.failed = 1, sum.why = "out of memory";
    for (int pi = 0; pi < NSPLACES && !sum.failed; pi++) {
        ctx->place = &places[sample_places[pi] % nplaces];
        test_place(&t, pi, nsamples, &sum);
    }
    ctx->place = NULL;
    gcolor_free(&t.ri);
    gcolor_free(&t.weight);
    gcolor_free(&t.value);
    gcolor_free(&t.white);
    report_summary(&sum, nsamples, report, k);
}

int gmat_albedo_sampled(GmatContext *ctx, GVec3 out, int n, double *mean, double *se)
{
    const GColorModel *m = ctx->model;
    int nv = m->nvalues;
    GSurfPoint sp;
    GColor ri = {0}, weight = {0};
    double *sum2 = calloc((size_t)nv, sizeof *sum2);
    int rc = sum2 ? G_OK : G_ERR_NOMEM;
    if (rc == G_OK)
        rc = gcolor_alloc(&ri, m);
    if (rc == G_OK)
        rc = gcolor_alloc(&weight, m);
    gmat_surface_point(ctx, &sp, 0);
    if (rc == G_OK) {
        GScratchMark mark = gscratch_mark(ctx->scratch);
        rc = gmat_relative_index(&sp, &ri);
        gscratch_release(ctx->scratch, mark);
    }
    for (int j = 0; j < nv; j++)
        mean[j] = se[j] = 0.0;
    unsigned long long seed = 0xa1bed0ULL;
    for (int i = 0; i < n && rc == G_OK; i++) {
        /* stratified in u1 (n strata), u2 uniform: the same unbiased mean with less spread */
        double u1 = (i + next_uniform(&seed)) / n, u2 = next_uniform(&seed);
        GMaterialSample s;
        GScratchMark mark = gscratch_mark(ctx->scratch);
        int drawn = gmaterial_sample(ctx->material, &sp, out, &ri, u1, u2, &s, &weight);
        gscratch_release(ctx->scratch, mark);
        if (drawn < 0) {
            rc = drawn;
            break;
        }
        if (drawn == 0)
            continue; /* nothing passed on: a weight of 0 */
        if (!gcolor_is_finite(&weight) || !(s.pdf > 0.0)) {
            rc = G_ERR_INVALID;
            break;
        }
        for (int j = 0; j < nv; j++)
            mean[j] += weight.v[j], sum2[j] += (double)weight.v[j] * weight.v[j];
    }
    for (int j = 0; j < nv && rc == G_OK; j++) {
        mean[j] /= n;
        double var = fmax(0.0, sum2[j] / n - mean[j] * mean[j]);
        se[j] = sqrt(var / (n > 1 ? n - 1 : 1));
    }
    free(sum2);
    gcolor_free(&ri);
    gcolor_free(&weight);
    return rc;
}
