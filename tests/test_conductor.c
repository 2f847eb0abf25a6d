/* test_conductor.c - the conductor material (materials/conductor.c): the normal-incidence reflectance of measured
 * metals against ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) of their own table; the chi-square goodness of fit of its
 * sampling against its pdf, integrated over each bin; the white furnace (a compensated rough conductor of reflectance 1
 * keeps all the light at every angle; uncompensated it keeps the single-scattering albedo, integrated here with an
 * independent D and G2); reciprocity; energy conservation of real metals; the tabulated Fresnel term against the
 * exact one, and the kit's table (kit/fresnel.h) itself; and the file format's refusals. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "material_fixture.h"
#include "generic/builtins.h"
#include "generic/kit/fresnel.h"
#include "generic/kit/metals.h"
#include "generic/kit/microfacet.h"

/* A small deterministic generator (splitmix64). */
static double next_u(unsigned long long *s)
{
    unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

typedef struct Case {
    GColorModel *model;
    GScratch *scratch;
    GLibrary *lib;
    GMaterial *m;
    GSurfPoint sp;
    GColor white, r;
} Case;

/* Loads `text` in `model` (step_nm 0: its default) and takes material m; the surface point is the plane z = 0 seen
 * from +z, dP/du along +x. */
static void case_open(Case *c, const char *model, double step_nm, const char *text)
{
    memset(c, 0, sizeof *c);
    GError err;
    GColorModelOptions opt = {.step_nm = step_nm};
    assert_int_equal(gcolormodel_create(model, &opt, &c->model, &err), G_OK);
    c->scratch = gscratch_create(0);
    GReaderOptions ro = {.model = c->model};
    if (greader_load_string(text, "case.mat", &ro, &c->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    c->m = glibrary_material(c->lib, "m");
    assert_non_null(c->m);
    gsurfpoint_init(&c->sp, c->model, c->scratch);
    c->sp.geometric_normal = gvec3(0, 0, 1);
    c->sp.dpdu = gvec3(1, 0, 0);
    c->sp.dpdv = gvec3(0, 1, 0);
    c->sp.entering = 1;
    c->sp.material = c->m;
    assert_int_equal(gcolor_alloc(&c->white, c->model), G_OK);
    assert_int_equal(gcolor_fill(&c->white, 1.0), G_OK);
    assert_int_equal(gcolor_alloc(&c->r, c->model), G_OK);
}

static void case_close(Case *c)
{
    gcolor_free(&c->white);
    gcolor_free(&c->r);
    glibrary_destroy(c->lib);
    gscratch_destroy(c->scratch);
    gcolormodel_destroy(c->model);
}

/* ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) */
static double r0(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

/* conductor { metal Au }, Ag, Cu at 450, 550, 650 nm in spectrum at 1 and 5 nm: the table's own R(0) within 1e-6. */
static void normal_incidence(void **state)
{
    (void)state;
    const char *metals[] = {"Au", "Ag", "Cu"};
    const double steps[] = {1.0, 5.0};
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < 3; i++) {
            char text[128];
            snprintf(text, sizeof text, "material m conductor { metal %s }", metals[i]);
            Case c;
            case_open(&c, "spectrum", steps[s], text);
            GVec3 n = gvec3(0, 0, 1);
            assert_int_equal(gmaterial_reflection(c.m, &c.sp, n, &c.white, n, &c.r), G_OK);
            int metal = gmetal_find(metals[i]);
            for (double nm = 450; nm <= 650; nm += 100) {
                int j = (int)lround((nm - c.model->lambda_min) / c.model->lambda_step);
                assert_near(c.model->lambda_min + j * c.model->lambda_step, nm, 1e-9);
                assert_near(c.r.v[j], r0(gmetal_eta_at(metal, nm), gmetal_k_at(metal, nm)), 1e-6);
            }
            case_close(&c);
        }
}

/* The tabulated Fresnel term of a rough conductor (fresnel table, the default) against the exact one (fresnel exact)
 * for every metal of the table in spectrum, at facet cosines halfway between the table's nodes (where a lerp is
 * furthest from the curve: the nodes are at cos_h = (j / 1024)^2) and at normal incidence. The pair is symmetric about
 * the normal (h = n, cos_h = the pair's cosine), uncompensated, so that the two values differ by F alone:
 * |F_table - F_exact| = |r_table / r_exact - 1| F_exact within 1e-5 at every sample; at cos_h = 1 every float equal. */
static void fresnel_table(void **state)
{
    (void)state;
    const int probes = TU_SANITIZED ? 24 : 160;
    for (int metal = 0; metal < gmetal_count(); metal += TU_SANITIZED ? 6 : 1) {
        GMetalInfo info;
        assert_int_equal(gmetal_info(metal, &info), G_OK);
        char text[256];
        snprintf(text, sizeof text,
                 "material m conductor { metal %s roughness 0.3 compensate off }\n"
                 "material e conductor { metal %s roughness 0.3 compensate off fresnel exact }", info.name, info.name);
        Case c;
        case_open(&c, "spectrum", 0.0, text);
        GMaterial *exact = glibrary_material(c.lib, "e");
        assert_non_null(exact);
        GColor re, f, eta, k;
        assert_int_equal(gcolor_alloc(&re, c.model), G_OK);
        assert_int_equal(gcolor_alloc(&f, c.model), G_OK);
        assert_int_equal(gcolor_alloc(&eta, c.model), G_OK);
        assert_int_equal(gcolor_alloc(&k, c.model), G_OK);
        assert_int_equal(gmetal_colors(metal, &eta, &k), G_OK);
        int n = c.model->nvalues;
        for (int p = 0; p <= probes; p++) {
            /* p < probes: the midpoints of intervals spread over the table, dense towards grazing; then cos_h = 1 */
            int j = (int)((double)p * p / ((double)probes * probes) * 1023.0);
            double u = (j + 0.5) / 1024.0, cos_h = p < probes ? u * u : 1.0, sin_h = sqrt(1.0 - cos_h * cos_h);
            GVec3 in = gvec3(sin_h, 0, cos_h), out = gvec3(-sin_h, 0, cos_h);
            assert_int_equal(gmaterial_reflection(c.m, &c.sp, in, &c.white, out, &c.r), G_OK);
            c.sp.material = exact;
            assert_int_equal(gmaterial_reflection(exact, &c.sp, in, &c.white, out, &re), G_OK);
            c.sp.material = c.m;
            assert_int_equal(gmaterial_fresnel_conductor(&f, cos_h, &eta, &k), G_OK);
            for (int i = 0; i < n; i++) {
                if (p == probes) {
                    assert_true(c.r.v[i] == re.v[i]);
                    continue;
                }
                assert_true(re.v[i] > 0.0f);
                double err = fabs(c.r.v[i] / (double)re.v[i] - 1.0) * f.v[i];
                if (!(err <= 1e-5))
                    fail_msg("%s at %g nm, cos_h %g: |F_table - F_exact| = %g > 1e-5", info.name,
                             c.model->lambda_min + i * c.model->lambda_step, cos_h, err);
            }
        }
        /* a coloured light: the white value times the light, float by float, also into the light's own colour */
        GVec3 in = gvec3(0.6, 0, 0.8), out = gvec3(-0.48, 0.36, 0.8);
        for (int i = 0; i < n; i++)
            f.v[i] = 0.25f + 0.5f * (float)i / (float)n;
        f.kind = GCOLOR_VECTOR;
        assert_int_equal(gmaterial_reflection(c.m, &c.sp, in, &c.white, out, &re), G_OK);
        assert_int_equal(gmaterial_reflection(c.m, &c.sp, in, &f, out, &c.r), G_OK);
        for (int i = 0; i < n; i++)
            assert_true(c.r.v[i] == re.v[i] * f.v[i] && c.r.v[i] > 0.0f);
        assert_int_equal(gmaterial_reflection(c.m, &c.sp, in, &f, out, &f), G_OK);
        for (int i = 0; i < n; i++)
            assert_true(f.v[i] == c.r.v[i]);
        gcolor_free(&re), gcolor_free(&f), gcolor_free(&eta), gcolor_free(&k);
        case_close(&c);
    }
}

/* ---- chi-square of the sampling ---- */

/* The p-value of a chi-square statistic x with dof degrees of freedom: Wilson and Hilferty's normal approximation. */
static double chi2_p(double x, int dof)
{
    double k = dof, z = (cbrt(x / k) - (1.0 - 2.0 / (9.0 * k))) / sqrt(2.0 / (9.0 * k));
    return 0.5 * erfc(z / sqrt(2.0));
}

enum { NT = 20, NP = 16, SUB = 6, DRAWS = 20000 };

/* Bins about the mirror direction r of out: the angle t from r mapped to x = t / (t + s) (s a few alpha: bins of
 * about equal mass), 20 bins in x over [0, pi / (pi + s)], 16 in the azimuth about r. */
typedef struct Bins {
    GVec3 r, t, b;
    double s, xmax;
} Bins;

static int bin_of(const Bins *bn, GVec3 d)
{
    double ang = acos(gfmin(1.0, gfmax(-1.0, gvec3_dot(d, bn->r))));
    double x = ang / (ang + bn->s), phi = atan2(gvec3_dot(d, bn->b), gvec3_dot(d, bn->t));
    int i = (int)(x / bn->xmax * NT), j = (int)((phi + M_PI) / (2 * M_PI) * NP);
    i = i < 0 ? 0 : i >= NT ? NT - 1 : i;
    j = j < 0 ? 0 : j >= NP ? NP - 1 : j;
    return i * NP + j;
}

static GVec3 bin_dir(const Bins *bn, double x, double phi, double *jac)
{
    double ang = bn->s * x / (1.0 - x), dang = bn->s / ((1.0 - x) * (1.0 - x));
    *jac = sin(ang) * dang;
    GVec3 d = gvec3_add(gvec3_scale(bn->r, cos(ang)), gvec3_add(gvec3_scale(bn->t, sin(ang) * cos(phi)),
                                                               gvec3_scale(bn->b, sin(ang) * sin(phi))));
    return d;
}

/* -log10 of the worst p over the draws for out at theta_deg: 0 when every p > 0.01 is asserted by the caller. */
static double chi2_case(Case *c, double alpha, double theta_deg, unsigned long long seed)
{
    GVec3 out = dir_at(theta_deg * DEG, 0.4);
    Bins bn;
    bn.r = gvec3(-out.x, -out.y, out.z);
    goptics_frame(bn.r, &bn.t, &bn.b);
    bn.s = 2.0 * alpha;
    bn.xmax = M_PI / (M_PI + bn.s);
    static double expected[NT * NP], observed[NT * NP];
    memset(observed, 0, sizeof observed);
    for (int i = 0; i < NT; i++)
        for (int j = 0; j < NP; j++) {
            double sum = 0.0;
            for (int a = 0; a < SUB; a++)
                for (int b = 0; b < SUB; b++) {
                    double x = (i + (a + 0.5) / SUB) / NT * bn.xmax, jac;
                    double phi = -M_PI + (j + (b + 0.5) / SUB) / NP * 2 * M_PI;
                    GVec3 d = bin_dir(&bn, x, phi, &jac);
                    sum += gmaterial_pdf(c->m, &c->sp, d, out, NULL) * jac;
                }
            expected[i * NP + j] = sum * (bn.xmax / NT / SUB) * (2 * M_PI / NP / SUB) * DRAWS;
        }
    GMaterialSample s;
    GScratchMark mark = gscratch_mark(c->scratch);
    for (int n = 0; n < DRAWS; n++) {
        int rc = gmaterial_sample(c->m, &c->sp, out, NULL, next_u(&seed), next_u(&seed), &s, &c->r);
        assert_true(rc >= 0);
        if (rc == 1) {
            assert_false(s.flags & GSAMPLE_DELTA);
            assert_near(s.pdf, gmaterial_pdf(c->m, &c->sp, s.in, out, NULL), 1e-9 * s.pdf);
            observed[bin_of(&bn, s.in)] += 1.0;
        }
    }
    gscratch_release(c->scratch, mark);
    /* bins expecting fewer than 5 draws pooled into one */
    double chi2 = 0.0, pool_e = 0.0, pool_o = 0.0;
    int dof = -1;
    for (int i = 0; i < NT * NP; i++) {
        if (expected[i] < 5.0) {
            pool_e += expected[i];
            pool_o += observed[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        dof++;
    }
    if (pool_e > 0.0) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / gfmax(pool_e, 1.0);
        dof++;
    }
    return dof > 0 ? chi2_p(chi2, dof) : 1.0;
}

static void chi2_model(const char *model, const char *distribution)
{
    const double alphas[] = {0.05, 0.3, 0.8};
    unsigned long long seed = 42;
    for (int a = 0; a < 3; a++) {
        char text[160];
        snprintf(text, sizeof text, "material m conductor { metal Au roughness %g distribution %s }", alphas[a],
                 distribution);
        Case c;
        case_open(&c, model, 0.0, text);
        for (int t = 0; t < 10; t++) {
            double theta = 8.5 * t + 0.5, p = chi2_case(&c, alphas[a], theta, seed++);
            if (!(p > 0.01))
                fail_msg("%s %s alpha %g theta %g: p = %g", model, distribution, alphas[a], theta, p);
        }
        case_close(&c);
    }
}

static void chi2_ggx(void **state) { chi2_model(*state, "ggx"); }

static void chi2_beckmann(void **state) { chi2_model(*state, "beckmann"); }

/* ---- energy ---- */

/* The albedo of out's light by the midpoint rule in (cos^2 theta, phi) over the incident hemisphere: the integral of
 * reflection(in, white, out) d(omega), the brightness of the result. */
static double albedo_of(Case *c, GVec3 out, int nt, int np)
{
    double sum = 0.0;
    for (int i = 0; i < nt; i++) {
        double ct = sqrt((i + 0.5) / nt), st = sqrt(1.0 - ct * ct); /* d(omega) = d(cos^2) / (2 cos) dphi */
        for (int j = 0; j < np; j++) {
            GVec3 in = gvec3(st * cos(2 * M_PI * (j + 0.5) / np), st * sin(2 * M_PI * (j + 0.5) / np), ct);
            assert_int_equal(gmaterial_reflection(c->m, &c->sp, in, &c->white, out, &c->r), G_OK);
            sum += gcolor_brightness(&c->r) / (2.0 * ct);
        }
    }
    return sum * (1.0 / nt) * (2 * M_PI / np);
}

/* An independent single-scattering albedo: GGX's D and height-correlated G2 written out here, f cos integrated. */
static double ggx_lambda(GVec3 w, double a)
{
    double t2 = a * a * (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return (sqrt(1.0 + t2) - 1.0) / 2.0;
}

static double ggx_single_albedo(GVec3 out, double a, int nt, int np)
{
    double sum = 0.0;
    for (int i = 0; i < nt; i++) {
        double ct = sqrt((i + 0.5) / nt), st = sqrt(1.0 - ct * ct);
        for (int j = 0; j < np; j++) {
            GVec3 in = gvec3(st * cos(2 * M_PI * (j + 0.5) / np), st * sin(2 * M_PI * (j + 0.5) / np), ct);
            GVec3 h = gvec3_normalize(gvec3_add(in, out));
            double q = (h.x * h.x + h.y * h.y) / (a * a) + h.z * h.z, d = 1.0 / (M_PI * a * a * q * q);
            double g2 = 1.0 / (1.0 + ggx_lambda(in, a) + ggx_lambda(out, a));
            sum += d * g2 / (4.0 * out.z) / (2.0 * ct);
        }
    }
    return sum * (1.0 / nt) * (2 * M_PI / np);
}

/* White furnace: n 0.001, k 1000 reflects 1 - 4e-9 at every angle. Compensated: 1 within 1% at alpha 1 (and 0.5) at
 * ten angles; uncompensated: the single-scattering albedo within 2e-3 (GGX, written out here), and the kit's table
 * within 2e-3. */
static void white_furnace(void **state)
{
    const char *white = "material m conductor { eta rgb 0.001 0.001 0.001 k rgb 1000 1000 1000 roughness %g "
                        "distribution %s compensate %s }";
    const char *dist[] = {"ggx", "beckmann"};
    for (int d = 0; d < 2; d++)
        for (int ai = 0; ai < 2; ai++) {
            double alpha = ai ? 0.5 : 1.0;
            char text[256];
            Case on, off;
            snprintf(text, sizeof text, white, alpha, dist[d], "on");
            case_open(&on, *state, 0.0, text);
            snprintf(text, sizeof text, white, alpha, dist[d], "off");
            case_open(&off, *state, 0.0, text);
            GMicrofacet mf = gmicrofacet_make(d, alpha, alpha);
            float e[GMICROFACET_ALBEDO_N];
            gmicrofacet_albedo_table(&mf, e, NULL);
            for (int t = 0; t < 10; t++) {
                double theta = 9.0 * t + 0.5;
                GVec3 out = dir_at(theta * DEG, 1.0);
                double a_on = albedo_of(&on, out, 400, 96), a_off = albedo_of(&off, out, 400, 96);
                if (fabs(a_on - 1.0) > 0.01)
                    fail_msg("%s alpha %g theta %g: compensated albedo %g", dist[d], alpha, theta, a_on);
                if (fabs(a_off - gmicrofacet_albedo_at(e, out.z)) > 2e-3)
                    fail_msg("%s alpha %g theta %g: uncompensated albedo %g, table %g", dist[d], alpha, theta, a_off,
                             gmicrofacet_albedo_at(e, out.z));
                if (d == 0)
                    assert_near(a_off, ggx_single_albedo(out, alpha, 400, 96), 2e-3);
                assert_true(a_off < a_on);
            }
            case_close(&on);
            case_close(&off);
        }
}

/* Real metals keep at most what arrives, compensated, at every angle and roughness. */
static void energy_conserved(void **state)
{
    const char *metals[] = {"Ag", "Al", "Au"};
    for (int i = 0; i < 3; i++)
        for (int r = 1; r <= 3; r++) {
            char text[160];
            snprintf(text, sizeof text, "material m conductor { metal %s roughness %g }", metals[i], 0.3 * r);
            Case c;
            case_open(&c, *state, 0.0, text);
            for (int t = 0; t < 6; t++) {
                double a = albedo_of(&c, dir_at((15.0 * t + 1.0) * DEG, 0.0), 200, 64);
                assert_true(a <= 1.0 + 2e-3 && a > 0.3);
            }
            case_close(&c);
        }
}

/* f(in, out) = f(out, in): reflection / cos_in is symmetric, compensated or not, isotropic or not. */
static void reciprocity(void **state)
{
    const char *texts[] = {"material m conductor { metal Cu roughness 0.4 }",
                           "material m conductor { metal Cu roughness 0.4 compensate off distribution beckmann }",
                           "material m conductor { metal Ti roughness_u 0.1 roughness_v 0.6 }"};
    unsigned long long seed = 9;
    for (int i = 0; i < 3; i++) {
        Case c;
        case_open(&c, *state, 0.0, texts[i]);
        GColor back;
        assert_int_equal(gcolor_alloc(&back, c.model), G_OK);
        for (int n = 0; n < 200; n++) {
            GVec3 a = dir_at(acos(next_u(&seed)), 2 * M_PI * next_u(&seed));
            GVec3 b = dir_at(acos(next_u(&seed)), 2 * M_PI * next_u(&seed));
            assert_int_equal(gmaterial_reflection(c.m, &c.sp, a, &c.white, b, &c.r), G_OK);
            assert_int_equal(gmaterial_reflection(c.m, &c.sp, b, &c.white, a, &back), G_OK);
            for (int s = 0; s < c.model->nvalues; s++)
                assert_near(c.r.v[s] / a.z, back.v[s] / b.z, 2e-5 * (1.0 + back.v[s] / b.z));
        }
        gcolor_free(&back);
        case_close(&c);
    }
}

/* Smooth: one delta lobe with the Fresnel colour, the mirror ray, is_delta; rough: none. */
static void smooth_and_rough(void **state)
{
    Case c;
    case_open(&c, *state, 0.0, "material m conductor { metal Au }");
    assert_true(gmaterial_is_delta(c.m, &c.sp));
    GVec3 dir, out = dir_at(40 * DEG, 0.3);
    assert_int_equal(gmaterial_reflection_dir(c.m, &c.sp, gvec3_neg(out), &dir), 1);
    GMaterialSample s;
    assert_int_equal(gmaterial_sample(c.m, &c.sp, out, NULL, 0.3, 0.7, &s, &c.r), 1);
    assert_true(s.flags & GSAMPLE_DELTA);
    assert_near(gvec3_dot(s.in, dir), 1.0, 1e-12);
    GColor v;
    assert_int_equal(gcolor_alloc(&v, c.model), G_OK);
    assert_int_equal(gmaterial_reflection(c.m, &c.sp, s.in, &c.white, out, &v), G_OK);
    assert_color_near(&c.r, &v, 1e-6);
    assert_true(gcolor_brightness(&v) > 0.5);
    assert_near(gmaterial_pdf(c.m, &c.sp, s.in, out, NULL), 0.0, 0.0);
    gcolor_free(&v);
    case_close(&c);
    case_open(&c, *state, 0.0, "material m conductor { metal Au roughness 0.2 }");
    assert_false(gmaterial_is_delta(c.m, &c.sp));
    assert_int_equal(gmaterial_reflection_dir(c.m, &c.sp, gvec3_neg(out), &dir), 0);
    assert_true(c.m->flags & GMAT_NO_UV);
    assert_true(c.m->flags & GMAT_DIAGONAL);
    case_close(&c);
}

/* The format's refusals, each at file:line:col naming the bound. */
static void refusals(void **state)
{
    (void)state;
    const struct {
        const char *text, *want;
    } bad[] = {
        {"material m conductor { roughness 1.5 }", "case.mat:1:34: value 1.5 is out of range [0, 1]"},
        {"material m conductor { roughness_u -0.1 }", "case.mat:1:36: value -0.1 is out of range [0, 1]"},
        {"material m conductor { metal Kryptonite }",
         "case.mat:1:30: conductor: unknown metal 'Kryptonite' (known: Ag, "},
        {"material m conductor { eta rgb 1 0 1 k rgb 1 1 1 }", "case.mat:1:28: conductor: eta has the value 0"},
        {"material m conductor { eta rgb 1 1 1 k rgb 1 -1 1 }", "case.mat:1:40: conductor: k has the value -1"},
        {"material m conductor { eta rgb 1 1 1 k rgb 1 1 2000 }", "(must be >= 0 and <= 1000)"},
        {"material m conductor { roughness 0.3 fresnel fast }",
         "case.mat:1:46: material conductor: expected one of table, exact"},
        {"material m conductor { eta rgb 1 1 1 }", "conductor: eta given without k"},
        {"material m conductor { metal Au eta rgb 1 1 1 }", "conductor: metal and eta/k exclude each other"},
        {"material m conductor { roughness 0.1 roughness_v 0.2 }", "roughness and roughness_u/roughness_v exclude"},
        {"material m conductor { distribution phong }", "case.mat:1:37: "},
        {"material m conductor { eta line 500 1 k rgb 1 1 1 }", "conductor: eta must be an rgb triple or a spectrum"},
    };
    GColorModel *model;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &model, &err), G_OK);
    GReaderOptions ro = {.model = model};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        GLibrary *lib = NULL;
        assert_int_not_equal(greader_load_string(bad[i].text, "case.mat", &ro, &lib, &err), G_OK);
        assert_null(lib);
        if (!strstr(err.message, bad[i].want))
            fail_msg("'%s': got '%s', expected '%s'", bad[i].text, err.message, bad[i].want);
    }
    gcolormodel_destroy(model);
}

/* The kit's table itself (gmaterial_fresnel_table_mix) in every model: at each node the exact kernel's colour float
 * for float, s F + t add times a light sample by sample as the kernel and gcolor operations compute it, operands of
 * another model refused; and n and k from two literals (gmaterial_complex_index_from_specs) naming the one refused. */
static void kit_fresnel_table(void **state)
{
    (void)state;
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    for (int mi = 0; mi < 4; mi++) {
        GColorModel *m, *other;
        GError err;
        assert_int_equal(gcolormodel_create(models[mi], NULL, &m, &err), G_OK);
        assert_int_equal(gcolormodel_create(mi ? "rgb" : "spectrum", NULL, &other, &err), G_OK);
        GColor eta, k, f, want, add, light, alien;
        assert_int_equal(gcolor_alloc(&eta, m), G_OK);
        assert_int_equal(gcolor_alloc(&k, m), G_OK);
        assert_int_equal(gcolor_alloc(&f, m), G_OK);
        assert_int_equal(gcolor_alloc(&want, m), G_OK);
        assert_int_equal(gcolor_alloc(&add, m), G_OK);
        assert_int_equal(gcolor_alloc(&light, m), G_OK);
        assert_int_equal(gcolor_alloc(&alien, other), G_OK);
        assert_int_equal(gmetal_colors(gmetal_find("Au"), &eta, &k), G_OK);
        assert_int_equal(gcolor_fill(&add, 0.25), G_OK);
        assert_int_equal(gcolor_fill(&light, 0.5), G_OK);
        GFresnelTable *t;
        assert_int_equal(gmaterial_fresnel_table_create(&eta, &k, &t), G_OK);
        for (int j = 0; j <= GFRESNEL_TABLE_K; j += j < GFRESNEL_TABLE_K - 31 ? 31 : 1) {
            double u = (double)j / GFRESNEL_TABLE_K, cos_h = j == GFRESNEL_TABLE_K ? 1.0 : u * u;
            assert_int_equal(gmaterial_fresnel_table_mix(t, cos_h, 1.0, NULL, 0.0, NULL, &f), G_OK);
            assert_int_equal(gmaterial_fresnel_conductor_mix(&want, cos_h, &eta, &k, 1.0, NULL, 0.0), G_OK);
            for (int i = 0; i < m->nvalues; i++)
                assert_true(f.v[i] == want.v[i]);
            assert_int_equal(gmaterial_fresnel_table_mix(t, cos_h, 0.5, &add, 2.0, &light, &f), G_OK);
            for (int i = 0; i < m->nvalues; i++)
                assert_true(fabs(f.v[i] - (0.5 * want.v[i] + 2.0 * 0.25) * 0.5) <= 1e-6);
        }
        assert_int_equal(gmaterial_fresnel_table_mix(t, 0.5, 1.0, NULL, 0.0, &alien, &f), G_ERR_MISMATCH);
        assert_int_equal(gmaterial_fresnel_table_mix(t, 0.5, 1.0, &alien, 1.0, NULL, &f), G_ERR_MISMATCH);
        assert_int_equal(gmaterial_fresnel_table_mix(t, 0.5, 1.0, NULL, 0.0, NULL, &alien), G_ERR_MISMATCH);
        gmaterial_fresnel_table_destroy(t);
        GColorSpec *good = gcolorspec_create(), *bad = gcolorspec_create();
        assert_non_null(good);
        assert_non_null(bad);
        good->form = GCOLORSPEC_RGB, good->rgb[0] = good->rgb[1] = good->rgb[2] = 0.5, good->scale = 1.0;
        bad->form = GCOLORSPEC_RGB, bad->rgb[0] = 1.0, bad->scale = 1e300; /* overflows a float: refused */
        assert_int_equal(gmaterial_complex_index_from_specs(good, good, &eta, &k, &err), G_OK);
        assert_int_not_equal(gmaterial_complex_index_from_specs(good, bad, &eta, &k, &err), G_OK);
        assert_string_equal(err.param, "k");
        gcolorspec_destroy(good);
        gcolorspec_destroy(bad);
        GColor *all[] = {&eta, &k, &f, &want, &add, &light, &alien};
        for (int i = 0; i < 7; i++)
            gcolor_free(all[i]);
        gcolormodel_destroy(m);
        gcolormodel_destroy(other);
    }
}

#define MODELS(f)                                                                                              \
    {#f " (rgb)", f, NULL, NULL, (void *)"rgb"}, {#f " (spectrum9)", f, NULL, NULL, (void *)"spectrum9"},      \
        {#f " (spectrum)", f, NULL, NULL, (void *)"spectrum"},                                                 \
    {                                                                                                          \
        #f " (bispectral)", f, NULL, NULL, (void *)"bispectral"                                                \
    }

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(normal_incidence),
        cmocka_unit_test(fresnel_table),
        cmocka_unit_test(kit_fresnel_table),
        MODELS(chi2_ggx),
        {"chi2_beckmann (spectrum)", chi2_beckmann, NULL, NULL, (void *)"spectrum"},
        BOTH(white_furnace),
        BOTH(energy_conserved),
        MODELS(reciprocity),
        MODELS(smooth_and_rough),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
