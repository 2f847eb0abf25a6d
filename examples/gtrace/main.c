/* gtrace - a Whitted ray tracer written only against the generic colour and material interfaces.
 * main.c: the command line, loading, rendering, writing, and the summary line. */
#include "parse.h"
#include "accel.h"
#include "bands.h"
#include "render.h"
#include "output.h"
#include "probe_env.h"

#include <generic/builtins.h>
#include <generic/plugin.h>
#include <generic/registry.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *f)
{
    char models[256];
    gregistry_names(GKIND_COLORMODEL, models, sizeof models);
    fprintf(f,
            "usage: gtrace SCENE -o OUT [--width W] [--height H] [--spp N] [--depth D] [--max-rays N]\n"
            "              [--colormodel M] [--threads N] [--cutoff W] [--bands K] [--exposure STOPS] [--plugin FILE.so]... [-q]\n"
            "              [--allow-plugins] [--confine DIR]\n"
            "              [--probe FILE] [--probe-technique T] [--probe-count N] [--probe-samples N]\n"
            "              [--probe-scale S] [--probe-shadows on|off] [--integrator whitted|path]\n"
            "Renders a scene file (the library's text format with camera, object and light entries) with a\n"
            "Whitted ray tracer that uses colours and materials only through the generic interfaces.\n"
            "Every scene coordinate (after transforms) must be finite and within +-1e15.\n"
            "  -o OUT            output image; the extension picks the format: .exr linear float,\n"
            "                    .png/.jpg display-encoded (sRGB) after the exposure, clamped\n"
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
            "                    searched in the current directory, then GENERIC_PLUGIN_PATH)\n"
            "  --allow-plugins   let `plugin` statements of the scene load modules (a module runs native\n"
            "                    code: refused without this or GENERIC_ALLOW_PLUGINS=1)\n"
            "  --confine DIR     every file the scene reads (itself, includes, modules, meshes, images,\n"
            "                    BFC files, probes) must lie under DIR once symbolic links are resolved\n"
            "  --cutoff W        do not trace rays whose weight in the pixel is below W (default: the\n"
            "                    camera's, 1e-3; 0 traces every ray to the depth limit)\n"
            "  --bands K         most wavelength groups a dispersive refraction splits into, 1..1024\n"
            "                    (default: the camera's, 16; the model's bands are grouped evenly; 1: no\n"
            "                    dispersion)\n"
            "  --threads N       render threads (default: all processors)\n"
            "  --integrator I    whitted (default: the paper's Fig. 4) or path (path tracing: next-event\n"
            "                    estimation and material sampling by MIS, Russian roulette; --spp paths\n"
            "                    per pixel, --depth bounces)\n"
            "  --exposure STOPS  exposure for .png/.jpg output (default: the camera's)\n"
            "  --probe FILE      replace the image of the scene's `light probe` (relative to the current\n"
            "                    directory); the other --probe options replace its other settings\n"
            "  --probe-technique T    mediancut, adaptive, kmeans, irradiance (directional lights) or\n"
            "                         reference (Monte Carlo over the whole probe)\n"
            "  --probe-count N        number of lights of a technique (1..4096; irradiance: at most 128,\n"
            "                         and count x fit_normals at most 524288)\n"
            "  --probe-samples N      reference: samples per shading point (1..65536)\n"
            "  --probe-shadows on|off reference: shadow rays (off: the unoccluded image)\n"
            "  --probe-scale S        multiplies the probe's radiance\n"
            "  -q                no progress bar and no summary line\n"
            "  -h, --help        this text\n",
            models);
}

static int parse_int(const char *opt, const char *s, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi) {
        fprintf(stderr, "gtrace: %s expects a whole number in [%ld, %ld], got '%s'\n", opt, lo, hi, s);
        return -1;
    }
    *out = (int)v;
    return 0;
}

