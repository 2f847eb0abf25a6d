/* test_texture_generators.c - the generators: checker parity and filtering, improved Perlin noise (range,
 * continuity, determinism, analytic gradient), fbm, turbulence, wood, marble, surface, gradient fields,
 * the default finite-difference gradient, the value cache, and bad parameters. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "test_util.h"
#include "texture_fixtures.h"

#include <stdio.h>

/* A deterministic sequence in [lo, hi) (no libc rand: the same values everywhere). */
static double uniform(uint64_t *s, double lo, double hi)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(*s >> 11) / 9007199254740992.0;
}

static double at_uv(const GGenerator *g, double u, double v, double uv_footprint)
{
    GSurfPoint sp;
    plane_point(&sp, NULL, NULL, u, v);
    sp.uv_footprint = uv_footprint;
    return ggenerator_value(g, &sp);
}

static double at_xyz(const GGenerator *g, GVec3 p)
{
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.point = sp.object_point = p;
    return ggenerator_value(g, &sp);
}

static void test_checker_parity(void **state)
{
    (void)state;
    GGenerator *c2, *c4, *c3;
    GError err;
    assert_int_equal(ggenerator_checker_create(2, 1.0, &c2, &err), G_OK);
    assert_int_equal(ggenerator_checker_create(2, 4.0, &c4, &err), G_OK);
    assert_int_equal(ggenerator_checker_create(3, 1.0, &c3, &err), G_OK);
    assert_string_equal(ggenerator_name(c2), "checker");
    const double pts[][3] = {{0.5, 0.5, 0}, {1.5, 0.5, 1}, {-0.5, 0.5, 1}, {-0.5, -0.5, 0},
                             {2.5, 3.5, 1}, {10.2, 7.9, 1}, {-3.1, 2.2, 0}};
    for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++)
        assert_float_equal(at_uv(c2, pts[i][0], pts[i][1], 0.0), pts[i][2], 0.0);
    assert_float_equal(at_uv(c4, 0.3, 0.1, 0.0), 1.0, 0.0); /* cells (1, 0) at 4 per unit */
    assert_float_equal(at_uv(c4, 0.6, 0.3, 0.0), 1.0, 0.0); /* (2, 1) */
    assert_float_equal(at_uv(c4, 0.6, 0.6, 0.0), 0.0, 0.0); /* (2, 2) */
    const double p3[][4] = {{0.5, 0.5, 0.5, 0}, {1.5, 0.5, 0.5, 1}, {1.5, 1.5, 0.5, 0},
                            {1.5, 1.5, 1.5, 1}, {-0.5, 0.5, 0.5, 1}, {-0.5, -0.5, -0.5, 1}};
    for (size_t i = 0; i < sizeof p3 / sizeof p3[0]; i++)
        assert_float_equal(at_xyz(c3, gvec3(p3[i][0], p3[i][1], p3[i][2])), p3[i][3], 0.0);

    /* box filtering over the footprint: two whole cells average to 1/2; a cell-wide box centred on an
     * edge gives 1/2; at a cell centre a box of one cell gives the cell */
    assert_float_equal(at_uv(c2, 0.37, 0.61, 2.0), 0.5, 1e-12);
    assert_float_equal(at_uv(c2, 1.0, 0.5, 1.0), 0.5, 1e-12);
    assert_float_equal(at_uv(c2, 1.5, 0.5, 1.0), 1.0, 1e-12);
    assert_float_equal(at_uv(c2, 1.5, 0.5, 0.5), 1.0, 1e-12);
    /* a box of 1/2 cell reaching a quarter over the edge at u = 1: 1/2 of it white */
    assert_float_equal(at_uv(c2, 1.0, 0.5, 0.5), 0.5, 1e-12);
    assert_float_equal(at_uv(c2, 1.125, 0.5, 0.5), 0.75, 1e-12);
    assert_float_equal(at_uv(c2, 12345.3, 77.1, 5000.0), 0.5, 1e-12); /* far away: grey */
    /* a window inside one cell gives the cell exactly (0 or 1, not 1 - 2e-16: a blend over the checker then
     * evaluates one child), at any position and width that stays inside, on both sides of 0 */
    uint64_t s = 7;
    for (int i = 0; i < 10000; i++) {
        double cu = floor(uniform(&s, -50, 50)), cv = floor(uniform(&s, -50, 50)), w = uniform(&s, 1e-8, 0.5);
        double u = cu + 0.5 * w + uniform(&s, 0, 1 - w), v = cv + 0.5 * w + uniform(&s, 0, 1 - w);
        double want = fmod(fabs(cu), 2.0) != fmod(fabs(cv), 2.0) ? 1.0 : 0.0;
        double got = at_uv(c2, u, v, w);
        if (u - 0.5 * w > cu && u + 0.5 * w < cu + 1 && v - 0.5 * w > cv && v + 0.5 * w < cv + 1)
            assert_true(got == want);
        else
            assert_float_equal(got, want, 1e-9); /* rounding put an end on the edge */
    }
    /* the parity of a cell far out, where u is an integer or an even one (2^52 and up), on both sides of 0:
     * the cell of floor(u), as fmod(|floor(u)|, 2) gives it; at v = 0.5 (cell 0) the checker is that parity */
    for (int e = 20; e <= 70; e++)
        for (int k = -3; k <= 3; k++)
            for (int sign = -1; sign <= 1; sign += 2) {
                double u = sign * (ldexp(1.0, e) + k + 0.25);
                assert_true(at_uv(c2, u, 0.5, 0.0) == fmod(fabs(floor(u)), 2.0));
            }
    ggenerator_unref(c2);
    ggenerator_unref(c4);
    ggenerator_unref(c3);
}

