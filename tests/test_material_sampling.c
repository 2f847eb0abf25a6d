/* test_material_sampling.c - the sampling slots of every built-in material and texture node (material.h):
 * E[weight] over many draws equals the light the material's own methods return for white light, integrated over
 * the incident directions by quadrature (plus its ideal rays), within a few standard errors; lambert's weight is
 * rho exactly; delta lobes carry the mirror's reflectance and the Fresnel reflectance of the dielectric; the pdf
 * integrates to 1 - P(delta); and the default sampling of a class without the slots stays unbiased. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "material_fixture.h"
#include "generic/builtins.h"
#include "test_util.h"

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
    GColor ri, white;
} Case;

/* Loads `text` in the model named `model` and takes the material `name`; the surface point is the plane z = 0
 * seen from outside (from vacuum into the material), at (u, v) = (0.3, 0.6). */
static void case_open(Case *c, const char *model, const char *text, const char *name)
{
    memset(c, 0, sizeof *c);
    GError err;
    assert_int_equal(gcolormodel_create(model, NULL, &c->model, &err), G_OK);
    c->scratch = gscratch_create(0);
    GReaderOptions ro = {.model = c->model};
    if (greader_load_string(text, "case.mat", &ro, &c->lib, &err) != G_OK)
        fail_msg("%s", err.message);
    c->m = glibrary_material(c->lib, name);
    assert_non_null(c->m);
    gsurfpoint_init(&c->sp, c->model, c->scratch);
    c->sp.geometric_normal = gvec3(0, 0, 1);
    c->sp.dpdu = gvec3(1, 0, 0);
    c->sp.dpdv = gvec3(0, 1, 0);
    c->sp.u = 0.3;
    c->sp.v = 0.6;
    c->sp.point = c->sp.object_point = gvec3(0.3, 0.6, 0);
    c->sp.entering = 1;
    c->sp.material = c->m;
    c->sp.to = c->m;
    assert_int_equal(gcolor_alloc(&c->ri, c->model), G_OK);
    assert_int_equal(gcolor_alloc(&c->white, c->model), G_OK);
    assert_int_equal(gcolor_fill(&c->white, 1.0), G_OK);
    GColor to;
    assert_int_equal(gcolor_alloc(&to, c->model), G_OK);
    assert_int_equal(gmaterial_refraction_index(NULL, &c->sp, &c->ri), G_OK);
    assert_int_equal(gmaterial_refraction_index(c->m, &c->sp, &to), G_OK);
    assert_int_equal(gcolor_div(&c->ri, &c->ri, &to), G_OK);
    gcolor_free(&to);
}

static void case_close(Case *c)
{
    gcolor_free(&c->ri);
    gcolor_free(&c->white);
    glibrary_destroy(c->lib);
    gscratch_destroy(c->scratch);
    gcolormodel_destroy(c->model);
}

/* The ideal (delta) part of the light along the ideal ray d: the value on the ray, for a material (its
 * reflection() or refraction() is only the ideal part there) and for a node alike (at its ideal ray a blend sums
 * only the children that have one, material.h). */
static void ideal_part(Case *c, GVec3 d, GVec3 out, int transmit, GColor *r)
{
    if (transmit)
        assert_int_equal(gmaterial_refraction(c->m, &c->sp, d, &c->white, &c->ri, out, r), G_OK);
    else
        assert_int_equal(gmaterial_reflection(c->m, &c->sp, d, &c->white, out, r), G_OK);
}

/* The reference: the integral over in of reflection(in, white, out) (upper hemisphere) and refraction (lower),
 * midpoint rule on an nt x 4nt grid in (theta, phi) per hemisphere, plus the values along the ideal rays. */
