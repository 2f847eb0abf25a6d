/* bench_batch.c - the batch API (generic/batch.h) against the same evaluations one call at a time, and the
 * reference the Python package's tests compare with.
 *   bench_batch                prints evaluations per second of reflection for lambert in rgb and phong in
 *                              spectrum: one call per row through the dispatch, gbatch_reflection on one thread
 *                              and on every thread (bench/python_batch.py measures the same from Python)
 *   bench_batch --reference FILE MATERIAL MODEL rgb|samples N SEED OUT
 *                              writes, as raw doubles, reflection of unit white light for N rows of inputs drawn
 *                              from SEED (rows() below; tests/python/conftest.py draws the same), one call per row
 *                              through the dispatch on a point filled here, not by the batch code. */
#include "generic/batch.h"
#include "generic/builtins.h"
#include "generic/reader.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The n-th uniform number in [0, 1) of a seed: splitmix64 of seed + n times the golden gamma, its top 53 bits. */
static double uniform(unsigned long long seed, unsigned long long n)
{
    unsigned long long z = seed + n * 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

static void unit(double *v, double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    v[0] = x / l;
    v[1] = y / l;
    v[2] = z / l;
}

/* Row i's normal (within about 17 degrees of +z), in and out directions (mostly above the surface): eight draws. */
static void rows(unsigned long long seed, size_t n, double *normal, double *in, double *out)
{
    for (size_t i = 0; i < n; i++) {
        unsigned long long k = 8 * (unsigned long long)i;
        unit(normal + 3 * i, 0.3 * (2 * uniform(seed, k) - 1), 0.3 * (2 * uniform(seed, k + 1) - 1), 1.0);
        unit(in + 3 * i, 2 * uniform(seed, k + 2) - 1, 2 * uniform(seed, k + 3) - 1, uniform(seed, k + 4) + 0.05);
        unit(out + 3 * i, 2 * uniform(seed, k + 5) - 1, 2 * uniform(seed, k + 6) - 1, uniform(seed, k + 7) + 0.05);
    }
}

static GVec3 at(const double *a, size_t i) { return gvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

/* One call per row through the dispatch into result (width doubles a row). */
static int one_by_one(const GMaterial *m, size_t n, const double *normal, const double *in, const double *out,
                      GBatchOutput output, double *result)
{
    const GColorModel *model = m->model;
    int width = gbatch_output_width(model, output);
    GScratch *s = gscratch_create(0);
    GColor white = {0}, c = {0};
    const double one[3] = {1.0, 1.0, 1.0};
    int rc = !s ? G_ERR_NOMEM : gcolor_alloc(&white, model);
    if (rc == G_OK)
        rc = gcolor_from_rgb(&white, one, GCOLOR_LIGHT);
    if (rc == G_OK)
        rc = gcolor_alloc(&c, model);
    for (size_t i = 0; i < n && rc == G_OK; i++) {
        GSurfPoint sp;
        gsurfpoint_init(&sp, model, s);
        sp.geometric_normal = gvec3_normalize(at(normal, i));
        sp.material = sp.to = m;
        GScratchMark mark = gscratch_mark(s);
        rc = gmaterial_reflection(m, &sp, at(in, i), &white, at(out, i), &c);
        gscratch_release(s, mark);
        double *dst = result + (size_t)width * i;
        if (rc == G_OK && output == GBATCH_RGB)
            rc = gcolor_to_rgb(&c, GCOLOR_LIGHT, dst);
        else if (rc == G_OK)
            for (int k = 0; k < model->nvalues; k++)
                dst[k] = c.v[k];
    }
    gcolor_free(&white);
    gcolor_free(&c);
    gscratch_destroy(s);
    return rc;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int reference(char **argv)
{
    GReaderOptions opt = {.colormodel = argv[3]};
    GLibrary *lib;
    GError err;
    int samples = strcmp(argv[4], "samples") == 0;
    size_t n = strtoull(argv[5], NULL, 10);
    unsigned long long seed = strtoull(argv[6], NULL, 10);
    if (greader_load_file(argv[1], &opt, &lib, &err) != G_OK) {
        fprintf(stderr, "bench_batch: %s\n", err.message);
        return 1;
    }
    const GMaterial *m = glibrary_material(lib, argv[2]);
    GBatchOutput output = samples ? GBATCH_SAMPLES : GBATCH_RGB;
    double *normal = malloc(n * 3 * sizeof(double)), *in = malloc(n * 3 * sizeof(double));
    double *out = malloc(n * 3 * sizeof(double));
    double *result = m ? malloc(n * (size_t)gbatch_output_width(m->model, output) * sizeof(double)) : NULL;
    int rc = 1;
    if (m && normal && in && out && result) {
        rows(seed, n, normal, in, out);
        FILE *f = fopen(argv[7], "wb");
        size_t count = n * (size_t)gbatch_output_width(m->model, output);
        rc = f && one_by_one(m, n, normal, in, out, output, result) == G_OK &&
                     fwrite(result, sizeof(double), count, f) == count ? 0 : 1;
        if (f && fclose(f) != 0)
            rc = 1;
    }
    if (rc)
        fprintf(stderr, "bench_batch: no material '%s', out of memory, or writing %s failed\n", argv[2], argv[7]);
    free(normal);
    free(in);
    free(out);
    free(result);
    glibrary_destroy(lib);
    return rc;
}

static void bench(const char *model, const char *text, const char *name)
{
    enum { N = 1000000 };
    GReaderOptions opt = {.colormodel = model};
    GLibrary *lib;
    GError err;
    if (greader_load_string(text, "bench", &opt, &lib, &err) != G_OK) {
        fprintf(stderr, "bench_batch: %s\n", err.message);
        return;
    }
    const GMaterial *m = glibrary_material(lib, name);
    double *normal = malloc(N * 3 * sizeof(double)), *in = malloc(N * 3 * sizeof(double));
    double *out = malloc(N * 3 * sizeof(double)), *result = malloc(N * 3 * sizeof(double));
    if (!normal || !in || !out || !result) {
        fprintf(stderr, "bench_batch: out of memory\n");
    } else {
        rows(1, N, normal, in, out);
        double t0 = now();
        int rc = one_by_one(m, N, normal, in, out, GBATCH_RGB, result);
        double t1 = now();
        GBatchPoints one = {.n = N, .normal = normal, .threads = 1}, all = {.n = N, .normal = normal};
        rc = rc ? rc : gbatch_reflection(m, &one, in, out, GBATCH_RGB, result, &err);
        double t2 = now();
        rc = rc ? rc : gbatch_reflection(m, &all, in, out, GBATCH_RGB, result, &err);
        double t3 = now();
        printf("%-8s %-9s rgb out: one call a row %8.3f M/s, batch 1 thread %8.3f M/s, batch %d threads %8.3f M/s%s\n",
               name, model, N / (t1 - t0) * 1e-6, N / (t2 - t1) * 1e-6, omp_get_max_threads(),
               N / (t3 - t2) * 1e-6, rc ? " (failed)" : "");
    }
    free(normal);
    free(in);
    free(out);
    free(result);
    glibrary_destroy(lib);
}

int main(int argc, char **argv)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    if (argc == 9 && strcmp(argv[1], "--reference") == 0)
        return reference(argv + 1);
    if (argc != 1) {
        fprintf(stderr, "usage: bench_batch [--reference FILE MATERIAL MODEL rgb|samples N SEED OUT]\n");
        return 2;
    }
    bench("rgb", "material matte lambert { reflectance rgb 0.7 0.5 0.2 }", "matte");
    bench("spectrum", "material plastic phong { diffuse rgb 0.6 0.08 0.05 specular rgb 0.25 0.25 0.25 exponent 60 }",
          "plastic");
    return 0;
}
