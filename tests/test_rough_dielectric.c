/* test_rough_dielectric.c - the rough dielectric (Walter et al. 2007 on the microfacet kit) in the four colour
 * models: an index-matched interface passes all the light straight on; a compensated lossless interface keeps all
 * of it (the mean sample weight, reflection and refraction, is 1) from outside and inside; uncompensated it keeps
 * the single-scattering albedo R + T of the kit's table; sampling against pdf by Pearson's chi2 (p > 0.01) at
 * alpha 0.05, 0.3, 0.8 and 10 incidences, the pdf integrated over each bin adaptively; reciprocity of the
 * reflection; roughness 0 is the smooth dielectric; bad roughness refused at file:line:col. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "material_fixture.h"
#include "generic/kit/microfacet_dielectric.h"

static double next_u(unsigned long long *s)
{
    unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static const char *const models[4] = {"rgb", "spectrum9", "spectrum", "bispectral"};

typedef struct Glass {
    GColorModel *model;
    GScratch *scratch;
    GLibrary *lib;
    GMaterial *m;
    GSurfPoint sp;
    GColor ri, w;
} Glass;

/* The material `text` names g in model; the plane z = 0 seen from outside (inside = 0: vacuum to glass) or from
 * inside (1: glass to vacuum). */
static void glass_open(Glass *g, const char *model, const char *text, int inside)
{
    memset(g, 0, sizeof *g);
    GError err;
    assert_int_equal(gcolormodel_create(model, NULL, &g->model, &err), G_OK);
    g->scratch = gscratch_create(0);
    GReaderOptions ro = {.model = g->model};
    if (greader_load_string(text, "rough.mat", &ro, &g->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    g->m = glibrary_material(g->lib, "g");
    gsurfpoint_init(&g->sp, g->model, g->scratch);
    g->sp.geometric_normal = gvec3(0, 0, 1);
    g->sp.dpdu = gvec3(1, 0, 0);
    g->sp.dpdv = gvec3(0, 1, 0);
    g->sp.material = g->m;
    g->sp.entering = !inside;
    g->sp.from = inside ? g->m : NULL;
    g->sp.to = inside ? NULL : g->m;
    assert_int_equal(gcolor_alloc(&g->ri, g->model), G_OK);
    assert_int_equal(gcolor_alloc(&g->w, g->model), G_OK);
    GColor to;
    assert_int_equal(gcolor_alloc(&to, g->model), G_OK);
    assert_int_equal(gmaterial_refraction_index(g->sp.from, &g->sp, &g->ri), G_OK);
    assert_int_equal(gmaterial_refraction_index(g->sp.to, &g->sp, &to), G_OK);
    assert_int_equal(gcolor_div(&g->ri, &g->ri, &to), G_OK);
    gcolor_free(&to);
}

static void glass_close(Glass *g)
{
    gcolor_free(&g->ri);
    gcolor_free(&g->w);
    glibrary_destroy(g->lib);
    gscratch_destroy(g->scratch);
    gcolormodel_destroy(g->model);
}

/* Every angle of the ten (1 to 82 degrees), or every third under the sanitizers (the same code paths). */
#define ANGLE_STRIDE (TU_SANITIZED ? 3 : 1)

/* The mean brightness of the sample weight for out (nothing drawn counts 0). */
static double mean_weight(Glass *g, GVec3 out, int n, unsigned long long seed)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++) {
        GMaterialSample s;
        double u1 = (i + next_u(&seed)) / n, u2 = next_u(&seed);
        int got = gmaterial_sample(g->m, &g->sp, out, &g->ri, u1, u2, &s, &g->w);
        assert_true(got >= 0);
        if (got)
            sum += gcolor_brightness(&g->w);
    }
    return sum / n;
}

static void index_matched_passes_all(void **state)
{
    (void)state;
    for (int k = 0; k < 4; k++) {
        Glass g;
        glass_open(&g, models[k], "material g dielectric { index 1.0 roughness 0.5 }", 0);
        for (int a = 0; a < 10; a++) {
            GVec3 out = dir_at((a * 9 + 1) * DEG, 0.3);
            double t = mean_weight(&g, out, 200, 7);
            if (fabs(t - 1.0) > 1e-3)
                fail_msg("%s: index 1 seen as relative index %.9f transmits %.6f", models[k], gcolor_brightness(&g.ri),
                         t);
            GMaterialSample s;
            assert_int_equal(gmaterial_sample(g.m, &g.sp, out, &g.ri, 0.3, 0.6, &s, &g.w), 1);
            assert_true((s.flags & GSAMPLE_TRANSMIT) && (s.flags & GSAMPLE_DELTA));
            assert_true(gvec3_dot(s.in, out) < -1.0 + 1e-12);
        }
        assert_int_equal(gmaterial_is_delta(g.m, &g.sp), 1);
        glass_close(&g);
    }
}

