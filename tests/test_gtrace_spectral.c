/* test_gtrace_spectral.c - `gtrace --spectral -o OUT.exr`: the file, read back with OpenImageIO (oiiotool), has
 * the channels R, G, B and one emissive channel S0.<nm>nm per wavelength of the model's grid (Fichet et al. 2021,
 * comma as decimal separator), the attributes spectralLayoutVersion "1.0" and emissiveUnits "W.m^-2.sr^-1", and
 * the stored spectra integrated against the CIE 1931 observer give the RGB channels; a crop stores the same
 * spectra as the full render in its data window; what cannot be written is refused before rendering; the reader of
 * the layout (gimage_read_spectra) gives the spectra back and refuses malformed files. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_util.h"

#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/services/image.h"

#include <string.h>

#define MAXCH 512

static char dir[128];
static char gtrace[1024];

static int setup(void **state)
{
    (void)state;
    const char *b = getenv("GENERIC_BUILD_DIR");
    snprintf(gtrace, sizeof gtrace, "%s/bin/gtrace", b ? b : "build");
    return tu_tempdir(dir, sizeof dir, "gtrace_spectral");
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

/* Runs gtrace with args (the scene file is relative to GENERIC_SOURCE_DIR); its exit status, output in log. */
static int run_gtrace(const char *args, char *log, size_t n)
{
    if (access(gtrace, X_OK) != 0)
        skip();
    const char *src = getenv("GENERIC_SOURCE_DIR");
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "cd '%.2000s' && '%.1000s' -q %.4000s 2>&1", src ? src : ".", gtrace, args);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t got = fread(log, 1, n - 1, p);
    log[got] = 0;
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* An image as oiiotool reads it: channel names, the data window's origin and size, all values. */
typedef struct Exr {
    int nch, x, y, w, h;
    char names[MAXCH][32];
    char attrs[1 << 16]; /* the verbose header */
    float *v;         /* w * h * nch */
} Exr;

static void exr_read(const char *path, Exr *e)
{
    memset(e, 0, sizeof *e);
    if (system("command -v oiiotool > /dev/null") != 0)
        fail_msg("oiiotool (openimageio-tools, scripts/deps.sh) is missing");
    char args[1200];
    snprintf(args, sizeof args, "--info -v '%s'", path);
    static char info[65536];
    assert_int_equal(tu_run_capture("oiiotool", args, info, sizeof info), 0);
    memcpy(e->attrs, info, sizeof e->attrs);
    const char *cl = strstr(info, "channel list: ");
    assert_non_null(cl);
    cl += strlen("channel list: ");
    while (*cl && *cl != '\n') {
        size_t len = strcspn(cl, ",\n");
        if (cl[len] == ',' && cl[len + 1] != ' ') /* the comma inside a wavelength */
            len += 1 + strcspn(cl + len + 1, ",\n");
        assert_true(e->nch < MAXCH && len < sizeof e->names[0]);
        memcpy(e->names[e->nch], cl, len);
        e->names[e->nch++][len] = 0;
        cl += len;
        if (*cl == ',')
            cl += 2;
    }
    const char *sz = strstr(info, ": ");
    assert_int_equal(sscanf(sz, ": %d x %d", &e->w, &e->h), 2);
    const char *org = strstr(info, "pixel data origin: x=");
    if (org)
        assert_int_equal(sscanf(org, "pixel data origin: x=%d, y=%d", &e->x, &e->y), 2);
    e->v = calloc((size_t)e->w * e->h * e->nch, sizeof(float));
    assert_non_null(e->v);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "oiiotool --dumpdata '%s'", path);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    static char line[1 << 16];
    int pixels = 0;
    while (fgets(line, sizeof line, p)) {
        int px, py, off;
        if (sscanf(line, " Pixel (%d, %d):%n", &px, &py, &off) != 2)
            continue;
        assert_true(px >= e->x && px < e->x + e->w && py >= e->y && py < e->y + e->h);
        float *d = e->v + ((size_t)(py - e->y) * e->w + (px - e->x)) * e->nch;
        char *s = line + off;
        for (int c = 0; c < e->nch; c++)
            d[c] = strtof(s, &s);
        pixels++;
    }
    pclose(p);
    assert_int_equal(pixels, e->w * e->h);
}

static int channel(const Exr *e, const char *name)
{
    for (int c = 0; c < e->nch; c++)
        if (!strcmp(e->names[c], name))
            return c;
    return -1;
}

