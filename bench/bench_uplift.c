/* bench_uplift.c - cost of uplifting an RGB colour (generic/colorspace.h): nanoseconds per colour for the table
 * lookup alone (guplift_from_rgb), and for from_rgb in each model with the sigmoid uplift (lookup, refinement
 * against the model's weights, the sigmoid at every sample) and with the basis uplift, over a fixed set of random
 * colours of the sRGB cube, reflectances and lights. No allocation per colour. Prints figures; never fails on
 * time. */
#include "generic/builtins.h"
#include "generic/color.h"
#include "generic/colorspace.h"

#include <stdio.h>
#include <time.h>

enum { NCOLOURS = 4096 };

/* The thread's CPU time: time slices other processes take on a busy machine do not count. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static double rgb[NCOLOURS][3];
static double sink;

static double per_colour_lookup(GColorRole role)
{
    GUplift u;
    double t0 = now();
    int reps = 0;
    do {
        for (int i = 0; i < NCOLOURS; i++) {
            if (guplift_from_rgb(rgb[i], role, &u) == G_OK)
                sink += u.c[0];
        }
        reps++;
    } while (now() - t0 < 0.2);
    return (now() - t0) / ((double)reps * NCOLOURS) * 1e9;
}

static double per_colour_model(const GColorModel *m, GColorRole role)
{
    float buf[4096];
    GColor c;
    if (gcolor_wrap(&c, m, buf, 4096) != G_OK)
        return -1.0;
    double t0 = now();
    int reps = 0;
    do {
        for (int i = 0; i < NCOLOURS; i++)
            if (gcolor_from_rgb(&c, rgb[i], role) == G_OK)
                sink += c.v[0];
        reps++;
    } while (now() - t0 < 0.2);
    return (now() - t0) / ((double)reps * NCOLOURS) * 1e9;
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    unsigned long long s = 12345;
    for (int i = 0; i < NCOLOURS; i++)
        for (int j = 0; j < 3; j++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            rgb[i][j] = (double)(s >> 11) * 0x1.0p-53;
        }
    printf("uplift: ns per colour (%d random colours of the sRGB cube)\n", NCOLOURS);
    printf("%-12s %-8s %10s %10s\n", "", "", "reflect.", "light");
    printf("%-12s %-8s %10.1f %10.1f\n", "table", "lookup", per_colour_lookup(GCOLOR_REFLECTANCE),
           per_colour_lookup(GCOLOR_LIGHT));
    const char *models[] = {"rgb", "spectrum9", "spectrum", "bispectral"};
    const char *uplifts[] = {"sigmoid", "basis"};
    for (int mi = 0; mi < 4; mi++)
        for (int u = 0; u < 2; u++) {
            GColorModel *m = NULL;
            GError err;
            GColorModelOptions o = {.uplift = u == 0 ? GCOLOR_UPLIFT_SIGMOID : GCOLOR_UPLIFT_BASIS};
            if (gcolormodel_create(models[mi], &o, &m, &err) != G_OK) {
                fprintf(stderr, "%s\n", err.message);
                return 1;
            }
            printf("%-12s %-8s %10.1f %10.1f\n", models[mi], uplifts[u], per_colour_model(m, GCOLOR_REFLECTANCE),
                   per_colour_model(m, GCOLOR_LIGHT));
            gcolormodel_destroy(m);
            if (mi == 0)
                break; /* rgb needs no uplifting */
        }
    return sink == 12345.0;
}
