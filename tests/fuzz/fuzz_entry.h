/* fuzz_entry.h - the entry points shared by the libFuzzer targets (tests/fuzz/fuzz_*.c) and by the regression
 * replay of the normal test suite (tests/test_regress.c): each takes one input, runs it through the library the
 * way a program reading untrusted files would, and returns 0 when the library answered cleanly (a result or an
 * error status with a message), -1 when a promise is broken (the reason in gfuzz_why). Crashes, leaks and
 * undefined behaviour are the sanitizers' to catch.
 *
 *   gfuzz_reader  the text format loaded from a string, every kind of entry the library registers, in one of
 *                 the colour models; the loaded colours and materials are then evaluated (all finite)
 *   gfuzz_bfc     gbfc_parse on the bytes, the matrix brought into each colour model
 *   gfuzz_probe   the bytes as an .hdr or .pfm file (by their magic) loaded with gprobe_load, then approximated
 *                 by lights (finite, non-negative: NaN and infinity are clamped and counted)
 *   gfuzz_image   the bytes as an image file (extension by magic) read with gimage_read and through the image
 *                 texture node, which is evaluated at a few points
 *
 * Confinement. Files are only read from a private directory made by gfuzz_setup (fixtures: a BFC matrix, an
 * included material file, small images); text inputs containing '/' are skipped, so no include, bfc or image
 * path can leave it ('..' names a directory, which every reader refuses), and plug-in statements are disabled
 * (GReaderOptions.no_plugins), so an input can never dlopen anything. gfuzz_setup must succeed first.
 *
 * Large mode. With GFUZZ_LARGE=1 in the environment (the generated inputs of `make fuzz`, tests/fuzz/gen/), inputs
 * up to GFUZZ_LARGE_INPUT bytes are run (the reader's file limit raised to match) and image and probe headers
 * claiming any number of pixels go to the library, which must refuse a lie before it allocates. Otherwise
 * (libFuzzer, the regression replay) larger inputs and headers over GFUZZ_MAX_PIXELS are skipped, for speed.
 * In either mode a library with many entries is evaluated at its first and last GFUZZ_EVAL_ENDS entries of each
 * kind: evaluating every entry of a chain of n references would cost n^2 by the harness alone. In large mode a
 * text or BFC input that contains GFUZZ_MUST_FAIL (the generator's mark of an input wrong by construction) and
 * loads is a broken promise: a silent wrong success. */
#ifndef GENERIC_TESTS_FUZZ_ENTRY_H
#define GENERIC_TESTS_FUZZ_ENTRY_H

#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "generic/services/bfc.h"
#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/services/image.h"
#include "generic/material.h"
#include "generic/memory.h"
#include "generic/services/probe.h"
#include "generic/reader.h"
#include "generic/texture.h"

#define GFUZZ_FN static __attribute__((unused))

/* A leak in a system library, not in this code, suppressed by a frame of its allocation stack: OpenImageIO's PNG
 * reader keeps its error message in a std::string across libpng's longjmp, which skips the destructor, on every
 * corrupt PNG. A target that keeps the fast unwinder for allocations (fuzz_image: the slow one made it 2.6 times
 * slower) defines GFUZZ_FAST_UNWIND and suppresses the frame where that unwinder stops instead.
 * One definition per program: include this header once. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
#ifdef GFUZZ_FAST_UNWIND
    /* the same string seen through the fast unwinder, which stops in libstdc++ (no frame pointers there) */
    return "leak:PNGInput::PngReadCallback\n"
           "leak:std::__cxx11::basic_string<char, std::char_traits<char>, std::allocator<char> >::_M_assign\n";
#else
    return "leak:PNGInput::PngReadCallback\n";
#endif
}