/* The wavelength of a channel named S0.<nm>nm (comma as decimal separator), or -1. */
static double channel_nm(const char *name)
{
    char buf[32];
    size_t n = strlen(name);
    if (strncmp(name, "S0.", 3) != 0 || n < 6 || strcmp(name + n - 2, "nm") != 0)
        return -1.0;
    snprintf(buf, sizeof buf, "%.*s", (int)(n - 5), name + 3);
    char *comma = strchr(buf, ',');
    if (comma)
        *comma = '.';
    return atof(buf);
}

/* Checks the layout for the model's grid and returns the largest error of the spectra integrated against the
 * CIE 1931 observer against the RGB channels, relative to each pixel's largest channel. */
static double check_layout(const Exr *e, const char *model)
{
    GColorModel *m = NULL;
    GError err;
    assert_int_equal(gcolormodel_create(model, NULL, &m, &err), G_OK);
    double nm[GNM_COUNT];
    int n = gcolormodel_wavelengths(m, nm, GNM_COUNT);
    gcolormodel_destroy(m);
    assert_true(n > 0);
    assert_int_equal(e->nch, 3 + n);
    int rc = channel(e, "R"), gc = channel(e, "G"), bc = channel(e, "B");
    assert_true(rc >= 0 && gc >= 0 && bc >= 0);
    int idx[GNM_COUNT];
    for (int k = 0; k < n; k++) {
        char want[32];
        snprintf(want, sizeof want, "S0.%.6fnm", nm[k]);
        *strchr(want + 3, '.') = ','; /* S0.550,000000nm */
        idx[k] = channel(e, want);
        if (idx[k] < 0)
            fail_msg("no channel %s", want);
        assert_true(fabs(channel_nm(want) - nm[k]) < 1e-9);
    }
    assert_non_null(strstr(e->attrs, "spectralLayoutVersion: \"1.0\""));
    assert_non_null(strstr(e->attrs, "emissiveUnits: \"W.m^-2.sr^-1\""));
    double worst = 0.0, ysum = 0.0, cmf[GNM_COUNT][3];
    for (int k = 0; k < n; k++) {
        gcie_cmf(nm[k], cmf[k]);
        ysum += cmf[k][1];
    }
    int lit = 0;
    for (int i = 0; i < e->w * e->h; i++) {
        const float *px = e->v + (size_t)i * e->nch;
        double xyz[3] = {0, 0, 0}, rgb[3];
        for (int k = 0; k < n; k++)
            for (int j = 0; j < 3; j++)
                xyz[j] += px[idx[k]] * cmf[k][j] / ysum; /* a light: equal energy has Y = 1 */
        gcie_xyz_to_rgb(xyz, rgb);
        double ref[3] = {px[rc], px[gc], px[bc]};
        double big = fmax(fabs(ref[0]), fmax(fabs(ref[1]), fabs(ref[2])));
        if (big < 1e-4)
            continue;
        lit++;
        for (int j = 0; j < 3; j++)
            worst = fmax(worst, fabs(rgb[j] - ref[j]) / big);
    }
    assert_true(lit > e->w * e->h / 4); /* the test sees light, not a black image */
    return worst;
}

static void render_and_check(const char *model, double tol)
{
    char out[256], args[1024], log[4096];
    tu_in_dir(dir, model, out, sizeof out);
    strcat(out, ".exr");
    snprintf(args, sizeof args,
             "examples/scenes/cornell.scene --colormodel %s --width 24 --spp 2 --threads 2 --spectral -o '%s'", model,
             out);
    int st = run_gtrace(args, log, sizeof log);
    assert_int_equal(st, 0);
    Exr e;
    exr_read(out, &e);
    double worst = check_layout(&e, model);
    print_message("%s: %d channels, spectra integrated against CIE 1931 give R,G,B within %.3g%% of each pixel's "
                  "largest channel\n", model, e.nch, worst * 100.0);
    assert_true(worst <= tol);
    free(e.v);
}

/* spectrum (5 nm: 81 channels) and bispectral (10 nm: 41). The tolerance is the quadrature of the CIE observer
 * on the model's grid against the model's own conversion: measured 0.076% and 0.32% of the largest channel. */
static void test_layout_and_integration(void **state)
{
    (void)state;
    render_and_check("spectrum", 0.002);
    render_and_check("bispectral", 0.005);
}

