/* test_material_uvflag.c - GMAT_NO_UV (material.h): every built-in leaf material has it; the nodes that read the
 * point only through a generator (interpolate, select, spline, scale) have it over children that have it and a
 * generator not in (u, v) space, transform over such a child too; a node over a (u, v) generator, bump, or a child
 * without the bit has none. A material with the bit gives the same colours, normal and opacity at random points
 * whatever u, v and the tangents hold (what lets a renderer leave them zero), and the checker in (u, v) space,
 * which has no bit, does not: the comparison can fail. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "generic/builtins.h"
#include "generic/materials.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_util.h"

#define GREY(x) "lambert { reflectance rgb " #x " " #x " " #x " }"

/* name, whether it has the bit, its definition */
static const struct {
    const char *name;
    int bit;
    const char *text;
} cases[] = {
    {"lam", 1, "material lam " GREY(0.5)},
    {"mir", 1, "material mir mirror { reflectance rgb 0.9 0.9 0.9 }"},
    {"glass", 1, "material glass dielectric { index 1.5 }"},
    {"ph", 1, "material ph phong { diffuse rgb 0.6 0.3 0.1 specular rgb 0.3 0.3 0.3 exponent 80 }"},
    {"glow", 1, "material glow emitter { radiance rgb 1 1 1 }"},
    {"checker3", 1,
     "material checker3 interpolate { a " GREY(0.8) " b " GREY(0.1) " t checker { dims 3 frequency 3 } }"},
    {"wood", 1,
     "material wood spline { t wood { space object frequency 6 rings 6 turbulence 0.1 } basis linear "
     "colors { 0 rgb 0.75 0.5 0.25  1 rgb 0.4 0.22 0.08 } }"},
    {"faces", 1, "material faces select { index surface children { " GREY(0.2) " " GREY(0.8) " } }"},
    {"fbm", 1, "material fbm scale { child " GREY(0.85) " factor fbm { space object frequency 4 } }"},
    {"moved", 1,
     "material moved transform { child spline { t marble { space object frequency 2 stripes 2 turbulence 1 } "
     "basis linear colors { 0 rgb 0.9 0.9 0.9  1 rgb 0.2 0.2 0.2 } } uv { rotate 30 scale 0.5 } }"},
    {"glassy", 1,
     "material glassy interpolate { a dielectric { index 1.3 } b mirror { } t checker { dims 3 frequency 2 } }"},
    {"checker2", 0,
     "material checker2 interpolate { a " GREY(0.8) " b " GREY(0.1) " t checker { dims 2 frequency 3 } }"},
    {"moved2", 0,
     "material moved2 transform { child interpolate { a " GREY(0.8) " b " GREY(0.1)
     " t checker { dims 2 frequency 4 } } uv { rotate 30 scale 0.5 } }"},
    {"bumped", 0, "material bumped bump { child " GREY(0.6) " height fbm { space object frequency 6 } strength 0.06 }"},
    {"over_uv", 0,
     "material over_uv spline { t wood { space object frequency 6 rings 6 } basis linear children { " GREY(0.3)
     " interpolate { a " GREY(0.8) " b " GREY(0.1) " t checker { dims 2 frequency 3 } } } }"},
};
enum { NCASES = sizeof cases / sizeof *cases };

static unsigned long long seed = 99;
static double uniform(void) { return tu_uniform(&seed); }
static GVec3 random_vec(double s)
{
    return gvec3(s * (2 * uniform() - 1), s * (2 * uniform() - 1), s * (2 * uniform() - 1));
}

/* A point on a plane at p with the parametrisation set at random (with_uv) or zero, as a renderer leaves it. */
static void point_at(GSurfPoint *sp, const GColorModel *m, GScratch *s, const GMaterial *mat, GVec3 p, int below,
                     int with_uv, unsigned long long uv_seed)
{
    gsurfpoint_init(sp, m, s);
    sp->point = sp->object_point = p;
    sp->geometric_normal = gvec3(0, 0, below ? -1 : 1);
    sp->entering = !below;
    sp->material = mat;
    sp->from = below ? mat : NULL;
    sp->to = below ? NULL : mat;
    sp->footprint = 0.01;
    sp->surface = (int)(p.x * 10) & 1;
    if (!with_uv)
        return;
    unsigned long long keep = seed;
    seed = uv_seed;
    sp->u = uniform();
    sp->v = uniform();
    sp->dpdu = random_vec(2.0);
    sp->dpdv = random_vec(2.0);
    sp->object_dpdu = random_vec(1.0);
    sp->object_dpdv = random_vec(1.0);
    sp->uv_footprint = 0.05 * uniform();
    sp->uv_axis1[0] = sp->uv_axis1[1] = 0.03 * uniform();
    sp->uv_axis2[0] = -0.01 * uniform();
    sp->uv_axis2[1] = 0.02 * uniform();
    seed = keep;
}

