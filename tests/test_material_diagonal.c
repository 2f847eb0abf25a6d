/* test_material_diagonal.c - GMAT_DIAGONAL (material.h): reflection(sp, in, illum, out) is reflection(sp, in,
 * white, out) * illum (gcolor_mul), white being 1 in every sample, and the same for refraction with any rel_index,
 * so a renderer may weigh a secondary ray by what the material passes on of white light:
 *  - which materials and nodes get the bit, in rgb, spectrum and bispectral: lambert, mirror, phong, dielectric
 *    (with and without a tint) and emitter; interpolate, interpolate-one, select, spline, bump, scale and transform
 *    over children that all have it; not the fluorescent materials, not a node over one of them, and in bispectral
 *    not a lambert whose reflectance is a re-radiation matrix, nor a node over it;
 *  - the property itself for every flagged one, computed here from the class's own slots at random points on both
 *    sides, over random pairs of directions (and the ideal reflection and refraction of out, where a mirror or
 *    glass passes light on alone) and random lights, with the relative indices 1, 1.5 and 1 / 1.5: per pair the
 *    largest difference over the largest value, at most 1e-5; and the comparison can fail: a fluorescent material
 *    in bispectral is far from it;
 *  - `gmat check`'s diagonal property (GENERIC_BUILD_DIR/bin/gmat, run on a file of them) for each flagged one:
 *    PASS with its worst figure below 1e-5; for a fluorescent one PASS as "not set". Only that line is read: the
 *    other properties are conformance.sh's (a fluorescent fold fails albedo in rgb, a known case there). */
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
#include "generic/materials.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"

#define TOL 1e-5
#define PAIRS 300

/* A fluorescent pigment (examples/materials/fluorescent.mat): a re-radiation matrix in bispectral, its fold (a
 * plain reflectance) in the other models. */
#define DAYGLO                                                                                                 \
    "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"             \
    "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"

/* The leaves and the nodes over them; MATRIX_LAMBERT is added in bispectral only (rgb refuses the pigment's fold
 * as a lambert's reflectance: its energy there is above 1). */
static const char *const library_text =
    DAYGLO "material lam lambert { reflectance rgb 0.8 0.4 0.2 }\n"
           "material mir mirror { reflectance rgb 0.9 0.8 0.6 }\n"
           "material ph phong { diffuse rgb 0.4 0.3 0.2 specular rgb 0.2 0.3 0.3 exponent 40 mirror rgb 0.2 0.1 0.3 }\n"
           "material glass dielectric { index 1.5 }\n"
           "material tinted dielectric { index cauchy 1.5 0.01 tint rgb 0.9 0.6 0.3 absorption rgb 0.1 0.2 0.3 }\n"
           "material glow emitter { radiance rgb 1 0.8 0.6 }\n"
           "material fphong fluorescent-phong { matrix dayglo ks 0.04 }\n"
           "material fvarnish fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
           "node interp interpolate { a lam b glass t checker { dims 3 frequency 3 } }\n"
           "node interp_one interpolate-one { method reflection a ph b mir t perlin { frequency 5 } }\n"
           "node sel select { index surface children { lam mir ph tinted } }\n"
           "node spl spline { t marble { space object frequency 2 turbulence 1 } basis bspline\n"
           "    children { lam ph tinted mir glow } }\n"
           "node bumped bump { child ph height fbm { space object frequency 6 } strength 0.06 }\n"
           "node scaled scale { child tinted factor fbm { space object frequency 4 } }\n"
           "node moved transform { child interp uv { rotate 30 scale 0.5 } xyz { rotate 0 1 0 20 } }\n"
           "node interp_f interpolate { a lam b fphong t checker { dims 3 frequency 3 } }\n"
           "node sel_f select { index surface children { lam fvarnish } }\n"
           "node spl_f spline { t marble { space object frequency 2 } basis linear children { ph fphong glass } }\n"
           "node bumped_f bump { child fphong height fbm { space object frequency 6 } strength 0.06 }\n"
           "node scaled_f scale { child fvarnish factor fbm { space object frequency 4 } }\n"
           "node moved_f transform { child fphong uv { rotate 30 } }\n";
#define MATRIX_LAMBERT                                                                                         \
    "material lam_m lambert { reflectance dayglo }\n"                                                          \
    "node interp_m interpolate { a lam b lam_m t checker { dims 3 frequency 3 } }\n"

