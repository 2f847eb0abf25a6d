/* test_oom.c - out of memory: every allocation the library makes while loading files can fail, and the load then
 * returns an error status with a message instead of crashing, and frees everything it made.
 *
 * The test allocator (test_alloc.h) fails the k-th allocation for k = 0, 1, 2, ... (and, in a second
 * sweep, every allocation from the k-th on, so the error paths themselves get no memory either) over:
 *   - a material file with an include, colours of every literal form, every built-in material, a BFC matrix
 *     and the fluorescent materials, read in the spectral model (glibrary_create + glibrary_load_file);
 *   - texture files: the paper's Fig. 2 tree (image node, CPG contour, wood, bump, transform) and a tree of
 *     every other node and generator type (glibrary_load_file), and the first through greader_load_file;
 *   - gbfc_read of a measured matrix.
 * Each sweep ends when an attempt runs without reaching the failing allocation: it must then succeed. Every
 * attempt must leave no block allocated (the allocator counts them; AddressSanitizer checks the rest). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/services/bfc.h"
#include "generic/memory.h"
#include "generic/reader.h"
#include "test_alloc.h"

/* ---- the failing allocator: the test allocator (test_alloc.h) ---- */

static TuAlloc alloc;

/* ---- files ---- */

static char workdir[4096];

static const char *source_path(const char *rel, char *buf, size_t size)
{
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(buf, size, "%s/%s", src ? src : ".", rel);
    return buf;
}

static void write_file(const char *name, const char *text)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", workdir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static void copy_file(const char *from, const char *name)
{
    FILE *in = fopen(from, "rb");
    assert_non_null(in);
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", workdir, name);
    FILE *out = fopen(path, "wb");
    assert_non_null(out);
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        assert_int_equal(fwrite(buf, 1, n, out), n);
    fclose(in);
    assert_int_equal(fclose(out), 0);
}

static const char *work_path(const char *name)
{
    static char buf[4][4200];
    static int next;
    char *b = buf[next++ & 3];
    snprintf(b, sizeof buf[0], "%s/%s", workdir, name);
    return b;
}

/* A material file touching every part of the reader and every built-in colour literal and material. */
static const char materials_text[] =
    "# every colour literal and material, an include and a measured matrix\n"
    "include \"common.mat\"\n"
    "color warm blackbody 3200\n"
    "color sky spectrum { 400 0.2 500 0.4 600 0.3 700 0.25 }\n"
    "color d65 illuminant D65\n"
    "color laser line 532 2\n"
    "color measured bfc \"tiny.BFC\"\n"
    "color brighter scale 0.5 warm\n"
    "color alias sky\n"
    "material a lambert { reflectance scale 0.5 sky }\n"
    "material b phong { diffuse rgb 0.2 0.3 0.4 specular rgb 0.1 0.1 0.1 exponent 30 mirror rgb 0.05 0.05 0.05 }\n"
    "material c mirror { reflectance alias }\n"
    "material d dielectric { index sellmeier 1.03961212 0.231792344 1.01046945 0.00600069867 0.0200179144 "
    "103.560653 absorption rgb 0.1 0.2 0.3 tint rgb 1 1 1 }\n"
    "material e emitter { radiance scale 4 warm two_sided yes }\n"
    "material g fluorescent-phong { matrix measured ks 0.04 }\n"
    "color dayglo reradiation { absorb_peak 470 absorb_width 115 emit_width 20 stokes_shift 135 }\n"
    "material h fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
    "material a_copy a\n";

static const char common_text[] = "color grey rgb 0.5 0.5 0.5\n"
                                  "material base lambert { reflectance grey }\n";

