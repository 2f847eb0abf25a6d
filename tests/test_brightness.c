/* test_brightness.c - one brightness in every model (color.h: Y of the value as a reflectance under D65): the same
 * reflectance has the same brightness in rgb, spectrum9, spectrum and bispectral within 1e-3, a model without a
 * brightness slot gets the same from its conversion, constants and black keep their meaning, and lights stay
 * within the bounds color.h states of their Y as a light. The brightness of a light (gcolor_brightness_as with
 * GCOLOR_LIGHT) is its Y as a light in every model within 1e-3 (relative), and so is a reflectance's over random
 * colours of the cube. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "generic/builtins.h"
#include "generic/color.h"
#include "test_util.h"

static const char *const models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
enum { NMODELS = 4, STEPS = 5 };

static GColorModel *make(const char *name)
{
    GColorModel *m = NULL;
    GError err;
    assert_int_equal(gcolormodel_create(name, NULL, &m, &err), G_OK);
    return m;
}

static double brightness_of(const GColorModel *m, const double rgb[3], GColorRole role)
{
    float buf[4096];
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, buf, 4096), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, role), G_OK);
    return gcolor_brightness(&c);
}

/* The example, reflectance 0.8 0.1 0.1 (Y 0.2489), and a 5^3 grid of the cube: equal within 1e-3. */
static void test_same_reflectance_same_brightness(void **state)
{
    (void)state;
    GColorModel *m[NMODELS];
    for (int i = 0; i < NMODELS; i++)
        m[i] = make(models[i]);
    double red[3] = {0.8, 0.1, 0.1}, xyz[3];
    gcie_rgb_to_xyz(red, xyz);
    for (int i = 0; i < NMODELS; i++)
        assert_near(brightness_of(m[i], red, GCOLOR_REFLECTANCE), xyz[1], 1e-3);
    double worst = 0.0;
    for (int a = 0; a < STEPS; a++)
        for (int b = 0; b < STEPS; b++)
            for (int c = 0; c < STEPS; c++) {
                double rgb[3] = {a / (STEPS - 1.0), b / (STEPS - 1.0), c / (STEPS - 1.0)};
                double y = brightness_of(m[0], rgb, GCOLOR_REFLECTANCE);
                for (int i = 1; i < NMODELS; i++)
                    worst = fmax(worst, fabs(brightness_of(m[i], rgb, GCOLOR_REFLECTANCE) - y));
            }
    print_message("reflectances of the 5^3 grid: largest difference from rgb's brightness %.2e\n", worst);
    assert_true(worst <= 1e-3);
    for (int i = 0; i < NMODELS; i++) {
        float buf[4096];
        GColor c;
        assert_int_equal(gcolor_wrap(&c, m[i], buf, 4096), G_OK);
        assert_near(gcolor_brightness(&c), 0.0, 0.0);
        assert_int_equal(gcolor_fill(&c, 0.37), G_OK);
        assert_near(gcolor_brightness(&c), 0.37, 1e-6);
        gcolormodel_destroy(m[i]);
    }
}

/* Lights: the brightness of a light of the cube against its Y as a light (equal-energy white 1): D65 weighs a
 * light's samples twice, so the spectral models' brightness of a saturated light is up to 11% off its Y (a blue
 * light), the white light's within 1%. */
static void test_lights_bounded(void **state)
{
    (void)state;
    for (int i = 0; i < NMODELS; i++) {
        GColorModel *m = make(models[i]);
        double worst = 0.0;
        for (int a = 0; a < STEPS; a++)
            for (int b = 0; b < STEPS; b++)
                for (int c = 0; c < STEPS; c++) {
                    double rgb[3] = {a / (STEPS - 1.0), b / (STEPS - 1.0), c / (STEPS - 1.0)}, xyz[3];
                    if (a + b + c == 0)
                        continue;
                    gcie_rgb_to_xyz(rgb, xyz);
                    worst = fmax(worst, fabs(brightness_of(m, rgb, GCOLOR_LIGHT) / xyz[1] - 1.0));
                }
        double white[3] = {1, 1, 1}, w = brightness_of(m, white, GCOLOR_LIGHT);
        print_message("%s: lights of the 5^3 grid, brightness / Y within %.4f of 1; white light %.5f\n", models[i],
                      worst, w);
        assert_true(worst <= 0.11);
        assert_near(w, 1.0, 0.01);
        gcolormodel_destroy(m);
    }
}

