/* bench_probe.c - figures for the light-probe code (prints them; never fails on time).
 *   1. ground-truth irradiance at 20000 normals on a 1024x512 probe (a blender-data EXR when installed,
 *      else a synthetic sky with a sun), against the pixel-by-pixel sum;
 *   2. median cut and adaptive median cut for N = 2..128 together;
 *   3. irradiance optimisation of 64 lights on that probe;
 *   4. the accuracy goal on each shared probe: irradiance optimisation with N/2 lights against median cut
 *      with N lights (mean error, the paper's measure), N = 8..128. */
#include "generic/builtins.h"
#include "generic/memory.h"
#include "generic/services/probe.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static GProbe *synthetic_probe(void)
{
    const int w = 1024, h = 512;
    float *px = malloc(sizeof(float) * 3 * w * h);
    for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++) {
            double th = M_PI * (v + 0.5) / h, ph = 2.0 * M_PI * (u + 0.5) / w;
            double sky = th < M_PI / 2 ? 0.6 + 0.4 * cos(th) : 0.15;
            float *p = px + 3 * (v * w + u);
            p[0] = (float)(sky * (0.7 + 0.1 * sin(3 * ph)));
            p[1] = (float)(sky * 0.85);
            p[2] = (float)(sky * (1.0 + 0.1 * cos(2 * ph)));
            double d = hypot(th - 0.6, (ph - 2.0) * sin(0.6)); /* a sun about 1.2 degrees across */
            if (d < 0.01)
                p[0] = p[1] = p[2] = 30000.0f;
        }
    GProbe *p = NULL;
    gprobe_create(w, h, px, &p, NULL);
    free(px);
    return p;
}

static double loadavg(void)
{
    double l = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1.0;
        fclose(f);
    }
    return l;
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    GError err;
    const char *blender[] = {"courtyard.exr", "forest.exr", "city.exr", "sunrise.exr", NULL};
    char path[512] = "";
    for (int i = 0; blender[i]; i++) {
        snprintf(path, sizeof path, "/usr/share/blender/datafiles/studiolights/world/%s", blender[i]);
        if (access(path, R_OK) == 0)
            break;
        path[0] = '\0';
    }
    GProbe *p = NULL;
    if (path[0]) {
        if (gprobe_load(path, GPROBE_AUTO, 0, &p, &err) != G_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
    } else {
        p = synthetic_probe();
        snprintf(path, sizeof path, "synthetic sky with a sun");
    }
    printf("probe: %s (%dx%d), %d OpenMP threads, load average %.2f at start\n", path, gprobe_width(p),
           gprobe_height(p), omp_get_max_threads(), loadavg());

    /* 1. ground truth */
    const int m = 20000;
    GVec3 *n = malloc(sizeof *n * m);
    double *E = malloc(sizeof(double) * 3 * m), *D = malloc(sizeof(double) * 3 * m);
    gprobe_fibonacci(m, n);
    gprobe_irradiance(p, n, 64, E, NULL); /* warm up threads and pages */
    double best = 1e30, best_cpu = 0.0;
    for (int r = 0; r < 3; r++) {
        double t0 = wall(), c0 = cpu();
        gprobe_irradiance(p, n, m, E, NULL);
        double t = wall() - t0;
        if (t < best) {
            best = t;
            best_cpu = cpu() - c0;
        }
    }
    const int md = 100;
    double t0 = wall();
    gprobe_irradiance_direct(p, n, md, D, NULL);
    double td = wall() - t0, worst = 0.0;
    for (int i = 0; i < 3 * md; i++)
        worst = fmax(worst, fabs(D[i] - E[i]) / fmax(D[i], 1e-300));
    printf("\n1. ground truth, %d normals: %.3f s wall (%.3f s CPU), best of 3     [goal <= 2 s on 2 cores]\n", m,
           best, best_cpu);
    printf("   pixel-by-pixel sum: %.3f s for %d normals, so about %.1f s for %d; largest relative difference %.2g\n",
           td, md, td * m / md, m, worst);

    /* 2. median cut and adaptive median cut, N = 2..128 */
    GProbeLight lights[128];
    best = 1e30;
    for (int r = 0; r < 5; r++) {
        t0 = wall();
        for (int k = 1; k <= 7; k++) {
            gprobe_median_cut(p, 1 << k, lights, NULL);
            gprobe_adaptive_median_cut(p, 1 << k, lights, NULL);
        }
        best = fmin(best, wall() - t0);
    }
    printf("\n2. median cut + adaptive median cut for N = 2,4,...,128: %.1f ms, best of 5     [goal <= 50 ms]\n",
           1e3 * best);

    /* 3. irradiance optimisation of 64 lights */
    GProbeFitReport rep;
    t0 = wall();
    double c0 = cpu();
    gprobe_irradiance_fit(p, 64, NULL, lights, &rep, NULL);
    double t64 = wall() - t0, c64 = cpu() - c0;
    gprobe_lights_irradiance(lights, 64, n, m, D);
    GProbeErrors e;
    gprobe_compare(E, D, m, &e);
    printf("\n3. irradiance optimisation, 64 lights, 2000 fit normals: %.2f s wall (%.2f s CPU)     [goal <= 10 s]\n",
           t64, c64);
    printf("   %d iterations, %s; objective %.4g (start) -> %.4g (colours solved) -> %.4g; mean error %.3f%%, "
           "max %.3f%%\n",
           rep.iterations, rep.converged ? "converged" : "stopped at the iteration limit", rep.initial, rep.projected,
           rep.final, e.mean_rel, e.max_rel);
    gprobe_destroy(p);

    /* 4. accuracy goal on the shared probes */
    printf("\n4. accuracy goal: irradiance optimisation with N/2 lights reaches median cut's mean error with N\n"
           "   (mean of |E' - E| / E over %d normals, averaged over RGB, in percent)\n", m);
    const char *src = getenv("GENERIC_SOURCE_DIR");
    const char *names[] = {"grace.hdr", "pisa.hdr", "uffizi.hdr"};
    int met = 0, total = 0;
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/../shared/data/probes/%s", src ? src : ".", names[k]);
        if (access(path, R_OK) != 0)
            snprintf(path, sizeof path, "/work/shared/data/probes/%s", names[k]);
        if (gprobe_load(path, GPROBE_AUTO, 0, &p, &err) != G_OK) {
            printf("   %s: not available (%s)\n", names[k], err.message);
            continue;
        }
        gprobe_irradiance(p, n, m, E, NULL);
        printf("   %-10s   N   median cut(N)   irradiance(N/2)   %s\n", names[k], "goal");
        for (int N = 8; N <= 128; N *= 2) {
            GProbeErrors emc, eio;
            gprobe_median_cut(p, N, lights, NULL);
            gprobe_lights_irradiance(lights, N, n, m, D);
            gprobe_compare(E, D, m, &emc);
            t0 = wall();
            gprobe_irradiance_fit(p, N / 2, NULL, lights, &rep, NULL);
            double tf = wall() - t0;
            gprobe_lights_irradiance(lights, N / 2, n, m, D);
            gprobe_compare(E, D, m, &eio);
            int ok = eio.mean_rel <= emc.mean_rel;
            met += ok;
            total++;
            printf("   %-10s %4d   %10.3f%%      %10.3f%%       %s   (fit %.2f s, %s)\n", "", N, emc.mean_rel,
                   eio.mean_rel, ok ? "met" : "MISSED", tf, rep.converged ? "converged" : "iteration limit");
        }
        gprobe_destroy(p);
    }
    printf("   goal met in %d of %d cases\n", met, total);
    free(n);
    free(E);
    free(D);
    return 0;
}