/** Inputs longer than this are skipped (keeps every execution fast; the format limits are tested elsewhere). */
#define GFUZZ_MAX_INPUT (256u * 1024u)
/** Images with more pixels than this are not decoded: a header of a few bytes can claim any size (lib/image/image.cpp
 * accepts up to 2^29 pixels), and decoding a large image under AddressSanitizer takes seconds. 64x64 keeps
 * OpenImageIO's float buffers (64 KiB) in AddressSanitizer's size classes: larger ones are mapped and unmapped
 * per allocation, and their page faults took most of the image target's time at 256x256. */
#ifndef GFUZZ_MAX_PIXELS
#define GFUZZ_MAX_PIXELS (64L * 64L)
#endif
/** The input limit of large mode. */
#define GFUZZ_LARGE_INPUT (64u * 1024u * 1024u)
/** Entries evaluated at each end of a kind's list (all of them when there are at most twice as many). */
#define GFUZZ_EVAL_ENDS 32

/** The generator's mark (tests/fuzz/gen/gen.h, GEN_MUST_FAIL). */
#define GFUZZ_MUST_FAIL "gfuzz: must be refused"

static size_t gfuzz_max_input = GFUZZ_MAX_INPUT;
static int gfuzz_large;

/* Whether the input is marked as wrong by construction (large mode only). */
static int gfuzz_must_fail(const void *data, size_t size)
{
    return gfuzz_large && memmem(data, size, GFUZZ_MUST_FAIL, sizeof GFUZZ_MUST_FAIL - 1) != NULL;
}
static long gfuzz_max_pixels = GFUZZ_MAX_PIXELS;

/* The index of the j-th entry evaluated out of n (j < gfuzz_eval_count(n)). */
static int gfuzz_eval_count(int n) { return n < 2 * GFUZZ_EVAL_ENDS ? n : 2 * GFUZZ_EVAL_ENDS; }
static int gfuzz_eval_index(int j, int n)
{
    return n <= 2 * GFUZZ_EVAL_ENDS || j < GFUZZ_EVAL_ENDS ? j : n - 2 * GFUZZ_EVAL_ENDS + j;
}

static char gfuzz_dir[4096];
static char gfuzz_why[1024];
static unsigned long gfuzz_serial; /* numbers the image files: the texture system caches files by name */
/* An image node kept for the whole run, so the texture system it shares with the nodes of every input is made
 * once (making and freeing one per input costs more than the rest of the input). */
static GLibrary *gfuzz_keep;
static GColorModel *gfuzz_models[4]; /* rgb, spectrum (5 nm), spectrum9, bispectral (made once) */

GFUZZ_FN int gfuzz_violation(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(gfuzz_why, sizeof gfuzz_why, fmt, ap);
    va_end(ap);
    return -1;
}

static const char gfuzz_bfc_fixture[] = "VEC_01\t3\nBFC-450 Matrix File\n;tiny.BFC\n;A tiny test matrix\n;x\n;<none>\n"
                                        ";x\n;x\n;01/01/2000\n;00:00:00\n400\t420\t10\t3\t400\t10\n"
                                        "r:c:\t400\t410\t420\n400\t0.5\t0.0\t0.0\n410\t0.1\t0.4\t0.0\n"
                                        "420\t0.2\t0.1\t0.3\nEOD\n";
static const char gfuzz_mat_fixture[] = "color warm blackbody 3200\n"
                                        "color grey rgb 0.5 0.5 0.5\n"
                                        "material base lambert { reflectance grey }\n"
                                        "material shiny phong { diffuse rgb 0.3 0.2 0.1 exponent 40 }\n"
                                        "node checked interpolate { a base b shiny t checker }\n";

static int gfuzz_write(const char *name, const void *data, size_t size, char *path, size_t pathsize)
{
    snprintf(path, pathsize, "%s/%s", gfuzz_dir, name);
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t put = size ? fwrite(data, 1, size, f) : 0;
    return fclose(f) == 0 && put == size ? 0 : -1;
}

