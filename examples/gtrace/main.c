/* gtrace - a Whitted ray tracer written only against the generic colour and material interfaces.
 * main.c: the command line of `gtrace` (loading, rendering, writing, the summary line; `gtrace merge` is
 * film/merge_cli.c); the tracer itself is libgtrace (the folders beside this file), and every message of its
 * failures is printed here. */
#include "scenefile/parse.h"
#include "scene/accel.h"
#include "integrators/bands.h"
#include "integrators/sppm.h"
#include "distributed/dist.h"
#include "film/merge_cli.h"
#include "distributed/mpi_load.h"
#include "render/render.h"
#include "trace/sampler.h"
#include "film/output.h"
#include "film/viewing.h"
#include "lights/probe_env.h"
#include "scenefile/type_list.h"
#include "../common/cli.h"
#include "../common/startup.h"

#include <generic/builtins.h>
#include <generic/services/file.h>
#include <generic/services/image.h>
#include <generic/memory.h>
#include <generic/plugin.h>
#include <generic/registry.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Prints the space-separated words of list on lines of at most width columns, each indented by indent. */
static void print_wrapped(FILE *f, int indent, int width, const char *list)
{
    int col = 0;
    for (const char *p = list; *p;) {
        int len = (int)strcspn(p, " ");
        if (col > 0 && col + 1 + len > width) {
            fputc('\n', f);
            col = 0;
        }
        col += col ? fprintf(f, " %.*s", len, p) : fprintf(f, "%*s%.*s", indent, "", len, p);
        p += len;
        p += *p == ' ';
    }
    fputc('\n', f);
}

