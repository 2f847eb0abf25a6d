/* swatch.c - `gmat swatch`: a picture of a material or texture tree, so a pattern can be seen without a scene.
 *
 *   gmat swatch FILE MATERIAL -o SWATCH.png [--size N] [--sphere] [--samples N] [--colormodel NAME [--step NM]]
 *               [--plugin FILE.so]... (modules are loaded by main.c before the subcommand runs)
 *
 * The flat swatch is the unit square of (u, v) (u to the right, v up; the object-space point is (u, v, 0)),
 * seen from straight above; --sphere shows a unit sphere instead, u around it (longitude) and v from the south
 * to the north pole, object point = surface point. Both are lit by one white directional light from the upper
 * left (irradiance pi * 0.85, so a white Lambertian surface facing it shows 0.85), an ambient white of 0.15,
 * and, where the material has an ideal reflection ray, a sky that is bright above the horizon and dark below
 * it. Emission is added as it is. Each pixel averages samples x samples stratified points whose footprints are
 * the sample spacing, so textures filter themselves over the footprint and shapes get smooth edges. */
#include "gmat.h"
#include "../common/cli.h"

#include <generic/services/image.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Swatch {
    GLibrary *lib;
    const GColorModel *model;
    const GMaterial *m;
    GScratch *scratch;
    GColor key, amb, sky, c, sum;
    GVec3 light;
} Swatch;

static void swatch_usage(FILE *f)
{
    fprintf(f, "usage: gmat swatch FILE MATERIAL -o SWATCH.png [--size N] [--sphere] [--samples N]\n"
               "                   [--colormodel NAME [--step NM]]\n\n"
               "Renders MATERIAL (a material or texture tree defined in FILE) on the unit square of (u, v), or with\n"
               "--sphere on a unit sphere, lit by a white light from the upper left, a little ambient light and a\n"
               "sky for ideal reflections.\n"
               "  -o SWATCH.png       output image (8-bit sRGB for .png/.jpg, linear for .exr/.hdr)\n"
               "  --size N            width and height in pixels (16..4096, default 256)\n"
               "  --samples N         N x N samples per pixel (1..8, default 2)\n"
               "  --colormodel NAME   compute in this model instead of the file's (or one a module registers);\n"
               "                      --step NM its spacing\n"
               "  --plugin FILE.so    load a module first (repeatable)\n"
            "  --allow-plugins     let `plugin` statements of FILE load modules; --confine DIR: files under DIR only\n"
            "  -h, --help          this text\n"
            "  --version           the version\n"
            CLI_EXIT_STATUS_HELP);
}

/* Light reaching the point's viewer (+z) from the swatch's lights, added into s->sum. */
static int shade(Swatch *s, GSurfPoint *sp)
{
    GVec3 out = gvec3(0, 0, 1);
    GScratchMark mark = gscratch_mark(s->scratch);
    int rc = gmaterial_emission(s->m, sp, out, &s->c);
    if (rc == G_OK)
        rc = gcolor_add(&s->sum, &s->sum, &s->c);
    if (rc == G_OK && gvec3_dot(s->light, sp->geometric_normal) > 0.0) {
        rc = gmaterial_reflection(s->m, sp, s->light, &s->key, out, &s->c);
        if (rc == G_OK)
            rc = gcolor_add(&s->sum, &s->sum, &s->c);
    }
    if (rc == G_OK)
        rc = gmaterial_ambient(s->m, sp, &s->amb, &s->c);
    if (rc == G_OK)
        rc = gcolor_add(&s->sum, &s->sum, &s->c);
    GVec3 dir;
    if (rc == G_OK && gmaterial_reflection_dir(s->m, sp, gvec3(0, 0, -1), &dir) == 1) {
        /* the sky: 1 straight up, falling to 0.25 at the horizon, 0.05 below it */
        double level = dir.z > 0.0 ? 0.25 + 0.75 * dir.z : 0.05;
        double rgb[3] = {level, level, level * 1.1};
        rc = gcolor_from_rgb(&s->sky, rgb, GCOLOR_LIGHT);
        if (rc == G_OK)
            rc = gmaterial_reflection(s->m, sp, dir, &s->sky, out, &s->c);
        if (rc == G_OK)
            rc = gcolor_add(&s->sum, &s->sum, &s->c);
    }
    gscratch_release(s->scratch, mark);
    return rc;
}

