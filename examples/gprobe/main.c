/* gprobe - turns an HDR light probe into N directional lights and evaluates how well each technique does
 * (after Madsen & Laursen, "A Comparison of Techniques for Approximating Full Image-Based Lighting").
 * main.c: the command dispatch and the pieces every command shares. */
#include "gprobe.h"
#include "../common/startup.h"

#include <generic/services/image.h>

#include <generic/memory.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static void usage(FILE *f)
{
    fprintf(f,
            "usage: gprobe COMMAND [options]     (gprobe COMMAND --help for its options)\n"
            "       gprobe --help | --version\n"
            "Approximates an HDR light probe by N directional lights, spherical harmonics, an ambient cube or\n"
            "spherical Gaussians and compares the techniques by the irradiance they give, as in Madsen &\n"
            "Laursen's evaluation (their Fig. 6).\n"
            "commands:\n"
            "  eval        error of every technique and size against the ground truth: table, CSV, plot\n"
            "  report      an HTML page (and a markdown table) with every technique's radiance, irradiance and\n"
            "              error images and the plot\n"
            "  approx      write the lights of one technique as text-format entries (gtrace reads them)\n"
            "  irradiance  print the ground-truth irradiance (RGB) for one normal\n"
            "  convert     write the probe as a lat-long or angular map (after --rotate)\n"
            "  compare     RMSE of a render against a reference, whole image and inside the cast shadows\n"
            "  sky         write a synthetic sky-and-sun probe\n"
            "Every command also takes --plugin FILE.so (repeatable): load a module first, --memory-limit SIZE:\n"
            "the memory for probes and images (MiB, or with M, G, T; default 4096, or GENERIC_MEMORY_LIMIT_MB),\n"
            "--help and --version;\n"
            "every option value may also be written --option=value.\n"
            "Directions: right-handed, z up. In a lat-long probe row 0 is the zenith, the middle column looks\n"
            "along +x, a quarter of the way along +y and the edges along -x, as Blender maps world textures\n"
            "(see include/generic/services/probe.h).\n"
            CLI_EXIT_STATUS_HELP);
}

static int gprobe_main(int argc, char **argv)
{
    int rc = startup("gprobe", &argc, argv);
    if (rc >= 0)
        return rc;
    if (argc < 2 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(argv[1], "--version") == 0)
        return cli_version("gprobe");
    static const struct {
        const char *name;
        int (*run)(int argc, char **argv);
    } commands[] = {{"eval", cmd_eval},       {"approx", cmd_approx},   {"irradiance", cmd_irradiance},
                    {"convert", cmd_convert}, {"compare", cmd_compare}, {"sky", cmd_sky},
                    {"report", cmd_report}};
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        if (strcmp(argv[1], commands[i].name) == 0)
            return commands[i].run(argc - 1, argv + 1);
    fprintf(stderr, "gprobe: unknown command '%s' (expected eval, report, approx, irradiance, convert, compare or "
            "sky)\n", argv[1]);
    return 2;
}

/* ---- shared pieces ---- */

const char probe_args_help[] =
    "  --probe FILE      the light probe (EXR, HDR, PFM, TIFF, ...: anything OpenImageIO reads)\n"
    "  --format F        auto (default: 2:1 is lat-long, square is an angular map), latlong, angular\n"
    "  --rotate X,Y,Z    turn the environment by these angles in degrees about x, then y, then z\n"
    "                    (e.g. --rotate -90,0,0 makes the probe's zenith +y for a y-up scene)\n"
    "  -q, --quiet       no progress and no warnings\n"
    "  -h, --help        this text\n"
    "  --version         the version\n";

double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int no_operands(const CliParser *p)
{
    int n;
    char **rest = cli_operands(p, &n);
    if (n > 0)
        return cli_usage_error(p->prog, "unexpected argument '%s'", rest[0]);
    return 0;
}

int parse_vec3(const char *opt, const char *s, double v[3])
{
    const char *p = s;
    for (int k = 0; k < 3; k++) {
        char *end;
        errno = 0;
        v[k] = strtod(p, &end);
        if (errno || end == p || !isfinite(v[k]) || (k < 2 && *end != ',') || (k == 2 && *end)) {
            fprintf(stderr, "gprobe: %s expects three numbers X,Y,Z, got '%s'\n", opt, s);
            return -1;
        }
        p = end + 1;
    }
    return 0;
}