static void gfuzz_cleanup(void)
{
    glibrary_destroy(gfuzz_keep);
    gfuzz_keep = NULL;
    /* and the scene target's fixtures (fuzz_scene_entry.h) */
    static const char *const names[] = {"tiny.BFC", "common.mat", "tex.png",      "tex.hdr", "grey.pfm",
                                        "tri.obj",  "lamp.ies",   "common.scene", NULL};
    char path[4200];
    for (int i = 0; gfuzz_dir[0] && names[i]; i++) {
        snprintf(path, sizeof path, "%s/%s", gfuzz_dir, names[i]);
        unlink(path);
    }
    if (gfuzz_dir[0])
        rmdir(gfuzz_dir);
    gfuzz_dir[0] = '\0';
    for (int i = 0; i < 4; i++) {
        gcolormodel_destroy(gfuzz_models[i]);
        gfuzz_models[i] = NULL;
    }
}

/** Makes the private directory with its fixtures and the colour models; 0 on success. Registers its own
 * clean-up with atexit (gfuzz_cleanup may also be called directly). */
GFUZZ_FN int gfuzz_setup(void)
{
    if (gfuzz_dir[0])
        return 0;
    /* the readers run in this process, where the sanitizers and libFuzzer see them (not in a decoder process) */
    setenv("GENERIC_DECODE", "inprocess", 1);
    const char *large = getenv("GFUZZ_LARGE");
    if (large && strcmp(large, "1") == 0) {
        gfuzz_large = 1;
        gfuzz_max_input = GFUZZ_LARGE_INPUT;
        gfuzz_max_pixels = -1;
    }
    if (generic_register_builtins(NULL) != G_OK)
        return -1;
    const char *tmp = getenv("TMPDIR");
    snprintf(gfuzz_dir, sizeof gfuzz_dir, "%s/gfuzz.XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(gfuzz_dir)) {
        gfuzz_dir[0] = '\0';
        return -1;
    }
    atexit(gfuzz_cleanup);
    char path[4200];
    GError err;
    if (gfuzz_write("tiny.BFC", gfuzz_bfc_fixture, strlen(gfuzz_bfc_fixture), path, sizeof path) ||
        gfuzz_write("common.mat", gfuzz_mat_fixture, strlen(gfuzz_mat_fixture), path, sizeof path))
        return -1;
    /* a 4x4 sRGB PNG, a 4x2 float HDR (a tiny lat-long probe) and a grey PFM for the image node */
    GImage img = {0};
    if (gimage_create(&img, 4, 4, 3, &err) != G_OK)
        return -1;
    for (int i = 0; i < 4 * 4 * 3; i++)
        img.pixels[i] = (float)((i * 37) % 11) / 10.0f;
    snprintf(path, sizeof path, "%s/tex.png", gfuzz_dir);
    int rc = gimage_write(path, &img, NULL, &err);
    img.height = 2;
    snprintf(path, sizeof path, "%s/tex.hdr", gfuzz_dir);
    if (rc == G_OK)
        rc = gimage_write(path, &img, NULL, &err);
    gimage_free(&img);
    /* OpenImageIO reads PFM but has no writer for it: 2x2 grey floats by hand (rows bottom-up, little-endian) */
    static const char pfm[] = "Pf\n2 2\n-1.0\n\x00\x00\x00\x3f\x00\x00\x80\x3e\x00\x00\x40\x3f\x00\x00\x80\x3f";
    if (rc == G_OK && gfuzz_write("grey.pfm", pfm, sizeof pfm - 1, path, sizeof path) != 0)
        rc = G_ERR_IO;
    GColorModelOptions five = {.step_nm = 5};
    if (rc == G_OK)
        rc = gcolormodel_create("rgb", NULL, &gfuzz_models[0], &err);
    if (rc == G_OK)
        rc = gcolormodel_create("spectrum", &five, &gfuzz_models[1], &err);
    if (rc == G_OK)
        rc = gcolormodel_create("spectrum9", NULL, &gfuzz_models[2], &err);
    if (rc == G_OK)
        rc = gcolormodel_create("bispectral", NULL, &gfuzz_models[3], &err);
    snprintf(path, sizeof path, "node keep image { child lambert file \"%s/tex.png\" }", gfuzz_dir);
    GReaderOptions opt = {.model = gfuzz_models[0], .no_plugins = 1};
    if (rc == G_OK)
        rc = greader_load_string(path, "keep.mat", &opt, &gfuzz_keep, &err);
    if (rc != G_OK)
        fprintf(stderr, "gfuzz_setup: %s\n", err.message);
    return rc == G_OK ? 0 : -1;
}

