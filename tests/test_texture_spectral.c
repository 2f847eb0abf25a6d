/* test_texture_spectral.c - spectral OpenEXR textures (kit/texparam.h; the layout of Fichet, Pacanowski and Wilkie
 * 2021, services/image.h): a file whose texels are known spectra (ramps and a line) gives, at every texel centre,
 * gcolor_from_nm of that spectrum in each of the four models; the reflective channels (T.) serve a reflectance and
 * the emissive ones (S0.) a light (either layer serving when the file has only one); halfway between two texel
 * centres the colour is their mean; the image node reads the same file; and broken files are refused naming the
 * file: malformed and duplicated wavelengths, too many channels, NaN and negative values, a header claiming a huge
 * image, a value budget too small. The files are written by the test (tests/exr_writer.h) into a temporary
 * directory. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "generic/builtins.h"
#include "generic/kit/texparam.h"
#include "generic/material.h"
#include "generic/memory.h"
#include "generic/nodes.h"
#include "generic/reader.h"
#include "generic/services/image.h"
#include "exr_writer.h"
#include "reader_fixture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { W = 4, H = 3, NW = 41 }; /* texels, and wavelengths 380, 390, ..., 780 nm */

static char dir[64];

/* The known spectrum of texel (x, y) at nm (380..780): a ramp a + b (nm - 380) / 400 whose coefficients depend on the
 * texel, except texel (1, 1), a line at 550 nm (1 there, falling linearly to 0 at 540 and 560 nm, the file's
 * neighbours). Linear between the file's wavelengths, so the nm spectrum is known exactly. */
static double texel_spectrum(int x, int y, double nm)
{
    if (x == 1 && y == 1)
        return fmax(0.0, 1.0 - fabs(nm - 550.0) / 10.0);
    double a = 0.05 + 0.1 * x + 0.05 * y, b = 0.4 - 0.15 * y + 0.05 * x;
    return a + b * (nm - 380.0) / 400.0;
}

static void texel_nm(int x, int y, GSpectrumNM *s)
{
    for (int i = 0; i < GNM_COUNT; i++)
        s->v[i] = (float)texel_spectrum(x, y, GNM_MIN + i);
}

/* Writes the W x H texels' spectra as channels PREFIX<nm>nm into dir/name; its path in out. */
static void write_spectral(const char *name, const char *prefix, char *out, size_t size)
{
    static char names[NW][32];
    const char *ptr[NW];
    float values[W * H * NW];
    for (int k = 0; k < NW; k++)
        ptr[k] = exr_spectral_name(names[k], sizeof names[k], prefix, 380.0 + 10.0 * k);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int k = 0; k < NW; k++)
                values[(y * W + x) * NW + k] = (float)texel_spectrum(x, y, 380.0 + 10.0 * k);
    snprintf(out, size, "%s/%s", dir, name);
    assert_int_equal(exr_write(out, W, H, NW, ptr, values, 0, 0), 0);
}

/* The largest |got - want| over the values of two colours of one model (vectors or matrices). */
static double largest_difference(const GColor *got, const GColor *want)
{
    assert_int_equal(got->kind, want->kind);
    const int n = got->kind == GCOLOR_MATRIX ? got->model->capacity : got->model->nvalues;
    double d = 0.0;
    for (int i = 0; i < n; i++)
        d = fmax(d, fabs((double)got->v[i] - (double)want->v[i]));
    return d;
}

static const char *const models[] = {"rgb", "spectrum", "spectrum9", "bispectral"};

/* At every texel centre, in each model: the reflectance of `lambert { reflectance image { file T.exr } }` (its
 * diffuse colour) and the light of `emitter { radiance image { file S0.exr } }` (its emission) equal gcolor_from_nm
 * of the texel's spectrum in the role, within 1e-6; the GTexImage opened directly (gtexparam_image_open) gives the
 * same reflectance through gtexparam_image_color. */
