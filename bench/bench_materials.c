/* bench_materials.c - evaluations per second of each physically based material against lambert's, in each built-in
 * colour model, in thread CPU time, one thread: reflection() over the same 4096 random direction pairs above the
 * surface and sample() from the same outgoing directions, for the rough conductor, the rough dielectric, the thin
 * dielectric, the plastic, the layer and the thin film (over lambert and over a metal; its Airy sum tabulated,
 * the default, and exact, `airy exact`). Prints the figures and the ratios to lambert; never fails on time.
 * `bench_materials N` takes N calls a figure (default 100000). */
#include "generic/builtins.h"
#include "generic/material.h"
#include "generic/reader.h"
#include "material_timing.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* The materials, lambert first (the baseline): the docs' material preview's, at the roughness its tiles use. */
static const char *const library =
    "material lambert lambert { reflectance rgb 0.8 0.6 0.4 }\n"
    "material conductor_ggx conductor { metal Cu roughness 0.3 }\n"
    "material dielectric_rough dielectric { glass BK7 roughness 0.1 }\n"
    "material thindielectric thindielectric { index 1.5 }\n"
    "material plastic plastic { reflectance rgb 0.6 0.05 0.04 roughness 0.2 }\n"
    "material layer layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.1 0.3 0.6 } }\n"
    "material thinfilm_lambert thinfilm { thickness 320 index 1.4 base lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
    "material thinfilm_metal thinfilm { thickness 320 index 1.4 base conductor { metal Al } }\n"
    "material tf_exact_lambert thinfilm { thickness 320 index 1.4 airy exact base lambert { reflectance rgb 0.5 0.5 "
    "0.5 } }\n"
    "material tf_exact_metal thinfilm { thickness 320 index 1.4 airy exact base conductor { metal Al } }\n";
static const char *const names[] = {"lambert", "conductor_ggx", "dielectric_rough", "thindielectric", "plastic",
                                    "layer", "thinfilm_lambert", "thinfilm_metal", "tf_exact_lambert",
                                    "tf_exact_metal"};
enum { NAMES = sizeof names / sizeof names[0] };

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
        gcolormodel_destroy(md);
        return 1;
    }
    GScratch *sc = gscratch_create(0);
    GColor light;
    if (!sc || gcolor_alloc(&light, md) != G_OK || gcolor_fill(&light, 1.0) != G_OK)
        return 1;
    double base[2] = {0.0, 0.0};
    for (int i = 0; i < NAMES; i++) {
        const GMaterial *m = glibrary_material(lib, names[i]);
        double t[2];
        for (int s = 0; s < 2; s++) {
            t[s] = time_material(m, &light, sc, n, s);
            if (i == 0)
                base[s] = t[s];
        }
        printf("%-10s %-17s reflection %7.1f ns (%6.2f M/s) %5.2fx   sample %7.1f ns (%6.2f M/s) %5.2fx\n",
               model_name, names[i], t[0], 1e3 / t[0], t[0] / base[0], t[1], 1e3 / t[1], t[1] / base[1]);
    }
    gcolor_free(&light);
    gscratch_destroy(sc);
    glibrary_destroy(lib);
    gcolormodel_destroy(md);
    return 0;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 100000;
    if (n <= 0 || generic_register_builtins(NULL) != G_OK)
        return 1;
    fill_pairs();
    printf("per call, thread CPU time, the best of 3 batches of %ld; ratios to lambert's\n", n);
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    for (int i = 0; i < 4; i++)
        if (run(models[i], n))
            return 1;
    return 0;
}
