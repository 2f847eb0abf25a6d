/* gmat - a material inspector built only on libgeneric's public API.
 *
 *   gmat eval   FILE MATERIAL --in THETA[,PHI] --out THETA[,PHI] [--spectrum]
 *   gmat albedo FILE MATERIAL --in THETA [--samples N]
 *   gmat plot   FILE MATERIAL --in THETA -o PLOT.png [--size PIXELS] [--log-radius] [--data TABLE]
 *   gmat list   FILE
 *   gmat check  FILE MATERIAL [--samples N]
 *   gmat types  [colormodel|color|material|node|generator] [--markdown]
 *   gmat swatch FILE MATERIAL -o SWATCH.png ...   (swatch.c)
 *   gmat laser  FILE MATERIAL ...                 (laser.c)
 *   gmat glasses [--markdown]                     (glasses.c)
 * common options: --colormodel NAME [--step NM], --plugin MODULE.so (repeatable), --allow-plugins, --confine DIR,
 * --help, --version */
#include "gmat.h"
#include "../common/startup.h"
#include "../common/type_doc.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char convention[] =
    "Convention: the surface is the xy plane with its normal along +z, seen from outside. Angles are in\n"
    "degrees: THETA from the normal (0..90), PHI the azimuth from +x. The light is unit white light: rgb 1 1 1\n"
    "as a light, i.e. CIE D65 with luminance Y = 1, arriving from the --in direction with irradiance 1 on a\n"
    "plane perpendicular to it (so cos(THETA_in) on the surface). Printed colours are the reflected radiance\n"
    "towards --out, f_r * cos(THETA_in) for a non-specular direction; when --out is the ideal mirror direction\n"
    "of a material with a specular ray, the value is that ray's reflectance times the light (the radiance the\n"
    "ray carries). Colours are linear sRGB (Rec.709, D65) and CIE 1931 XYZ, read as light.\n";

static const char common[] = "Common options:\n"
                             "  --colormodel NAME   compute in this colour model instead of the file's\n"
                             "  --step NM           sample spacing for --colormodel (spectral models)\n"
                             "  --plugin FILE.so    load a module before reading (repeatable)\n"
                             "  --allow-plugins     let `plugin` statements of the files load modules (they run\n"
                             "                      native code; also GENERIC_ALLOW_PLUGINS=1)\n"
                             "  --confine DIR       every file read (includes, modules, BFC, images) must lie "
                             "under DIR\n"
                             "  --memory-limit SIZE memory for what the files size (images, colours, ...): MiB, or\n"
                             "                      with M, G, T (default 4096, or GENERIC_MEMORY_LIMIT_MB)\n"
                             "  -h, --help          this text\n"
                             "  --version           the version\n"
                             "Every option value may also be written --option=value.\n"
                             CLI_EXIT_STATUS_HELP;

static void usage_main(FILE *f)
{
    fprintf(f, "usage: gmat COMMAND FILE MATERIAL [options]\n"
               "       gmat --help | --version\n\n"
               "Commands:\n"
               "  eval    reflected colour for one pair of directions\n"
               "  albedo  directional-hemispherical reflectance (numeric integration)\n"
               "  plot    polar plot of the reflection in the plane of incidence (PNG)\n"
               "  list    the materials, texture nodes and generators a file (or a scene) defines\n"
               "  check   conformance checks: albedo, reciprocity, finite values, Snell's law, defaults,\n"
               "          the instance flags, sampling (chi-square, pdf, weights)\n"
               "  types   the registered types, or with --markdown the reference of their parameters\n"
               "  swatch  a picture of a material or texture tree (gmat swatch --help)\n"
               "  laser   the laser experiment of Wilkie et al. (gmat laser --help)\n"
               "  metals  the measured metals of `conductor { metal NAME }` (gmat metals --help)\n"
               "  glasses the named glasses a dielectric's index may be (gmat glasses --help)\n\n"
               "`gmat COMMAND --help` describes each command.\n\n%s\n%s",
            convention, common);
}

static void usage_eval(FILE *f)
{
    fprintf(f, "usage: gmat eval FILE MATERIAL --in THETA[,PHI] --out THETA[,PHI] [--spectrum] [options]\n\n"
               "Prints the light MATERIAL (a name defined in FILE) reflects towards --out.\n"
               "  --spectrum          also print the spectrum of the result\n\n%s\n%s",
            convention, common);
}