/* A generated colour: components uniform in [0, scale) (a 64-bit LCG, the same sequence on every run). */
static void random_rgb(unsigned long long *seed, double scale, double rgb[3])
{
    for (int k = 0; k < 3; k++) {
        *seed = *seed * 6364136223846793005ULL + 1442695040888963407ULL;
        rgb[k] = scale * (double)(*seed >> 11) / 9007199254740992.0;
    }
}

static double brightness_as(const GColorModel *m, const double rgb[3], GColorRole role)
{
    float buf[4096];
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, buf, 4096), G_OK);
    assert_int_equal(gcolor_from_rgb(&c, rgb, role), G_OK);
    return gcolor_brightness_as(&c, role);
}

/* 1000 generated lights (components up to 4, saturated ones included) and reflectances of the cube: every model's
 * brightness of the same colour read in its role within 1e-3 of the colour's Y (relative for lights). */
static void test_generated_colours(void **state)
{
    (void)state;
    GColorModel *m[NMODELS];
    for (int i = 0; i < NMODELS; i++)
        m[i] = make(models[i]);
    unsigned long long seed = 20240605ULL;
    double worst_light[NMODELS] = {0}, worst_refl[NMODELS] = {0};
    for (int n = 0; n < 1000; n++) {
        double light[3], refl[3], xyz[3];
        random_rgb(&seed, 4.0, light);
        if (n % 4 == 0) /* a saturated light: one or two components 0 */
            light[n / 4 % 3] = 0.0;
        random_rgb(&seed, 1.0, refl);
        gcie_rgb_to_xyz(light, xyz);
        double y_light = xyz[1];
        gcie_rgb_to_xyz(refl, xyz);
        double y_refl = xyz[1];
        for (int i = 0; i < NMODELS; i++) {
            worst_light[i] = fmax(worst_light[i], fabs(brightness_as(m[i], light, GCOLOR_LIGHT) / y_light - 1.0));
            worst_refl[i] = fmax(worst_refl[i], fabs(brightness_as(m[i], refl, GCOLOR_REFLECTANCE) - y_refl));
        }
    }
    for (int i = 0; i < NMODELS; i++) {
        print_message("%-10s 1000 generated colours: light |brightness / Y - 1| <= %.2e, reflectance "
                      "|brightness - Y| <= %.2e\n", models[i], worst_light[i], worst_refl[i]);
        assert_true(worst_light[i] <= 1e-3);
        assert_true(worst_refl[i] <= 1e-3);
    }
    /* black is 0, and a light the eye does not see is not */
    float buf[4096];
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m[2], buf, 4096), G_OK);
    assert_true(gcolor_brightness_as(&c, GCOLOR_LIGHT) == 0.0);
    c.v[m[2]->nvalues - 1] = -2.0f; /* 780 nm, negative: by magnitude */
    assert_true(gcolor_brightness_as(&c, GCOLOR_LIGHT) > 0.0);
    for (int i = 0; i < NMODELS; i++)
        gcolormodel_destroy(m[i]);
}

/* A model without a brightness slot: Y of its conversion, the same as the built-in's within 1e-3. */
static void test_default_brightness(void **state)
{
    (void)state;
    GColorModel *s = make("spectrum");
    GColorModelClass cls = *s->cls;
    cls.name = "spectrum-without-brightness";
    cls.brightness = NULL;
    GColorModel *d = NULL;
    GError err;
    assert_int_equal(gcolormodel_create_class(&cls, NULL, &d, &err), G_OK);
    double rgb[3] = {0.2, 0.6, 0.9};
    assert_near(brightness_of(d, rgb, GCOLOR_REFLECTANCE), brightness_of(s, rgb, GCOLOR_REFLECTANCE), 1e-3);
    float buf[4096];
    GColor c;
    assert_int_equal(gcolor_wrap(&c, d, buf, 4096), G_OK);
    assert_near(gcolor_brightness(&c), 0.0, 0.0);
    c.v[0] = 1.0f; /* 380 nm only: Y 0, yet not black */
    assert_true(gcolor_brightness(&c) > 0.0);
    gcolormodel_destroy(d);
    gcolormodel_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_reflectance_same_brightness),
        cmocka_unit_test(test_lights_bounded),
        cmocka_unit_test(test_generated_colours),
        cmocka_unit_test(test_default_brightness),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
