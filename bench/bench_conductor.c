/* bench_conductor.c - evaluations per second of the conductor material (smooth, rough GGX, rough Beckmann,
 * uncompensated) against lambert's, in each built-in colour model, in thread CPU time: reflection() over the same 4096
 * random direction pairs, and sample() for the rough GGX conductor. One thread. Prints figures and the ratios to
 * lambert, never fails on time. `bench_conductor N MODEL` takes N calls a figure (default 200000) and runs only the
 * named colour model (default: all four), e.g. under a profiler. */
#include "generic/builtins.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "material_timing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

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
    fill_pairs();
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    if (argc > 2)
        return run(argv[2], n);
    for (int i = 0; i < 4; i++)
        if (run(models[i], n))
            return 1;
    return 0;
}