static void usage(FILE *f)
{
    char models[256];
    gregistry_names(GKIND_COLORMODEL, models, sizeof models);
    fprintf(f,
            "usage: gtrace SCENE -o OUT [--width W] [--height H] [--spp N] [--depth D] [--max-rays N]\n"
            "              [--colormodel M] [--threads N] [--cutoff W] [--bands K] [--exposure STOPS]\n"
            "              [--plugin FILE.so]... [-q]\n"
            "              [--allow-plugins] [--confine DIR]\n"
            "              [--probe FILE] [--probe-technique T] [--probe-count N] [--probe-samples N]\n"
            "              [--probe-scale S] [--probe-shadows on|off] [--crop X0,Y0,X1,Y1]\n"
            "              [--integrator whitted|path|sppm|light] [--passes N] [--photons N] [--radius R] [--alpha A]\n"
            "              [--sampler sobol|independent] [--equiangular on|off] [--illuminant NAME]\n"
            "              [--spectral] [--display D] [--view V] [--ocio-config FILE]\n"
            "              [--mpi-block N] [--mpi-timeout S] [--mpi-dedicated]\n"
            "       gtrace merge PIECE... -o OUT\n"
            "       gtrace types [object|light|camera] [--markdown]\n"
            "       gtrace --help | --version\n"
            "Renders a scene file (the library's text format with camera, object and light entries) with a\n"
            "Whitted ray tracer that uses colours and materials only through the generic interfaces.\n"
            "Every scene coordinate (after transforms) must be finite and within +-1e15.\n"
            "  -o OUT            output image; the extension picks the format: .exr/.hdr linear float,\n"
            "                    the others (.png, .jpg, ...) display-encoded (sRGB) after the exposure,\n"
            "                    clamped. This build writes (OpenImageIO's writers, found when it was built):\n");
    print_wrapped(f, 20, 100, gimage_write_extensions());
    fprintf(f,
            "  --width W         image width (default: the camera's; height follows its aspect)\n"
            "  --height H        image height (default: the camera's)\n"
            "  --spp N           samples per pixel, stratified and jittered (default: the camera's)\n"
            "  --depth D         reflection/refraction recursion depth (default: the camera's, 0..1000)\n"
            "  --max-rays N      reflected and refracted rays one camera sample may spawn, 1..1000000\n"
            "                    (default 4096): with cutoff 0, glass doubles them at every level; the\n"
            "                    branches beyond are not traced and the samples so cut are reported\n"
            "  --colormodel M    compute in colour model M instead of the scene's (%s, or one a\n"
            "                    module registers: --plugin or a `plugin` statement of the scene)\n"
            "  --plugin FILE.so  load a module before reading the scene (repeatable; a bare name is\n"
            "                    searched in GENERIC_PLUGIN_PATH, then the installed plug-in directory, then\n"
            "                    the current directory)\n"
            "  --allow-plugins   let `plugin` statements of the scene load modules (a module runs native\n"
            "                    code: refused without this or GENERIC_ALLOW_PLUGINS=1)\n"
            "  --confine DIR     every file the scene reads (itself, includes, modules, meshes, images,\n"
            "                    BFC files, probes) and the LUTs of the OpenColorIO config must lie under\n"
            "                    DIR once symbolic links are resolved\n"
            "  --memory-limit SIZE  memory for what the scene's files size (images, probes, meshes,\n"
            "                    colours, framebuffer, ...): MiB, or with M, G, T (default 4096, or\n"
            "                    GENERIC_MEMORY_LIMIT_MB); a scene over it is refused before the allocation\n"
            "  --cutoff W        do not trace rays whose weight in the pixel is below W (default: the\n"
            "                    camera's, 1e-3; 0 traces every ray to the depth limit)\n"
            "  --bands K         most wavelength groups a dispersive refraction splits into, 1..1024\n"
            "                    (default: the camera's, 16; the model's bands are grouped evenly; 1: no\n"
            "                    dispersion)\n"
            "  --threads N       threads for rendering and the BVH build (default: all processors)\n"
            "  --integrator I    whitted (default: the paper's Fig. 4) or path (path tracing: next-event\n"
            "                    estimation and material sampling by MIS, Russian roulette; --spp paths\n"
            "                    per pixel, --depth bounces) or sppm (stochastic progressive photon\n"
            "                    mapping: caustics through glass and from mirrors; --spp is not used)\n"
            "                    or light (particles from the lights connected to a pinhole camera;\n"
            "                    --passes x --photons paths; lights seen directly are not drawn)\n"
            "  --passes N        sppm, light: passes, 1..1000000 (default 64)\n"
            "  --photons N       sppm, light: photon paths per pass, 1..100000000 (default 100000)\n"
            "  --radius R        sppm: initial gather radius in scene units (default: twice a pixel's\n"
            "                    footprint at the scene's centre)\n"
            "  --alpha A         sppm: fraction of a pass's photons kept, in (0, 1] (default 2/3)\n"
            "  --sampler S       path: sobol (default: pixel positions, light and material samples from\n"
            "                    each pixel's scrambled Sobol sequence) or independent (random numbers)\n"
            "  --equiangular on|off  path: also sample scattering in homogeneous media towards point, spot\n"
            "                    and IES lights by equiangular sampling, MIS-weighted (default on)\n"
            "  --illuminant NAME the viewing illuminant, the film's white: a CIE illuminant (A, D50, F11,\n"
            "                    LED-B1, ...; gcolor list --illuminants) or 'blackbody K'; the rendered XYZ is\n"
            "                    adapted from its white to sRGB's (D65) by the Bradford transform, so that a\n"
            "                    white surface lit by it comes out neutral (default: none, no adaptation;\n"
            "                    --spectral's values at wavelengths are not adapted)\n"
            "  --exposure STOPS  exposure for .png/.jpg output (default: the camera's)\n"
            "  --probe FILE      replace the image of the scene's `light probe` (relative to the current\n"
            "                    directory); the other --probe options replace its other settings\n"
            "  --probe-technique T    mediancut, adaptive, kmeans, irradiance, variance (directional\n"
            "                         lights), reference (Monte Carlo over the whole probe), or a basis\n"
            "                         as an ambient term: sh, sh-hanning, ambientcube, sg-naive, sg-ls,\n"
            "                         sg-nnls, sg-ambient\n"
            "  --probe-count N        number of lights of a technique (1..4096; irradiance: at most 128,\n"
            "                         and count x fit_normals at most 524288)\n"
            "  --probe-samples N      reference: samples per shading point (1..65536)\n"
            "  --probe-shadows on|off reference: shadow rays (off: the unoccluded image)\n"
            "  --probe-scale S        multiplies the probe's radiance\n"
            "  --crop X0,Y0,X1,Y1  render only the pixels X0 <= x < X1, Y0 <= y < Y1 of the full image (top\n"
            "                    left is 0,0); the output is the region's size and its pixels equal those of\n"
            "                    the full render; an .exr records the region as its data window (the full\n"
            "                    image is the display window), so crops can be merged\n"
            "  --display D       write the 8-bit output through the view of display D of an OpenColorIO\n"
            "  --view V          config instead of the sRGB encoding (default: the config's default display,\n"
            "                    the display's default view); the config is --ocio-config FILE, else $OCIO,\n"
            "                    else the one libgeneric ships (share/generic/ocio/config.ocio: display sRGB,\n"
            "                    views Standard (the sRGB transfer function, as without --display), Log (12\n"
            "                    stops, 2^-8..2^4) and Raw (linear, clamped)); unknown names are listed\n"
            "  --ocio-config FILE  the OpenColorIO config for --display and --view\n"
            "  --spectral        with -o OUT.exr: also store each pixel's light at the colour model's own\n"
            "                    wavelengths, as emissive channels S0.<nm>nm (e.g. S0.550,000000nm) beside\n"
            "                    R,G,B, in the OpenEXR layout of Fichet, Pacanowski and Wilkie 2021 (JCGT\n"
            "                    10(3)); refused in a model without wavelength samples and for other formats\n"
            "Under mpirun (Open MPI) every rank loads the scene, rank 0 hands out blocks of the image on demand,\n"
            "renders some itself, gathers the rest and writes the image, equal to a single-process render\n"
            "(docs/distributed.md); sppm and light share each batch of photons instead of blocks:\n"
            "  --mpi-block N     blocks of N x N pixels, the unit a rank asks for (default %d)\n"
            "  --mpi-timeout S   seconds rank 0 waits for a silent rank before it ends the job (default %g;\n"
            "                    longer than a block takes to render)\n"
            "  --mpi-dedicated   rank 0 only hands out and gathers blocks\n"
            "  gtrace merge PIECE... -o OUT   joins --crop pieces (.exr) rendered apart into the full image\n"
            "                    (gtrace merge --help)\n"
            "  gtrace types      the object, light and camera types, or with --markdown the reference of their\n"
            "                    parameters (gtrace types --help)\n"
            "  -q, --quiet       no progress and no summary line (progress: a bar on a terminal; elsewhere a\n"
            "                    line when a tenth of the work and 10 s have passed, GTRACE_PROGRESS_INTERVAL=S\n"
            "                    for another interval)\n"
            "  -h, --help        this text\n"
            "  --version         the version\n"
            "Every option value may also be written --option=value.\n"
            CLI_EXIT_STATUS_HELP,
            models, DIST_DEFAULT_BLOCK, DIST_DEFAULT_TIMEOUT);
}

