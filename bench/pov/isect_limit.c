/* isect_limit.c - the intersection-only limit of gtrace's Whitted tracer on a scene:
 *
 *   isect_limit SCENE [--width W] [--height H] [--rounds N] [--embree]
 *
 * Loads SCENE the way gtrace does (scene_load_opts, accel_build_for; colour model and camera of the file, 1
 * thread), renders it once while recording every ray the render casts (camera, reflected and refracted rays
 * through accel_intersect, shadow rays through accel_occluded, in the order cast), then, N rounds (default 5),
 * renders it again and casts the recorded rays again through the same two functions with no shading: no surface
 * point, material, texture, light or colour, only each ray's closest hit or occlusion. Both are timed by the
 * process's CPU clock (load average barely enters it), the render without loading, set-up and output, as gtrace's
 * summary line times it. Prints ns per ray of each (the same rays: the recorded count) and the median of the
 * per-round ratios render / limit, min-max. --embree traces both through Embree (Scene.accel_embree_only) where the
 * scene would otherwise take the direct list of a few analytic shapes (accel_direct.c).
 *
 * The recording sees the rays through the linker: the program is linked with --wrap for accel_intersect and
 * accel_occluded (examples/gtrace/build.mk), so the tracer's calls reach __wrap_*, which append the ray when
 * recording and pass it on to __real_*; the tracer itself is the unchanged libgtrace.a. The timed renders run
 * with recording off: one predictable branch per ray more than gtrace. The recording holds 72 bytes a ray (110 MB
 * for the bench scene at 800x600; its array grows by doubling). */
#include "embed/render_file.h"
#include "render/render.h"
#include "scene/accel.h"
#include "scenefile/parse.h"

#include <generic/error.h>
#include <generic/reader.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int __real_accel_intersect(const Scene *s, const Ray *r, Hit *h);
int __real_accel_occluded(const Scene *s, const Ray *r);
int __wrap_accel_intersect(const Scene *s, const Ray *r, Hit *h);
int __wrap_accel_occluded(const Scene *s, const Ray *r);

/* One recorded ray: what the intersection reads of it (not the cone) and which query cast it. */
typedef struct Cast {
    GVec3 o, d;
    double tmin, tmax;
    int occlusion; /* 1: accel_occluded, 0: accel_intersect */
} Cast;

static struct {
    int on;
    Cast *rays;
    size_t n, cap;
    int failed;
} rec;

static void record(const Ray *r, int occlusion)
{
    if (rec.n == rec.cap) {
        size_t cap = rec.cap ? 2 * rec.cap : (size_t)1 << 16;
        Cast *grown = realloc(rec.rays, cap * sizeof *grown);
        if (!grown) {
            rec.failed = 1;
            return;
        }
        rec.rays = grown;
        rec.cap = cap;
    }
    rec.rays[rec.n++] = (Cast){r->o, r->d, r->tmin, r->tmax, occlusion};
}

int __wrap_accel_intersect(const Scene *s, const Ray *r, Hit *h)
{
    if (rec.on)
        record(r, 0);
    return __real_accel_intersect(s, r, h);
}

int __wrap_accel_occluded(const Scene *s, const Ray *r)
{
    if (rec.on)
        record(r, 1);
    return __real_accel_occluded(s, r);
}

static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One render of s by the Whitted tracer on 1 thread: its CPU seconds; *rays gets the tracer's own ray count. */
static int render_once(const Scene *s, const RenderSettings *rs, double *seconds, unsigned long long *rays)
{
    GError err = {0};
    Framebuffer fb = {0};
    RenderStats st = {0};
    double t0 = cpu_seconds();
    int rc = render_image(s, rs, &fb, &st, &err);
    *seconds = cpu_seconds() - t0;
    *rays = (unsigned long long)st.rays;
    framebuffer_free(&fb);
    if (rc != G_OK)
        fprintf(stderr, "isect_limit: render failed: %s\n", err.message);
    return rc;
}

