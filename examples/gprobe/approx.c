/* approx.c - `gprobe approx` (lights as text-format entries), `gprobe irradiance` and `gprobe convert`. */
#include "gprobe.h"

#include <generic/memory.h>

#include <math.h>
#include <string.h>

static void approx_usage(FILE *f)
{
    fprintf(f,
            "usage: gprobe approx --probe FILE --technique T -n N -o LIGHTS.txt [--fit-normals N]\n"
            "Approximates the probe by N directional lights and writes them as text-format entries\n"
            "    light directional { direction DX DY DZ irradiance rgb R G B }\n"
            "(gtrace's directional light: `direction` is the way the light travels, i.e. from the light\n"
            "towards the scene, and the colour is the irradiance on a surface facing the light, in linear\n"
            "Rec.709 RGB as the probe's pixels). Lights that carry no energy are left out. The file's\n"
            "header states the technique and the irradiance error of the lights.\n"
            "%s"
            "  --technique T     mediancut (N a power of two), adaptive, kmeans, irradiance or variance\n"
            "                    (the bases of gprobe eval are not lights: see gprobe report)\n"
            "  -n N              number of lights (1..4096)\n"
            "  -o FILE           output text file (written whole or not at all)\n"
            "  --fit-normals N   normals the irradiance optimisation fits (default 2000)\n" CLI_EXIT_STATUS_HELP,
            probe_args_help);
}