static void reference(Case *c, GVec3 out, int nt, GColor *ref)
{
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor r, ring;
    assert_int_equal(gcolor_scratch(&r, c->model, c->scratch), G_OK);
    assert_int_equal(gcolor_scratch(&ring, c->model, c->scratch), G_OK);
    gcolor_black(ref);
    int np = 4 * nt, opaque = gmaterial_opaque(c->m, &c->sp);
    double dt = 0.5 * M_PI / nt, dp = 2.0 * M_PI / np;
    for (int below = 0; below < (opaque ? 1 : 2); below++)
        for (int i = 0; i < nt; i++) {
            double th = (i + 0.5) * dt, w = sin(th) * dt * dp;
            gcolor_black(&ring);
            for (int j = 0; j < np; j++) {
                GVec3 in = dir_at(th, (j + 0.5) * dp);
                if (below) {
                    in.z = -in.z;
                    assert_int_equal(gmaterial_refraction(c->m, &c->sp, in, &c->white, &c->ri, out, &r), G_OK);
                } else {
                    assert_int_equal(gmaterial_reflection(c->m, &c->sp, in, &c->white, out, &r), G_OK);
                }
                assert_int_equal(gcolor_add_scaled(&ring, &r, w), G_OK);
            }
            assert_int_equal(gcolor_add(ref, ref, &ring), G_OK);
        }
    GVec3 d;
    int v = gmaterial_reflection_dir(c->m, &c->sp, gvec3_neg(out), &d);
    assert_true(v >= 0);
    if (v) {
        ideal_part(c, d, out, 0, &r);
        assert_int_equal(gcolor_add(ref, ref, &r), G_OK);
    }
    v = opaque ? 0 : gmaterial_refraction_dir(c->m, &c->sp, gvec3_neg(out), &c->ri, &d);
    assert_true(v >= 0);
    if (v) {
        ideal_part(c, d, out, 1, &r);
        assert_int_equal(gcolor_add(ref, ref, &r), G_OK);
    }
    gscratch_release(c->scratch, mark);
}

/* The pdf integrated over the sphere (nt x 4nt per hemisphere). */
static double pdf_integral(Case *c, GVec3 out, int nt)
{
    int np = 4 * nt;
    double dt = 0.5 * M_PI / nt, dp = 2.0 * M_PI / np, sum = 0.0;
    for (int below = 0; below < 2; below++)
        for (int i = 0; i < nt; i++) {
            double th = (i + 0.5) * dt;
            for (int j = 0; j < np; j++) {
                GVec3 in = dir_at(th, (j + 0.5) * dp);
                if (below)
                    in.z = -in.z;
                double p = gmaterial_pdf(c->m, &c->sp, in, out, &c->ri);
                assert_true(p >= 0.0 && isfinite(p));
                sum += p * sin(th) * dt * dp;
            }
        }
    return sum;
}

/* Draws n samples for out: the mean weight per colour sample and its standard error; returns the share of draws
 * that gave a non-delta direction (1 - P(delta) - P(nothing drawn)). */
static double estimate(Case *c, GVec3 out, int n, double *mean, double *se)
{
    int nv = c->model->nvalues, nondelta = 0;
    double *s1 = calloc((size_t)nv, sizeof *s1), *s2 = calloc((size_t)nv, sizeof *s2);
    assert_non_null(s1);
    assert_non_null(s2);
    GColor w;
    assert_int_equal(gcolor_alloc(&w, c->model), G_OK);
    unsigned long long seed = 42;
    for (int k = 0; k < n; k++) {
        GMaterialSample s;
        int rc = gmaterial_sample(c->m, &c->sp, out, &c->ri, next_u(&seed), next_u(&seed), &s, &w);
        assert_true(rc >= 0);
        if (rc == 0)
            continue;
        assert_true(s.pdf > 0.0);
        assert_true(gcolor_is_finite(&w));
        nondelta += (s.flags & GSAMPLE_DELTA) == 0;
        for (int i = 0; i < nv; i++) {
            s1[i] += w.v[i];
            s2[i] += (double)w.v[i] * w.v[i];
        }
    }
    for (int i = 0; i < nv; i++) {
        mean[i] = s1[i] / n;
        se[i] = sqrt(fmax(0.0, s2[i] / n - mean[i] * mean[i]) / n);
    }
    gcolor_free(&w);
    free(s1);
    free(s2);
    return (double)nondelta / n;
}

/* E[weight] against the reference for out at theta_deg: within 4.5 standard errors plus the quadrature's
 * tolerance (relative tol_quad, absolute 1e-4). */
static void assert_unbiased(Case *c, double theta_deg, int n, int nt, double tol_quad)
{
    GVec3 out = dir_at(theta_deg * DEG, 0.7);
    int nv = c->model->nvalues;
    double *mean = calloc((size_t)nv, sizeof *mean), *se = calloc((size_t)nv, sizeof *se);
    assert_non_null(mean);
    assert_non_null(se);
    GColor ref;
    assert_int_equal(gcolor_alloc(&ref, c->model), G_OK);
    reference(c, out, nt, &ref);
    estimate(c, out, n, mean, se);
    for (int i = 0; i < nv; i++) {
        double tol = 4.5 * se[i] + tol_quad * fabs(ref.v[i]) + 1e-4;
        if (!(fabs(mean[i] - ref.v[i]) <= tol))
            fail_msg("%s at %g deg, sample %d: E[weight] %.6f, reference %.6f (se %.2g, tolerance %.2g)",
                     gmaterial_name(c->m), theta_deg, i, mean[i], ref.v[i], se[i], tol);
    }
    gcolor_free(&ref);
    free(mean);
    free(se);
}