/* ---- helpers ---- */

/* Enters the private directory: the descriptor of the directory to return to (fchdir), or -1 (nothing changed). */
static int gfuzz_enter(void)
{
    int here = open(".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (here >= 0 && chdir(gfuzz_dir) != 0) {
        close(here);
        here = -1;
    }
    return here;
}

static int gfuzz_color_ok(const GColor *c, const char *what)
{
    if (!gcolor_is_finite(c))
        return gfuzz_violation("%s is not finite", what);
    return 0;
}

/* An error must say what went wrong. */
static int gfuzz_error_ok(int rc, const GError *err, const char *what)
{
    if (rc >= 0)
        return gfuzz_violation("%s: status %d is not an error", what, rc);
    if (err->code != rc)
        return gfuzz_violation("%s: status %d but the error record says %d (%s)", what, rc, err->code, err->message);
    if (!err->message[0])
        return gfuzz_violation("%s: error %d without a message", what, rc);
    return 0;
}

static GVec3 gfuzz_unit(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return gvec3(x / l, y / l, z / l);
}

static int gfuzz_vec_ok(GVec3 v, const char *what)
{
    if (!isfinite(v.x) || !isfinite(v.y) || !isfinite(v.z))
        return gfuzz_violation("%s is not finite (%g %g %g)", what, v.x, v.y, v.z);
    return 0;
}

/* 1 when message begins "FILE:LINE:COL: " (any file: the input, or a file it includes, whatever its name). */
static int gfuzz_has_position(const char *message)
{
    const char *p = message;
    while (*p && *p != ':' && *p != '\n')
        p++;
    if (p == message || *p != ':')
        return 0;
    for (int field = 0; field < 2; field++) {
        const char *digits = ++p;
        while (*p >= '0' && *p <= '9')
            p++;
        if (p == digits || *p != ':')
            return 0;
    }
    return p[1] == ' ';
}

/* The promises of a refused greader_load_string: an error the targets expect, no library, and the position in the
 * message (but for an out-of-memory refusal when nomem_unplaced). 0 when kept, else the violation. */
GFUZZ_FN int gfuzz_load_refused(int rc, const GError *err, const GLibrary *lib, int nomem_unplaced)
{
    int bad = gfuzz_error_ok(rc, err, "greader_load_string");
    if (!bad && lib)
        bad = gfuzz_violation("a failed load returned a library");
    if (!bad && !(nomem_unplaced && rc == G_ERR_NOMEM) && !gfuzz_has_position(err->message))
        bad = gfuzz_violation("the message has no position: %s", err->message);
    return bad;
}

/* Calls every method of a material (or texture node) at a few surface points under white light: every colour
 * and direction that comes back with a success status must be finite. */
