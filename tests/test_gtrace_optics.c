/* test_gtrace_optics.c - optics through the generic interfaces, measured on rendered images and on the
 * tracer's shadow rays:
 *  - dispersion: a 60-degree BK7 prism (Sellmeier) seen against a narrow slit. The slit of a 450, 550 or 650 nm
 *    line (spectrum model, every band its own ray) appears where Snell's law with the Sellmeier index sends it,
 *    within 0.05 degrees of deviation; in rgb the three primaries land where the indices at 610, 550 and 465 nm
 *    say; a white slit becomes a spectrum whose hue runs from red to violet monotonically; a constant index
 *    does not split and renders the same with any band count;
 *  - shadows through glass: the light a glass sphere lets through to the plane under it is the two-interface
 *    Fresnel transmittance T(theta)^2 of the straight chord, continuous across the radius where the straight
 *    path would meet total internal reflection;
 *  - what a shadow ray meets (accel_occluded): clear, a surface that blocks all light (no walk needed), or
 *    surfaces that may let light through, for analytic shapes and Embree's own triangles. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"

#include <unistd.h>

#define BK7 "sellmeier 1.03961212 0.231792344 1.01046945 0.00600069867 0.0200179144 103.560653"

static double bk7(double nm)
{
    const double b[3] = {1.03961212, 0.231792344, 1.01046945}, c[3] = {0.00600069867, 0.0200179144, 103.560653};
    GDispersion d = gdispersion_sellmeier(b, c);
    return gdispersion_index(&d, nm);
}

/* ---- the prism: a 60-degree prism, axis along y, seen by a camera at the origin looking down -z ---- */

#define APEX_DEG 60.0
#define PRISM_Z (-3.0)
#define SLIT_DIST 40.0
#define WIDTH 1200
#define HEIGHT 2 /* the strip; row ROW is measured */
#define ROW 1
#define HFOV_DEG 12.0

/* The prism's cross-section in the xz-plane: the entrance face meets the camera's axis at the minimum-deviation
 * incidence for 550 nm, the exit ray leaves towards -x. corner[0] is the apex. */
typedef struct Prism {
    double corner[3][2]; /* (x, z) */
    GVec3 slit;          /* the slit's centre */
} Prism;

static GVec3 rot_y(GVec3 v, double a) { return gvec3(cos(a) * v.x + sin(a) * v.z, v.y, -sin(a) * v.x + cos(a) * v.z); }

static Prism make_prism(void)
{
    Prism p;
    const double s = 1.4, h = s * sqrt(3.0) / 2.0, A = APEX_DEG * M_PI / 180.0;
    /* local frame: light travels along +u, apex towards +w; the entrance face's inward normal is at -30 degrees */
    double n = bk7(550.0), i_min = asin(n * sin(A / 2.0)); /* incidence at minimum deviation */
    double beta = i_min - M_PI / 6.0;                      /* the incoming ray's angle above +u */
    double loc[3][2] = {{0.0, 2.0 * h / 3.0}, {-s / 2.0, -h / 3.0}, {s / 2.0, -h / 3.0}};
    /* rotate the local frame by -beta so that the incoming ray is along +u, then u -> -z, w -> +x */
    for (int k = 0; k < 3; k++) {
        double u = cos(beta) * loc[k][0] + sin(beta) * loc[k][1], w = -sin(beta) * loc[k][0] + cos(beta) * loc[k][1];
        p.corner[k][0] = w;
        p.corner[k][1] = PRISM_Z - u;
    }
    double dev = 2.0 * i_min - A; /* the exit ray turns towards the base (-w, that is -x) by dev */
    GVec3 out = rot_y(gvec3(0, 0, -1), dev);
    p.slit = gvec3_madd(gvec3(0, 0, PRISM_Z), out, SLIT_DIST);
    return p;
}