/* The largest difference, over 200 random points and direction pairs, between the material's reflection,
 * refraction, emission and diffuse colours (and its normal and opacity) with a random parametrisation and with
 * none. */
static double largest_gap(const GColorModel *m, const GMaterial *mat)
{
    GScratch *s = gscratch_create(0);
    double worst = 0.0;
    for (int k = 0; k < 200; k++) {
        GVec3 p = random_vec(3.0), in = gvec3_normalize(random_vec(1.0)), out = gvec3_normalize(random_vec(1.0));
        int below = k & 1;
        in.z = (below ? -1 : 1) * (fabs(in.z) + 0.05);
        out.z = (below ? -1 : 1) * (fabs(out.z) + 0.05);
        unsigned long long uv_seed = seed ^ 0x5bd1e995u;
        GSurfPoint a, z;
        point_at(&a, m, s, mat, p, below, 1, uv_seed);
        point_at(&z, m, s, mat, p, below, 0, uv_seed);
        GScratchMark mark = gscratch_mark(s);
        GColor ca, cz, ri;
        assert_int_equal(gcolor_scratch(&ca, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&cz, m, s), G_OK);
        assert_int_equal(gcolor_scratch(&ri, m, s), G_OK);
        assert_int_equal(gcolor_fill(&ri, below ? 1.3 : 1.0 / 1.3), G_OK);
        for (int method = 0; method < 4; method++) {
            GColor white;
            assert_int_equal(gcolor_scratch(&white, m, s), G_OK);
            assert_int_equal(gcolor_fill(&white, 1.0), G_OK);
            int ra, rz;
            GVec3 o = method == 1 ? gvec3(-out.x, -out.y, -out.z) : out;
            if (method == 0)
                ra = gmaterial_reflection(mat, &a, in, &white, o, &ca),
                rz = gmaterial_reflection(mat, &z, in, &white, o, &cz);
            else if (method == 1)
                ra = gmaterial_refraction(mat, &a, in, &white, &ri, o, &ca),
                rz = gmaterial_refraction(mat, &z, in, &white, &ri, o, &cz);
            else if (method == 2)
                ra = gmaterial_emission(mat, &a, o, &ca), rz = gmaterial_emission(mat, &z, o, &cz);
            else
                ra = gmaterial_diffuse(mat, &a, &ca), rz = gmaterial_diffuse(mat, &z, &cz);
            assert_int_equal(ra, G_OK);
            assert_int_equal(rz, G_OK);
            for (int j = 0; j < m->nvalues; j++)
                worst = fmax(worst, fabs((double)ca.v[j] - (double)cz.v[j]));
        }
        gscratch_release(s, mark);
        worst = fmax(worst, gvec3_length(gvec3_sub(gsurfpoint_normal(&a), gsurfpoint_normal(&z))));
        worst = fmax(worst, gmaterial_opaque(mat, &a) != gmaterial_opaque(mat, &z));
    }
    gscratch_destroy(s);
    return worst;
}

static void test_bits_and_values(void **state)
{
    const char *model = *state;
    char text[8192];
    int at = snprintf(text, sizeof text, "colormodel %s\n", model);
    for (int i = 0; i < NCASES; i++)
        at += snprintf(text + at, sizeof text - (size_t)at, "%s\n", cases[i].text);
    assert_true(at < (int)sizeof text);
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "uv.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    const GColorModel *m = glibrary_colormodel(lib);
    for (int i = 0; i < NCASES; i++) {
        GMaterial *mat = glibrary_material(lib, cases[i].name);
        assert_non_null(mat);
        int bit = (mat->flags & GMAT_NO_UV) != 0;
        if (bit != cases[i].bit)
            fail_msg("%s (%s): GMAT_NO_UV %d, expected %d", cases[i].name, model, bit, cases[i].bit);
        double gap = largest_gap(m, mat);
        print_message("%-9s %-8s GMAT_NO_UV %d  largest gap with and without (u, v): %g\n", cases[i].name, model,
                      bit, gap);
        if (bit)
            assert_true(gap == 0.0); /* exactly the same: nothing read them */
        else
            assert_true(gap > 0.01); /* (u, v) checkers and bump's tangents: the comparison can fail */
    }
    glibrary_destroy(lib);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        {"test_bits_and_values (rgb)", test_bits_and_values, NULL, NULL, (void *)"rgb"},
        {"test_bits_and_values (spectrum)", test_bits_and_values, NULL, NULL, (void *)"spectrum"},
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