static int gfuzz_eval_material(const GMaterial *mat, const char *name)
{
    const GColorModel *m = mat->model;
    GScratch *s = gscratch_create(0);
    GColor illum = {0}, res = {0}, idx = {0};
    int bad = 0;
    if (!s || gcolor_alloc(&illum, m) || gcolor_alloc(&res, m) || gcolor_alloc(&idx, m)) {
        bad = gfuzz_violation("out of memory evaluating %s", name);
        goto done;
    }
    static const double white[3] = {1, 1, 1};
    if (gcolor_from_rgb(&illum, white, GCOLOR_LIGHT) != G_OK) {
        bad = gfuzz_violation("cannot make a white light in %s", name);
        goto done;
    }
    static const double uv[3][3] = {{0.3, 0.7, 0.0}, {0.5, 0.5, 0.01}, {0.95, 0.05, 0.2}};
    char what[160];
    for (int k = 0; k < 3 && !bad; k++) {
        GSurfPoint sp;
        gsurfpoint_init(&sp, m, s);
        sp.u = uv[k][0];
        sp.v = uv[k][1];
        sp.point = gvec3(2.0 * uv[k][0] - 1.0, 2.0 * uv[k][1] - 1.0, 0.25 * k);
        sp.object_point = sp.point;
        sp.geometric_normal = gvec3(0, 0, 1);
        sp.dpdu = gvec3(2, 0, 0);
        sp.dpdv = gvec3(0, 2, 0);
        sp.entering = 1;
        sp.t = 1.0 + k;
        sp.footprint = 2.0 * uv[k][2];
        sp.uv_footprint = uv[k][2];
        sp.material = mat;
        sp.to = mat;
        GVec3 in = gfuzz_unit(0.3, 0.2, 0.9), out = gfuzz_unit(-0.2, 0.1, 0.95), view = gvec3(-in.x, -in.y, -in.z);
        GVec3 n = gsurfpoint_normal(&sp), dir;
        snprintf(what, sizeof what, "%s: shading normal at point %d", name, k);
        if ((bad = gfuzz_vec_ok(n, what)))
            break;
        double rel = gsurfpoint_relative_index(&sp);
        if (!isfinite(rel)) {
            bad = gfuzz_violation("%s: relative index %g at point %d", name, rel, k);
            break;
        }
#define GFUZZ_CHECK(call, label)                                                                  \
    do {                                                                                         \
        gcolor_black(&res);                                                                      \
        if ((call) == G_OK) {                                                                    \
            snprintf(what, sizeof what, "%s: %s at point %d", name, label, k);                   \
            if ((bad = gfuzz_color_ok(&res, what)))                                              \
                goto done;                                                                       \
        }                                                                                        \
    } while (0)
        GFUZZ_CHECK(gmaterial_reflection(mat, &sp, in, &illum, out, &res), "reflection");
        GFUZZ_CHECK(gmaterial_emission(mat, &sp, out, &res), "emission");
        GFUZZ_CHECK(gmaterial_ambient(mat, &sp, &illum, &res), "ambient");
        GFUZZ_CHECK(gmaterial_diffuse(mat, &sp, &res), "diffuse");
        GFUZZ_CHECK(gmaterial_absorption(mat, &sp, &illum, 2.5, &res), "absorption");
        if (gmaterial_reflection_dir(mat, &sp, view, &dir) == 1) {
            snprintf(what, sizeof what, "%s: reflection direction at point %d", name, k);
            if ((bad = gfuzz_vec_ok(dir, what)))
                break;
            GFUZZ_CHECK(gmaterial_reflection(mat, &sp, in, &illum, dir, &res), "mirror reflection");
        }
        gcolor_black(&idx);
        if (gmaterial_refraction_index(mat, &sp, &idx) == G_OK) {
            snprintf(what, sizeof what, "%s: refraction index at point %d", name, k);
            if ((bad = gfuzz_color_ok(&idx, what)))
                break;
            if (gmaterial_refraction_dir(mat, &sp, view, &idx, &dir) == 1) {
                snprintf(what, sizeof what, "%s: refraction direction at point %d", name, k);
                if ((bad = gfuzz_vec_ok(dir, what)))
                    break;
                GFUZZ_CHECK(gmaterial_refraction(mat, &sp, gvec3(-dir.x, -dir.y, -dir.z), &illum, &idx, out, &res),
                            "refraction");
            }
        }
        if (gmaterial_opaque(mat, &sp) < 0)
            bad = gfuzz_violation("%s: opaque failed", name);
#undef GFUZZ_CHECK
        gscratch_reset(s);
    }
done:
    gcolor_free(&illum);
    gcolor_free(&res);
    gcolor_free(&idx);
    gscratch_destroy(s);
    return bad;
}