enum {
    OPT_WIDTH = CLI_FIRST_OWN, OPT_HEIGHT, OPT_SPP, OPT_DEPTH, OPT_MAX_RAYS, OPT_THREADS, OPT_COLORMODEL,
    OPT_EXPOSURE, OPT_CUTOFF, OPT_CROP, OPT_BANDS, OPT_INTEGRATOR, OPT_PROBE, OPT_PROBE_TECHNIQUE, OPT_PROBE_COUNT,
    OPT_PROBE_SAMPLES, OPT_PROBE_SHADOWS, OPT_PROBE_SCALE, OPT_WAVES, OPT_DISPLAY, OPT_VIEW, OPT_OCIO_CONFIG,
    OPT_MPI_BLOCK, OPT_MPI_TIMEOUT, OPT_MPI_DEDICATED, OPT_PASSES, OPT_PHOTONS, OPT_RADIUS, OPT_ALPHA, OPT_SAMPLER,
    OPT_EQUIANGULAR, OPT_ILLUMINANT
};

/* The --probe options (code c, its value v); -1 with a message for a bad one. */
static int parse_probe_option(int c, const char *v, ProbeOverride *p)
{
    switch (c) {
    case OPT_PROBE:
        p->file = v;
        return 0;
    case OPT_PROBE_TECHNIQUE:
        p->technique = v;
        return 0;
    case OPT_PROBE_COUNT:
        return cli_int("gtrace", "--probe-count", v, 1, 4096, &p->count);
    case OPT_PROBE_SAMPLES:
        return cli_int("gtrace", "--probe-samples", v, 1, 65536, &p->samples);
    case OPT_PROBE_SHADOWS:
        if (strcmp(v, "on") != 0 && strcmp(v, "off") != 0) {
            fprintf(stderr, "gtrace: --probe-shadows expects on or off, got '%s'\n", v);
            return -1;
        }
        p->shadows = strcmp(v, "on") == 0;
        return 0;
    default: /* OPT_PROBE_SCALE */
        if (cli_double("gtrace", "--probe-scale", v, 0.0, 1e30, &p->scale) != 0)
            return -1;
        if (!(p->scale > 0.0)) {
            fprintf(stderr, "gtrace: --probe-scale expects a positive number, got '%s'\n", v);
            return -1;
        }
        return 0;
    }
}