/* The box-filtered square wave by its definition, with floors: the cell's parity (fmod(|floor(x)|, 2)) when the
 * window [x - w/2, x + w/2] lies in one cell or w is negligible, else the integral over the window over w. */
static double wave_integral_ref(double x) { return floor(0.5 * x) + fmax(0.0, x - 2.0 * floor(0.5 * x) - 1.0); }

static double filtered_ref(double x, double w)
{
    if (w > 1e3)
        return 0.5;
    double lo = x - 0.5 * w, hi = x + 0.5 * w;
    if (w > 1e-9 && floor(lo) != floor(hi))
        return (wave_integral_ref(hi) - wave_integral_ref(lo)) / w;
    return fmod(fabs(floor(x)), 2.0);
}

/* The checker equals the definition above, xor-ed over the axes, to the bit: windows inside cells, across edges
 * (ends within rounding of an integer), on both sides of 0 and far out (2^52 and beyond, where u is an integer). */
static void test_checker_definition(void **state)
{
    (void)state;
    GGenerator *c2, *c3;
    GError err;
    assert_int_equal(ggenerator_checker_create(2, 1.0, &c2, &err), G_OK);
    assert_int_equal(ggenerator_checker_create(3, 1.0, &c3, &err), G_OK);
    uint64_t s = 11;
    int n = TU_SANITIZED ? 2000 : 200000;
    for (int i = 0; i < n; i++) {
        double x[3], w;
        for (int k = 0; k < 3; k++) {
            switch ((i + k) % 4) {
            case 0: x[k] = uniform(&s, -40, 40); break;
            case 1: x[k] = floor(uniform(&s, -40, 40)) + uniform(&s, -1e-9, 1e-9); break; /* at an edge */
            case 2: x[k] = -0.0; break;
            default: x[k] = ldexp(uniform(&s, -1, 1), 50 + (int)uniform(&s, 0, 6)); break; /* near 2^52 */
            }
        }
        switch (i % 3) {
        case 0: w = uniform(&s, 0, 2); break;
        case 1: w = uniform(&s, 0, 2e-9); break; /* about the negligible width */
        default: w = 0.0; break;
        }
        double a = filtered_ref(x[0], w), b = filtered_ref(x[1], w), c = filtered_ref(x[2], w);
        double want2 = a + b - 2.0 * a * b, want3 = want2 + c - 2.0 * want2 * c;
        assert_true(at_uv(c2, x[0], x[1], w) == want2);
        GSurfPoint sp;
        gsurfpoint_init(&sp, NULL, NULL);
        sp.point = sp.object_point = gvec3(x[0], x[1], x[2]);
        sp.footprint = w;
        assert_true(ggenerator_value(c3, &sp) == want3);
    }
    ggenerator_unref(c2);
    ggenerator_unref(c3);
}

