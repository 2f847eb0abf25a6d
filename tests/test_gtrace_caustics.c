/* test_gtrace_caustics.c - what the particle integrators (integrators/sppm.c, integrators/light.c) render that the
 * others cannot, against numbers computed here independently: a prism's deviation per wavelength against Snell's
 * law with the kit's Sellmeier index of BK7, the light inside a glass ball's shadow against the power the ball
 * transmits there (a ray tree through the sphere with Fresnel weights), the glass ball's focus and the diffuse
 * Cornell box in every colour model, the re-radiated light of a fluorescent screen in bispectral, and the light of
 * glowing geometry and of a probe (particles from both) against the path tracer. */
#include "test_gtrace_common.h"
#include "integrators/sppm.h"
#include "generic/builtins.h"
#include "generic/kit/dispersion.h"
#include "generic/services/probe.h"

/* ---- helpers ---- */

/* Loads the scene in `text` (written to temp_path(name)) in `model` (NULL: the file's) and builds its accelerator;
 * skips the test when the model is not registered. */
static Scene *load_text(const char *name, const char *text, const char *model)
{
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    if (model) {
        GColorModel *m = model_or_skip(model);
        gcolormodel_destroy(m);
    }
    Scene *s = NULL;
    if (scene_load(write_text(name, text), model, &s, &err) != G_OK)
        fail_msg("%s: %s", name, err.message);
    if (accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    return s;
}

/* Loads a scene of the source tree (GENERIC_SOURCE_DIR, else the working directory) in `model`. */
static Scene *load_source_scene(const char *rel, const char *model)
{
    const char *root = getenv("GENERIC_SOURCE_DIR");
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", root ? root : ".", rel);
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    GColorModel *m = model_or_skip(model);
    gcolormodel_destroy(m);
    Scene *s = NULL;
    if (scene_load(path, model, &s, &err) != G_OK)
        fail_msg("%s: %s", path, err.message);
    if (accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    return s;
}

/* Settings of a small render by `integrator` with `passes` passes of `photons` particle paths. */
static RenderSettings settings(int w, int h, int integrator, int passes, long photons)
{
    return (RenderSettings){.width = w, .height = h, .spp = 1, .depth = 8, .threads = 2, .quiet = 1,
                            .integrator = integrator, .sppm_passes = passes, .sppm_photons = photons};
}

static void render_ok(const Scene *s, const RenderSettings *rs, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    RenderStats st;
    if (render_image(s, rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    assert_int_equal(st.nonfinite, 0);
}

/* The image-plane point of pixel coordinates (x, y) (0..w, 0..h) as a unit direction from the eye. */
static GVec3 pixel_dir(const Camera *cam, double x, double y, int w, int h)
{
    double u = (2.0 * x / w - 1.0) * cam->half_w, v = (1.0 - 2.0 * y / h) * cam->half_h;
    return gvec3_normalize(gvec3_add(cam->forward, gvec3_add(gvec3_scale(cam->right, u), gvec3_scale(cam->upv, v))));
}

/* The colour models the ball and the Cornell box are rendered in: all four; under the address sanitizer (ten times
 * slower) the first and the last, whose code paths the middle two share. */
static const char *const models[] = {"rgb", "spectrum", "spectrum9", "bispectral"};
#ifdef __SANITIZE_ADDRESS__
static const size_t model_step = 3;
#else
static const size_t model_step = 1;
#endif

/* ---- the prism: a collimated slit beam through a 60 degree BK7 prism onto a screen ---- */

typedef struct V2 {
    double x, z;
} V2;

static V2 v2(double x, double z) { return (V2){x, z}; }
static V2 v2_sub(V2 a, V2 b) { return v2(a.x - b.x, a.z - b.z); }
static V2 v2_madd(V2 a, V2 d, double t) { return v2(a.x + d.x * t, a.z + d.z * t); }
static double v2_dot(V2 a, V2 b) { return a.x * b.x + a.z * b.z; }
static double v2_cross(V2 a, V2 b) { return a.x * b.z - a.z * b.x; }

/* Refracts unit d at a surface of unit normal nrm (against d) from index n1 into n2; 0 at total reflection. */
static int v2_refract(V2 d, V2 nrm, double n1, double n2, V2 *out)
{
    double eta = n1 / n2, ci = -v2_dot(d, nrm), k = 1.0 - eta * eta * (1.0 - ci * ci);
    if (k < 0.0)
        return 0;
    *out = v2_madd(v2(d.x * eta, d.z * eta), nrm, eta * ci - sqrt(k));
    return 1;
}

/* The nearest crossing (t > 1e-9) of the ray o + t d with the triangle tri's edges, its outward normal. */
static double v2_hit_triangle(const V2 tri[3], V2 o, V2 d, V2 *normal)
{
    double best = INFINITY;
    V2 c = v2((tri[0].x + tri[1].x + tri[2].x) / 3, (tri[0].z + tri[1].z + tri[2].z) / 3);
    for (int k = 0; k < 3; k++) {
        V2 a = tri[k], e = v2_sub(tri[(k + 1) % 3], a);
        double den = v2_cross(d, e);
        if (fabs(den) < 1e-15)
            continue;
        V2 ao = v2_sub(a, o);
        double t = v2_cross(ao, e) / den, s = v2_cross(ao, d) / den;
        if (t > 1e-9 && s >= 0.0 && s <= 1.0 && t < best) {
            best = t;
            V2 nn = v2(e.z, -e.x);
            double len = sqrt(v2_dot(nn, nn));
            nn = v2(nn.x / len, nn.z / len);
            if (v2_dot(nn, v2_sub(a, c)) < 0.0)
                nn = v2(-nn.x, -nn.z);
            *normal = nn;
        }
    }
    return best;
}

/* Snell's law through the prism: the ray along +x from origin o, refracted in and out at index n; the exit point
 * and direction. */
static void prism_exit(const V2 tri[3], V2 o, double n, V2 *exit_point, V2 *exit_dir)
{
    V2 d = v2(1, 0), nrm, inside, out;
    double t = v2_hit_triangle(tri, o, d, &nrm);
    assert_true(isfinite(t));
    assert_true(v2_refract(d, nrm, 1.0, n, &inside));
    V2 p = v2_madd(o, d, t);
    t = v2_hit_triangle(tri, p, inside, &nrm);
    assert_true(isfinite(t));
    p = v2_madd(p, inside, t);
    assert_true(v2_refract(inside, v2(-nrm.x, -nrm.z), n, 1.0, &out));
    *exit_point = p;
    *exit_dir = out;
}

static double deviation_deg(V2 d) { return atan2(-d.z, d.x) * 180.0 / M_PI; }

static void test_prism_deviation(void **state)
{
    int integrator = (int)(intptr_t)*state;
    const GGlass *bk7 = gdispersion_glass_find("BK7");
    assert_non_null(bk7);
    /* The prism, apex edge vertical: an equilateral triangle of side 0.8 in the x-z plane, turned so that the beam
     * (along +x through the origin) meets its first face at the incidence of minimum deviation for 550 nm. */
    double n550 = gdispersion_index(&bk7->formula, 550.0), side = 0.8, hgt = side * sqrt(3.0) / 2.0;
    double inc = asin(n550 * 0.5), phi = inc - M_PI / 6.0;
    V2 local[3] = {v2(0, hgt), v2(-side / 2, 0), v2(side / 2, 0)}; /* beam enters the apex-to-(-side/2) face */
    V2 entry = v2(-side / 4, hgt / 2), tri[3];
    for (int k = 0; k < 3; k++) { /* turn by -phi about the entry point, which goes to the origin */
        V2 p = v2_sub(local[k], entry);
        tri[k] = v2(p.x * cos(phi) + p.z * sin(phi), -p.x * sin(phi) + p.z * cos(phi));
    }
    char obj[1024];
    int len = 0;
    for (int k = 0; k < 6; k++)
        len += snprintf(obj + len, sizeof obj - (size_t)len, "v %.9f %.3f %.9f\n", tri[k % 3].x, k < 3 ? -0.3 : 0.3,
                        tri[k % 3].z);
    /* faces wound counter-clockwise seen from outside */
    int ccw = v2_cross(v2_sub(tri[1], tri[0]), v2_sub(tri[2], tri[0])) > 0.0; /* seen from +y: clockwise */
    len += snprintf(obj + len, sizeof obj - (size_t)len, ccw ? "f 1 2 3\nf 6 5 4\n" : "f 3 2 1\nf 4 5 6\n");
    for (int k = 0; k < 3; k++) {
        int a = k + 1, b = (k + 1) % 3 + 1;
        if (ccw)
            len += snprintf(obj + len, sizeof obj - (size_t)len, "f %d %d %d %d\n", b, a, a + 3, b + 3);
        else
            len += snprintf(obj + len, sizeof obj - (size_t)len, "f %d %d %d %d\n", a, b, b + 3, a + 3);
    }
    write_text("prism.obj", obj);
    /* the screen: 3 units from the 550 nm exit point, across that ray; the camera 1 unit in front of it */
    V2 e550, d550;
    prism_exit(tri, v2(-1, 0), n550, &e550, &d550);
    double dist = 3.0;
    V2 sc = v2_madd(e550, d550, dist), eye = v2_madd(e550, d550, dist - 1.0);
    int w = 128, h = 12;
    char text[4096];
    snprintf(text, sizeof text,
             "colormodel spectrum\n"
             "material bk7 dielectric { index glass BK7 }\n"
             "material black lambert { reflectance rgb 0 0 0 }\n"
             "object mesh { file \"gtrace_test_%d_prism.obj\" material bk7 }\n"
             /* the slit: 4 mm wide, across the beam, in front of the prism */
             "object box { min <-0.31, -0.5, -0.5> max <-0.3, 0.5, -0.002> material black }\n"
             "object box { min <-0.31, -0.5, 0.002> max <-0.3, 0.5, 0.5> material black }\n"
             "object disc { center <%.9f, 0, %.9f> normal <%.9f, 0, %.9f> radius 0.4 "
             "material lambert { reflectance rgb 0.8 0.8 0.8 } }\n"
             /* nearly collimated: a spot of 0.01 degrees 100 units away (a beam 35 mm across) */
             "light spot { position <-100, 0, 0> at <0, 0, 0> intensity scale 10000 illuminant E inner 0.005 "
             "outer 0.01 }\n"
             "camera pinhole { from <%.9f, 0, %.9f> at <%.9f, 0, %.9f> fov %.6f width %d height %d }\n",
             (int)getpid(), sc.x, sc.z, -d550.x, -d550.z, eye.x, eye.z, sc.x, sc.z,
             2.0 * atan(0.5 * h / w * 0.12) * 180.0 / M_PI, w, h);
    Scene *s = load_text("prism.scene", text, NULL);
    RenderSettings rs = settings(w, h, integrator, 6, 50000);
    rs.bands = 81;
    rs.waves = 1;
    Framebuffer fb;
    render_ok(s, &rs, &fb);
    Camera cam = s->camera;
    camera_setup(&cam, w, h);
    const double nm[3] = {450.0, 550.0, 650.0};
    for (int c = 0; c < 3; c++) {
        int k = -1;
        for (int i = 0; i < fb.nwaves; i++)
            if (fabs(fb.wavelengths[i] - nm[c]) < 1e-6)
                k = i;
        assert_true(k >= 0);
        /* the channel's column sums; its peak, refined by the centroid of the columns around it */
        double col[128] = {0}, total = 0.0;
        int peak = 0;
        for (int x = 0; x < w; x++) {
            for (int y = 0; y < h; y++)
                col[x] += fb.waves[((size_t)y * (size_t)w + (size_t)x) * (size_t)fb.nwaves + (size_t)k];
            total += col[x];
            if (col[x] > col[peak])
                peak = x;
        }
        assert_true(total > 0.0);
        double sum = 0.0, mom = 0.0;
        for (int x = peak - 4; x <= peak + 4; x++)
            if (x >= 0 && x < w)
                sum += col[x], mom += col[x] * (x + 0.5);
        double px = mom / sum;
        /* where that column's centre ray meets the screen, and the direction from the exit point there */
        GVec3 d = pixel_dir(&cam, px, 0.5 * h, w, h);
        GVec3 nrm = gvec3(d550.x, 0, d550.z);
        double t = gvec3_dot(gvec3_sub(gvec3(sc.x, 0, sc.z), cam.eye), nrm) / gvec3_dot(d, nrm);
        GVec3 hit = gvec3_madd(cam.eye, d, t);
        double n = gdispersion_index(&bk7->formula, nm[c]);
        V2 ep, ed;
        prism_exit(tri, v2(-1, 0), n, &ep, &ed);
        double want = deviation_deg(ed), got = deviation_deg(v2_sub(v2(hit.x, hit.z), ep));
        print_message("%.0f nm: n %.6f, Snell deviation %.4f deg, measured %.4f deg (peak column %.2f, %.1f%% of "
                      "the channel within the peak)\n", nm[c], n, want, got, px, 100.0 * sum / total);
        assert_near(got, want, 0.05);
        assert_true(sum > 0.8 * total); /* one peak, not a smear */
    }
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- the light in a glass ball's shadow ---- */

/* A ray tree through the sphere (centre c, radius r, index n in air) with unpolarised Fresnel weights, to depth
 * `depth`: adds weight to *in of every leaving ray that meets the floor y = 0 inside the region `inside`
 * decides, and to *down every leaving ray that meets the floor. */
typedef int (*RegionTest)(GVec3 p);

static double fresnel_unpolarised(double ci, double n1, double n2)
{
    double s2 = (n1 / n2) * (n1 / n2) * (1.0 - ci * ci);
    if (s2 >= 1.0)
        return 1.0;
    double ct = sqrt(1.0 - s2);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct), rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 0.5 * (rs * rs + rp * rp);
}

static void leave_ball(GVec3 o, GVec3 d, double weight, RegionTest inside, double *in, double *down)
{
    if (d.y >= 0.0)
        return;
    GVec3 p = gvec3_madd(o, d, -o.y / d.y);
    *down += weight;
    if (inside(p))
        *in += weight;
}

static void ball_tree(GVec3 c, double r, double n, GVec3 o, GVec3 d, int in_glass, double weight, int depth,
                      RegionTest inside, double *in, double *down)
{
    if (weight < 1e-9 || depth < 0)
        return;
    GVec3 oc = gvec3_sub(o, c);
    double b = gvec3_dot(oc, d), cc = gvec3_dot(oc, oc) - r * r, disc = b * b - cc;
    if (!in_glass && (disc <= 0.0 || -b - sqrt(fmax(0.0, disc)) <= 1e-12)) {
        leave_ball(o, d, weight, inside, in, down);
        return;
    }
    double t = in_glass ? -b + sqrt(fmax(0.0, disc)) : -b - sqrt(disc);
    GVec3 p = gvec3_madd(o, d, t), nrm = gvec3_scale(gvec3_sub(p, c), 1.0 / r);
    if (in_glass)
        nrm = gvec3_neg(nrm); /* against d */
    double ci = -gvec3_dot(d, nrm), n1 = in_glass ? n : 1.0, n2 = in_glass ? 1.0 : n;
    double fr = fresnel_unpolarised(ci, n1, n2);
    GVec3 refl = gvec3_madd(d, nrm, 2.0 * ci);
    if (in_glass)
        ball_tree(c, r, n, p, refl, 1, weight * fr, depth - 1, inside, in, down);
    else
        leave_ball(p, refl, weight * fr, inside, in, down);
    if (fr < 1.0) {
        double eta = n1 / n2, k = 1.0 - eta * eta * (1.0 - ci * ci);
        GVec3 tr = gvec3_normalize(gvec3_madd(gvec3_scale(d, eta), nrm, eta * ci - sqrt(k)));
        if (in_glass)
            leave_ball(p, tr, weight * (1.0 - fr), inside, in, down);
        else
            ball_tree(c, r, n, p, tr, 1, weight * (1.0 - fr), depth - 1, inside, in, down);
    }
}

/* The scene: a ball of index 1.5, radius 0.5, centre 1.5 above a grey floor, under a collimated beam 45 degrees
 * from the vertical; the camera straight above the shadow's centre (1.5, 0, 0), clear of the ball. */
#define SH_TILT (M_PI / 4)
#define SH_R 0.5
#define SH_H 1.5
#define SH_RHO 0.1
#define SH_CAM 4.0
/* the part of the shadow measured: the floor points whose line along the beam passes within 0.85 R of the centre */
#define SH_REGION (0.85 * SH_R)

static int in_shadow_region(GVec3 p)
{
    GVec3 l = gvec3(sin(SH_TILT), -cos(SH_TILT), 0), v = gvec3_sub(p, gvec3(0, SH_H, 0));
    GVec3 perp = gvec3_madd(v, l, -gvec3_dot(v, l));
    return gvec3_dot(perp, perp) < SH_REGION * SH_REGION;
}

static const char shadow_scene[] =
    "colormodel rgb\n"
    "camera pinhole { from <1.5, 4, 0> at <1.5, 0, 0> up <-1, 0, 0> fov 22 width 64 height 64 }\n"
    "object sphere { center <0, 1.5, 0> radius 0.5 material dielectric { index 1.5 } }\n"
    "object box { min <0.3, -0.05, -0.9> max <2.7, 0, 0.9> material lambert { reflectance rgb 0.1 0.1 0.1 } }\n"
    "light directional { direction <0.70710678, -0.70710678, 0> irradiance rgb 1 1 1 }\n";

static void test_shadow_energy(void **state)
{
    int integrator = (int)(intptr_t)*state;
    /* the power reaching the region, per unit irradiance across the beam: the ray tree over the ball's disc */
    GVec3 l = gvec3(sin(SH_TILT), -cos(SH_TILT), 0), t1, t2, c = gvec3(0, SH_H, 0);
    goptics_frame(l, &t1, &t2);
    int rings = 600, spokes = 96;
    double want = 0.0, down = 0.0, cell = M_PI * SH_R * SH_R / (rings * spokes);
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < spokes; j++) {
            double rad = SH_R * sqrt((i + 0.5) / rings), ph = 2.0 * M_PI * (j + 0.5) / spokes;
            GVec3 o = gvec3_add(gvec3_madd(c, l, -2.0),
                                gvec3_add(gvec3_scale(t1, rad * cos(ph)), gvec3_scale(t2, rad * sin(ph))));
            ball_tree(c, SH_R, 1.5, o, l, 0, cell, 12, in_shadow_region, &want, &down);
        }
    Scene *s = load_text("shadow.scene", shadow_scene, NULL);
    int w = 64, h = 64;
    RenderSettings rs = settings(w, h, integrator, 8, 320000);
    rs.depth = 12;
    Framebuffer fb;
    render_ok(s, &rs, &fb);
    Camera cam = s->camera;
    camera_setup(&cam, w, h);
    /* each pixel's floor area (the floor is parallel to the image plane), its part inside the region by 4 x 4
     * points, irradiance pi L / rho */
    double side = 2.0 * SH_CAM * cam.half_h / h, got = 0.0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int k = 0;
            for (int sy = 0; sy < 4; sy++)
                for (int sx = 0; sx < 4; sx++) {
                    GVec3 d = pixel_dir(&cam, x + (sx + 0.5) / 4, y + (sy + 0.5) / 4, w, h);
                    k += in_shadow_region(gvec3_madd(cam.eye, d, -cam.eye.y / d.y));
                }
            double e = M_PI * luma(pixel(&fb, x, y)) / SH_RHO;
            got += e * side * side * k / 16.0;
        }
    print_message("inside the shadow: measured %.5f, transmitted there %.5f (%+.2f%%); the ball transmits %.5f "
                  "downwards of %.5f on its disc\n", got, want,
                  100.0 * (got - want) / want, down, M_PI * SH_R * SH_R);
    assert_near(got, want, 0.02 * want);
    framebuffer_free(&fb);
    scene_destroy(s);
}

/* ---- the glass ball's focus in every colour model ---- */

static const char ball_scene[] =
    "camera pinhole { from <0, 0.3, 3> at <0, 0, 0> fov 12 width 33 height 25 spp 1 depth 8 }\n"
    "material glass dielectric { index 1.5 }\n"
    "object sphere { center <0, 0.75, 0> radius 0.5 material glass }\n" /* f = 1.5 * 0.5 / 1 = 0.75 */
    "object box { min <-1.5, -0.05, -1.5> max <1.5, 0, 1.5> material lambert { reflectance rgb 0.8 0.8 0.8 } }\n"
    "light directional { direction <0, -1, 0> irradiance rgb 1 1 1 }\n";

static void test_glass_ball_models(void **state)
{
    (void)state;
    for (size_t mi = 0; mi < sizeof models / sizeof *models; mi += model_step) {
        Scene *s = load_text("ball.scene", ball_scene, models[mi]);
        int w = 33, h = 25; /* the focus in the middle of a pixel */
        Framebuffer fb;
        RenderSettings rs = settings(w, h, RENDER_SPPM, 32, 10000);
        rs.sppm_radius = 0.008;
        render_ok(s, &rs, &fb);
        Camera cam = s->camera;
        camera_setup(&cam, w, h);
        GVec3 v = gvec3_sub(gvec3(0, 0, 0), cam.eye);
        double z = gvec3_dot(v, cam.forward);
        double fx = (gvec3_dot(v, cam.right) / (z * cam.half_w) + 1.0) * 0.5 * w;
        double fy = (1.0 - gvec3_dot(v, cam.upv) / (z * cam.half_h)) * 0.5 * h;
        /* the brightest point of the screen below the ball's image (rows 0..2 see the screen through the ball) */
        int bx = 0, by = 4;
        for (int y = 4; y < h; y++)
            for (int x = 0; x < w; x++)
                if (luma(pixel(&fb, x, y)) > luma(pixel(&fb, bx, by)))
                    bx = x, by = y;
        double lit = 0.0; /* rows 17..19 meet the screen in front of the ball's shadow */
        for (int y = 17; y < 20; y++)
            for (int x = 0; x < w; x++)
                lit += luma(pixel(&fb, x, y)) / (3 * w);
        double peak = luma(pixel(&fb, bx, by));
        print_message("%s: focus expected at (%.2f, %.2f), brightest pixel centre (%.1f, %.1f); peak %.3f, lit screen "
                      "%.4f (rho E / pi = %.4f)\n", models[mi], fx, fy, bx + 0.5, by + 0.5, peak, lit, 0.8 / M_PI);
        assert_true(fabs(bx + 0.5 - fx) <= 1.0 && fabs(by + 0.5 - fy) <= 1.0);
        assert_true(peak > 10.0 * lit);
        assert_near(lit, 0.8 / M_PI, 0.05 * 0.8 / M_PI);
        framebuffer_free(&fb);
        scene_destroy(s);
    }
}

/* ---- the diffuse Cornell box in every colour model: sppm and light agree with the path tracer ---- */

static double patch_luma(const Framebuffer *fb, int x0, int y0, int n)
{
    double sum = 0.0;
    for (int y = y0; y < y0 + n; y++)
        for (int x = x0; x < x0 + n; x++)
            sum += luma(pixel(fb, x, y));
    return sum / (n * n);
}

static void test_cornell_models(void **state)
{
    (void)state;
    for (size_t mi = 0; mi < sizeof models / sizeof *models; mi += model_step) {
        Scene *s = load_source_scene("examples/scenes/cornell.scene", models[mi]);
        int w = 16, n = 8;
        Framebuffer ref, fb[2];
        /* the lower half: the patches without the lamp (the top row of patches shows it) */
        RenderSettings rp = settings(w, w, RENDER_PATH, 0, 0);
        rp.spp = 512;
        rp.depth = 6;
        rp.crop[1] = n, rp.crop[2] = w, rp.crop[3] = w;
        render_ok(s, &rp, &ref);
        const int integrators[2] = {RENDER_SPPM, RENDER_LIGHT};
        for (int k = 0; k < 2; k++) {
            RenderSettings rq = settings(w, w, integrators[k], k == 0 ? 8 : 4, 20000);
            rq.depth = 6;
            memcpy(rq.crop, rp.crop, sizeof rq.crop);
            render_ok(s, &rq, &fb[k]);
        }
        for (int py = 0; py < w - n; py += n)
            for (int px = 0; px < w; px += n) {
                double a = patch_luma(&ref, px, py, n);
                for (int k = 0; k < 2; k++) {
                    double b = patch_luma(&fb[k], px, py, n);
                    print_message("%s patch %2d,%2d: path %.5f %s %.5f (%+.2f%%)\n", models[mi], px, py, a,
                                  k == 0 ? "sppm" : "light", b, 100.0 * (b - a) / a);
                    assert_near(b, a, 0.03 * a);
                }
            }
        framebuffer_free(&ref);
        framebuffer_free(&fb[0]);
        framebuffer_free(&fb[1]);
        scene_destroy(s);
    }
}

/* ---- a blue beam through the prism onto a fluorescent screen: re-radiated light in bispectral only ---- */

/* The light of the image above 560 nm over the light at 450 nm (the beam's line), from the kept wavelengths. */
static double red_over_blue(const char *model)
{
    Scene *s = load_source_scene("examples/scenes/fluorescent_beam.scene", model);
    int w = 40, h = 30;
    RenderSettings rs = settings(w, h, RENDER_SPPM, 4, 20000);
    rs.waves = 1;
    Framebuffer fb;
    render_ok(s, &rs, &fb);
    double red = 0.0, blue = 0.0;
    for (size_t p = 0; p < (size_t)w * (size_t)h; p++)
        for (int k = 0; k < fb.nwaves; k++) {
            double v = fb.waves[p * (size_t)fb.nwaves + (size_t)k];
            if (fb.wavelengths[k] >= 560.0)
                red += v;
            else if (fabs(fb.wavelengths[k] - 450.0) < 3.0)
                blue += v;
        }
    print_message("%s: light above 560 nm %.4g, at 450 nm %.4g\n", model, red, blue);
    assert_true(blue > 0.0);
    framebuffer_free(&fb);
    scene_destroy(s);
    return red / blue;
}

static void test_fluorescent_screen(void **state)
{
    (void)state;
    double bi = red_over_blue("bispectral"), sp = red_over_blue("spectrum");
    print_message("red over blue: bispectral %.4f, spectrum %.4f\n", bi, sp);
    assert_true(bi > 1.0);       /* the screen turns the blue beam orange */
    assert_true(sp < 0.1 * bi);  /* without re-radiation only the faint background is red */
}

/* ---- particles from glowing geometry and from a probe: sppm and light agree with the path tracer ---- */

/* Renders s by path (reference), sppm and light at w x w over the rows y0..w-1, and compares the n x n patches. */
static void agree_with_path(const Scene *s, int w, int y0, int n, int spp, int sppm_passes, int light_passes,
                            long photons)
{
    Framebuffer ref, fb[2];
    RenderSettings rp = settings(w, w, RENDER_PATH, 0, 0);
    rp.spp = spp;
    rp.depth = 6;
    rp.crop[1] = y0, rp.crop[2] = w, rp.crop[3] = w;
    render_ok(s, &rp, &ref);
    const int integrators[2] = {RENDER_SPPM, RENDER_LIGHT};
    for (int k = 0; k < 2; k++) {
        RenderSettings rq = settings(w, w, integrators[k], k == 0 ? sppm_passes : light_passes, photons);
        rq.depth = 6;
        memcpy(rq.crop, rp.crop, sizeof rq.crop);
        render_ok(s, &rq, &fb[k]);
    }
    for (int py = 0; py + n <= w - y0; py += n)
        for (int px = 0; px + n <= w; px += n) {
            double a = patch_luma(&ref, px, py, n);
            for (int k = 0; k < 2; k++) {
                double b = patch_luma(&fb[k], px, py, n);
                print_message("patch %2d,%2d: path %.5f %s %.5f (%+.2f%%)\n", px, py + y0, a, k == 0 ? "sppm" : "light",
                              b, 100.0 * (b - a) / a);
                assert_near(b, a, 0.03 * a);
            }
        }
    framebuffer_free(&ref);
    framebuffer_free(&fb[0]);
    framebuffer_free(&fb[1]);
}

/* The Cornell box with its lamp a glowing quad (an emitter material), not a light. */
static const char glowing_cornell[] =
    "colormodel rgb\n"
    "material white lambert { reflectance rgb 0.73 0.73 0.73 }\n"
    "object box { min <-1.05, -0.05, -1.05> max <1.05, 0, 1.05> material white }\n"
    "object box { min <-1.05, 2, -1.05> max <1.05, 2.05, 1.05> material white }\n"
    "object box { min <-1.05, 0, -1.05> max <1.05, 2, -1> material white }\n"
    "object box { min <-1.05, 0, -1> max <-1, 2, 1.05> material lambert { reflectance rgb 0.63 0.065 0.05 } }\n"
    "object box { min <1, 0, -1> max <1.05, 2, 1.05> material lambert { reflectance rgb 0.14 0.45 0.09 } }\n"
    "object box { min <-0.3, 0, -0.3> max <0.3, 0.6, 0.3> material white "
    "transform { rotate <0, -18, 0> translate <0.33, 0, 0.35> } }\n"
    "object quad { corner <-0.25, 1.99, -0.25> edge1 <0.5, 0, 0> edge2 <0, 0, 0.5> "
    "material emitter { radiance rgb 17 12 4 } }\n"
    "camera pinhole { from <0, 1, 3.9> at <0, 1, 0> fov 38 }\n";

static void test_glowing_geometry(void **state)
{
    (void)state;
    Scene *s = load_text("glowing.scene", glowing_cornell, NULL);
    agree_with_path(s, 16, 8, 8, 512, 8, 16, 20000);
    scene_destroy(s);
}

/* A constant grey sky (a probe sampled as a whole) over a grey floor with a white block. */
static void test_probe_photons(void **state)
{
    (void)state;
    enum { PW = 32, PH = 16 };
    static float px[PW * PH * 3];
    for (int i = 0; i < PW * PH * 3; i++)
        px[i] = 1.0f;
    GProbe *p = NULL;
    GError err;
    assert_int_equal(gprobe_create(PW, PH, px, &p, &err), G_OK);
    char *probe = temp_path("sky.exr");
    if (gprobe_save(p, probe, GPROBE_LATLONG, &err) != G_OK)
        fail_msg("gprobe_save: %s", err.message);
    gprobe_destroy(p);
    char text[1024];
    snprintf(text, sizeof text,
             "colormodel rgb\n"
             "light probe { file \"gtrace_test_%d_sky.exr\" technique reference samples 4 }\n"
             "object box { min <-1, -0.05, -1> max <1, 0, 1> material lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
             "object box { min <-0.3, 0, -0.3> max <0.3, 0.8, 0.3> material lambert { reflectance rgb 0.8 0.8 0.8 } }\n"
             "camera pinhole { from <0, 3, 0.5> at <0, 0, 0> fov 30 }\n", (int)getpid());
    Scene *s = load_text("sky.scene", text, NULL);
    agree_with_path(s, 16, 0, 8, 1024, 32, 32, 40000);
    scene_destroy(s);
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        {"test_prism_deviation (sppm)", test_prism_deviation, NULL, NULL, (void *)RENDER_SPPM},
        {"test_prism_deviation (light)", test_prism_deviation, NULL, NULL, (void *)RENDER_LIGHT},
        {"test_shadow_energy (sppm)", test_shadow_energy, NULL, NULL, (void *)RENDER_SPPM},
        {"test_shadow_energy (light)", test_shadow_energy, NULL, NULL, (void *)RENDER_LIGHT},
        cmocka_unit_test(test_glass_ball_models),
        cmocka_unit_test(test_cornell_models),
        cmocka_unit_test(test_fluorescent_screen),
        cmocka_unit_test(test_glowing_geometry),
        cmocka_unit_test(test_probe_photons),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