typedef struct Options {
    ProbeOverride probe;
    GImageDisplay display; /* --display, --view, --ocio-config */
    int have_display;
    const char *scene, *out, *colormodel;
    const char *illuminant; /* --illuminant (NULL: none) */
    int width, height, spp, depth, threads, quiet, max_rays, bands, integrator, waves;
    int passes, photons;   /* --integrator sppm (0: its defaults) */
    int sampler;           /* --sampler: SAMPLER_SOBOL (0, default) or SAMPLER_INDEPENDENT */
    int no_equiangular;    /* --equiangular off */
    double radius, alpha;
    int have_exposure, have_cutoff, have_crop;
    int crop[4]; /* x0, y0, x1, y1 */
    double exposure, cutoff;
    DistSettings dist;
} Options;

/* "X0,Y0,X1,Y1": four whole numbers with X0 < X1, Y0 < Y1 (checked against the image size later). */
static int parse_crop(const char *s, int crop[4])
{
    const char *p = s;
    for (int k = 0; k < 4; k++) {
        char *end;
        errno = 0;
        long v = strtol(p, &end, 10);
        if (errno || end == p || v < 0 || v > 65536 || (k < 3 && *end != ',') || (k == 3 && *end)) {
            fprintf(stderr, "gtrace: --crop expects X0,Y0,X1,Y1 (whole pixel numbers), got '%s'\n", s);
            return -1;
        }
        crop[k] = (int)v;
        p = end + 1;
    }
    if (crop[0] >= crop[2] || crop[1] >= crop[3]) {
        fprintf(stderr, "gtrace: --crop %s is empty (it needs X0 < X1 and Y0 < Y1; X1 and Y1 are excluded)\n", s);
        return -1;
    }
    return 0;
}

