/* bench_mesh_decode.c - what reading mesh files in the mesh reader process costs (gtrace's geometry/mesh_isolated.c)
 * against reading them in this process (GENERIC_DECODE=inprocess): for a small OBJ (read by gtrace itself either
 * way: the reference of no isolation), a small PLY, STL and glTF (2 triangles) and a binary PLY of 100,000 triangles,
 * the wall time and the CPU time (this process and its reader processes, user and system) of object_mesh_load in
 * each mode, interleaved (isolated, in this process, ...) so that a change of the machine's load falls on both
 * alike, median of ROUNDS. On a loaded machine the CPU time is the steadier figure. Prints figures; never fails on
 * time. */
#include "geometry/object.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#define ROUNDS 15
/** The large PLY's grid: (GRID + 1)^2 vertices, 2 GRID^2 triangles (100,352). */
#define GRID 224

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

/* CPU seconds of this process and of its children that ended. */
static double cpu_now(void)
{
    struct rusage self, kids;
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_CHILDREN, &kids);
    const struct timeval *t[4] = {&self.ru_utime, &self.ru_stime, &kids.ru_utime, &kids.ru_stime};
    double s = 0;
    for (int i = 0; i < 4; i++)
        s += (double)t[i]->tv_sec + 1e-6 * (double)t[i]->tv_usec;
    return s;
}

/* The wall time of one object_mesh_load in the mode, in ms, and its CPU time in *cpu_ms; -1 on failure (printed). */
static double load_once(const char *path, const char *mode, double *cpu_ms)
{
    setenv("GENERIC_DECODE", mode, 1);
    Object *o = object_new(SHAPE_MESH, NULL);
    GError err;
    double c0 = cpu_now(), t0 = now();
    int rc = object_mesh_load(o, path, &err);
    double t = (now() - t0) * 1e3;
    *cpu_ms = (cpu_now() - c0) * 1e3;
    object_free(o);
    if (rc != G_OK) {
        fprintf(stderr, "bench_mesh_decode: %s\n", err.message);
        return -1.0;
    }
    return t;
}

static int write_bytes(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t w = fwrite(data, 1, n, f);
    return fclose(f) == 0 && w == n ? 0 : -1;
}

/* A binary PLY of a GRID x GRID height field. */
static int write_big_ply(const char *path)
{
    char head[512];
    int hn = snprintf(head, sizeof head,
                      "ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                      "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n",
                      (GRID + 1) * (GRID + 1), 2 * GRID * GRID);
    size_t n = (size_t)hn + (size_t)(GRID + 1) * (GRID + 1) * 12 + (size_t)2 * GRID * GRID * 13;
    unsigned char *buf = malloc(n), *p = buf;
    if (!buf)
        return -1;
    memcpy(p, head, (size_t)hn), p += hn;
    for (int y = 0; y <= GRID; y++)
        for (int x = 0; x <= GRID; x++) {
            float v[3] = {(float)x / GRID, (float)y / GRID, 0.1f * (float)((x * 7 + y * 13) % 10) / 10.0f};
            memcpy(p, v, 12), p += 12;
        }
    for (int y = 0; y < GRID; y++)
        for (int x = 0; x < GRID; x++) {
            int32_t a = y * (GRID + 1) + x, b = a + 1, c = a + GRID + 1, d = c + 1;
            int32_t t[2][3] = {{a, b, d}, {a, d, c}};
            for (int k = 0; k < 2; k++) {
                *p++ = 3;
                memcpy(p, t[k], 12), p += 12;
            }
        }
    int rc = write_bytes(path, buf, n);
    free(buf);
    return rc;
}

int main(void)
{
    char dir[] = "/tmp/bench_mesh_decode.XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    static const char *const names[] = {"small.obj", "small.ply", "small.stl", "small.gltf", "grid100k.ply"};
    static const char *const texts[] = {
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n",
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
        "3 0 1 2\n3 0 2 3\n",
        "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n",
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"buffers\":[{\"byteLength\":36,"
        "\"uri\":\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],"
        "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,"
        "\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[1,1,0]}]}\n",
        NULL};
    char path[5][256];
    for (int i = 0; i < 5; i++) {
        snprintf(path[i], sizeof path[i], "%s/%s", dir, names[i]);
        if (texts[i] ? write_bytes(path[i], texts[i], strlen(texts[i])) : write_big_ply(path[i])) {
            fprintf(stderr, "bench_mesh_decode: cannot write %s\n", path[i]);
            return 1;
        }
    }
    printf("%-14s %12s %12s %12s %12s %12s\n", "file", "isolated ms", "in-proc ms", "cost ms", "iso cpu ms",
           "in cpu ms");
    for (int i = 0; i < 5; i++) {
        double iso[ROUNDS], in[ROUNDS], iso_cpu[ROUNDS], in_cpu[ROUNDS];
        for (int r = 0; r < ROUNDS; r++) {
            iso[r] = load_once(path[i], "isolated", &iso_cpu[r]);
            in[r] = load_once(path[i], "inprocess", &in_cpu[r]);
            if (iso[r] < 0 || in[r] < 0)
                return 1;
        }
        double *all[4] = {iso, in, iso_cpu, in_cpu};
        for (int k = 0; k < 4; k++)
            qsort(all[k], ROUNDS, sizeof iso[0], cmp);
        printf("%-14s %12.2f %12.2f %12.2f %12.2f %12.2f\n", names[i], iso[ROUNDS / 2], in[ROUNDS / 2],
               iso[ROUNDS / 2] - in[ROUNDS / 2], iso_cpu[ROUNDS / 2], in_cpu[ROUNDS / 2]);
    }
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : 1;
}
