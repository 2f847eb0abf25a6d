/* test_plugin.c - run-time modules: the example modules of examples/plugins/ (built by `make all` against the
 * installed headers into BUILD/plugins/) are loaded from a text file and used without rebuilding the library:
 * the "grey" colour model, the Oren-Nayar material (checked against its formula) and the "bands" generator.
 * Broken modules are refused with their reason: another interface version (both versions named), a failing
 * init (nothing stays registered), no entry point, not a shared object, a missing file. */
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
#include "generic/plugin.h"
#include "generic/reader.h"
#include "generic/texture.h"
#include "module/plugin_elf.h"

#include <fcntl.h>
#include <sys/stat.h>

#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __LINE__)
static void near_(double a, double b, double tol, const char *what, int line)
{
    if (!(fabs(a - b) <= tol)) {
        print_error("line %d: %s = %.10g, expected %.10g within %g\n", line, what, a, b, tol);
        fail();
    }
}

static char plugdir[4096];

static const char *plugin(const char *name)
{
    static char buf[4][4200];
    static int next;
    char *b = buf[next++ & 3];
    snprintf(b, sizeof buf[0], "%s/%s", plugdir, name);
    return b;
}

static int setup(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    snprintf(plugdir, sizeof plugdir, "%s/plugins", build ? build : "build");
    return 0;
}

static void require(const char *name)
{
    if (access(plugin(name), R_OK) != 0) { /* `make all` builds them: a missing module is a failure */
        print_error("%s is not built (run the test through scripts/run_tests.sh after make all)\n", plugin(name));
        fail();
    }
}

