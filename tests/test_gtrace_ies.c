/* test_gtrace_ies.c - IES LM-63 photometric lights (examples/gtrace/scene/ies.c, `light ies`): the flux of type C
 * tables (axially and quadrant symmetric) and of a type B table within 1% of their lumens; the symmetries unfolded;
 * the illuminance on a floor at three points equal to I(theta) cos(theta) / r^2 within 1% in both integrators (the
 * candela converted with the luminous efficacy of the light's spectrum); hostile files refused at their file, line
 * and column: lying counts, truncation, NaN, huge angle tables, angles out of order, type A, tilt from a file. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"
#include "scene/ies.h"

#define DEG (M_PI / 180.0)

/* An LM-63-2002 text: the header, then "1 LUMENS 1 NV NH TYPE 2 0 0 0\n1 1 100\n", the angles and the candela
 * values of f(v, h), a horizontal angle's values on one line. */
static char *ies_text(int type, double lumens, int nv, double v0, double v1, int nh, double h0, double h1,
                      double (*f)(double, double))
{
    size_t cap = 4096 + (size_t)(nv + nh + nv * nh) * 24;
    char *t = malloc(cap), *p = t;
    assert_non_null(t);
    p += sprintf(p, "IESNA:LM-63-2002\n[TEST] synthetic\n[MANUFAC] none\nTILT=NONE\n");
    p += sprintf(p, "1 %.6f 1 %d %d %d 2 0 0 0\n1 1 100\n", lumens, nv, nh, type);
    for (int i = 0; i < nv; i++)
        p += sprintf(p, "%.6g ", nv > 1 ? v0 + (v1 - v0) * i / (nv - 1) : v0);
    p += sprintf(p, "\n");
    for (int j = 0; j < nh; j++)
        p += sprintf(p, "%.6g ", nh > 1 ? h0 + (h1 - h0) * j / (nh - 1) : h0);
    p += sprintf(p, "\n");
    for (int j = 0; j < nh; j++) {
        double h = nh > 1 ? h0 + (h1 - h0) * j / (nh - 1) : h0;
        for (int i = 0; i < nv; i++)
            p += sprintf(p, "%.6f ", f(nv > 1 ? v0 + (v1 - v0) * i / (nv - 1) : v0, h));
        p += sprintf(p, "\n");
    }
    return t;
}

/* type C: 1000 cos(v) in the lower hemisphere (flux 1000 pi) */
static double cosine(double v, double h)
{
    (void)h;
    return v <= 90.0 ? 1000.0 * cos(v * DEG) : 0.0;
}

/* type C: 1000 cos(v) (1 + 0.5 cos(2 h)), quadrant symmetric (flux 1000 pi: the cos 2h term integrates to 0) */
static double quadrant(double v, double h) { return cosine(v, h) * (1.0 + 0.5 * cos(2.0 * h * DEG)); }

/* type B: 1000 cos(v) cos(h) over the front half (flux 1000 * 2 * pi / 2) */
static double type_b(double v, double h) { return 1000.0 * cos(v * DEG) * cos(h * DEG); }

static void parse_ok(const char *text, IesData *d)
{
    GError err;
    gerror_clear(&err);
    if (ies_parse(text, strlen(text), "test.ies", d, &err) != G_OK)
        fail_msg("ies_parse: %s", err.message);
}

static void test_flux(void **state)
{
    (void)state;
    struct {
        const char *what;
        int type, nv, nh;
        double v0, v1, h0, h1;
        double (*f)(double, double);
    } cases[] = {
        {"type C, axial", IES_TYPE_C, 37, 1, 0, 180, 0, 0, cosine},
        {"type C, quadrant", IES_TYPE_C, 37, 19, 0, 180, 0, 90, quadrant},
        {"type C, full", IES_TYPE_C, 19, 73, 0, 90, 0, 360, quadrant},
        {"type B, symmetric", IES_TYPE_B, 37, 19, -90, 90, 0, 90, type_b},
        {"type B, full", IES_TYPE_B, 37, 37, -90, 90, -90, 90, type_b},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        char *t = ies_text(cases[k].type, 1000.0 * M_PI, cases[k].nv, cases[k].v0, cases[k].v1, cases[k].nh,
                           cases[k].h0, cases[k].h1, cases[k].f);
        IesData d;
        parse_ok(t, &d);
        double flux = ies_flux(&d);
        print_message("%s: flux %.2f lm, file %.2f lm (ratio %.5f)\n", cases[k].what, flux, d.lumens,
                      flux / d.lumens);
        assert_near(flux / d.lumens, 1.0, 0.01);
        ies_free(&d);
        free(t);
    }
}

