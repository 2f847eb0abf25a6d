/* bench_texparam.c - what a textured parameter costs per evaluation against the same material with a constant one
 * (kit/texparam.h), in thread CPU time: one reflection() per surface point at 4096 points of the unit square
 * (each point's caches cleared first, as at a new hit), and four reflections per point (the texture evaluated
 * once, then taken from the point's cache), and the image reflectance against the image node over a white lambert
 * (what it replaces). ARG: rounds of POINTS points (default 10). Pairs: lambert with an image or a checker mix
 * for its reflectance, phong with a perlin exponent, conductor with a perlin roughness, thinfilm with a perlin
 * thickness, plastic with a perlin roughness or a checker mix for its reflectance,
 * dielectric with a perlin roughness (light entering it from vacuum), layer with a perlin thickness and a checker mix
 * for its albedo (the film and the layer 1/20 of the rounds); in rgb and spectrum. One thread. Prints
 * nanoseconds and the ratio textured / constant; never fails on time. */
#include "generic/builtins.h"
#include "generic/material.h"
#include "generic/reader.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { POINTS = 4096 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); /* CPU time: other processes do not count */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static volatile float sink;

/* Nanoseconds per reflection() over rounds of POINTS points, `calls` reflections per point, the best of 3. */
static double time_material(const GMaterial *m, const GColor *light, GScratch *sc, long rounds, int calls)
{
    GSurfPoint sp;
    gsurfpoint_init(&sp, m->model, sc);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.dpdu = gvec3(1, 0, 0);
    sp.dpdv = gvec3(0, 1, 0);
    sp.material = m;
    sp.to = m; /* light enters m from vacuum: a dielectric's relative index 1 / n */
    GScratchMark mark = gscratch_mark(sc);
    GColor out;
    if (gcolor_scratch(&out, m->model, sc) != G_OK)
        return NAN;
    GVec3 in = gvec3_normalize(gvec3(0.3, 0.2, 1.0)), view = gvec3_normalize(gvec3(-0.3, -0.1, 1.0));
    double best = INFINITY;
    for (int round = 0; round < 3; round++) {
        double t0 = now();
        for (long r = 0; r < rounds; r++)
            for (int k = 0; k < POINTS; k++) {
                sp.u = (k & 63) / 64.0 + 0.004;
                sp.v = (k >> 6) / 64.0 + 0.004;
                sp.point = sp.object_point = gvec3(sp.u, sp.v, 0.0);
                gsurfpoint_invalidate(&sp);
                for (int c = 0; c < calls; c++)
                    gmaterial_reflection(m, &sp, in, light, view, &out);
            }
        double dt = (now() - t0) / ((double)rounds * POINTS * calls) * 1e9;
        best = dt < best ? dt : best;
    }
    sink += out.v[0];
    gscratch_release(sc, mark);
    return best;
}

