/* bench_decode.c - what decoding images in the decoder process costs (lib/image/decode_isolated.c) against decoding
 * them in this process (GENERIC_DECODE=inprocess): for a PNG, an OpenEXR and a Radiance HDR file of 64x32, 512x256
 * and 2048x1024 pixels, the wall time of gimage_read in each mode, interleaved (isolated, in this process, isolated,
 * ...) so that a change of the machine's load falls on both alike, median of ROUNDS; then the first read of each
 * mode (the decoder process's start, OpenImageIO's load). Prints figures; never fails on time. */
#include "generic/services/image.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define ROUNDS 15

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The wall time of one gimage_read in the mode, in ms; -1 on failure (printed). */
static double read_once(const char *path, const char *mode)
{
    setenv("GENERIC_DECODE", mode, 1);
    GImage img;
    GError err;
    double t0 = now();
    int rc = gimage_read(path, 0, &img, &err);
    double t = (now() - t0) * 1e3;
    if (rc != G_OK) {
        fprintf(stderr, "bench_decode: %s\n", err.message);
        return -1.0;
    }
    gimage_free(&img);
    return t;
}

int main(void)
{
    char dir[] = "/tmp/bench_decode.XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    static const char *const exts[] = {".png", ".exr", ".hdr"};
    static const int sizes[][2] = {{64, 32}, {512, 256}, {2048, 1024}};
    char path[3][3][256];
    for (int s = 0; s < 3; s++) {
        GImage img;
        GError err;
        if (gimage_create(&img, sizes[s][0], sizes[s][1], 3, &err) != G_OK)
            return 1;
        for (size_t i = 0; i < (size_t)sizes[s][0] * sizes[s][1] * 3; i++)
            img.pixels[i] = (float)((i * 2654435761u) % 1000) / 1000.0f;
        for (int e = 0; e < 3; e++) {
            snprintf(path[s][e], sizeof path[s][e], "%s/img%d%s", dir, s, exts[e]);
            if (gimage_write(path[s][e], &img, NULL, &err) != G_OK) {
                fprintf(stderr, "bench_decode: %s\n", err.message);
                return 1;
            }
        }
        gimage_free(&img);
    }
    double first_iso = read_once(path[0][0], "isolated"), first_in = read_once(path[0][0], "inprocess");
    printf("first read: %.1f ms isolated (starts the decoder process), %.1f ms in this process (loads "
           "OpenImageIO, which the image writes above loaded already)\n", first_iso, first_in);
    printf("%-6s %-10s %12s %12s %12s\n", "format", "size", "isolated ms", "in-proc ms", "cost ms");
    for (int s = 0; s < 3; s++)
        for (int e = 0; e < 3; e++) {
            double iso[ROUNDS], in[ROUNDS];
            for (int r = 0; r < ROUNDS; r++) {
                iso[r] = read_once(path[s][e], "isolated");
                in[r] = read_once(path[s][e], "inprocess");
                if (iso[r] < 0 || in[r] < 0)
                    return 1;
            }
            qsort(iso, ROUNDS, sizeof iso[0], cmp);
            qsort(in, ROUNDS, sizeof in[0], cmp);
            char size[32];
            snprintf(size, sizeof size, "%dx%d", sizes[s][0], sizes[s][1]);
            printf("%-6s %-10s %12.2f %12.2f %12.2f\n", exts[e] + 1, size, iso[ROUNDS / 2], in[ROUNDS / 2],
                   iso[ROUNDS / 2] - in[ROUNDS / 2]);
        }
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : 1;
}