static void usage_albedo(FILE *f)
{
    fprintf(f, "usage: gmat albedo FILE MATERIAL --in THETA[,PHI] [--samples N] [options]\n\n"
               "Directional-hemispherical reflectance: the fraction of the light from --in reflected into\n"
               "the hemisphere, integrated numerically over N x 2N directions (midpoints in sin^2(theta)\n"
               "and phi, exact for Lambertian surfaces; default N = 256) plus the ideal specular ray.\n"
               "Printed as the luminance fraction and as the reflected colour.\n"
               "  --samples N         grid resolution (8..4096)\n\n%s\n%s",
            convention, common);
}

static void usage_plot(FILE *f)
{
    fprintf(f, "usage: gmat plot FILE MATERIAL --in THETA -o PLOT.png [--size PIXELS] [--log-radius] [--data TABLE]\n"
               "                 [options]\n\n"
               "Draws (with gnuplot) a polar plot of the light reflected in the plane of incidence: the lobe's\n"
               "radius is the reflected luminance for unit white light, the angle the outgoing direction from\n"
               "the normal (negative towards the light, which comes from the left: dashed line); the lobe is\n"
               "filled with the reflected colour of its brightest direction; an ideal specular ray is a line\n"
               "labelled with its reflectance. Both axes are labelled.\n"
               "  -o FILE             output image (any format OpenImageIO writes; PNG is 8-bit sRGB)\n"
               "  --size PIXELS       width (64..8192, default 512; height is 3/4 of it)\n"
               "  --log-radius        logarithmic radius over %d decades below the maximum (a diffuse lobe\n"
               "                      beside a specular one)\n"
               "  --data TABLE        also write the plotted values: angle, luminance, colour per line\n"
               "Needs gnuplot (Debian: gnuplot-nox).\n\n%s\n%s",
            GMAT_PLOT_DECADES, convention, common);
}

static void usage_check(FILE *f)
{
    fprintf(f, "usage: gmat check FILE MATERIAL [--samples N] [options]\n\n"
               "Measures the properties every material and texture tree must have and prints one line each:\n"
               "the worst figure, the tolerance, PASS or FAIL; the exit status is 1 when one fails.\n"
               "  albedo       reflected plus transmitted light <= incident (+0.01 for the quadrature) at\n"
               "               incidences 0..85 degrees, per sample of the colour model\n"
               "  reciprocity  f_r(in, out) = f_r(out, in) over random pairs (relative 1e-3)\n"
               "  finite       no failure, NaN, infinite or negative value from any colour method\n"
               "  snell        refraction_dir follows Snell's law both ways, total internal reflection\n"
               "               past the critical angle (materials that are not opaque)\n"
               "  defaults     methods the class leaves out behave as material.h documents\n"
               "  no-emission  a material flagged GMAT_NO_EMISSION gets black from its class's emission\n"
               "  opaque-flag  a material flagged GMAT_OPAQUE gets 1 from its class's opaque slot\n"
               "  geometric-normal  a material flagged GMAT_GEOMETRIC_NORMAL gets the geometric normal\n"
               "               from its class's normal slot\n"
               "  lambertian   a material flagged GMAT_LAMBERTIAN reflects diffuse * light * cos / pi\n"
               "               by its class's reflection slot (random pairs and lights, relative 1e-5)\n"
               "  diagonal     a material flagged GMAT_DIAGONAL passes on of any light, by its class's\n"
               "               reflection and refraction slots, what it passes on of white times the light\n"
               "               (random and ideal pairs, random lights, relative 1e-5)\n"
               "  no-uv        a material flagged GMAT_NO_UV gives the same values with and without\n"
               "               the surface's (u, v) and tangents\n"
               "  no-ideal     a material flagged GMAT_NO_IDEAL gets 0 (not valid) from its class's\n"
               "               reflection_dir and refraction_dir slots\n"
               "  no-rel-index a material flagged GMAT_NO_REL_INDEX gives the same results, bit for bit,\n"
               "               from its class's slots with the relative indices 1.5 and 1 / 1.5\n"
               "  constant-index a material flagged GMAT_CONSTANT_INDEX gives the same refraction\n"
               "               index, bit for bit, at every point drawn and for no point\n"
               "  clear        a material flagged GMAT_CLEAR gives back the light, bit for bit, from\n"
               "               its class's absorption for any length, light and point\n"
               "Each is measured at several surface points (u, v, point and surface index vary).\n"
               "  --samples N         albedo grid N x 2N (8..4096, default 64)\n\n%s",
            common);
}