/* Sets up the surface point of the sample at (x, y) in [-1, 1]^2 of the view; 0 when it misses the sphere. */
static int sample_point(Swatch *s, GSurfPoint *sp, double x, double y, double foot, int sphere)
{
    gsurfpoint_init(sp, s->model, s->scratch);
    sp->material = s->m;
    if (!sphere) {
        sp->u = 0.5 * (x + 1.0);
        sp->v = 0.5 * (y + 1.0);
        sp->point = sp->object_point = gvec3(sp->u, sp->v, 0.0);
        sp->geometric_normal = gvec3(0, 0, 1);
        sp->dpdu = gvec3(1, 0, 0);
        sp->dpdv = gvec3(0, 1, 0);
        sp->uv_footprint = 0.5 * foot;
        sp->footprint = 0.5 * foot;
        return 1;
    }
    double r2 = x * x + y * y;
    if (r2 >= 1.0)
        return 0;
    GVec3 p = gvec3(x, y, sqrt(1.0 - r2));
    double phi = atan2(p.x, p.z), theta = acos(fmax(-1.0, fmin(1.0, p.y)));
    sp->u = phi / (2.0 * M_PI) + 0.5;
    sp->v = 1.0 - theta / M_PI;
    sp->point = sp->object_point = p;
    sp->geometric_normal = p;
    /* p = (sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)), phi = 2 pi (u - 1/2), theta = pi (1 - v) */
    double st = sin(theta);
    sp->dpdu = gvec3(2.0 * M_PI * st * cos(phi), 0.0, -2.0 * M_PI * st * sin(phi));
    sp->dpdv = gvec3(-M_PI * cos(theta) * sin(phi), M_PI * st, -M_PI * cos(theta) * cos(phi));
    sp->footprint = foot / fmax(p.z, 0.05);
    sp->uv_footprint = sp->footprint / (M_PI * fmax(st, 0.05));
    return 1;
}

static int render(Swatch *s, int size, int samples, int sphere, GImage *img)
{
    const float background[3] = {0.18f, 0.18f, 0.2f};
    for (int py = 0; py < size; py++)
        for (int px = 0; px < size; px++) {
            gcolor_black(&s->sum);
            int hits = 0;
            for (int j = 0; j < samples; j++)
                for (int i = 0; i < samples; i++) {
                    double x = ((px + (i + 0.5) / samples) / size) * 2.0 - 1.0;
                    double y = 1.0 - ((py + (j + 0.5) / samples) / size) * 2.0;
                    GSurfPoint sp;
                    if (!sample_point(s, &sp, x, y, 2.0 / (size * samples), sphere))
                        continue;
                    int rc = shade(s, &sp);
                    if (rc != G_OK)
                        return rc;
                    hits++;
                }
            float *out = img->pixels + ((size_t)py * size + px) * 3;
            double rgb[3] = {0, 0, 0};
            if (hits > 0) {
                int rc = gcolor_scale(&s->sum, &s->sum, 1.0 / (samples * samples));
                if (rc == G_OK)
                    rc = gcolor_to_rgb(&s->sum, GCOLOR_LIGHT, rgb);
                if (rc != G_OK)
                    return rc;
            }
            double cover = (double)hits / (samples * samples);
            for (int k = 0; k < 3; k++)
                out[k] = (float)(fmax(0.0, rgb[k]) + (1.0 - cover) * background[k]);
        }
    return G_OK;
}

/* The command line of swatch. */
typedef struct SwatchArgs {
    const char *file, *name, *output, *colormodel;
    double size, samples, step;
    int sphere;
} SwatchArgs;

enum { OPT_SPHERE = CLI_FIRST_OWN, OPT_COLORMODEL, OPT_SIZE, OPT_SAMPLES, OPT_STEP };