/* The recorded rays cast again, closest hit or occlusion only: CPU seconds; *hits counts what they met. */
static double replay(const Scene *s, size_t *hits)
{
    size_t met = 0;
    double t0 = cpu_seconds();
    for (size_t i = 0; i < rec.n; i++) {
        const Cast *c = &rec.rays[i];
        Ray r = {c->o, c->d, c->tmin, c->tmax, 0.0, 0.0};
        Hit h;
        met += c->occlusion ? __real_accel_occluded(s, &r) != 0 : __real_accel_intersect(s, &r, &h);
    }
    double t = cpu_seconds() - t0;
    *hits = met;
    return t;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    const char *path = NULL;
    int width = 0, height = 0, rounds = 5, embree = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--width") && i + 1 < argc)
            width = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--height") && i + 1 < argc)
            height = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--rounds") && i + 1 < argc)
            rounds = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--embree"))
            embree = 1;
        else if (!path && argv[i][0] != '-')
            path = argv[i];
        else {
            fprintf(stderr, "usage: isect_limit SCENE [--width W] [--height H] [--rounds N] [--embree]\n");
            return 2;
        }
    }
    if (!path || rounds < 1 || rounds > 1000 || width < 0 || height < 0 || width > 100000 || height > 100000) {
        fprintf(stderr, "usage: isect_limit SCENE [--width W] [--height H] [--rounds N (1-1000)] [--embree]\n");
        return 2;
    }
    GError err = {0};
    Scene *s = NULL;
    GReaderOptions trust = {0};
    int rc = gtrace_embed_register(&err);
    if (rc == G_OK)
        rc = scene_load_opts(path, NULL, NULL, &trust, &s, &err);
    if (rc != G_OK) {
        fprintf(stderr, "isect_limit: %s\n", err.message);
        return 1;
    }
    const Camera *cam = &s->camera;
    RenderSettings rs = {.width = width ? width : cam->width, .height = height ? height : cam->height,
                         .spp = cam->spp, .depth = cam->depth, .threads = 1, .quiet = 1, .cutoff = cam->cutoff,
                         .bands = cam->bands, .integrator = RENDER_WHITTED};
    if (width && !height)
        rs.height = (int)((double)width * cam->height / cam->width + 0.5);
    s->accel_embree_only = embree;
    if ((rc = accel_build_for(s, (double)rs.width * rs.height * rs.spp, &err)) != G_OK) {
        fprintf(stderr, "isect_limit: %s\n", err.message);
        scene_destroy(s);
        return 1;
    }
    double t;
    unsigned long long rays = 0;
    rec.on = 1;
    rc = render_once(s, &rs, &t, &rays);
    rec.on = 0;
    if (rc != G_OK || rec.failed || rec.n == 0) {
        if (rec.failed)
            fprintf(stderr, "isect_limit: out of memory recording the rays\n");
        free(rec.rays);
        scene_destroy(s);
        return 1;
    }
    size_t occl = 0, hits = 0;
    for (size_t i = 0; i < rec.n; i++)
        occl += (size_t)rec.rays[i].occlusion;
    double *ratio = malloc((size_t)rounds * sizeof *ratio), best_render = 1e300, best_limit = 1e300;
    for (int k = 0; ratio && k < rounds && rc == G_OK; k++) {
        double tr, tl;
        rc = render_once(s, &rs, &tr, &rays);
        tl = replay(s, &hits);
        ratio[k] = tl > 0.0 ? tr / tl : 0.0;
        best_render = tr < best_render ? tr : best_render;
        best_limit = tl < best_limit ? tl : best_limit;
    }
    if (ratio && rc == G_OK) {
        qsort(ratio, (size_t)rounds, sizeof *ratio, by_value);
        double med = rounds % 2 ? ratio[rounds / 2] : 0.5 * (ratio[rounds / 2 - 1] + ratio[rounds / 2]);
        printf("isect_limit: %s %dx%d, %s, 1 thread: %zu rays (%zu closest-hit, %zu shadow; the tracer counts %llu), "
               "%zu met\n", path, rs.width, rs.height, s->direct ? "direct list" : "Embree", rec.n, rec.n - occl, occl,
               rays, hits);
        printf("isect_limit: ns per ray, least CPU of %d rounds: Whitted render %.1f, intersection only %.1f; "
               "render / limit, median of the rounds %.2f (min-max %.2f-%.2f)\n", rounds,
               1e9 * best_render / (double)rec.n, 1e9 * best_limit / (double)rec.n, med, ratio[0], ratio[rounds - 1]);
    }
    free(ratio);
    free(rec.rays);
    scene_destroy(s);
    return rc == G_OK && ratio ? 0 : 1;
}