static void test_symmetry(void **state)
{
    (void)state;
    char *t = ies_text(IES_TYPE_C, 1000.0, 37, 0, 180, 19, 0, 90, quadrant);
    IesData d;
    parse_ok(t, &d);
    /* quadrant symmetry: h, -h, 180 - h and 180 + h are alike; the table's own points are exact */
    for (double h = 0.0; h < 360.0; h += 17.0) {
        double want = quadrant(40.0, h), got = ies_candela(&d, 40.0, h);
        assert_near(got, want, 0.01 * want + 1e-9); /* bilinear between 5 degree samples */
    }
    assert_near(ies_candela(&d, 30.0, 20.0), quadrant(30.0, 20.0), 1e-3);
    assert_near(ies_candela(&d, 30.0, 200.0), quadrant(30.0, 20.0), 1e-3);
    assert_near(ies_candela(&d, 30.0, 340.0), quadrant(30.0, 20.0), 1e-3);
    assert_near(ies_candela(&d, 30.0, 160.0), quadrant(30.0, 20.0), 1e-3);
    assert_true(ies_candela(&d, 120.0, 0.0) == 0.0);
    /* the frame: straight along the aim is vertical angle 0 */
    GVec3 aim = gvec3(0, -1, 0), along = gvec3(1, 0, 0), third = gvec3_cross(aim, along);
    assert_near(ies_candela_dir(&d, aim, aim, along, third), 1500.0, 1e-3);
    ies_free(&d);
    free(t);
}

/* The luminous sum of a light's spectrum over the 1 nm grid: ybar summed, for Y = 1. */
static double ybar_sum(void)
{
    double s = 0.0, c[3];
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm++) {
        gcie_cmf(nm, c);
        s += c[1];
    }
    return s;
}

/* A white floor (albedo 1) under a type C light 2 above, seen from straight above through pixel centres: the
 * floor's luminance at three points is I(theta) cos(theta) / (pi r^2), in W/(m^2 sr nm) units of the light's
 * spectrum: Y * 683 * sum(ybar) gives it in cd/m^2. */