/* The noise's values are part of every scene that uses it: a faster evaluation must give the same doubles, so
 * that a scene renders the same picture after it. These were computed before the corner loop was unrolled. */
static void test_noise_values_pinned(void **state)
{
    (void)state;
    static const struct {
        unsigned seed;
        double x, y, z, value, gx, gy, gz;
    } pinned[] = {
        {0u, 0x1p-2, 0x1p-1, 0x1.8p-1, -0x1.291f2p-2, -0x1.1401p-3, 0x1.0e9dc4p-1, 0x1.209d8p+0},
        {7u, -0x1.a666666666666p+1, 0x1.8051eb851eb85p+3, 0x1.6p+2, 0x1.f31d4add43a5p-6, -0x1.50532541254f3p+0,
         -0x1.1c2e18fe41fb6p-13, -0x1.536144bed5aa2p-1},
        {123456789u, 0x1.e848033333333p+19, -0x1.86a059999999ap+17, 0x1.ap+1, 0x1.5632306eb68e9p-2,
         0x1.ad6865c5d4ab1p-1, 0x1.1ec30d153f293p+0, -0x1.450de611f1e76p+0},
        {3u, -0x0p+0, -0x1p-1, 0x1.ff7ced916872bp-1, -0x1.fef9d9cc13ad4p-3, 0x1.57150c8p-27, -0x1.c1eb85c99e2a4p-2,
         -0x1.0003eb47f22abp-1},
        {4000000000u, 0x1p-1, 0x1p-1, -0x1.56e1fc2f8f359p-997, -0x1.8p-2, 0x1.dp-1, 0x1.cp-3, -0x1.8p-1},
    };
    for (size_t i = 0; i < sizeof pinned / sizeof pinned[0]; i++) {
        GVec3 g, p = gvec3(pinned[i].x, pinned[i].y, pinned[i].z);
        double v = gnoise_signed(pinned[i].seed, p, &g);
        assert_true(v == pinned[i].value);
        assert_true(g.x == pinned[i].gx && g.y == pinned[i].gy && g.z == pinned[i].gz);
        assert_true(gnoise_signed(pinned[i].seed, p, NULL) == v); /* with and without the gradient */
    }
}

