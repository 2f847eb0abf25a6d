/* test_gtrace_common.h - shared by the gtrace test programs, which link the tracer's library (libgtrace.a): its
 * headers and helpers that build scenes from C and render them small. */
#ifndef TEST_GTRACE_COMMON_H
#define TEST_GTRACE_COMMON_H

#include "film/framebuffer.h"
#include "film/output.h"
#include "film/progress.h"
#include "geometry/geometry.h"
#include "geometry/mesh_format.h"
#include "integrators/bands.h"
#include "integrators/path.h"
#include "integrators/whitted.h"
#include "lights/lighting.h"
#include "lights/probe_env.h"
#include "render/render.h"
#include "scene/accel.h"
#include "scene/accel_direct.h"
#include "scene/scene.h"
#include "scenefile/parse.h"
#include "trace/sampler.h"
#include "trace/trace.h"

#include "generic/materials.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

/* |a - b| <= tol in double precision. */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)

static inline void near_(double a, double b, double tol, const char *what, const char *file, int line)
{
    if (!(fabs(a - b) <= tol)) {
        print_error("%s:%d: %s = %.10g, expected %.10g within %g\n", file, line, what, a, b, tol);
        _fail(file, line);
    }
}

#define assert_ok(expr)                                                                                                \
    do {                                                                                                               \
        GError e_;                                                                                                     \
        gerror_clear(&e_);                                                                                             \
        int rc_ = (expr);                                                                                              \
        if (rc_ != G_OK) {                                                                                             \
            print_error("%s:%d: %s failed (%d)\n", __FILE__, __LINE__, #expr, rc_);                                  \
            _fail(__FILE__, __LINE__);                                                                                 \
        }                                                                                                              \
    } while (0)

/* A scratch file name under /tmp for this process (the last 8 stay valid at once). */
static inline char *temp_path(const char *name)
{
    static char path[8][256];
    static int k;
    char *p = path[k++ % 8];
    snprintf(p, sizeof path[0], "/tmp/gtrace_test_%d_%s", (int)getpid(), name);
    return p;
}

/* Writes n bytes to temp_path(name); its path. */
static inline char *write_file(const char *name, const void *data, size_t n)
{
    char *p = temp_path(name);
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    fclose(f);
    return p;
}

/* Writes a text to temp_path(name); its path. */
static inline char *write_text(const char *name, const char *text) { return write_file(name, text, strlen(text)); }

/* A model by name, skipping the test when it is not registered. */
static inline GColorModel *model_or_skip(const char *name)
{
    GColorModel *m = NULL;
    GError err;
    if (gcolormodel_create(name, NULL, &m, &err) != G_OK) {
        print_message("colour model '%s' not available: %s\n", name, err.message);
        skip();
    }
    return m;
}

/* A scene owning its model, with a camera at from looking at at. */
static inline Scene *new_scene(const char *model, GVec3 from, GVec3 at, double fov)
{
    GColorModel *m = model_or_skip(model);
    Scene *s = NULL;
    GError err;
    assert_int_equal(scene_create(m, &s, &err), G_OK);
    s->owned_model = m;
    s->camera.from = from;
    s->camera.at = at;
    s->camera.up = gvec3(0, 1, 0);
    s->camera.fov = fov;
    s->camera.cutoff = 0.0; /* trace every ray to the depth limit unless a test asks otherwise */
    return s;
}

static inline void set_grey(GColor *c, double v, GColorRole role)
{
    double rgb[3] = {v, v, v};
    assert_int_equal(gcolor_from_rgb(c, rgb, role), G_OK);
}

static inline GMaterial *lambert(const Scene *s, double rho)
{
    GColor c;
    assert_int_equal(gcolor_alloc(&c, s->model), G_OK);
    set_grey(&c, rho, GCOLOR_REFLECTANCE);
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(glambert_create(s->model, &c, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

/* A mirror of reflectance r in every sample (a flat spectrum in spectral models). */
static inline GMaterial *mirror(const Scene *s, double r)
{
    GColor c;
    assert_int_equal(gcolor_alloc(&c, s->model), G_OK);
    if (s->model->nsamples > 0) { /* spectral: a flat spectrum */
        GSpectrumNM flat;
        for (int i = 0; i < GNM_COUNT; i++)
            flat.v[i] = (float)r;
        assert_int_equal(gcolor_from_nm(&c, &flat, GCOLOR_REFLECTANCE), G_OK);
    } else {
        set_grey(&c, r, GCOLOR_REFLECTANCE);
    }
    GMaterial *m = NULL;
    GError err;
    if (gmirror_create(s->model, &c, &m, &err) != G_OK)
        fail_msg("gmirror_create: %s", err.message);
    gcolor_free(&c);
    return m;
}

static inline GMaterial *glass(const Scene *s, double n)
{
    GDielectricParams p = {gdispersion_constant(n), NULL, NULL};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gdielectric_create(s->model, &p, &m, &err), G_OK);
    return m;
}

static inline GMaterial *emitter(const Scene *s, double radiance)
{
    GColor c;
    assert_int_equal(gcolor_alloc(&c, s->model), G_OK);
    set_grey(&c, radiance, GCOLOR_LIGHT);
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gemitter_create(s->model, &c, 0, &m, &err), G_OK);
    gcolor_free(&c);
    return m;
}

/* Adds an object; the material reference passed in is consumed. */
static inline Object *add_sphere(Scene *s, GMaterial *m, GVec3 c, double r)
{
    Object *o = object_new(SHAPE_SPHERE, m);
    gmaterial_unref(m);
    GError err;
    assert_int_equal(object_sphere(o, c, r, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

static inline Object *add_plane(Scene *s, GMaterial *m, GVec3 p, GVec3 n)
{
    Object *o = object_new(SHAPE_PLANE, m);
    gmaterial_unref(m);
    GError err;
    assert_int_equal(object_plane(o, p, n, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

static inline Object *add_box(Scene *s, GMaterial *m, GVec3 lo, GVec3 hi)
{
    Object *o = object_new(SHAPE_BOX, m);
    gmaterial_unref(m);
    GError err;
    assert_int_equal(object_box(o, lo, hi, &err), G_OK);
    assert_int_equal(scene_add_object(s, o, &err), G_OK);
    return o;
}

static inline Light *add_light(Scene *s, LightKind kind, double value)
{
    Light *l = light_new(s->model, kind);
    assert_non_null(l);
    set_grey(&l->color, value, GCOLOR_LIGHT);
    GError err;
    assert_int_equal(scene_add_light(s, l, &err), G_OK);
    return l;
}

/* Renders quietly on two threads; the caller frees fb. */
static inline RenderStats render(Scene *s, int w, int h, int spp, int depth, Framebuffer *fb)
{
    GError err;
    gerror_clear(&err);
    if (!s->rtc && accel_build(s, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    RenderSettings rs = {.width = w, .height = h, .spp = spp, .depth = depth, .threads = 2, .quiet = 1,
                         .cutoff = s->camera.cutoff};
    RenderStats st;
    if (render_image(s, &rs, fb, &st, &err) != G_OK)
        fail_msg("render_image: %s", err.message);
    return st;
}

static inline const float *pixel(const Framebuffer *fb, int x, int y)
{
    return fb->pixels + 3 * ((size_t)y * fb->width + x);
}

/* Luminance of a linear sRGB pixel. */
static inline double luma(const float *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

/* The largest relative difference of two pictures' channels (over 1e-6 absolute for near-black ones), and how
 * many channels differ by more than relative 1e-5 into *off: two renders that should agree within rounding. */
static inline double largest_difference(const Framebuffer *a, const Framebuffer *b, int *off)
{
    assert_int_equal(a->width, b->width);
    assert_int_equal(a->height, b->height);
    double worst = 0.0;
    *off = 0;
    for (size_t i = 0; i < 3 * (size_t)a->width * a->height; i++) {
        double x = a->pixels[i], y = b->pixels[i], d = fabs(x - y) / fmax(1e-6, fmax(fabs(x), fabs(y)));
        worst = fmax(worst, d);
        *off += d > 1e-5;
    }
    return worst;
}

#endif