/* name, whether it has the bit, and whether it is defined in bispectral only (MATRIX_LAMBERT) */
static const struct {
    const char *name;
    int bit, bispectral_only;
} cases[] = {
    {"lam", 1, 0},      {"mir", 1, 0},      {"ph", 1, 0},       {"glass", 1, 0},    {"tinted", 1, 0},
    {"glow", 1, 0},     {"interp", 1, 0},   {"interp_one", 1, 0}, {"sel", 1, 0},    {"spl", 1, 0},
    {"bumped", 1, 0},   {"scaled", 1, 0},   {"moved", 1, 0},    {"fphong", 0, 0},   {"fvarnish", 0, 0},
    {"interp_f", 0, 0}, {"sel_f", 0, 0},    {"spl_f", 0, 0},    {"bumped_f", 0, 0}, {"scaled_f", 0, 0},
    {"moved_f", 0, 0},  {"lam_m", 0, 1},    {"interp_m", 0, 1},
};
enum { NCASES = sizeof cases / sizeof *cases };

static int diag(const GMaterial *m) { return (m->flags & GMAT_DIAGONAL) != 0; }

static GVec3 random_dir(unsigned long long *s)
{
    double z = 1.0 - 2.0 * tu_uniform(s), p = 2.0 * M_PI * tu_uniform(s), r = sqrt(fmax(0.0, 1.0 - z * z));
    return gvec3(r * cos(p), r * sin(p), z);
}

/* d turned to the side of n (behind = 0) or away from it. */
static GVec3 on_side(GVec3 d, GVec3 n, int behind) { return (gvec3_dot(d, n) < 0.0) != behind ? gvec3_neg(d) : d; }

/* A point of m at random: (u, v), point, surface index, a geometric normal tilted from +z (below: -z, seen from
 * inside, from the material into vacuum). */
static void random_point(GSurfPoint *sp, const GMaterial *m, GScratch *s, unsigned long long *seed, int below)
{
    gsurfpoint_init(sp, m->model, s);
    sp->u = tu_uniform(seed);
    sp->v = tu_uniform(seed);
    sp->dpdu = gvec3(1, 0, 0);
    sp->dpdv = gvec3(0, 1, 0);
    sp->point = sp->object_point = gvec3(4 * tu_uniform(seed) - 2, 4 * tu_uniform(seed) - 2, tu_uniform(seed));
    sp->surface = tu_uniform(seed) < 0.5;
    GVec3 g = gvec3_normalize(gvec3(tu_uniform(seed) - 0.5, tu_uniform(seed) - 0.5, 1.0));
    sp->geometric_normal = below ? gvec3_neg(g) : g;
    sp->entering = !below;
    sp->material = m;
    sp->from = below ? m : NULL;
    sp->to = below ? NULL : m;
}

/* The largest relative difference of one pair: |got - want| over the largest |value| of either (0 when both are
 * black); *lit counts the pairs that pass something on. */
static double relative(const GColor *got, const GColor *want, int *lit)
{
    double d = 0.0, big = 0.0;
    for (int j = 0; j < got->model->nvalues; j++) {
        d = fmax(d, fabs((double)got->v[j] - want->v[j]));
        big = fmax(big, fmax(fabs(got->v[j]), fabs(want->v[j])));
    }
    *lit += big > 0.0;
    return big > 0.0 ? d / big : d;
}

/* Work colours of the measure. */
typedef struct Work {
    GColor white, light, got, want, index[3];
} Work;

/* The class's own reflection (ri NULL) or refraction of w->light from in towards out against its pass-on of white
 * times the light; a missing slot is black (the default) and not compared. */
static double compare_pair(const GMaterial *m, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *ri, Work *w,
                           int *lit)
{
    if (ri ? !m->cls->refraction : !m->cls->reflection)
        return 0.0;
    if (ri) {
        assert_int_equal(m->cls->refraction(m, sp, in, &w->light, ri, out, &w->got), G_OK);
        assert_int_equal(m->cls->refraction(m, sp, in, &w->white, ri, out, &w->want), G_OK);
    } else {
        assert_int_equal(m->cls->reflection(m, sp, in, &w->light, out, &w->got), G_OK);
        assert_int_equal(m->cls->reflection(m, sp, in, &w->white, out, &w->want), G_OK);
    }
    assert_int_equal(gcolor_mul(&w->want, &w->want, &w->light), G_OK);
    return relative(&w->got, &w->want, lit);
}

/* The direction light comes from along the ideal reflection (ri NULL) or refraction of out, when the material
 * has one; else d. */
static GVec3 ideal_or(const GMaterial *m, GSurfPoint *sp, GVec3 out, const GColor *ri, GVec3 d)
{
    GVec3 dir;
    int valid = ri ? gmaterial_refraction_dir(m, sp, gvec3_neg(out), ri, &dir)
                   : gmaterial_reflection_dir(m, sp, gvec3_neg(out), &dir);
    assert_true(valid >= 0);
    return valid == 1 && gvec3_length(dir) > 0.0 ? gvec3_normalize(dir) : d;
}