/* The --probe options (a, its value v); -1 with a message for a bad one. */
static int parse_probe_option(const char *a, const char *v, ProbeOverride *p)
{
    if (strcmp(a, "--probe") == 0)
        p->file = v;
    else if (strcmp(a, "--probe-technique") == 0)
        p->technique = v;
    else if (strcmp(a, "--probe-count") == 0)
        return parse_int(a, v, 1, 4096, &p->count);
    else if (strcmp(a, "--probe-samples") == 0)
        return parse_int(a, v, 1, 65536, &p->samples);
    else if (strcmp(a, "--probe-shadows") == 0 && (strcmp(v, "on") == 0 || strcmp(v, "off") == 0))
        p->shadows = strcmp(v, "on") == 0;
    else if (strcmp(a, "--probe-scale") == 0) {
        char *end;
        p->scale = strtod(v, &end);
        if (end == v || *end || !(p->scale > 0.0 && p->scale < 1e30)) {
            fprintf(stderr, "gtrace: --probe-scale expects a positive number, got '%s'\n", v);
            return -1;
        }
    } else {
        fprintf(stderr, "gtrace: unknown option '%s' or bad value '%s' (see gtrace --help)\n", a, v);
        return -1;
    }
    return 0;
}

typedef struct Options {
    ProbeOverride probe;
    const char *scene, *out, *colormodel;
    int width, height, spp, depth, threads, quiet, max_rays, bands, integrator;
    int have_exposure, have_cutoff;
    double exposure, cutoff;
} Options;