/* The command line of approx. */
typedef struct ApproxArgs {
    ProbeArgs probe;
    const char *out, *tech; /* -o, --technique */
    int n, fit;             /* -n, --fit-normals */
} ApproxArgs;

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int approx_args(int argc, char **argv, ApproxArgs *a)
{
    enum { OPT_FIT = PROBE_OPT_OWN };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS,
        {"technique", required_argument, NULL, 't'}, {"lights", required_argument, NULL, 'n'},
        {"output", required_argument, NULL, 'o'}, {"fit-normals", required_argument, NULL, OPT_FIT},
        {NULL, 0, NULL, 0},
    };
    memset(a, 0, sizeof *a);
    CliParser cp;
    cli_begin(&cp, "gprobe approx", argc, argv, "hqt:n:o:", longopts);
    int c, status = CLI_OK;
    while ((c = probe_next_option(&cp, &a->probe, approx_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        switch (c) {
        case 't':
            a->tech = optarg;
            break;
        case 'o':
            a->out = optarg;
            break;
        case 'n':
            if (cli_int("gprobe", "-n", optarg, 1, 4096, &a->n) != 0)
                return CLI_USAGE;
            break;
        case OPT_FIT:
            if (cli_int("gprobe", "--fit-normals", optarg, 2, 1000000, &a->fit) != 0)
                return CLI_USAGE;
            break;
        default:
            return CLI_USAGE;
        }
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!a->tech || a->n <= 0 || !a->out) {
        fprintf(stderr, "gprobe approx: --technique, -n and -o are required (gprobe approx --help)\n");
        return CLI_USAGE;
    }
    return -1;
}

/* The technique named by a, checked against its count: G_OK, or a usage error with its message printed. */
static int approx_technique(const ApproxArgs *a, GProbeTechnique *t)
{
    GError err;
    if (gprobe_technique_parse(a->tech, t, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return G_ERR_INVALID;
    }
    if (*t == GPROBE_MEDIANCUT && (a->n & (a->n - 1)) != 0) {
        fprintf(stderr, "gprobe: median cut makes a power of two of lights, not %d (use adaptive for any count)\n",
                a->n);
        return G_ERR_INVALID;
    }
    return G_OK;
}

static int carries_light(const GProbeLight *l) { return l->rgb[0] > 0.0 || l->rgb[1] > 0.0 || l->rgb[2] > 0.0; }

/* The lights file: a header with the technique, its errors and the probe's frame, then the lights that carry
 * energy as text-format entries. */
static void write_lights(FILE *f, const ApproxArgs *a, const GProbe *p, const GProbeLight *lights, int kept,
                         const GProbeErrors *e, int m)
{
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (a->probe.rotate)
        gprobe_rotation_xyz(a->probe.rot[0], a->probe.rot[1], a->probe.rot[2], R);
    for (int k = 0; k < 9; k++)
        R[k] = fabs(R[k]) < 1e-12 ? 0.0 : R[k];
    fprintf(f,
            "# %d directional lights approximating the light probe %s (%dx%d)\n"
            "# technique %s; irradiance error at %d normals: mean %.3f%%, max %.3f%% of the true irradiance,\n"
            "# mean %.4f%% of the largest irradiance.\n"
            "# The probe's zenith is (%.6g, %.6g, %.6g)%s. `direction` is the way the light travels;\n"
            "# the colour is the irradiance on a surface facing the light (linear Rec.709 RGB).\n",
            kept, a->probe.path, gprobe_width(p), gprobe_height(p), a->tech, m, e->mean_rel, e->max_rel, e->mean_norm,
            R[2], R[5], R[8], a->probe.rotate ? " after --rotate" : "");
    if (gprobe_clamped_count(p) > 0)
        fprintf(f, "# %ld probe pixels had negative, NaN, infinite or too large values and were clamped.\n",
                gprobe_clamped_count(p));
    if (kept < a->n)
        fprintf(f, "# %d of the %d lights carry no energy and are left out.\n", a->n - kept, a->n);
    for (int i = 0; i < a->n; i++) {
        const GProbeLight *l = &lights[i];
        if (carries_light(l))
            fprintf(f, "light directional { direction %.9g %.9g %.9g irradiance rgb %.9g %.9g %.9g }\n", -l->dir.x,
                    -l->dir.y, -l->dir.z, l->rgb[0], l->rgb[1], l->rgb[2]);
    }
}

/* Makes the lights, measures their irradiance error at the truth's normals and writes them: 0, or -1 with a
 * message. */
static int approx_lights(const ApproxArgs *a, GProbeTechnique tech, const GProbe *p, GProbeLight *lights,
                         Truth *truth)
{
    GError err;
    GProbeOptions opt = probe_options(a->fit, a->probe.quiet);
    double t0 = now_seconds();
    if (gprobe_approximate(p, tech, a->n, &opt, lights, &err) != G_OK) {
        fprintf(stderr, "\ngprobe: %s\n", err.message);
        return -1;
    }
    double dt = now_seconds() - t0;
    if (truth_compute(truth, p, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    gprobe_lights_irradiance(lights, a->n, truth->normals, truth->m, truth->approx);
    GProbeErrors e;
    gprobe_compare(truth->truth, truth->approx, truth->m, &e);
    int kept = 0;
    for (int i = 0; i < a->n; i++)
        kept += carries_light(&lights[i]);
    TextOut to;
    if (text_open(&to, a->out) != 0)
        return -1;
    write_lights(to.f, a, p, lights, kept, &e, truth->m);
    if (text_close(&to, 1) != 0)
        return -1;
    if (!a->probe.quiet)
        fprintf(stderr, "%sgprobe: %s: %d lights (%s) in %.2f s; irradiance error mean %.3f%%, max %.3f%%\n",
                opt.progress ? "\r" : "", a->out, kept, a->tech, dt, e.mean_rel, e.max_rel);
    return 0;
}

int cmd_approx(int argc, char **argv)
{
    ApproxArgs a;
    int status = approx_args(argc, argv, &a);
    if (status >= 0)
        return status;
    GProbeTechnique t;
    if (approx_technique(&a, &t) != G_OK)
        return CLI_USAGE;
    if (output_check(a.out, 0) != 0)
        return 1;
    GProbe *p = probe_args_load(&a.probe);
    if (!p)
        return 1;
    Truth truth = {0};
    GProbeLight *lights = gmem_calloc((size_t)a.n, sizeof *lights);
    status = 1;
    if (truth_alloc(&truth, 20000) != 0 || !lights)
        fprintf(stderr, "gprobe: out of memory\n");
    else if (approx_lights(&a, t, p, lights, &truth) == 0)
        status = 0;
    truth_free(&truth);
    gmem_free(lights);
    gprobe_destroy(p);
    return status;
}

static void irradiance_usage(FILE *f)
{
    fprintf(f, "usage: gprobe irradiance --probe FILE --normal X,Y,Z\n"
               "Prints the ground-truth irradiance R G B (every pixel of the probe summed, the paper's Eq. 4)\n"
               "on a surface with the given normal (normalised; z is up).\n%s"
               "  --normal X,Y,Z    the surface normal\n" CLI_EXIT_STATUS_HELP,
            probe_args_help);
}

int cmd_irradiance(int argc, char **argv)
{
    ProbeArgs pa = {0};
    double n[3];
    int have = 0;
    enum { OPT_NORMAL = PROBE_OPT_OWN };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS, {"normal", required_argument, NULL, OPT_NORMAL}, {NULL, 0, NULL, 0}};
    CliParser cp;
    cli_begin(&cp, "gprobe irradiance", argc, argv, "hq", longopts);
    int c, status = CLI_OK;
    while ((c = probe_next_option(&cp, &pa, irradiance_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (c != OPT_NORMAL || parse_vec3("--normal", optarg, n) != 0)
            return CLI_USAGE;
        have = 1;
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!have) {
        fprintf(stderr, "gprobe irradiance: --normal X,Y,Z is required\n");
        return 2;
    }
    GVec3 nv = gvec3(n[0], n[1], n[2]);
    if (!(gvec3_length(nv) > 0.0)) {
        fprintf(stderr, "gprobe irradiance: the normal must not be zero\n");
        return 2;
    }
    nv = gvec3_normalize(nv);
    GProbe *p = probe_args_load(&pa);
    if (!p)
        return 1;
    double E[3];
    GError err;
    int rc = gprobe_irradiance(p, &nv, 1, E, &err);
    if (rc == G_OK)
        printf("%.9g %.9g %.9g\n", E[0], E[1], E[2]);
    else
        fprintf(stderr, "gprobe: %s\n", err.message);
    gprobe_destroy(p);
    return rc == G_OK ? 0 : 1;
}

static void convert_usage(FILE *f)
{
    fprintf(f, "usage: gprobe convert --probe FILE [--to latlong|angular] [--size N] -o OUT\n"
               "Writes the probe (after --rotate) as a latitude-longitude image or an angular map; the output's\n"
               "extension picks the format (.exr/.hdr linear float; .png/.jpg sRGB encoded, clamped).\n%s"
               "  --to F            latlong (default) or angular\n"
               "  --size N          angular map size in pixels (default: the probe's height)\n"
               "  -o OUT            output image\n" CLI_EXIT_STATUS_HELP,
            probe_args_help);
}

int cmd_convert(int argc, char **argv)
{
    ProbeArgs pa = {0};
    const char *out = NULL;
    GProbeFormat to = GPROBE_LATLONG;
    int size = 0;
    enum { OPT_TO = PROBE_OPT_OWN, OPT_SIZE };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS, {"output", required_argument, NULL, 'o'},
        {"to", required_argument, NULL, OPT_TO}, {"size", required_argument, NULL, OPT_SIZE}, {NULL, 0, NULL, 0}};
    CliParser cp;
    cli_begin(&cp, "gprobe convert", argc, argv, "hqo:", longopts);
    int c, status = CLI_OK;
    while ((c = probe_next_option(&cp, &pa, convert_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (c == 'o') {
            out = optarg;
        } else if (c == OPT_TO && (strcmp(optarg, "latlong") == 0 || strcmp(optarg, "angular") == 0)) {
            to = strcmp(optarg, "latlong") == 0 ? GPROBE_LATLONG : GPROBE_ANGULAR;
        } else if (c == OPT_TO) {
            fprintf(stderr, "gprobe convert: --to expects latlong or angular, got '%s'\n", optarg);
            return CLI_USAGE;
        } else if (c != OPT_SIZE || cli_int("gprobe", "--size", optarg, 2, 32768, &size) != 0) {
            return CLI_USAGE;
        }
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!out) {
        fprintf(stderr, "gprobe convert: -o OUT is required\n");
        return 2;
    }
    if (output_check(out, 1) != 0)
        return 1;
    GProbe *p = probe_args_load(&pa);
    if (!p)
        return 1;
    GError err;
    GImage img;
    int rc = to == GPROBE_ANGULAR ? gprobe_to_angular(p, size ? size : gprobe_height(p), &img, &err)
                                  : gprobe_to_image(p, &img, &err);
    if (rc == G_OK) {
        rc = gimage_write(out, &img, NULL, &err);
        gimage_free(&img);
    }
    if (rc != G_OK)
        fprintf(stderr, "gprobe: %s\n", err.message);
    gprobe_destroy(p);
    return rc == G_OK ? 0 : 1;
}