static void test_texel_centres_equal_from_nm(void **state)
{
    (void)state;
    char refl[128], emis[128];
    write_spectral("reflective.exr", "T.", refl, sizeof refl);
    write_spectral("emissive.exr", "S0.", emis, sizeof emis);
    for (int mi = 0; mi < 4; mi++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "colormodel %s\n"
                 "material r lambert { reflectance image { file \"%s\" wrap clamp } }\n"
                 "material e emitter { radiance image { file \"%s\" wrap clamp } }\n", models[mi], refl, emis);
        GLibrary *lib = load_ok(text);
        const GColorModel *m = glibrary_colormodel(lib);
        GError err;
        GTexImage *direct = NULL;
        assert_int_equal(gtexparam_image_open(refl, NULL, m, &direct, &err), G_OK);
        GScratch *s = gscratch_create(1 << 16);
        GColor got, want;
        assert_int_equal(gcolor_alloc(&got, m), G_OK);
        assert_int_equal(gcolor_alloc(&want, m), G_OK);
        double worst = 0.0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                GSpectrumNM nm;
                texel_nm(x, y, &nm);
                GSurfPoint *sp = plane_point(m, s, (x + 0.5) / W, 1.0 - (y + 0.5) / H);
                assert_int_equal(gcolor_from_nm(&want, &nm, GCOLOR_REFLECTANCE), G_OK);
                assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "r"), sp, &got), G_OK);
                worst = fmax(worst, largest_difference(&got, &want));
                assert_int_equal(gtexparam_image_color(direct, sp, GCOLOR_REFLECTANCE, &got), G_OK);
                worst = fmax(worst, largest_difference(&got, &want));
                assert_int_equal(gcolor_from_nm(&want, &nm, GCOLOR_LIGHT), G_OK);
                assert_int_equal(gmaterial_emission(glibrary_material(lib, "e"), sp, gvec3(0, 0, 1), &got), G_OK);
                worst = fmax(worst, largest_difference(&got, &want));
                gsurfpoint_free(sp);
            }
        print_message("%s: largest difference at the texel centres %.2e\n", models[mi], worst);
        assert_true(worst <= 1e-6);
        gcolor_free(&got);
        gcolor_free(&want);
        gscratch_destroy(s);
        gtexparam_image_free(direct);
        glibrary_destroy(lib);
    }
}

/* Halfway between the centres of texels (0, 0) and (1, 0) the spectrum is their mean (bilinear), and the image node
 * over a white lambert gives the textured lambert's colour there (both read the reflective channels). */
static void test_bilinear_and_image_node(void **state)
{
    (void)state;
    char refl[128];
    write_spectral("halfway.exr", "T.", refl, sizeof refl);
    char text[1024];
    snprintf(text, sizeof text,
             "colormodel spectrum\n"
             "material r lambert { reflectance image { file \"%s\" } }\n"
             "node n image { child lambert { reflectance rgb 1 1 1 } file \"%s\" }\n", refl, refl);
    GLibrary *lib = load_ok(text);
    const GColorModel *m = glibrary_colormodel(lib);
    GScratch *s = gscratch_create(1 << 16);
    GColor got, node, want;
    assert_int_equal(gcolor_alloc(&got, m), G_OK);
    assert_int_equal(gcolor_alloc(&node, m), G_OK);
    assert_int_equal(gcolor_alloc(&want, m), G_OK);
    GSpectrumNM a, b, mean;
    texel_nm(0, 0, &a);
    texel_nm(1, 0, &b);
    for (int i = 0; i < GNM_COUNT; i++)
        mean.v[i] = 0.5f * (a.v[i] + b.v[i]);
    assert_int_equal(gcolor_from_nm(&want, &mean, GCOLOR_REFLECTANCE), G_OK);
    GSurfPoint *sp = plane_point(m, s, 1.0 / W, 1.0 - 0.5 / H);
    assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "r"), sp, &got), G_OK);
    assert_true(largest_difference(&got, &want) <= 1e-6);
    GSurfPoint *sq = plane_point(m, s, 1.0 / W, 1.0 - 0.5 / H);
    const GMaterial *n = glibrary_material(lib, "n");
    assert_non_null(n);
    assert_int_equal(gmaterial_diffuse(n, sq, &node), G_OK);
    assert_true(largest_difference(&node, &want) <= 1e-6);
    gsurfpoint_free(sp);
    gsurfpoint_free(sq);
    gcolor_free(&got);
    gcolor_free(&node);
    gcolor_free(&want);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* A file with both layers, S0. twice T.: a reflectance reads T., a light S0.; a file with only T. gives its spectra
 * to a light too (values are role free), and one with only S0. to a reflectance. */
