/* test_gtrace_media_grid.c - grid media (examples/gtrace/media/grid*.c, medium_grid.c): a VDB grid of constant
 * density renders as the homogeneous medium within noise (rgb and spectrum); through a grid whose density is a
 * gradient, rendered pixels and the delta and ratio tracking estimates along rays match a quadrature of the
 * transmittance within 1%; bad VDB files (missing, truncated, not VDB, lying about their extent, huge, beyond the
 * memory budget, of vectors, with negative densities, a reader that crashes) are refused at file:line:col, and
 * randomly corrupted files load or are refused, never crashing the process.
 * The grids are written by examples/gtrace/media/vdb/make_grid.py (python3-openvdb); without it or without the
 * reader gtrace-vdb the tests skip with a message. */
#include "test_gtrace_common.h"
#include "media/medium.h"

#include "generic/builtins.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the files ---- */

/* A Python that imports pyopenvdb, or NULL. */
static const char *openvdb_python(void)
{
    static const char *const cands[] = {"python3", "/usr/bin/python3"};
    for (int i = 0; i < 2; i++) {
        char cmd[256];
        snprintf(cmd, sizeof cmd, "%s -c 'import pyopenvdb' >/dev/null 2>&1", cands[i]);
        if (system(cmd) == 0)
            return cands[i];
    }
    return NULL;
}

/* 1 when the reader gtrace-vdb is beside this program (build/tests/../lib/generic/). */
static int reader_present(void)
{
    char exe[1024];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 64);
    if (n <= 0)
        return 0;
    exe[n] = 0;
    char *slash = strrchr(exe, '/');
    if (!slash)
        return 0;
    strcpy(slash, "/../lib/generic/gtrace-vdb");
    return access(exe, X_OK) == 0;
}

/* Writes the grid `what` of make_grid.py to a temporary file and returns its path; skips the test when python3-openvdb
 * or the reader is missing. */
static const char *grid_file(const char *what)
{
    static const char *py;
    static int checked;
    if (!checked) {
        py = openvdb_python();
        checked = 1;
        if (!py)
            print_message("skipped: python3-openvdb (pyopenvdb) is not installed\n");
        else if (!reader_present())
            print_message("skipped: the OpenVDB reader gtrace-vdb is not built (libopenvdb-dev missing)\n");
    }
    if (!py || !reader_present())
        skip();
    char name[64];
    snprintf(name, sizeof name, "%s.vdb", what);
    char *path = temp_path(name);
    const char *root = getenv("GENERIC_SOURCE_DIR");
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s %s/examples/gtrace/media/vdb/make_grid.py %s %s", py, root ? root : ".", what, path);
    if (system(cmd) != 0)
        fail_msg("%s failed", cmd);
    return path;
}

static Scene *scene_text(const char *name, const char *text, const char *model)
{
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(write_text(name, text), model, &s, &err) != G_OK)
        fail_msg("%s: %s", name, err.message);
    return s;
}

static void render_path(Scene *s, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = s->camera.width, .height = s->camera.height, .spp = s->camera.spp,
                         .depth = s->camera.depth, .threads = 2, .quiet = 1, .cutoff = 0.0,
                         .integrator = RENDER_PATH};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

/* ---- a grid of constant density is the homogeneous medium ---- */