static void test_perlin_noise(void **state)
{
    (void)state;
    /* 0.5 on every lattice point */
    for (int i = -3; i <= 3; i++)
        assert_float_equal(gnoise_perlin3(0, i, 2 * i, -i, NULL), 0.5, 1e-15);
    uint64_t s = 42;
    double lo = 1, hi = 0, sum = 0, sum2 = 0, max_step = 0;
    const int n = 100000;
    const double delta = 1e-5;
    for (int i = 0; i < n; i++) {
        double x = uniform(&s, -100, 100), y = uniform(&s, -100, 100), z = uniform(&s, -100, 100);
        GVec3 g;
        double v = gnoise_perlin3(9, x, y, z, &g);
        lo = fmin(lo, v);
        hi = fmax(hi, v);
        sum += v;
        sum2 += v * v;
        /* continuity: a step of 1e-5 in a random direction changes the value by at most 2e-5 */
        GVec3 d = gvec3_normalize(gvec3(uniform(&s, -1, 1), uniform(&s, -1, 1), uniform(&s, -1, 1)));
        double w = gnoise_perlin3(9, x + delta * d.x, y + delta * d.y, z + delta * d.z, NULL);
        max_step = fmax(max_step, fabs(w - v));
        /* determinism: the same seed and point give the same value */
        assert_true(gnoise_perlin3(9, x, y, z, NULL) == v);
    }
    double mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
    print_message("perlin: range [%.4f, %.4f], mean %.4f, sd %.4f, largest change over 1e-5: %.3g\n", lo, hi, mean,
                  sd, max_step);
    assert_true(lo >= 0.0 && hi <= 1.0);
    assert_true(lo < 0.15 && hi > 0.85); /* it does use its range */
    assert_float_equal(mean, 0.5, 0.01);
    assert_true(sd > 0.08 && sd < 0.25);
    assert_true(max_step < 2.0 * delta);
    /* a different seed is a different noise */
    assert_true(fabs(gnoise_perlin3(1, 0.3, 0.7, 0.2, NULL) - gnoise_perlin3(2, 0.3, 0.7, 0.2, NULL)) > 1e-6);

    /* the generator: frequency scales the coordinates; the analytic gradient matches central differences */
    GNoiseParams p = {.frequency = 2.5, .seed = 9};
    GGenerator *g;
    GError err;
    assert_int_equal(ggenerator_perlin_create(&p, &g, &err), G_OK);
    assert_int_equal(g->space, GGENERATOR_SPACE_OBJECT);
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    for (int i = 0; i < 200; i++) {
        sp.object_point = gvec3(uniform(&s, -5, 5), uniform(&s, -5, 5), uniform(&s, -5, 5));
        GVec3 p2 = gvec3_scale(sp.object_point, 2.5);
        assert_float_equal(ggenerator_value(g, &sp), gnoise_perlin3(9, p2.x, p2.y, p2.z, NULL), 1e-15);
        GVec3 a;
        assert_int_equal(ggenerator_gradient(g, &sp, &a), G_OK);
        double e = 1e-6;
        GSurfPoint q = sp;
        q.object_point.y += e;
        double up = ggenerator_value(g, &q);
        q.object_point.y -= 2 * e;
        assert_float_equal(a.y, (up - ggenerator_value(g, &q)) / (2 * e), 1e-6);
    }
    ggenerator_unref(g);
}

static void test_fractals(void **state)
{
    (void)state;
    GError err;
    GGenerator *fbm, *turb, *fbm2;
    GNoiseParams p = {.octaves = 6, .seed = 3};
    assert_int_equal(ggenerator_fbm_create(&p, &fbm, &err), G_OK);
    assert_int_equal(ggenerator_fbm_create(&p, &fbm2, &err), G_OK);
    assert_int_equal(ggenerator_turbulence_create(&p, &turb, &err), G_OK);
    uint64_t s = 7;
    double tsum = 0, fsum = 0;
    const int n = 20000;
    for (int i = 0; i < n; i++) {
        GVec3 x = gvec3(uniform(&s, -20, 20), uniform(&s, -20, 20), uniform(&s, -20, 20));
        double f = at_xyz(fbm, x), t = at_xyz(turb, x);
        assert_true(f >= 0.0 && f <= 1.0);
        assert_true(t >= 0.0 && t <= 1.0);
        assert_true(at_xyz(fbm2, x) == f); /* two instances with one seed agree */
        /* continuity of the sums too: six octaves at most double the slope each */
        double step = 1e-6;
        assert_true(fabs(at_xyz(turb, gvec3(x.x + step, x.y, x.z)) - t) < 64 * 2 * step);
        tsum += t;
        fsum += f;
    }
    assert_float_equal(fsum / n, 0.5, 0.01);
    assert_true(tsum / n > 0.1 && tsum / n < 0.4); /* the mean of |noise| */
    ggenerator_unref(fbm);
    ggenerator_unref(fbm2);
    ggenerator_unref(turb);
}