/* One material in one model: unbiased at three incidences, and pdf integrates to 1 - P(delta). */
static void check_material(const char *model, const char *text, const char *name, int nt, double tol_quad)
{
    Case c;
    case_open(&c, model, text, name);
    static const double thetas[] = {50, 15, 75};
    for (int k = 0; k < (TU_SANITIZED ? 1 : 3); k++) { /* the sanitizers look at the code paths: one angle there */
        assert_unbiased(&c, thetas[k], 60000, nt, tol_quad);
        GVec3 out = dir_at(thetas[k] * DEG, 0.7);
        int nv = c.model->nvalues;
        double *mean = calloc((size_t)nv, sizeof *mean), *se = calloc((size_t)nv, sizeof *se);
        double share = estimate(&c, out, 20000, mean, se);
        free(mean);
        free(se);
        double integral = pdf_integral(&c, out, nt);
        if (!(fabs(integral - share) < 0.02))
            fail_msg("%s at %g deg: pdf integrates to %.4f, the share of non-delta draws (1 - P(delta)) is %.4f", name,
                     thetas[k], integral, share);
    }
    case_close(&c);
}

#define MODELS(f) {#f " (rgb)", f, NULL, NULL, (void *)"rgb"}, {#f " (bispectral)", f, NULL, NULL, (void *)"bispectral"}

static void lambert_unbiased(void **state)
{
    check_material(*state, "material m lambert { reflectance rgb 0.7 0.5 0.2 }", "m", 64, 2e-3);
}

static void phong_unbiased(void **state)
{
    check_material(*state,
                   "material m phong { diffuse rgb 0.3 0.2 0.1  specular rgb 0.3 0.3 0.3  exponent 40 "
                   "mirror rgb 0.2 0.2 0.2 }",
                   "m", 160, 5e-3);
}

static void mirror_unbiased(void **state)
{
    check_material(*state, "material m mirror { reflectance rgb 0.9 0.6 0.3 }", "m", 16, 1e-4);
}

static void dielectric_unbiased(void **state)
{
    check_material(*state, "material m dielectric { index 1.5 }", "m", 16, 1e-4);
}

static void emitter_unbiased(void **state)
{
    check_material(*state, "material m emitter { radiance rgb 1 1 1 }", "m", 16, 1e-4);
}

static void fluorescent_phong_unbiased(void **state)
{
    check_material(*state, "material m fluorescent-phong { ks 0.2 exponents 20 60 200 weights 0.3 0.3 0.4 }", "m",
                   360, 1e-2);
}

static void fluorescent_varnish_unbiased(void **state)
{
    check_material(*state, "material m fluorescent-varnish { slope 12 }", "m", 200, 1e-2);
}

static const char *const kids = "material a lambert { reflectance rgb 0.8 0.4 0.2 }\n"
                                "material b phong { diffuse rgb 0.1 0.3 0.5  specular rgb 0.4 0.4 0.4 exponent 30 }\n"
                                "material c mirror { reflectance rgb 0.5 0.5 0.5 }\n";

static void run_node(void **state, const char *node)
{
    char text[1024];
    snprintf(text, sizeof text, "%s%s\n", kids, node);
    check_material(*state, text, "n", 160, 5e-3);
}

static void interpolate_unbiased(void **state)
{
    run_node(state, "node n interpolate { a a  b b  t constant { value 0.3 } }");
}

static void interpolate_with_mirror(void **state)
{
    run_node(state, "node n interpolate { a c  b b  t constant { value 0.6 } }");
}

static void spline_unbiased(void **state)
{
    run_node(state, "node n spline { t constant { value 0.4 } children { a b c a } }");
}

static void select_unbiased(void **state)
{
    run_node(state, "node n select { index constant { value 1 } children { a b c } }");
}

static void bump_unbiased(void **state)
{
    run_node(state, "node n bump { child b  height gradient { space uv slope 1 0 0 }  strength 0.6 }");
}

static void scale_unbiased(void **state)
{
    run_node(state, "node n scale { child b  factor constant { value 0.5 } }");
}

static void transform_unbiased(void **state)
{
    run_node(state,
             "node n transform { child interpolate { a a  b b  t checker { frequency 4 } }  uv { translate 0.2 0 } }");
}

