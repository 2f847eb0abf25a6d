/* gcolor - a colour report: a few colours converted into every registered colour model and back,
 * printed as linear sRGB and CIE XYZ; `gcolor list` names the registered models and `gcolor check MODEL`
 * runs the conformance checks (check.c). Built only on the public API. */
#include "gcolor.h"
#include "../common/cli.h"
#include "../common/startup.h"

#include <generic/color.h>
#include <generic/registry.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *f)
{
    fprintf(f,
            "usage: gcolor [--models LIST] [--rgb R,G,B]... [--plugin FILE.so]...\n"
            "       gcolor list [--illuminants] [--plugin FILE.so]...   the registered colour models (or the\n"
            "                                           named illuminants), one per line\n"
            "       gcolor check MODEL [--step NM] [--plugin FILE.so]...   conformance checks of MODEL\n"
            "       gcolor convert [--colormodel M] [--step NM] [--role reflectance|light] [--samples] LITERAL...\n"
            "                                           one line per colour literal (gcolor convert --help)\n"
            "       gcolor --help | --version\n"
            "Prints sample colours in every colour model (or the comma-separated LIST): the value the model\n"
            "stores, its brightness, and its conversion back to linear sRGB and CIE 1931 XYZ.\n"
            "  --rgb R,G,B   add a reflectance in linear sRGB to the report (repeatable)\n"
            "  --models LIST only these models, e.g. rgb,spectrum\n"
            "  --plugin FILE.so  load a module first (repeatable; a bare name is searched in\n"
            "                GENERIC_PLUGIN_PATH, then PREFIX/lib/generic/plugins, then the current directory)\n"
            "  --memory-limit SIZE  memory for what input sizes: MiB, or with M, G, T (default 4096, or\n"
            "                GENERIC_MEMORY_LIMIT_MB)\n"
            "  -h, --help    this text\n"
            "  --version     the version\n"
            "Every option value may also be written --option=value.\n"
            "Exit status: 0 when every conversion succeeded, 1 when one failed (it is named on stderr and no value\n"
            "is printed for it), 2 for a usage error such as an unknown option or model.\n");
}

typedef struct Sample {
    const char *name;
    double rgb[3];
    GColorRole role;
} Sample;

/* Prints every sample in one model; a sample whose conversion fails is reported as failed (never with the
 * previous sample's values). Returns 0, or 1 when the model cannot be created or a conversion failed. */
static int report_model(const char *model_name, const Sample *samples, int n)
{
    GError err;
    GColorModel *m = NULL;
    if (gcolormodel_create(model_name, NULL, &m, &err) != G_OK) {
        fprintf(stderr, "gcolor: %s\n", err.message);
        return 1;
    }
    printf("\n== %s (%d values per colour)\n", model_name, m->nvalues);
    GColor c;
    if (gcolor_alloc(&c, m) != G_OK) {
        fprintf(stderr, "gcolor: out of memory\n");
        gcolormodel_destroy(m);
        return 1;
    }
    int failed = 0;
    for (int i = 0; i < n; i++) {
        double rgb[3], xyz[3];
        const char *step = "from sRGB";
        int rc = gcolor_from_rgb(&c, samples[i].rgb, samples[i].role);
        if (rc == G_OK && (rc = gcolor_to_rgb(&c, samples[i].role, rgb)) != G_OK)
            step = "to sRGB";
        if (rc == G_OK && (rc = gcolor_to_xyz(&c, samples[i].role, xyz)) != G_OK)
            step = "to XYZ";
        double bright = rc == G_OK ? gcolor_brightness(&c) : 0.0;
        const char *why = rc != G_OK ? gstatus_string(rc) : NULL;
        if (rc == G_OK && !(isfinite(bright) && isfinite(rgb[0] + rgb[1] + rgb[2]) &&
                            isfinite(xyz[0] + xyz[1] + xyz[2]))) {
            rc = G_ERR_INVALID;
            step = "to sRGB and XYZ";
            why = "the result is not finite (the value is out of the model's range)";
        }
        if (rc != G_OK) {
            printf("  %-18s conversion %s failed\n", samples[i].name, step);
            fprintf(stderr, "gcolor: %s: '%s': the conversion %s failed: %s\n", model_name, samples[i].name, step,
                    why);
            failed = 1;
            continue;
        }
        printf("  %-18s brightness %.4f  -> sRGB %.4f %.4f %.4f  XYZ %.4f %.4f %.4f\n", samples[i].name,
               bright, rgb[0], rgb[1], rgb[2], xyz[0], xyz[1], xyz[2]);
    }
    gcolor_free(&c);
    gcolormodel_destroy(m);
    return failed;
}