/* The largest relative difference between m's own pass-on of a light and its pass-on of white times the light,
 * over PAIRS random points, directions out and lights: the reflection from a direction on out's side (every third
 * pair the ideal reflection; one in five anywhere) and the refraction with each relative index from across the
 * surface (every third pair the ideal refraction; one in five anywhere). *lit counts the comparisons that pass
 * something on. */
static double worst_relative(const GMaterial *m, GScratch *s, int *lit)
{
    const GColorModel *model = m->model;
    Work w;
    static const double indices[3] = {1.0, 1.5, 1.0 / 1.5};
    assert_int_equal(gcolor_alloc(&w.white, model), G_OK);
    assert_int_equal(gcolor_alloc(&w.light, model), G_OK);
    assert_int_equal(gcolor_alloc(&w.got, model), G_OK);
    assert_int_equal(gcolor_alloc(&w.want, model), G_OK);
    assert_int_equal(gcolor_fill(&w.white, 1.0), G_OK);
    for (int r = 0; r < 3; r++) {
        assert_int_equal(gcolor_alloc(&w.index[r], model), G_OK);
        assert_int_equal(gcolor_fill(&w.index[r], indices[r]), G_OK);
    }
    unsigned long long seed = 7;
    double worst = 0.0;
    *lit = 0;
    for (int i = 0; i < PAIRS; i++) {
        GSurfPoint sp;
        random_point(&sp, m, s, &seed, i & 1);
        GScratchMark mark = gscratch_mark(s);
        GVec3 g = sp.geometric_normal, out = random_dir(&seed);
        int anywhere = i % 5 == 4, ideal = i % 3 == 0;
        out = anywhere ? out : on_side(out, g, 0);
        for (int j = 0; j < model->nvalues; j++) /* a coloured light, every sample its own (plain samples) */
            w.light.v[j] = (float)(0.05 + 2.0 * tu_uniform(&seed));
        GVec3 in = random_dir(&seed);
        in = anywhere ? in : on_side(in, g, 0);
        in = ideal ? ideal_or(m, &sp, out, NULL, in) : in;
        worst = fmax(worst, compare_pair(m, &sp, in, out, NULL, &w, lit));
        for (int r = 0; r < 3; r++) {
            in = random_dir(&seed);
            in = anywhere ? in : on_side(in, g, 1);
            in = ideal ? ideal_or(m, &sp, out, &w.index[r], in) : in;
            worst = fmax(worst, compare_pair(m, &sp, in, out, &w.index[r], &w, lit));
        }
        gscratch_release(s, mark);
    }
    gcolor_free(&w.white);
    gcolor_free(&w.light);
    gcolor_free(&w.got);
    gcolor_free(&w.want);
    for (int r = 0; r < 3; r++)
        gcolor_free(&w.index[r]);
    return worst;
}

/* The library text of model into text (size n). */
static void library_for(const char *model, char *text, size_t n)
{
    int len = snprintf(text, n, "colormodel %s\n%s%s", model, library_text,
                       strcmp(model, "bispectral") == 0 ? MATRIX_LAMBERT : "");
    assert_true(len > 0 && (size_t)len < n);
}

/* `gmat check FILE NAME`'s diagonal line: its worst figure into *worst; 1 when it says PASS, and *set whether it
 * says the bit is set. */
static int gmat_diagonal(const char *file, const char *name, double *worst, int *set)
{
    const char *build = getenv("GENERIC_BUILD_DIR");
    char gmat[4200], args[4400], out[16384];
    snprintf(gmat, sizeof gmat, "%s/bin/gmat", build ? build : "build");
    snprintf(args, sizeof args, "check '%s' %s", file, name);
    tu_run_capture(gmat, args, out, sizeof out);
    const char *line = strstr(out, "\ndiagonal ");
    if (!line) {
        print_error("no diagonal line from gmat check %s:\n%s\n", name, out);
        fail();
    }
    const char *w = strstr(line, "worst ");
    assert_non_null(w);
    *worst = strtod(w + strlen("worst "), NULL);
    const char *end = strchr(line + 1, '\n');
    size_t len = end ? (size_t)(end - line) : strlen(line);
    char copy[512];
    snprintf(copy, sizeof copy, "%.*s", (int)(len < sizeof copy ? len : sizeof copy - 1), line);
    *set = strstr(copy, "GMAT_DIAGONAL set") != NULL;
    return strstr(copy, " PASS ") != NULL;
}