/* ---- the text format ---- */

/** Loads the text from a string inside the private directory, then evaluates what it defines. */
GFUZZ_FN int gfuzz_reader(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input || memchr(data, '/', size))
        return 0;
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    /* the file's own colormodel statement (rgb by default), or one of the models made once (their creation
     * costs more than most inputs) */
    GReaderOptions opt = {.model = size % 4 ? gfuzz_models[size % 4] : NULL, .no_plugins = 1,
                          .max_file_size = gfuzz_max_input > (1u << 20) ? gfuzz_max_input : 1u << 20};
    int here = gfuzz_enter();
    if (here < 0) {
        free(text);
        return gfuzz_violation("cannot enter %s", gfuzz_dir);
    }
    GLibrary *lib = (GLibrary *)&opt; /* must be set to NULL on failure */
    GError err;
    gerror_clear(&err);
    int rc = greader_load_string(text, "fuzz.mat", &opt, &lib, &err);
    int bad = 0;
    if (rc != G_OK) {
        bad = gfuzz_load_refused(rc, &err, lib, 0);
        lib = NULL;
    }
    if (rc == G_OK && gfuzz_must_fail(data, size))
        bad = gfuzz_violation("an input wrong by construction (" GFUZZ_MUST_FAIL ") loaded without an error");
    const GColorModel *m = lib ? glibrary_colormodel(lib) : NULL;
    if (lib && !m)
        bad = gfuzz_violation("a loaded library without a colour model");
    /* every colour in both roles */
    GColor c = {0};
    if (m && !bad && gcolor_alloc(&c, m) == G_OK) {
        int n = glibrary_count(lib, GKIND_COLOR);
        for (int j = 0; j < gfuzz_eval_count(n) && !bad; j++) {
            int i = gfuzz_eval_index(j, n);
            const char *name = NULL;
            if (!glibrary_entry(lib, GKIND_COLOR, i, &name, NULL) || !name)
                continue;
            for (int role = 0; role < 2 && !bad; role++) {
                gerror_clear(&err);
                int crc = glibrary_color(lib, name, (GColorRole)role, &c, &err);
                char what[200];
                snprintf(what, sizeof what, "color '%s' as a %s", name, role ? "light" : "reflectance");
                bad = crc == G_OK ? gfuzz_color_ok(&c, what) : gfuzz_error_ok(crc, &err, what);
            }
        }
        gcolor_free(&c);
    }
    /* every material and node; generators through their values at a point */
    for (int kind = GKIND_MATERIAL; m && kind <= GKIND_NODE && !bad; kind++) {
        int n = glibrary_count(lib, (GKind)kind);
        for (int j = 0; j < gfuzz_eval_count(n) && !bad; j++) {
            const char *name = NULL;
            GMaterial *mat = glibrary_entry(lib, (GKind)kind, gfuzz_eval_index(j, n), &name, NULL);
            if (mat)
                bad = gfuzz_eval_material(mat, name ? name : "(anonymous)");
        }
    }
    int ng = m ? glibrary_count(lib, GKIND_GENERATOR) : 0;
    for (int j = 0; j < gfuzz_eval_count(ng) && !bad; j++) {
        int i = gfuzz_eval_index(j, ng);
        const GGenerator *g = glibrary_entry(lib, GKIND_GENERATOR, i, NULL, NULL);
        GScratch *s = gscratch_create(4096);
        GSurfPoint sp;
        gsurfpoint_init(&sp, m, s);
        sp.u = 0.37;
        sp.v = 0.61;
        sp.point = sp.object_point = gvec3(0.37, 0.61, 0.2);
        sp.geometric_normal = gvec3(0, 0, 1);
        sp.dpdu = gvec3(1, 0, 0);
        sp.dpdv = gvec3(0, 1, 0);
        sp.uv_footprint = sp.footprint = 0.01;
        double v = ggenerator_value(g, &sp);
        GVec3 grad = gvec3(0, 0, 0);
        int grc = ggenerator_gradient(g, &sp, &grad);
        if (!isfinite(v))
            bad = gfuzz_violation("generator %d (%s): value %g", i, ggenerator_name(g), v);
        else if (grc == G_OK)
            bad = gfuzz_vec_ok(grad, "generator gradient");
        gscratch_destroy(s);
    }
    glibrary_destroy(lib);
    if (fchdir(here) != 0 && !bad)
        bad = gfuzz_violation("cannot return to the working directory");
    close(here);
    free(text);
    return bad;
}