/* The prism as an OBJ solid (faces wound counter-clockwise seen from outside). */
static void write_prism_obj(const Prism *p, const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int y = 0; y < 2; y++)
        for (int k = 0; k < 3; k++)
            fprintf(f, "v %.17g %d %.17g\n", p->corner[k][0], y ? 2 : -2, p->corner[k][1]);
    /* orient each face by the cross product against the outward direction from the centroid */
    double cx = (p->corner[0][0] + p->corner[1][0] + p->corner[2][0]) / 3.0;
    double cz = (p->corner[0][1] + p->corner[1][1] + p->corner[2][1]) / 3.0;
    int faces[5][4] = {{1, 2, 3, 0}, {4, 5, 6, 0}, {1, 2, 5, 4}, {2, 3, 6, 5}, {3, 1, 4, 6}};
    for (int fi = 0; fi < 5; fi++) {
        int nv = faces[fi][3] ? 4 : 3;
        GVec3 v[4], c = gvec3(0, 0, 0);
        for (int j = 0; j < nv; j++) {
            int id = faces[fi][j] - 1;
            v[j] = gvec3(p->corner[id % 3][0], id >= 3 ? 2 : -2, p->corner[id % 3][1]);
            c = gvec3_add(c, gvec3_scale(v[j], 1.0 / nv));
        }
        GVec3 nrm = gvec3_cross(gvec3_sub(v[1], v[0]), gvec3_sub(v[2], v[0]));
        int flip = gvec3_dot(nrm, gvec3_sub(c, gvec3(cx, 0, cz))) < 0.0;
        fprintf(f, "f");
        for (int j = 0; j < nv; j++)
            fprintf(f, " %d", faces[fi][flip ? nv - 1 - j : j]);
        fprintf(f, "\n");
    }
    fclose(f);
}

/* Renders the prism scene: a WIDTH x 1 strip, the slit emitting `radiance`, the prism's index `index`. */
static void render_prism(const char *model, const char *radiance, const char *index, int bands, Framebuffer *fb,
                         Camera *cam_out)
{
    Prism p = make_prism();
    char *obj = temp_path("prism.obj");
    write_prism_obj(&p, obj);
    /* vertical fov of a strip HEIGHT pixels high whose horizontal fov is HFOV_DEG */
    double vfov = 2.0 * atan(tan(HFOV_DEG * M_PI / 360.0) * HEIGHT / WIDTH) * 180.0 / M_PI;
    char text[2048];
    snprintf(text, sizeof text,
             "colormodel %s\n"
             "camera pinhole { from <0, 0, 0> at <0, 0, -1> fov %.17g width %d height %d spp 1 depth 4 bands %d }\n"
             "object mesh { file \"%s\" material dielectric { index %s } }\n"
             "object cylinder { base <%.17g, -5, %.17g> top <%.17g, 5, %.17g> radius 0.006\n"
             "                  material emitter { radiance %s } }\n",
             model, vfov, WIDTH, HEIGHT, bands, obj, index, p.slit.x, p.slit.z, p.slit.x, p.slit.z, radiance);
    char *path = temp_path("prism.scene");
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    Scene *s = NULL;
    GError err;
    if (scene_load(path, NULL, &s, &err) != G_OK)
        fail_msg("%s", err.message);
    unlink(path);
    unlink(obj);
    GError e2;
    assert_int_equal(accel_build(s, &e2), G_OK);
    RenderSettings rs = {.width = WIDTH, .height = HEIGHT, .spp = 1, .depth = 4, .threads = 2, .quiet = 1,
                         .cutoff = 0.0, .bands = s->camera.bands};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    *cam_out = s->camera;
    camera_setup(cam_out, WIDTH, HEIGHT);
    scene_destroy(s);
}

/* Snell's law in vector form (n1 / n2 = eta); 0 on total internal reflection. */
static int snell(GVec3 d, GVec3 n, double eta, GVec3 *t)
{
    if (gvec3_dot(d, n) > 0.0)
        n = gvec3_neg(n);
    double ci = -gvec3_dot(d, n), s2 = eta * eta * (1.0 - ci * ci);
    if (s2 > 1.0)
        return 0;
    *t = gvec3_normalize(gvec3_add(gvec3_scale(d, eta), gvec3_scale(n, eta * ci - sqrt(1.0 - s2))));
    return 1;
}

/* Crosses the plane of the prism face from corner a to corner b: the hit point of (o, d). */
static GVec3 face_hit(const Prism *p, int a, int b, GVec3 o, GVec3 d, GVec3 *normal)
{
    GVec3 pa = gvec3(p->corner[a][0], 0, p->corner[a][1]), pb = gvec3(p->corner[b][0], 0, p->corner[b][1]);
    GVec3 e = gvec3_sub(pb, pa);
    *normal = gvec3_normalize(gvec3(-e.z, 0, e.x));
    double t = gvec3_dot(gvec3_sub(pa, o), *normal) / gvec3_dot(d, *normal);
    return gvec3_madd(o, d, t);
}

/* The exit direction of the camera ray through pixel column x (continuous) for index n; *hit_x is where it
 * crosses the slit's plane, measured across the exit direction of 550 nm from the slit's centre. */