/* Every texture node and generator type the library registers (Fig. 2 covers image, cpg, wood, bump). */
static const char textures_text[] =
    "material red lambert { reflectance rgb 0.8 0.1 0.1 }\n"
    "material blue phong { diffuse rgb 0.1 0.1 0.6 specular rgb 0.2 0.2 0.2 exponent 40 }\n"
    "generator n perlin { frequency 3 seed 2 }\n"
    "generator f fbm { space uv frequency 4 octaves 4 }\n"
    "generator t turbulence { frequency 3 octaves 3 }\n"
    "generator face surface\n"
    "node a interpolate { a red b blue t marble { stripes 2 turbulence 1 } }\n"
    "node b interpolate-one { method refraction_index a dielectric { index 1.52 } b dielectric { index 1.5 } t n }\n"
    "node c select { index face children { red blue a } }\n"
    "node d spline { t gradient { space uv slope 0 1 0 } basis catmull-rom children { red blue red blue } }\n"
    "node e scale { child red factor checker { frequency 4 } }\n"
    "node g transform { child c uv { rotate 45 scale 2 } xyz { rotate 0 1 0 80 translate 0 0 0.5 } }\n"
    "node h bump { child d height f strength 0.01 }\n"
    "node i interpolate { a e b h t csg { space object shape union { transform { translate 0.5 0.5 0 } sphere "
    "0.1 box -0.1 -0.03 -0.2 0.1 0.03 -0.06 } } }\n"
    "node j interpolate { a i b g t wood { rings 5 turbulence 0.3 } }\n"
    "node k scale { child j factor constant { value 0.5 } }\n";

static int setup(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    snprintf(workdir, sizeof workdir, "%s/tmp_oom_XXXXXX", build ? build : "/tmp");
    if (!mkdtemp(workdir))
        return -1;
    char src[4200];
    copy_file(source_path("tests/bad/tiny.BFC", src, sizeof src), "tiny.BFC");
    copy_file(source_path("examples/textures/fig2.txt", src, sizeof src), "fig2.txt");
    copy_file(source_path("examples/textures/picture.png", src, sizeof src), "picture.png");
    write_file("common.mat", common_text);
    write_file("materials.mat", materials_text);
    write_file("textures.txt", textures_text);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    static const char *const names[] = {"tiny.BFC", "fig2.txt", "picture.png", "common.mat", "materials.mat",
                                        "textures.txt", NULL};
    for (int i = 0; names[i]; i++)
        unlink(work_path(names[i]));
    rmdir(workdir);
    return 0;
}

/* ---- the sweeps ---- */

typedef int (*Attempt)(const void *arg, GError *err);

/* Runs attempt with the k-th allocation failing, k = 0, 1, ..., until an attempt no longer reaches the failing
 * allocation; every failing attempt must report an error with a message, every attempt must free all it
 * allocated. Returns the number of allocation points covered. */
static long sweep(Attempt attempt, const void *arg, int sticky, const char *what)
{
    GError err;
    gerror_clear(&err);
    gmem_set_allocator(NULL);
    int rc = attempt(arg, &err); /* a clean run first (registers the built-ins, fails nothing) */
    if (rc != G_OK)
        print_error("%s: %s\n", what, err.message);
    assert_int_equal(rc, G_OK);
    long k;
    for (k = 0; k < 1000000; k++) {
        alloc = (TuAlloc){.fail_call = k + 1, .fail_after = sticky};
        tu_alloc_install(&alloc);
        gerror_clear(&err);
        rc = attempt(arg, &err);
        gmem_set_allocator(NULL);
        TuAlloc b = alloc;
        if (b.live != 0)
            print_error("%s: allocation %ld failing (%s) leaves %ld blocks (status %d: %s)\n", what, k,
                        sticky ? "and all after it" : "alone", b.live, rc, err.message);
        assert_int_equal(b.live, 0);
        if (!b.failed) { /* the attempt made fewer than k + 1 allocations: all failure points are covered */
            if (rc != G_OK)
                print_error("%s: %s\n", what, err.message);
            assert_int_equal(rc, G_OK);
            break;
        }
        if (rc == G_OK)
            continue; /* the failure was survived (e.g. an optional cache); nothing leaked */
        if (rc >= 0 || err.code != rc || !err.message[0])
            print_error("%s: allocation %ld failing gives status %d, error record %d '%s'\n", what, k, rc, err.code,
                        err.message);
        assert_true(rc < 0);
        assert_int_equal(err.code, rc);
        assert_true(err.message[0] != '\0');
    }
    return k;
}