/* A scene file next to the modules, naming them by relative path. */
static void test_load_from_text_and_use(void **state)
{
    (void)state;
    require("oren_nayar.so");
    require("grey.so");
    require("bands.so");
    char path[4200];
    snprintf(path, sizeof path, "%s/test_plugin.mat", plugdir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("plugin \"grey.so\"\n"
          "plugin \"oren_nayar.so\"\n"
          "plugin \"bands.so\"\n"
          "colormodel grey\n"
          "material smooth oren_nayar { reflectance rgb 0.5 0.5 0.5 sigma 0 }\n"
          "material rough oren_nayar { reflectance rgb 0.5 0.5 0.5 sigma 30 }\n"
          "generator stripes bands { period 2 axis <0, 0, 3> }\n",
          f);
    fclose(f);
    GLibrary *lib = NULL;
    GError err;
    GReaderOptions allow = {.allow_plugins = 1};
    int rc = greader_load_file(path, &allow, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    assert_true(gplugin_count() >= 3);
    const GColorModel *m = glibrary_colormodel(lib);
    assert_string_equal(gcolormodel_name(m), "grey");
    assert_int_equal(m->nvalues, 1);

    GScratch *s = gscratch_create(0);
    GSurfPoint sp;
    gsurfpoint_init(&sp, m, s);
    sp.geometric_normal = gvec3(0, 0, 1);
    float iv[1], ov[1];
    GColor illum, out;
    assert_int_equal(gcolor_wrap(&illum, m, iv, sizeof iv / sizeof iv[0]), G_OK);
    assert_int_equal(gcolor_wrap(&out, m, ov, sizeof ov / sizeof ov[0]), G_OK);
    iv[0] = 1.0f;
    GMaterial *smooth = glibrary_material(lib, "smooth"), *rough = glibrary_material(lib, "rough");
    assert_non_null(smooth);
    assert_string_equal(gmaterial_name(smooth), "oren_nayar");
    /* sigma 0 is Lambert: rho / pi * cos(theta_in) */
    double ti = 40 * M_PI / 180, to = 60 * M_PI / 180;
    GVec3 in = gvec3(sin(ti), 0, cos(ti)), out_back = gvec3(-sin(to), 0, cos(to)),
          out_retro = gvec3(sin(to), 0, cos(to));
    sp.material = smooth;
    assert_int_equal(gmaterial_reflection(smooth, &sp, in, &illum, out_back, &out), G_OK);
    assert_near(ov[0], 0.5 / M_PI * cos(ti), 1e-6);
    /* sigma 30 degrees: the formula, in the retro-reflecting half (cos dphi = 1) and the forward half (0) */
    double s2 = pow(30 * M_PI / 180, 2), A = 1 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
    sp.material = rough;
    gsurfpoint_invalidate(&sp);
    assert_int_equal(gmaterial_reflection(rough, &sp, in, &illum, out_retro, &out), G_OK);
    assert_near(ov[0], 0.5 / M_PI * (A + B * sin(to) * tan(ti)) * cos(ti), 1e-6);
    assert_int_equal(gmaterial_reflection(rough, &sp, in, &illum, out_back, &out), G_OK);
    assert_near(ov[0], 0.5 / M_PI * A * cos(ti), 1e-6);
    assert_int_equal(gmaterial_diffuse(rough, &sp, &out), G_OK);
    assert_near(ov[0], 0.5 * 0.2126729 + 0.5 * 0.7151522 + 0.5 * 0.0721750, 1e-6);

    GGenerator *g = glibrary_find(lib, GKIND_GENERATOR, "stripes");
    assert_non_null(g);
    sp.object_point = gvec3(7, -3, 0.5); /* only z counts; period 2: sin(pi/2) */
    assert_near(ggenerator_value(g, &sp), 1.0, 1e-12);
    GVec3 grad;
    sp.object_point = gvec3(0, 0, 0);
    assert_int_equal(ggenerator_gradient(g, &sp, &grad), G_OK);
    assert_near(grad.z, 0.5 * M_PI, 1e-12);
    assert_near(grad.x, 0.0, 1e-12);

    gscratch_destroy(s);
    glibrary_destroy(lib);
    /* loading the same modules again does nothing */
    int before = gplugin_count();
    assert_int_equal(gplugin_load(plugin("oren_nayar.so"), &err), G_OK);
    assert_int_equal(gplugin_count(), before);
    unlink(path);
}

static void test_abi_mismatch_refused(void **state)
{
    (void)state;
    require("bad_abi.so");
    GError err;
    const char *p = plugin("bad_abi.so");
    assert_int_equal(gplugin_load(p, &err), G_ERR_VERSION);
    char want[8400];
    snprintf(want, sizeof want,
             "module '%s' was built for module interface version %d, this library has version %d (not loaded, "
             "nothing of it was run)",
             p, GMODULE_ABI_VERSION + 41, GMODULE_ABI_VERSION);
    assert_string_equal(err.message, want);
    assert_null(gregistry_find(GKIND_MATERIAL, "never_registered"));
    /* the same from a text file: the message is placed at the plugin statement */
    char text[4400];
    snprintf(text, sizeof text, "color c rgb 1 1 1\nplugin \"%s\"\n", p);
    GLibrary *lib = NULL;
    GReaderOptions allow = {.allow_plugins = 1};
    assert_int_equal(greader_load_string(text, "scene.mat", &allow, &lib, &err), G_ERR_VERSION);
    assert_null(lib);
    assert_true(strncmp(err.message, "scene.mat:2:8: module '", 23) == 0);
    snprintf(want, sizeof want, "version %d, this library has version %d", GMODULE_ABI_VERSION + 41,
             GMODULE_ABI_VERSION);
    assert_non_null(strstr(err.message, want));
}

static void test_broken_modules(void **state)
{
    (void)state;
    require("failing_init.so");
    require("no_init.so");
    GError err;
    assert_int_equal(gplugin_load(plugin("failing_init.so"), &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "failed to initialise: this module always fails"));
    assert_null(gregistry_find(GKIND_MATERIAL, "never_registered")); /* its registration was dropped */
    assert_int_equal(gplugin_load(plugin("no_init.so"), &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "has no entry point: "));
    assert_non_null(strstr(err.message, "generic_module_init")); /* dlerror's text */
    /* not a shared object: dlopen's own message is passed on */
    char path[4200];
    snprintf(path, sizeof path, "%s/not_a_module.so", plugdir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("this is text\n", f);
    fclose(f);
    assert_int_equal(gplugin_load(path, &err), G_ERR_IO);
    char prefix[4400];
    snprintf(prefix, sizeof prefix, "cannot load module '%s': ", path);
    assert_true(strncmp(err.message, prefix, strlen(prefix)) == 0);
    assert_true(strlen(err.message) > strlen(prefix) + 5);
    unlink(path);
    assert_int_equal(gplugin_load(plugin("does_not_exist.so"), &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "file not found"));
    /* plugin statements can be refused */
    GReaderOptions opt = {.no_plugins = 1};
    GLibrary *lib = NULL;
    assert_int_equal(greader_load_string("plugin \"x.so\"", "t.mat", &opt, &lib, &err), G_ERR_PARSE);
    assert_string_equal(err.message, "t.mat:1:8: plugin statements are disabled for this file");
}

/* A `plugin` statement needs consent (the option or GENERIC_ALLOW_PLUGINS=1), and the message names the ways to
 * give it; --plugin-style loads (gplugin_load) are consent themselves. */
static void test_plugin_statements_need_consent(void **state)
{
    (void)state;
    require("grey.so");
    char text[4400];
    snprintf(text, sizeof text, "color c rgb 1 1 1\nplugin \"%s\"\n", plugin("grey.so"));
    GLibrary *lib = NULL;
    GError err;
    unsetenv(GPLUGIN_ALLOW_ENV);
    int before = gplugin_count();
    assert_int_equal(greader_load_string(text, "scene.mat", NULL, &lib, &err), G_ERR_PARSE);
    assert_null(lib);
    assert_string_equal(err.message,
                        "scene.mat:2:8: plugin statements are not allowed: a module runs native code, so a file may "
                        "load one only with consent (--allow-plugins, GENERIC_ALLOW_PLUGINS=1, or "
                        "GReaderOptions.allow_plugins; --plugin FILE on the command line loads one)");
    assert_int_equal(gplugin_count(), before); /* nothing was loaded */
    setenv(GPLUGIN_ALLOW_ENV, "0", 1); /* only "1" allows */
    assert_int_equal(greader_load_string(text, "scene.mat", NULL, &lib, &err), G_ERR_PARSE);
    setenv(GPLUGIN_ALLOW_ENV, "1", 1);
    assert_int_equal(greader_load_string(text, "scene.mat", NULL, &lib, &err), G_OK);
    assert_true(gregistry_find(GKIND_COLORMODEL, "grey") != NULL);
    glibrary_destroy(lib);
    unsetenv(GPLUGIN_ALLOW_ENV);
    GReaderOptions both = {.allow_plugins = 1, .no_plugins = 1}; /* no_plugins wins */
    assert_int_equal(greader_load_string(text, "scene.mat", &both, &lib, &err), G_ERR_PARSE);
    assert_string_equal(err.message, "scene.mat:2:8: plugin statements are disabled for this file");
}

/* Files that are not modules, or modules for another interface, are refused before dlopen: their ELF constructor
 * (which creates a marker file) never runs. A module that passes the check does run it. */
static void test_refused_before_any_code_runs(void **state)
{
    (void)state;
    require("constructor_only.so");
    require("bad_abi.so");
    require("no_init.so");
    require("failing_init.so");
    char mark[4200];
    snprintf(mark, sizeof mark, "%s/constructor_ran.mark", plugdir);
    unlink(mark);
    setenv("GENERIC_TEST_CONSTRUCTOR_MARK", mark, 1);
    GError err;
    assert_int_equal(gplugin_load(plugin("constructor_only.so"), &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "it is a shared object but not a libgeneric module (it defines neither "
                                        "generic_module_abi nor generic_module_init)"));
    assert_int_equal(gplugin_load(plugin("bad_abi.so"), &err), G_ERR_VERSION);
    assert_int_equal(gplugin_load(plugin("no_init.so"), &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "nothing of it was run"));
    assert_int_equal(access(mark, F_OK), -1); /* no constructor ran */
    assert_int_equal(gplugin_load(plugin("failing_init.so"), &err), G_ERR_INVALID);
    assert_int_equal(access(mark, F_OK), 0); /* the marker works: a real module's constructor made it */
    unlink(mark);
    unsetenv("GENERIC_TEST_CONSTRUCTOR_MARK");
}

/* The ELF reader on damaged copies of a real module: every cut copy is refused (the section table is at the end),
 * and copies with bytes of the headers and symbol tables overwritten are refused or accepted without reading
 * outside the file (AddressSanitizer watches the sanitizer build). Only the check runs: nothing is dlopen'd. */
static void test_elf_check_on_damaged_files(void **state)
{
    (void)state;
    require("grey.so");
    int fd = open(plugin("grey.so"), O_RDONLY);
    assert_true(fd >= 0);
    struct stat st;
    assert_int_equal(fstat(fd, &st), 0);
    size_t n = (size_t)st.st_size;
    unsigned char *bytes = malloc(n);
    assert_non_null(bytes);
    assert_int_equal(read(fd, bytes, n), (ssize_t)n);
    int abi;
    GError err;
    assert_int_equal(gplugin_elf_check(fd, "grey.so", &abi, &err), G_OK);
    assert_int_equal(abi, GMODULE_ABI_VERSION);
    close(fd);
    char path[4200];
    snprintf(path, sizeof path, "%s/damaged.so", plugdir);
    int cuts = 0, accepted = 0, refused = 0;
    for (size_t len = 0; len < n; len += 1 + len / 16, cuts++) {
        int w = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        assert_true(w >= 0);
        assert_int_equal(write(w, bytes, len), (ssize_t)len);
        close(w);
        int r = open(path, O_RDONLY);
        assert_int_equal(gplugin_elf_check(r, path, &abi, &err), G_ERR_IO);
        assert_non_null(strstr(err.message, "nothing of it was run"));
        close(r);
    }
    unsigned seed = 7;
    for (int trial = 0; trial < 2000; trial++) {
        unsigned char *copy = malloc(n);
        memcpy(copy, bytes, n);
        for (int k = 0; k < 4; k++) { /* overwrite bytes in the ELF header or in the last 4 KiB (section table) */
            seed = seed * 1103515245u + 12345u;
            size_t at = (seed >> 8) % 2 ? (seed >> 12) % 64 : n - 1 - (seed >> 12) % (n < 4096 ? n : 4096);
            seed = seed * 1103515245u + 12345u;
            copy[at] = (unsigned char)(seed >> 16);
        }
        int w = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        assert_int_equal(write(w, copy, n), (ssize_t)n);
        close(w);
        int r = open(path, O_RDONLY);
        int rc = gplugin_elf_check(r, path, &abi, &err);
        close(r);
        assert_true(rc == G_OK || rc == G_ERR_IO);
        if (rc == G_OK)
            accepted++;
        else
            refused++;
        free(copy);
    }
    print_message("%d cut copies refused; damaged copies: %d refused, %d accepted\n", cuts, refused, accepted);
    assert_true(refused > 100);
    unlink(path);
    free(bytes);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_load_from_text_and_use),
        cmocka_unit_test(test_abi_mismatch_refused),
        cmocka_unit_test(test_plugin_statements_need_consent),
        cmocka_unit_test(test_refused_before_any_code_runs),
        cmocka_unit_test(test_elf_check_on_damaged_files),
        cmocka_unit_test(test_broken_modules),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