static void test_constant_equals_homogeneous(void **state)
{
    (void)state;
    const char *file = grid_file("constant");
    static const char *const models[] = {"rgb", "spectrum"};
    /* a scattering, chromatic fog cube lit by a point light, before a grey background; the grid's voxel centres
     * reach beyond the cube, so its density is 1 everywhere inside */
    static const char body[] =
        "object box { min <-0.5, -0.5, -0.5> max <0.5, 0.5, 0.5> material dielectric { index 1 } interior fog }\n"
        "light point { position <2, 2, 3> intensity rgb 20 20 20 }\n"
        "light background { color rgb 0.3 0.3 0.3 }\n"
        "camera pinhole { from <0, 0, 3> at <0, 0, 0> fov 30 width 16 height 16 spp 256 depth 16 }\n";
    for (int k = 0; k < 2; k++) {
        char text[2048];
        snprintf(text, sizeof text, "medium fog homogeneous { sigma_a rgb 0.5 1 2 sigma_s rgb 1.5 1.5 1.5 }\n%s",
                 body);
        Scene *hs = scene_text("hom.scene", text, models[k]);
        snprintf(text, sizeof text, "medium fog grid { file \"%s\" sigma_a rgb 0.5 1 2 sigma_s rgb 1.5 1.5 1.5 }\n%s",
                 file, body);
        Scene *gs = scene_text("grid.scene", text, models[k]);
        Framebuffer hf, gf;
        render_path(hs, &hf);
        render_path(gs, &gf);
        /* per pixel, the two estimates have one expectation: their differences average to 0 */
        double sum = 0.0, sum2 = 0.0, hm = 0.0, gm = 0.0;
        const int n = 16 * 16;
        for (int y = 0; y < 16; y++)
            for (int x = 0; x < 16; x++) {
                double a = luma(pixel(&hf, x, y)), b = luma(pixel(&gf, x, y));
                sum += b - a;
                sum2 += (b - a) * (b - a);
                hm += a;
                gm += b;
            }
        double mean = sum / n, sd = sqrt(fmax(sum2 / n - mean * mean, 0.0)), z = mean / (sd / sqrt(n));
        print_message("%s: mean homogeneous %.5f grid %.5f (%+.2f%%), difference %.2e, z %.2f\n", models[k], hm / n,
                      gm / n, 100.0 * (gm / hm - 1.0), mean, z);
        assert_true(fabs(z) < 4.0);
        assert_true(fabs(gm / hm - 1.0) < 0.02);
        /* the medium shows: the centre is not the background */
        assert_true(fabs(luma(pixel(&hf, 8, 8)) - 0.3) > 0.02);
        framebuffer_free(&hf);
        framebuffer_free(&gf);
        scene_destroy(hs);
        scene_destroy(gs);
    }
}

/* ---- a gradient of density: quadrature of the transmittance ---- */

/* The optical depth in units of density along o + t d for t in (t0, t1): the midpoint rule on 4000 steps (the
 * density is piecewise trilinear; the error is far below the tests' 1%). */
static double depth_quadrature(const Grid *g, GVec3 o, GVec3 d, double t0, double t1)
{
    const int steps = 4000;
    double h = (t1 - t0) / steps, sum = 0.0;
    for (int i = 0; i < steps; i++)
        sum += grid_density(g, gvec3_madd(o, d, t0 + (i + 0.5) * h));
    return sum * h;
}