/* lambert: every weight is rho exactly, every direction above the surface with pdf cos / pi. */
static void lambert_weight_is_rho(void **state)
{
    Case c;
    case_open(&c, *state, "material m lambert { reflectance rgb 0.7 0.5 0.2 }", "m");
    GColor rho, w;
    assert_int_equal(gcolor_alloc(&rho, c.model), G_OK);
    assert_int_equal(gcolor_alloc(&w, c.model), G_OK);
    assert_int_equal(gmaterial_diffuse(c.m, &c.sp, &rho), G_OK);
    unsigned long long seed = 7;
    GVec3 out = dir_at(40 * DEG, 1.0);
    for (int k = 0; k < 1000; k++) {
        GMaterialSample s;
        assert_int_equal(gmaterial_sample(c.m, &c.sp, out, &c.ri, next_u(&seed), next_u(&seed), &s, &w), 1);
        assert_true(s.in.z > 0.0);
        assert_true(fabs(s.pdf - s.in.z / M_PI) < 1e-12);
        assert_int_equal(s.flags, GSAMPLE_REFLECT);
        for (int i = 0; i < c.model->nvalues; i++)
            assert_true(w.v[i] == rho.v[i]);
    }
    assert_int_equal(gmaterial_is_delta(c.m, &c.sp), 0);
    gcolor_free(&rho);
    gcolor_free(&w);
    case_close(&c);
}

/* mirror: one delta lobe, pdf 1, weight the reflectance; dielectric: reflection with probability F (Fresnel for
 * n = 1.5 at 45 degrees, written out here), weight 1 for both lobes; past the critical angle, reflection alone. */
static void delta_lobes(void **state)
{
    Case c;
    case_open(&c, *state, "material m mirror { reflectance rgb 0.9 0.6 0.3 }", "m");
    GColor w, refl;
    assert_int_equal(gcolor_alloc(&w, c.model), G_OK);
    assert_int_equal(gcolor_alloc(&refl, c.model), G_OK);
    GVec3 out = dir_at(45 * DEG, 0.0);
    GMaterialSample s;
    assert_int_equal(gmaterial_sample(c.m, &c.sp, out, &c.ri, 0.3, 0.7, &s, &w), 1);
    assert_int_equal(s.flags, GSAMPLE_REFLECT | GSAMPLE_DELTA);
    assert_true(s.pdf == 1.0);
    assert_true(fabs(s.in.x + out.x) < 1e-12 && fabs(s.in.z - out.z) < 1e-12);
    assert_int_equal(gmaterial_reflection(c.m, &c.sp, s.in, &c.white, out, &refl), G_OK);
    assert_color_near(&w, &refl, 1e-6);
    assert_int_equal(gmaterial_is_delta(c.m, &c.sp), 1);
    assert_true(gmaterial_pdf(c.m, &c.sp, s.in, out, &c.ri) == 0.0);
    gcolor_free(&w);
    gcolor_free(&refl);
    case_close(&c);

    case_open(&c, *state, "material m dielectric { index 1.5 }", "m");
    assert_int_equal(gcolor_alloc(&w, c.model), G_OK);
    double ci = cos(45 * DEG), eta = 1.0 / 1.5, st = eta * sin(45 * DEG), ct = sqrt(1.0 - st * st);
    double rs = (eta * ci - ct) / (eta * ci + ct), rp = (ci - eta * ct) / (ci + eta * ct),
           F = 0.5 * (rs * rs + rp * rp);
    assert_int_equal(gmaterial_sample(c.m, &c.sp, out, &c.ri, 0.5 * F, 0.5, &s, &w), 1);
    assert_int_equal(s.flags, GSAMPLE_REFLECT | GSAMPLE_DELTA);
    assert_true(fabs(s.pdf - F) < 1e-4);
    for (int i = 0; i < c.model->nvalues; i++)
        assert_true(fabs(w.v[i] - 1.0) < 1e-3);
    assert_int_equal(gmaterial_sample(c.m, &c.sp, out, &c.ri, F + 0.5 * (1.0 - F), 0.5, &s, &w), 1);
    assert_int_equal(s.flags, GSAMPLE_TRANSMIT | GSAMPLE_DELTA);
    assert_true(fabs(s.pdf - (1.0 - F)) < 1e-4);
    assert_true(s.in.z < 0.0 && fabs(sqrt(s.in.x * s.in.x + s.in.y * s.in.y) - st) < 1e-4);
    for (int i = 0; i < c.model->nvalues; i++)
        assert_true(fabs(w.v[i] - 1.0) < 1e-3);
    /* from inside past the critical angle (41.8 degrees): total internal reflection */
    c.sp.geometric_normal = gvec3(0, 0, -1);
    c.sp.entering = 0;
    c.sp.from = c.m;
    c.sp.to = NULL;
    gsurfpoint_invalidate(&c.sp);
    assert_int_equal(gcolor_fill(&c.ri, 1.5), G_OK);
    GVec3 in_out = dir_at(60 * DEG, 0.0);
    in_out.z = -in_out.z;
    for (int k = 0; k < 5; k++) {
        assert_int_equal(gmaterial_sample(c.m, &c.sp, in_out, &c.ri, 0.2 * k + 0.1, 0.5, &s, &w), 1);
        assert_int_equal(s.flags, GSAMPLE_REFLECT | GSAMPLE_DELTA);
        assert_true(s.pdf == 1.0);
    }
    gcolor_free(&w);
    case_close(&c);
}