static void test_wood_and_marble(void **state)
{
    (void)state;
    GError err;
    GGenerator *wood, *plain, *marble, *veined;
    GNoiseParams p = {.frequency = 2.0, .seed = 1};
    /* without turbulence: rings of period 1/4 in the radius, 0 at each ring's start, 1 at its peak */
    assert_int_equal(ggenerator_wood_create(&p, 4.0, 0.0, 0.25, &plain, &err), G_OK);
    for (int k = 1; k < 6; k++) {
        double r = k / 4.0;
        assert_float_equal(at_xyz(plain, gvec3(r * cos(k), r * sin(k), 0.3 * k)), 0.0, 1e-9);
        assert_float_equal(at_xyz(plain, gvec3(r + 0.75 / 4.0, 0, 0)), 1.0, 1e-9);
        assert_float_equal(at_xyz(plain, gvec3(0, r + 0.375 / 4.0, 5.0)), 0.5, 1e-9);
    }
    assert_int_equal(ggenerator_wood_create(&p, 4.0, 0.3, 0.0, &wood, &err), G_OK);
    uint64_t s = 11;
    double max_step = 0;
    for (int i = 0; i < 20000; i++) {
        GVec3 x = gvec3(uniform(&s, -3, 3), uniform(&s, -3, 3), uniform(&s, -3, 3));
        double v = at_xyz(wood, x);
        assert_true(v >= 0.0 && v <= 1.0);
        max_step = fmax(max_step, fabs(at_xyz(wood, gvec3(x.x + 1e-7, x.y, x.z)) - v));
    }
    assert_true(max_step < 1e-4); /* continuous: no jumps at ring boundaries */

    /* marble without turbulence is the plain sine; with it, a displaced sine in [0, 1] */
    assert_int_equal(ggenerator_marble_create(&p, 3.0, 0.0, &marble, &err), G_OK);
    for (int i = 0; i < 50; i++) {
        double x = uniform(&s, -2, 2);
        assert_float_equal(at_xyz(marble, gvec3(x, 1.0, 2.0)), 0.5 + 0.5 * sin(2 * M_PI * 3.0 * x), 1e-12);
    }
    /* the default gradient (central differences) follows the analytic derivative */
    GSurfPoint sp;
    gsurfpoint_init(&sp, NULL, NULL);
    sp.object_point = gvec3(0.13, 0.4, 0.0);
    GVec3 g;
    assert_int_equal(ggenerator_gradient(marble, &sp, &g), G_OK);
    assert_float_equal(g.x, 0.5 * cos(2 * M_PI * 3.0 * 0.13) * 2 * M_PI * 3.0, 1e-4);
    assert_float_equal(g.y, 0.0, 1e-9);
    assert_int_equal(ggenerator_marble_create(&p, 3.0, 1.5, &veined, &err), G_OK);
    for (int i = 0; i < 5000; i++) {
        double v = at_xyz(veined, gvec3(uniform(&s, -2, 2), uniform(&s, -2, 2), uniform(&s, -2, 2)));
        assert_true(v >= 0.0 && v <= 1.0);
    }
    ggenerator_unref(wood);
    ggenerator_unref(plain);
    ggenerator_unref(marble);
    ggenerator_unref(veined);
}

/* Analytic gradients against central differences: everywhere for smooth generators, away from the creases
 * of |noise| for turbulence and marble (95% of random points). */
