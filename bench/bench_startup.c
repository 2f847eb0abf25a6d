/* bench_startup.c - what the tools cost before they do anything: for `gtrace --help`, a 1x1 render to PNG,
 * `gmat --help` and `gcolor list`, the CPU time (user + system of the child, from wait4, best of RUNS), the
 * peak resident set (ru_maxrss of the best run) and the number of shared objects the dynamic loader mapped
 * (LD_DEBUG=files, "generating link map" lines, dlopen included); then `povray --help` the same way when
 * POV-Ray is installed, as the reference. Targets: <= 15 ms CPU and <= 20 MiB for gtrace's start-up and the
 * 1x1 render. The tools are found beside this program (BUILD/bench/../bin). Prints figures; never fails on
 * time (it fails only when a tool cannot be run). */
#include "generic/builtins.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#define RUNS 10

typedef struct {
    double cpu_ms;  /* user + system */
    double rss_mib; /* peak resident set */
    int objects;    /* shared objects mapped; -1 unknown */
} Cost;

/* Runs argv once with stdout and stderr to /dev/null (or stderr to debug_file, with LD_DEBUG=files); fills
 * the child's CPU time and peak RSS. Returns its exit status, or -1 if it could not run. */
static int run_once(char *const argv[], const char *debug_file, Cost *c)
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        int errfd = debug_file ? open(debug_file, O_WRONLY | O_CREAT | O_TRUNC, 0600) : null;
        if (null < 0 || errfd < 0)
            _exit(126);
        dup2(null, 1);
        dup2(errfd, 2);
        if (debug_file)
            setenv("LD_DEBUG", "files", 1);
        execv(argv[0], argv);
        _exit(127);
    }
    int status;
    struct rusage ru;
    while (wait4(pid, &status, 0, &ru) < 0)
        if (errno != EINTR)
            return -1;
    c->cpu_ms = (ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1e3 + (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) * 1e-3;
    c->rss_mib = ru.ru_maxrss / 1024.0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int count_link_maps(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char line[4096];
    int n = 0;
    while (fgets(line, sizeof line, f))
        if (strstr(line, "generating link map"))
            n++;
    fclose(f);
    return n;
}

/* Best of RUNS by CPU time, then one more run under LD_DEBUG=files for the object count. */
static int measure(char *const argv[], int expect_status, Cost *best)
{
    best->cpu_ms = 1e30;
    for (int i = 0; i < RUNS; i++) {
        Cost c;
        int st = run_once(argv, NULL, &c);
        if (st < 0 || (expect_status >= 0 && st != expect_status))
            return -1;
        if (c.cpu_ms < best->cpu_ms)
            *best = c;
    }
    char dbg[] = "/tmp/bench_startup_XXXXXX";
    int fd = mkstemp(dbg);
    best->objects = -1;
    if (fd >= 0) {
        close(fd);
        Cost c;
        if (run_once(argv, dbg, &c) >= 0)
            best->objects = count_link_maps(dbg);
        unlink(dbg);
    }
    return 0;
}

static void print_row(const char *name, const Cost *c, const Cost *ref)
{
    printf("%-26s %8.1f %9.1f %8d", name, c->cpu_ms, c->rss_mib, c->objects);
    if (ref && ref->cpu_ms > 0)
        printf("   %5.2fx %5.2fx", c->cpu_ms / ref->cpu_ms, c->rss_mib / ref->rss_mib);
    printf("\n");
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "bench_startup: %s\n", err.message);
        return 1;
    }
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return 1;
    self[n] = 0;
    char *slash = strrchr(self, '/');
    *slash = 0; /* BUILD/bench */
    char bin[PATH_MAX + 16], gtrace[PATH_MAX + 32], gmat[PATH_MAX + 32], gcolor[PATH_MAX + 32];
    snprintf(bin, sizeof bin, "%s/../bin", self);
    snprintf(gtrace, sizeof gtrace, "%s/gtrace", bin);
    snprintf(gmat, sizeof gmat, "%s/gmat", bin);
    snprintf(gcolor, sizeof gcolor, "%s/gcolor", bin);

    char dir[] = "/tmp/bench_startup_dir_XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    char scene[sizeof dir + 16], out[sizeof dir + 16];
    snprintf(scene, sizeof scene, "%s/s.scene", dir);
    snprintf(out, sizeof out, "%s/o.png", dir);
    FILE *f = fopen(scene, "w");
    if (!f)
        return 1;
    fputs("camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 1 height 1 }\n"
          "object sphere { center <0, 0, 0> radius 1 material lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
          "light point { position <2, 2, 4> intensity rgb 10 10 10 }\n",
          f);
    fclose(f);

    struct {
        const char *name;
        char *argv[8];
    } cases[] = {
        {"gtrace --help", {gtrace, "--help", NULL}},
        {"gtrace 1x1 render (png)", {gtrace, scene, "-o", out, "-q", "--threads", "1", NULL}},
        {"gmat --help", {gmat, "--help", NULL}},
        {"gcolor list", {gcolor, "list", NULL}},
    };
    Cost ref = {0, 0, -1};
    int have_ref = 0;
    char *pov[] = {"/usr/bin/povray", "--help", NULL};
    if (access(pov[0], X_OK) == 0 && measure(pov, -1, &ref) == 0)
        have_ref = 1;

    printf("start-up, best of %d runs (CPU = user + system of the process; targets for gtrace: <= 15 ms, <= 20 MiB)\n",
           RUNS);
    printf("%-26s %8s %9s %8s   %s\n", "", "CPU ms", "peak MiB", "objects", have_ref ? "ratios to povray --help" : "");
    int rc = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        Cost c;
        if (measure(cases[i].argv, 0, &c) != 0) {
            fprintf(stderr, "bench_startup: '%s' failed\n", cases[i].name);
            rc = 1;
            continue;
        }
        print_row(cases[i].name, &c, have_ref ? &ref : NULL);
    }
    if (have_ref)
        print_row("povray --help (reference)", &ref, NULL);
    unlink(out);
    unlink(scene);
    rmdir(dir);
    return rc;
}