/* 0 to go on, 1 after --help or --version (exit 0), -1 after a usage error (exit 2). */
static int parse_args(int argc, char **argv, Options *o)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS,
        {"output", required_argument, NULL, 'o'},
        {"quiet", no_argument, NULL, 'q'},
        {"width", required_argument, NULL, OPT_WIDTH},
        {"height", required_argument, NULL, OPT_HEIGHT},
        {"spp", required_argument, NULL, OPT_SPP},
        {"depth", required_argument, NULL, OPT_DEPTH},
        {"max-rays", required_argument, NULL, OPT_MAX_RAYS},
        {"threads", required_argument, NULL, OPT_THREADS},
        {"colormodel", required_argument, NULL, OPT_COLORMODEL},
        {"exposure", required_argument, NULL, OPT_EXPOSURE},
        {"cutoff", required_argument, NULL, OPT_CUTOFF},
        {"crop", required_argument, NULL, OPT_CROP},
        {"bands", required_argument, NULL, OPT_BANDS},
        {"integrator", required_argument, NULL, OPT_INTEGRATOR},
        {"sampler", required_argument, NULL, OPT_SAMPLER},
        {"equiangular", required_argument, NULL, OPT_EQUIANGULAR},
        {"illuminant", required_argument, NULL, OPT_ILLUMINANT},
        {"passes", required_argument, NULL, OPT_PASSES},
        {"photons", required_argument, NULL, OPT_PHOTONS},
        {"radius", required_argument, NULL, OPT_RADIUS},
        {"alpha", required_argument, NULL, OPT_ALPHA},
        {"probe", required_argument, NULL, OPT_PROBE},
        {"probe-technique", required_argument, NULL, OPT_PROBE_TECHNIQUE},
        {"probe-count", required_argument, NULL, OPT_PROBE_COUNT},
        {"probe-samples", required_argument, NULL, OPT_PROBE_SAMPLES},
        {"probe-shadows", required_argument, NULL, OPT_PROBE_SHADOWS},
        {"probe-scale", required_argument, NULL, OPT_PROBE_SCALE},
        {"spectral", no_argument, NULL, OPT_WAVES},
        {"display", required_argument, NULL, OPT_DISPLAY},
        {"view", required_argument, NULL, OPT_VIEW},
        {"ocio-config", required_argument, NULL, OPT_OCIO_CONFIG},
        {"mpi-block", required_argument, NULL, OPT_MPI_BLOCK},
        {"mpi-timeout", required_argument, NULL, OPT_MPI_TIMEOUT},
        {"mpi-dedicated", no_argument, NULL, OPT_MPI_DEDICATED},
        {NULL, 0, NULL, 0},
    };
    memset(o, 0, sizeof *o);
    o->width = o->height = o->spp = o->depth = -1;
    o->probe.shadows = -1;
    o->dist = (DistSettings){.block = DIST_DEFAULT_BLOCK, .timeout = DIST_DEFAULT_TIMEOUT};
    CliParser p;
    cli_begin(&p, "gtrace", argc, argv, "ho:q", longopts);
    int c, rc = 0;
    while (rc == 0 && (c = cli_next(&p)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return 1;
        case CLI_VERSION:
            cli_version("gtrace");
            printf("%s\n", mpi_build_note());
            return 1;
        case 'q':
            o->quiet = 1;
            break;
        case 'o':
            o->out = optarg;
            break;
        case OPT_WIDTH:
            rc = cli_int("gtrace", "--width", optarg, 1, 65536, &o->width);
            break;
        case OPT_HEIGHT:
            rc = cli_int("gtrace", "--height", optarg, 1, 65536, &o->height);
            break;
        case OPT_SPP:
            rc = cli_int("gtrace", "--spp", optarg, 1, 65536, &o->spp);
            break;
        case OPT_DEPTH:
            rc = cli_int("gtrace", "--depth", optarg, 0, 1000, &o->depth);
            break;
        case OPT_MAX_RAYS:
            rc = cli_int("gtrace", "--max-rays", optarg, 1, RENDER_LIMIT_MAX_RAYS, &o->max_rays);
            break;
        case OPT_THREADS:
            rc = cli_int("gtrace", "--threads", optarg, 1, 1024, &o->threads);
            break;
        case OPT_BANDS:
            rc = cli_int("gtrace", "--bands", optarg, 1, BANDS_LIMIT, &o->bands);
            break;
        case OPT_INTEGRATOR:
            if (strcmp(optarg, "whitted") == 0 || strcmp(optarg, "path") == 0 || strcmp(optarg, "sppm") == 0 ||
                strcmp(optarg, "light") == 0) {
                o->integrator = strcmp(optarg, "path") == 0    ? RENDER_PATH
                                : strcmp(optarg, "sppm") == 0  ? RENDER_SPPM
                                : strcmp(optarg, "light") == 0 ? RENDER_LIGHT
                                                               : RENDER_WHITTED;
            } else {
                fprintf(stderr, "gtrace: --integrator expects whitted, path, sppm or light, got '%s'\n", optarg);
                rc = -1;
            }
            break;
        case OPT_SAMPLER:
            if (strcmp(optarg, "sobol") == 0 || strcmp(optarg, "independent") == 0) {
                o->sampler = strcmp(optarg, "sobol") == 0 ? SAMPLER_SOBOL : SAMPLER_INDEPENDENT;
            } else {
                fprintf(stderr, "gtrace: --sampler expects sobol or independent, got '%s'\n", optarg);
                rc = -1;
            }
            break;
        case OPT_EQUIANGULAR:
            if (strcmp(optarg, "on") == 0 || strcmp(optarg, "off") == 0) {
                o->no_equiangular = strcmp(optarg, "off") == 0;
            } else {
                fprintf(stderr, "gtrace: --equiangular expects on or off, got '%s'\n", optarg);
                rc = -1;
            }
            break;
        case OPT_PASSES:
            rc = cli_int("gtrace", "--passes", optarg, 1, SPPM_MAX_PASSES, &o->passes);
            break;
        case OPT_PHOTONS:
            rc = cli_int("gtrace", "--photons", optarg, 1, SPPM_MAX_PHOTONS, &o->photons);
            break;
        case OPT_RADIUS:
            rc = cli_double("gtrace", "--radius", optarg, 1e-12, 1e15, &o->radius);
            break;
        case OPT_ALPHA:
            rc = cli_double("gtrace", "--alpha", optarg, 1e-6, 1.0, &o->alpha);
            break;
        case OPT_COLORMODEL:
            o->colormodel = optarg;
            break;
        case OPT_ILLUMINANT: {
            GError e;
            o->illuminant = optarg;
            if (gcolor_named_light(NULL, optarg, &e) != G_OK) {
                fprintf(stderr, "gtrace: --illuminant: %s\n", e.message);
                rc = -1;
            }
            break;
        }
        case OPT_EXPOSURE:
            o->have_exposure = 1;
            rc = cli_double("gtrace", "--exposure", optarg, -30.0, 30.0, &o->exposure);
            break;
        case OPT_CUTOFF:
            o->have_cutoff = 1;
            rc = cli_double("gtrace", "--cutoff", optarg, 0.0, 1.0, &o->cutoff);
            break;
        case OPT_WAVES:
            o->waves = 1;
            break;
        case OPT_DISPLAY:
        case OPT_VIEW:
        case OPT_OCIO_CONFIG:
            o->have_display = 1;
            *(c == OPT_DISPLAY ? &o->display.display : c == OPT_VIEW ? &o->display.view : &o->display.config) = optarg;
            break;
        case OPT_CROP:
            o->have_crop = 1;
            rc = parse_crop(optarg, o->crop);
            break;
        case OPT_MPI_BLOCK:
            rc = cli_int("gtrace", "--mpi-block", optarg, 1, 4096, &o->dist.block);
            break;
        case OPT_MPI_TIMEOUT:
            rc = cli_double("gtrace", "--mpi-timeout", optarg, 0.1, 1e6, &o->dist.timeout);
            break;
        case OPT_MPI_DEDICATED:
            o->dist.dedicated = 1;
            break;
        case '?':
            return -1;
        default:
            rc = parse_probe_option(c, optarg, &o->probe);
            break;
        }
    }
    if (rc)
        return -1;
    int n;
    char **rest = cli_operands(&p, &n);
    if (n > 1) {
        fprintf(stderr, "gtrace: more than one scene file given ('%s' and '%s')\n", rest[0], rest[1]);
        return -1;
    }
    o->scene = n ? rest[0] : NULL;
    if (!o->scene || !o->out) {
        fprintf(stderr, "gtrace: %s\n", !o->scene ? "no scene file given" : "no output file given (-o OUT)");
        usage(stderr);
        return -1;
    }
    if (o->have_display && output_is_float(o->out)) {
        fprintf(stderr, "gtrace: --display, --view and --ocio-config are for 8-bit formats (.png, .jpg, ...); '%s' "
                "stores linear floats\n", o->out);
        return -1;
    }
    if (o->waves && !output_is_exr(o->out)) {
        fprintf(stderr, "gtrace: --spectral writes an OpenEXR file: -o must end in .exr, not '%s'\n", o->out);
        return -1;
    }
    return 0;
}