/* The pairs: constant, textured. %s: the path of the image. */
static const char *const library =
    "material lambert_c lambert { reflectance rgb 0.8 0.6 0.4 }\n"
    "material lambert_image lambert { reflectance image { file \"%s\" } }\n"
    "material image_node image { child lambert { reflectance rgb 1 1 1 } file \"%s\" }\n"
    "material lambert_mix lambert { reflectance mix { by checker { dims 2 frequency 8 } a rgb 0.8 0.6 0.4 "
    "b rgb 0.2 0.3 0.4 } }\n"
    "material phong_c phong { diffuse rgb 0.4 0.4 0.4 specular rgb 0.3 0.3 0.3 exponent 40 }\n"
    "material phong_perlin phong { diffuse rgb 0.4 0.4 0.4 specular rgb 0.3 0.3 0.3 "
    "exponent perlin { frequency 4 range 10 200 } }\n"
    "material conductor_c conductor { metal Au roughness 0.3 }\n"
    "material conductor_perlin conductor { metal Au roughness perlin { frequency 4 range 0.1 0.5 } }\n"
    "material film_c thinfilm { thickness 400 base lambert { reflectance rgb 0.2 0.2 0.2 } }\n"
    "material film_perlin thinfilm { thickness perlin { frequency 4 range 200 800 } "
    "base lambert { reflectance rgb 0.2 0.2 0.2 } }\n"
    "material plastic_c plastic { reflectance rgb 0.6 0.3 0.2 roughness 0.2 }\n"
    "material plastic_perlin plastic { reflectance rgb 0.6 0.3 0.2 roughness perlin { frequency 4 range 0.1 0.5 } }\n"
    "material plastic_mix plastic { reflectance mix { by checker { dims 2 frequency 8 } a rgb 0.6 0.3 0.2 "
    "b rgb 0.2 0.3 0.4 } roughness 0.2 }\n"
    "material glass_c dielectric { glass BK7 roughness 0.2 }\n"
    "material glass_perlin dielectric { glass BK7 roughness perlin { frequency 4 range 0.1 0.5 } }\n"
    "material layer_c layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 } thickness 1 }\n"
    "material layer_perlin layer { top dielectric { } bottom lambert { reflectance rgb 0.5 0.4 0.3 } "
    "thickness perlin { frequency 4 range 0.2 2 } albedo mix { by checker { dims 2 frequency 8 } a rgb 1 1 1 "
    "b rgb 0.6 0.7 0.8 } }\n";

static const char *const pairs[][2] = {{"lambert_c", "lambert_image"},
                                        {"image_node", "lambert_image"},
                                        {"lambert_c", "lambert_mix"},
                                        {"phong_c", "phong_perlin"},
                                        {"conductor_c", "conductor_perlin"},
                                        {"film_c", "film_perlin"},
                                        {"plastic_c", "plastic_perlin"},
                                        {"plastic_c", "plastic_mix"},
                                        {"glass_c", "glass_perlin"},
                                        {"layer_c", "layer_perlin"}};

static int run(const char *model_name, const char *image, long rounds)
{
    GColorModel *md;
    GError err;
    if (gcolormodel_create(model_name, NULL, &md, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    char text[4096];
    snprintf(text, sizeof text, library, image, image);
    GReaderOptions ro = {.model = md};
    GLibrary *lib;
    if (greader_load_string(text, "bench_texparam", &ro, &lib, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        gcolormodel_destroy(md);
        return 1;
    }
    GScratch *sc = gscratch_create(1 << 16);
    GColor light;
    double white[3] = {1, 1, 1};
    if (!sc || gcolor_alloc(&light, md) != G_OK || gcolor_from_rgb(&light, white, GCOLOR_LIGHT) != G_OK) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        for (int calls = 1; calls <= 4; calls += 3) {
            const GMaterial *c = glibrary_material(lib, pairs[i][0]), *t = glibrary_material(lib, pairs[i][1]);
            int slow = strncmp(pairs[i][1], "film", 4) == 0 || strncmp(pairs[i][1], "layer", 5) == 0;
            long n = slow ? (rounds + 19) / 20 : rounds; /* a film or layer evaluation costs ~1000 lambert ones */
            double tc = time_material(c, &light, sc, n, calls), tt = time_material(t, &light, sc, n, calls);
            printf("%-10s %-14s %d call%s a point: %-10s %7.1f ns  textured %7.1f ns  ratio %5.2f\n", model_name,
                   pairs[i][1], calls, calls > 1 ? "s" : " ", i == 1 ? "image node" : "constant", tc, tt, tt / tc);
        }
    gcolor_free(&light);
    gscratch_destroy(sc);
    glibrary_destroy(lib);
    gcolormodel_destroy(md);
    return 0;
}

int main(int argc, char **argv)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    long rounds = argc > 1 ? atol(argv[1]) : 10;
    const char *image = getenv("BENCH_TEXPARAM_IMAGE") ? getenv("BENCH_TEXPARAM_IMAGE") : "examples/scenes/label.png";
    printf("bench_texparam: ns per reflection(), textured parameter against constant (one thread, CPU time)\n");
    if (run("rgb", image, rounds) || run("spectrum", image, rounds))
        return 1;
    return 0;
}