static GVec3 analytic_exit(const Camera *cam, const Prism *p, double x, double n, double *across)
{
    Ray r;
    camera_ray(cam, x, ROW + 0.5, &r);
    GVec3 n1, n2, t1, t2;
    /* the entrance face is apex-corner1 (the side the camera sees), the exit face corner2-apex */
    GVec3 h1 = face_hit(p, 0, 1, r.o, r.d, &n1);
    assert_true(snell(r.d, n1, 1.0 / n, &t1));
    GVec3 h2 = face_hit(p, 2, 0, h1, t1, &n2);
    assert_true(snell(t1, n2, n, &t2));
    GVec3 axis = gvec3_normalize(gvec3_sub(p->slit, gvec3(0, 0, PRISM_Z)));
    double t = gvec3_dot(gvec3_sub(p->slit, h2), axis) / gvec3_dot(t2, axis);
    GVec3 at = gvec3_madd(h2, t2, t);
    GVec3 side = gvec3_cross(axis, gvec3(0, 1, 0));
    *across = gvec3_dot(gvec3_sub(at, p->slit), side);
    return t2;
}

/* The column where the analytic ray of index n meets the slit's centre (bisection over the strip). */
static double predicted_column(const Camera *cam, const Prism *p, double n)
{
    double lo = 0.0, hi = WIDTH, alo, ahi, amid;
    analytic_exit(cam, p, lo, n, &alo);
    analytic_exit(cam, p, hi, n, &ahi);
    assert_true(alo * ahi < 0.0);
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi);
        analytic_exit(cam, p, mid, n, &amid);
        if ((amid < 0.0) == (alo < 0.0)) {
            lo = mid;
            alo = amid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

/* The centroid of a channel weight over the strip (pixel centres at x + 0.5); fails when nothing is lit. */
static double centroid(const Framebuffer *fb, const double w[3])
{
    double sum = 0.0, sx = 0.0, peak = 0.0;
    for (int x = 0; x < fb->width; x++) {
        const float *px = pixel(fb, x, ROW);
        double v = fabs(w[0] * px[0] + w[1] * px[1] + w[2] * px[2]);
        peak = fmax(peak, v);
        sum += v;
        sx += v * (x + 0.5);
    }
    if (!(sum > 0.0))
        fail_msg("the slit is not in the picture");
    /* the slit covers a few pixels, the rest is black */
    assert_true(peak > 1e-3);
    return sx / sum;
}

/* The angle in degrees between the exit directions of columns a and b for index n. */
static double deviation_error(const Camera *cam, const Prism *p, double a, double b, double n)
{
    double dummy;
    GVec3 ea = analytic_exit(cam, p, a, n, &dummy), eb = analytic_exit(cam, p, b, n, &dummy);
    return acos(fmin(1.0, gvec3_dot(ea, eb))) * 180.0 / M_PI;
}

static void check_line(const char *model, const char *radiance, double nm_index, int bands, const double w[3])
{
    Framebuffer fb;
    Camera cam;
    render_prism(model, radiance, BK7, bands, &fb, &cam);
    Prism p = make_prism();
    double n = bk7(nm_index);
    double want = predicted_column(&cam, &p, n), got = centroid(&fb, w);
    double err = deviation_error(&cam, &p, want, got, n);
    print_message("%s, %s: slit at column %.2f, Snell with n = %.5f says %.2f: %.4f degrees apart\n", model, radiance,
                  got, n, want, err);
    if (!(err < 0.05))
        fail_msg("%s %s: the deviation is %.4f degrees off Snell's law with the Sellmeier index", model, radiance, err);
    /* a shift of one band's index moves the slit by more than the tolerance: the test sees dispersion */
    double other = predicted_column(&cam, &p, bk7(nm_index + 50.0));
    assert_true(deviation_error(&cam, &p, want, other, n) > 0.1);
    framebuffer_free(&fb);
}

static const double Y_WEIGHTS[3] = {0.2126, 0.7152, 0.0722};

static void test_prism_lines_spectrum(void **state)
{
    (void)state;
    check_line("spectrum", "scale 50 line 450", 450.0, 81, Y_WEIGHTS);
    check_line("spectrum", "scale 50 line 550", 550.0, 81, Y_WEIGHTS);
    check_line("spectrum", "scale 50 line 650", 650.0, 81, Y_WEIGHTS);
}

static void test_prism_rgb_bands(void **state)
{
    (void)state;
    const double r[3] = {1, 0, 0}, g[3] = {0, 1, 0}, b[3] = {0, 0, 1};
    check_line("rgb", "rgb 5 0 0", 610.0, 3, r);
    check_line("rgb", "rgb 0 5 0", 550.0, 3, g);
    check_line("rgb", "rgb 0 0 5", 465.0, 3, b);
}

/* The hue of a linear RGB pixel: its angle in the opponent plane, in degrees. */
static double hue_of(const float *px)
{
    return atan2(sqrt(3.0) * (px[1] - px[2]), 2.0 * px[0] - px[1] - px[2]) * 180.0 / M_PI;
}

/* A white slit through the prism: across the lit columns the hue (unwrapped) runs one way only, through more
 * than 180 degrees, from red (least deviated) to violet. */
static void test_prism_white_spectrum(void **state)
{
    (void)state;
    Framebuffer fb;
    Camera cam;
    render_prism("spectrum", "scale 20 illuminant E", BK7, 81, &fb, &cam);
    double peak = 0.0;
    for (int x = 0; x < fb.width; x++)
        peak = fmax(peak, luma(pixel(&fb, x, ROW)));
    assert_true(peak > 0.0);
    int lit = 0, up = 0, down = 0, first = -1, last = -1;
    double h0 = 0.0, prev = 0.0;
    for (int x = 0; x < fb.width; x++) {
        const float *px = pixel(&fb, x, ROW);
        if (!(luma(px) > 0.05 * peak))
            continue;
        double h = hue_of(px);
        if (lit == 0) {
            h0 = h;
            first = x;
        } else {
            while (h < prev - 180.0)
                h += 360.0;
            while (h > prev + 180.0)
                h -= 360.0;
            up += h > prev + 0.5;
            down += h < prev - 0.5;
        }
        prev = h;
        last = x;
        lit++;
    }
    print_message("white slit: %d lit columns (%d..%d), hue from %.1f to %.1f degrees; steps up %d, down %d\n", lit,
                  first, last, h0, prev, up, down);
    assert_true(lit > 40);
    assert_true(fabs(prev - h0) > 180.0);
    assert_true(up == 0 || down == 0);
    /* red is the least deviated end: its hue is the one nearer 0 */
    const float *red_end = pixel(&fb, fabs(remainder(h0, 360.0)) < fabs(remainder(prev, 360.0)) ? first : last, ROW);
    assert_true(red_end[0] > red_end[1] && red_end[0] > red_end[2]);
    framebuffer_free(&fb);
}

/* A constant index never splits: the picture with 1 band and with 81 is the same, bit for bit. */
static void test_constant_index_does_not_split(void **state)
{
    (void)state;
    Framebuffer a, b;
    Camera cam;
    render_prism("spectrum", "scale 20 illuminant E", "1.5", 1, &a, &cam);
    render_prism("spectrum", "scale 20 illuminant E", "1.5", 81, &b, &cam);
    assert_memory_equal(a.pixels, b.pixels, sizeof(float) * 3 * WIDTH * HEIGHT);
    framebuffer_free(&a);
    framebuffer_free(&b);
}

/* ---- shadows through glass ---- */

/* The light a glass sphere (radius 1, index 1.5, centre 3 above the plane y = 0) lets through to the plane
 * point at distance r from the axis, from a light straight above. */
static double sphere_shadow(Scene *s, double r)
{
    TraceCtx c = {.scene = s, .max_depth = 2, .cutoff = 0.0, .band = -1};
    c.scratch = gscratch_create(0);
    assert_non_null(c.scratch);
    Ray down = {gvec3(r, 0.5, 0.0), gvec3(0, -1, 0), 0.0, INFINITY, 0.0, 0.0};
    Hit h;
    assert_true(accel_intersect(s, &down, &h));
    Media none = {{NULL}, 0};
    GSurfPoint sp;
    GVec3 facing;
    surfpoint_fill(&c, &down, &h, &none, &sp, &facing);
    GColor light;
    assert_int_equal(gcolor_alloc(&light, s->model), G_OK);
    assert_int_equal(gcolor_fill(&light, 1.0), G_OK);
    int visible = 0;
    assert_int_equal(light_transmit(&c, &sp, facing, &none, gvec3(0, 1, 0), INFINITY, &light, &visible), G_OK);
    double t = visible ? gcolor_brightness(&light) : 0.0;
    gcolor_free(&light);
    gscratch_destroy(c.scratch);
    return t;
}

static void check_glass_shadow(const char *model)
{
    Scene *s = new_scene(model, gvec3(0, 5, 5), gvec3(0, 0, 0), 40.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, glass(s, 1.5), gvec3(0, 3, 0), 1.0);
    GError err;
    assert_int_equal(accel_build(s, &err), G_OK);
    double worst = 0.0, prev = -1.0, max_step = 0.0;
    for (int k = 0; k < 400; k++) {
        double r = (k + 0.5) / 400.0 * 0.999;
        double t = sphere_shadow(s, r);
        /* the straight chord enters and leaves at theta = asin(r); the real path at the same outside angle */
        double cos_t = sqrt(1.0 - r * r), T = 1.0 - goptics_fresnel(cos_t, 1.0 / 1.5);
        worst = fmax(worst, fabs(t - T * T));
        if (prev >= 0.0 && r < 0.95) /* (nearer the rim T falls steeply towards 0 at grazing incidence) */
            max_step = fmax(max_step, fabs(t - prev));
        prev = t;
        if (!(t >= T * T - 1e-3))
            fail_msg("%s: at r = %.4f the shadow lets %.5f through, below the Fresnel bound %.5f", model, r, t, T * T);
    }
    print_message("%s: |shadow - T^2| <= %.2g, largest step between neighbours %.3g\n", model, worst, max_step);
    assert_true(worst < 2e-3);
    /* continuous: no jump at r = 1/1.5, where a straight path would be totally reflected */
    assert_true(max_step < 0.05);
    assert_true(sphere_shadow(s, 0.8) > 0.5);
    scene_destroy(s);
}

static void test_glass_shadow(void **state)
{
    (void)state;
    check_glass_shadow("rgb");
    check_glass_shadow("spectrum");
}

/* The occlusion of the segment from (x, 0, 5) along -z over length len. */
static int occlusion(Scene *s, double x, double len)
{
    GError err;
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    Ray r = {gvec3(x, 0, 5), gvec3(0, 0, -1), 0.0, len, 0.0, 0.0};
    return accel_occluded(s, &r);
}

/* A triangle across the z axis at height z. */
static void add_triangle(Scene *s, GMaterial *m, double z)
{
    Object *o = object_new(SHAPE_TRIANGLE, m);
    gmaterial_unref(m);
    GError err;
    assert_int_equal(object_triangle(o, gvec3(-1, -1, z), gvec3(1, -1, z), gvec3(0, 1, z), &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
}

static void test_occlusion_kinds(void **state)
{
    (void)state;
    /* an opaque sphere: blocked outright; beside it: clear */
    Scene *s = new_scene("rgb", gvec3(0, 0, 8), gvec3(0, 0, 0), 40.0);
    add_sphere(s, lambert(s, 0.5), gvec3(0, 0, -2), 1.0);
    assert_int_equal(occlusion(s, 0.0, 10.0), OCCLUDED_OPAQUE);
    assert_int_equal(occlusion(s, 3.0, 10.0), OCCLUDED_CLEAR);
    assert_int_equal(occlusion(s, 0.0, 5.0), OCCLUDED_CLEAR); /* ends before the sphere */
    /* glass alone on the segment (it ends before the opaque sphere): passable; glass in front of the opaque
     * sphere: whichever of the two Embree meets first ends the query, so blocked or passable, never clear */
    add_sphere(s, glass(s, 1.5), gvec3(0, 0, 2), 1.0);
    accel_release(s);
    assert_int_equal(occlusion(s, 0.0, 5.0), OCCLUDED_PASSABLE);
    assert_int_not_equal(occlusion(s, 0.0, 10.0), OCCLUDED_CLEAR);
    assert_int_equal(occlusion(s, 1.5, 10.0), OCCLUDED_CLEAR); /* beside the glass, above the opaque sphere's edge */
    scene_destroy(s);
    /* Embree's own triangles: an opaque one blocks; a glass one anywhere makes every blocking by them passable */
    s = new_scene("rgb", gvec3(0, 0, 8), gvec3(0, 0, 0), 40.0);
    add_triangle(s, lambert(s, 0.5), 0.0);
    assert_int_equal(occlusion(s, 0.0, 10.0), OCCLUDED_OPAQUE);
    assert_int_equal(occlusion(s, 5.0, 10.0), OCCLUDED_CLEAR);
    assert_int_equal(s->native_may_pass, 0);
    add_triangle(s, glass(s, 1.5), 3.0);
    accel_release(s);
    assert_int_equal(occlusion(s, 0.0, 10.0), OCCLUDED_PASSABLE);
    assert_int_equal(s->native_may_pass, 1);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prism_lines_spectrum),
        cmocka_unit_test(test_prism_rgb_bands),
        cmocka_unit_test(test_prism_white_spectrum),
        cmocka_unit_test(test_constant_index_does_not_split),
        cmocka_unit_test(test_glass_shadow),
        cmocka_unit_test(test_occlusion_kinds),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