/* phong with kd = ks = 0.3, mirror 0.2 (grey): the mirror lobe is chosen with probability 0.25 and carries
 * 0.2 / 0.25; the pdf integrates to 0.75. */
static void phong_delta_share(void **state)
{
    Case c;
    case_open(&c, *state, "material m phong { diffuse rgb 0.3 0.3 0.3  specular rgb 0.3 0.3 0.3 exponent 20 "
                          "mirror rgb 0.2 0.2 0.2 }", "m");
    GColor w;
    assert_int_equal(gcolor_alloc(&w, c.model), G_OK);
    GVec3 out = dir_at(30 * DEG, 0.0);
    GMaterialSample s;
    assert_int_equal(gmaterial_sample(c.m, &c.sp, out, &c.ri, 0.9, 0.5, &s, &w), 1);
    assert_int_equal(s.flags, GSAMPLE_REFLECT | GSAMPLE_DELTA);
    assert_true(fabs(s.pdf - 0.25) < 1e-3);
    for (int i = 0; i < c.model->nvalues; i++)
        assert_true(fabs(w.v[i] - 0.8) < 3e-3);
    double integral = pdf_integral(&c, out, 200);
    assert_true(fabs(integral - 0.75) < 3e-3);
    gcolor_free(&w);
    case_close(&c);
}

/* A class without the sampling slots (a built-in's class copied, the slots NULL) is sampled by the defaults of
 * material.h: still unbiased. */
static void defaults_unbiased_one(const char *model, const char *text, int nt, double tol_quad)
{
    Case c;
    case_open(&c, model, text, "m");
    GMaterialClass copy = *c.m->cls;
    const GMaterialClass *own = c.m->cls;
    copy.sample = NULL;
    copy.pdf = NULL;
    copy.is_delta = NULL;
    c.m->cls = &copy;
    assert_int_equal(gmaterial_is_delta(c.m, &c.sp), 0);
    assert_unbiased(&c, 20, 60000, nt, tol_quad);
    if (!TU_SANITIZED)
        assert_unbiased(&c, 70, 60000, nt, tol_quad);
    c.m->cls = own;
    case_close(&c);
}

static void defaults_unbiased(void **state)
{
    defaults_unbiased_one(*state, "material m lambert { reflectance rgb 0.7 0.5 0.2 }", 64, 2e-3);
    defaults_unbiased_one(*state, "material m phong { diffuse rgb 0.3 0.2 0.1  specular rgb 0.3 0.3 0.3  exponent 10 "
                                  "mirror rgb 0.2 0.2 0.2 }", 160, 5e-3);
    defaults_unbiased_one(*state, "material m phong { specular rgb 0.5 0.5 0.5  exponent 5 }", 160, 5e-3);
    defaults_unbiased_one(*state, "material m dielectric { index 1.5 }", 16, 1e-4);
    defaults_unbiased_one(*state, "material m fluorescent-varnish { slope 20 }", 200, 1e-2);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        MODELS(lambert_unbiased),
        MODELS(phong_unbiased),
        MODELS(mirror_unbiased),
        MODELS(dielectric_unbiased),
        MODELS(emitter_unbiased),
        MODELS(fluorescent_phong_unbiased),
        MODELS(fluorescent_varnish_unbiased),
        MODELS(interpolate_unbiased),
        MODELS(interpolate_with_mirror),
        MODELS(spline_unbiased),
        MODELS(select_unbiased),
        MODELS(bump_unbiased),
        MODELS(scale_unbiased),
        MODELS(transform_unbiased),
        MODELS(lambert_weight_is_rho),
        MODELS(delta_lobes),
        MODELS(phong_delta_share),
        MODELS(defaults_unbiased),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