/* Compensated, a lossless interface seen from outside keeps its light (reflection + refraction) at every angle. From
 * inside the compensation is held to a factor 2 (materials.h), so that it gives back part of the light there: never
 * more than all of it. */
static void compensated_keeps_energy(void **state)
{
    (void)state;
    static const char *const texts[] = {"material g dielectric { index 1.5 roughness 0.3 }",
                                        "material g dielectric { index 1.5 roughness 1.0 }",
                                        "material g dielectric { glass SF11 roughness 0.6 distribution beckmann }"};
    for (int k = 0; k < 4; k++)
        for (int t = 0; t < 3; t++)
            for (int inside = 0; inside < 2; inside++) {
                if (TU_SANITIZED && (2 * t + inside) % 4 != k) /* under the sanitizers each case in one model */
                    continue;
                Glass g;
                glass_open(&g, models[k], texts[t], inside);
                double worst = 0.0, lowest = 1.0, highest = 0.0;
                for (int a = 0; a < 10; a += ANGLE_STRIDE) {
                    double theta = (a * 9 + 1) * DEG;
                    double e = mean_weight(&g, dir_at(theta, 0.3), 20000, 11 + a);
                    worst = fmax(worst, fabs(e - 1.0));
                    lowest = fmin(lowest, e);
                    highest = fmax(highest, e);
                }
                if (k == 0)
                    print_message("%s, %s: mean weight in [%.4f, %.4f]\n", texts[t], inside ? "inside" : "outside",
                                  lowest, highest);
                if (!inside)
                    assert_true(worst < 0.015);
                assert_true(highest < 1.015);
                glass_close(&g);
            }
}

/* Uncompensated, the mean weight is the single-scattering albedo R + T, which the kit's table holds. */
static void uncompensated_is_single_scattering(void **state)
{
    (void)state;
    Glass g;
    glass_open(&g, "rgb", "material g dielectric { index 1.5 roughness 0.8 compensate off }", 0);
    GMicrofacet mf = gmicrofacet_make(GMICROFACET_GGX, 0.8, 0.8);
    GMicrofacetDielectricAlbedo *tab = malloc(sizeof *tab);
    gmicrofacet_dielectric_albedo_init(tab, &mf, 1.6);
    double eta = gcolor_brightness(&g.ri), lowest = 1.0;
    for (int a = 0; a < 10; a++) {
        double theta = (a * 9 + 1) * DEG, r, t;
        gmicrofacet_dielectric_albedo(tab, cos(theta), eta, &r, &t);
        double e = mean_weight(&g, dir_at(theta, 0.3), 40000, 3 + a);
        assert_near(e, r + t, 0.01);
        lowest = fmin(lowest, e);
    }
    print_message("alpha 0.8, n 1.5 from outside, single scattering: albedo down to %.4f\n", lowest);
    assert_true(lowest < 0.97); /* it does lose light: the compensation has something to do */
    free(tab);
    glass_close(&g);
}

/* ---- chi2 ---- */

#define CB 16 /* bins in cos theta over [-1, 1] */
#define PB 32 /* bins in phi */

/* The bins' polar axis is perpendicular to the plane of incidence (out's azimuth is 0.3), so that the lobes lie
 * along the bins' equator, where the cells are well shaped (about the normal, a narrow lobe falls in the sliver of
 * cells at a pole). */
static GVec3 bin_axis(void) { return gvec3(-sin(0.3), cos(0.3), 0.0); }
static GVec3 bin_e1(void) { return gvec3(cos(0.3), sin(0.3), 0.0); }
static GVec3 bin_e2(void) { return gvec3(0.0, 0.0, 1.0); }

static GVec3 bin_dir(double c, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    return gvec3_add(gvec3_scale(bin_axis(), c),
                     gvec3_add(gvec3_scale(bin_e1(), s * cos(phi)), gvec3_scale(bin_e2(), s * sin(phi))));
}

static double pdf_at(Glass *g, GVec3 out, double c, double phi)
{
    return gmaterial_pdf(g->m, &g->sp, bin_dir(c, phi), out, &g->ri);
}