/* Loads the scene (checking first, when asked, that the output can be written) and works out the render settings
 * and exposure from the options and the camera. G_OK, or an error in err; *usage is set when the command line is
 * at fault (exit status 2). */
/* What decides a crop's pixels, recorded in the piece for `gtrace merge` to compare (film/merge.c): the scene
 * file's content (FNV-1a 64 of its bytes; the files it includes are not hashed), the colour model, the full size and
 * the render settings, the light-probe options and the viewing illuminant; fields "NAME VALUE" separated by "; ".
 * Returns buf. */
static const char *piece_note(const Options *o, const Scene *scene, const RenderSettings *rs, char *buf, size_t size)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    char *text = NULL;
    size_t len = 0;
    GError err;
    if (gfile_read_all(o->scene, (size_t)1 << 30, &text, &len, &err) == G_OK)
        for (size_t i = 0; i < len; i++)
            h = (h ^ (unsigned char)text[i]) * 0x100000001b3ULL;
    gmem_free(text);
    const ProbeOverride *p = &o->probe;
    snprintf(buf, size, "scene %016llx; colormodel %s; size %dx%d; spp %d; depth %d; max-rays %d; bands %d; "
             "integrator %d; cutoff %.17g; waves %d; probe %.100s %.40s %d %d %.17g %d; sampler %d; equiangular %d; "
             "illuminant %.40s",
             (unsigned long long)h,
             gcolormodel_name(scene->model), rs->width, rs->height, rs->spp, rs->depth, rs->max_rays, rs->bands,
             rs->integrator, rs->cutoff, rs->waves, p->file ? p->file : "-", p->technique ? p->technique : "-",
             p->count, p->samples, p->scale, p->shadows, rs->sampler, !rs->no_equiangular,
             o->illuminant ? o->illuminant : "none");
    return buf;
}