/* glibrary_create + glibrary_load_file in a colour model, then glibrary_destroy. */
typedef struct LoadArgs {
    const char *path;
    const char *model; /* NULL: rgb */
} LoadArgs;

static int load_into_library(const void *arg, GError *err)
{
    const LoadArgs *a = arg;
    GColorModel *m = NULL;
    int rc = G_OK;
    if (a->model) {
        GColorModelOptions o = {.step_nm = 10};
        rc = gcolormodel_create(a->model, &o, &m, err);
        if (rc != G_OK)
            return rc;
    }
    GLibrary *lib = NULL;
    rc = glibrary_create(m, &lib, err);
    if (rc == G_OK) {
        GReaderOptions opt = {.no_plugins = 1};
        rc = glibrary_load_file(lib, a->path, &opt, err);
    }
    glibrary_destroy(lib);
    gcolormodel_destroy(m);
    return rc;
}

static int load_file(const void *arg, GError *err)
{
    GLibrary *lib = (GLibrary *)&lib;
    int rc = greader_load_file(arg, NULL, &lib, err);
    if (rc != G_OK && lib)
        return gerror_set(err, G_ERR_INVALID, "a failed load returned a library");
    glibrary_destroy(lib);
    return rc;
}

static int read_bfc(const void *arg, GError *err)
{
    GBfcData d;
    int rc = gbfc_read(arg, &d, err);
    if (rc == G_OK && (!d.values || d.rerad.n_in < 1))
        rc = gerror_set(err, G_ERR_INVALID, "gbfc_read succeeded without values");
    if (rc != G_OK && d.values)
        rc = gerror_set(err, G_ERR_INVALID, "a failed gbfc_read left values behind");
    gbfc_free(&d);
    return rc;
}

static void test_material_file(void **state)
{
    (void)state;
    LoadArgs spectral = {work_path("materials.mat"), "bispectral"};
    long n1 = sweep(load_into_library, &spectral, 0, "materials.mat (bispectral)");
    long n2 = sweep(load_into_library, &spectral, 1, "materials.mat (bispectral)");
    LoadArgs rgb = {work_path("materials.mat"), NULL};
    long n3 = sweep(load_into_library, &rgb, 0, "materials.mat (rgb)");
    print_message("materials.mat: %ld allocations (bispectral), %ld (rgb)\n", n1, n3);
    assert_true(n1 > 50);
    assert_int_equal(n1, n2);
    assert_true(n3 > 50);
}

static void test_texture_files(void **state)
{
    (void)state;
    LoadArgs fig2 = {work_path("fig2.txt"), NULL};
    long n1 = sweep(load_into_library, &fig2, 0, "fig2.txt");
    sweep(load_into_library, &fig2, 1, "fig2.txt");
    LoadArgs all = {work_path("textures.txt"), "spectrum"};
    long n2 = sweep(load_into_library, &all, 0, "textures.txt");
    sweep(load_into_library, &all, 1, "textures.txt");
    long n3 = sweep(load_file, work_path("fig2.txt"), 0, "fig2.txt (greader_load_file)");
    print_message("fig2.txt: %ld allocations, textures.txt: %ld, fig2.txt as a new library: %ld\n", n1, n2, n3);
    assert_true(n1 > 30);
    assert_true(n2 > 30);
    assert_true(n3 >= n1);
}

static void test_bfc_read(void **state)
{
    (void)state;
    long n = sweep(read_bfc, work_path("tiny.BFC"), 0, "tiny.BFC");
    sweep(read_bfc, work_path("tiny.BFC"), 1, "tiny.BFC");
    assert_true(n >= 2); /* the file buffer and the values */
    char path[4200];
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/../shared/data/bispectral/CIBA12.BFC", src ? src : ".");
    if (access(path, R_OK) != 0)
        snprintf(path, sizeof path, "/work/shared/data/bispectral/CIBA12.BFC");
    if (access(path, R_OK) != 0)
        skip(); /* the measured matrices are shared data outside the repository */
    long m = sweep(read_bfc, path, 0, "CIBA12.BFC");
    assert_true(m >= 2);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_material_file),
        cmocka_unit_test(test_texture_files),
        cmocka_unit_test(test_bfc_read),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