/* A crop stores the pixels of the full render, spectra too, in its data window. */
static void test_crop(void **state)
{
    (void)state;
    char full[256], crop[256], args[1024], log[4096];
    tu_in_dir(dir, "full.exr", full, sizeof full);
    tu_in_dir(dir, "crop.exr", crop, sizeof crop);
    const char *common = "examples/scenes/cornell.scene --colormodel spectrum --width 24 --spp 2 --spectral";
    snprintf(args, sizeof args, "%s -o '%s'", common, full);
    assert_int_equal(run_gtrace(args, log, sizeof log), 0);
    snprintf(args, sizeof args, "%s --crop 5,7,19,15 -o '%s'", common, crop);
    assert_int_equal(run_gtrace(args, log, sizeof log), 0);
    Exr f, c;
    exr_read(full, &f);
    exr_read(crop, &c);
    assert_int_equal(c.x, 5);
    assert_int_equal(c.y, 7);
    assert_int_equal(c.w, 14);
    assert_int_equal(c.h, 8);
    assert_int_equal(c.nch, f.nch);
    assert_non_null(strstr(c.attrs, "full/display size: 24 x 24"));
    for (int y = 0; y < c.h; y++)
        for (int x = 0; x < c.w; x++)
            for (int ch = 0; ch < c.nch; ch++) {
                float a = c.v[((size_t)y * c.w + x) * c.nch + ch];
                float b = f.v[((size_t)(y + 7) * f.w + (x + 5)) * f.nch + ch];
                if (a != b)
                    fail_msg("crop pixel %d,%d channel %s: %g, full render %g", x + 5, y + 7, c.names[ch], a, b);
            }
    free(f.v);
    free(c.v);
}

/* Refused before rendering, nothing written: a model without wavelength samples, another format, a spectral
 * image over the memory budget. */
static void test_refusals(void **state)
{
    (void)state;
    char out[256], args[1024], log[4096];
    tu_in_dir(dir, "refused.exr", out, sizeof out);
    snprintf(args, sizeof args, "examples/scenes/cornell.scene --colormodel rgb --width 8 --spectral -o '%s'", out);
    assert_int_equal(run_gtrace(args, log, sizeof log), 1);
    assert_non_null(strstr(log, "has no wavelength samples"));
    assert_int_equal(access(out, F_OK), -1);
    tu_in_dir(dir, "refused.png", out, sizeof out);
    snprintf(args, sizeof args, "examples/scenes/cornell.scene --width 8 --spectral -o '%s'", out);
    assert_int_equal(run_gtrace(args, log, sizeof log), 2);
    assert_non_null(strstr(log, "must end in .exr"));
    assert_int_equal(access(out, F_OK), -1);
    tu_in_dir(dir, "huge.exr", out, sizeof out);
    snprintf(args, sizeof args,
             "examples/scenes/cornell.scene --colormodel spectrum --width 65536 --height 65536 --spectral -o '%s'",
             out);
    assert_int_equal(run_gtrace(args, log, sizeof log), 1);
    assert_non_null(strstr(log, "more than the memory limit"));
    assert_int_equal(access(out, F_OK), -1);
}

/* A 5x3 RGB image with spectra at 400, 550, 700 and 1000 nm (OpenEXR sorts its channels by name, so the file
 * has S0.1000,000000nm first), written by gimage_write into dir/name; values in vals. */
static void write_spectral(const char *name, float vals[5 * 3 * 4])
{
    static const double nm[4] = {400.0, 550.0, 700.0, 1000.0};
    GImage img;
    GError err;
    char path[256];
    assert_int_equal(gimage_create(&img, 5, 3, 3, &err), G_OK);
    for (int i = 0; i < 5 * 3 * 3; i++)
        img.pixels[i] = 0.25f * (float)i;
    for (int i = 0; i < 5 * 3 * 4; i++)
        vals[i] = 1.0f + 0.5f * (float)i;
    GImageSpectra sp = {.count = 4, .wavelengths = nm, .values = vals};
    GImageWriteOptions opt = {.spectra = &sp};
    assert_int_equal(gimage_write(tu_in_dir(dir, name, path, sizeof path), &img, &opt, &err), G_OK);
    gimage_free(&img);
}

/* dir/to: dir/from with its channels renamed by oiiotool --chnames (a comma separates the names there, so the
 * names are the layout's without decimals). */