static void test_analytic_gradients(void **state)
{
    (void)state;
    GError err;
    GNoiseParams p = {.frequency = 1.7, .octaves = 5, .seed = 21};
    GGenerator *g[4];
    assert_int_equal(ggenerator_fbm_create(&p, &g[0], &err), G_OK);
    assert_int_equal(ggenerator_wood_create(&p, 3.0, 0.4, 0.3, &g[1], &err), G_OK);
    assert_int_equal(ggenerator_turbulence_create(&p, &g[2], &err), G_OK);
    assert_int_equal(ggenerator_marble_create(&p, 1.5, 0.8, &g[3], &err), G_OK);
    const int smooth[4] = {1, 1, 0, 0};
    uint64_t s = 99;
    for (int k = 0; k < 4; k++) {
        assert_non_null(g[k]->cls->gradient);
        int agree = 0, n = 400;
        for (int i = 0; i < n; i++) {
            GSurfPoint sp;
            gsurfpoint_init(&sp, NULL, NULL);
            sp.object_point = gvec3(uniform(&s, -3, 3), uniform(&s, -3, 3), uniform(&s, -3, 3));
            GVec3 a, fd;
            assert_int_equal(ggenerator_gradient(g[k], &sp, &a), G_OK);
            double e = 1e-6, *c = &sp.object_point.x, out[3];
            for (int j = 0; j < 3; j++) {
                double c0 = c[j];
                c[j] = c0 + e;
                double up = ggenerator_value(g[k], &sp);
                c[j] = c0 - e;
                out[j] = (up - ggenerator_value(g[k], &sp)) / (2 * e);
                c[j] = c0;
            }
            fd = gvec3(out[0], out[1], out[2]);
            double diff = gvec3_length(gvec3_sub(a, fd)), scale = fmax(1.0, gvec3_length(fd));
            agree += diff < 1e-4 * scale;
            if (smooth[k] && diff >= 1e-4 * scale)
                print_error("%s at (%g %g %g): analytic (%g %g %g), differences (%g %g %g)\n", ggenerator_name(g[k]),
                            sp.object_point.x, sp.object_point.y, sp.object_point.z, a.x, a.y, a.z, fd.x, fd.y, fd.z);
        }
        if (smooth[k])
            assert_int_equal(agree, n);
        else
            assert_true(agree >= 0.95 * n);
        ggenerator_unref(g[k]);
    }
}

static void test_surface_constant_gradient(void **state)
{
    (void)state;
    GError err;
    GGenerator *surf, *k, *field, *uvfield;
    assert_int_equal(ggenerator_surface_create(&surf, &err), G_OK);
    assert_int_equal(ggenerator_constant_create(0.25, &k, &err), G_OK);
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_OBJECT, gvec3(1, -2, 0.5), 3.0, &field, &err), G_OK);
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(0.5, 2, 9), 0.0, &uvfield, &err), G_OK);
    GSurfPoint sp;
    plane_point(&sp, NULL, NULL, 0.2, 0.6);
    sp.object_point = gvec3(1, 1, 2);
    sp.surface = 4;
    assert_float_equal(ggenerator_value(surf, &sp), 4.0, 0.0);
    assert_float_equal(ggenerator_value(k, &sp), 0.25, 0.0);
    assert_float_equal(ggenerator_value(field, &sp), 3.0 + 1 - 2 + 1, 1e-15);
    assert_float_equal(ggenerator_value(uvfield, &sp), 0.1 + 1.2, 1e-15);
    GVec3 g;
    assert_int_equal(ggenerator_gradient(surf, &sp, &g), G_OK);
    assert_true(g.x == 0 && g.y == 0 && g.z == 0);
    assert_int_equal(ggenerator_gradient(uvfield, &sp, &g), G_OK);
    assert_true(g.x == 0.5 && g.y == 2 && g.z == 0); /* (d/du, d/dv, 0) */
    double du, dv;
    sp.dpdu = gvec3(0, 2, 0); /* object tangents fall back to these */
    sp.dpdv = gvec3(1, 0, 0);
    assert_int_equal(ggenerator_surface_derivatives(field, &sp, &du, &dv), G_OK);
    assert_float_equal(du, -4.0, 1e-15);
    assert_float_equal(dv, 1.0, 1e-15);
    ggenerator_unref(surf);
    ggenerator_unref(k);
    ggenerator_unref(field);
    ggenerator_unref(uvfield);
}