static void list_usage(FILE *f)
{
    fprintf(f, "usage: gcolor list [--illuminants] [--plugin FILE.so]...\nThe registered colour models, one per line;\n"
               "with --illuminants the named CIE illuminants of `illuminant NAME` instead.\n" CLI_EXIT_STATUS_HELP);
}

/* `gcolor list`: the registered models, or with --illuminants the named illuminants, one per line. */
static int list_models(int argc, char **argv)
{
    static const struct option longopts[] = {CLI_COMMON_OPTIONS, {"illuminants", no_argument, NULL, 'i'}, {0}};
    CliParser p;
    cli_begin(&p, "gcolor list", argc, argv, "h", longopts);
    int c, n, status = CLI_OK, illuminants = 0;
    while ((c = cli_next_own(&p, "gcolor", list_usage, &status)) != -1) {
        if (c != 'i')
            return c == CLI_EXIT ? status : CLI_USAGE;
        illuminants = 1;
    }
    char **rest = cli_operands(&p, &n);
    if (n > 0)
        return cli_usage_error("gcolor list", "unexpected argument '%s'", rest[0]);
    for (int i = 0; illuminants && gcie_illuminant_name(i); i++)
        printf("%s\n", gcie_illuminant_name(i));
    if (illuminants)
        return 0;
    const GTypeInfo *types[64];
    int k = gregistry_list(GKIND_COLORMODEL, types, 64);
    for (int i = 0; i < k && i < 64; i++)
        printf("%s\n", types[i]->name);
    return 0;
}

/* The report's colours: the six samples, then each --rgb; and --models. */
typedef struct ReportArgs {
    Sample samples[32];
    char names[32][48];
    int n;
    const char *models;
} ReportArgs;

/* Adds --rgb R,G,B as a reflectance: 0, or the usage error's status (message printed). */
static int add_rgb(ReportArgs *a, const char *v)
{
    if (a->n == 32) {
        fprintf(stderr, "gcolor: at most %d --rgb colours\n", 32 - 6);
        return CLI_USAGE;
    }
    Sample *s = &a->samples[a->n];
    char tail;
    if (sscanf(v, "%lf,%lf,%lf%c", &s->rgb[0], &s->rgb[1], &s->rgb[2], &tail) != 3 || !isfinite(s->rgb[0]) ||
        !isfinite(s->rgb[1]) || !isfinite(s->rgb[2])) {
        fprintf(stderr, "gcolor: --rgb expects three finite numbers R,G,B, got '%s'\n", v);
        return CLI_USAGE;
    }
    snprintf(a->names[a->n], sizeof a->names[a->n], "rgb %s", v);
    s->name = a->names[a->n];
    s->role = GCOLOR_REFLECTANCE;
    a->n++;
    return 0;
}