static int prepare(const Options *o, const GReaderOptions *trust, int check_output, Scene **scene, RenderSettings *rs,
                   double *exposure, int *usage, GError *err)
{
    *usage = 0;
    *scene = NULL;
    int rc = check_output ? output_check(o->out, err) : G_OK; /* before the scene is read and rendered */
    if (rc == G_OK && check_output && o->have_display &&
        (rc = gimage_display_check(&o->display, NULL, 0, err)) == G_ERR_NOTFOUND)
        *usage = 1; /* an unknown display or view: the message lists the config's names */
    if (rc == G_OK)
        rc = scene_load_opts(o->scene, o->colormodel, &o->probe, trust, scene, err);
    if (rc < 0)
        return rc;
    if (!o->quiet)
        probe_describe(*scene, stdout);
    const Camera *cam = &(*scene)->camera;
    *rs = (RenderSettings){.width = cam->width, .height = cam->height, .spp = cam->spp, .depth = cam->depth,
                           .threads = o->threads, .quiet = o->quiet, .cutoff = o->have_cutoff ? o->cutoff : cam->cutoff,
                           .max_rays = o->max_rays, .bands = o->bands > 0 ? o->bands : cam->bands,
                           .integrator = o->integrator, .waves = o->waves, .sppm_passes = o->passes,
                           .sppm_photons = o->photons, .sppm_radius = o->radius, .sppm_alpha = o->alpha,
                           .sampler = o->sampler, .no_equiangular = o->no_equiangular};
    if (o->width > 0 && o->height > 0) {
        rs->width = o->width;
        rs->height = o->height;
    } else if (o->width > 0) {
        rs->width = o->width;
        rs->height = (int)((double)o->width * cam->height / cam->width + 0.5);
    } else if (o->height > 0) {
        rs->height = o->height;
        rs->width = (int)((double)o->height * cam->width / cam->height + 0.5);
    }
    if (rs->width < 1)
        rs->width = 1;
    if (rs->height < 1)
        rs->height = 1;
    Camera *framed = &(*scene)->camera; /* a view fitted to the scene, fitted again to another image size */
    if (framed->frame >= 0.0 && (rs->width != framed->width || rs->height != framed->height) &&
        (rc = camera_frame(framed, framed->frame_lo, framed->frame_hi, rs->width, rs->height, err)) < 0)
        return rc;
    if (o->spp > 0)
        rs->spp = o->spp;
    if (o->depth >= 0)
        rs->depth = o->depth;
    if (o->have_crop) {
        if (o->crop[2] > rs->width || o->crop[3] > rs->height) {
            *usage = 1;
            return gerror_set(err, G_ERR_INVALID, "--crop %d,%d,%d,%d reaches outside the %dx%d image", o->crop[0],
                              o->crop[1], o->crop[2], o->crop[3], rs->width, rs->height);
        }
        memcpy(rs->crop, o->crop, sizeof rs->crop);
    }
    *exposure = o->have_exposure ? o->exposure : cam->exposure;
    if (o->illuminant) {
        if ((rc = viewing_adaptation((*scene)->model, o->illuminant, rs->adaptation, err)) < 0)
            return rc;
        rs->adapt = 1;
    }
    (*scene)->accel_threads = o->threads;
    return accel_build_for(*scene, (double)rs->width * rs->height * rs->spp, err);
}