static void test_layer_by_role(void **state)
{
    (void)state;
    static char names[2 * NW][32];
    const char *ptr[2 * NW];
    float values[W * H * 2 * NW];
    for (int k = 0; k < NW; k++) { /* sorted by name: S0. before T. */
        ptr[k] = exr_spectral_name(names[k], sizeof names[k], "S0.", 380.0 + 10.0 * k);
        ptr[NW + k] = exr_spectral_name(names[NW + k], sizeof names[NW + k], "T.", 380.0 + 10.0 * k);
    }
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int k = 0; k < NW; k++) {
                double v = texel_spectrum(x, y, 380.0 + 10.0 * k);
                values[(y * W + x) * 2 * NW + k] = (float)(2.0 * v);
                values[(y * W + x) * 2 * NW + NW + k] = (float)v;
            }
    char both[128], refl[128], emis[128];
    snprintf(both, sizeof both, "%s/both.exr", dir);
    assert_int_equal(exr_write(both, W, H, 2 * NW, ptr, values, 0, 0), 0);
    write_spectral("only_t.exr", "T.", refl, sizeof refl);
    write_spectral("only_s0.exr", "S0.", emis, sizeof emis);
    char text[1400];
    snprintf(text, sizeof text,
             "colormodel spectrum\n"
             "material r lambert { reflectance image { file \"%s\" } }\n"
             "material e emitter { radiance image { file \"%s\" } }\n"
             "material et emitter { radiance image { file \"%s\" } }\n"
             "material rs lambert { reflectance image { file \"%s\" } }\n", both, both, refl, emis);
    GLibrary *lib = load_ok(text);
    const GColorModel *m = glibrary_colormodel(lib);
    GScratch *s = gscratch_create(1 << 16);
    GColor got, want;
    assert_int_equal(gcolor_alloc(&got, m), G_OK);
    assert_int_equal(gcolor_alloc(&want, m), G_OK);
    GSpectrumNM nm, twice;
    texel_nm(2, 1, &nm);
    for (int i = 0; i < GNM_COUNT; i++)
        twice.v[i] = 2.0f * nm.v[i];
    GSurfPoint *sp = plane_point(m, s, 2.5 / W, 1.0 - 1.5 / H);
    assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "r"), sp, &got), G_OK);
    assert_int_equal(gcolor_from_nm(&want, &nm, GCOLOR_REFLECTANCE), G_OK);
    assert_true(largest_difference(&got, &want) <= 1e-6);
    assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "rs"), sp, &got), G_OK);
    assert_true(largest_difference(&got, &want) <= 1e-6);
    assert_int_equal(gmaterial_emission(glibrary_material(lib, "e"), sp, gvec3(0, 0, 1), &got), G_OK);
    assert_int_equal(gcolor_from_nm(&want, &twice, GCOLOR_LIGHT), G_OK);
    assert_true(largest_difference(&got, &want) <= 1e-6);
    assert_int_equal(gmaterial_emission(glibrary_material(lib, "et"), sp, gvec3(0, 0, 1), &got), G_OK);
    assert_int_equal(gcolor_from_nm(&want, &nm, GCOLOR_LIGHT), G_OK);
    assert_true(largest_difference(&got, &want) <= 1e-6);
    gsurfpoint_free(sp);
    gcolor_free(&got);
    gcolor_free(&want);
    gscratch_destroy(s);
    glibrary_destroy(lib);
}

/* Writes a 1 x 1 file of the given channels and values, reads it as a reflectance texture, and checks the refusal:
 * G_ERR_IO (or `code`) with a message naming the file and containing want. */
static void refused(const char *name, int n, const char *const *names, const float *values, int hw, int hh,
                    int code, const char *want)
{
    char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    assert_int_equal(exr_write(path, 1, 1, n, names, values, hw, hh), 0);
    char text[512];
    snprintf(text, sizeof text, "colormodel spectrum\nmaterial r lambert { reflectance image { file \"%s\" } }\n",
             path);
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
    if (rc != code || !strstr(err.message, path) || !strstr(err.message, want))
        print_error("%s: status %d, message: %s\n(want %d, '%s')\n", name, rc, err.message, code, want);
    assert_int_equal(rc, code);
    assert_null(lib);
    assert_non_null(strstr(err.message, path));
    assert_non_null(strstr(err.message, want));
    assert_non_null(strstr(err.message, "t.mat:2:")); /* at the file name's position */
}