/* The integral of pdf over [c0, c1] x [p0, p1] (solid angle = dc dphi): a 4 x 4 midpoint rule, refined by quarters
 * where it disagrees with the 2 x 2 rule by more than 1e-4 of the bin's mass (depth at most 6). */
static double integrate(Glass *g, GVec3 out, double c0, double c1, double p0, double p1, int depth)
{
    double fine = 0.0, coarse = 0.0, area = (c1 - c0) * (p1 - p0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            fine += pdf_at(g, out, c0 + (i + 0.5) * (c1 - c0) / 4, p0 + (j + 0.5) * (p1 - p0) / 4);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            coarse += pdf_at(g, out, c0 + (i + 0.5) * (c1 - c0) / 2, p0 + (j + 0.5) * (p1 - p0) / 2);
    fine *= area / 16;
    coarse *= area / 4;
    if (depth >= 6 || fabs(fine - coarse) <= 1e-4 * fmax(fine, 1e-3 * area))
        return fine;
    double cm = 0.5 * (c0 + c1), pm = 0.5 * (p0 + p1);
    return integrate(g, out, c0, cm, p0, pm, depth + 1) + integrate(g, out, cm, c1, p0, pm, depth + 1) +
           integrate(g, out, c0, cm, pm, p1, depth + 1) + integrate(g, out, cm, c1, pm, p1, depth + 1);
}

static double log_gamma(double x) { return lgamma(x); }

/* Q(a, x), the regularised upper incomplete gamma function (series or continued fraction). */
static double gamma_q(double a, double x)
{
    if (x <= 0.0)
        return 1.0;
    if (x < a + 1.0) {
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 1000; n++) {
            term *= x / (a + n);
            sum += term;
            if (fabs(term) < 1e-15 * fabs(sum))
                break;
        }
        return 1.0 - sum * exp(-x + a * log(x) - log_gamma(a));
    }
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; i++) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        d = fabs(d) < 1e-300 ? 1e-300 : d;
        c = b + an / c;
        c = fabs(c) < 1e-300 ? 1e-300 : c;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (fabs(del - 1.0) < 1e-15)
            break;
    }
    return exp(-x + a * log(x) - log_gamma(a)) * h;
}

/* p-value of Pearson's chi2 of n draws for out against pdf, bins expecting fewer than 5 pooled. */
static double chi2_p(Glass *g, GVec3 out, int n, unsigned long long seed)
{
    static double expected[CB * PB];
    static int observed[CB * PB];
    memset(observed, 0, sizeof observed);
    for (int i = 0; i < n; i++) {
        GMaterialSample s;
        int got = gmaterial_sample(g->m, &g->sp, out, &g->ri, next_u(&seed), next_u(&seed), &s, &g->w);
        if (got != 1)
            continue;
        assert_false(s.flags & GSAMPLE_DELTA);
        double phi = atan2(gvec3_dot(s.in, bin_e2()), gvec3_dot(s.in, bin_e1()));
        phi = phi < 0 ? phi + 2 * M_PI : phi;
        int bc = (int)((gvec3_dot(s.in, bin_axis()) + 1.0) * 0.5 * CB), bp = (int)(phi / (2 * M_PI) * PB);
        bc = bc < 0 ? 0 : bc >= CB ? CB - 1 : bc;
        bp = bp < 0 ? 0 : bp >= PB ? PB - 1 : bp;
        observed[bc * PB + bp]++;
    }
    for (int bc = 0; bc < CB; bc++)
        for (int bp = 0; bp < PB; bp++)
            expected[bc * PB + bp] = n * integrate(g, out, -1.0 + 2.0 * bc / CB, -1.0 + 2.0 * (bc + 1) / CB,
                                                   2 * M_PI * bp / PB, 2 * M_PI * (bp + 1) / PB, 0);
    double chi2 = 0.0, pool_e = 0.0, pool_o = 0.0;
    int dof = -1;
    for (int b = 0; b < CB * PB; b++) {
        if (expected[b] < 5.0) {
            pool_e += expected[b];
            pool_o += observed[b];
            continue;
        }
        double d = observed[b] - expected[b];
        chi2 += d * d / expected[b];
        dof++;
    }
    if (pool_e > 0.0) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        dof++;
    }
    return dof > 0 ? gamma_q(0.5 * dof, 0.5 * chi2) : 1.0;
}

