/* test_regress.c - replays every input kept in tests/regress/<target>/ (each a crasher or a broken promise the
 * fuzzers found, fixed since) and the small seed corpus tests/fuzz/corpus/<target>/ through the same entry points
 * as the libFuzzer targets (tests/fuzz/fuzz_entry.h): every input must end in a clean result or a clean error,
 * never a crash; under `make test SANITIZE=1` AddressSanitizer also checks for leaks and memory errors. Also
 * the regressions found while writing the robustness tests that are not single inputs. The scene target's inputs
 * too: this test links gtrace (examples/gtrace/build.mk). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz/fuzz_entry.h"
#include "fuzz/fuzz_scene_entry.h"
#include "generic/builtins.h"
#include "generic/materials.h"
#include "generic/plugin.h"

typedef int (*Entry)(const uint8_t *data, size_t size);

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* Runs every regular file of SOURCE/dir through entry (in name order); returns how many were run. */
static int replay_dir(const char *dir, Entry entry)
{
    const char *src = getenv("GENERIC_SOURCE_DIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", src ? src : ".", dir);
    DIR *d = opendir(path);
    if (!d)
        return 0;
    char *names[1024];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 1024)
        if (e->d_name[0] != '.')
            names[n++] = strdup(e->d_name);
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, by_name);
    int run = 0, bad = 0;
    for (int i = 0; i < n; i++) {
        char file[8192];
        snprintf(file, sizeof file, "%s/%s", path, names[i]);
        struct stat st;
        FILE *f = stat(file, &st) == 0 && S_ISREG(st.st_mode) ? fopen(file, "rb") : NULL;
        if (f) {
            size_t size = (size_t)st.st_size;
            uint8_t *data = malloc(size ? size : 1);
            assert_non_null(data);
            assert_int_equal(fread(data, 1, size, f), size);
            fclose(f);
            if (entry(data, size) != 0) {
                print_error("%s/%s: %s\n", dir, names[i], gfuzz_why);
                bad++;
            }
            free(data);
            run++;
        }
        free(names[i]);
    }
    assert_int_equal(bad, 0);
    return run;
}

static int setup(void **state)
{
    (void)state;
    return gfuzz_setup();
}

static int teardown(void **state)
{
    (void)state;
    gfuzz_cleanup();
    return 0;
}

static void replay(const char *target, Entry entry, int min_regress)
{
    char dir[256];
    snprintf(dir, sizeof dir, "tests/regress/%s", target);
    int regress = replay_dir(dir, entry);
    snprintf(dir, sizeof dir, "tests/fuzz/corpus/%s", target);
    int seeds = replay_dir(dir, entry);
    print_message("%s: %d regression inputs, %d seeds\n", target, regress, seeds);
    assert_true(regress >= min_regress);
    assert_true(seeds > 0);
}

static void test_reader(void **state)
{
    (void)state;
    replay("reader", gfuzz_reader, 0);
}

static void test_bfc(void **state)
{
    (void)state;
    replay("bfc", gfuzz_bfc, 1);
}

static void test_probe(void **state)
{
    (void)state;
    replay("probe", gfuzz_probe, 1);
}

static void test_image(void **state)
{
    (void)state;
    replay("image", gfuzz_image, 1);
}

static void test_scene(void **state)
{
    (void)state;
    replay("scene", gfuzz_scene, 1);
}