int probe_args_option(ProbeArgs *a, int c, const char *v)
{
    switch (c) {
    case 'q':
        a->quiet = 1;
        return 1;
    case PROBE_OPT_PROBE:
        a->path = v;
        return 1;
    case PROBE_OPT_FORMAT:
        if (strcmp(v, "auto") == 0)
            a->format = GPROBE_AUTO;
        else if (strcmp(v, "latlong") == 0)
            a->format = GPROBE_LATLONG;
        else if (strcmp(v, "angular") == 0)
            a->format = GPROBE_ANGULAR;
        else {
            fprintf(stderr, "gprobe: --format expects auto, latlong or angular, got '%s'\n", v);
            return -1;
        }
        return 1;
    case PROBE_OPT_ROTATE:
        if (parse_vec3("--rotate", v, a->rot) != 0)
            return -1;
        a->rotate = 1;
        return 1;
    default:
        return 0;
    }
}

int probe_next_option(CliParser *p, ProbeArgs *a, void (*usage)(FILE *), int *status)
{
    int c;
    while ((c = cli_next_own(p, "gprobe", usage, status)) >= 0) {
        int r = probe_args_option(a, c, optarg);
        if (r == 0)
            return c;
        if (r < 0) {
            *status = CLI_USAGE;
            return CLI_EXIT;
        }
    }
    return c;
}

GProbe *probe_args_load(const ProbeArgs *a)
{
    if (!a->path) {
        fprintf(stderr, "gprobe: no probe given (--probe FILE)\n");
        return NULL;
    }
    GError err;
    GProbe *p = NULL;
    if (gprobe_load(a->path, a->format, 0, &p, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return NULL;
    }
    if (gprobe_clamped_count(p) > 0 && !a->quiet)
        fprintf(stderr, "gprobe: warning: %s: %ld pixels had negative, NaN or infinite values (set to 0) or values "
                "above %g (clamped)\n", a->path, gprobe_clamped_count(p), (double)GPROBE_MAX_RADIANCE);
    if (a->rotate) {
        double R[9];
        gprobe_rotation_xyz(a->rot[0], a->rot[1], a->rot[2], R);
        GProbe *r = NULL;
        if (gprobe_rotate(p, R, &r, &err) != G_OK) {
            fprintf(stderr, "gprobe: %s\n", err.message);
            gprobe_destroy(p);
            return NULL;
        }
        gprobe_destroy(p);
        p = r;
    }
    return p;
}

int output_check(const char *path, int image)
{
    if (!path)
        return 0;
    GError err;
    if ((image ? gimage_check_output(path, &err) : gfile_check_output(path, &err)) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    return 0;
}

int text_open(TextOut *t, const char *path)
{
    memset(t, 0, sizeof *t);
    GError err;
    if (!(t->path = gmem_strdup(path))) {
        fprintf(stderr, "gprobe: out of memory\n");
        return -1;
    }
    if (gfile_output_begin(&t->out, path, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        gmem_free(t->path);
        return -1;
    }
    int fd = dup(t->out.fd); /* the stream's own descriptor; the output keeps its one for the fsync */
    if (fd < 0 || !(t->f = fdopen(fd, "w"))) {
        fprintf(stderr, "gprobe: cannot write %s: %s\n", path, strerror(errno));
        if (fd >= 0)
            close(fd);
        gfile_output_abort(&t->out);
        gmem_free(t->path);
        return -1;
    }
    return 0;
}

int text_close(TextOut *t, int ok)
{
    int rc = 0, failed = ferror(t->f);
    if (fclose(t->f) != 0 || failed) {
        if (ok)
            fprintf(stderr, "gprobe: cannot write %s: %s\n", t->path, failed ? "write error" : strerror(errno));
        ok = 0, rc = -1;
    }
    GError err;
    if (!ok) {
        gfile_output_abort(&t->out);
    } else if (gfile_output_commit(&t->out, -1, t->path, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        rc = -1;
    }
    gmem_free(t->path);
    return rc;
}

GProbeOptions probe_options(int fit_normals, int quiet)
{
    GProbeOptions opt = {0};
    opt.fit_normals = fit_normals;
    if (!quiet)
        opt.progress = progress_print;
    return opt;
}

void progress_print(void *user, const char *stage, double fraction)
{
    (void)user;
    static int tty = -1;
    if (tty < 0)
        tty = isatty(2);
    if (tty)
        fprintf(stderr, "\r  %s %3.0f%%", stage, 100.0 * fraction);
}

/* The run holds the standard descriptors, and every status leaves through cli_finish_stdout: a failed write to
 * standard output makes the run fail (cli_run). */
int main(int argc, char **argv) { return cli_run("gprobe", gprobe_main, argc, argv); }