static void check_floor(int integrator, const char *model)
{
    char *t = ies_text(IES_TYPE_C, 1000.0 * M_PI, 37, 0, 180, 19, 0, 90, quadrant);
    char *ies = write_text("floor.ies", t);
    free(t);
    char scene[1024];
    snprintf(scene, sizeof scene,
             "camera pinhole { from <0, 6, 0> at <0, 0, 0> up <0, 0, -1> fov 70 width 64 height 64 spp 1 depth 3 }\n"
             "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 1 1 1 } }\n"
             "light ies { file \"%s\" position <0, 2, 0> direction <0, -1, 0> along <1, 0, 0> color illuminant A }\n",
             ies);
    char *path = write_text("floor.scene", scene);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    if (scene_load(path, model, &s, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    assert_int_equal(accel_build(s, &err), G_OK);
    RenderSettings rs = {.width = 64, .height = 64, .spp = 1, .depth = 3, .threads = 2, .quiet = 1,
                         .integrator = integrator};
    Framebuffer fb;
    RenderStats st;
    if (render_image(s, &rs, &fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    Camera cam = s->camera;
    camera_setup(&cam, 64, 64);
    IesData d;
    parse_ok(t = ies_text(IES_TYPE_C, 1000.0 * M_PI, 37, 0, 180, 19, 0, 90, quadrant), &d);
    free(t);
    const int px[3][2] = {{32, 32}, {50, 20}, {8, 60}};
    for (int k = 0; k < 3; k++) {
        Ray r;
        camera_ray(&cam, px[k][0] + 0.5, px[k][1] + 0.5, &r);
        GVec3 p = gvec3_madd(r.o, r.d, -r.o.y / r.d.y); /* the floor point */
        GVec3 w = gvec3_sub(gvec3(0, 2, 0), p);
        double r2 = gvec3_dot(w, w), ct = 2.0 / sqrt(r2);
        double v = acos(ct) / DEG, h = atan2(p.z, p.x) / DEG; /* third = aim x along = (0,-1,0) x (1,0,0) = +z */
        double want = ies_candela(&d, v, h) * ct / r2 / M_PI;
        double got = luma(pixel(&fb, px[k][0], px[k][1])) * 683.0 * ybar_sum();
        print_message("%s %s: floor at (%.3f, %.3f): luminance %.4f cd/m^2, I cos / (pi r^2) %.4f (ratio %.5f)\n",
                      integrator == RENDER_PATH ? "path" : "whitted", model, p.x, p.z, got, want, got / want);
        assert_true(want > 1.0);
        assert_near(got / want, 1.0, 0.01);
    }
    ies_free(&d);
    framebuffer_free(&fb);
    scene_destroy(s);
}

static void test_floor_illuminance(void **state)
{
    (void)state;
    check_floor(RENDER_PATH, "rgb");
    check_floor(RENDER_WHITTED, "rgb");
    check_floor(RENDER_PATH, "spectrum");
}

/* The text with the first occurrence of `from` replaced by `to`. */
static char *replaced(const char *text, const char *from, const char *to)
{
    const char *at = strstr(text, from);
    assert_non_null(at);
    char *out = malloc(strlen(text) + strlen(to) + 1);
    assert_non_null(out);
    sprintf(out, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    return out;
}

static void expect_refused(const char *text, const char *where, const char *words)
{
    IesData d;
    GError err;
    gerror_clear(&err);
    int rc = ies_parse(text, strlen(text), "bad.ies", &d, &err);
    print_message("refused: %s\n", err.message);
    assert_true(rc < 0);
    assert_non_null(strstr(err.message, where));
    assert_non_null(strstr(err.message, words));
    assert_null(d.cd);
}

static void test_hostile(void **state)
{
    (void)state;
    /* 5 vertical angles, 1 horizontal: line 4 the counts, 6 the vertical angles, 7 the horizontal, 8 the candela */
    const char *good = "IESNA:LM-63-1995\n[TEST] x\nTILT=NONE\n1 1000 1 5 1 1 2 0 0 0\n1 1 100\n0 22.5 45 67.5 90\n0\n"
                       "100 90 70 40 0\n";
    IesData d;
    parse_ok(good, &d);
    assert_int_equal(d.version, 1995);
    ies_free(&d);
    char *t;
    /* counts that lie: more vertical angles than given (the horizontal angle read as one), more candela values
     * than announced, a table that ends early */
    expect_refused(t = replaced(good, "1 5 1 1", "1 6 1 1"), "bad.ies:7:1:", "does not increase");
    free(t);
    expect_refused(t = replaced(good, "40 0\n", "40 0 7\n"), "bad.ies:8:16:", "after the");
    free(t);
    char *t2 = replaced(good, "1 5 1 1", "1 4 1 1");
    expect_refused(t = replaced(t2, "67.5 90", "67.5"), "bad.ies:8:", "after the");
    free(t);
    free(t2);
    expect_refused(t = replaced(good, "100 90 70 40 0\n", "100 90 70"), "bad.ies:8:10:", "the file ends");
    free(t);
    expect_refused(t = replaced(good, "100 90 70", "100 nan 70"), "bad.ies:8:5:", "not finite");
    free(t);
    expect_refused(t = replaced(good, "100 90 70", "100 1e999 70"), "bad.ies:8:5:", "not finite");
    free(t);
    expect_refused(t = replaced(good, "100 90 70", "100 -90 70"), "bad.ies:8:5:", "outside");
    free(t);
    expect_refused(t = replaced(good, "1 5 1 1", "1 5000000 1 1"), "bad.ies:4:10:", "outside");
    free(t);
    expect_refused(t = replaced(good, "1 5 1 1", "1 1441 1441 1"), "bad.ies:4:", "more than");
    free(t);
    expect_refused(t = replaced(good, "0 22.5 45", "0 45 22.5"), "bad.ies:6:6:", "does not increase");
    free(t);
    expect_refused(t = replaced(good, "0 22.5 45 67.5 90", "0 22.5 45 67.5 190"), "bad.ies:6:16:", "outside");
    free(t);
    expect_refused(t = replaced(good, "1 5 1 1", "1 5 1 3"), "bad.ies:4:", "type A");
    free(t);
    expect_refused(t = replaced(good, "TILT=NONE", "TILT=lamp.tlt"), "bad.ies:3:6:", "another file");
    free(t);
    expect_refused(t = replaced(good, "TILT=NONE", "NO TILT"), "bad.ies:", "TILT=");
    free(t);
    expect_refused(t = replaced(good, "1 5 1 1", "1 5.5 1 1"), "bad.ies:4:10:", "whole number");
    free(t);
    expect_refused(t = replaced(good, "\n0\n", "\n45\n"), "bad.ies:", "horizontal angles");
    free(t);
    /* TILT=INCLUDE: its block read and checked */
    parse_ok(t = replaced(good, "TILT=NONE\n", "TILT=INCLUDE\n1\n2\n0 90\n1 0.9\n"), &d);
    ies_free(&d);
    free(t);
    expect_refused(t = replaced(good, "TILT=NONE\n", "TILT=INCLUDE\n1\n2\n0 95\n1 0.9\n"), "bad.ies:6:3:",
                   "a tilt angle");
    free(t);
    /* a scene naming a bad file: the message names the IES file and line */
    char *bad = write_text("bad.ies", t = replaced(good, "100 90 70", "100 9x 70"));
    free(t);
    char scene[512];
    snprintf(scene, sizeof scene, "light ies { file \"%s\" color illuminant A }\n", bad);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    Scene *s = NULL;
    assert_true(scene_load(write_text("bad.scene", scene), "rgb", &s, &err) < 0);
    print_message("scene: %s\n", err.message);
    assert_non_null(strstr(err.message, "bad.ies:8:5:"));
    const char *nofile = "light ies { position <0, 1, 0> color blackbody 3000 }\n";
    assert_true(scene_load(write_text("nofile.scene", nofile), "rgb", &s, &err) < 0);
    assert_non_null(strstr(err.message, "needs its file"));
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flux),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_floor_illuminance),
        cmocka_unit_test(test_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