static void test_bits_and_property(void **state)
{
    const char *model = *state;
    static char text[8192];
    library_for(model, text, sizeof text);
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "diagonal.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    char dir[128], file[256];
    assert_int_equal(tu_tempdir(dir, sizeof dir, "test_material_diagonal"), 0);
    assert_int_equal(tu_write_file(tu_in_dir(dir, "diagonal.mat", file, sizeof file), text), 0);
    GScratch *s = gscratch_create(0);
    int checked_by_gmat = 0;
    for (int i = 0; i < NCASES; i++) {
        if (cases[i].bispectral_only && strcmp(model, "bispectral") != 0)
            continue;
        GMaterial *m = glibrary_material(lib, cases[i].name);
        assert_non_null(m);
        int want = cases[i].bit;
        if (diag(m) != want)
            fail_msg("%s (%s): GMAT_DIAGONAL %d, expected %d", cases[i].name, model, diag(m), want);
        assert_int_equal(gmaterial_diagonal(m), want);
        double gw;
        int set, pass;
        if (!want) { /* gmat check reads the bit alone then: once is enough (a whole check costs 0.1 to 0.8 s) */
            if (strcmp(cases[i].name, "fphong") == 0) {
                pass = gmat_diagonal(file, cases[i].name, &gw, &set);
                print_message("%-10s %-10s GMAT_DIAGONAL 0  gmat check diagonal: %s\n", cases[i].name, model,
                              pass && !set ? "PASS (not set)" : "unexpected");
                assert_true(pass && !set);
            }
            continue;
        }
        /* gmat check under the sanitizers costs seconds a run: there the first flagged case is enough */
        if (TU_SANITIZED && checked_by_gmat++ > 0)
            pass = set = 1, gw = 0.0;
        else
            pass = gmat_diagonal(file, cases[i].name, &gw, &set);
        int lit;
        double worst = worst_relative(m, s, &lit);
        print_message("%-10s %-10s GMAT_DIAGONAL 1  largest relative difference %.3g over %d lit comparisons;"
                      " gmat check diagonal worst %.3g\n",
                      cases[i].name, model, worst, lit, gw);
        assert_true(worst < TOL);
        assert_true(pass && set);
        assert_true(gw < TOL);
        if (strcmp(cases[i].name, "glow") != 0)
            assert_true(lit > 50); /* the comparison saw light passed on (an emitter passes none on) */
    }
    gscratch_destroy(s);
    assert_int_equal(tu_rmtree(dir), 0);
    glibrary_destroy(lib);
}

/* The comparison can fail: a fluorescent material (and a lambert over a re-radiation matrix) in bispectral moves
 * light between samples, far from its pass-on of white times the light. */
static void test_comparison_sees_fluorescence(void **state)
{
    (void)state;
    static char text[8192];
    library_for("bispectral", text, sizeof text);
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(greader_load_string(text, "diagonal.mat", NULL, &lib, &err), G_OK);
    GScratch *s = gscratch_create(0);
    static const char *const names[] = {"fphong", "fvarnish", "lam_m", "interp_f", "interp_m"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        GMaterial *m = glibrary_material(lib, names[i]);
        assert_non_null(m);
        int lit;
        double worst = worst_relative(m, s, &lit);
        print_message("%-10s bispectral GMAT_DIAGONAL 0  largest relative difference %.3g\n", names[i], worst);
        assert_false(diag(m));
        assert_true(worst > 1e-2);
    }
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

static void keep(GMaterial *self) { (void)self; } /* on the stack: nothing to free */

/* NULL (vacuum) passes nothing on and is not diagonal; gmaterial_init never sets the bit (material.h: only the
 * class knows), not even for a class without reflection and refraction slots. */
static void test_vacuum_and_init(void **state)
{
    (void)state;
    assert_false(gmaterial_diagonal(NULL));
    static const GMaterialClass bare = {.abi_version = GMATERIAL_ABI_VERSION, .name = "test-bare",
                                        .description = "no slots", .destroy = keep};
    GColorModel *rgb;
    GError err;
    assert_int_equal(gcolormodel_create("rgb", NULL, &rgb, &err), G_OK);
    GMaterial m;
    assert_int_equal(gmaterial_init(&m, &bare, rgb, &err), G_OK);
    assert_false(diag(&m));
    gcolormodel_destroy(rgb);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        {"test_bits_and_property (rgb)", test_bits_and_property, NULL, NULL, (void *)"rgb"},
        {"test_bits_and_property (spectrum)", test_bits_and_property, NULL, NULL, (void *)"spectrum"},
        {"test_bits_and_property (bispectral)", test_bits_and_property, NULL, NULL, (void *)"bispectral"},
        cmocka_unit_test(test_comparison_sees_fluorescence),
        cmocka_unit_test(test_vacuum_and_init),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