/* ---- BFC matrices ---- */

GFUZZ_FN int gfuzz_bfc(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input)
        return 0;
    /* an exact-size copy, so reading past the end is caught */
    char *text = malloc(size ? size : 1);
    if (!text)
        return 0;
    if (size)
        memcpy(text, data, size);
    GBfcData d;
    GError err;
    gerror_clear(&err);
    int rc = gbfc_parse(text, size, "fuzz.BFC", &d, &err);
    int bad = 0;
    if (rc != G_OK) {
        bad = gfuzz_error_ok(rc, &err, "gbfc_parse");
        if (!bad && (d.values || d.rerad.data))
            bad = gfuzz_violation("a failed parse left data behind");
        if (!bad && strncmp(err.message, "fuzz.BFC:", 9) != 0)
            bad = gfuzz_violation("the message has no position: %s", err.message);
    } else if (gfuzz_must_fail(data, size)) {
        bad = gfuzz_violation("a matrix wrong by construction (" GFUZZ_MUST_FAIL ") parsed without an error "
                              "(%d x %d)", d.rerad.n_out, d.rerad.n_in);
    } else if (!d.values || d.rerad.n_in < 1 || d.rerad.n_out < 1 || !(d.rerad.in_step > 0) ||
               !(d.rerad.out_step > 0)) {
        bad = gfuzz_violation("a parsed matrix without values or with an empty grid");
    } else {
        for (size_t i = 0; i < (size_t)d.rerad.n_in * (size_t)d.rerad.n_out && !bad; i++)
            if (!isfinite(d.values[i]))
                bad = gfuzz_violation("matrix value %zu is %g", i, d.values[i]);
        for (int k = 0; k < 4 && !bad; k++) {
            GColor c = {0};
            if (gcolor_alloc(&c, gfuzz_models[k]) != G_OK)
                break;
            gerror_clear(&err);
            rc = gcolor_from_reradiation(&c, &d.rerad, &err);
            char what[120];
            snprintf(what, sizeof what, "the matrix in model %s", gcolormodel_name(gfuzz_models[k]));
            bad = rc == G_OK ? gfuzz_color_ok(&c, what) : gfuzz_error_ok(rc, &err, what);
            if (!bad && rc == G_OK) {
                double xyz[3];
                if (gcolor_to_xyz(&c, GCOLOR_REFLECTANCE, xyz) == G_OK &&
                    !(isfinite(xyz[0]) && isfinite(xyz[1]) && isfinite(xyz[2])))
                    bad = gfuzz_violation("%s: XYZ %g %g %g", what, xyz[0], xyz[1], xyz[2]);
            }
            gcolor_free(&c);
        }
    }
    gbfc_free(&d);
    free(text);
    return bad;
}

/* ---- images and probes: gfuzz_image, gfuzz_probe ---- */
#include "fuzz_entry_image.h"

#endif
