/* material_timing.h - what the material benches (bench_conductor.c, bench_materials.c) share: thread CPU time, a
 * fixed set of random direction pairs above the surface, and the time of one material's reflection() or sample().
 * Header-only (static): each bench is one program. */
#ifndef BENCH_MATERIAL_TIMING_H
#define BENCH_MATERIAL_TIMING_H

#include "generic/material.h"

#include <math.h>
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
    sp.material = m, sp.from = NULL, sp.to = m; /* seen from outside, as a renderer's primary hit */
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

/* Fills the direction pairs, the same for every run (seeded). */
static void fill_pairs(void)
{
    srand(7);
    for (int i = 0; i < PAIRS; i++) {
        in_dir[i] = random_dir();
        out_dir[i] = random_dir();
    }
}

#endif