static void test_hostile_files_refused(void **state)
{
    (void)state;
    const float one[3] = {0.5f, 0.5f, 0.5f};
    const char *bad_name[] = {"T.5x0nm"};
    refused("badname.exr", 1, bad_name, one, 0, 0, G_ERR_IO, "is not a wavelength");
    const char *no_unit[] = {"T.550"};
    refused("nounit.exr", 1, no_unit, one, 0, 0, G_ERR_IO, "is not a wavelength");
    const char *zero[] = {"T.0,000nm"};
    refused("zero.exr", 1, zero, one, 0, 0, G_ERR_IO, "is not a wavelength");
    const char *dup[] = {"T.550,0nm", "T.550nm"};
    refused("duplicate.exr", 2, dup, one, 0, 0, G_ERR_IO, "same wavelength");
    const char *two[] = {"T.450nm", "T.550nm"};
    const float nan_values[2] = {0.5f, NAN};
    refused("nan.exr", 2, two, nan_values, 0, 0, G_ERR_IO, "at 550 nm is nan");
    const float negative[2] = {-0.25f, 0.5f};
    refused("negative.exr", 2, two, negative, 0, 0, G_ERR_IO, "at 450 nm is -0.25");
    const float inf_values[2] = {INFINITY, 0.5f};
    refused("inf.exr", 2, two, inf_values, 0, 0, G_ERR_IO, "must be finite");
    /* a header claiming 100000 x 100000 pixels: refused before any pixel memory (the claim, or the budget) */
    char path[128];
    snprintf(path, sizeof path, "%s/huge.exr", dir);
    assert_int_equal(exr_write(path, 1, 1, 2, two, one, 100000, 100000), 0);
    {
        GImageSpectraBuf buf;
        GError err;
        int rc = gimage_read_spectra_layer(path, GIMAGE_SPECTRA_REFLECTIVE, &buf, &err);
        assert_true(rc == G_ERR_IO || rc == G_ERR_NOMEM);
        assert_non_null(strstr(err.message, path));
        assert_int_equal(buf.count, 0);
        assert_null(buf.values);
    }
    /* more channels than GIMAGE_MAX_WAVELENGTHS */
    enum { MANY = GIMAGE_MAX_WAVELENGTHS + 1 };
    char (*names)[32] = calloc(MANY, 32);
    const char **ptr = calloc(MANY, sizeof *ptr);
    float *values = calloc(MANY, sizeof *values);
    assert_non_null(names);
    assert_non_null(ptr);
    assert_non_null(values);
    for (int k = 0; k < MANY; k++) /* 1000,0000nm .. 1004,0960nm: increasing, sorted by name */
        ptr[k] = exr_spectral_name(names[k], 32, "T.", 1000.0 + 0.001 * k);
    refused("many.exr", MANY, ptr, values, 0, 0, G_ERR_IO, "4097 channels"); /* the header check */
    free(names);
    free(ptr);
    free(values);
}

/* The texels' values are held against the memory budget while the texture lives: a budget too small for them is
 * G_ERR_NOMEM naming the file, and the bytes held return to the budget when the texture is freed. */
static void test_values_charged_to_budget(void **state)
{
    (void)state;
    char refl[128];
    write_spectral("budget.exr", "T.", refl, sizeof refl);
    GError err;
    GColorModel *m = NULL;
    assert_int_equal(gcolormodel_create("spectrum", NULL, &m, &err), G_OK);
    size_t before = gmem_budget_used();
    GTexImage *im = NULL;
    assert_int_equal(gtexparam_image_open(refl, NULL, m, &im, &err), G_OK);
    assert_int_equal(gmem_budget_used() - before, (size_t)W * H * NW * sizeof(float));
    gtexparam_image_free(im);
    assert_int_equal(gmem_budget_used(), before);
    GImageSpectraBuf buf;
    assert_int_equal(gimage_read_spectra_layer(refl, GIMAGE_SPECTRA_REFLECTIVE, &buf, &err), G_OK);
    assert_int_equal(buf.count, NW);
    assert_int_equal(buf.charged, (size_t)W * H * NW * sizeof(float));
    assert_true(buf.wavelengths[0] == 380.0 && buf.wavelengths[NW - 1] == 780.0);
    gimage_spectra_free(&buf);
    assert_int_equal(gimage_read_spectra_layer(refl, GIMAGE_SPECTRA_EMISSIVE, &buf, &err), G_OK);
    assert_int_equal(buf.count, 0); /* no S0. channel */
    gimage_spectra_free(&buf);
    gmem_budget_set_limit((size_t)W * H * 4); /* room for the header's check, not for 41 values a texel */
    int rc = gtexparam_image_open(refl, NULL, m, &im, &err);
    gmem_budget_set_limit(0);
    assert_int_equal(rc, G_ERR_NOMEM);
    assert_non_null(strstr(err.message, refl));
    assert_int_equal(gmem_budget_used(), before);
    gcolormodel_destroy(m);
}

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/gspexrXXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_texel_centres_equal_from_nm),
        cmocka_unit_test(test_bilinear_and_image_node),
        cmocka_unit_test(test_layer_by_role),
        cmocka_unit_test(test_hostile_files_refused),
        cmocka_unit_test(test_values_charged_to_budget),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