/* The promises the entry points check do fail on broken values (so the replay above cannot pass vacuously). */
static void test_checks_catch(void **state)
{
    (void)state;
    GColorModel *m = gfuzz_models[0];
    GColor c = {0};
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    assert_int_equal(gfuzz_color_ok(&c, "black"), 0);
    c.v[1] = NAN;
    assert_int_equal(gfuzz_color_ok(&c, "nan"), -1);
    assert_non_null(strstr(gfuzz_why, "nan is not finite"));
    c.v[1] = INFINITY;
    assert_int_equal(gfuzz_color_ok(&c, "inf"), -1);
    gcolor_free(&c);
    GError err;
    gerror_clear(&err);
    assert_int_equal(gfuzz_error_ok(G_ERR_PARSE, &err, "x"), -1); /* an error without a message */
    gerror_set(&err, G_ERR_PARSE, "x.mat:1:1: broken");
    assert_int_equal(gfuzz_error_ok(G_ERR_PARSE, &err, "x"), 0);
    assert_int_equal(gfuzz_error_ok(G_ERR_IO, &err, "x"), -1); /* status and record disagree */
    /* a path is never followed: an input naming a file outside the private directory is skipped */
    static const char outside[] = "include \"/etc/passwd\"";
    assert_int_equal(gfuzz_reader((const uint8_t *)outside, sizeof outside - 1), 0);
    /* and plug-ins are refused without loading anything */
    static const char plugin[] = "plugin \"grey.so\"";
    int before = gplugin_count();
    assert_int_equal(gfuzz_reader((const uint8_t *)plugin, sizeof plugin - 1), 0);
    assert_int_equal(gplugin_count(), before);
}

/* Found while writing the out-of-memory test: white (rgb 1 1 1) and kd + ks = 1 were refused in every spectral
 * model, because the RGB-to-spectrum round trip overshoots 1 by 1.5e-4 there. They load in every model, and
 * the reflectance stays <= 1: a white Lambertian surface at normal incidence reflects 1/pi of D65 at most. */
static void test_white_in_every_model(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        double step;
    } models[] = {{"rgb", 0}, {"spectrum", 1}, {"spectrum", 5}, {"spectrum", 20}, {"spectrum9", 0}, {"bispectral", 0}};
    const char *text = "material white lambert { reflectance rgb 1 1 1 }\n"
                       "material split phong { diffuse rgb 0.5 0.5 0.5 specular rgb 0.5 0.5 0.5 }\n"
                       "material clear dielectric { tint rgb 1 1 1 }\n";
    for (size_t k = 0; k < sizeof models / sizeof models[0]; k++) {
        GColorModelOptions o = {.step_nm = models[k].step};
        GColorModel *m = NULL;
        GError err;
        assert_int_equal(gcolormodel_create(models[k].name, &o, &m, &err), G_OK);
        GReaderOptions opt = {.model = m};
        GLibrary *lib = NULL;
        int rc = greader_load_string(text, "white.mat", &opt, &lib, &err);
        if (rc != G_OK)
            print_error("%s %g: %s\n", models[k].name, models[k].step, err.message);
        assert_int_equal(rc, G_OK);
        GScratch *s = gscratch_create(0);
        GColor light = {0}, out = {0};
        assert_int_equal(gcolor_alloc(&light, m), G_OK);
        assert_int_equal(gcolor_alloc(&out, m), G_OK);
        static const double one[3] = {1, 1, 1};
        assert_int_equal(gcolor_from_rgb(&light, one, GCOLOR_LIGHT), G_OK);
        GSurfPoint sp;
        gsurfpoint_init(&sp, m, s);
        sp.geometric_normal = gvec3(0, 0, 1);
        sp.entering = 1;
        GMaterial *white = glibrary_material(lib, "white");
        sp.material = white;
        assert_int_equal(gmaterial_reflection(white, &sp, gvec3(0, 0, 1), &light, gvec3(0.6, 0, 0.8), &out), G_OK);
        double worst = 0.0;
        for (int i = 0; i < m->nvalues; i++)
            if (light.v[i] > 0)
                worst = fmax(worst, out.v[i] / light.v[i] * M_PI);
        assert_true(worst <= 1.0 + 1e-6);
        assert_true(worst >= 0.999);
        double rgb[3];
        assert_int_equal(gcolor_to_rgb(&out, GCOLOR_LIGHT, rgb), G_OK);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(rgb[i] * M_PI - 1.0) < 2e-3);
        gcolor_free(&light);
        gcolor_free(&out);
        gscratch_destroy(s);
        glibrary_destroy(lib);
        gcolormodel_destroy(m);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reader),
        cmocka_unit_test(test_bfc),
        cmocka_unit_test(test_probe),
        cmocka_unit_test(test_image),
        cmocka_unit_test(test_scene),
        cmocka_unit_test(test_checks_catch),
        cmocka_unit_test(test_white_in_every_model),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