/* Reads the command line of the report into a: -1 to go on, else the exit status to end with. */
static int report_args(int argc, char **argv, ReportArgs *a)
{
    static const Sample defaults[] = {
        {"white light", {1, 1, 1}, GCOLOR_LIGHT},
        {"grey 18%", {0.18, 0.18, 0.18}, GCOLOR_REFLECTANCE},
        {"red", {0.8, 0.1, 0.1}, GCOLOR_REFLECTANCE},
        {"green", {0.1, 0.7, 0.15}, GCOLOR_REFLECTANCE},
        {"blue", {0.05, 0.1, 0.75}, GCOLOR_REFLECTANCE},
        {"skin", {0.61, 0.42, 0.33}, GCOLOR_REFLECTANCE},
    };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"models", required_argument, NULL, 'm'}, {"rgb", required_argument, NULL, 'r'}, {0}};
    memset(a, 0, sizeof *a);
    a->n = (int)(sizeof defaults / sizeof *defaults);
    memcpy(a->samples, defaults, sizeof defaults);
    CliParser p;
    cli_begin(&p, "gcolor", argc, argv, "h", longopts);
    int c, nrest, status = CLI_OK;
    while ((c = cli_next_own(&p, "gcolor", usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (c == 'm')
            a->models = optarg;
        else if (c != 'r' || add_rgb(a, optarg) != 0)
            return CLI_USAGE;
    }
    char **rest = cli_operands(&p, &nrest);
    if (nrest > 0) {
        fprintf(stderr,
                "gcolor: unknown command or argument '%s' (expected list, check or convert; see gcolor --help)\n",
                rest[0]);
        return CLI_USAGE;
    }
    return -1;
}

/* The next name of a comma-separated list at *p (at most 127 characters of it into name); *len gets its whole
 * length and *p moves past its comma. */
static void next_name(const char **p, char name[128], size_t *len)
{
    *len = strcspn(*p, ",");
    snprintf(name, 128, "%.*s", (int)(*len < 128 ? *len : 127), *p);
    *p += *len + 1;
}

/* 0 when every name of the list is a registered colour model, else 2 after a message naming the first that is not:
 * checked before anything is printed. */
static int models_known(const char *models)
{
    const char *end = models + strlen(models);
    for (const char *p = models; p <= end;) {
        const char *at = p;
        char name[128];
        size_t k;
        next_name(&p, name, &k);
        if (!k || k >= sizeof name || !gregistry_find(GKIND_COLORMODEL, name)) {
            char names[512];
            gregistry_names(GKIND_COLORMODEL, names, sizeof names);
            fprintf(stderr, "gcolor: --models: unknown colour model '%.*s' (registered: %s)\n", (int)k, at, names);
            return 2;
        }
    }
    return 0;
}

/* The report in each model of the list (NULL: every registered one): 0, or 1 when a conversion failed. */
static int report_models(const char *models, const Sample *samples, int n)
{
    int failed = 0;
    if (!models) {
        const GTypeInfo *types[64];
        int k = gregistry_list(GKIND_COLORMODEL, types, 64);
        for (int i = 0; i < k && i < 64; i++)
            failed |= report_model(types[i]->name, samples, n);
        return failed;
    }
    const char *end = models + strlen(models);
    for (const char *p = models; p <= end;) {
        char name[128];
        size_t k;
        next_name(&p, name, &k);
        failed |= report_model(name, samples, n);
    }
    return failed;
}

static int gcolor_main(int argc, char **argv)
{
    int rc = startup("gcolor", &argc, argv);
    if (rc >= 0)
        return rc;
    if (argc > 1 && strcmp(argv[1], "check") == 0)
        return gcolor_check(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "list") == 0)
        return list_models(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "convert") == 0)
        return gcolor_convert_command(argc - 1, argv + 1);
    static ReportArgs a;
    if ((rc = report_args(argc, argv, &a)) >= 0)
        return rc;
    if (a.models && (rc = models_known(a.models)) != 0)
        return rc;
    printf("Colour report: reflectances are seen under D65 (Y = 1); lights are their own spectrum.\n");
    return report_models(a.models, a.samples, a.n);
}

/* The run holds the standard descriptors, and every status leaves through cli_finish_stdout: a failed write to
 * standard output makes the run fail (cli_run). */
int main(int argc, char **argv) { return cli_run("gcolor", gcolor_main, argc, argv); }
