/* test_builtin_modules.c - a built-in type's file is all of the type: materials/lambert.c and colormodels/rgb.c,
 * each compiled unchanged plus the line `GENERIC_MODULE(&gtype_NAME);` into BUILD/modules/NAME.so (tests/build.mk,
 * "built-in files as run-time modules"), are loaded into a registry that holds every other built-in but not those
 * two. The registered types are the modules' (their own vtables, not the built-in records'), a material file
 * reads with them, and the module lambert in the module rgb model gives bit for bit the results of the built-in
 * lambert in the built-in rgb model, made straight from the built-in records, over many directions. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/kit/material_kit.h"
#include "generic/plugin.h"
#include "generic/reader.h"

static char moddir[4096];

/* The built-in record of a kind and name (names come from the vtable when the record leaves them NULL). */
static const GTypeInfo *builtin(GKind kind, const char *name)
{
    for (const GTypeInfo *const *t = generic_builtin_types(); *t; t++) {
        GTypeInfo c = **t;
        if (c.kind == kind && gtypeinfo_complete(&c, NULL) == G_OK && strcmp(c.name, name) == 0)
            return *t;
    }
    return NULL;
}

static int is_replaced(const GTypeInfo *t)
{
    return t == builtin(GKIND_MATERIAL, "lambert") || t == builtin(GKIND_COLORMODEL, "rgb");
}

/* Every built-in but lambert and rgb, then the two modules. */
static int setup(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    snprintf(moddir, sizeof moddir, "%s/modules", build ? build : "build");
    GError err;
    for (const GTypeInfo *const *t = generic_builtin_types(); *t; t++)
        if (!is_replaced(*t) && gregistry_add(*t, &err) != G_OK) {
            fprintf(stderr, "%s\n", err.message);
            return -1;
        }
    return 0;
}

static void load_module(const char *name)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", moddir, name);
    if (access(path, R_OK) != 0) { /* `make all` builds them: a missing module is a failure */
        print_error("%s is not built (run the test through scripts/run_tests.sh after make all)\n", path);
        fail();
    }
    GError err;
    int rc = gplugin_load(path, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
}

static void test_modules_replace_the_builtins(void **state)
{
    (void)state;
    const GTypeInfo *lambert_rec = builtin(GKIND_MATERIAL, "lambert"), *rgb_rec = builtin(GKIND_COLORMODEL, "rgb");
    assert_non_null(lambert_rec);
    assert_non_null(rgb_rec);
    /* the registry lacks both, and has the others */
    assert_null(gregistry_find(GKIND_MATERIAL, "lambert"));
    assert_null(gregistry_find(GKIND_COLORMODEL, "rgb"));
    assert_non_null(gregistry_find(GKIND_MATERIAL, "phong"));
    assert_non_null(gregistry_find(GKIND_COLORMODEL, "spectrum"));

    load_module("rgb.so");
    load_module("lambert.so");
    const GTypeInfo *lambert = gregistry_find(GKIND_MATERIAL, "lambert"),
                    *rgb = gregistry_find(GKIND_COLORMODEL, "rgb");
    assert_non_null(lambert);
    assert_non_null(rgb);
    /* the modules' own records: vtables and parse routine of the .so, not of the program */
    assert_ptr_not_equal(lambert->vtable, lambert_rec->vtable);
    assert_ptr_not_equal(lambert->parse, lambert_rec->parse);
    assert_ptr_not_equal(rgb->vtable, rgb_rec->vtable);
    assert_string_equal(((const GMaterialClass *)lambert->vtable)->name, "lambert");
    assert_string_equal(((const GColorModelClass *)rgb->vtable)->name, "rgb");
    /* the same keyword and summary, taken from the class both times */
    assert_string_equal(lambert->summary, ((const GMaterialClass *)lambert_rec->vtable)->description);
}