static void renamed(const char *from, const char *to, const char *names)
{
    char a[256], b[256], args[1024], log[4096];
    snprintf(args, sizeof args, "'%s' --chnames '%s' -o '%s'", tu_in_dir(dir, from, a, sizeof a), names,
             tu_in_dir(dir, to, b, sizeof b));
    if (tu_run_capture("oiiotool", args, log, sizeof log) != 0)
        fail_msg("oiiotool --chnames failed: %s", log);
}

/* gimage_read_spectra refuses the file dir/name with G_ERR_IO and a message naming what, and zeroes out. */
static void refused(const char *name, const char *what)
{
    char path[256];
    GError err;
    GImageSpectraBuf s = {.count = 7};
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, name, path, sizeof path), &s, &err), G_ERR_IO);
    if (!strstr(err.message, what) || !strstr(err.message, name))
        fail_msg("%s: the message '%s' does not name '%s'", name, err.message, what);
    assert_true(s.count == 0 && s.width == 0 && !s.wavelengths && !s.values);
}

/* The reader of the layout (gimage_read_spectra, what `gtrace merge` joins --spectral pieces with): spectra come
 * back bit for bit, sorted by wavelength whatever the channel order; a file without spectra has none; names
 * without decimals are read; malformed names, two names of one wavelength and spectra over the memory budget are
 * refused. */
static void test_spectra_reader(void **state)
{
    (void)state;
    float vals[5 * 3 * 4];
    char path[256];
    GError err;
    GImageSpectraBuf s;
    write_spectral("sp.exr", vals);
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, "sp.exr", path, sizeof path), &s, &err), G_OK);
    assert_int_equal(s.width, 5);
    assert_int_equal(s.height, 3);
    assert_int_equal(s.count, 4);
    assert_true(s.wavelengths[0] == 400.0 && s.wavelengths[1] == 550.0 && s.wavelengths[2] == 700.0 &&
                s.wavelengths[3] == 1000.0);
    assert_memory_equal(s.values, vals, sizeof vals);
    gimage_spectra_free(&s);
    assert_true(s.count == 0 && !s.values && !s.wavelengths);
    gimage_spectra_free(&s); /* twice: a no-op */

    renamed("sp.exr", "plain.exr", "R,G,B,X,Y,Z,W"); /* no spectral channel */
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, "plain.exr", path, sizeof path), &s, &err), G_OK);
    assert_true(s.count == 0 && s.width == 5 && s.height == 3 && !s.wavelengths && !s.values);
    /* the layout's names without decimals; 0550 is 550 */
    renamed("sp.exr", "short.exr", "R,G,B,S0.1000nm,S0.400nm,S0.0550nm,S0.700nm");
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, "short.exr", path, sizeof path), &s, &err), G_OK);
    assert_int_equal(s.count, 4);
    assert_true(s.wavelengths[0] == 400.0 && s.wavelengths[1] == 550.0 && s.wavelengths[3] == 1000.0);
    assert_memory_equal(s.values, vals, sizeof vals); /* the file's order is 0550, 1000, 400, 700 */
    gimage_spectra_free(&s);

    static const char *const bad[] = {
        "S0.550.5nm",         "S0.550um", "S0.nm", "S0.0nm", "S0.abcnm", "S0.550nm ", "S0.-550nm",
        "S0.1234567890123456nm", /* 16 digits */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char names[256];
        snprintf(names, sizeof names, "R,G,B,S0.300nm,%s,S0.800nm,S0.900nm", bad[i]);
        renamed("sp.exr", "bad.exr", names);
        refused("bad.exr", bad[i]);
    }
    renamed("sp.exr", "dup.exr", "R,G,B,S0.400nm,S0.550nm,S0.0550nm,S0.700nm");
    refused("dup.exr", "are the same wavelength (550 nm)");

    gimage_set_memory_budget(5 * 3 * 4 * sizeof(float)); /* less than the file's 7 channels */
    s.count = 7;
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, "sp.exr", path, sizeof path), &s, &err), G_ERR_NOMEM);
    assert_true(s.count == 0 && !s.values);
    gimage_set_memory_budget(0);
    assert_int_equal(gimage_read_spectra(tu_in_dir(dir, "absent.exr", path, sizeof path), &s, &err), G_ERR_IO);
    assert_int_equal(gimage_read_spectra(NULL, &s, &err), G_ERR_INVALID);
    assert_int_equal(gimage_read_spectra(path, NULL, &err), G_ERR_INVALID);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layout_and_integration),
        cmocka_unit_test(test_crop),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_spectra_reader),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