/* Handles one of swatch's own options: 0, or the usage error's status (message printed). */
static int swatch_option(SwatchArgs *a, int c, const char *v)
{
    double n;
    switch (c) {
    case OPT_SPHERE:
        a->sphere = 1;
        return 0;
    case 'o':
        a->output = v;
        return 0;
    case OPT_COLORMODEL:
        a->colormodel = v;
        return 0;
    case OPT_SIZE:
        if (gmat_number(v, 16, 4096, &n) || n != floor(n))
            return gmat_usage_error("swatch", "--size: '%s' is not a whole number in 16..4096", v);
        a->size = n;
        return 0;
    case OPT_SAMPLES:
        if (gmat_number(v, 1, 8, &n) || n != floor(n))
            return gmat_usage_error("swatch", "--samples: '%s' is not a whole number in 1..8", v);
        a->samples = n;
        return 0;
    case OPT_STEP:
        if (gmat_number(v, 0.1, 400, &a->step))
            return gmat_usage_error("swatch", "--step: '%s' is not a spacing in nm (0.1..400)", v);
        return 0;
    default:
        return CLI_USAGE;
    }
}

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int swatch_args(int argc, char **argv, SwatchArgs *a)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS,
        {"sphere", no_argument, NULL, OPT_SPHERE},
        {"output", required_argument, NULL, 'o'},
        {"colormodel", required_argument, NULL, OPT_COLORMODEL},
        {"size", required_argument, NULL, OPT_SIZE},
        {"samples", required_argument, NULL, OPT_SAMPLES},
        {"step", required_argument, NULL, OPT_STEP},
        {NULL, 0, NULL, 0},
    };
    *a = (SwatchArgs){.size = 256, .samples = 2};
    CliParser p;
    cli_begin(&p, "gmat swatch", argc - 1, argv + 1, "ho:", longopts);
    int c, rc, status = CLI_OK;
    while ((c = cli_next_own(&p, "gmat", swatch_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if ((rc = swatch_option(a, c, optarg)) != 0)
            return rc;
    }
    if ((rc = gmat_operands("swatch", &p, 2, &a->file, &a->name)) != 0)
        return rc;
    if (!a->file || !a->name)
        return gmat_usage_error("swatch", "%s", "needs FILE and MATERIAL");
    if (!a->output)
        return gmat_usage_error("swatch", "%s", "-o SWATCH.png is required");
    return -1;
}

/* The lights and work colours of s in its model, and the picture: 0, or -1 when out of memory. */
static int swatch_setup(Swatch *s, int size, GImage *img)
{
    double key[3] = {M_PI * 0.85, M_PI * 0.85, M_PI * 0.85}, amb[3] = {0.15, 0.15, 0.15};
    GError err;
    s->scratch = gscratch_create(0);
    if (!s->scratch || gcolor_alloc(&s->key, s->model) || gcolor_alloc(&s->amb, s->model) ||
        gcolor_alloc(&s->sky, s->model) || gcolor_alloc(&s->c, s->model) || gcolor_alloc(&s->sum, s->model) ||
        gcolor_from_rgb(&s->key, key, GCOLOR_LIGHT) || gcolor_from_rgb(&s->amb, amb, GCOLOR_LIGHT) ||
        gimage_create(img, size, size, 3, &err))
        return -1;
    s->light = gvec3_normalize(gvec3(-0.5, 0.6, 1.0));
    return 0;
}

/* Renders the material of s into a.output: the exit status. */
static int swatch_draw(const SwatchArgs *a, Swatch *s)
{
    GImage img = {0};
    GError err;
    int rc = 1;
    if (swatch_setup(s, (int)a->size, &img) != 0)
        fprintf(stderr, "gmat swatch: out of memory\n");
    else if (render(s, (int)a->size, (int)a->samples, a->sphere, &img) != G_OK)
        fprintf(stderr, "gmat swatch: evaluating '%s' failed\n", a->name);
    else if (gimage_write(a->output, &img, NULL, &err) != G_OK)
        fprintf(stderr, "gmat swatch: %s\n", err.message);
    else
        rc = 0;
    gimage_free(&img);
    return rc;
}

int gmat_swatch(int argc, char **argv, const GReaderOptions *base)
{
    SwatchArgs a;
    int rc = swatch_args(argc, argv, &a);
    if (rc >= 0)
        return rc;
    Swatch s = {0};
    GError err;
    if (gimage_check_output(a.output, &err) != G_OK) { /* before any work */
        fprintf(stderr, "gmat swatch: %s\n", err.message);
        return 1;
    }
    if (gmat_read(a.file, base, a.colormodel, a.step, 0, &s.lib, &err) != G_OK) {
        fprintf(stderr, "gmat swatch: %s\n", err.message);
        return 1;
    }
    s.model = glibrary_colormodel(s.lib);
    s.m = glibrary_material(s.lib, a.name);
    rc = 1;
    if (!s.m)
        fprintf(stderr, "gmat swatch: %s defines no material or texture node named '%s' (see gmat list)\n", a.file,
                a.name);
    else
        rc = swatch_draw(&a, &s);
    gcolor_free(&s.key);
    gcolor_free(&s.amb);
    gcolor_free(&s.sky);
    gcolor_free(&s.c);
    gcolor_free(&s.sum);
    gscratch_destroy(s.scratch);
    glibrary_destroy(s.lib);
    return rc;
}