/* Module types read from text against the built-in ones made from their records, compared bit for bit. */
static void test_same_results_bit_for_bit(void **state)
{
    (void)state;
    const GTypeInfo *lambert = gregistry_find(GKIND_MATERIAL, "lambert");
    if (!lambert || lambert->vtable == builtin(GKIND_MATERIAL, "lambert")->vtable) {
        print_error("the lambert module is not loaded\n");
        fail();
    }
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string("material clay lambert { reflectance rgb 0.62 0.41 0.27 }\n"
                                 "material chalk lambert\n",
                                 "modules.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    const GColorModel *mm = glibrary_colormodel(lib);
    assert_ptr_equal(mm->cls, gregistry_find(GKIND_COLORMODEL, "rgb")->vtable);

    /* the built-ins, from their records: the rgb class, the lambert class over a GMaterialOneColor */
    GColorModel *bm = NULL;
    assert_int_equal(gcolormodel_create_class(builtin(GKIND_COLORMODEL, "rgb")->vtable, NULL, &bm, &err), G_OK);
    const GMaterialClass *bcls = builtin(GKIND_MATERIAL, "lambert")->vtable;
    static const double rho[2][3] = {{0.62, 0.41, 0.27}, {0.8, 0.8, 0.8}}; /* the second: lambert's default */
    static const char *const names[2] = {"clay", "chalk"};

    float bv[9], mv[9], biv[9], miv[9], bov[9], mov[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor bc, mc, bill, mill, bout, mout;
    assert_int_equal(gcolor_wrap(&bc, bm, bv, 9), G_OK);
    assert_int_equal(gcolor_wrap(&mc, mm, mv, 9), G_OK);
    assert_int_equal(gcolor_wrap(&bill, bm, biv, 9), G_OK);
    assert_int_equal(gcolor_wrap(&mill, mm, miv, 9), G_OK);
    assert_int_equal(gcolor_wrap(&bout, bm, bov, 9), G_OK);
    assert_int_equal(gcolor_wrap(&mout, mm, mov, 9), G_OK);
    GScratch *bs = gscratch_create(0), *ms = gscratch_create(0);
    long compared = 0;
    for (int k = 0; k < 2; k++) {
        GMaterial *mmat = glibrary_material(lib, names[k]), *bmat = NULL;
        assert_non_null(mmat);
        assert_ptr_equal(mmat->cls, lambert->vtable);
        assert_int_equal(gcolor_from_rgb(&bc, rho[k], GCOLOR_REFLECTANCE), G_OK);
        assert_int_equal(gmaterial_one_color_create(bcls, bm, sizeof(GMaterialOneColor), &bc, GCOLOR_REFLECTANCE, 1.0,
                                               "reflectance", &bmat, &err),
                         G_OK);
        assert_ptr_equal(bmat->cls, bcls);
        GSurfPoint bsp, msp;
        gsurfpoint_init(&bsp, bm, bs);
        gsurfpoint_init(&msp, mm, ms);
        bsp.geometric_normal = msp.geometric_normal = gvec3(0, 0, 1);
        bsp.material = bmat;
        msp.material = mmat;

        assert_int_equal(gmaterial_diffuse(bmat, &bsp, &bout), G_OK);
        assert_int_equal(gmaterial_diffuse(mmat, &msp, &mout), G_OK);
        assert_memory_equal(bov, mov, 3 * sizeof *bov); /* the three components */
        for (int c = 0; c < 3; c++) /* and it is the file's reflectance */
            assert_float_equal(mov[c], (float)rho[k][c], 0.0);
        /* 24 x 12 incident and outgoing directions over the sphere (some below the surface), three lights */
        for (int l = 0; l < 3; l++) {
            double light[3] = {1.0 + l, 0.5 + 0.25 * l, 3.0 - l};
            assert_int_equal(gcolor_from_rgb(&bill, light, GCOLOR_LIGHT), G_OK);
            assert_int_equal(gcolor_from_rgb(&mill, light, GCOLOR_LIGHT), G_OK);
            assert_int_equal(gmaterial_ambient(bmat, &bsp, &bill, &bout), G_OK);
            assert_int_equal(gmaterial_ambient(mmat, &msp, &mill, &mout), G_OK);
            assert_memory_equal(bov, mov, 3 * sizeof *bov); /* the three components */
            for (int i = 0; i < 24 * 12; i++)
                for (int o = 0; o < 24 * 12; o += 7) {
                    double ti = (i / 24 + 0.5) * M_PI / 12, pi = (i % 24) * 2 * M_PI / 24;
                    double to = (o / 24 + 0.5) * M_PI / 12, po = (o % 24) * 2 * M_PI / 24;
                    GVec3 in = gvec3(sin(ti) * cos(pi), sin(ti) * sin(pi), cos(ti));
                    GVec3 out = gvec3(sin(to) * cos(po), sin(to) * sin(po), cos(to));
                    assert_int_equal(gmaterial_reflection(bmat, &bsp, in, &bill, out, &bout), G_OK);
                    assert_int_equal(gmaterial_reflection(mmat, &msp, in, &mill, out, &mout), G_OK);
                    assert_memory_equal(bov, mov, 3 * sizeof *bov); /* the three components */
                    if (cos(ti) > 0 && cos(to) > 0) /* rho / pi cos(theta_in) illum */
                        assert_float_equal(mov[1], (float)(rho[k][1] / M_PI * cos(ti) * light[1]), 1e-6);
                    compared++;
                }
        }
        gmaterial_unref(bmat);
    }
    assert_int_equal(compared, 2 * 3 * 24 * 12 * ((24 * 12 + 6) / 7));
    gscratch_destroy(bs);
    gscratch_destroy(ms);
    glibrary_destroy(lib);
    gcolormodel_destroy(bm);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_modules_replace_the_builtins),
        cmocka_unit_test(test_same_results_bit_for_bit),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