/* The warnings and the summary line of a finished render (ranks: the MPI job's size, 0 without MPI). */
static void report(const Options *o, const Scene *scene, const RenderSettings *rs, const Framebuffer *fb,
                   const RenderStats *st, int ranks)
{
    if (st->capped)
        fprintf(stderr,
                "gtrace: warning: %llu camera samples reached the limit of %d reflected and refracted "
                "rays per sample; their deeper branches were not traced (raise --cutoff, lower --depth, or "
                "raise --max-rays)\n",
                (unsigned long long)st->capped, rs->max_rays > 0 ? rs->max_rays : RENDER_DEFAULT_MAX_RAYS);
    if (st->nonfinite)
        fprintf(stderr, "gtrace: warning: %llu samples were NaN or infinite and were replaced by black\n",
                (unsigned long long)st->nonfinite);
    if (o->quiet)
        return;
    char ranks_text[32] = "";
    if (ranks > 0)
        snprintf(ranks_text, sizeof ranks_text, " x %d ranks", ranks);
    printf("gtrace: %s %dx%d, %d spp, depth %d, %s, %d threads%s: %.4f s, %.2f M rays, %.2f M rays/s, "
           "%llu non-finite\n",
           o->out, fb->width, fb->height, rs->spp, rs->depth, gcolormodel_name(scene->model), st->threads, ranks_text,
           st->seconds, st->rays * 1e-6, st->seconds > 0 ? st->rays * 1e-6 / st->seconds : 0.0,
           (unsigned long long)st->nonfinite);
}

static int gtrace_main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return merge_cli_main(argc - 1, argv + 1);
    int limit = startup_memory_limit("gtrace", &argc, argv);
    if (limit >= 0)
        return limit;
    GError reg_err;
    if (generic_register_builtins(&reg_err) != G_OK || gtrace_register_kinds(&reg_err) != G_OK) {
        fprintf(stderr, "%s\n", reg_err.message);
        return 1;
    }
    if (gplugin_load_args(&argc, argv, &reg_err) != G_OK) {
        fprintf(stderr, "gtrace: %s\n", reg_err.message);
        return reg_err.code == G_ERR_INVALID ? 2 : 1;
    }
    GReaderOptions trust = {0};
    if (greader_options_args(&argc, argv, &trust, &reg_err) != G_OK) {
        fprintf(stderr, "gtrace: %s\n", reg_err.message);
        return 2;
    }
    if (argc > 1 && strcmp(argv[1], "types") == 0)
        return type_list_main(argc - 1, argv + 1);
    Options o;
    int a = parse_args(argc, argv, &o);
    if (a != 0)
        return a > 0 ? 0 : 2;
    o.display.confine_dir = trust.confine_dir; /* the LUTs an OpenColorIO config names stay under --confine too */
    GError err;
    gerror_clear(&err);
    char note[GIMAGE_NOTE_MAX];
    Dist *dist = NULL; /* under mpirun: this process is one rank of the job */
    if (mpi_launched() && dist_start(&dist, &err) != G_OK) {
        fprintf(stderr, "gtrace: %s\n", err.message);
        return 1;
    }
    int rank = dist ? dist_rank(dist) : 0;
    if (rank != 0)
        o.quiet = 1; /* rank 0 speaks for the job */
    Scene *scene = NULL;
    RenderSettings rs = {0};
    double exposure = 0.0;
    int usage = 0;
    int rc = prepare(&o, &trust, rank == 0, &scene, &rs, &exposure, &usage, &err);
    Framebuffer fb = {0};
    RenderStats st = {0};
    if (dist) {
        uint64_t digest = rc == G_OK ? dist_digest(o.scene, o.colormodel, &rs) : 0;
        rc = dist_render(dist, &o.dist, rc, err.message, digest, scene, &rs, &fb, &st, &err);
        usage = 0;
    } else if (rc == G_OK) {
        rc = render_image(scene, &rs, &fb, &st, &err);
    }
    /* the note goes only into a crop (output_write_piece): a whole image does not re-read the scene file for it */
    int crop = fb.full_width > 0 && (fb.width != fb.full_width || fb.height != fb.full_height);
    if (rc == G_OK)
        rc = output_write_piece(o.out, &fb, exposure, o.have_display ? &o.display : NULL,
                                crop ? piece_note(&o, scene, &rs, note, sizeof note) : NULL, &err);
    if (rc == G_OK)
        report(&o, scene, &rs, &fb, &st, dist ? dist_size(dist) : 0);
    else if (rc < 0)
        fprintf(stderr, "gtrace: %s\n", err.message);
    framebuffer_free(&fb);
    scene_destroy(scene);
    dist_finish(dist);
    return rc == G_OK || rc == DIST_SENT ? 0 : usage ? 2 : 1;
}

/* The run holds the standard descriptors, and every status leaves through cli_finish_stdout: a failed write to
 * standard output makes the run fail (cli_run). */
int main(int argc, char **argv) { return cli_run("gtrace", gtrace_main, argc, argv); }
