/* test_microfacet_alloc.c - no allocation per ray in the physically based materials: after one warm-up call (which
 * may create the thread's scratch arena), reflection(), sample() and pdf() of the rough conductor (GGX, Beckmann,
 * anisotropic, uncompensated, textured roughness), the rough dielectric, the thin dielectric, the plastic, the layer
 * and the thin film make no call to the allocator, at new points and directions, in every built-in colour model. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "generic/builtins.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "generic/surfpoint.h"
#include "test_alloc.h"
#include "test_util.h"

static const char *const library =
    "material ggx conductor { metal Au roughness 0.3 }\n"
    "material beckmann conductor { metal Cu roughness 0.2 distribution beckmann }\n"
    "material brushed conductor { metal Ag roughness_u 0.05 roughness_v 0.3 }\n"
    "material single conductor { metal Al roughness 0.5 compensate off }\n"
    "material textured conductor { metal Au roughness fbm { frequency 8 octaves 3 range 0.05 0.5 } }\n"
    "material glass dielectric { glass BK7 roughness 0.1 }\n"
    "material pane thindielectric { index 1.5 }\n"
    "material plastic plastic { reflectance rgb 0.6 0.05 0.04 roughness 0.2 }\n"
    "material layer layer { top dielectric { index 1.5 roughness 0.2 }\n"
    "    bottom lambert { reflectance rgb 0.1 0.3 0.6 } }\n"
    "material film thinfilm { thickness 320 index 1.4 base conductor { metal Al roughness 0.1 } }\n";
static const char *const names[] = {"ggx", "beckmann", "brushed", "single", "textured",
                                    "glass", "pane", "plastic", "layer", "film"};
enum { NAMES = sizeof names / sizeof names[0] };

/* Evaluates m n times at points and directions that change with k; the statuses or-ed together. */
static int evaluate(const GMaterial *m, GSurfPoint *sp, const GColor *light, GColor *out, int k0, int n, double *sum)
{
    int rc = G_OK;
    for (int k = k0; k < k0 + n; k++) {
        double t = 0.37 * k, c = 0.1 + 0.85 * fmod(0.618 * k, 1.0), s = sqrt(1.0 - c * c);
        GVec3 in = gvec3(s * cos(t), s * sin(t), c), out_dir = gvec3_normalize(gvec3(-0.3 + 0.01 * (k % 50), 0.2, 1.0));
        sp->u = fmod(0.013 * k, 1.0);
        sp->v = fmod(0.029 * k, 1.0);
        sp->point = sp->object_point = gvec3(sp->u, sp->v, 0.0);
        gsurfpoint_invalidate(sp);
        rc |= gmaterial_reflection(m, sp, in, light, out_dir, out);
        *sum += gcolor_brightness(out);
        GMaterialSample smp;
        int drawn = gmaterial_sample(m, sp, out_dir, NULL, fmod(0.754 * k, 1.0), fmod(0.291 * k, 1.0), &smp, out);
        if (drawn < 0)
            rc |= drawn;
        else if (drawn)
            *sum += gcolor_brightness(out);
        double pdf = gmaterial_pdf(m, sp, in, out_dir, NULL);
        if (!(pdf >= 0.0))
            rc |= G_ERR_INVALID;
    }
    return rc;
}

static void zero_alloc_case(const char *model_name)
{
    GError err;
    GColorModel *md;
    assert_int_equal(gcolormodel_create(model_name, NULL, &md, &err), G_OK);
    GReaderOptions ro = {.model = md};
    GLibrary *lib;
    if (greader_load_string(library, "alloc.mat", &ro, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    GScratch *s = gscratch_create(1 << 16);
    assert_non_null(s);
    GSurfPoint *sp = gsurfpoint_new(md, s, gvec3(0, 0, 0), gvec3(0, 0, 1), gvec3(1, 0, 0), gvec3(0, 1, 0), 0.0, 0.0, 0,
                                    &err);
    assert_non_null(sp);
    GColor light, out;
    assert_int_equal(gcolor_alloc(&light, md), G_OK);
    assert_int_equal(gcolor_alloc(&out, md), G_OK);
    assert_int_equal(gcolor_fill(&light, 1.0), G_OK);
    int rounds = TU_SANITIZED ? 40 : 400;
    for (int i = 0; i < NAMES; i++) {
        const GMaterial *m = glibrary_material(lib, names[i]);
        assert_non_null(m);
        sp->material = m;
        sp->from = NULL; /* light arrives from vacuum onto the material */
        sp->to = m;
        double sum = 0.0;
        assert_int_equal(evaluate(m, sp, &light, &out, 0, 1, &sum), G_OK); /* warm-up: the thread's arena */
        static TuAlloc counter;
        counter = (TuAlloc){0};
        tu_alloc_install(&counter);
        int rc = evaluate(m, sp, &light, &out, 1, rounds, &sum);
        gmem_set_allocator(NULL);
        print_message("%s %s: %d rounds of reflection, sample and pdf: %ld allocations (sum %g)\n", model_name,
                      names[i], rounds, counter.calls, sum);
        assert_int_equal(rc, G_OK);
        assert_int_equal(counter.calls, 0);
        assert_true(sum > 1.0 && isfinite(sum)); /* the calls did reflect light */
    }
    gcolor_free(&light);
    gcolor_free(&out);
    gsurfpoint_free(sp);
    gscratch_destroy(s);
    glibrary_destroy(lib);
    gcolormodel_destroy(md);
}

static void test_zero_alloc(void **state) { zero_alloc_case(*state); }

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_prestate(test_zero_alloc, (void *)"rgb"),
        cmocka_unit_test_prestate(test_zero_alloc, (void *)"spectrum9"),
        cmocka_unit_test_prestate(test_zero_alloc, (void *)"spectrum"),
        cmocka_unit_test_prestate(test_zero_alloc, (void *)"bispectral"),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