static void usage_types(FILE *f)
{
    fprintf(f, "usage: gmat types [colormodel|color|material|node|generator] [--markdown] [options]\n\n"
               "Prints the registered types of a kind (default: material, node and generator), one `KIND NAME`\n"
               "per line, including those the modules given with --plugin add.\n"
               "  --markdown          the reference page instead: per kind (default: all five) and type, its\n"
               "                      summary and the table of its parameters (docs/reference/types.md)\n\n%s",
            common);
}

static void usage_list(FILE *f)
{
    fprintf(f, "usage: gmat list FILE [options]\n\n"
               "Lists the materials, texture nodes and generators FILE defines, with their\n"
               "types: `KIND NAME TYPE - summary` per line. FILE may be a gtrace scene: its object, light and\n"
               "camera entries are skipped.\n\n%s",
            common);
}

int gmat_usage_error(const char *cmd, const char *fmt, const char *arg)
{
    fprintf(stderr, "gmat%s%s: ", cmd ? " " : "", cmd ? cmd : "");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(see gmat %s%s--help)\n", cmd ? cmd : "", cmd ? " " : "");
    return 2;
}

int gmat_markdown_option(const char *prog, int argc, char **argv, void (*usage)(FILE *), CliParser *p, int *markdown)
{
    enum { OPT_MARKDOWN = CLI_FIRST_OWN };
    static const struct option longopts[] = {CLI_COMMON_OPTIONS, {"markdown", no_argument, NULL, OPT_MARKDOWN},
                                             {NULL, 0, NULL, 0}};
    cli_begin(p, prog, argc - 1, argv + 1, "h", longopts);
    int c, status = CLI_OK;
    *markdown = 0;
    while ((c = cli_next_own(p, "gmat", usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (c != OPT_MARKDOWN)
            return CLI_USAGE;
        *markdown = 1;
    }
    return -1;
}

int gmat_number(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v) || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

int gmat_operands(const char *cmd, const CliParser *p, int want, const char **file, const char **material)
{
    int n;
    char **rest = cli_operands(p, &n);
    if (n > want)
        return gmat_usage_error(cmd, "unexpected argument '%s'", rest[want]);
    *file = n > 0 ? rest[0] : NULL;
    *material = n > 1 ? rest[1] : NULL;
    return 0;
}

int gmat_read(const char *file, const GReaderOptions *base, const char *colormodel, double step, unsigned skip_kinds,
              GLibrary **lib, GError *err)
{
    GColorModelOptions mo = {.step_nm = step};
    GReaderOptions opt = *base;
    opt.colormodel = colormodel;
    opt.colormodel_options = &mo;
    opt.skip_kinds = skip_kinds;
    return greader_load_file(file, &opt, lib, err);
}

/* THETA or THETA,PHI in degrees. */
static int angles(const char *s, double tmax, double *theta, double *phi)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s", s);
    char *comma = strchr(buf, ',');
    *phi = 0.0;
    if (comma) {
        *comma = '\0';
        if (gmat_number(comma + 1, -360.0, 360.0, phi))
            return -1;
    }
    return gmat_number(buf, 0.0, tmax, theta);
}

/* The commands main.c reads itself, with their help. */
static const struct {
    const char *name;
    void (*usage)(FILE *f);
} commands[] = {{"eval", usage_eval}, {"albedo", usage_albedo}, {"plot", usage_plot}, {"list", usage_list},
                {"check", usage_check}};

typedef struct Args {
    const char *cmd, *file, *material, *colormodel, *output, *data;
    void (*usage)(FILE *f); /* the command's help */
    double step, in_t, in_p, out_t, out_p;
    int have_in, have_out, spectrum, samples, size, log_radius;
} Args;

enum { OPT_IN = CLI_FIRST_OWN, OPT_OUT, OPT_SPECTRUM, OPT_COLORMODEL, OPT_STEP, OPT_SAMPLES, OPT_SIZE, OPT_LOG_RADIUS,
       OPT_DATA };

/* Handles one option of eval, albedo, plot, list and check: 0, or the usage error's status 2 (message printed). */
static int gmat_option(Args *a, int c, const char *v)
{
    const char *cmd = a->cmd;
    double n;
    switch (c) {
    case OPT_SPECTRUM:
        a->spectrum = 1;
        return 0;
    case OPT_LOG_RADIUS:
        a->log_radius = 1;
        return 0;
    case OPT_IN:
        if (angles(v, 89.9, &a->in_t, &a->in_p))
            return gmat_usage_error(cmd, "--in: '%s' is not THETA[,PHI] with 0 <= THETA < 90 degrees", v);
        a->have_in = 1;
        return 0;
    case OPT_OUT:
        if (angles(v, 90.0, &a->out_t, &a->out_p))
            return gmat_usage_error(cmd, "--out: '%s' is not THETA[,PHI] with 0 <= THETA <= 90 degrees", v);
        a->have_out = 1;
        return 0;
    case OPT_COLORMODEL:
        a->colormodel = v;
        return 0;
    case OPT_STEP:
        if (gmat_number(v, 0.1, 400.0, &a->step))
            return gmat_usage_error(cmd, "--step: '%s' is not a spacing in nm (0.1..400)", v);
        return 0;
    case OPT_SAMPLES:
        if (gmat_number(v, 8, 4096, &n) || n != floor(n))
            return gmat_usage_error(cmd, "--samples: '%s' is not a whole number in 8..4096", v);
        a->samples = (int)n;
        return 0;
    case OPT_SIZE:
        if (gmat_number(v, 64, 8192, &n) || n != floor(n))
            return gmat_usage_error(cmd, "--size: '%s' is not a whole number in 64..8192", v);
        a->size = (int)n;
        return 0;
    case 'o':
        a->output = v;
        return 0;
    case OPT_DATA:
        a->data = v;
        return 0;
    default:
        return CLI_USAGE;
    }
}

/* What the command needs besides its options: FILE, MATERIAL (not for list), --in (eval, albedo, plot), --out
 * (eval), -o (plot). 0, or the usage error's status 2. */
static int required(const Args *a)
{
    const char *cmd = a->cmd;
    if (!a->file)
        return gmat_usage_error(cmd, "%s", "no FILE given");
    if (strcmp(cmd, "list") == 0)
        return 0;
    if (!a->material)
        return gmat_usage_error(cmd, "%s", "no MATERIAL given");
    if (strcmp(cmd, "check") == 0)
        return 0;
    if (!a->have_in)
        return gmat_usage_error(cmd, "%s", "--in THETA is required");
    if (strcmp(cmd, "eval") == 0 && !a->have_out)
        return gmat_usage_error(cmd, "%s", "--out THETA[,PHI] is required");
    if (strcmp(cmd, "plot") == 0 && !a->output)
        return gmat_usage_error(cmd, "%s", "-o PLOT.png is required");
    return 0;
}

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int parse_args(int argc, char **argv, Args *a)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS,
        {"in", required_argument, NULL, OPT_IN},
        {"out", required_argument, NULL, OPT_OUT},
        {"spectrum", no_argument, NULL, OPT_SPECTRUM},
        {"colormodel", required_argument, NULL, OPT_COLORMODEL},
        {"step", required_argument, NULL, OPT_STEP},
        {"samples", required_argument, NULL, OPT_SAMPLES},
        {"size", required_argument, NULL, OPT_SIZE},
        {"output", required_argument, NULL, 'o'},
        {"log-radius", no_argument, NULL, OPT_LOG_RADIUS},
        {"data", required_argument, NULL, OPT_DATA},
        {NULL, 0, NULL, 0},
    };
    char prog[32];
    snprintf(prog, sizeof prog, "gmat %s", a->cmd);
    CliParser p;
    cli_begin(&p, prog, argc - 1, argv + 1, "ho:", longopts);
    int c, rc, status = CLI_OK;
    while ((c = cli_next_own(&p, "gmat", a->usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if ((rc = gmat_option(a, c, optarg)) != 0)
            return rc;
    }
    if ((rc = gmat_operands(a->cmd, &p, strcmp(a->cmd, "list") == 0 ? 1 : 2, &a->file, &a->material)) != 0)
        return rc;
    return required(a) != 0 ? CLI_USAGE : -1;
}

static int list(GLibrary *lib)
{
    printf("colour model: %s\n", gcolormodel_name(glibrary_colormodel(lib)));
    for (int k = GKIND_MATERIAL; k <= GKIND_GENERATOR; k++)
        for (int i = 0; i < glibrary_count(lib, (GKind)k); i++) {
            const char *name;
            const GTypeInfo *t;
            glibrary_entry(lib, (GKind)k, i, &name, &t);
            const char *base = glibrary_entry_base(lib, (GKind)k, i);
            printf("%-10s %-24s %s%s%s%s%s\n", gkind_name((GKind)k), name ? name : "(anonymous)", t->name,
                   base ? " like " : "", base ? base : "", t->summary ? " - " : "", t->summary ? t->summary : "");
        }
    return 0;
}

/* The kinds of the library's text format, and what an entry of each is, for `gmat types --markdown`. */
static const GKind doc_kinds[] = {GKIND_COLORMODEL, GKIND_COLOR, GKIND_MATERIAL, GKIND_NODE, GKIND_GENERATOR};
static const char *const doc_intros[] = {
    "`colormodel TYPE [{ ... }]` chooses the colour model every colour of the file is converted into; it comes\n"
    "before the first material (default `rgb`). The reader reads the grid options for every model.\n",
    "`color [NAME] TYPE ...` names a colour literal. Wherever a parameter of type color is read, a literal of\n"
    "these types (or the name of a colour) stands; it is converted in the role of its use (reflectance or\n"
    "light).\n",
    "`material [NAME] TYPE [{ ... }]`. A colour parameter's range holds for each sample in the file's colour\n"
    "model, widened by the model's conversion error; a reflectance exceeds 1 in a band only as the fold of a\n"
    "re-radiation matrix whose energy stays at most 1 ([colour.md](colour.md#range-after-conversion),\n"
    "[format.md](format.md#reflectances-above-1)). A parameter of type texnumber is a number or a generator, one\n"
    "of type texcolor a colour, `image { ... }` or `mix { ... }`\n"
    "([textured parameters](format.md#textured-parameters)).\n",
    "`node [NAME] TYPE { ... }`: the nodes of texture trees. Nodes are materials: each stands wherever a\n"
    "material is expected, and the other way round.\n",
    "`generator [NAME] TYPE [{ ... }]`: a scalar (with its gradient) per surface point, for the parameters of\n"
    "type generator of the nodes and of type texnumber or texcolor of the materials. Every generator also takes\n"
    "`range LO HI` (default 0 1), which maps its value v to LO (1 - v) + HI v.\n",
};
#define NDOC_KINDS ((int)(sizeof doc_kinds / sizeof doc_kinds[0]))

/* The reference page of the library's types (docs/reference/types.md). */
static int types_markdown(const char *only)
{
    printf("# Types of the text format\n\n"
           "<!-- Generated by `gmat types --markdown` from the registered types; do not edit. -->\n\n"
           "Every entry of a file is `KIND [NAME] TYPE PARAMETERS` ([format.md](format.md)). These are the\n"
           "types libgeneric registers, by kind; gtrace's scene entries are in scene-types.md.\n\n%s\n",
           TYPE_DOC_COLUMNS);
    for (int k = 0; k < NDOC_KINDS; k++) {
        if (only && strcmp(only, gkind_name(doc_kinds[k])) != 0)
            continue;
        if (type_doc_kind(stdout, doc_kinds[k], doc_intros[k]) < 0) {
            fprintf(stderr, "gmat types: out of memory\n");
            return CLI_FAILED;
        }
    }
    return fflush(stdout) == 0 ? CLI_OK : CLI_FAILED;
}

/* `gmat types [KIND] [--markdown]`: the registry's own list, so a script can check every registered type; with
 * --markdown the reference page of every type's parameters. */
static int types(int argc, char **argv)
{
    const char *only = NULL;
    int markdown, n;
    CliParser p;
    int status = gmat_markdown_option("gmat types", argc, argv, usage_types, &p, &markdown);
    if (status >= 0)
        return status;
    char **rest = cli_operands(&p, &n);
    for (int i = 0; i < n; i++) {
        int known = 0;
        for (int k = 0; k < NDOC_KINDS; k++)
            known |= strcmp(rest[i], gkind_name(doc_kinds[k])) == 0;
        if (!known || only)
            return gmat_usage_error("types", "unexpected argument '%s' (expected colormodel, color, material, node "
                                    "or generator)", rest[i]);
        only = rest[i];
    }
    if (markdown)
        return types_markdown(only);
    for (int k = 0; k < NDOC_KINDS; k++) {
        GKind kind = doc_kinds[k];
        if (only ? strcmp(only, gkind_name(kind)) != 0 : kind == GKIND_COLORMODEL || kind == GKIND_COLOR)
            continue;
        const GTypeInfo *t[256];
        int n = gregistry_list(kind, t, 256);
        for (int i = 0; i < n && i < 256; i++)
            printf("%s %s\n", gkind_name(kind), t[i]->name);
    }
    return 0;
}

/* The kinds of a gtrace scene's entries, registered without types: gmat reads a scene's materials, and `gmat list`
 * reads past its objects, lights, camera, media and phase functions. */
static GKind scene_kinds[5];

static int register_scene_kinds(GError *err)
{
    static const GKindInfo kinds[5] = {{"object", NULL, 0}, {"light", NULL, 0}, {"camera", NULL, 0},
                                       {"phase", NULL, 0}, {"medium", NULL, 0}};
    int rc = G_OK;
    for (int i = 0; i < 5 && rc == G_OK; i++)
        rc = gregistry_add_kind(&kinds[i], &scene_kinds[i], err);
    return rc;
}

static int run(const Args *a, GmatContext *ctx)
{
    if (strcmp(a->cmd, "check") == 0)
        return gmat_check(ctx, a->samples);
    if (strcmp(a->cmd, "eval") == 0) {
        GVec3 in = gmat_direction(a->in_t, a->in_p), out = gmat_direction(a->out_t, a->out_p);
        int rc = gmat_reflect(ctx, in, out);
        if (rc != G_OK) {
            fprintf(stderr, "gmat eval: the material failed (%s)\n", gstatus_string(rc));
            return 1;
        }
        printf("material %s (%s), colour model %s\n", ctx->material_name, gmaterial_name(ctx->material),
               gcolormodel_name(ctx->model));
        printf("in  theta %g phi %g, out theta %g phi %g\n", a->in_t, a->in_p, a->out_t, a->out_p);
        gmat_print_color("reflected", &ctx->result, a->spectrum);
        return 0;
    }
    if (strcmp(a->cmd, "albedo") == 0) {
        GColor total = {0};
        if (gcolor_alloc(&total, ctx->model) != G_OK)
            return 1;
        double y = 0, ys = 0;
        int rc = gmat_albedo(ctx, gmat_direction(a->in_t, a->in_p), a->samples ? a->samples : 256, &total, &y, &ys);
        if (rc == G_OK) {
            printf("material %s (%s), colour model %s, in theta %g phi %g\n", ctx->material_name,
                   gmaterial_name(ctx->material), gcolormodel_name(ctx->model), a->in_t, a->in_p);
            printf("albedo Y     %.6f\n", y);
            printf("specular Y   %.6f\n", ys);
            gmat_print_color("albedo", &total, a->spectrum);
        } else {
            fprintf(stderr, "gmat albedo: the material failed (%s)\n", gstatus_string(rc));
        }
        gcolor_free(&total);
        return rc == G_OK ? 0 : 1;
    }
    GError err;
    GmatPlotOptions po = {.size = a->size ? a->size : 512, .log_radius = a->log_radius, .data = a->data};
    if (gmat_plot(ctx, a->in_t, &po, a->output, &err) != G_OK) {
        fprintf(stderr, "gmat plot: %s\n", err.message);
        return 1;
    }
    return 0;
}

/* The material `name` of lib, or NULL after a message that names the materials and nodes file defines. */
static GMaterial *find_material(GLibrary *lib, const char *file, const char *name)
{
    GMaterial *m = glibrary_material(lib, name);
    if (m)
        return m;
    char names[1024] = "";
    size_t used = 0;
    for (int k = GKIND_MATERIAL; k <= GKIND_NODE; k++)
        for (int i = 0; i < glibrary_count(lib, (GKind)k) && used + 1 < sizeof names; i++) {
            const char *n;
            glibrary_entry(lib, (GKind)k, i, &n, NULL);
            if (n)
                used += (size_t)snprintf(names + used, sizeof names - used, "%s%s", used ? ", " : "", n);
        }
    fprintf(stderr, "gmat: %s defines no material named '%s' (it defines: %s)\n", file, name, used ? names : "none");
    return NULL;
}

/* Runs eval, albedo, plot or check on the material of lib: the exit status. */
static int inspect(const Args *a, GLibrary *lib)
{
    GmatContext ctx = {.lib = lib, .model = glibrary_colormodel(lib), .material_name = a->material};
    if (!(ctx.material = find_material(lib, a->file, a->material)))
        return 1;
    double one[3] = {1, 1, 1};
    int rc;
    ctx.scratch = gscratch_create(0);
    if (!ctx.scratch || gcolor_alloc(&ctx.white, ctx.model) != G_OK || gcolor_alloc(&ctx.result, ctx.model) != G_OK ||
        gcolor_from_rgb(&ctx.white, one, GCOLOR_LIGHT) != G_OK) {
        fprintf(stderr, "gmat: out of memory\n");
        rc = 1;
    } else {
        rc = run(a, &ctx);
    }
    gcolor_free(&ctx.white);
    gcolor_free(&ctx.result);
    gscratch_destroy(ctx.scratch);
    return rc;
}

static int gmat_main(int argc, char **argv)
{
    GError err;
    if (register_scene_kinds(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    int rc = startup("gmat", &argc, argv);
    if (rc >= 0)
        return rc;
    GReaderOptions trust = {0};
    if (greader_options_args(&argc, argv, &trust, &err) != G_OK) {
        fprintf(stderr, "gmat: %s\n", err.message);
        return 2;
    }
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage_main(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(argv[1], "--version") == 0)
        return cli_version("gmat");
    if (strcmp(argv[1], "laser") == 0) /* laser.c parses its own options */
        return gmat_laser(argc, argv, &trust);
    if (strcmp(argv[1], "swatch") == 0)
        return gmat_swatch(argc, argv, &trust);
    if (strcmp(argv[1], "types") == 0)
        return types(argc, argv);
    if (strcmp(argv[1], "metals") == 0)
        return gmat_metals(argc, argv);
    if (strcmp(argv[1], "glasses") == 0)
        return gmat_glasses(argc, argv);
    Args a = {.cmd = argv[1]};
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        if (strcmp(a.cmd, commands[i].name) == 0)
            a.usage = commands[i].usage;
    if (!a.usage)
        return gmat_usage_error(NULL, "unknown command '%s' (expected eval, albedo, plot, list, check, types, swatch, "
                                      "laser, metals or glasses)", a.cmd);
    if ((rc = parse_args(argc, argv, &a)) >= 0)
        return rc;
    int listing = strcmp(a.cmd, "list") == 0;
    /* a listed scene's entries that only gtrace knows are skipped */
    unsigned skip = 0;
    for (int k = 0; listing && k < 5; k++)
        skip |= 1u << scene_kinds[k];
    GLibrary *lib;
    if (gmat_read(a.file, &trust, a.colormodel, a.step, skip, &lib, &err) != G_OK) {
        fprintf(stderr, "gmat: %s\n", err.message);
        return 1;
    }
    rc = listing ? list(lib) : inspect(&a, lib);
    glibrary_destroy(lib);
    return rc;
}

/* The run holds the standard descriptors, and every status leaves through cli_finish_stdout: a failed write to
 * standard output makes the run fail (cli_run). */
int main(int argc, char **argv) { return cli_run("gmat", gmat_main, argc, argv); }
