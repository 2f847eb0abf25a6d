/* bench_conductor.c - evaluations per second of the conductor material (smooth, rough GGX, rough Beckmann,
 * uncompensated) against lambert's, in each built-in colour model, in thread CPU time: reflection() over the same 4096
 * random direction pairs, and sample() for the rough GGX conductor. One thread. Prints figures and the ratios to
 * lambert, never fails on time. */
#include "generic/builtins.h"
#include "generic/material.h"
#include "generic/reader.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { PAIRS = 4096 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); /* CPU time: other processes do not count */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static GVec3 in_dir[PAIRS], out_dir[PAIRS];
static volatile float sink;

static GVec3 random_dir(void)
{
    double c = 0.02 + 0.98 * rand() / (double)RAND_MAX, phi = 2 * M_PI * rand() / (double)RAND_MAX;
    double s = sqrt(1 - c * c);
    return gvec3(s * cos(phi), s * sin(phi), c);
}

/* Nanoseconds per reflection() (sampling 0) or sample() (sampling 1) call over n calls, the best of 3 batches. */
static double time_material(const GMaterial *m, const GColor *light, GScratch *sc, long n, int sampling)
{
    GSurfPoint sp;
    gsurfpoint_init(&sp, m->model, sc);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.material = m;
    GScratchMark mark = gscratch_mark(sc);
    GColor out;
    if (gcolor_scratch(&out, m->model, sc) != G_OK)
        return NAN;
    double best = INFINITY;
    for (int round = 0; round < 3; round++) {
        double t0 = now();
        for (long k = 0; k < n; k++) {
            int j = (int)(k & (PAIRS - 1));
            if (sampling) {
                GMaterialSample s;
                gmaterial_sample(m, &sp, out_dir[j], NULL, in_dir[j].x * 0.5 + 0.5, in_dir[j].y * 0.5 + 0.5, &s, &out);
            } else {
                gmaterial_reflection(m, &sp, in_dir[j], light, out_dir[j], &out);
            }
        }
        double dt = (now() - t0) / n * 1e9;
        best = dt < best ? dt : best;
    }
    sink += out.v[0];
    gscratch_release(sc, mark);
    return best;
}

static const char *const library =
    "material diffuse lambert { reflectance rgb 0.8 0.6 0.4 }\n"
    "material smooth conductor { metal Au }\n"
    "material ggx conductor { metal Au roughness 0.3 }\n"
    "material ggx_single conductor { metal Au roughness 0.3 compensate off }\n"
    "material beckmann conductor { metal Au roughness 0.3 distribution beckmann }\n";

static int run(const char *model_name, long n)
{
    GColorModel *md;
    GError err;
    if (gcolormodel_create(model_name, NULL, &md, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    GReaderOptions ro = {.model = md};
    GLibrary *lib;
    if (greader_load_string(library, "bench", &ro, &lib, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    GScratch *sc = gscratch_create(0);
    GColor light;
    if (gcolor_alloc(&light, md) != G_OK || gcolor_fill(&light, 1.0) != G_OK)
        return 1;
    const char *names[] = {"diffuse", "smooth", "ggx", "ggx_single", "beckmann"};
    double base = time_material(glibrary_material(lib, "diffuse"), &light, sc, n, 0);
    printf("%-10s lambert reflection %7.1f ns (%.2f M/s)\n", model_name, base, 1e3 / base);
    for (int i = 1; i < 5; i++) {
        double t = time_material(glibrary_material(lib, names[i]), &light, sc, n, 0);
        printf("%-10s conductor %-10s reflection %7.1f ns (%.2f M/s)  %.2fx lambert\n", model_name, names[i], t,
               1e3 / t, t / base);
    }
    double ts = time_material(glibrary_material(lib, "ggx"), &light, sc, n, 1);
    double tl = time_material(glibrary_material(lib, "diffuse"), &light, sc, n, 1);
    printf("%-10s sample(): conductor ggx %7.1f ns, lambert %7.1f ns  %.2fx lambert\n", model_name, ts, tl, ts / tl);
    gcolor_free(&light);
    gscratch_destroy(sc);
    glibrary_destroy(lib);
    gcolormodel_destroy(md);
    return 0;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 200000;
    if (n <= 0 || generic_register_builtins(NULL) != G_OK)
        return 1;
    srand(7);
    for (int i = 0; i < PAIRS; i++) {
        in_dir[i] = random_dir();
        out_dir[i] = random_dir();
    }
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    for (int i = 0; i < 4; i++)
        if (run(models[i], n))
            return 1;
    return 0;
}