static void test_cache(void **state)
{
    (void)state;
    CountGen *g = countgen_new(0.7);
    GSurfPoint sp;
    plane_point(&sp, NULL, NULL, 0, 0);
    for (int i = 0; i < 5; i++)
        assert_float_equal(ggenerator_cached_value(&g->base, &sp), 0.7, 0.0);
    assert_int_equal(g->calls, 1);
    double v;
    GVec3 d;
    /* a gradient by central differences of a space-NONE generator is zero, with the cached value */
    assert_int_equal(ggenerator_cached_gradient(&g->base, &sp, &v, &d), G_OK);
    assert_float_equal(v, 0.7, 0.0);
    assert_int_equal(ggenerator_cached_gradient(&g->base, &sp, NULL, &d), G_OK);
    assert_int_equal(g->calls, 1);
    /* sixteen other generators push it out of the slots: then it is evaluated again */
    CountGen *others[GSURF_CACHE_SLOTS];
    for (int i = 0; i < GSURF_CACHE_SLOTS; i++) {
        others[i] = countgen_new(i);
        ggenerator_cached_value(&others[i]->base, &sp);
    }
    ggenerator_cached_value(&g->base, &sp);
    assert_int_equal(g->calls, 2);
    for (int i = 0; i < GSURF_CACHE_SLOTS; i++)
        ggenerator_unref(&others[i]->base);
    ggenerator_unref(&g->base);
}

static void test_bad_parameters(void **state)
{
    (void)state;
    GError err;
    GGenerator *g = (GGenerator *)1;
    assert_int_equal(ggenerator_checker_create(4, 1.0, &g, &err), G_ERR_INVALID);
    assert_null(g);
    assert_non_null(strstr(err.message, "dims"));
    assert_int_equal(ggenerator_checker_create(2, 0.0, &g, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "frequency"));
    assert_int_equal(ggenerator_constant_create(NAN, &g, &err), G_ERR_INVALID);
    GNoiseParams p = {.octaves = 40};
    assert_int_equal(ggenerator_fbm_create(&p, &g, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "octaves"));
    p = (GNoiseParams){.frequency = -1};
    assert_int_equal(ggenerator_perlin_create(&p, &g, &err), G_ERR_INVALID);
    assert_int_equal(ggenerator_wood_create(NULL, 4.0, 0.1, 1.5, &g, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "latewood"));
    assert_int_equal(ggenerator_wood_create(NULL, 0.0, 0.1, 0.2, &g, &err), G_ERR_INVALID);
    assert_int_equal(ggenerator_marble_create(NULL, INFINITY, 0.1, &g, &err), G_ERR_INVALID);
    assert_int_equal(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(NAN, 0, 0), 0, &g, &err), G_ERR_INVALID);
    /* a class of another interface version is refused */
    GGeneratorClass future = countgen_class;
    future.abi_version = GGENERATOR_ABI_VERSION + 1;
    GGenerator raw;
    assert_int_equal(ggenerator_init(&raw, &future, GGENERATOR_SPACE_UV, &err), G_ERR_VERSION);
    assert_non_null(strstr(err.message, "version"));
    ggenerator_unref(NULL); /* a no-op */
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_checker_parity),
        cmocka_unit_test(test_checker_definition),
        cmocka_unit_test(test_noise_values_pinned),
        cmocka_unit_test(test_perlin_noise),
        cmocka_unit_test(test_fractals),
        cmocka_unit_test(test_wood_and_marble),
        cmocka_unit_test(test_analytic_gradients),
        cmocka_unit_test(test_surface_constant_gradient),
        cmocka_unit_test(test_cache),
        cmocka_unit_test(test_bad_parameters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