static int parse_args(int argc, char **argv, Options *o)
{
    memset(o, 0, sizeof *o);
    o->width = o->height = o->spp = o->depth = -1;
    o->probe.shadows = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            return 1;
        }
        if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
            continue;
        }
        if (a[0] == '-' && a[1]) {
            if (i + 1 >= argc) {
                fprintf(stderr, "gtrace: %s needs a value\n", a);
                return -1;
            }
            const char *v = argv[++i];
            int rc = 0;
            if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0)
                o->out = v;
            else if (strcmp(a, "--width") == 0)
                rc = parse_int(a, v, 1, 65536, &o->width);
            else if (strcmp(a, "--height") == 0)
                rc = parse_int(a, v, 1, 65536, &o->height);
            else if (strcmp(a, "--spp") == 0)
                rc = parse_int(a, v, 1, 65536, &o->spp);
            else if (strcmp(a, "--depth") == 0)
                rc = parse_int(a, v, 0, 1000, &o->depth);
            else if (strcmp(a, "--max-rays") == 0)
                rc = parse_int(a, v, 1, RENDER_LIMIT_MAX_RAYS, &o->max_rays);
            else if (strcmp(a, "--threads") == 0)
                rc = parse_int(a, v, 1, 1024, &o->threads);
            else if (strcmp(a, "--bands") == 0)
                rc = parse_int(a, v, 1, BANDS_LIMIT, &o->bands);
            else if (strcmp(a, "--integrator") == 0) {
                if (strcmp(v, "whitted") == 0 || strcmp(v, "path") == 0)
                    o->integrator = strcmp(v, "path") == 0 ? RENDER_PATH : RENDER_WHITTED;
                else {
                    fprintf(stderr, "gtrace: --integrator expects whitted or path, got '%s'\n", v);
                    rc = -1;
                }
            } else if (strcmp(a, "--colormodel") == 0)
                o->colormodel = v;
            else if (strncmp(a, "--probe", 7) == 0)
                rc = parse_probe_option(a, v, &o->probe);
            else if (strcmp(a, "--exposure") == 0) {
                char *end;
                o->exposure = strtod(v, &end);
                o->have_exposure = 1;
                if (end == v || *end || !(o->exposure >= -30.0 && o->exposure <= 30.0)) {
                    fprintf(stderr, "gtrace: --exposure expects a number in [-30, 30], got '%s'\n", v);
                    rc = -1;
                }
            } else if (strcmp(a, "--cutoff") == 0) {
                char *end;
                o->cutoff = strtod(v, &end);
                o->have_cutoff = 1;
                if (end == v || *end || !(o->cutoff >= 0.0 && o->cutoff <= 1.0)) {
                    fprintf(stderr, "gtrace: --cutoff expects a number in [0, 1], got '%s'\n", v);
                    rc = -1;
                }
            } else {
                fprintf(stderr, "gtrace: unknown option '%s' (see gtrace --help)\n", a);
                return -1;
            }
            if (rc)
                return -1;
            continue;
        }
        if (o->scene) {
            fprintf(stderr, "gtrace: more than one scene file given ('%s' and '%s')\n", o->scene, a);
            return -1;
        }
        o->scene = a;
    }
    if (!o->scene || !o->out) {
        fprintf(stderr, "gtrace: %s\n", !o->scene ? "no scene file given" : "no output file given (-o OUT)");
        usage(stderr);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    GError reg_err;
    if (generic_register_builtins(&reg_err) != G_OK) {
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
    Options o;
    int a = parse_args(argc, argv, &o);
    if (a != 0)
        return a > 0 ? 0 : 2;
    GError err;
    gerror_clear(&err);
    Scene *scene = NULL;
    if (output_check(o.out, &err) != G_OK) { /* before the scene is read and rendered */
        fprintf(stderr, "gtrace: %s\n", err.message);
        return 1;
    }
    if (scene_load_opts(o.scene, o.colormodel, &o.probe, &trust, &scene, &err) < 0) {
        fprintf(stderr, "gtrace: %s\n", err.message);
        return 1;
    }
    if (!o.quiet)
        probe_describe(scene, stdout);
    const Camera *cam = &scene->camera;
    RenderSettings rs = {.width = cam->width, .height = cam->height, .spp = cam->spp, .depth = cam->depth,
                         .threads = o.threads, .quiet = o.quiet, .cutoff = o.have_cutoff ? o.cutoff : cam->cutoff,
                         .max_rays = o.max_rays, .bands = o.bands > 0 ? o.bands : cam->bands,
                         .integrator = o.integrator};
    if (o.width > 0 && o.height > 0) {
        rs.width = o.width;
        rs.height = o.height;
    } else if (o.width > 0) {
        rs.width = o.width;
        rs.height = (int)((double)o.width * cam->height / cam->width + 0.5);
    } else if (o.height > 0) {
        rs.height = o.height;
        rs.width = (int)((double)o.height * cam->width / cam->height + 0.5);
    }
    if (rs.width < 1)
        rs.width = 1;
    if (rs.height < 1)
        rs.height = 1;
    if (o.spp > 0)
        rs.spp = o.spp;
    if (o.depth >= 0)
        rs.depth = o.depth;
    double exposure = o.have_exposure ? o.exposure : cam->exposure;

    Framebuffer fb = {0};
    RenderStats st;
    int rc = accel_build(scene, &err);
    if (rc == G_OK)
        rc = render_image(scene, &rs, &fb, &st, &err);
    if (rc == G_OK)
        rc = output_write(o.out, &fb, exposure, &err);
    if (rc != G_OK) {
        fprintf(stderr, "gtrace: %s\n", err.message);
        framebuffer_free(&fb);
        scene_destroy(scene);
        return 1;
    }
    if (st.capped)
        fprintf(stderr, "gtrace: warning: %llu camera samples reached the limit of %d reflected and refracted "
                "rays per sample; their deeper branches were not traced (raise --cutoff, lower --depth, or "
                "raise --max-rays)\n", (unsigned long long)st.capped, rs.max_rays > 0 ? rs.max_rays : RENDER_DEFAULT_MAX_RAYS);
    if (st.nonfinite)
        fprintf(stderr, "gtrace: warning: %llu samples were NaN or infinite and were replaced by black\n",
                (unsigned long long)st.nonfinite);
    if (!o.quiet)
        printf("gtrace: %s %dx%d, %d spp, depth %d, %s, %d threads: %.2f s, %.2f M rays, %.2f M rays/s, "
               "%llu non-finite\n",
               o.out, rs.width, rs.height, rs.spp, rs.depth, gcolormodel_name(scene->model), st.threads, st.seconds,
               st.rays * 1e-6, st.seconds > 0 ? st.rays * 1e-6 / st.seconds : 0.0,
               (unsigned long long)st.nonfinite);
    framebuffer_free(&fb);
    scene_destroy(scene);
    return 0;
}