static void test_gradient_pixels(void **state)
{
    (void)state;
    const char *file = grid_file("gradient");
    char text[2048];
    /* an absorbing slab between z -0.5 and 0.5 seen head-on before a white background: a pixel is the background
     * times the transmittance averaged over its footprint */
    snprintf(text, sizeof text,
             "medium ink grid { file \"%s\" sigma_a rgb 1 1 1 scale 0.6 }\n"
             "object box { min <-0.8, -0.8, -0.5> max <0.8, 0.8, 0.5> material dielectric { index 1 } interior ink }\n"
             "light background { color rgb 1 1 1 }\n"
             "camera orthographic { from <0, 0, 3> at <0, 0, 0> size 1.6 width 4 height 4 spp 65536 depth 8 }\n",
             file);
    static const char *const models[] = {"rgb", "spectrum"};
    for (int k = 0; k < 2; k++) {
        Scene *s = scene_text("gradient.scene", text, models[k]);
        Framebuffer fb;
        render_path(s, &fb);
        const Grid *g = s->interiors[0].medium->grid;
        camera_setup(&s->camera, 4, 4);
        double worst = 0.0;
        for (int py = 0; py < 4; py++)
            for (int px = 0; px < 4; px++) {
                double tsum = 0.0;
                for (int b = 0; b < 8; b++)
                    for (int a = 0; a < 8; a++) {
                        Ray r;
                        camera_ray(&s->camera, px + (a + 0.5) / 8.0, py + (b + 0.5) / 8.0, &r);
                        tsum += exp(-0.6 * depth_quadrature(g, r.o, r.d, 2.5, 3.5));
                    }
                double want = tsum / 64.0, got = luma(pixel(&fb, px, py));
                worst = fmax(worst, fabs(got / want - 1.0));
                if (px == py)
                    print_message("%s pixel %d,%d: rendered %.5f, quadrature %.5f (%+.3f%%)\n", models[k], px, py, got,
                                  want, 100.0 * (got / want - 1.0));
                assert_true(want > 0.1 && want < 0.9);
                assert_near(got / want, 1.0, 0.01);
            }
        print_message("%s: largest relative difference over 16 pixels %.3f%%\n", models[k], 100.0 * worst);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

/* Delta tracking (the passing weight) and ratio tracking along rays of a chromatic scattering medium: each band's
 * mean is exp(-sigma_t quadrature) within 1%. */
static void test_gradient_tracking(void **state)
{
    (void)state;
    const char *file = grid_file("gradient");
    char text[1024];
    snprintf(text, sizeof text,
             "medium fog grid { file \"%s\" sigma_a rgb 0.05 0.2 0.4 sigma_s rgb 0.25 0.25 0.25 }\n"
             "object sphere { radius 3 material dielectric { index 1 } interior fog }\n", file);
    Scene *s = scene_text("tracking.scene", text, "rgb");
    const Medium *m = s->interiors[0].medium;
    assert_non_null(m->grid);
    GScratch *scratch = gscratch_create(0);
    assert_non_null(scratch);
    GColor w = {0}, tr = {0}, sum_w = {0}, sum_tr = {0};
    assert_int_equal(gcolor_alloc(&w, s->model), G_OK);
    assert_int_equal(gcolor_alloc(&tr, s->model), G_OK);
    assert_int_equal(gcolor_alloc(&sum_w, s->model), G_OK);
    assert_int_equal(gcolor_alloc(&sum_tr, s->model), G_OK);
    const GVec3 origins[3] = {{-0.7, -0.3, -2.0}, {0.4, 0.6, -2.0}, {-2.0, 0.1, 0.3}};
    const GVec3 dirs[3] = {{0.3, 0.1, 1.0}, {-0.2, -0.4, 1.0}, {1.0, 0.05, -0.1}};
    Rng rng;
    rng_seed(&rng, 12345, 7);
    for (int i = 0; i < 3; i++) {
        GVec3 d = gvec3_normalize(dirs[i]);
        const double tmax = 4.0, n = 1000000;
        double depth = depth_quadrature(m->grid, origins[i], d, 0.0, tmax);
        gcolor_black(&sum_w);
        gcolor_black(&sum_tr);
        for (int k = 0; k < n; k++) {
            double t;
            int ev = medium_grid_flight(m, origins[i], d, tmax, &rng, &t, &w, scratch);
            assert_true(ev == 0 || ev == 1);
            if (ev == 0)
                assert_int_equal(gcolor_add(&sum_w, &sum_w, &w), G_OK);
            assert_int_equal(gcolor_fill(&tr, 1.0), G_OK);
            assert_int_equal(medium_transmit(m, origins[i], d, tmax, &rng, &tr, scratch), G_OK);
            assert_int_equal(gcolor_add(&sum_tr, &sum_tr, &tr), G_OK);
        }
        for (int b = 0; b < m->bands; b++) {
            double want = exp(-gcolor_band_value(&m->sigma_t, b) * depth);
            double delta = gcolor_band_value(&sum_w, b) / n, ratio = gcolor_band_value(&sum_tr, b) / n;
            print_message("ray %d band %d: optical depth %.4f, transmittance %.5f, delta tracking %.5f (%+.2f%%), "
                          "ratio tracking %.5f (%+.2f%%)\n", i, b, depth * gcolor_band_value(&m->sigma_t, b), want,
                          delta, 100.0 * (delta / want - 1.0), ratio, 100.0 * (ratio / want - 1.0));
            assert_true(want > 0.05);
            assert_near(delta / want, 1.0, 0.01);
            assert_near(ratio / want, 1.0, 0.01);
        }
    }
    gcolor_free(&w);
    gcolor_free(&tr);
    gcolor_free(&sum_w);
    gcolor_free(&sum_tr);
    gscratch_destroy(scratch);
    scene_destroy(s);
}

/* The placement: the file's transform (voxels of 0.1 from index -10) and the entry's after it; the density is the
 * gradient's linear function (trilinear interpolation reproduces it) inside and 0 beyond the voxels' reach. */
static void test_placement(void **state)
{
    (void)state;
    const char *file = grid_file("gradient");
    char text[1024];
    snprintf(text, sizeof text,
             "medium a grid { file \"%s\" sigma_a rgb 1 1 1 }\n"
             "medium b grid { file \"%s\" sigma_a rgb 1 1 1 transform { scale 2 translate <1, 0, 0> } }\n"
             "object sphere { radius 0.5 material dielectric { index 1 } interior a }\n"
             "object sphere { center <3, 0, 0> radius 0.5 material dielectric { index 1.5 } interior b }\n",
             file, file);
    Scene *s = scene_text("placement.scene", text, "rgb");
    assert_int_equal(s->ninteriors, 2);
    const Grid *a = s->interiors[0].medium->grid, *b = s->interiors[1].medium->grid;
    const GVec3 pts[3] = {{0.23, -0.41, 0.07}, {-0.95, 0.9, 0.5}, {0.0, 0.0, 0.0}};
    for (int i = 0; i < 3; i++) {
        GVec3 p = pts[i];
        double want = 0.5 + 0.04 * (10.0 * p.x + 10.0) + 0.03 * (10.0 * p.y + 10.0) + 0.05 * (10.0 * p.z + 10.0);
        double da = grid_density(a, p), db = grid_density(b, gvec3_add(gvec3_scale(p, 2.0), gvec3(1, 0, 0)));
        print_message("at <%g, %g, %g>: %.6f, placed by the entry %.6f, the gradient %.6f\n", p.x, p.y, p.z, da, db,
                      want);
        assert_near(da, want, 1e-5);
        assert_near(db, want, 1e-5);
    }
    assert_near(grid_density(a, gvec3(1.11, 0, 0)), 0.0, 0.0); /* beyond voxel 10 and its reach */
    assert_near(grid_density(b, gvec3(0.0, 0, 0)), grid_density(a, gvec3(-0.5, 0, 0)), 1e-6);
    scene_destroy(s);
}

/* ---- bad input ---- */

/* A scene with `medium m grid { file "PATH" EXTRA }` is refused at the file name (line 1, column 22), with what in
 * the message. */
static void refused_file(const char *path, const char *extra, const char *what)
{
    char text[2048], where[64];
    snprintf(text, sizeof text, "medium m grid { file \"%s\" %s }\n", path, extra);
    snprintf(where, sizeof where, "bad.scene:1:22:");
    GError err;
    gerror_clear(&err);
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    assert_true(scene_load(write_text("bad.scene", text), NULL, &s, &err) < 0);
    assert_null(s);
    print_message("%s\n", err.message);
    assert_non_null(strstr(err.message, where));
    assert_non_null(strstr(err.message, what));
}

static void test_bad_files(void **state)
{
    (void)state;
    static char good[256];
    snprintf(good, sizeof good, "%s", grid_file("constant"));
    refused_file("/nonexistent/cloud.vdb", "", "No such file");
    refused_file(write_text("text.vdb", "not a VDB file\n"), "", "not a readable OpenVDB file");
    FILE *f = fopen(good, "rb");
    assert_non_null(f);
    char head[4000];
    size_t got = fread(head, 1, sizeof head, f);
    fclose(f);
    assert_true(got == sizeof head);
    refused_file(write_file("truncated.vdb", head, 300), "", "not a readable OpenVDB file");
    refused_file(write_file("truncated2.vdb", head, sizeof head), "", "not a readable OpenVDB file");
    refused_file(grid_file("lying"), "", "lies about its extent");
    refused_file(grid_file("huge"), "", "states a bounding box [0,0,0]..[200000,200000,200000]");
    refused_file(grid_file("vector"), "", "not float values");
    refused_file(grid_file("negative"), "", "finite and >= 0");
    refused_file(good, "grid smoke", "has no grid 'smoke'");
    refused_file(grid_file("gradient"), "sigma_s rgb 1 1 1 scale 5e8", "beyond the largest extinction");
    /* the memory budget bounds the copy before it is made: 25^3 floats do not fit in 32 KiB */
    size_t limit = gmem_budget_limit();
    gmem_budget_set_limit(32 << 10);
    refused_file(good, "", "15625 voxels, more than the "); /* the budget's room: 8192 less what the scene holds */
    refused_file(good, "", "its dense copy may have (the memory budget");
    gmem_budget_set_limit(limit);
    /* a reader that crashes ends only itself */
    char *crash = write_text("crash.sh", "#!/bin/sh\nkill -SEGV $$\n");
    assert_int_equal(chmod(crash, 0755), 0);
    setenv("GTRACE_VDB_READER", crash, 1);
    refused_file(good, "", "ended on signal 11");
    unsetenv("GTRACE_VDB_READER");
    /* and the entry itself */
    GError err;
    Scene *s = NULL;
    assert_true(scene_load(write_text("bad.scene", "medium m grid { sigma_a rgb 1 1 1 }\n"), NULL, &s, &err) < 0);
    print_message("%s\n", err.message);
    assert_non_null(strstr(err.message, "needs its OpenVDB file"));
}

/* Files with bytes flipped at random places: each loads or is refused at the file's name; the process never crashes
 * (the reader does, at worst). */
static void test_corrupted_files(void **state)
{
    (void)state;
    const char *good = grid_file("gradient");
    FILE *f = fopen(good, "rb");
    assert_non_null(f);
    static unsigned char data[1 << 18];
    size_t n = fread(data, 1, sizeof data, f);
    fclose(f);
    assert_true(n > 1000 && n < sizeof data);
    static unsigned char bad[1 << 18];
    uint64_t x = 0x9e3779b97f4a7c15ull;
    int refused = 0, loaded = 0;
    for (int k = 0; k < 16; k++) {
        memcpy(bad, data, n);
        for (int j = 0; j < 1 + k; j++) { /* 1 to 16 bytes anywhere in the file */
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            bad[x % n] ^= (unsigned char)(1 + (x >> 32) % 255);
        }
        char text[512];
        snprintf(text, sizeof text, "medium m grid { file \"%s\" sigma_a rgb 1 1 1 }\n",
                 write_file("corrupt.vdb", bad, n));
        GError err;
        gerror_clear(&err);
        Scene *s = NULL;
        if (scene_load(write_text("bad.scene", text), NULL, &s, &err) == G_OK) {
            loaded++;
            scene_destroy(s);
        } else {
            refused++;
            print_message("%.160s\n", strstr(err.message, "grid: ") ? strstr(err.message, "grid: ") : err.message);
            assert_non_null(strstr(err.message, "bad.scene:1:22: grid: "));
        }
    }
    print_message("16 corrupted files: %d refused at the file's name, %d loaded\n", refused, loaded);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_constant_equals_homogeneous),
        cmocka_unit_test(test_gradient_pixels),
        cmocka_unit_test(test_gradient_tracking),
        cmocka_unit_test(test_placement),
        cmocka_unit_test(test_bad_files),
        cmocka_unit_test(test_corrupted_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
