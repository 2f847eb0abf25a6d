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

int cmd_approx(int argc, char **argv)
{
    ProbeArgs pa = {0};
    const char *out = NULL, *tech = NULL;
    int n = 0, fit = 0;
    enum { OPT_FIT = PROBE_OPT_OWN };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS,
        {"technique", required_argument, NULL, 't'}, {"lights", required_argument, NULL, 'n'},
        {"output", required_argument, NULL, 'o'}, {"fit-normals", required_argument, NULL, OPT_FIT},
        {NULL, 0, NULL, 0},
    };
    CliParser cp;
    cli_begin(&cp, "gprobe approx", argc, argv, "hqt:n:o:", longopts);
    int c;
    while ((c = cli_next(&cp)) != -1) {
        int r = probe_args_option(&pa, c, optarg);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == 'h') {
            approx_usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == 't') {
            tech = optarg;
        } else if (c == 'n') {
            if (parse_int("-n", optarg, 1, 4096, &n) != 0)
                return CLI_USAGE;
        } else if (c == 'o') {
            out = optarg;
        } else if (c == OPT_FIT) {
            if (parse_int("--fit-normals", optarg, 2, 1000000, &fit) != 0)
                return CLI_USAGE;
        } else {
            return CLI_USAGE;
        }
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!tech || n <= 0 || !out) {
        fprintf(stderr, "gprobe approx: --technique, -n and -o are required (gprobe approx --help)\n");
        return 2;
    }
    GError err;
    GProbeTechnique t;
    if (gprobe_technique_parse(tech, &t, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return 2;
    }
    if (t == GPROBE_MEDIANCUT && (n & (n - 1)) != 0) {
        fprintf(stderr, "gprobe: median cut makes a power of two of lights, not %d (use adaptive for any count)\n", n);
        return 2;
    }
    if (output_check(out, 0) != 0)
        return 1;
    GProbe *p = probe_args_load(&pa);
    if (!p)
        return 1;
    int status = 1;
    const int m = 20000;
    GProbeLight *lights = gmem_calloc((size_t)n, sizeof *lights);
    GVec3 *normals = gmem_calloc(m, sizeof *normals);
    double *truth = gmem_calloc((size_t)m * 3, sizeof(double)), *approx = gmem_calloc((size_t)m * 3, sizeof(double));
    if (!lights || !normals || !truth || !approx) {
        fprintf(stderr, "gprobe: out of memory\n");
        goto done;
    }
    GProbeOptions opt = {0};
    opt.fit_normals = fit;
    if (!pa.quiet)
        opt.progress = progress_print;
    double t0 = now_seconds();
    if (gprobe_approximate(p, t, n, &opt, lights, &err) != G_OK) {
        fprintf(stderr, "\ngprobe: %s\n", err.message);
        goto done;
    }
    double dt = now_seconds() - t0;
    gprobe_fibonacci(m, normals);
    if (gprobe_irradiance(p, normals, m, truth, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        goto done;
    }
    gprobe_lights_irradiance(lights, n, normals, m, approx);
    GProbeErrors e;
    gprobe_compare(truth, approx, m, &e);
    int kept = 0;
    for (int i = 0; i < n; i++)
        kept += lights[i].rgb[0] > 0.0 || lights[i].rgb[1] > 0.0 || lights[i].rgb[2] > 0.0;

    TextOut to;
    if (text_open(&to, out) != 0)
        goto done;
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (pa.rotate)
        gprobe_rotation_xyz(pa.rot[0], pa.rot[1], pa.rot[2], R);
    for (int k = 0; k < 9; k++)
        R[k] = fabs(R[k]) < 1e-12 ? 0.0 : R[k];
    fprintf(to.f,
            "# %d directional lights approximating the light probe %s (%dx%d)\n"
            "# technique %s; irradiance error at %d normals: mean %.3f%%, max %.3f%% of the true irradiance,\n"
            "# mean %.4f%% of the largest irradiance.\n"
            "# The probe's zenith is (%.6g, %.6g, %.6g)%s. `direction` is the way the light travels;\n"
            "# the colour is the irradiance on a surface facing the light (linear Rec.709 RGB).\n",
            kept, pa.path, gprobe_width(p), gprobe_height(p), tech, m, e.mean_rel, e.max_rel, e.mean_norm, R[2], R[5],
            R[8], pa.rotate ? " after --rotate" : "");
    if (gprobe_clamped_count(p) > 0)
        fprintf(to.f, "# %ld probe pixels had negative, NaN, infinite or too large values and were clamped.\n",
                gprobe_clamped_count(p));
    if (kept < n)
        fprintf(to.f, "# %d of the %d lights carry no energy and are left out.\n", n - kept, n);
    for (int i = 0; i < n; i++) {
        const GProbeLight *l = &lights[i];
        if (!(l->rgb[0] > 0.0 || l->rgb[1] > 0.0 || l->rgb[2] > 0.0))
            continue;
        fprintf(to.f, "light directional { direction %.9g %.9g %.9g irradiance rgb %.9g %.9g %.9g }\n", -l->dir.x,
                -l->dir.y, -l->dir.z, l->rgb[0], l->rgb[1], l->rgb[2]);
    }
    if (text_close(&to, 1) != 0)
        goto done;
    if (!pa.quiet)
        fprintf(stderr, "%sgprobe: %s: %d lights (%s) in %.2f s; irradiance error mean %.3f%%, max %.3f%%\n",
                opt.progress ? "\r" : "", out, kept, tech, dt, e.mean_rel, e.max_rel);
    status = 0;
done:
    gmem_free(lights);
    gmem_free(normals);
    gmem_free(truth);
    gmem_free(approx);
    gprobe_destroy(p);
    return status;
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
    int c;
    while ((c = cli_next(&cp)) != -1) {
        int r = probe_args_option(&pa, c, optarg);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == 'h') {
            printf("usage: gprobe irradiance --probe FILE --normal X,Y,Z\n"
                   "Prints the ground-truth irradiance R G B (every pixel of the probe summed, the paper's Eq. 4)\n"
                   "on a surface with the given normal (normalised; z is up).\n%s"
                   "  --normal X,Y,Z    the surface normal\n" CLI_EXIT_STATUS_HELP,
                   probe_args_help);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == OPT_NORMAL) {
            if (parse_vec3("--normal", optarg, n) != 0)
                return CLI_USAGE;
            have = 1;
        } else {
            return CLI_USAGE;
        }
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
    int c;
    while ((c = cli_next(&cp)) != -1) {
        int r = probe_args_option(&pa, c, optarg);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == 'h') {
            printf("usage: gprobe convert --probe FILE [--to latlong|angular] [--size N] -o OUT\n"
                   "Writes the probe (after --rotate) as a latitude-longitude image or an angular map; the output's\n"
                   "extension picks the format (.exr/.hdr linear float; .png/.jpg sRGB encoded, clamped).\n%s"
                   "  --to F            latlong (default) or angular\n"
                   "  --size N          angular map size in pixels (default: the probe's height)\n"
                   "  -o OUT            output image\n" CLI_EXIT_STATUS_HELP,
                   probe_args_help);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == 'o') {
            out = optarg;
        } else if (c == OPT_TO) {
            if (strcmp(optarg, "latlong") == 0)
                to = GPROBE_LATLONG;
            else if (strcmp(optarg, "angular") == 0)
                to = GPROBE_ANGULAR;
            else {
                fprintf(stderr, "gprobe convert: --to expects latlong or angular, got '%s'\n", optarg);
                return CLI_USAGE;
            }
        } else if (c == OPT_SIZE) {
            if (parse_int("--size", optarg, 2, 32768, &size) != 0)
                return CLI_USAGE;
        } else {
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