static void sampling_chi2(void **state)
{
    (void)state;
    static const double alphas[3] = {0.05, 0.3, 0.8};
    /* p > 0.01 for the 120 tests together: each above the Sidak-corrected level 1 - 0.99^(1/120) */
    double smallest = 1.0, level = 1.0 - pow(0.99, 1.0 / 120.0);
    for (int k = 0; k < 4; k++)
        for (int a = 0; a < 3; a++) {
            char text[128];
            if (TU_SANITIZED && (k + a) % 3 != 0) /* under the sanitizers every model and every alpha, not all pairs */
                continue;
            snprintf(text, sizeof text, "material g dielectric { index 1.5 roughness %g }", alphas[a]);
            Glass g;
            glass_open(&g, models[k], text, k % 2); /* rgb and spectrum from outside, the others from inside */
            for (int t = 0; t < 10; t += ANGLE_STRIDE) {
                double theta = (t * 9 + 1) * DEG, p = chi2_p(&g, dir_at(theta, 0.3), 10000, 97 + t + 10 * a);
                if (!(p > level))
                    fail_msg("%s, alpha %g, theta %.0f, %s: chi2 p = %.3g", models[k], alphas[a], theta / DEG,
                             k % 2 ? "inside" : "outside", p);
                smallest = fmin(smallest, p);
            }
            glass_close(&g);
        }
    print_message("chi2: smallest p-value over 120 tests %.3g\n", smallest);
}

static void reflection_reciprocal(void **state)
{
    (void)state;
    Glass g;
    glass_open(&g, "spectrum", "material g dielectric { index 1.5 roughness 0.4 }", 0);
    GColor a, b, one;
    assert_int_equal(gcolor_alloc(&a, g.model), G_OK);
    assert_int_equal(gcolor_alloc(&b, g.model), G_OK);
    assert_int_equal(gcolor_alloc(&one, g.model), G_OK);
    assert_int_equal(gcolor_fill(&one, 1.0), G_OK);
    unsigned long long seed = 5;
    for (int i = 0; i < 200; i++) {
        GVec3 in = dir_at(acos(next_u(&seed)), 2 * M_PI * next_u(&seed));
        GVec3 out = dir_at(acos(next_u(&seed)), 2 * M_PI * next_u(&seed));
        assert_int_equal(gmaterial_reflection(g.m, &g.sp, in, &one, out, &a), G_OK);
        assert_int_equal(gmaterial_reflection(g.m, &g.sp, out, &one, in, &b), G_OK);
        double fa = gcolor_brightness(&a) / in.z, fb = gcolor_brightness(&b) / out.z;
        assert_true(fabs(fa - fb) <= 1e-6 * fmax(fa, fb) + 1e-12);
    }
    gcolor_free(&a);
    gcolor_free(&b);
    gcolor_free(&one);
    glass_close(&g);
}

static void text_format(void **state)
{
    (void)state;
    Glass g;
    glass_open(&g, "rgb", "material g dielectric { roughness 0 }", 0);
    assert_int_equal(gmaterial_is_delta(g.m, &g.sp), 1); /* roughness 0: the smooth dielectric */
    glass_close(&g);
    static const struct {
        const char *text, *want;
    } bad[] = {
        {"material g dielectric { roughness 1.5 }", "bad.mat:1:35: value 1.5 is out of range [0, 1]"},
        {"material g dielectric { roughness -0.1 }", "bad.mat:1:35: value -0.1 is out of range [0, 1]"},
        {"material g dielectric {\n roughness_u 0.2 roughness_v 2 }", "bad.mat:2:30: value 2 is out of range [0, 1]"},
        {"material g dielectric { distribution phong }", "bad.mat:1:38: "},
        {"material g dielectric { compensate maybe }", "bad.mat:1:36: "},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GError err;
        GLibrary *lib = NULL;
        GColorModel *model;
        assert_int_equal(gcolormodel_create("rgb", NULL, &model, &err), G_OK);
        GReaderOptions ro = {.model = model};
        assert_int_not_equal(greader_load_string(bad[i].text, "bad.mat", &ro, &lib, &err), G_OK);
        if (!strstr(err.message, bad[i].want))
            fail_msg("'%s': '%s' lacks '%s'", bad[i].text, err.message, bad[i].want);
        gcolormodel_destroy(model);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(index_matched_passes_all),   cmocka_unit_test(compensated_keeps_energy),
        cmocka_unit_test(uncompensated_is_single_scattering), cmocka_unit_test(sampling_chi2),
        cmocka_unit_test(reflection_reciprocal),      cmocka_unit_test(text_format),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
