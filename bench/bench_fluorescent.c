/* bench_fluorescent.c - evaluations per second of the fluorescent materials against lambert, in the
 * bispectral model (41 x 41 re-radiation matrix) and in the spectrum model (the matrix folded into a
 * reflectance), with the cost of the matrix-vector product alone for comparison. One thread; the same
 * 4096 random direction pairs for every material. Prints figures, never fails on time. */
#include "generic/builtins.h"
#include "generic/fluorescent.h"
#include "generic/materials.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { PAIRS = 4096 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
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

/* Nanoseconds per reflection() call of one batch of n calls. */
static double time_material(const GMaterial *m, const GColor *light, GScratch *sc, long n)
{
    GSurfPoint sp;
    gsurfpoint_init(&sp, m->model, sc);
    sp.geometric_normal = gvec3(0, 0, 1);
    sp.material = m;
    GScratchMark mark = gscratch_mark(sc);
    GColor out;
    if (gcolor_scratch(&out, m->model, sc) != G_OK)
        return NAN;
    double t0 = now();
    for (long k = 0; k < n; k++) {
        int j = (int)(k & (PAIRS - 1));
        gmaterial_reflection(m, &sp, in_dir[j], light, out_dir[j], &out);
    }
    double dt = (now() - t0) / n * 1e9;
    sink += out.v[0];
    gscratch_release(sc, mark);
    return dt;
}

/* Nanoseconds per gcolor_mul(a, light). */
static double time_mul(const GColor *a, const GColor *light, GScratch *sc, long n)
{
    GScratchMark mark = gscratch_mark(sc);
    GColor out;
    if (gcolor_scratch(&out, a->model, sc) != G_OK)
        return NAN;
    double t0 = now();
    for (long k = 0; k < n; k++)
        gcolor_mul(&out, a, light);
    double dt = (now() - t0) / n * 1e9;
    sink += out.v[0];
    gscratch_release(sc, mark);
    return dt;
}

static int run(const char *model_name, const GReradiation *r, long n)
{
    GColorModel *md;
    GError err;
    if (gcolormodel_create(model_name, NULL, &md, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    GScratch *sc = gscratch_create(0);
    GColor light, matrix, half, grey;
    gcolor_scratch(&light, md, sc);
    gcolor_scratch(&matrix, md, sc);
    gcolor_scratch(&half, md, sc);
    gcolor_scratch(&grey, md, sc);
    double white[3] = {1, 1, 1}, g[3] = {0.5, 0.5, 0.5};
    gcolor_from_rgb(&light, white, GCOLOR_LIGHT);
    gcolor_from_rgb(&grey, g, GCOLOR_REFLECTANCE);
    if (gcolor_from_reradiation(&matrix, r, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    /* lambert refuses reflectances brighter than 1; the fluorescent matrix is (its emission peak exceeds 1
     * under equal-energy light), so it gets the matrix scaled down: the same work per call */
    double peak = gcolor_brightness(&matrix);
    if (matrix.kind == GCOLOR_VECTOR)
        for (int k = 0; k < md->nvalues; k++)
            peak = fmax(peak, matrix.v[k]);
    gcolor_scale(&half, &matrix, 0.9 / peak);
    if (half.kind == GCOLOR_VECTOR) /* rgb: an orange this saturated is out of gamut, blue slightly negative */
        for (int k = 0; k < md->nvalues; k++)
            half.v[k] = half.v[k] > 0.0f ? half.v[k] : 0.0f;
    GMaterial *lv = NULL, *lm = NULL, *ph = NULL, *va = NULL;
    int rc = glambert_create(md, &grey, &lv, &err);
    if (rc == G_OK)
        rc = glambert_create(md, &half, &lm, &err);
    if (rc == G_OK)
        rc = gfluor_phong_create(md, r, NULL, &ph, &err);
    if (rc == G_OK)
        rc = gfluor_varnish_create(md, r, NULL, &va, &err);
    if (rc != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    /* rounds that take every candidate in turn, the best round of each: fair on a busy machine */
    const GMaterial *mats[4] = {lv, lm, ph, va};
    double best[5] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY};
    for (int round = 0; round < 7; round++) {
        best[4] = fmin(best[4], time_mul(&matrix, &light, sc, n / 7));
        for (int k = 0; k < 4; k++)
            best[k] = fmin(best[k], time_material(mats[k], &light, sc, n / 7));
    }
    double t_lv = best[0], t_lm = best[1], t_ph = best[2], t_va = best[3], t_mul = best[4];
    printf("%s model (%d values per colour, %s):\n", model_name, md->nvalues,
           matrix.kind == GCOLOR_MATRIX ? "matrix kept" : "matrix folded into a reflectance");
    printf("  gcolor_mul(matrix, light) alone   %8.1f ns  %7.2f M/s\n", t_mul, 1e3 / t_mul);
    printf("  lambert, grey reflectance         %8.1f ns  %7.2f M/s\n", t_lv, 1e3 / t_lv);
    printf("  lambert, fluorescent matrix       %8.1f ns  %7.2f M/s\n", t_lm, 1e3 / t_lm);
    printf("  fluorescent-phong                 %8.1f ns  %7.2f M/s  (%.2f x lambert with the matrix)\n", t_ph,
           1e3 / t_ph, t_ph / t_lm);
    printf("  fluorescent-varnish               %8.1f ns  %7.2f M/s  (%.2f x lambert with the matrix)\n", t_va,
           1e3 / t_va, t_va / t_lm);
    double t0 = now();
    GMaterial *tmp;
    for (int k = 0; k < 10; k++) {
        gfluor_varnish_create(md, r, NULL, &tmp, &err);
        gmaterial_unref(tmp);
    }
    printf("  fluorescent-varnish creation      %8.2f ms (facet albedo table and (I - F M)^-1 M)\n",
           (now() - t0) / 10 * 1e3);
    gmaterial_unref(lv);
    gmaterial_unref(lm);
    gmaterial_unref(ph);
    gmaterial_unref(va);
    gscratch_destroy(sc);
    gcolormodel_destroy(md);
    return 0;
}

int main(int argc, char **argv)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    long n = argc > 1 ? atol(argv[1]) : 2000000;
    srand(1);
    for (int k = 0; k < PAIRS; k++) {
        in_dir[k] = random_dir();
        out_dir[k] = random_dir();
    }
    GFluorBands b;
    gfluor_bands_default(&b);
    GReradiation r;
    GError err;
    if (gfluor_matrix_create(&b, 380, 10, 41, &r, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    printf("reflection() calls, best of 7 rounds of %ld / 7 calls, one thread, parametric day-glo orange matrix\n", n);
    int rc = run("bispectral", &r, n) || run("spectrum", &r, n) || run("rgb", &r, n);
    gfluor_matrix_free(&r);
    return rc;
}
